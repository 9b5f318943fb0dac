r"""A wheel unit as bodies and joints, as data: what a robot description (URDF, MJCF) is written from.

wmr's model of a unit is a block of :math:`\mathbf J_2` (:mod:`wmr.model.wheels`); a robot description
and a physics engine need the unit's **mechanism**: the intermediate body on its steering joint at
:math:`P_i`, the arm to the wheel centre, the wheels on their drive joints.  Each kind has an entry here,
:func:`root_body` (:func:`functools.singledispatch` on the unit's class, so a subclass takes its base's
entry), giving a tree of :class:`Body` that :func:`mechanism` checks and assembles: plain data with no
engine in it.  :mod:`wmr.io.urdf_write` writes any such tree as URDF, :mod:`wmr.sim` as a MuJoCo model
(adding masses, friction and servos), without knowing which kind it came from.

Frames (those of :mod:`wmr.model.conventions`): the root body's origin is given in the platform frame,
on the mount plane (at height ``height`` above the ground), a child's in its parent's frame.  A
steering joint turns its body about :math:`\mathbf k` (:data:`VERTICAL`) by :math:`\beta_i`, so that at
joint angle :math:`\beta_i` the body's x axis is the axle :math:`\mathbf i_i` and its y axis the rolling
direction :math:`\mathbf j_i`.  A wheel body spins about its own x axis (:data:`AXLE`) with wmr's sign,
:math:`\dot\theta_i > 0` moving the wheel centre along :math:`-\mathbf j_i` (6), and touches the ground at
one point directly below its origin (the paper's thin disk).

The joints of the tree are the unit's own (:attr:`~wmr.model.wheels.unit.WheelUnit.joints`, with the
unit's actuation): a physics engine puts a motor on the driven ones only, so a castor
(``OffsetWheel(..., driven={"steer": False, "drive": False})``) is exported with none.

=======  ===================================================================================================
kind     mechanism (bodies on the unit's joints)
=======  ===================================================================================================
offset   steer body at :math:`P_i` on ``steer``; the arm to the wheel at :math:`H_i = P_i - d\,\mathbf j_i` on
         ``drive``
centred  steer body at :math:`P_i` on ``steer``; the wheel at :math:`P_i` on ``drive``
dual     swivel body at :math:`P_i` on ``swivel``; wheels at :math:`P_i \pm b\,\mathbf i_i` on ``drive1``,
         ``drive2``
fixed    the wheel at :math:`P_i`, turned by its ``angle``, on ``drive``
swedish  none: refused (``NotImplementedError``, the reason: :data:`NO_FAITHFUL_MECHANISM`)
=======  ===================================================================================================

Examples
--------
>>> from wmr import OffsetWheel
>>> m = mechanism(OffsetWheel((0.3, 0.0), r=0.05, d=0.02), height=0.05)
>>> [(b.name, b.joint.name, b.axis) for b in m.bodies]
[('steer', 'steer', (0.0, 0.0, 1.0)), ('wheel', 'drive', (1.0, 0.0, 0.0))]
>>> m.wheels[0].pos                        # H = P - d j, at the wheel's height (the mount plane's)
(0.0, -0.02, 0.0)
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

from ..errors import InputValueError
from ..model.checks import number, show
from ..model.wheels import CentredWheel, DualWheel, FixedWheel, OffsetWheel, SwedishWheel
from ..model.wheels.joints import Joint

__all__ = ["AXLE", "VERTICAL", "NO_FAITHFUL_MECHANISM", "Body", "Mechanism", "root_body", "mechanism"]

#: the axis of a steering joint, in its body's frame: the vertical :math:`\mathbf k`
VERTICAL = (0.0, 0.0, 1.0)
#: the axis of a drive joint, in the wheel body's frame: its x axis, the axle :math:`\mathbf i_i`
AXLE = (1.0, 0.0, 0.0)

Point = tuple[float, float, float]


@dataclass(frozen=True)
class Body:
    """A rigid body of a unit's mechanism.

    Parameters
    ----------
    name : str
        Its name in the unit (unique there), e.g. ``"steer"``, ``"wheel1"``.
    pos : tuple of 3 floats
        Its origin in the parent's frame (the root's: the platform frame, z = 0 on the mount plane).
    angle : float, optional
        A constant turn about z relative to the parent, radians (a fixed wheel's own angle).
    joint : Joint or None, optional
        The unit's joint between it and its parent (None: welded to the parent).
    axis : tuple of 3 floats or None, optional
        The joint's unit axis in this body's frame (:data:`VERTICAL`, :data:`AXLE`).
    wheel : float or None, optional
        The radius of the wheel this body is (it spins about its x axis and touches the ground below
        its origin); None for an intermediate body.
    size : float, optional
        A length for the inertia of an intermediate body (that of a small cube of this side).
    rods : tuple of pairs of points, optional
        Bars to draw between points of this body (an offset wheel's arm); they have no mass and do
        not touch anything.
    children : tuple of Body, optional
    """

    name: str
    pos: Point
    angle: float = 0.0
    joint: Joint | None = None
    axis: Point | None = None
    wheel: float | None = None
    size: float = 0.0
    rods: tuple[tuple[Point, Point], ...] = ()
    children: tuple[Body, ...] = ()

    def walk(self) -> list[Body]:
        """This body and its descendants, depth first (the order in which a physics engine numbers their joints).

        Returns
        -------
        list of Body
        """
        out = [self]
        for c in self.children:
            out.extend(c.walk())
        return out


@dataclass(frozen=True)
class Mechanism:
    """A wheel unit as a tree of bodies and joints.

    Parameters
    ----------
    root : Body
        The body mounted on the platform, at :math:`P_i` (or the wheel itself, for a unit without
        an intermediate body).
    """

    root: Body

    def __post_init__(self) -> None:
        names = [b.name for b in self.bodies]
        joints = [j.name for j in self.joints]
        if len(set(names)) != len(names) or len(set(joints)) != len(joints):
            raise InputValueError(
                f"a mechanism's bodies and joints must have distinct names, got bodies {names}, joints {joints}"
            )
        for b in self.bodies:
            if b.joint is not None and (b.axis is None or len(b.axis) != 3):
                raise InputValueError(f"body {b.name!r} turns on joint {b.joint.name!r} about no axis: {show(b.axis)}")
            if b.wheel is not None and not b.wheel > 0:
                raise InputValueError(f"body {b.name!r} is a wheel of radius {show(b.wheel)} (must be > 0)")

    @property
    def bodies(self) -> list[Body]:
        """Every body, depth first: list of Body."""
        return self.root.walk()

    @property
    def joints(self) -> list[Joint]:
        """Every joint, depth first (a physics engine's order): list of Joint."""
        return [b.joint for b in self.bodies if b.joint is not None]

    @property
    def wheels(self) -> list[Body]:
        """The bodies that touch the ground: list of Body."""
        return [b for b in self.bodies if b.wheel is not None]


def mount(position: Any) -> Point:
    r"""The mount point :math:`P_i` of a unit's (numeric) ``position``, as a root body's origin: ``(x, y, 0.0)``."""
    x, y = (float(v) for v in position)
    return (x, y, 0.0)


def wheel(name: str, pos: Point, r: float, joint: Joint, angle: float = 0.0) -> Body:
    """A wheel body of radius ``r`` centred at ``pos`` (parent's frame) on its drive joint (about its x axis, the axle).

    ``angle`` is a constant turn about z (a wheel without a steering joint: its own angle).
    """
    return Body(name, pos, angle, joint, AXLE, wheel=float(r))


@functools.singledispatch
def root_body(unit: Any, height: float) -> Body:
    """The body mounted on the platform, with the rest of the unit under it: the kind's entry (module notes).

    Parameters
    ----------
    unit : WheelUnit
        A numeric unit.
    height : float
        Height of the mount plane above the ground (checked by :func:`mechanism`: at least the wheel radius).

    Returns
    -------
    Body

    Raises
    ------
    NotImplementedError
        For a kind without an entry (the message says how to register one), or whose entry refuses
        (the message says why).
    """
    raise NotImplementedError(
        f"{type(unit).__name__} does not describe its mechanism (its bodies and joints): register one with "
        "@wmr.io.mechanism.root_body.register, or a refusal that says why, so no physics engine can take it"
    )


@root_body.register
def _offset(unit: OffsetWheel, height: float) -> Body:
    r"""The steer body at :math:`P_i` on ``steer``, its arm to the wheel at :math:`H_i = P_i - d\,\mathbf j_i` on ``drive``."""
    r, d = float(unit.r), float(unit.d)
    H = (0.0, -d, r - height)  # H = P - d j, the wheel centre at height r
    steer, drive = unit.joints
    rods = (((0.0, 0.0, 0.0), H),)
    return Body(
        "steer",
        mount(unit.position),
        0.0,
        steer,
        VERTICAL,
        size=max(d, r / 2),
        rods=rods,
        children=(wheel("wheel", H, r, drive),),
    )


@root_body.register
def _centred(unit: CentredWheel, height: float) -> Body:
    r"""The steer body at :math:`P_i` on ``steer``, the wheel under it (centre :math:`P_i`) on ``drive``."""
    r = float(unit.r)
    steer, drive = unit.joints
    return Body(
        "steer",
        mount(unit.position),
        0.0,
        steer,
        VERTICAL,
        size=r / 2,
        children=(wheel("wheel", (0.0, 0.0, r - height), r, drive),),
    )


@root_body.register
def _dual(unit: DualWheel, height: float) -> Body:
    r"""The swivel body at :math:`P_i` on ``swivel``, the wheels at :math:`P_i \pm b\,\mathbf i_i` on ``drive1``, ``drive2``."""
    r, b = float(unit.r), float(unit.b)
    z = r - height  # the wheel centres at height r
    swivel, drive1, drive2 = unit.joints
    wheels = (wheel("wheel1", (b, 0.0, z), r, drive1), wheel("wheel2", (-b, 0.0, z), r, drive2))
    rods = (((b, 0.0, z), (-b, 0.0, z)), ((0.0, 0.0, 0.0), (0.0, 0.0, z)))  # the axle, the post to it
    return Body("swivel", mount(unit.position), 0.0, swivel, VERTICAL, size=r / 2, rods=rods, children=wheels)


@root_body.register
def _fixed(unit: FixedWheel, height: float) -> Body:
    r"""The wheel alone, centred at :math:`P_i` and turned by its ``angle``, on ``drive``."""
    r = float(unit.r)
    x, y = (float(v) for v in unit.position)
    (drive,) = unit.joints
    return wheel("wheel", (x, y, r - height), r, drive, angle=float(unit.angle))


#: why a Swedish wheel has no mechanism a physics engine could take (its entry refuses)
NO_FAITHFUL_MECHANISM = (
    "a Swedish (omni/mecanum) wheel rolls on a ring of free rollers, and a physics engine of rigid bodies and point "
    "contacts (MuJoCo) has no roller contact: a faithful model needs every roller as a body on its own hinge, shaped "
    "(a convex barrel mesh) so that the rollers' envelope is the wheel's circle, with the contact passing from roller "
    "to roller and no encoder for the roller rate sigma_dot. wmr does not build that, and a sphere with anisotropic "
    "friction would not be a roller at all: the wheel is refused rather than simulated as something else under its "
    "name"
)


@root_body.register
def _swedish(unit: SwedishWheel, height: float) -> Body:
    """None a physics engine could take faithfully: refused (:data:`NO_FAITHFUL_MECHANISM`)."""
    raise NotImplementedError(f"Swedish wheel at {tuple(float(v) for v in unit.position)}: {NO_FAITHFUL_MECHANISM}")


def has_mechanism(kind: type) -> bool:
    """Whether a wheel kind has an entry in :func:`root_body` (its own or a base class's; a refusal counts)."""
    return root_body.dispatch(kind) is not root_body.dispatch(object)


def mechanism(unit: Any, height: float) -> Mechanism:
    """The unit's bodies and joints (module notes), at joint angles 0.

    Parameters
    ----------
    unit : WheelUnit
    height : float
        Height of the mount plane (the root's origin) above the ground, at least the unit's wheel radius.

    Returns
    -------
    Mechanism

    Raises
    ------
    NotImplementedError
        For a unit that a physics engine of rigid bodies and point contacts cannot represent
        faithfully (the message says why), or a kind without an entry.
    wmr.errors.InputError
        If ``height`` is not a number at least the wheel radius, or the unit has free symbols.
    """
    unit = unit.numeric()
    height = number("height", height)
    if not height >= unit.r:
        raise InputValueError(
            f"height (of the mount plane above the ground) must be at least the wheel radius r = {unit.r!r}, got {show(height)}"
        )
    return Mechanism(root_body(unit, height))
