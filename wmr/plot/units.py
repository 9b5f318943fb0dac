r"""The parts of a robot seen from above: the platform disc, and each wheel unit drawn part by part.

A unit's parts come from its kind's entry in :func:`wmr.plot.parts.unit_parts`, so any wheel kind with one is drawn;
:mod:`wmr.plot.robot` assembles them into the robot.
"""

from __future__ import annotations

import numpy as np
from matplotlib.patches import Circle, FancyArrowPatch, FancyBboxPatch
from matplotlib.transforms import Affine2D

from ..errors import InputTypeError, InputValueError
from .geometry import to_world
from .parts import Disc, Link, Pivot, Rollers, drawn_angle, unit_parts
from .snapping import snap
from .style import PALETTE, ROLE

__all__ = ["draw_unit"]


def draw_platform(ax, centre, radius, *, ghost=False, zorder=1.0):
    """The platform as a disc (dashed outline only when ``ghost``: an earlier or later pose)."""
    ax.add_patch(
        Circle(
            centre,
            radius,
            facecolor="none" if ghost else ROLE["platform_face"],
            edgecolor=ROLE["platform_edge"],
            linewidth=0.8 if ghost else 0.9,
            linestyle=(0, (4, 3)) if ghost else "-",
            zorder=zorder,
        )
    )


def draw_wheel(
    ax,
    centre,
    heading,
    r,
    width=None,
    *,
    ghost=False,
    arrow=True,
    zorder=4.0,
    color=None,
    light=False,
    towards="travel",
):
    r"""A wheel disc from above: a rounded rectangle 2r long along :math:`\mathbf j_i`, world angle ``heading``.

    Width 0.42 r by default; ``ghost`` dashed outline only, ``light`` a light grey face.  The arrow points the way the
    wheel moves at a positive rolling rate, :math:`-\mathbf j_i` (6), for ``towards="travel"``, or along
    :math:`+\mathbf j_i` for ``"j"``.
    """
    w = 0.42 * r if width is None else width
    col = color or ROLE["wheel"]
    face = "none" if ghost else ("#D4D4D4" if light else col)
    box = FancyBboxPatch(
        (-w / 2, -r),
        w,
        2 * r,
        boxstyle=f"round,pad=0,rounding_size={0.45 * w}",
        facecolor=face,
        edgecolor=col,
        linewidth=0.8,
        linestyle=(0, (3, 2)) if ghost else "-",
        zorder=zorder,
    )
    # the placement is snapped here: snap_figure sees the box in its own frame, not this transform
    box.set_transform(Affine2D().rotate(float(snap(heading))).translate(*snap(centre).tolist()) + ax.transData)
    ax.add_patch(box)
    if arrow and not ghost:
        if towards not in ("travel", "j"):
            raise InputValueError(f"towards must be 'travel' or 'j', got {towards!r}")
        jdir = np.array([-np.sin(heading), np.cos(heading)]) * (1.0 if towards == "j" else -1.0)
        c = np.asarray(centre, dtype=float)
        ax.add_patch(
            FancyArrowPatch(
                c - 0.62 * r * jdir,
                c + 0.72 * r * jdir,
                arrowstyle="-|>",
                mutation_scale=5.5,
                color=PALETTE["dark"] if light else "white",
                linewidth=0.8,
                shrinkA=0,
                shrinkB=0,
                zorder=zorder + 0.1,
            )
        )


def draw_pivot(ax, p, size, *, ghost=False, zorder=5.0):
    """The steering axis at :math:`P_i` (world): a white disc of radius ``size`` with a dark rim."""
    ax.add_patch(
        Circle(
            p, size, facecolor="white" if not ghost else "none", edgecolor=PALETTE["dark"], linewidth=0.8, zorder=zorder
        )
    )
    if not ghost:
        ax.add_patch(Circle(p, 0.28 * size, facecolor=PALETTE["dark"], edgecolor="none", zorder=zorder + 0.1))


def draw_unit(
    ax, unit, beta, pose=(0.0, 0.0, 0.0), *, ghost=False, zorder=4.0, show_j=True, light=False, arrows="travel"
):
    r"""One wheel unit: its parts (:func:`wmr.plot.parts.unit_parts`), each drawn by its type, placed by ``pose``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    unit : wheel unit
        One of ``robot.wheels``.
    beta : float
        Its steering angle (radians); a unit without a steering joint is drawn at its own angle.
    pose : sequence (3,), optional
        :math:`(\psi, X, Y)`.
    ghost, show_j, light : bool, optional
        Dashed outlines only; mark the rolling direction on each wheel; light grey wheels (close-ups).
    zorder : float, optional
    arrows : {"travel", "j"}, optional
        Where the wheels' arrows point (:func:`draw_wheel`'s ``towards``).

    Returns
    -------
    P, H : numpy.ndarray (2,)
        The unit's steering-axis point and centre (world).
    """
    beta = drawn_angle(unit, beta)
    pts = unit.points(beta)
    lw = 2.2 if not ghost else 1.0
    ls = "-" if not ghost else (0, (3, 2))
    for part in unit_parts(unit, beta):
        if isinstance(part, Link):
            ends = to_world(pose, part.ends)
            if part.over:  # an arm, over the wheel
                ax.plot(
                    *ends.T,
                    color=ROLE["body"] if not light else PALETTE["dark"],
                    linewidth=lw,
                    linestyle=ls,
                    solid_capstyle="round",
                    zorder=zorder + 0.5,
                )
            else:  # a bar between wheels, under them
                ax.plot(*ends.T, color=ROLE["body"], linewidth=lw, linestyle=ls, zorder=zorder - 0.1)
        elif isinstance(part, Disc):
            draw_wheel(
                ax,
                to_world(pose, part.centre),
                pose[0] + part.heading,
                part.r,
                ghost=ghost,
                arrow=show_j and part.arrow,
                zorder=zorder,
                light=light,
                towards=arrows,
            )
        elif isinstance(part, Rollers):
            _draw_rollers(ax, to_world(pose, part.centre), pose[0] + part.heading, part.r, part.angle, zorder + 0.1)
        elif isinstance(part, Pivot):
            draw_pivot(ax, to_world(pose, part.point), 0.16 * part.r, ghost=ghost, zorder=zorder + 1)
        else:
            raise InputTypeError(
                f"unit_parts(unit) must give Disc, Link, Rollers or Pivot parts, got {type(part).__name__}"
            )
    return to_world(pose, pts["P"]), to_world(pose, pts["H"])


def _draw_rollers(ax, centre, heading, r, angle, zorder):
    """Three white strokes across a wheel disc along its roller axes (world angle ``heading + angle``)."""
    a = heading + angle
    half = min(0.21 * r / max(abs(np.cos(angle)), 1e-3), 0.25 * r)  # across the tyre
    ends = half * np.array([np.cos(a), np.sin(a)])
    jdir = np.array([-np.sin(heading), np.cos(heading)])
    for k in (-0.6, 0.0, 0.6):
        m = centre + k * r * jdir
        ax.plot(*np.stack([m - ends, m + ends]).T, color="white", linewidth=0.8, zorder=zorder)
