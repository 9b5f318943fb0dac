r"""Time integration of the kinematics for given driving and steering inputs (:func:`integrate`).

The state is the platform pose :math:`(\psi, X, Y)` in the fixed frame :math:`\mathcal F` and the
steering angles :math:`\boldsymbol\beta`.  At each instant the twist follows from the joint rates by
the forward kinematics (least squares on (21)); :math:`\dot X, \dot Y` are :math:`\dot{\mathbf c}`
rotated by :math:`\psi`; and each :math:`\dot\beta_i` follows its unit's law: (7) for offset wheels
(:math:`\dot\beta_i = \dot\phi_i - \dot\psi`), the steering input for centred wheels, and the
corrected (15) for dual wheels.  A fixed-step classical Runge-Kutta scheme keeps runs
deterministic.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import InputTypeError, InputValueError
from ..model import validation
from ..model.robot import Robot
from ..model.types import ArrayLike, FloatArray
from .kinematics import forward

__all__ = ["Trajectory", "integrate", "MAX_STEPS"]


@dataclass(frozen=True)
class Trajectory:
    """An integrated run.

    Attributes
    ----------
    robot : Robot
        The robot.
    t : numpy.ndarray (N,)
    pose : numpy.ndarray (N, 3)
        :math:`(\\psi, X, Y)`, fixed frame.
    beta : numpy.ndarray (N, w)
    twist : numpy.ndarray (N, 3)
        Body-frame twist at each sample.
    slip : numpy.ndarray (N,)
        Norm of the residual of (21): zero when the commanded rates were compatible.
    """

    robot: Robot
    t: np.ndarray
    pose: np.ndarray
    beta: np.ndarray
    twist: np.ndarray
    slip: np.ndarray

    def world(self, body_points: ArrayLike) -> FloatArray:
        """Map body-frame points to the fixed frame along the run.

        Parameters
        ----------
        body_points : array (N, ..., 2) or (..., 2)
            Points in the body frame: one set per sample (leading axis N = ``len(t)``) or one
            set for the whole run.

        Returns
        -------
        numpy.ndarray (N, ..., 2)
            :math:`[X, Y] + \\mathbf R(\\psi)\\,\\mathbf p` at every sample.
        """
        p = validation.finite_array("body_points", body_points, last=2)
        psi, XY = self.pose[:, 0], self.pose[:, 1:]
        c, s = np.cos(psi), np.sin(psi)
        per_sample = p.ndim >= 2 and p.shape[0] == len(self.t)
        extra = p.ndim - 2 if per_sample else p.ndim - 1
        shape = (len(self.t),) + (1,) * extra
        c, s = c.reshape(shape), s.reshape(shape)
        with np.errstate(over="ignore", invalid="ignore"):
            X = c * p[..., 0] - s * p[..., 1] + XY[:, 0].reshape(shape)
            Y = s * p[..., 0] + c * p[..., 1] + XY[:, 1].reshape(shape)
        if not (np.isfinite(X).all() and np.isfinite(Y).all()):
            raise InputValueError(
                f"body_points are too large: their fixed-frame positions overflow "
                f"(largest |body_points| = {np.abs(p).max():.3g})"
            )
        return np.stack([X, Y], axis=-1)

    def unit_points(self, i: int, key: str) -> FloatArray:
        """World positions along the run of a point of unit ``i``.

        Parameters
        ----------
        i : int
            Index of the unit (0-based, as in ``robot.wheels``).
        key : str
            A key of :meth:`OffsetWheel.points`: ``"P"``, ``"H"``, ``"wheels"``, ``"i"`` or ``"j"``.

        Returns
        -------
        numpy.ndarray (N, ..., 2)
        """
        i = validation.integer("i", i)
        if not -self.robot.w <= i < self.robot.w:
            raise InputValueError(f"i must be a unit index in 0..{self.robot.w - 1}, got {i}")
        pts = self.robot.wheels[i].points(self.beta[:, i])
        if not isinstance(key, str) or key not in pts:
            raise (InputTypeError if not isinstance(key, str) else InputValueError)(
                f"key must be one of {sorted(pts)}, got {validation.show(key)}"
            )
        return self.world(pts[key])


def _one(name, value, size):
    arr = validation.finite_array(name, value, last=size)
    if arr.ndim != 1:
        raise InputValueError(f"{name} must be one vector of shape ({size},), got shape {arr.shape}")
    return arr


def _as_input(f, size, name):
    if callable(f):

        def call(t, state):
            try:
                return f(t, state)
            except (TypeError, ValueError) as e:  # the caller's function: say which one failed
                raise type(e)(f"{name}(t, state) raised {type(e).__name__}: {e}") from e

        return call
    arr = _one(name, f, size)
    return lambda t, state: arr


#: The most steps :func:`integrate` takes unless told otherwise (a run of 10^6 steps takes minutes).
MAX_STEPS = 1_000_000


def integrate(
    robot: Robot,
    rates: ArrayLike | Callable[[float, FloatArray], ArrayLike],
    beta0: ArrayLike,
    t_end: float,
    dt: float,
    steer: ArrayLike | Callable[[float, FloatArray], ArrayLike] | None = None,
    pose0: ArrayLike = (0.0, 0.0, 0.0),
    max_steps: int = MAX_STEPS,
) -> Trajectory:
    r"""Integrate the robot's motion under joint-rate (and steering) inputs.

    Parameters
    ----------
    robot : Robot
    rates : array (n_rates,) or callable ``(t, state) -> (n_rates,)``
        Joint rates :math:`\dot{\boldsymbol\theta}`; ``state`` is ``(pose, beta)``.
    beta0 : array (w,)
        Initial steering angles.
    t_end, dt : float
        Duration and largest step, > 0; the fixed step used is ``t_end / ceil(t_end / dt)`` so that
        the last sample is at ``t_end``.
    steer : array (w,) or callable, optional
        Steering rates :math:`\dot\beta_i` of centred wheels (ignored for other units).
    pose0 : triple
        Initial :math:`(\psi, X, Y)`.
    max_steps : int, optional
        The most steps allowed (default :data:`MAX_STEPS`): a ``dt`` that would need more raises
        ``ValueError`` instead of running for hours or exhausting memory.

    Returns
    -------
    Trajectory

    Examples
    --------
    >>> from wmr.model.robots import paper_robot
    >>> bot = paper_robot("centred", L=1.0, r=0.5)
    >>> tr = integrate(bot, [-2.0, -2.0, -2.0], [0.0, 0.0, 0.0], t_end=1.0, dt=0.1)
    >>> (tr.pose[-1].round(12) + 0.0).tolist(), bool(tr.slip.max() < 1e-12)   # 1 m along +y, no slip
    ([0.0, 0.0, 1.0], True)
    """
    robot = validation.numeric_robot(robot)
    t_end = validation.number("t_end", validation.positive("t_end", t_end))
    dt = validation.number("dt", validation.positive("dt", dt))
    max_steps = validation.integer("max_steps", max_steps, minimum=1)
    beta0 = _one("beta0", beta0, robot.w)
    pose0 = _one("pose0", pose0, 3)
    with np.errstate(over="ignore"):
        steps = np.ceil(t_end / dt - 1e-9)
    if not steps <= max_steps:
        raise InputValueError(
            f"dt = {dt!r} needs {steps:.3g} steps to reach t_end = {t_end!r}, more than "
            f"max_steps = {max_steps}: take a larger dt (or raise max_steps)"
        )
    rate_fn = _as_input(rates, robot.n_rates, "rates")
    steer_fn = _as_input(np.zeros(robot.w) if steer is None else steer, robot.w, "steer")

    def overflow(t):
        return InputValueError(
            f"rates or steer are too large for this run: the pose or the steering angles overflow at t = {t:.6g}"
        )

    def deriv(t, pose, beta):
        if not (np.isfinite(pose).all() and np.isfinite(beta).all()):
            raise overflow(t)
        th = _one("rates(t)", rate_fn(t, (pose, beta)), robot.n_rates)
        st = _one("steer(t)", steer_fn(t, (pose, beta)), robot.w)
        sol = forward(robot, beta, th)
        tw = sol.value
        c, s = np.cos(pose[0]), np.sin(pose[0])
        dpose = np.array([tw[0], c * tw[1] - s * tw[2], s * tw[1] + c * tw[2]])
        dbeta = np.array(
            [u.beta_rate(tw[0], th[sl], st[i]) for i, (u, sl) in enumerate(zip(robot.wheels, robot.rate_slices))]
        )
        if not (np.isfinite(dpose).all() and np.isfinite(dbeta).all()):
            raise overflow(t)
        return dpose, dbeta, tw, float(np.linalg.norm(sol.residual))

    n = max(1, int(steps))  # steps of t_end / n <= dt: the run ends at t_end
    dt = t_end / n
    ts = np.arange(n + 1) * dt
    pose, beta = np.empty((n + 1, 3)), np.empty((n + 1, robot.w))
    twist, slip = np.empty((n + 1, 3)), np.empty(n + 1)
    pose[0], beta[0] = pose0, beta0
    # an overflow is detected and reported by deriv; J1 and the units' blocks are kept on the robot (made once)
    with np.errstate(over="ignore", invalid="ignore"):
        for k in range(n):
            t, p, b = ts[k], pose[k], beta[k]
            k1p, k1b, tw, sl = deriv(t, p, b)
            twist[k], slip[k] = tw, sl
            k2p, k2b, *_ = deriv(t + dt / 2, p + dt / 2 * k1p, b + dt / 2 * k1b)
            k3p, k3b, *_ = deriv(t + dt / 2, p + dt / 2 * k2p, b + dt / 2 * k2b)
            k4p, k4b, *_ = deriv(t + dt, p + dt * k3p, b + dt * k3b)
            pose[k + 1] = p + dt / 6 * (k1p + 2 * k2p + 2 * k3p + k4p)
            beta[k + 1] = b + dt / 6 * (k1b + 2 * k2b + 2 * k3b + k4b)
        _, _, twist[n], slip[n] = deriv(ts[n], pose[n], beta[n])
    if not (np.isfinite(pose).all() and np.isfinite(beta).all() and np.isfinite(slip).all()):
        raise InputValueError(f"rates are too large for t_end = {t_end!r}: the pose overflows double precision")
    return Trajectory(robot, ts, pose, beta, twist, slip)
