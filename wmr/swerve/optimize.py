r"""Which way to turn each module: WPILib's per-module ``optimize`` and a robot-level choice.

A module realises the same wheel velocity at :math:`\beta_i` with speed :math:`s_i` and at :math:`\beta_i + \pi`
with :math:`-s_i`.  WPILib's ``SwerveModuleState.optimize`` picks, module by module, the one nearer the current
angle; near a turn of :math:`\pi/2` neighbouring modules can then turn opposite ways, and while they turn their
wheel planes share no instantaneous centre and the wheels slip.  :func:`optimize_robot` chooses all flips together.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.platform import wrap_angle
from ..model.robot import Robot
from ..model.types import ArrayLike, FloatArray, TwistLike
from .modules import chassis_twist, module_commands, swerve_robot

__all__ = ["SteeringChoice", "optimize_modules", "optimize_robot", "transition_slip", "MAX_MODULES"]

#: Most modules :func:`optimize_robot` enumerates (:math:`2^w` patterns).
MAX_MODULES = 10


@dataclass(frozen=True)
class SteeringChoice:
    r"""Target angles and speeds of the modules, chosen from their current angles.

    Attributes
    ----------
    beta : numpy.ndarray (..., w)
        Target steering angles, in :math:`(-\pi, \pi]`.
    speed : numpy.ndarray (..., w)
        Signed module speeds at the targets, m/s.
    flipped : numpy.ndarray of bool (..., w)
        Modules turned to :math:`\beta_i + \pi` with the speed reversed (relative to
        :func:`~wmr.swerve.modules.module_commands`, whose speeds are :math:`\ge 0`).
    resteer : numpy.ndarray (...)
        Total turn :math:`\sum_i|\Delta_i|`, radians.
    slip : numpy.ndarray (...)
        Mean relative slip :math:`\bar\sigma` of the transition (:func:`transition_slip`).
    """

    beta: np.ndarray
    speed: np.ndarray
    flipped: np.ndarray
    resteer: np.ndarray
    slip: np.ndarray


def transition_slip(
    robot: Robot, current: ArrayLike, beta: ArrayLike, speed: ArrayLike, samples: int = 8
) -> FloatArray:
    r"""Mean relative slip :math:`\bar\sigma` while the modules turn from ``current`` to ``beta`` at one common rate.

    The modules turn along their shorter arcs :math:`\Delta_i = \operatorname{wrap}(\beta_i - \beta^0_i)`,
    :math:`\beta_i(\tau) = \beta^0_i + \operatorname{clip}(\Delta_i, -\tau, \tau)`, driven at ``speed``; at
    ``samples`` midpoints :math:`\tau_k = (k + \tfrac12)\max|\Delta|/K`, :math:`\sigma = \|\mathbf J_1\mathbf t -
    \mathbf J_2\dot{\boldsymbol\theta}\| / \|\mathbf J_2\dot{\boldsymbol\theta}\| \in [0, 1]` (the residual of
    (21), :func:`wmr.forward`; 0 for zero speeds); :math:`\bar\sigma` is their mean.

    Parameters
    ----------
    robot : Robot
        Centred wheels only.
    current, beta : array (..., w)
        Angles now and target angles.
    speed : array (..., w)
        Signed module speeds during the transition (those of the targets), m/s.
    samples : int, optional
        Samples along the transition.

    Returns
    -------
    numpy.ndarray (...)
        In :math:`[0, 1]`; 0 when no module turns and the targets are admissible.
    """
    robot = swerve_robot(robot)
    w = robot.w
    current = validation.finite_array("current", current, last=w)
    beta = validation.finite_array("beta", beta, last=w)
    speed = validation.finite_array("speed", speed, last=w)
    samples = validation.integer("samples", samples, minimum=1)
    validation.batch_shape({"current": current, "beta": beta, "speed": speed})
    return _slip(robot, current, beta, speed, samples)


def _slip(robot, current, beta, speed, samples):
    """:func:`transition_slip` of checked arrays (..., w) that broadcast together."""
    batch = np.broadcast_shapes(current.shape, beta.shape, speed.shape)[:-1]
    delta = wrap_angle(beta - current)  # (..., w), shorter arcs
    span = np.abs(delta).max(axis=-1, keepdims=True)  # (..., 1)
    tau = (np.arange(samples) + 0.5) / samples * span  # (..., K)
    path = current[..., None, :] + np.clip(delta[..., None, :], -tau[..., None], tau[..., None])  # (..., K, w)
    s = np.broadcast_to(speed, batch + (robot.w,))[..., None, :]
    m = np.abs(s).max(axis=-1, keepdims=True)
    s = s / np.where(m > 0, m, 1.0)  # the ratio is scale-free: no overflow
    sol = chassis_twist(robot, path, s)  # (21) least squares at each sample
    size = np.linalg.norm(s, axis=-1)  # |J2 theta_dot| = |s|
    rel = np.linalg.norm(sol.residual, axis=-1) / np.where(size > 0, size, 1.0)
    return np.minimum(rel, 1.0).mean(axis=-1)


def _targets(robot, twist, current):
    """The checked robot, the module commands of ``twist`` and the current angles broadcast to their shape."""
    robot = swerve_robot(robot)
    current = validation.finite_array("current", current, last=robot.w)
    cmd = module_commands(robot, twist, current)
    cur = np.broadcast_to(current, cmd.beta.shape)
    return robot, cmd, cur


def optimize_modules(robot: Robot, twist: TwistLike, current: ArrayLike) -> SteeringChoice:
    r"""WPILib's ``SwerveModuleState.optimize``, module by module.

    Module :math:`i` flips (:math:`\beta_i + \pi`, speed :math:`-s_i`) exactly when
    :math:`|\operatorname{wrap}(\beta_i - \beta^0_i)| > \pi/2`, so that no module turns more than
    :math:`\pi/2`.

    Parameters
    ----------
    robot : Robot
        Centred wheels only.
    twist : array (..., 3)
        Commanded :math:`[\dot\psi, \dot x, \dot y]`, body frame.
    current : array (..., w)
        Current steering angles :math:`\beta^0`.

    Returns
    -------
    SteeringChoice
    """
    robot, cmd, cur = _targets(robot, twist, current)
    flip = np.abs(wrap_angle(cmd.beta - cur)) > np.pi / 2
    beta, speed, resteer, slip = _flipped(robot, cmd.beta, cmd.speed, cur, flip, 8)
    return SteeringChoice(beta, speed + 0.0, flip, resteer, slip)


def _flipped(robot, beta, speed, cur, flip, samples):
    """Targets, speeds, total re-steer and transition slip of the flip patterns ``flip`` (broadcast with ``beta``)."""
    beta = wrap_angle(beta + np.pi * flip)
    speed = np.where(flip, -speed, speed)
    resteer = np.abs(wrap_angle(beta - cur)).sum(axis=-1)
    return beta, speed, resteer, _slip(robot, cur, beta, speed, samples)


def optimize_robot(robot: Robot, twist: TwistLike, current: ArrayLike, samples: int = 8) -> SteeringChoice:
    r"""Robot-level steering choice: all modules' flips together, minimising re-steer plus transition slip.

    Over the :math:`2^w` flip patterns :math:`\mathbf f \in \{0, 1\}^w` (targets :math:`\beta_i + f_i\pi`, speeds
    :math:`(-1)^{f_i}s_i`, turns :math:`\Delta_i`), minimises :math:`J(\mathbf f) = \sum_i|\Delta_i| +
    w\,\bar\sigma(\mathbf f)`, the total re-steer plus :math:`w` times the transition slip
    (:func:`transition_slip`); ties go to the fewest flips.

    Parameters
    ----------
    robot : Robot
        Centred wheels only, at most :data:`MAX_MODULES`.
    twist : array (..., 3)
        Commanded :math:`[\dot\psi, \dot x, \dot y]`, body frame.
    current : array (..., w)
        Current steering angles :math:`\beta^0`.
    samples : int, optional
        Samples of each transition (:func:`transition_slip`).

    Returns
    -------
    SteeringChoice

    Examples
    --------
    >>> import wmr
    >>> bot = wmr.Robot([wmr.CentredWheel((x, y), r=0.05) for x, y in [(1, 1), (1, -1), (-1, 1), (-1, -1)]])
    >>> now = np.radians([89.0, 91.0, 89.0, 91.0])          # driving forward, encoders off by 1 degree
    >>> left = [0.0, 0.0, 1.0]                               # now drive left: a 90 degree change
    >>> optimize_modules(bot, left, now).flipped.tolist()    # neighbours turn opposite ways
    [True, False, True, False]
    >>> optimize_robot(bot, left, now).flipped.tolist()      # one sense for all
    [False, False, False, False]
    """
    robot, cmd, cur = _targets(robot, twist, current)
    w = robot.w
    if w > MAX_MODULES:
        raise InputValueError(
            f"robot has {w} modules: optimize_robot enumerates 2^w patterns, at most {MAX_MODULES} modules"
        )
    samples = validation.integer("samples", samples, minimum=1)
    flips = ((np.arange(2**w)[:, None] >> np.arange(w)) & 1).astype(bool)  # (P, w), P = 2^w
    flips = flips[np.argsort(flips.sum(axis=1), kind="stable")]  # fewest flips first
    beta, speed, resteer, slip = _flipped(  # (..., P, w), (..., P, w), (..., P), (..., P)
        robot, cmd.beta[..., None, :], cmd.speed[..., None, :], cur[..., None, :], flips, samples
    )
    best = np.argmin(resteer + w * slip, axis=-1)  # J(f), first minimum

    def take(a):  # the best pattern's row of a (..., P, w) array
        return np.take_along_axis(a, best[..., None, None], axis=-2)[..., 0, :]

    def pick(a):  # its entry of a (..., P) array
        return np.take_along_axis(a, best[..., None], axis=-1)[..., 0]

    flip = np.broadcast_to(flips, beta.shape)
    return SteeringChoice(take(beta), take(speed) + 0.0, take(flip), pick(resteer), pick(slip))
