r"""Wheel odometry: the platform's pose from sampled encoder angles and steering angles, with the slip residual.

Between two samples the joints turn by :math:`\Delta\boldsymbol\theta` and (21), integrated over the step at the
steering angles of its end, reads

.. math:: \mathbf J_1\,\Delta\mathbf t = \mathbf J_2(\boldsymbol\beta_{k+1})\,\Delta\boldsymbol\theta,
          \qquad \Delta\mathbf t = [\Delta\psi\ \Delta x\ \Delta y]^T \text{ (body frame at the step's start)}.

The **measured** joints (default :func:`measured_joints`) give their increments; the others (free rollers, passive
castors, wheels without an encoder) are unknowns solved with the twist.  A measured steering joint's rate is the
unit's absolute :math:`\dot\phi_i = \dot\psi + \dot\beta_i` (7): its column moves to :math:`\Delta\psi`'s and its
increment comes from the steering angles.  The least squares (columns scaled as for :func:`wmr.rank`) gives
:math:`\Delta\mathbf t`; the **residual** :math:`\mathbf J_1\Delta\mathbf t - \mathbf J_2\Delta\boldsymbol\theta`
(metres, two entries per unit) is the wheel travel no rigid motion explains.  The pose is integrated as WPILib's
``Odometry.update`` does (:func:`wmr.swerve.se2_exp` of each step; a gyro's ``heading`` replaces
:math:`\Delta\psi`); ``tests/test_odometry.py`` compares it with WPILib's odometries.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from .analysis.linalg import rank
from .errors import InputValueError
from .model import validation
from .model.platform import wrap_angle
from .model.robot import Robot
from .model.tolerance import TOL, column_norms
from .model.types import ArrayLike
from .swerve.limits import se2_exp

__all__ = ["Odometry", "wheel_odometry"]

#: the most samples one call takes (about 100 MB of work arrays for a four-wheel robot)
MAX_SAMPLES = 1_000_000
_CHUNK = 16384


@dataclass(frozen=True)
class Odometry:
    """The result of :func:`wheel_odometry`.

    Attributes
    ----------
    robot : Robot
    measured : tuple of str
        The rate names (:attr:`wmr.Robot.rate_names`) measured (from ``angles``, or from ``beta`` for
        a steering joint's rate).
    pose : numpy.ndarray (T, 3)
        :math:`(\\psi, X, Y)` at each sample, fixed frame (the first is ``pose0``).
    increment : numpy.ndarray (T-1, 3)
        :math:`[\\Delta\\psi, \\Delta x, \\Delta y]` of each step, body frame at its start (the gyro's
        :math:`\\Delta\\psi` when a heading was given).
    residual : numpy.ndarray (T-1, 2w)
        :math:`\\mathbf J_1\\Delta\\mathbf t - \\mathbf J_2\\Delta\\boldsymbol\\theta` of each step (metres).
    slip : numpy.ndarray (T-1,)
        Its norm.
    unknown : numpy.ndarray (T-1, u)
        The increments solved for the rates not measured, in the order of :attr:`wmr.Robot.rate_names`.
    """

    robot: Robot
    measured: tuple
    pose: np.ndarray
    increment: np.ndarray
    residual: np.ndarray
    slip: np.ndarray
    unknown: np.ndarray


def _columns(robot):
    """The rate columns of driven joints (measured by default), and the set of steering joints' rate columns."""
    driven: list[int] = []
    steering: set[int] = set()
    for sl, u in zip(robot.rate_slices, robot.wheels):
        rated = [j for j in u.joints if j.rate is not None]
        for k, j in enumerate(rated):
            if j.driven:
                driven.append(sl.start + k)
            if j.steering:
                steering.add(sl.start + k)
    return driven, steering


def measured_joints(robot: Robot) -> tuple[str, ...]:
    r"""The rate names an encoder measures by default: those of the joints with a motor (a column of J2 each).

    A steering joint's rate (an offset wheel's :math:`\dot\phi_i`) is measured through the steering angles.
    """
    robot = validation.numeric_robot(robot)
    return tuple(robot.rate_names[c] for c in _columns(robot)[0])


def _steps(name, values):
    """The increments between successive samples, checked not to overflow."""
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.diff(values, axis=0)
    if not np.isfinite(out).all():
        raise InputValueError(
            f"{name} are too large: the differences of successive samples overflow "
            f"(largest |{name}| = {np.abs(values).max():.3g})"
        )
    return out


def _solve(A):
    """Pseudo-inverses of ``A`` (..., m, k), columns scaled, and whether its first three unknowns are determined."""
    scale = column_norms(A)
    Ah = A / scale[..., None, :]
    P = np.linalg.pinv(Ah, rcond=TOL) / scale[..., :, None]
    determined = rank(Ah) - (rank(Ah[..., 3:]) if A.shape[-1] > 3 else 0) == 3
    return P, np.atleast_1d(determined)


def wheel_odometry(
    robot: Robot,
    beta: ArrayLike,
    angles: ArrayLike,
    heading: ArrayLike | None = None,
    pose0: ArrayLike = (0.0, 0.0, 0.0),
    measured: Sequence[str] | None = None,
) -> Odometry:
    r"""The pose over time from sampled joint angles (rules: module notes).

    Parameters
    ----------
    robot : Robot
    beta : array (T, w)
        Steering angles :math:`\beta_i` at each sample (radians; unsteered units' entries are ignored).
    angles : array (T, m)
        The measured joints' angles at each sample (radians, wmr's sign: :math:`\theta_i`; a WPILib
        module distance is :math:`r_i\theta_i`), in the order of ``measured``, steering joints left
        out (their angles are in ``beta``).
    heading : array (T,), optional
        A gyro's heading (radians): replaces the wheels' :math:`\Delta\psi`, as WPILib does.
    pose0 : triple, optional
        :math:`(\psi, X, Y)` at the first sample.
    measured : sequence of str, optional
        Rate names (:attr:`wmr.Robot.rate_names`) of the measured joints; default
        :func:`measured_joints`.  A steering joint's rate named here is measured through ``beta``.

    Returns
    -------
    Odometry

    Raises
    ------
    wmr.errors.InputValueError
        On bad shapes, fewer than 2 or more than :data:`MAX_SAMPLES` samples, unknown rate names,
        or when the measured joints do not determine the twist at a step (e.g. one wheel measured).
    """
    robot = validation.numeric_robot(robot)
    driven, steering_rates = _columns(robot)
    names = list(robot.rate_names)
    if measured is None:
        chosen = driven
    else:
        if isinstance(measured, str) or not all(isinstance(n, str) for n in measured):
            raise validation.kind_error("measured", measured, "a sequence of rate names")
        if any(n not in names for n in measured) or len(set(measured)) != len(measured):
            raise InputValueError(
                f"measured must name distinct rates of the robot ({', '.join(names)}), got {list(measured)}"
            )
        chosen = [names.index(n) for n in measured]
    steer = [c for c in chosen if c in steering_rates]  # through beta: phi = psi + beta (7)
    cols = [c for c in chosen if c not in steering_rates]  # through angles
    beta = validation.finite_array("beta", beta, last=robot.w)
    angles = validation.finite_array("angles", angles, last=len(cols))
    T = beta.shape[0] if beta.ndim == 2 else 0
    if beta.ndim != 2 or angles.shape != (T, len(cols)) or not 2 <= T <= MAX_SAMPLES:
        raise InputValueError(
            f"beta must be (T, {robot.w}) and angles (T, {len(cols)}) with 2 <= T <= {MAX_SAMPLES}, "
            f"got shapes {beta.shape} and {angles.shape}"
        )
    if heading is not None:
        heading = validation.finite_array("heading", heading)
        if heading.shape != (T,):
            raise InputValueError(f"heading must have shape ({T},), one angle per sample, got {heading.shape}")
    pose0 = validation.finite_array("pose0", pose0)
    if pose0.shape != (3,):
        raise InputValueError(f"pose0 must be (psi, X, Y), got shape {pose0.shape}")
    unknown = [c for c in range(robot.n_rates) if c not in cols and c not in steer]
    J1 = robot.J1()
    unit_of = [i for i, sl in enumerate(robot.rate_slices) for _ in range(sl.start, sl.stop)]  # column -> unit
    steering = [unit_of[c] for c in steer]
    # A (the unknowns' matrix) changes with beta only through steered units' unknown or steering columns
    constant = not any(robot.wheels[unit_of[c]].steered for c in unknown + steer)
    b_end = robot.effective_beta(beta[1:])
    d_theta = _steps("angles", angles)
    d_beta = wrap_angle(_steps("beta", beta[:, steering]))  # (T-1, 0) without measured steering
    z = np.empty((T - 1, 3 + len(unknown)))
    res = np.empty((T - 1, 2 * robot.w))
    fixed = None
    with np.errstate(over="ignore", invalid="ignore"):  # an overflow is caught on the pose
        for a in range(0, T - 1, _CHUNK):
            k = slice(a, min(a + _CHUNK, T - 1))
            J2 = robot.J2(b_end[k])  # (n, 2w, n_rates) at the steps' ends
            b = np.einsum("kij,kj->ki", J2[..., cols], d_theta[k])
            if steer:
                b += np.einsum("kij,kj->ki", J2[..., steer], d_beta[k])
            if constant and fixed is not None:
                A, P = fixed
                z[k] = b @ P.T
                res[k] = z[k] @ A.T - b
                continue
            A = np.concatenate([np.broadcast_to(J1, J2.shape[:1] + J1.shape), -J2[..., unknown]], axis=-1)
            A[..., 0] -= J2[..., steer].sum(axis=-1)  # phi_i = psi + beta_i (7): psi's column
            n = 1 if constant else len(b)  # a constant A: solved once
            P, determined = _solve(A[:n])
            if not determined.all():
                step = a + int(np.argmin(determined))
                raise InputValueError(
                    f"the measured joints {[names[c] for c in chosen]} do not determine the "
                    f"platform's motion at step {step} (samples {step}..{step + 1}, beta = "
                    f"{b_end[step].round(6).tolist()}): measure more joints"
                )
            if constant:
                fixed = (A[0], P[0])
            z[k] = np.einsum("kij,kj->ki", np.broadcast_to(P, (len(b),) + P.shape[1:]), b)
            res[k] = np.einsum("kij,kj->ki", A, z[k]) - b
    inc = z[:, :3].copy()
    if heading is not None:
        inc[:, 0] = wrap_angle(_steps("heading", heading))  # WPILib: the gyro's angle, wheels' dx, dy
    with np.errstate(over="ignore", invalid="ignore"):
        psi = pose0[0] + np.concatenate([[0.0], np.cumsum(inc[:, 0])])
        ok = np.isfinite(inc).all() and np.isfinite(res).all() and np.isfinite(psi).all()
        if ok:
            d = se2_exp(inc)  # Pose2d.exp: body-frame displacement
            c, s = np.cos(psi[:-1]), np.sin(psi[:-1])
            world = np.stack([c * d[:, 1] - s * d[:, 2], s * d[:, 1] + c * d[:, 2]], axis=-1)
            xy = pose0[1:] + np.concatenate([np.zeros((1, 2)), np.cumsum(world, axis=0)])
            ok = np.isfinite(xy).all()
    if not ok:
        raise InputValueError(
            f"angles, heading or pose0 are too large: the pose overflows double precision "
            f"(largest |angles| = {np.abs(angles).max():.3g})"
        )
    pose = np.column_stack([psi, xy])
    return Odometry(robot, tuple(names[c] for c in chosen), pose, inc, res, np.linalg.norm(res, axis=-1), z[:, 3:])
