r"""Marks at points of a drawing: labels, points, arrows, frames and angles (conventions: :mod:`wmr.plot.annotate`)."""

from __future__ import annotations

import numpy as np
from matplotlib.patches import Arc, FancyArrowPatch
from matplotlib.path import Path
from matplotlib.text import Annotation
from matplotlib.transforms import Bbox, IdentityTransform

from ..model.backend import NUMERIC
from ..model.platform import rotation
from .style import FONT_LABEL, HALO, ROLE

__all__ = ["label", "draw_point", "draw_arrow", "draw_frame", "draw_angle"]

#: directions a label may move to, tried in this order after the one asked for (unit steps; times the offset's size)
_DIRECTIONS = ((1, 1), (1, -1), (-1, 1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1))


def _align(dx, dy):
    """The alignment that puts a label on the side of its anchor the offset points to."""
    ha = "left" if dx > 0 else "right" if dx < 0 else "center"
    va = "bottom" if dy > 0 else "top" if dy < 0 else "center"
    return ha, va


def _outlined(patch) -> bool:
    """Whether ``patch`` draws an outline a label could cross (a circle's rim, a polygon's edges)."""
    return patch.get_linewidth() > 0 and patch.get_edgecolor()[3] > 0


class _ClearLabel(Annotation):
    """A label that, when drawn, moves off the lines, marked points, arrows, patch outlines and texts of its axes.

    At draw time (the limits final) it keeps its offset unless its box crosses one of them; then it takes the first
    offset of :data:`_DIRECTIONS` (at the same distance, then twice and three times it) whose box crosses none, or, if
    none is clear, the one it was given.  The choice depends only on the drawing: the same on every machine.
    """

    def __init__(self, *args, **kw):
        super().__init__(*args, **kw)
        self._asked = (tuple(self.xyann), self.get_horizontalalignment(), self.get_verticalalignment())

    def _obstacles(self, ax, renderer):
        """What the label must not cover: the lines, marked points and arrows of its axes, and its other texts."""
        paths = []
        for line in ax.get_lines():
            if not line.get_visible():
                continue
            xy = line.get_transform().transform(np.asarray(line.get_xydata(), dtype=float))
            xy = np.round(xy[np.all(np.isfinite(xy), axis=1)], 3)
            if line.get_linestyle() not in ("None", "none", "", " ") and len(xy) >= 2:
                paths.append(Path(xy))
            if line.get_marker() not in (None, "None", "none", "", " "):
                paths += [Path(p + [[-1.0, -1.0], [1.0, 1.0]]) for p in xy]
        for patch in ax.patches:
            if patch.get_visible() and (isinstance(patch, FancyArrowPatch) or _outlined(patch)):
                paths.append(patch.get_transform().transform_path(patch.get_path()))
        boxes = [t.get_window_extent(renderer) for t in ax.texts if t is not self and t.get_visible() and t.get_text()]
        return paths, boxes

    def _clear(self, ax, renderer, obstacles):
        paths, boxes = obstacles
        bb, frame = self.get_window_extent(renderer), ax.get_window_extent(renderer)
        inner = Bbox.from_extents(bb.x0 + 1, bb.y0 + 1, bb.x1 - 1, bb.y1 - 1)
        if not frame.contains(inner.x0, inner.y0) or not frame.contains(inner.x1, inner.y1):
            return False  # a label must stay inside its axes, where it is not clipped
        crosses = any(p.intersects_bbox(inner, filled=False) for p in paths)
        return not crosses and not any(inner.overlaps(b) for b in boxes)

    def draw(self, renderer):
        ax = self.axes
        if self.get_visible() and ax is not None:
            (dx, dy), ha, va = self._asked
            self.xyann = (dx, dy)
            self.set_horizontalalignment(ha)
            self.set_verticalalignment(va)
            paths = self._obstacles(ax, renderer)
            if not self._clear(ax, renderer, paths):
                size = max(float(np.hypot(dx, dy)), 4.0)
                for scale in (1.0, 2.0, 3.0):
                    for ux, uy in _DIRECTIONS:
                        n = float(np.hypot(ux, uy))
                        self.xyann = (scale * size * ux / n, scale * size * uy / n)
                        h, v = _align(ux, uy)
                        self.set_horizontalalignment(h)
                        self.set_verticalalignment(v)
                        if self._clear(ax, renderer, paths):
                            return super().draw(renderer)
                self.xyann = (dx, dy)
                self.set_horizontalalignment(ha)
                self.set_verticalalignment(va)
        return super().draw(renderer)


