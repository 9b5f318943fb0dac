r"""A robot's lines: axle and wheel-plane lines, where they meet, and the angles that put them through a point.

Part of :mod:`wmr.analysis.lines`.
"""

from __future__ import annotations

import numpy as np

from ...errors import InputTypeError, InputValueError
from ...model import validation
from ...model.platform import line_angle
from ...model.robot import Robot
from ...model.tolerance import TOL
from ...model.types import ArrayLike, FloatArray
from .geometry import Concurrency, lines_concurrency

__all__ = [
    "wheel_plane_lines",
    "axle_lines",
    "concurrency_point",
    "axles_concurrency",
    "planes_through",
    "axles_through",
    "pair_line_angle",
]


def _lines(robot, beta, at, along):
    """Points ``at`` and directions ``along`` (keys of ``unit.points``) of the units of a checked robot at checked ``beta``."""
    pts = [u.points(beta[..., i]) for i, u in enumerate(robot.wheels)]
    return np.stack([p[at] for p in pts], axis=-2), np.stack([p[along] for p in pts], axis=-2)


def wheel_plane_lines(robot: Robot, beta: ArrayLike) -> tuple[FloatArray, FloatArray]:
    r"""Wheel-plane lines :math:`\ell_i`: through :math:`P_i` along :math:`\mathbf j_i`.

    (For an offset wheel the line also passes through :math:`H_i = P_i - d\mathbf j_i`; for a dual
    wheel it is the unit's mid-plane.)

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)

    Returns
    -------
    points : numpy.ndarray (..., w, 2)
    directions : numpy.ndarray (..., w, 2)
        Unit vectors :math:`\mathbf j_i`.
    """
    robot = validation.numeric_robot(robot)
    return _lines(robot, robot.effective_beta(beta), "P", "j")


def axle_lines(robot: Robot, beta: ArrayLike) -> tuple[FloatArray, FloatArray]:
    r"""Axle lines: through each wheel centre along :math:`\mathbf i_i` (centred: through :math:`P_i`).

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)

    Returns
    -------
    points : numpy.ndarray (..., w, 2)
        Wheel centres :math:`H_i` (body frame).
    directions : numpy.ndarray (..., w, 2)
    """
    robot = validation.numeric_robot(robot)
    return _lines(robot, robot.effective_beta(beta), "H", "i")


def _one(robot, beta, what):
    robot = validation.numeric_robot(robot)
    if robot.w < 2:
        raise InputValueError(
            f"robot must have at least two wheel units for {what} (lines to meet), got {validation.show(robot)}"
        )
    beta = robot.effective_beta(beta)
    if beta.ndim != 1:
        raise InputValueError(
            f"beta must be one configuration of shape ({robot.w},) for {what}, got shape {beta.shape}"
        )
    return robot, beta


def concurrency_point(robot: Robot, beta: ArrayLike) -> Concurrency:
    r"""The point :math:`D_P` where the wheel-plane lines meet (one configuration).

    Parameters
    ----------
    robot : Robot
    beta : array (w,)

    Returns
    -------
    Concurrency
        For three centred wheels ``kind == NONE`` exactly when :math:`\det\mathbf J \ne 0`.
    """
    robot, beta = _one(robot, beta, "concurrency_point")
    return lines_concurrency(*_lines(robot, beta, "P", "j"))


def axles_concurrency(robot: Robot, beta: ArrayLike) -> Concurrency:
    """Where the axle lines meet (one configuration): the instantaneous centre when the robot can move.

    Parameters
    ----------
    robot : Robot
    beta : array (w,)

    Returns
    -------
    Concurrency
    """
    robot, beta = _one(robot, beta, "axles_concurrency")
    return lines_concurrency(*_lines(robot, beta, "H", "i"))


def planes_through(robot: Robot, D: ArrayLike) -> FloatArray:
    r"""Steering angles whose wheel-plane lines all pass through the point D (body frame).

    :math:`\mathbf j_i \parallel D - P_i`, with :math:`\beta_i\in(-\pi/2, \pi/2]` (the other choice,
    :math:`\beta_i + \pi`, gives the same line).  Where :math:`D = P_i` the angle is free and 0 is
    returned.

    Parameters
    ----------
    robot : Robot
    D : array (..., 2)

    Returns
    -------
    numpy.ndarray (..., w)
        (Fixed and Swedish wheels cannot turn: their entries are their own angles.)
    """
    return _through(robot, validation.finite_array("D", D, last=2), planes=True)


def axles_through(robot: Robot, U: ArrayLike) -> FloatArray:
    r"""Steering angles whose axles all pass through U (body frame): rotation about U is admissible.

    Parameters
    ----------
    robot : Robot
    U : array (..., 2)

    Returns
    -------
    numpy.ndarray (..., w), in :math:`(-\pi/2, \pi/2]`
        (except fixed and Swedish wheels: their own angles).
    """
    return _through(robot, validation.finite_array("U", U, last=2), planes=False)


def _through(robot, X, planes):
    """Angles whose wheel planes (or axles) pass through X; 0 where X is a mount point (within TOL)."""
    robot = validation.numeric_robot(robot)
    v = X[..., None, :] - robot.mount_points  # (..., w, 2)
    # planes: j = (-sin b, cos b) || v; axles: i = (cos b, sin b) || v
    beta = np.arctan2(-v[..., 0], v[..., 1]) if planes else np.arctan2(v[..., 1], v[..., 0])
    size = np.maximum(np.abs(robot.mount_points).max(), np.abs(X).max(axis=-1, keepdims=True))
    beta = np.where(np.abs(v).max(axis=-1) <= TOL * size, 0.0, beta)
    return robot.effective_beta(line_angle(beta))  # fixed, Swedish: their own angle


def pair_line_angle(robot: Robot, i: int, j: int) -> float:
    r"""The steering angle in :math:`(-\pi/2,\pi/2]` that puts the plane of wheel i on the line :math:`P_iP_j`.

    Wheels are numbered from 1.

    Parameters
    ----------
    robot : Robot
    i, j : int
        Wheel numbers, 1-based, distinct.

    Returns
    -------
    float
    """
    robot = validation.numeric_robot(robot)
    for name, k in (("i", i), ("j", j)):
        if isinstance(k, bool) or not isinstance(k, (int, np.integer)):
            raise InputTypeError(f"{name} must be a wheel number (int), got {k!r}")
        if not 1 <= k <= robot.w:
            raise InputValueError(f"{name} must be a wheel number in 1..{robot.w}, got {k!r}")
    if i == j:
        raise InputValueError(f"i and j must be two different wheels, got i = j = {i}")
    return float(planes_through(robot, robot.mount_points[j - 1])[i - 1])
