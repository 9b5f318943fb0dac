r"""Swerve modules in wmr's terms, and the mapping to WPILib's.

A swerve module is a centred steered wheel (:class:`wmr.CentredWheel`): its steering angle
:math:`\beta_i` and its rolling rate :math:`\dot\theta_i` are the joint variables; a swerve robot is
a :class:`wmr.Robot` whose units are all centred wheels.

Conventions (wmr, :mod:`wmr.conventions`, and WPILib's ``SwerveDriveKinematics``)
-----------------------------------------------------------------------------------
Body frame
    wmr's body frame (origin C, :math:`\mathbf i` forward, :math:`\mathbf k` up, counter-clockwise
    positive) is WPILib's robot frame (x forward, y left, CCW positive); mount points
    :math:`\mathbf d_i` are WPILib's module ``Translation2d`` (metres, from the centre of rotation C).
Twist
    wmr's :math:`\mathbf t = [\dot\psi, \dot x, \dot y]` (body frame) is WPILib's robot-relative
    ``ChassisSpeeds(vx, vy, omega)`` with :math:`v_x = \dot x`, :math:`v_y = \dot y`,
    :math:`\omega = \dot\psi` (:func:`to_chassis`, :func:`from_chassis`).
Module angle
    wmr's :math:`\beta_i` is the angle of the **axle** :math:`\mathbf i_i = (\cos\beta_i, \sin\beta_i)`;
    no slip gives the wheel-centre velocity :math:`\dot{\mathbf h}_i = -r\dot\theta_i\mathbf j_i =
    r\dot\theta_i(\sin\beta_i, -\cos\beta_i)` (6).  WPILib's module angle :math:`\alpha_i` is the
    direction of the wheel's velocity for a positive speed :math:`s_i`:
    :math:`\dot{\mathbf h}_i = s_i(\cos\alpha_i, \sin\alpha_i)`.  Hence

    .. math:: \alpha_i = \beta_i - \tfrac{\pi}{2}, \qquad s_i = r_i\dot\theta_i

    (:func:`to_wpilib`, :func:`from_wpilib`).  ``wmr.steering_angles`` chooses
    :math:`\dot\theta_i \ge 0`, which is WPILib's ``toSwerveModuleStates`` (speed
    :math:`\|\dot{\mathbf p}_i\|`, angle of :math:`\dot{\mathbf p}_i`).
Speed
    Here a module's **speed** :math:`s_i = r_i\dot\theta_i` is signed (the ground speed of the wheel
    along :math:`-\mathbf j_i`, m/s); turning the module by :math:`\pi` and negating :math:`s_i` gives
    the same wheel velocity.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..analysis.kinematics import Solution, forward, inverse
from ..analysis.steering import steering_angles
from ..errors import InputValueError
from ..model import validation
from ..model.conventions import angle_from, angle_to
from ..model.robot import Robot
from ..model.types import ArrayLike, FloatArray, TwistLike

__all__ = [
    "ModuleCommand",
    "swerve_robot",
    "radii",
    "module_commands",
    "module_speeds",
    "chassis_twist",
    "to_wpilib",
    "from_wpilib",
    "to_chassis",
    "from_chassis",
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
    r"""Return ``robot`` (as numbers) if every unit is a swerve module: a steered wheel with one rolling rate.

    A swerve module steers to any angle and rolls in its wheel plane with one rate :math:`\dot\theta_i`,
    its speed :math:`r_i\dot\theta_i` (a :class:`wmr.CentredWheel`).

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

    Examples
    --------
    >>> import wmr
    >>> swerve_robot(wmr.paper_robot("offset")).w
    Traceback (most recent call last):
        ...
    wmr.errors.InputValueError: robot must have centred wheels only (swerve modules), got units ['offset', ...]
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
        Centred wheels only.

    Returns
    -------
    numpy.ndarray (w,)
    """
    robot = swerve_robot(robot)
    return np.array([float(u.r) for u in robot.wheels])


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
        is read by its fields as ``[omega, vx, vy]`` (:func:`wmr.model.arrays.twist_array`).
    current : array (..., w), optional
        Angles kept by modules whose mount point is still (default 0), as WPILib keeps the last heading.

    Returns
    -------
    ModuleCommand

    Examples
    --------
    >>> import wmr
    >>> bot = wmr.Robot([wmr.CentredWheel((x, y), r=0.05) for x, y in [(1, 1), (1, -1), (-1, 1), (-1, -1)]])
    >>> cmd = module_commands(bot, [0.0, 1.0, 0.0])          # forward at 1 m/s
    >>> np.degrees(cmd.beta).round(9).tolist(), cmd.speed.round(12).tolist()
    ([90.0, 90.0, 90.0, 90.0], [1.0, 1.0, 1.0, 1.0])
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


def to_wpilib(beta: ArrayLike, speed: ArrayLike | None = None) -> FloatArray | tuple[FloatArray, FloatArray]:
    r"""WPILib's module angle :math:`\alpha = \beta - \pi/2` (wrapped to :math:`(-\pi, \pi]`); speeds are the same.

    Parameters
    ----------
    beta : array (...)
        wmr's steering angles (axle directions).
    speed : array (...), optional
        Signed module speeds, returned unchanged (as an array).

    Returns
    -------
    numpy.ndarray or tuple
        ``alpha`` (...), or ``(alpha, speed)`` when ``speed`` is given.

    Examples
    --------
    >>> float(np.degrees(to_wpilib(np.pi / 2)))                 # axle along y: rolls forward
    0.0
    """
    alpha = angle_to(beta, "wpilib")
    return alpha if speed is None else (alpha, validation.finite_array("speed", speed))


def from_wpilib(alpha: ArrayLike, speed: ArrayLike | None = None) -> FloatArray | tuple[FloatArray, FloatArray]:
    r"""wmr's steering angle :math:`\beta = \alpha + \pi/2` (wrapped) from WPILib's module angle.

    Parameters
    ----------
    alpha : array (...)
        WPILib module angles (direction of travel at positive speed), radians.
    speed : array (...), optional
        Signed module speeds, returned unchanged (as an array).

    Returns
    -------
    numpy.ndarray or tuple
        ``beta`` (...), or ``(beta, speed)`` when ``speed`` is given.
    """
    beta = angle_from(alpha, "wpilib", "alpha")
    return beta if speed is None else (beta, validation.finite_array("speed", speed))


def to_chassis(twist: TwistLike) -> FloatArray:
    r"""WPILib's ``ChassisSpeeds`` order :math:`(v_x, v_y, \omega)` of a wmr twist :math:`[\dot\psi, \dot x, \dot y]`.

    Parameters
    ----------
    twist : array (..., 3)

    Returns
    -------
    numpy.ndarray (..., 3)

    Examples
    --------
    >>> to_chassis([3.0, 1.0, 2.0]).tolist()
    [1.0, 2.0, 3.0]
    """
    return np.roll(validation.twist_array("twist", twist), -1, axis=-1)


def from_chassis(chassis: TwistLike) -> FloatArray:
    r"""wmr's twist :math:`[\dot\psi, \dot x, \dot y]` from WPILib's :math:`(v_x, v_y, \omega)`.

    Parameters
    ----------
    chassis : array (..., 3) or ChassisSpeeds
        Numbers in WPILib's order, or a WPILib ``ChassisSpeeds`` itself (read by its fields).

    Returns
    -------
    numpy.ndarray (..., 3)

    Examples
    --------
    >>> from_chassis([1.0, 2.0, 3.0]).tolist()
    [3.0, 1.0, 2.0]
    """
    if validation.twist_kind(chassis) is not None:
        return validation.twist_array("chassis", chassis)
    return np.roll(validation.finite_array("chassis", chassis, last=3), 1, axis=-1)