def label(
    ax, xy, text, *, offset=(4, 4), color=None, ha="left", va="bottom", fontsize=FONT_LABEL, zorder=9.0, halo=True, **kw
):
    """A text label at ``xy`` shifted by ``offset`` points, with a white halo; when drawn it moves off what it would cover.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    xy : array_like (2,)
        Anchor in data coordinates.
    text : str
        The label (matplotlib mathtext allowed).
    offset : tuple (2,), optional
        Shift of the text from ``xy``, in points.
    color : str, optional
        Default: the annotation colour of :data:`wmr.plot.style.ROLE`.
    ha, va : str, optional
        Alignment of the text relative to the shifted anchor.
    fontsize, zorder : float, optional
    halo : bool, optional
        Draw a white outline behind the text.
    **kw
        Passed to :class:`matplotlib.text.Annotation`.

    Returns
    -------
    matplotlib.text.Annotation
    """
    t = _ClearLabel(
        text,
        xy=tuple(np.asarray(xy, dtype=float)),
        xytext=offset,
        textcoords="offset points",
        ha=ha,
        va=va,
        color=color or ROLE["annotation"],
        fontsize=fontsize,
        zorder=zorder,
        **kw,
    )
    t.set_transform(IdentityTransform())  # as Axes.annotate does: the offset is in points
    ax.add_artist(t)
    if halo:
        t.set_path_effects(list(HALO))
    return t


def draw_point(
    ax,
    xy,
    text=None,
    *,
    marker="o",
    color=None,
    size=4.0,
    offset=(4, 4),
    ha="left",
    va="bottom",
    zorder=8.0,
    fontsize=FONT_LABEL,
    face=None,
):
    """A marked point with an optional label (in the point's colour).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    xy : array_like (2,)
        The point, data coordinates.
    text : str, optional
        Label (:func:`label`); none by default.
    marker : str, optional
        A matplotlib marker.
    color, face : str, optional
        Colour (default: the point colour of :data:`wmr.plot.style.ROLE`) and face colour (default ``color``).
    size : float, optional
        Marker size (points).
    offset, ha, va, fontsize : optional
        Placement and size of the label, as in :func:`label`.
    zorder : float, optional

    Returns
    -------
    None
    """
    col = color or ROLE["point"]
    ax.plot(
        [xy[0]],
        [xy[1]],
        marker=marker,
        markersize=size,
        color=col,
        markerfacecolor=face or col,
        markeredgewidth=0.8,
        linestyle="none",
        zorder=zorder,
    )
    if text:
        label(ax, xy, text, offset=offset, color=col if col != ROLE["point"] else None, ha=ha, va=va, fontsize=fontsize)


