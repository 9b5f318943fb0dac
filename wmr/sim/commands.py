r"""Joint commands from wmr's inverse kinematics: what the servos must do for a commanded twist.

For a constant body twist, :func:`twist_schedule` integrates the model (:func:`wmr.integrate`) with the joint rates
of :func:`wmr.inverse`: centred and dual wheels keep the angles of :func:`wmr.steering_angles`, an offset wheel steers
at :math:`\dot\beta_i = \dot\phi_i - \dot\psi` (7).  Its angles and rates are the servos' targets.
"""

from __future__ import annotations

import numpy as np

from ..analysis.integration import integrate
from ..analysis.kinematics import inverse
from ..analysis.steering import steering_angles
from ..model import validation
from ..model.platform import point_velocity
from ..model.robot import Robot
from ..model.types import ArrayLike, FloatArray, TwistLike
from .recording import Schedule

__all__ = ["start_angles", "twist_schedule"]


def start_angles(robot: Robot, twist: TwistLike) -> FloatArray:
    r"""Steering angles to start a constant twist from.

    Units that roll in their plane (centred and dual wheels): :func:`wmr.steering_angles`.  Other steered units
    (offset wheels): trailing, :math:`\mathbf j_i` along :math:`\dot{\mathbf p}_i` (the arm behind :math:`P_i`, as a
    castor settles; a still mount point keeps 0).  Units without a steering joint: their own angle.

    Parameters
    ----------
    robot : Robot
    twist : array (3,)
        :math:`[\dot\psi, \dot x, \dot y]`, body frame.

    Returns
    -------
    numpy.ndarray (w,)
    """
    robot = validation.numeric_robot(robot)
    twist = validation.finite_array("twist", twist, last=3).reshape(3)
    beta = np.array(steering_angles(robot, twist), dtype=float)
    pdot = point_velocity(twist, robot.mount_points)  # (2): c_dot + psi_dot E d_i
    for i, u in enumerate(robot.wheels):
        if u.steered and not u.rolls_in_plane and np.hypot(*pdot[i]) > 0:
            beta[i] = np.arctan2(-pdot[i, 0], pdot[i, 1])  # j_i = (-sin, cos) along p_dot_i
    return beta


def twist_schedule(
    robot: Robot, twist: TwistLike, seconds: float, beta0: ArrayLike | None = None, dt: float = 0.05
) -> Schedule:
    r"""The joint commands of a constant body twist, from wmr's inverse kinematics (module docstring).

    Parameters
    ----------
    robot : Robot
    twist : array (3,)
        :math:`[\dot\psi, \dot x, \dot y]`, body frame.
    seconds : float
        Duration, > 0.
    beta0 : array (w,), optional
        Initial steering angles (default :func:`start_angles`).
    dt : float
        Knot spacing, s.

    Returns
    -------
    Schedule
    """
    robot = validation.numeric_robot(robot)
    twist = validation.finite_array("twist", twist, last=3).reshape(3)
    b0 = (
        start_angles(robot, twist)
        if beta0 is None
        else validation.finite_array("beta0", beta0, last=robot.w).reshape(robot.w)
    )
    traj = integrate(robot, lambda t, state: inverse(robot, state[1], twist).value, b0, seconds, dt)
    rates = inverse(robot, traj.beta, twist).value
    return Schedule(traj.t, traj.beta, rates)
