r"""One way of drawing a wheeled mobile robot, used by every figure of :mod:`wmr.paper.figures`.

A robot is drawn seen from above: the platform as a disc, the operation point C with the body
frame :math:`(\mathbf i, \mathbf j)`, and each wheel unit as its intermediate body (a pivot at
:math:`P_i` on the steering axis, an arm to :math:`H_i` for an offset wheel, a bar for a dual wheel)
carrying wheel discs, which from above are rounded rectangles of length :math:`2r` along the
rolling direction :math:`\mathbf j_i` (marked by an arrow).  Axles (dashed, along
:math:`\mathbf i_i`) and wheel-plane lines (along :math:`\mathbf j_i`) can be drawn and extended to
where they meet.  The geometry comes from :meth:`wmr.model.wheels._Unit.points`, so the pictures obey
:mod:`wmr.conventions` by construction.

Style: the Okabe-Ito colour-blind-safe palette (:data:`PALETTE`), one set of line widths and
font sizes (:data:`RC`), equal aspect, no axes ticks (a scale bar instead).

Figures are plain :class:`matplotlib.figure.Figure` objects (not registered with pyplot, so
nothing accumulates and a notebook's backend is left alone); saving renders PNG with Agg and
SVG/PDF with matplotlib's vector backends, whatever backend is active.
"""
from __future__ import annotations

from contextlib import contextmanager
from dataclasses import dataclass

import matplotlib
import matplotlib.patheffects as pe
import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Arc, Circle, FancyArrowPatch, FancyBboxPatch, Polygon
from matplotlib.transforms import Affine2D

from ..model.backend import NUMERIC
from ..model.platform import rotation

#: Okabe & Ito (2008) colour-blind-safe palette, by role.
PALETTE = {
    "black": "#000000", "orange": "#E69F00", "sky": "#56B4E9", "green": "#009E73",
    "yellow": "#F0E442", "blue": "#0072B2", "vermillion": "#D55E00", "purple": "#CC79A7",
    "grey": "#7F7F7F", "light": "#EDEDED", "dark": "#2B2B2B",
}
ROLE = {
    "platform_face": "#EEEEEE", "platform_edge": "#8C8C8C", "wheel": PALETTE["dark"],
    "body": "#6E6E6E", "axle": PALETTE["blue"], "plane": PALETTE["vermillion"],
    "frame": PALETTE["black"], "fixed_frame": PALETTE["grey"], "point": PALETTE["black"],
    "path": (PALETTE["orange"], PALETTE["sky"], PALETTE["green"], PALETTE["purple"], PALETTE["vermillion"]),
    "ic": PALETTE["blue"], "dp": PALETTE["vermillion"], "annotation": PALETTE["dark"],
}

#: Matplotlib settings of every figure (also what makes the output files deterministic).
RC = {
    "font.family": "DejaVu Sans",
    "font.size": 9.0,
    "mathtext.fontset": "dejavusans",
    "axes.titlesize": 10.0,
    "axes.titleweight": "normal",
    "axes.linewidth": 0.6,
    "lines.linewidth": 1.2,
    "lines.solid_capstyle": "round",
    "legend.fontsize": 8.0,
    "legend.frameon": False,
    "savefig.dpi": 200,
    "savefig.bbox": "standard",
    "figure.dpi": 100,
    "svg.hashsalt": "wmr-leow-low-loh-2002",
    "svg.fonttype": "path",
    "pdf.fonttype": 3,
    "image.cmap": "cividis",
    "path.simplify": False,
}

FONT_LABEL = 9.0
FONT_SMALL = 7.5
HALO = [pe.withStroke(linewidth=2.6, foreground="white")]


@contextmanager
def style():
    """Context in which figures are made and saved (Agg, :data:`RC`)."""
    with matplotlib.rc_context(RC):
        yield


def new_figure(nrows=1, ncols=1, width=7.0, height=3.2, **subplot_kw):
    """A :class:`matplotlib.figure.Figure` (not registered with pyplot) and its axes, flattened.

    Returns
    -------
    fig : Figure
    axes : list of Axes (length nrows * ncols)
    """
    fig = Figure(figsize=(width, height), layout="constrained")
    axs = fig.subplots(nrows, ncols, squeeze=False, **subplot_kw)
    axes = list(axs.ravel())
    for ax in axes:
        plain_axes(ax)
    return fig, axes


