r"""Swerve modules in wmr's terms: angles and speeds of a twist (inverse kinematics), twist of angles and speeds.

A swerve module is a centred steered wheel (:class:`wmr.CentredWheel`).  Its speed is wmr's
:math:`s_i = r_i\dot\theta_i`, signed (the ground speed of the wheel along :math:`-\mathbf j_i`, m/s): turning a
module by :math:`\pi` and negating :math:`s_i` gives the same wheel velocity.  ``wmr.steering_angles`` chooses
:math:`\dot\theta_i \ge 0`, as WPILib's ``toSwerveModuleStates`` does.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..analysis.kinematics import Solution, forward, inverse
from ..analysis.steering import steering_angles
from ..errors import InputValueError
from ..model import validation
from ..model.robot import Robot
from ..model.types import ArrayLike, FloatArray, TwistLike

__all__ = [
    "ModuleCommand",
    "swerve_robot",
    "radii",
    "module_commands",
    "module_speeds",
    "chassis_twist",
]


@dataclass(frozen=True)
class ModuleCommand:
    r"""Steering angles and speeds of the modules of a swerve robot.

    Attributes
    ----------
    beta : numpy.ndarray (..., w)
        wmr's steering angles :math:`\beta_i` (axle directions), radians.
    speed : numpy.ndarray (..., w)
        Signed module speeds :math:`s_i = r_i\dot\theta_i`, m/s (wheel velocity
        :math:`s_i(\sin\beta_i, -\cos\beta_i)`).
    """

    beta: np.ndarray
    speed: np.ndarray


def swerve_robot(robot: Robot) -> Robot:
    """Return ``robot`` (as numbers) if every unit is a swerve module: a steered wheel with one rolling rate.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    Robot

    Raises
    ------
    wmr.errors.InputValueError
        If a unit is not a swerve module (an offset, dual, fixed or Swedish wheel).
    """
    robot = validation.numeric_robot(robot)
    if not all(u.steered and u.rolls_in_plane and u.n_rates == 1 for u in robot.wheels):
        kinds = [u.kind for u in robot.wheels]
        raise InputValueError(f"robot must have centred wheels only (swerve modules), got units {kinds}")
    return robot


def radii(robot: Robot) -> FloatArray:
    """Wheel radii of a swerve robot's modules.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    numpy.ndarray (w,)
    """
    return np.array([float(u.r) for u in swerve_robot(robot).wheels])


def module_speeds(robot: Robot, beta: ArrayLike, twist: TwistLike) -> FloatArray:
    r"""Module speeds :math:`s_i = r_i\dot\theta_i` that realise ``twist`` at the angles ``beta``.

    The least-squares rolling rates of :func:`wmr.inverse`: :math:`s_i` is the component of the
    mount-point velocity :math:`\dot{\mathbf p}_i = \dot{\mathbf c} + \dot\psi\mathbf E\mathbf d_i` (2)
    along the rolling direction :math:`-\mathbf j_i`, i.e. :math:`s_i = \dot{\mathbf p}_i\cdot(\sin\beta_i,
    -\cos\beta_i)` -- WPILib's ``cosineScale`` of the exact speed when :math:`\beta` is off target.

    Parameters
    ----------
    robot : Robot
        Centred wheels only.
    beta : array (..., w)
    twist : array (..., 3)
        :math:`[\dot\psi, \dot x, \dot y]`, body frame.

    Returns
    -------
    numpy.ndarray (..., w)
    """
    robot = swerve_robot(robot)
    return inverse(robot, beta, twist).value * radii(robot)


def module_commands(robot: Robot, twist: TwistLike, current: ArrayLike | None = None) -> ModuleCommand:
    r"""Inverse kinematics of a swerve robot: the angles and speeds of ``twist`` (WPILib's ``toSwerveModuleStates``).

    :math:`\beta_i` from :func:`wmr.steering_angles` (the wheel plane parallel to
    :math:`\dot{\mathbf p}_i`, :math:`\dot\theta_i \ge 0`) and :math:`s_i = \|\dot{\mathbf p}_i\|`.

    Parameters
    ----------
    robot : Robot
        Centred wheels only.
    twist : array (..., 3) or ChassisSpeeds
        :math:`[\dot\psi, \dot x, \dot y]`, body frame; a WPILib ``ChassisSpeeds`` (or a list of them)
        is read by its fields as ``[omega, vx, vy]`` (:func:`wmr.model.checks.twist_array`).
    current : array (..., w), optional
        Angles kept by modules whose mount point is still (default 0), as WPILib keeps the last heading.

    Returns
    -------
    ModuleCommand
    """
    robot = swerve_robot(robot)
    twist = validation.twist_array("twist", twist)
    m = np.abs(twist).max(axis=-1, keepdims=True)
    beta = steering_angles(robot, twist / np.where(m > 0, m, 1.0), current)  # angles: scale-free, no overflow
    return ModuleCommand(beta, module_speeds(robot, beta, twist))


def chassis_twist(robot: Robot, beta: ArrayLike, speed: ArrayLike) -> Solution:
    r"""Forward kinematics of a swerve robot (least squares): WPILib's ``toChassisSpeeds``.

    :math:`\mathbf t = \mathbf J_1^+\mathbf J_2\dot{\boldsymbol\theta}` with :math:`\dot\theta_i =
    s_i/r_i` (:func:`wmr.forward`); the residual :math:`\mathbf J_1\mathbf t - \mathbf J_2\dot{\boldsymbol\theta}`
    is the slip velocity of the modules (m/s, two entries per module).

    Parameters
    ----------
    robot : Robot
        Centred wheels only.
    beta : array (..., w)
    speed : array (..., w)
        Signed module speeds :math:`s_i`, m/s.

    Returns
    -------
    Solution
        ``value`` the twist (..., 3), ``residual`` (..., 2w), ``admissible`` (...).
    """
    robot = swerve_robot(robot)
    speed = validation.finite_array("speed", speed, last=robot.w)
    with np.errstate(over="ignore"):
        rates = speed / radii(robot)
    if not np.isfinite(rates).all():
        raise InputValueError(
            f"speed is too large for these wheel radii: the rolling rates overflow "
            f"(largest |speed| = {np.abs(speed).max():.3g})"
        )
    return forward(robot, beta, rates)
