r"""Commanding a real swerve drive: desaturation, cosine compensation, discretisation (the SE(2) exponential).

The module speeds are linear in the twist and the angles depend only on its direction, so scaling the **twist**
(:func:`desaturate`) keeps the instantaneous centre (63) and every angle.  WPILib's ``desaturateWheelSpeeds``
scales the module speeds by the same factor, which is the same thing for a continuous twist, but applied after
``ChassisSpeeds.discretize`` it scales the *discretised* twist, whose arc is no longer the commanded one (the robot
drifts sideways).  Desaturate first, then discretise.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.robot import Robot
from ..model.types import ArrayLike, FloatArray, TwistLike
from .modules import swerve_robot

__all__ = ["desaturate", "desaturation_scale", "cosine_compensate", "se2_exp", "se2_log", "discretize"]


def desaturation_scale(robot: Robot, twist: TwistLike, max_speed: float) -> FloatArray:
    r"""The factor :math:`k = \min(1, s_{\max}/\max_i s_i)` that brings the fastest module to ``max_speed``.

    Parameters
    ----------
    robot : Robot
        Centred wheels only.
    twist : array (..., 3)
        :math:`[\dot\psi, \dot x, \dot y]`, body frame.
    max_speed : float
        Largest module speed, m/s, > 0.

    Returns
    -------
    numpy.ndarray (...)
        In :math:`(0, 1]`; 1 for the zero twist.
    """
    robot = swerve_robot(robot)
    t = validation.twist_array("twist", twist)
    max_speed = validation.number("max_speed", validation.positive("max_speed", max_speed))
    d = np.asarray(robot.mount_points, dtype=float)
    with np.errstate(over="ignore", invalid="ignore"):
        # p_i = c_dot + psi_dot E d_i (2), scaled by m first so that |p_i| cannot overflow
        m = np.abs(t[..., 1:]).max(axis=-1) + np.abs(t[..., 0]) * np.abs(d).max()
        m = np.where(m > 0, m, 1.0)[..., None]
        tm = t / m
        px = tm[..., 1:2] - tm[..., 0:1] * d[:, 1]
        py = tm[..., 2:3] + tm[..., 0:1] * d[:, 0]
        peak = np.hypot(px, py).max(axis=-1) * m[..., 0]
        k = np.where(peak > max_speed, max_speed / np.where(peak > 0, peak, 1.0), 1.0)
    if not np.isfinite(k).all():
        raise InputValueError(
            f"twist is too large: the module speeds overflow (largest |twist| = {np.abs(t).max():.3g})"
        )
    return k


def desaturate(robot: Robot, twist: TwistLike, max_speed: float) -> FloatArray:
    r"""Scale the twist so that no module exceeds ``max_speed``, keeping the instantaneous centre.

    :math:`k\,\mathbf t` with :math:`k` of :func:`desaturation_scale`: the angles do not change, the
    module speeds all scale by :math:`k` (WPILib's ``desaturateWheelSpeeds``) and the centre
    :math:`\mathbf E\dot{\mathbf c}/\dot\psi` (63) stays where it was.

    Parameters
    ----------
    robot : Robot
        Centred wheels only.
    twist : array (..., 3)
    max_speed : float
        Largest module speed, m/s, > 0.

    Returns
    -------
    numpy.ndarray (..., 3)
    """
    t = validation.twist_array("twist", twist)
    return t * desaturation_scale(robot, t, max_speed)[..., None]


def cosine_compensate(speed: ArrayLike, beta: ArrayLike, target: ArrayLike) -> FloatArray:
    r"""Module speeds scaled by the cosine of the steering error, :math:`s_i\cos(\beta_i - \beta^*_i)`.

    Parameters
    ----------
    speed : array (...)
        Signed module speeds for the targets, m/s.
    beta : array (...)
        Actual steering angles.
    target : array (...)
        Target steering angles :math:`\beta^*`.

    Returns
    -------
    numpy.ndarray (...)
        Negative where the error exceeds :math:`\pi/2` (as WPILib's ``cosineScale``).
    """
    speed = validation.finite_array("speed", speed)
    beta = validation.finite_array("beta", beta)
    target = validation.finite_array("target", target)
    validation.batch_shape({"speed": speed, "beta": beta, "target": target}, core=0)
    return speed * np.cos(beta - target)


def _coefficients(theta):
    r""":math:`A = \sin\theta/\theta`, :math:`B = (1-\cos\theta)/\theta = \sin(\theta/2)\,\mathrm{sinc}(\theta/2)`: exact at 0."""
    return np.sinc(theta / np.pi), np.sin(theta / 2) * np.sinc(theta / (2 * np.pi))


def se2_exp(twist: TwistLike, dt: float = 1.0) -> FloatArray:
    r"""The pose reached by holding a body twist for ``dt``: the SE(2) exponential.

    Parameters
    ----------
    twist : array (..., 3)
        :math:`[\dot\psi, \dot x, \dot y]`, body frame.
    dt : float, optional
        Duration, > 0.

    Returns
    -------
    numpy.ndarray (..., 3)
        :math:`[\Delta\psi, \Delta x, \Delta y]` in the body frame at the start:
        :math:`\Delta\psi = \dot\psi\,\Delta t`,
        :math:`\Delta\mathbf c = \mathbf V(\Delta\psi)\dot{\mathbf c}\,\Delta t`,
        :math:`\mathbf V(\theta) = A\mathbf I + B\mathbf E`, :math:`A = \sin\theta/\theta`,
        :math:`B = (1-\cos\theta)/\theta`.

    Examples
    --------
    >>> se2_exp([np.pi, np.pi, 0.0], dt=1.0).round(12).tolist()    # half a turn about (0, 1)
    [3.14159265359, 0.0, 2.0]
    """
    t = validation.twist_array("twist", twist)
    dt = validation.number("dt", validation.positive("dt", dt))
    with np.errstate(over="ignore", invalid="ignore"):
        g = t * dt
        A, B = _coefficients(g[..., 0])
        out = np.stack([g[..., 0], A * g[..., 1] - B * g[..., 2], B * g[..., 1] + A * g[..., 2]], axis=-1)
    if not np.isfinite(out).all():
        raise InputValueError(
            f"twist and dt are too large: the pose overflows (largest |twist| = {np.abs(t).max():.3g}, dt = {dt!r})"
        )
    return out


def se2_log(delta: ArrayLike, dt: float = 1.0) -> FloatArray:
    r"""The constant body twist that reaches the pose ``delta`` in ``dt``: the SE(2) logarithm.

    Inverse of :func:`se2_exp` for :math:`|\Delta\psi| < 2\pi`:
    :math:`\dot{\mathbf c}\,\Delta t = \mathbf V(\Delta\psi)^{-1}\Delta\mathbf c` with
    :math:`\mathbf V^{-1} = (A\mathbf I - B\mathbf E)/(A^2 + B^2)`, :math:`A^2 + B^2 =
    \mathrm{sinc}^2(\Delta\psi/2)`.

    Parameters
    ----------
    delta : array (..., 3)
        :math:`[\Delta\psi, \Delta x, \Delta y]`, body frame at the start; :math:`|\Delta\psi| < 2\pi`.
    dt : float, optional
        Duration, > 0.

    Returns
    -------
    numpy.ndarray (..., 3)
        The twist :math:`[\dot\psi, \dot x, \dot y]`.
    """
    g = validation.finite_array("delta", delta, last=3)
    dt = validation.number("dt", validation.positive("dt", dt))
    if np.any(np.abs(g[..., 0]) >= 2 * np.pi):
        raise InputValueError(
            f"delta must turn by less than 2 pi (the logarithm is not unique), got "
            f"|delta psi| up to {np.abs(g[..., 0]).max():.6g}"
        )
    return _log(g, dt)


def _log(g, dt):
    """:func:`se2_log` of a checked pose (..., 3) turning by less than 2 pi, over a checked duration."""
    A, B = _coefficients(g[..., 0])
    n = A * A + B * B
    with np.errstate(over="ignore", invalid="ignore", under="ignore"):
        out = (
            np.stack([g[..., 0], (A * g[..., 1] + B * g[..., 2]) / n, (A * g[..., 2] - B * g[..., 1]) / n], axis=-1)
            / dt
        )
    if not np.isfinite(out).all():
        raise InputValueError(f"delta and dt give a twist beyond double precision (dt = {dt!r})")
    return out


def discretize(twist: TwistLike, dt: float) -> FloatArray:
    r"""The twist that, held for ``dt``, ends where the components of ``twist`` would if independent.

    :func:`se2_log` of :math:`(\dot\psi\Delta t, \dot x\Delta t, \dot y\Delta t)` over :math:`\Delta t`:
    WPILib's ``ChassisSpeeds.discretize`` in wmr's twist order.

    Parameters
    ----------
    twist : array (..., 3)
        :math:`[\dot\psi, \dot x, \dot y]`, body frame; :math:`|\dot\psi|\Delta t < 2\pi`.
    dt : float
        Control period, > 0.

    Returns
    -------
    numpy.ndarray (..., 3)

    Examples
    --------
    >>> tw = discretize([1.0, 1.0, 0.0], dt=0.5)
    >>> (se2_exp(tw, 0.5) / 0.5).round(12).tolist()                   # ends at (psi, x, y) = t dt
    [1.0, 1.0, ...0.0]
    """
    t = validation.twist_array("twist", twist)
    dt = validation.number("dt", validation.positive("dt", dt))
    with np.errstate(over="ignore"):
        g = t * dt
    if not np.isfinite(g).all():
        raise InputValueError(f"twist and dt are too large: twist * dt overflows (dt = {dt!r})")
    if np.any(np.abs(g[..., 0]) >= 2 * np.pi):
        raise InputValueError(f"twist turns by 2 pi or more in one period dt = {dt!r}: |psi_dot| dt must be < 2 pi")
    return _log(g, dt)
