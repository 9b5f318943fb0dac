r"""The robot seen from above: platform, C and body frame, wheel units, labels, axle and wheel-plane lines.

The geometry comes from :mod:`wmr.plot.geometry` (no matplotlib), each unit's drawing from :mod:`wmr.plot.units`;
both modules' public names are re-exported here.
"""

from __future__ import annotations

import numpy as np

from .geometry import RobotDrawing, platform_radius, robot_extent, robot_geometry
from .lines import draw_line
from .marks import draw_frame, draw_point, label
from .snapping import snap
from .units import draw_platform, draw_unit

__all__ = [
    "RobotDrawing",
    "robot_geometry",
    "platform_radius",
    "draw_unit",
    "draw_robot",
    "robot_extent",
    "draw_axles",
    "draw_planes",
]


# ----------------------------------------------------------------------------- the robot
def draw_robot(
    ax,
    robot,
    beta,
    pose=(0.0, 0.0, 0.0),
    *,
    ghost=False,
    labels=True,
    suffix="",
    frame=True,
    frame_length=None,
    platform=True,
    radius=None,
    show_C=True,
    show_j=True,
    arrows="travel",
    zorder=4.0,
    wheel_labels=True,
    label_offsets=None,
):
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
        Dashed outlines only (an earlier or later pose).
    labels, wheel_labels : bool
        Label C and (with ``wheel_labels``) the :math:`P_i`, each followed by ``suffix`` (e.g. ``"'"``).
    suffix : str, optional
    frame, platform, show_C, show_j : bool, optional
        Draw the body frame at C, the platform disc, the point C, the rolling direction on each wheel.
    frame_length, radius : float, optional
        Length of the frame arrows (default 0.42 radius) and platform radius (default :func:`platform_radius`).
    label_offsets : dict, optional
        Offsets in points of the labels ``"C"`` and ``1..w`` (default for :math:`P_i`: 17 points along the axle
        and 10 along the wheel plane, away from C, clear of both lines).
    arrows : {"travel", "j"}, optional
        Where the wheels' arrows point: the way each wheel moves at a positive rolling rate (default), or
        the paper's :math:`+\mathbf j_i`.
    zorder : float, optional

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
        draw_unit(ax, u, beta[k], pose, ghost=ghost, zorder=zorder + 0.01 * k, show_j=show_j, arrows=arrows)
    if show_C:
        draw_point(ax, g.C, None, size=4.5 if not ghost else 3.5, face="white" if ghost else None, zorder=zorder + 3)
    if frame and not ghost:
        fl = frame_length or 0.42 * R
        draw_frame(ax, g.C, pose[0], fl, zorder=zorder + 2)
    if labels:
        label(ax, g.C, f"$C{suffix}$", offset=offs.get("C", (-5, -5)), ha="right", va="top")
        if wheel_labels:
            for k in range(robot.w):
                out = g.P[k] - g.C  # beside the wheel, off the axle line, away from C
                # the sides are decided on snapped products: a product that is zero but for round-off
                # (a wheel plane through C) picks the same side on every machine
                e = 17 * g.i[k] * (1 if snap(g.i[k] @ out) >= 0 else -1) + 10 * g.j[k] * (
                    1 if snap(g.j[k] @ out) >= 0 else -1
                )
                dflt = (float(e[0]), float(e[1]))
                label(ax, g.P[k], f"$P_{{{k + 1}}}{suffix}$", offset=offs.get(k + 1, dflt), ha="center", va="center")
    return g


def _draw_lines(ax, points, directions, include, kind, **kw):
    """One line per unit through ``points[k]`` along ``directions[k]``, extended to the points ``include[k]``."""
    return [
        draw_line(ax, p, u, () if include is None else include[k], kind=kind, **kw)
        for k, (p, u) in enumerate(zip(points, directions))
    ]


def draw_axles(ax, g, include=None, **kw):
    r"""Dashed axle lines of a drawn robot (world): through :math:`H_i` along :math:`\mathbf i_i`.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    g : RobotDrawing
    include : sequence of sequences of array_like (2,), optional
        ``include[k]``: points the k-th line must reach (e.g. the instantaneous centre).
    **kw
        Passed to :func:`wmr.plot.lines.draw_line`.

    Returns
    -------
    list of numpy.ndarray (2, 2)
        The end points of each line drawn.
    """
    return _draw_lines(ax, g.H, g.i, include, "axle", **kw)


def draw_planes(ax, g, include=None, **kw):
    r"""Wheel-plane lines of a drawn robot (world): through :math:`P_i` along :math:`\mathbf j_i` (as :func:`draw_axles`).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    g : RobotDrawing
    include : sequence of sequences of array_like (2,), optional
    **kw

    Returns
    -------
    list of numpy.ndarray (2, 2)
    """
    return _draw_lines(ax, g.P, g.j, include, "plane", **kw)
