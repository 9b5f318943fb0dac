r"""The joints of a wheel unit: what turns in it, and whether a motor turns it.

Every wheel kind declares its joints once (``JOINTS``, a tuple of :class:`Joint`), with the
actuation that kind usually has; a unit can be built with another (``driven=``, see
:class:`~wmr.model.wheels.unit.WheelUnit`).  A joint whose rate is a column of :math:`\mathbf J_2`
names that rate variable (``rate``); the unit's rates :math:`\dot{\boldsymbol\theta}_i` are those
joints' rates, in the order of the joints.

==========  =====================================================================================
kind        the joint
==========  =====================================================================================
``steer``   a vertical joint between the platform and the unit, which a steering motor turns;
            its angle :math:`\beta_i` is an entry of the robot's configuration
``swivel``  a vertical joint that turns freely, with no motor of its own (the unit's wheels turn
            it, as in a dual-wheel unit); its angle :math:`\beta_i` is a configuration entry too
``drive``   a wheel's spin about its axle :math:`\mathbf i_i`
``roller``  the free rollers on the rim of a Swedish wheel
==========  =====================================================================================

A unit with a ``steer`` or ``swivel`` joint is *steered*: its :math:`\beta_i` comes from the
robot's configuration.  A unit without one has a constant angle of its own.  A joint's rate variable
is its own rate, or (``absolute``) its rate measured from the ground: an offset wheel's
:math:`\dot\phi_i = \dot\psi + \dot\beta_i` (7).

Examples
--------
>>> Joint("drive", "drive", driven=True, rate=("theta", r"\theta", ""))
Joint(name='drive', kind='drive', driven=True, rate=('theta', '\\theta', ''), absolute=False)
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from ...errors import InputTypeError, InputValueError
from ..checks import flag, kind_error, show

__all__ = ["JOINT_KINDS", "Joint"]

#: the kinds of joint a wheel unit can have, and what each is
JOINT_KINDS = {
    "steer": "a vertical joint turned by a steering motor (its angle is a configuration entry)",
    "swivel": "a vertical joint that turns freely (its angle is a configuration entry)",
    "drive": "a wheel's spin about its axle",
    "roller": "the free rollers on the rim of a Swedish wheel",
}
#: joint kinds that make a unit steered: their angle is the unit's entry of the configuration
STEERING_JOINTS = ("steer", "swivel")


@dataclass(frozen=True)
class Joint:
    r"""One joint of a wheel unit.

    Parameters
    ----------
    name : str
        Its name in the unit (unique there), e.g. ``"steer"``, ``"drive1"``.
    kind : str
        One of :data:`JOINT_KINDS`.
    driven : bool
        True when a motor drives it, False when it is passive.
    rate : tuple of 3 str, optional
        ``(plain name, TeX letter, suffix after the wheel number)`` of its rate variable when that
        rate is a column of :math:`\mathbf J_2`, e.g. ``("theta", r"\theta", "1")`` for the first
        wheel of a dual unit; ``None`` when it is not (a centred wheel's steering rate, which
        enters only through the angle).
    absolute : bool, optional
        True when the rate variable is the joint's rate **plus** the platform's turning rate
        :math:`\dot\psi` (a rate measured from the ground, as an offset wheel's absolute steering
        rate :math:`\dot\phi_i = \dot\psi + \dot\beta_i` (7)); default False, the joint's own rate.
    """

    name: str
    kind: str
    driven: bool
    rate: tuple[str, str, str] | None = None
    absolute: bool = False

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name.isidentifier():
            raise InputTypeError(f"name must be a joint name (an identifier), got {show(self.name)}")
        if self.kind not in JOINT_KINDS:
            raise InputValueError(f"kind must be one of {', '.join(JOINT_KINDS)}, got {show(self.kind)}")
        if not isinstance(self.driven, bool):
            raise InputTypeError(f"driven must be True or False, got {show(self.driven)}")
        if self.rate is not None and (len(self.rate) != 3 or not all(isinstance(s, str) for s in self.rate)):
            raise InputValueError(f"rate must be (plain name, TeX letter, suffix), got {show(self.rate)}")
        if not isinstance(self.absolute, bool):
            raise InputTypeError(f"absolute must be True or False, got {show(self.absolute)}")
        if self.absolute and self.rate is None:
            raise InputValueError(f"absolute is True for joint {self.name!r}, which has no rate variable")

    @property
    def steering(self) -> bool:
        """True for a vertical joint (``steer`` or ``swivel``): its angle is a configuration entry."""
        return self.kind in STEERING_JOINTS


def actuation(joints: tuple[Joint, ...], driven: Any, owner: str = "unit") -> tuple[bool, ...]:
    """Which of ``joints`` a motor drives (one bool each): their defaults, overridden by ``driven``.

    ``driven`` is None (the defaults), ``{joint name: bool}`` for the joints that differ, or one bool per
    joint; ``owner`` is the unit's class name, for messages.
    """
    names = [j.name for j in joints]
    out = [j.driven for j in joints]
    if driven is None:
        return tuple(out)
    if isinstance(driven, Mapping):
        for name, value in driven.items():
            if name not in names:
                raise InputValueError(
                    f"driven names a joint {name!r} that {owner} does not have (its joints: {', '.join(names)})"
                )
            out[names.index(name)] = flag(f"driven[{name!r}]", value)
        return tuple(out)
    if isinstance(driven, (str, bytes)) or not hasattr(driven, "__len__"):
        raise kind_error("driven", driven, "a mapping {joint name: bool} or one bool per joint")
    if len(driven) != len(names):
        raise InputValueError(f"driven must have one bool per joint ({', '.join(names)}), got {show(driven)}")
    return tuple(flag(f"driven[{k}]", value) for k, value in enumerate(driven))


def rate_columns(joints: tuple[Joint, ...]) -> dict[str, int]:
    r"""Where each joint's rate is among a unit's rates (its columns of :math:`\mathbf J_2`), by joint name."""
    return {j.name: k for k, j in enumerate(j for j in joints if j.rate is not None)}