def plain_axes(ax):
    """Equal aspect, no ticks or spines: a drawing, not a chart."""
    ax.set_aspect("equal", adjustable="box")
    ax.set_xticks([])
    ax.set_yticks([])
    for s in ax.spines.values():
        s.set_visible(False)


def panel_title(ax, letter, text):
    """Panel title '(a) text', left-aligned."""
    ax.set_title(f"({letter}) {text}" if letter else text, loc="left", fontsize=RC["axes.titlesize"])


def fit_view(ax, points, pad=0.15):
    """Set limits that contain ``points`` (n, 2) with a relative margin."""
    p = np.asarray(points, dtype=float).reshape(-1, 2)
    lo, hi = p.min(axis=0), p.max(axis=0)
    span = max(float((hi - lo).max()), 1e-9)
    m = pad * span
    ax.set_xlim(lo[0] - m, hi[0] + m)
    ax.set_ylim(lo[1] - m, hi[1] + m)


def common_view(axes, point_sets, pad=0.05):
    """Give every axes the same data span (same scale), each centred on its own points."""
    boxes = []
    for pts in point_sets:
        p = np.asarray(pts, dtype=float).reshape(-1, 2)
        boxes.append((p.min(axis=0), p.max(axis=0)))
    half = max(float(((hi - lo) / 2).max()) for lo, hi in boxes) * (1 + pad)
    hw = max(float((hi[0] - lo[0]) / 2) for lo, hi in boxes) * (1 + pad)
    hh = max(float((hi[1] - lo[1]) / 2) for lo, hi in boxes) * (1 + pad)
    del half
    for ax, (lo, hi) in zip(axes, boxes):
        c = (lo + hi) / 2
        ax.set_xlim(c[0] - hw, c[0] + hw)
        ax.set_ylim(c[1] - hh, c[1] + hh)


# ----------------------------------------------------------------------------- geometry
def rot(angle):
    """2x2 rotation matrix (the model's :func:`wmr.model.platform.rotation`)."""
    return rotation(angle, NUMERIC)


def to_world(pose, p):
    """Body-frame points (..., 2) to the fixed frame for pose (psi, X, Y)."""
    psi, X, Y = pose
    return np.asarray(p, dtype=float) @ rot(psi).T + np.array([X, Y])


@dataclass(frozen=True)
class RobotDrawing:
    """World coordinates of what :func:`draw_robot` drew (for labels and construction lines).

    Attributes
    ----------
    C : (2,)
    P, H : (w, 2)
        Steering-axis points and wheel-unit centres.
    wheels : list of (k, 2)
        Wheel centres of each unit.
    i, j : (w, 2)
        Axle and rolling directions (world).
    psi : float
    """

    C: np.ndarray
    P: np.ndarray
    H: np.ndarray
    wheels: list
    i: np.ndarray
    j: np.ndarray
    psi: float


def robot_geometry(robot, beta, pose=(0.0, 0.0, 0.0)):
    """World geometry of ``robot`` at steering angles ``beta`` (w,) and ``pose``; a :class:`RobotDrawing`."""
    beta = np.asarray(beta, dtype=float)
    R = rot(pose[0])
    P, H, wheels, ii, jj = [], [], [], [], []
    for k, u in enumerate(robot.wheels):
        pts = u.points(beta[k])
        P.append(to_world(pose, pts["P"]))
        H.append(to_world(pose, pts["H"]))
        wheels.append(to_world(pose, pts["wheels"]))
        ii.append(R @ pts["i"])
        jj.append(R @ pts["j"])
    return RobotDrawing(np.array(pose[1:], dtype=float), np.array(P), np.array(H), wheels,
                        np.array(ii), np.array(jj), float(pose[0]))


def platform_radius(robot):
    """Radius of the platform disc: a little beyond the farthest mount point."""
    d = np.linalg.norm(robot.mount_points, axis=1).max()
    r = max(float(u.r) for u in robot.wheels)
    return float(d + 0.9 * r)