def draw_arrow(ax, start, vec, *, color=None, lw=1.1, zorder=6.0, head=7.0, style="-|>", ls="-"):
    """An arrow from ``start`` along ``vec`` (data units): the tip at ``start + vec``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    start, vec : array_like (2,)
        Tail (data coordinates) and the arrow itself.
    color : str, optional
        Default: the frame colour of :data:`wmr.plot.style.ROLE`.
    lw, zorder : float, optional
        Line width and drawing order.
    head : float, optional
        Size of the head (``mutation_scale``).
    style, ls : str, optional
        Arrow style (``"-|>"``) and line style.

    Returns
    -------
    matplotlib.patches.FancyArrowPatch
    """
    s = np.asarray(start, dtype=float)
    e = s + np.asarray(vec, dtype=float)
    a = FancyArrowPatch(
        (float(s[0]), float(s[1])),
        (float(e[0]), float(e[1])),
        arrowstyle=style,
        mutation_scale=head,
        color=color or ROLE["frame"],
        linewidth=lw,
        linestyle=ls,
        shrinkA=0,
        shrinkB=0,
        zorder=zorder,
    )
    ax.add_patch(a)
    return a


def draw_frame(
    ax,
    origin,
    angle,
    length,
    labels=(r"$\mathbf{i}$", r"$\mathbf{j}$"),
    *,
    color=None,
    zorder=6.0,
    fontsize=FONT_LABEL,
    lw=1.1,
):
    r"""Two arrows (a frame) at ``origin``: the columns of :math:`\mathbf R(\text{angle})` times ``length``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    origin : array_like (2,)
        Data coordinates.
    angle : float
        Radians, counter-clockwise from the x-axis.
    length : float
        Length of each arrow (data units).
    labels : tuple of 2 str, optional
        Labels at the tips (an empty string: none).
    color : str, optional
        Default: the frame colour of :data:`wmr.plot.style.ROLE`.
    zorder, fontsize, lw : float, optional

    Returns
    -------
    None
    """
    col = color or ROLE["frame"]
    o = np.asarray(origin, dtype=float)
    R = rotation(angle, NUMERIC)
    for e, lab in zip(R.T, labels):
        draw_arrow(ax, o, length * e, color=col, zorder=zorder, lw=lw)
        if lab:
            label(ax, o + 1.12 * length * e, lab, color=col, offset=(0, 0), ha="center", va="center", fontsize=fontsize)


def draw_angle(
    ax,
    centre,
    radius,
    a0,
    a1,
    text=None,
    *,
    color=None,
    lw=0.9,
    text_radius=1.35,
    fontsize=FONT_LABEL,
    arrow=True,
    zorder=6.0,
):
    """An arc from angle ``a0`` to ``a1`` (radians, counter-clockwise if a1 > a0), with a head at ``a1`` and a label.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    centre : array_like (2,)
        Data coordinates.
    radius : float
        Radius of the arc (data units).
    a0, a1 : float
        Start and end angles (radians).
    text : str, optional
        Label, on the bisector at ``text_radius * radius``.
    color : str, optional
        Default: the annotation colour of :data:`wmr.plot.style.ROLE`.
    lw, text_radius, fontsize, zorder : float, optional
    arrow : bool, optional
        The head at ``a1`` (when the arc is long enough to carry one).

    Returns
    -------
    None
    """
    col = color or ROLE["annotation"]
    lo, hi = (a0, a1) if a1 >= a0 else (a1, a0)
    ax.add_patch(
        Arc(
            centre,
            2 * radius,
            2 * radius,
            theta1=np.degrees(lo),
            theta2=np.degrees(hi),
            color=col,
            linewidth=lw,
            zorder=zorder,
        )
    )
    if arrow and abs(a1 - a0) > 0.12:  # head at a1, along the arc
        e = np.array([np.cos(a1), np.sin(a1)])
        tdir = np.sign(a1 - a0) * np.array([-np.sin(a1), np.cos(a1)])
        tip = np.asarray(centre) + radius * e
        draw_arrow(ax, tip - 0.06 * radius * tdir, 0.06 * radius * tdir, color=col, lw=lw, head=6, zorder=zorder)
    if text:
        am = 0.5 * (a0 + a1)
        label(
            ax,
            np.asarray(centre) + text_radius * radius * np.array([np.cos(am), np.sin(am)]),
            text,
            offset=(0, 0),
            ha="center",
            va="center",
            color=col,
            fontsize=fontsize,
        )
