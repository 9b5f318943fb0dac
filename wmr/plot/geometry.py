r"""Where a robot drawn from above is: world coordinates of its points and axes, the platform disc, the extent.

No matplotlib: :func:`robot_geometry` computes what :func:`wmr.plot.robot.draw_robot` draws (a
:class:`RobotDrawing`), from the units' :meth:`~wmr.model.wheels.WheelUnit.points`, so the
labels and construction lines of a figure can be placed before anything is drawn.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model.backend import NUMERIC
from ..model.platform import rotation

__all__ = ["RobotDrawing", "robot_geometry", "platform_radius", "robot_extent"]


def to_world(pose, p):
    r"""Body-frame points (..., 2) in the fixed frame: :math:`\mathbf R(\psi)\,p + [X\ Y]^T`, pose :math:`(\psi, X, Y)`."""
    psi, X, Y = pose
    return np.asarray(p, dtype=float) @ rotation(psi, NUMERIC).T + np.array([X, Y])


@dataclass(frozen=True)
class RobotDrawing:
    r"""World coordinates of a drawn robot (for labels and construction lines).

    Attributes
    ----------
    C : numpy.ndarray (2,)
        The operation point.
    P : numpy.ndarray (w, 2)
        Steering-axis points :math:`P_i`.
    H : numpy.ndarray (w, 2)
        Wheel-unit centres :math:`H_i`.
    wheels : list of numpy.ndarray (k, 2)
        Wheel centres of each unit.
    i : numpy.ndarray (w, 2)
        Axle directions :math:`\mathbf i_i` (world).
    j : numpy.ndarray (w, 2)
        Rolling directions :math:`\mathbf j_i` (world).
    psi : float
        Heading of the platform (radians).
    """

    C: np.ndarray
    P: np.ndarray
    H: np.ndarray
    wheels: list
    i: np.ndarray
    j: np.ndarray
    psi: float


def robot_geometry(robot, beta, pose=(0.0, 0.0, 0.0)):
    r"""World geometry of a numeric ``robot`` at steering angles ``beta`` and ``pose`` (nothing is drawn).

    Parameters
    ----------
    robot : wmr.Robot
    beta : array_like (w,)
    pose : sequence (3,), optional
        :math:`(\psi, X, Y)`.

    Returns
    -------
    RobotDrawing
    """
    beta = np.asarray(beta, dtype=float)
    R = rotation(pose[0], NUMERIC)
    P, H, wheels, ii, jj = [], [], [], [], []
    for k, u in enumerate(robot.wheels):
        pts = u.points(beta[k])
        P.append(to_world(pose, pts["P"]))
        H.append(to_world(pose, pts["H"]))
        wheels.append(to_world(pose, pts["wheels"]))
        ii.append(R @ pts["i"])
        jj.append(R @ pts["j"])
    return RobotDrawing(
        np.array(pose[1:], dtype=float), np.array(P), np.array(H), wheels, np.array(ii), np.array(jj), float(pose[0])
    )


def platform_radius(robot):
    r"""Radius of the platform disc, beyond the farthest mount point: :math:`\max_i\|\mathbf d_i\| + 0.9\max_i r_i`.

    Parameters
    ----------
    robot : wmr.Robot

    Returns
    -------
    float
    """
    d = np.linalg.norm(robot.mount_points, axis=1).max()
    r = max(float(u.r) for u in robot.wheels)
    return float(d + 0.9 * r)


def robot_extent(g, radius):
    """Points bounding a drawn robot: the box around the platform disc of ``radius`` and the wheel centres.

    Parameters
    ----------
    g : RobotDrawing
    radius : float

    Returns
    -------
    numpy.ndarray (4 + n_wheels, 2)
    """
    c = np.asarray(g.C)
    box = c + radius * np.array([[1, 1], [-1, -1], [1, -1], [-1, 1]])
    return np.vstack([box] + [np.asarray(w) for w in g.wheels])