# ----------------------------------------------------------------------------- primitives
def draw_platform(ax, centre, radius, *, ghost=False, zorder=1.0):
    """The platform as a disc (dashed outline when ``ghost``)."""
    if ghost:
        ax.add_patch(Circle(centre, radius, facecolor="none", edgecolor=ROLE["platform_edge"],
                            linewidth=0.8, linestyle=(0, (4, 3)), zorder=zorder))
    else:
        ax.add_patch(Circle(centre, radius, facecolor=ROLE["platform_face"], edgecolor=ROLE["platform_edge"],
                            linewidth=0.9, zorder=zorder))


def draw_wheel(ax, centre, heading, r, width=None, *, ghost=False, arrow=True, zorder=4.0, color=None, light=False):
    r"""A wheel disc seen from above: a rounded rectangle, length 2r along ``heading`` (:math:`\mathbf j_i`).

    Parameters
    ----------
    centre : (2,)
    heading : float
        World angle of the wheel frame, :math:`\psi + \beta_i` (the rectangle's long side is
        along :math:`\mathbf j_i = \mathbf R(\psi+\beta_i)[0\ 1]^T`).
    r : float
    width : float, optional
        Tyre width (default 0.42 r).
    arrow : bool
        Mark the rolling direction :math:`+\mathbf j_i` with a white arrow.
    """
    w = 0.42 * r if width is None else width
    col = color or ROLE["wheel"]
    face = "none" if ghost else ("#D4D4D4" if light else col)
    box = FancyBboxPatch((-w / 2, -r), w, 2 * r, boxstyle=f"round,pad=0,rounding_size={0.45 * w}",
                         facecolor=face, edgecolor=col,
                         linewidth=0.8, linestyle=(0, (3, 2)) if ghost else "-", zorder=zorder)
    box.set_transform(Affine2D().rotate(heading).translate(*centre) + ax.transData)
    ax.add_patch(box)
    if arrow and not ghost:
        jdir = np.array([-np.sin(heading), np.cos(heading)])
        c = np.asarray(centre, dtype=float)
        ax.add_patch(FancyArrowPatch(c - 0.62 * r * jdir, c + 0.72 * r * jdir, arrowstyle="-|>",
                                     mutation_scale=5.5, color=PALETTE["dark"] if light else "white", linewidth=0.8,
                                     shrinkA=0, shrinkB=0, zorder=zorder + 0.1))


def draw_pivot(ax, p, size, *, ghost=False, zorder=5.0):
    """The steering axis at :math:`P_i`: a small white disc with a dark rim."""
    ax.add_patch(Circle(p, size, facecolor="white" if not ghost else "none", edgecolor=PALETTE["dark"],
                        linewidth=0.8, zorder=zorder))
    if not ghost:
        ax.add_patch(Circle(p, 0.28 * size, facecolor=PALETTE["dark"], edgecolor="none", zorder=zorder + 0.1))


def draw_unit(ax, unit, beta, pose=(0.0, 0.0, 0.0), *, ghost=False, zorder=4.0, show_j=True, light=False):
    """One wheel unit: intermediate body, wheel disc(s) and pivot (world coordinates from ``pose``).

    ``light`` draws the wheels light grey (close-ups, so that the arm and labels stay visible).
    """
    pts = unit.points(float(beta))
    P = to_world(pose, pts["P"])
    H = to_world(pose, pts["H"])
    heading = pose[0] + float(beta)
    r = float(unit.r)
    lw = 2.2 if not ghost else 1.0
    ls = "-" if not ghost else (0, (3, 2))
    if unit.kind == "offset":
        ax.plot(*np.stack([P, H]).T, color=ROLE["body"] if not light else PALETTE["dark"], linewidth=lw,
                linestyle=ls, solid_capstyle="round", zorder=zorder + 0.5)
    if unit.kind == "dual":
        wh = to_world(pose, pts["wheels"])
        ax.plot(*wh.T, color=ROLE["body"], linewidth=lw, linestyle=ls, zorder=zorder - 0.1)
    for c in to_world(pose, pts["wheels"]):
        draw_wheel(ax, c, heading, r, ghost=ghost, arrow=show_j, zorder=zorder, light=light)
    draw_pivot(ax, P, 0.16 * r, ghost=ghost, zorder=zorder + 1)
    return P, H


