r"""Re-steering transients: rate-limited modules following a commanded twist, and the slip they cause.

A real module steers at a finite rate :math:`|\dot\beta_i| \le \omega_s`, so after a change of command the
modules spend a transient at angles that realise no twist, and the wheels slip.  In each control period
:math:`\Delta t`: (1) the commanded twist :math:`\mathbf t_k` of a :class:`~wmr.swerve.profiles.TwistProfile`
gives targets by a **strategy** (``"plain"``: :func:`~wmr.swerve.modules.module_commands`; ``"module"``:
:func:`~wmr.swerve.optimize.optimize_modules`; ``"robot"``: :func:`~wmr.swerve.optimize.optimize_robot`),
optionally cosine-compensated; (2) each module turns towards its target by at most :math:`\omega_s\Delta t`;
(3) the platform moves with the least-squares twist of (21) held over the period (:func:`~wmr.swerve.limits.se2_exp`),
the residual's norm being the **slip** :math:`\sigma_k` (m/s); (4) the **path error** is the distance of C from
the reference pose that integrates the commanded twists.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..errors import InputTypeError, InputValueError
from ..model import validation
from ..model.platform import wrap_angle
from ..model.robot import Robot
from ..model.types import ArrayLike
from .limits import cosine_compensate, se2_exp
from .modules import chassis_twist, module_commands, swerve_robot
from .optimize import optimize_modules, optimize_robot
from .profiles import TwistProfile, direction_change, spin_and_translate

__all__ = [
    "TwistProfile",
    "Transient",
    "TransientStudy",
    "direction_change",
    "spin_and_translate",
    "resteer_transient",
    "resteer_study",
    "STRATEGIES",
]

#: The strategies compared by :func:`resteer_study`: (strategy, cosine compensation).
STRATEGIES = (("plain", False), ("module", False), ("module", True), ("robot", False), ("robot", True))


@dataclass(frozen=True)
class Transient:
    r"""One simulated run (:func:`resteer_transient`).

    Attributes
    ----------
    label : str
        Strategy, e.g. ``"robot + cos"``.
    t : numpy.ndarray (N+1,)
        Sample times, s.
    pose : numpy.ndarray (N+1, 3)
        :math:`(\psi, X, Y)` of the robot, fixed frame.
    reference : numpy.ndarray (N+1, 3)
        The pose the commanded twists would give.
    beta : numpy.ndarray (N+1, w)
        Steering angles (unwrapped: their changes are the turns).
    twist : numpy.ndarray (N, 3)
        The platform's least-squares twist in each period.
    slip : numpy.ndarray (N,)
        :math:`\sigma_k`, norm of the residual of (21), m/s.
    path_error : numpy.ndarray (N+1,)
        Distance between the robot's C and the reference's, m.
    speed : numpy.ndarray (N, w)
        The module speeds commanded in each period (after cosine compensation), m/s.
    """

    label: str
    t: np.ndarray
    pose: np.ndarray
    reference: np.ndarray
    beta: np.ndarray
    twist: np.ndarray
    slip: np.ndarray
    path_error: np.ndarray
    speed: np.ndarray

    @property
    def slip_distance(self) -> float:
        r""":math:`\sum_k\sigma_k\Delta t`: how far the wheels slide in all (m)."""
        return float(self.slip.sum() * (self.t[1] - self.t[0]))

    @property
    def peak_slip(self) -> float:
        """Largest slip, m/s."""
        return float(self.slip.max())

    @property
    def max_path_error(self) -> float:
        """Largest path error, m."""
        return float(self.path_error.max())

    @property
    def final_path_error(self) -> float:
        """Path error at the end, m."""
        return float(self.path_error[-1])

    @property
    def steering_travel(self) -> float:
        """Total turn of all modules, radians."""
        return float(np.abs(np.diff(self.beta, axis=0)).sum())


def _compose(pose, delta):
    """Pose (psi, X, Y) followed by a body-frame increment (dpsi, dx, dy)."""
    c, s = np.cos(pose[0]), np.sin(pose[0])
    return np.array([pose[0] + delta[0], pose[1] + c * delta[1] - s * delta[2], pose[2] + s * delta[1] + c * delta[2]])


def _targets(robot, strategy, twist, beta):
    """Target angles and speeds of one commanded twist from the angles ``beta`` by ``strategy``."""
    if strategy == "plain":
        cmd = module_commands(robot, twist, beta)
        return cmd.beta, cmd.speed
    ch = (optimize_modules if strategy == "module" else optimize_robot)(robot, twist, beta)
    return ch.beta, ch.speed


def resteer_transient(
    robot: Robot,
    profile: TwistProfile,
    strategy: str = "robot",
    cosine: bool = False,
    steer_rate: float = 2 * np.pi,
    beta0: ArrayLike | None = None,
) -> Transient:
    r"""Simulate rate-limited modules following ``profile`` (module docstring: the four steps).

    Parameters
    ----------
    robot : Robot
        Centred wheels only.
    profile : TwistProfile
    strategy : {"plain", "module", "robot"}
        How targets are chosen from the current angles.
    cosine : bool
        Scale each module's speed by the cosine of its steering error.
    steer_rate : float
        Largest steering rate :math:`\omega_s` of every module, rad/s, > 0.
    beta0 : array (w,), optional
        Initial angles; default: those of the first commanded twist (no transient at the start).

    Returns
    -------
    Transient
    """
    robot = swerve_robot(robot)
    if not isinstance(profile, TwistProfile):
        raise InputTypeError(
            f"profile must be a TwistProfile (direction_change(), spin_and_translate()), got {validation.show(profile)}"
        )
    if not isinstance(strategy, str) or strategy not in ("plain", "module", "robot"):
        raise InputValueError(f"strategy must be 'plain', 'module' or 'robot', got {validation.show(strategy)}")
    cosine = validation.flag("cosine", cosine)
    rate = validation.number("steer_rate", validation.positive("steer_rate", steer_rate))
    tw = validation.finite_array("profile.twist", profile.twist, last=3).reshape(-1, 3)
    dt, w = validation.number("profile.dt", validation.positive("profile.dt", profile.dt)), robot.w
    if len(tw) == 0:
        raise InputValueError("profile must command at least one period, got no twists")
    beta = np.empty((len(tw) + 1, w))
    beta[0] = module_commands(robot, tw[0]).beta if beta0 is None else validation.finite_array("beta0", beta0, last=w)
    pose, ref = np.zeros((len(tw) + 1, 3)), np.zeros((len(tw) + 1, 3))
    twist, slip, speeds = np.empty((len(tw), 3)), np.empty(len(tw)), np.empty((len(tw), w))
    step = rate * dt
    k = 0
    try:
        with np.errstate(over="ignore", invalid="ignore"):
            for k, t_k in enumerate(tw):  # time steps (each kernel call is batched)
                target, speed = _targets(robot, strategy, t_k, beta[k])
                beta[k + 1] = beta[k] + np.clip(wrap_angle(target - beta[k]), -step, step)  # |beta_dot| <= omega_s
                if cosine:
                    speed = cosine_compensate(speed, beta[k + 1], target)
                speeds[k] = speed
                sol = chassis_twist(robot, beta[k + 1], speed)  # (21): least squares; residual = slip
                twist[k], slip[k] = sol.value, np.hypot.reduce(sol.residual)
                pose[k + 1] = _compose(pose[k], se2_exp(sol.value, dt))
                ref[k + 1] = _compose(ref[k], se2_exp(t_k, dt))
            err = np.hypot(*(pose[:, 1:] - ref[:, 1:]).T)
    except ValueError as e:  # a kernel's check, said of the profile
        raise InputValueError(f"profile commands a twist this simulation cannot follow (period {k}): {e}") from None
    if not all(np.isfinite(a).all() for a in (pose, ref, slip, err)):
        raise InputValueError("profile commands twists too large: the simulated poses overflow double precision")
    label = strategy + (" + cos" if cosine else "")
    t = np.arange(len(tw) + 1) * dt
    return Transient(label, t, pose, ref, beta, twist, slip, err, speeds)


@dataclass(frozen=True)
class TransientStudy:
    """The runs of several strategies on one profile (:func:`resteer_study`).

    Attributes
    ----------
    profile : TwistProfile
    steer_rate : float
        rad/s.
    runs : tuple of Transient
    """

    profile: TwistProfile
    steer_rate: float
    runs: tuple

    def table(self) -> list[dict[str, object]]:
        """One row per strategy: slip and path error.

        Returns
        -------
        list of dict
            Keys ``strategy``, ``slip_distance_m``, ``peak_slip_m_s``, ``max_path_error_m``,
            ``final_path_error_m``, ``steering_travel_rad``.
        """
        return [
            {
                "strategy": r.label,
                "slip_distance_m": r.slip_distance,
                "peak_slip_m_s": r.peak_slip,
                "max_path_error_m": r.max_path_error,
                "final_path_error_m": r.final_path_error,
                "steering_travel_rad": r.steering_travel,
            }
            for r in self.runs
        ]

    def run(self, label: str) -> Transient:
        """The run of one strategy.

        Parameters
        ----------
        label : str
            E.g. ``"module"`` or ``"robot + cos"``.

        Returns
        -------
        Transient
        """
        for r in self.runs:
            if r.label == label:
                return r
        raise InputValueError(f"label must be one of {[r.label for r in self.runs]}, got {validation.show(label)}")


def resteer_study(
    robot: Robot,
    profile: TwistProfile,
    steer_rate: float = 2 * np.pi,
    strategies: Sequence[tuple[str, bool]] = STRATEGIES,
) -> TransientStudy:
    r"""Run every strategy on one profile: the data of the figure and table of the design notebook.

    Parameters
    ----------
    robot : Robot
        Centred wheels only.
    profile : TwistProfile
    steer_rate : float
        Largest steering rate of the modules, rad/s.
    strategies : sequence of (str, bool)
        (strategy, cosine compensation) pairs; default :data:`STRATEGIES`.

    Returns
    -------
    TransientStudy
    """
    rate = validation.number("steer_rate", validation.positive("steer_rate", steer_rate))
    try:
        pairs = [(s, c) for s, c in strategies]
    except (TypeError, ValueError):
        raise InputTypeError(
            f"strategies must be (strategy, cosine) pairs, got {validation.show(strategies)}"
        ) from None
    if not pairs:
        raise InputValueError("strategies must name at least one (strategy, cosine) pair, got none")
    runs = tuple(resteer_transient(robot, profile, s, c, rate) for s, c in pairs)
    return TransientStudy(profile, rate, runs)
