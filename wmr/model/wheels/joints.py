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
robot's configuration.  A unit without one has a constant angle of its own.

Examples
--------
>>> Joint("drive", "drive", driven=True, rate=("theta", r"\theta", ""))
Joint(name='drive', kind='drive', driven=True, rate=('theta', '\\theta', ''))
"""
from __future__ import annotations

from dataclasses import dataclass

from ...errors import InputTypeError, InputValueError
from ..checks import show

__all__ = ["JOINT_KINDS", "STEERING_JOINTS", "Joint"]

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
    """

    name: str
    kind: str
    driven: bool
    rate: tuple[str, str, str] | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name.isidentifier():
            raise InputTypeError(f"name must be a joint name (an identifier), got {show(self.name)}")
        if self.kind not in JOINT_KINDS:
            raise InputValueError(f"kind must be one of {', '.join(JOINT_KINDS)}, got {show(self.kind)}")
        if not isinstance(self.driven, bool):
            raise InputTypeError(f"driven must be True or False, got {show(self.driven)}")
        if self.rate is not None and (len(self.rate) != 3 or not all(isinstance(s, str) for s in self.rate)):
            raise InputValueError(f"rate must be (plain name, TeX letter, suffix), got {show(self.rate)}")

    @property
    def steering(self) -> bool:
        """True for a vertical joint (``steer`` or ``swivel``): its angle is a configuration entry."""
        return self.kind in STEERING_JOINTS
