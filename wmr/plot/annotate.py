r"""Annotations of a drawing: labels, points, arrows, frames, angles, construction lines, paths, boxes, legends.

All positions are in data coordinates of the axes (lengths in the robot's unit); offsets of
labels are in points.  Colours and dash patterns come from :mod:`wmr.plot.style`.
"""

from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Arc, FancyArrowPatch

from ..errors import InputValueError
from ..model.backend import NUMERIC
from ..model.platform import rotation
from .style import DASHES, FONT_LABEL, FONT_SMALL, HALO, PALETTE, ROLE

__all__ = [
    "label",
    "draw_point",
    "draw_arrow",
    "draw_frame",
    "draw_angle",
    "segment_through",
    "draw_line",
    "draw_path",
    "scale_bar",
    "info_box",
    "legend_handles",
]


def label(
    ax, xy, text, *, offset=(4, 4), color=None, ha="left", va="bottom", fontsize=FONT_LABEL, zorder=9.0, halo=True, **kw
):
    """A text label at ``xy`` shifted by ``offset`` points, with a white halo for legibility.

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
        Passed to :meth:`matplotlib.axes.Axes.annotate`.

    Returns
    -------
    matplotlib.text.Annotation
    """
    t = ax.annotate(
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
    if halo:
        t.set_path_effects(HALO)
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
        Label (see :func:`label`); none by default.
    marker : str, optional
        A matplotlib marker.
    color : str, optional
        Default: the point colour of :data:`wmr.plot.style.ROLE`.
    size : float, optional
        Marker size (points).
    offset, ha, va, fontsize : optional
        Placement and size of the label, as in :func:`label`.
    zorder : float, optional
    face : str, optional
        Face colour of the marker (default: ``color``).

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
    """An arrow from ``start`` along ``vec`` (data units).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    start : array_like (2,)
        Tail, data coordinates.
    vec : array_like (2,)
        The arrow itself: the tip is at ``start + vec``.
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
    """An arc from angle ``a0`` to ``a1`` (radians, counter-clockwise if a1 > a0) with a label.

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
        Label, placed on the bisector at ``text_radius * radius``.
    color : str, optional
        Default: the annotation colour of :data:`wmr.plot.style.ROLE`.
    lw : float, optional
    text_radius : float, optional
        Distance of the label from ``centre``, in radii.
    fontsize : float, optional
    arrow : bool, optional
        A head at ``a1`` (when the arc is long enough to carry one).
    zorder : float, optional

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


def segment_through(p, u, include=(), margin=0.3, min_half=0.5):
    r"""Parameters of the segment of the line :math:`p + t\,u/\|u\|` that covers ``p`` and the points ``include``.

    Each point :math:`q` of ``include`` is projected on the line, :math:`t_q = (q - p)\cdot u/\|u\|`.

    Parameters
    ----------
    p : array_like (2,)
        A point of the line.
    u : array_like (2,)
        Its direction (any length, not zero).
    include : sequence of array_like (2,), optional
        Points whose projections the segment must reach.
    margin : float, optional
        Added at both ends (data units).
    min_half : float, optional
        The segment reaches at least this far on either side of ``p``.

    Returns
    -------
    t0, t1 : float
        The ends, as distances along the unit direction.

    Examples
    --------
    >>> segment_through((0, 0), (2, 0), include=[(3, 1)], margin=0.0)
    (-0.5, 3.0)
    """
    p, u = np.asarray(p, dtype=float), np.asarray(u, dtype=float)
    u = u / np.linalg.norm(u)
    ts = [0.0, -min_half, min_half] + [float(np.dot(np.asarray(q, dtype=float) - p, u)) for q in include]
    return min(ts) - margin, max(ts) + margin


def draw_line(
    ax, p, u, include=(), *, kind="axle", margin=0.3, min_half=0.5, zorder=3.0, color=None, lw=None, alpha=1.0
):
    r"""A construction line through ``p`` along ``u``, long enough to reach the points ``include``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    p : array_like (2,)
        A point of the line.
    u : array_like (2,)
        Its direction.
    include : sequence of array_like (2,), optional
        Points the drawn segment must reach (:func:`segment_through`).
    kind : str, optional
        A key of :data:`wmr.plot.style.DASHES`: ``"axle"`` dashed blue (along
        :math:`\mathbf i_i`), ``"plane"`` dash-dotted vermillion (wheel-plane lines, along
        :math:`\mathbf j_i`), ``"thin"`` thin grey.
    margin, min_half : float, optional
        As for :func:`segment_through`.
    zorder : float, optional
    color : str, optional
        Overrides the colour of ``kind``.
    lw : float, optional
        Overrides the width of ``kind``.
    alpha : float, optional

    Returns
    -------
    numpy.ndarray (2, 2)
        The end points drawn.
    """
    p, u = np.asarray(p, dtype=float), np.asarray(u, dtype=float)
    u = u / np.linalg.norm(u)
    t0, t1 = segment_through(p, u, include, margin, min_half)
    seg = np.stack([p + t0 * u, p + t1 * u])
    col, ls, w = DASHES[kind]
    ax.plot(*seg.T, color=color or col, linestyle=ls, linewidth=lw or w, zorder=zorder, alpha=alpha)
    return seg


def draw_path(ax, xy, *, color=None, lw=1.3, ls="-", zorder=2.5, alpha=1.0):
    """A trajectory.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    xy : array_like (n, 2)
        The points of the path, in order.
    color : str, optional
        Default: the first path colour of :data:`wmr.plot.style.ROLE`.
    lw : float, optional
    ls : str, optional
    zorder, alpha : float, optional

    Returns
    -------
    matplotlib.lines.Line2D
    """
    xy = np.asarray(xy, dtype=float)
    return ax.plot(
        xy[:, 0], xy[:, 1], color=color or ROLE["path"][0], linewidth=lw, linestyle=ls, zorder=zorder, alpha=alpha
    )[0]


def scale_bar(ax, length, text, *, loc=(0.04, 0.05), color=None):
    """A scale bar of ``length`` data units at axes fraction ``loc`` (left end); call after the limits are set.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    length : float
        Data units.
    text : str
        Label above the bar.
    loc : tuple (2,), optional
        Left end of the bar, as fractions of the axes' limits.
    color : str, optional

    Returns
    -------
    None
    """
    col = color or PALETTE["dark"]
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    p = np.array([x0 + loc[0] * (x1 - x0), y0 + loc[1] * (y1 - y0)])
    ax.plot([p[0], p[0] + length], [p[1], p[1]], color=col, linewidth=1.6, solid_capstyle="butt", zorder=9)
    for x in (p[0], p[0] + length):
        ax.plot([x, x], [p[1] - 0.015 * (y1 - y0), p[1] + 0.015 * (y1 - y0)], color=col, linewidth=1.0, zorder=9)
    label(ax, (p[0] + length / 2, p[1]), text, offset=(0, 3), ha="center", va="bottom", fontsize=FONT_SMALL)


def info_box(ax, lines, *, loc=(0.98, 0.98), ha="right", va="top", fontsize=FONT_SMALL, below=False):
    """Computed numbers, one per line, in a light box at axes fraction ``loc``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    lines : sequence of str
        The lines of text.
    loc : tuple (2,), optional
        Anchor of the box, axes fractions.
    ha, va : str, optional
        Alignment of the box at ``loc``.
    fontsize : float, optional
    below : bool, optional
        Centre the box under the axes instead (overrides ``loc``, ``ha``, ``va``).

    Returns
    -------
    None
    """
    if below:
        loc, ha, va = (0.5, -0.015), "center", "top"
    ax.text(
        loc[0],
        loc[1],
        "\n".join(lines),
        transform=ax.transAxes,
        ha=ha,
        va=va,
        fontsize=fontsize,
        color=PALETTE["dark"],
        zorder=10,
        linespacing=1.35,
        clip_on=False,
        bbox=dict(boxstyle="round,pad=0.35", facecolor="white", edgecolor="#BBBBBB", linewidth=0.6, alpha=0.92),
    )


def legend_handles(items):
    """Line2D proxies for a legend.

    Parameters
    ----------
    items : list of (text, kind)
        ``kind``: ``"axle"``, ``"plane"``, ``"path:<colour>"``, ``"point:<colour>"``,
        ``"marker:<marker>:<colour>"`` (filled) or ``"open:<marker>:<colour>"`` (white face).

    Returns
    -------
    list of Line2D
    """
    hs = []
    for text, kind in items:
        if kind in DASHES:
            col, ls, w = DASHES[kind]
            hs.append(Line2D([], [], color=col, linestyle=ls, linewidth=w, label=text))
        elif kind.startswith("path:"):
            hs.append(Line2D([], [], color=kind[5:], linewidth=1.3, label=text))
        elif kind.startswith("point:"):
            hs.append(Line2D([], [], color=kind[6:], marker="o", markersize=4, linestyle="none", label=text))
        elif kind.startswith(("marker:", "open:")):
            how, m, c = kind.split(":")
            hs.append(
                Line2D(
                    [],
                    [],
                    color=c,
                    marker=m,
                    markersize=5,
                    linestyle="none",
                    label=text,
                    markerfacecolor="white" if how == "open" else c,
                )
            )
        else:
            raise InputValueError(
                f"legend item kind must be axle, plane, thin, path:, point:, marker: or open:, got {kind!r}"
            )
    return hs