def draw_frame(ax, origin, angle, length, labels=(r"$\mathbf{i}$", r"$\mathbf{j}$"), *, color=None,
               zorder=6.0, fontsize=FONT_LABEL, lw=1.1):
    """Two unit arrows (a frame) at ``origin`` rotated by ``angle``, labelled at their tips."""
    col = color or ROLE["frame"]
    o = np.asarray(origin, dtype=float)
    for k, lab in enumerate(labels):
        e = rot(angle) @ (np.array([1.0, 0.0]) if k == 0 else np.array([0.0, 1.0]))
        draw_arrow(ax, o, length * e, color=col, zorder=zorder, lw=lw)
        if lab:
            label(ax, o + 1.12 * length * e, lab, color=col, offset=(0, 0), ha="center", va="center",
                  fontsize=fontsize)


def draw_arrow(ax, start, vec, *, color=None, lw=1.1, zorder=6.0, head=7.0, style="-|>", ls="-"):
    """An arrow from ``start`` along ``vec`` (data units)."""
    s = np.asarray(start, dtype=float)
    a = FancyArrowPatch(s, s + np.asarray(vec, dtype=float), arrowstyle=style, mutation_scale=head,
                        color=color or ROLE["frame"], linewidth=lw, linestyle=ls, shrinkA=0, shrinkB=0,
                        zorder=zorder)
    ax.add_patch(a)
    return a


def label(ax, xy, text, *, offset=(4, 4), color=None, ha="left", va="bottom", fontsize=FONT_LABEL,
          zorder=9.0, halo=True, **kw):
    """A text label at ``xy`` shifted by ``offset`` points, with a white halo for legibility."""
    t = ax.annotate(text, xy=tuple(np.asarray(xy, dtype=float)), xytext=offset, textcoords="offset points",
                    ha=ha, va=va, color=color or ROLE["annotation"], fontsize=fontsize, zorder=zorder, **kw)
    if halo:
        t.set_path_effects(HALO)
    return t


def draw_point(ax, xy, text=None, *, marker="o", color=None, size=4.0, offset=(4, 4), ha="left", va="bottom",
               zorder=8.0, fontsize=FONT_LABEL, face=None):
    """A marked point with an optional label."""
    col = color or ROLE["point"]
    ax.plot([xy[0]], [xy[1]], marker=marker, markersize=size, color=col, markerfacecolor=face or col,
            markeredgewidth=0.8, linestyle="none", zorder=zorder)
    if text:
        label(ax, xy, text, offset=offset, color=col if col != ROLE["point"] else None, ha=ha, va=va,
              fontsize=fontsize)


def segment_through(p, u, include=(), margin=0.3, min_half=0.5):
    """Parameters (t0, t1) of the segment of the line p + t u covering p and the points ``include``."""
    p, u = np.asarray(p, dtype=float), np.asarray(u, dtype=float)
    u = u / np.linalg.norm(u)
    ts = [0.0, -min_half, min_half] + [float(np.dot(np.asarray(q, dtype=float) - p, u)) for q in include]
    return min(ts) - margin, max(ts) + margin


def draw_line(ax, p, u, include=(), *, kind="axle", margin=0.3, min_half=0.5, zorder=3.0, color=None, lw=None,
              alpha=1.0):
    """A construction line through ``p`` along ``u``, long enough to reach ``include``.

    ``kind="axle"``: dashed blue (axles, along :math:`\\mathbf i_i`); ``kind="plane"``: dash-dotted
    vermillion (wheel-plane lines, along :math:`\\mathbf j_i`); ``kind="thin"``: thin grey.
    """
    p, u = np.asarray(p, dtype=float), np.asarray(u, dtype=float)
    u = u / np.linalg.norm(u)
    t0, t1 = segment_through(p, u, include, margin, min_half)
    seg = np.stack([p + t0 * u, p + t1 * u])
    styles = {"axle": (ROLE["axle"], (0, (5, 3)), 0.9), "plane": (ROLE["plane"], (0, (8, 2, 1.5, 2)), 0.9),
              "thin": (PALETTE["grey"], (0, (2, 2)), 0.6)}
    col, ls, w = styles[kind]
    ax.plot(*seg.T, color=color or col, linestyle=ls, linewidth=lw or w, zorder=zorder, alpha=alpha)
    return seg


