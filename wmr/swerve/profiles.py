r"""Commanded twists for the re-steering transients (:mod:`wmr.swerve.transient`): one body twist
:math:`[\dot\psi, \dot x, \dot y]` per control period (:class:`TwistProfile`), made from a drive in the fixed
frame: a change of direction (:func:`direction_change`) or a spin while translating (:func:`spin_and_translate`).

The driver's velocity is given in the fixed frame and turned into the body frame with the heading
:math:`\psi = \int\dot\psi`; sizes are checked before any array is made (at most :data:`MAX_STEPS` periods).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.types import FloatArray

__all__ = ["TwistProfile", "direction_change", "spin_and_translate"]


#: Most control periods in a profile.
MAX_STEPS = 100_000


@dataclass(frozen=True)
class TwistProfile:
    r"""A commanded twist, one per control period.

    Attributes
    ----------
    name : str
    dt : float
        Control period, s.
    twist : numpy.ndarray (N, 3)
        :math:`[\dot\psi, \dot x, \dot y]` (body frame) held over :math:`[k\Delta t, (k+1)\Delta t)`.
    """

    name: str
    dt: float
    twist: np.ndarray

    @property
    def t(self) -> FloatArray:
        """Start of each period, s: (N,)."""
        return np.arange(len(self.twist)) * self.dt


def _times(t_change, t_end, dt, first="t_change"):
    """The checked change time and period, and the start of each period (at most :data:`MAX_STEPS` of them)."""
    t_change = validation.number(first, validation.positive(first, t_change))
    t_end = validation.number("t_end", validation.positive("t_end", t_end))
    dt = validation.number("dt", validation.positive("dt", dt))
    if not t_change < t_end:
        raise InputValueError(f"{first} must be before t_end, got {first} = {t_change!r}, t_end = {t_end!r}")
    n = np.ceil(t_end / dt - 1e-9)
    if not n <= MAX_STEPS:
        raise InputValueError(f"dt = {dt!r} needs {n:.3g} periods to reach t_end = {t_end!r}, more than {MAX_STEPS}")
    return t_change, dt, np.arange(int(n)) * dt


def _body(field_velocity, psi_dot, t, names):
    r"""Body twists from fixed-frame velocities (N, 2) and turning rates (N,), heading :math:`\psi = \int\dot\psi`."""
    with np.errstate(over="ignore", invalid="ignore"):
        psi = np.concatenate([[0.0], np.cumsum(psi_dot[:-1])]) * (t[1] - t[0] if len(t) > 1 else 0.0)
        c, s = np.cos(psi), np.sin(psi)
        vx, vy = field_velocity[:, 0], field_velocity[:, 1]
        out = np.column_stack([psi_dot, c * vx + s * vy, -s * vx + c * vy])  # R(-psi) v
    if not np.isfinite(out).all():
        raise InputValueError(f"{names} are too large: the commanded twist or heading overflows double precision")
    return out


def direction_change(
    speed: float = 1.0,
    angle: float = np.pi / 2,
    spin: float = 0.0,
    t_change: float = 0.25,
    t_end: float = 1.0,
    dt: float = 0.01,
) -> TwistProfile:
    r"""Drive along the fixed x axis, then, at ``t_change``, along the direction ``angle``.

    Parameters
    ----------
    speed : float
        Speed of C, m/s, > 0.
    angle : float
        Change of direction, radians (:math:`\pi/2`: a 90 degree change).
    spin : float
        Constant turning rate :math:`\dot\psi` throughout, rad/s (a driver's small rotation
        spreads the modules' angles, as real encoders do).
    t_change, t_end, dt : float
        Time of the change, duration and control period, s.

    Returns
    -------
    TwistProfile

    Examples
    --------
    >>> p = direction_change(speed=2.0, t_change=0.5, t_end=1.0, dt=0.25)
    >>> p.twist.round(12).tolist()
    [[0.0, 2.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.0], [0.0, 0.0, 2.0]]
    """
    speed = validation.number("speed", validation.positive("speed", speed))
    angle = validation.number("angle", angle)
    spin = validation.number("spin", spin)
    t_change, dt, t = _times(t_change, t_end, dt)
    after = t >= t_change - 1e-9 * dt
    heading = np.where(after, angle, 0.0)
    v = speed * np.column_stack([np.cos(heading), np.sin(heading)])
    with np.errstate(over="ignore"):
        name = f"{np.degrees(angle):g} deg change of direction"
    return TwistProfile(name, dt, _body(v, np.full(len(t), spin), t, "speed and spin"))


def spin_and_translate(
    speed: float = 1.0, rate: float = 3.0, t_start: float = 0.25, t_end: float = 1.0, dt: float = 0.01
) -> TwistProfile:
    r"""Drive along the fixed x axis; from ``t_start`` on, keep doing so while spinning at ``rate``.

    In the body frame the velocity of C turns at :math:`-\dot\psi`: every module must keep steering.

    Parameters
    ----------
    speed : float
        Speed of C, m/s, > 0.
    rate : float
        Turning rate :math:`\dot\psi` after ``t_start``, rad/s.
    t_start, t_end, dt : float
        Start of the spin, duration and control period, s.

    Returns
    -------
    TwistProfile
    """
    speed = validation.number("speed", validation.positive("speed", speed))
    rate = validation.number("rate", rate)
    t_start, dt, t = _times(t_start, t_end, dt, first="t_start")
    psi_dot = np.where(t >= t_start - 1e-9 * dt, rate, 0.0)
    v = np.tile([speed, 0.0], (len(t), 1))
    return TwistProfile("spin while translating", dt, _body(v, psi_dot, t, "speed and rate"))
