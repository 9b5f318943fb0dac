"""Drawing shared by Figs. 10-12 (matplotlib): a configuration with its wheel-plane lines, axles and meeting points."""

from __future__ import annotations

import numpy as np

from wmr.plot import annotate as an
from wmr.plot import robot as rd
from wmr.plot.style import ROLE

from .common import snap

__all__ = ["draw_singular", "LINES_LEGEND"]

#: Legend entries of the construction lines and points of :func:`draw_singular`.
LINES_LEGEND = [("wheel plane", "plane"), ("axle", "axle"), ("axles cross", f"open:o:{ROLE['axle']}")]


def draw_singular(ax, robot, cfg, *, dp_label=None, dp_offset=(7, 3), frame=True, label_offsets=None):
    """Draw ``robot`` at ``cfg.beta`` with its wheel-plane lines, axles, axle crossings and :math:`D_P`.

    Parameters
    ----------
    ax : Axes
    robot : Robot
    cfg : edition.figures.configs.SingularConfig
    dp_label : str, optional
        Label of :math:`D_P` (drawn when the planes meet at a finite point).
    dp_offset : tuple (2,), optional
        Offset of that label (points).
    frame : bool, optional
        Draw the body frame at C.
    label_offsets : dict, optional
        As for :func:`wmr.plot.robot.draw_robot`.

    Returns
    -------
    g : wmr.plot.robot.RobotDrawing
    extent : numpy.ndarray (n, 2)
        Points the view must contain.
    """
    g = rd.draw_robot(ax, robot, cfg.beta, frame=frame, label_offsets=label_offsets, arrows="j")
    rd.draw_planes(ax, g, include=cfg.plane_reach, margin=0.3, min_half=0.6)
    rd.draw_axles(ax, g, include=cfg.axle_reach, margin=0.3, min_half=0.6)
    ext = [rd.robot_extent(g, rd.platform_radius(robot))]
    for pt in snap(np.reshape(cfg.axle_crossings, (-1, 2))):
        an.draw_point(ax, pt, None, marker="o", color=ROLE["axle"], size=4.5, face="white", zorder=8)
        ext.append(pt[None])
    if cfg.D_P is not None:
        D = snap(cfg.D_P)
        an.draw_point(ax, D, dp_label, marker="D", color=ROLE["dp"], size=5.5, offset=dp_offset, zorder=8.6)
        ext.append(D[None])
    return g, np.vstack(ext)