def draw_angle(ax, centre, radius, a0, a1, text=None, *, color=None, lw=0.9, text_radius=1.35, fontsize=FONT_LABEL,
               arrow=True, zorder=6.0):
    """An arc from angle ``a0`` to ``a1`` (radians, counter-clockwise if a1 > a0) with a label."""
    col = color or ROLE["annotation"]
    lo, hi = (a0, a1) if a1 >= a0 else (a1, a0)
    ax.add_patch(Arc(centre, 2 * radius, 2 * radius, theta1=np.degrees(lo), theta2=np.degrees(hi), color=col,
                     linewidth=lw, zorder=zorder))
    if arrow and abs(a1 - a0) > 0.12:
        # arrow head at a1 pointing along the arc
        e = np.array([np.cos(a1), np.sin(a1)])
        tdir = np.sign(a1 - a0) * np.array([-np.sin(a1), np.cos(a1)])
        tip = np.asarray(centre) + radius * e
        draw_arrow(ax, tip - 0.06 * radius * tdir, 0.06 * radius * tdir, color=col, lw=lw, head=6, zorder=zorder)
    if text:
        am = 0.5 * (a0 + a1)
        label(ax, np.asarray(centre) + text_radius * radius * np.array([np.cos(am), np.sin(am)]), text,
              offset=(0, 0), ha="center", va="center", color=col, fontsize=fontsize)


def draw_path(ax, xy, *, color=None, lw=1.3, ls="-", zorder=2.5, label_text=None, alpha=1.0):
    """A trajectory (n, 2)."""
    xy = np.asarray(xy, dtype=float)
    return ax.plot(xy[:, 0], xy[:, 1], color=color or ROLE["path"][0], linewidth=lw, linestyle=ls, zorder=zorder,
                   label=label_text, alpha=alpha)[0]


def scale_bar(ax, length, text, *, loc=(0.04, 0.05), color=None):
    """A scale bar of ``length`` data units at axes fraction ``loc`` (left end)."""
    col = color or PALETTE["dark"]
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    p = np.array([x0 + loc[0] * (x1 - x0), y0 + loc[1] * (y1 - y0)])
    ax.plot([p[0], p[0] + length], [p[1], p[1]], color=col, linewidth=1.6, solid_capstyle="butt", zorder=9)
    for x in (p[0], p[0] + length):
        ax.plot([x, x], [p[1] - 0.015 * (y1 - y0), p[1] + 0.015 * (y1 - y0)], color=col, linewidth=1.0, zorder=9)
    label(ax, (p[0] + length / 2, p[1]), text, offset=(0, 3), ha="center", va="bottom", fontsize=FONT_SMALL)


def info_box(ax, lines, *, loc=(0.98, 0.98), ha="right", va="top", fontsize=FONT_SMALL, below=False):
    """Computed numbers, one per line, in a light box at axes fraction ``loc`` (``below``: under the axes)."""
    if below:
        loc, ha, va = (0.5, -0.015), "center", "top"
    ax.text(loc[0], loc[1], "\n".join(lines), transform=ax.transAxes, ha=ha, va=va, fontsize=fontsize,
            color=PALETTE["dark"], zorder=10, linespacing=1.35, clip_on=False,
            bbox=dict(boxstyle="round,pad=0.35", facecolor="white", edgecolor="#BBBBBB", linewidth=0.6, alpha=0.92))


# ----------------------------------------------------------------------------- the robot
def draw_robot(ax, robot, beta, pose=(0.0, 0.0, 0.0), *, ghost=False, labels=True, suffix="", frame=True,
               frame_length=None, platform=True, radius=None, show_C=True, show_j=True, zorder=4.0,
               wheel_labels=True, label_offsets=None):
    r"""Draw a whole robot: platform disc, operation point C, body frame, wheel units, labels.

    Parameters
    ----------
    ax : Axes
    robot : Robot
    beta : array (w,)
        Steering angles.
    pose : (psi, X, Y)
        Platform pose in the fixed frame.
    ghost : bool
        Draw dashed outlines only (an earlier or later pose).
    labels : bool
        Label C and the :math:`P_i` (with ``suffix``, e.g. ``"'"``).
    frame : bool
        Draw the body frame :math:`(\mathbf i, \mathbf j)` at C.
    radius : float, optional
        Platform radius (default :func:`platform_radius`).
    label_offsets : dict, optional
        Offsets in points for the labels ``"C"`` and ``1..w``.

    Returns
    -------
    RobotDrawing
    """
    beta = np.asarray(beta, dtype=float)
    g = robot_geometry(robot, beta, pose)
    R = radius or platform_radius(robot)
    offs = label_offsets or {}
    if platform:
        draw_platform(ax, g.C, R, ghost=ghost, zorder=zorder - 3)
    for k, u in enumerate(robot.wheels):
        draw_unit(ax, u, beta[k], pose, ghost=ghost, zorder=zorder + 0.01 * k, show_j=show_j)
    if show_C:
        draw_point(ax, g.C, None, size=4.5 if not ghost else 3.5, face="white" if ghost else None, zorder=zorder + 3)
    if frame and not ghost:
        fl = frame_length or 0.42 * R
        draw_frame(ax, g.C, pose[0], fl, zorder=zorder + 2)
    if labels:
        label(ax, g.C, f"$C{suffix}$", offset=offs.get("C", (-5, -5)), ha="right", va="top")
        if wheel_labels:
            for k in range(robot.w):
                e = g.i[k] if np.dot(g.i[k], g.P[k] - g.C) >= 0 else -g.i[k]
                dflt = (float(13 * e[0]), float(13 * e[1]))
                label(ax, g.P[k], f"$P_{{{k + 1}}}{suffix}$", offset=offs.get(k + 1, dflt), ha="center",
                      va="center")
    return g


def robot_extent(g, radius):
    """Points (n, 2) bounding a drawn robot: platform disc box and wheel centres +- one radius."""
    c = np.asarray(g.C)
    box = c + radius * np.array([[1, 1], [-1, -1], [1, -1], [-1, 1]])
    return np.vstack([box] + [np.asarray(w) for w in g.wheels])


def _outward_offset(v, dist):
    n = np.linalg.norm(v)
    if n == 0:
        return (dist, dist)
    e = v / n
    return (float(dist * e[0]), float(dist * e[1]))


def draw_axles(ax, g, include=None, **kw):
    """Dashed axle lines of a drawn robot (world), each extended to the points in ``include[k]``."""
    segs = []
    for k in range(len(g.P)):
        inc = () if include is None else include[k]
        segs.append(draw_line(ax, g.H[k], g.i[k], inc, kind="axle", **kw))
    return segs


def draw_planes(ax, g, include=None, **kw):
    """Wheel-plane lines (through :math:`P_i` along :math:`\\mathbf j_i`) of a drawn robot."""
    segs = []
    for k in range(len(g.P)):
        inc = () if include is None else include[k]
        segs.append(draw_line(ax, g.P[k], g.j[k], inc, kind="plane", **kw))
    return segs


def legend_handles(items):
    """Line2D proxies for a legend: items = [(text, kind)] with kind in axle|plane|path:<colour>|point:<colour>."""
    from matplotlib.lines import Line2D
    hs = []
    for text, kind in items:
        if kind == "axle":
            hs.append(Line2D([], [], color=ROLE["axle"], linestyle=(0, (5, 3)), linewidth=0.9, label=text))
        elif kind == "plane":
            hs.append(Line2D([], [], color=ROLE["plane"], linestyle=(0, (8, 2, 1.5, 2)), linewidth=0.9, label=text))
        elif kind.startswith("path:"):
            hs.append(Line2D([], [], color=kind[5:], linewidth=1.3, label=text))
        elif kind.startswith("point:"):
            hs.append(Line2D([], [], color=kind[6:], marker="o", markersize=4, linestyle="none", label=text))
        elif kind.startswith("marker:"):
            _, m, c = kind.split(":")
            hs.append(Line2D([], [], color=c, marker=m, markersize=5, linestyle="none", label=text))
    return hs


def polygon(ax, pts, **kw):
    """A filled polygon (n, 2)."""
    ax.add_patch(Polygon(np.asarray(pts, dtype=float), closed=True, **kw))
