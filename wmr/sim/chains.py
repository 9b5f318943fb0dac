r"""Each wheel unit as a small chain of bodies and joints: what a physics engine needs to know of it.

wmr's model of a unit is a block of :math:`\mathbf J_2`; a physics engine needs the unit's
**mechanism**: the intermediate body on its steering hinge at :math:`P_i`, the arm to the wheel
centre, the drive hinge about the axle, which hinges are servoed and which are passive.  This
module describes it **as data**, one function per wheel kind (:func:`unit_chain`, dispatched on the
unit's class), so that :mod:`wmr.sim.mjcf` writes any robot without knowing any wheel kind.

Frames (those of :mod:`wmr.model.conventions`): a unit's root link sits at :math:`P_i` in the
platform frame, on the mount plane (height ``height`` above the ground); its steering hinge turns
about :math:`\mathbf k` by :math:`\beta_i`, so that at joint angle :math:`\beta_i` the link's x axis is
the axle :math:`\mathbf i_i` and its y axis the rolling direction :math:`\mathbf j_i`.  A drive hinge
turns about the link's x axis with wmr's sign: :math:`\dot\theta_i > 0` moves the wheel centre along
:math:`-\mathbf j_i` (6).

==================  ====================================================================================
unit                chain (servo in brackets)
==================  ====================================================================================
OffsetWheel         steering hinge at P [position]; arm to :math:`H = P - d\,\mathbf j`; drive hinge [velocity]
CentredWheel        steering hinge at P [position]; drive hinge at P [velocity]
DualWheel           pivot at P [passive]; two drive hinges at :math:`P \pm b\,\mathbf i` [velocity each]
FixedWheel          no steering hinge (link turned by its ``angle``); drive hinge [velocity]
SwedishWheel        refused: :func:`unit_chain` raises ``NotImplementedError`` (see :data:`SWEDISH_REFUSAL`)
==================  ====================================================================================

Each wheel touches the ground through one sphere of the wheel's radius centred on the wheel centre:
a single contact point directly below the centre, the paper's thin disk (:mod:`wmr.sim.params`
for its friction).  A drawn disk (no contact) shows the wheel.

These functions use only the public attributes of the units (``position``, ``r``, ``d``, ``b``,
``angle``); when the wheel kinds answer for their own joints, each function becomes a method of its
kind, unchanged but for ``unit`` turning into ``self``.
"""
from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass

import numpy as np

from ..model.wheels import (
    CentredWheel,
    DualWheel,
    FixedWheel,
    OffsetWheel,
    SwedishWheel,
)
from .params import Params

__all__ = ["POSITION", "SWEDISH_REFUSAL", "VELOCITY", "Chain", "Joint", "Link", "Shape", "unit_chain"]

#: the servo of a steering hinge: MuJoCo's ``position`` actuator
POSITION = "position"
#: the servo of a drive hinge: MuJoCo's ``velocity`` actuator
VELOCITY = "velocity"

#: why Swedish wheels are not exported
SWEDISH_REFUSAL = (
    "a Swedish (omni/mecanum) wheel rolls on a ring of free rollers, and MuJoCo has no roller contact: a faithful model "
    "needs every roller as a body on its own hinge, shaped (a convex barrel mesh) so that the rollers' envelope is the "
    "wheel's circle, with the contact passing from roller to roller and no encoder for the roller rate sigma_dot. "
    "wmr.sim does not build that, and a sphere with anisotropic friction would not be a roller at all: it refuses the "
    "wheel rather than simulate something else under its name")


@dataclass(frozen=True)
class Joint:
    r"""A hinge of a unit.

    Attributes
    ----------
    name : str
        Its name inside the unit (``"steer"``, ``"drive"``, ``"pivot"``, ``"drive1"``, ...).
    axis : tuple of 3 floats
        Unit axis in its link's frame.
    servo : str or None
        :data:`POSITION`, :data:`VELOCITY`, or None for a passive hinge.
    rate : int or None
        The index, among the unit's rate variables (``unit.RATES``), of the rate this hinge's
        encoder gives; None if it gives none.
    absolute : bool
        That rate is the hinge's rate **plus** the platform's turning rate: the absolute
        steering rate :math:`\dot\phi_i = \dot\psi + \dot\beta_i` (7) of an offset wheel.
    steering : bool
        The hinge's angle is the unit's :math:`\beta_i`.
    """

    name: str
    axis: tuple
    servo: str | None
    rate: int | None = None
    absolute: bool = False
    steering: bool = False


@dataclass(frozen=True)
class Shape:
    """A geometric shape of a link (MuJoCo geom).

    Attributes
    ----------
    kind : str
        ``"sphere"``, ``"cylinder"`` or ``"capsule"``.
    radius : float
    fromto : tuple of 6 floats or None
        End points of a cylinder or capsule, link frame.
    contact : bool
        True for the shape that touches the ground (a wheel's sphere); the others are drawn only.
    """

    kind: str
    radius: float
    fromto: tuple | None = None
    contact: bool = False


@dataclass(frozen=True)
class Link:
    """A rigid body of a unit.

    Attributes
    ----------
    name : str
        Its name inside the unit.
    pos : tuple of 3 floats
        Origin in the parent's frame (the root's parent is the platform).
    angle : float
        Turn about z relative to the parent, radians (a fixed wheel's own angle).
    joint : Joint or None
        The hinge joining it to its parent (None: welded).
    mass : float
        kg.
    inertia : tuple of 3 floats
        Principal moments about the link's axes at its origin, kg m^2.
    shapes : tuple of Shape
    children : tuple of Link
    """

    name: str
    pos: tuple
    angle: float
    joint: Joint | None
    mass: float
    inertia: tuple
    shapes: tuple
    children: tuple = ()

    def walk(self):
        """This link and its descendants, depth first (the order MuJoCo numbers their joints).

        Returns
        -------
        list of Link
        """
        out = [self]
        for c in self.children:
            out.extend(c.walk())
        return out


@dataclass(frozen=True)
class Chain:
    """A wheel unit as bodies and joints.

    Attributes
    ----------
    root : Link
        The link at :math:`P_i`.
    """

    root: Link

    @property
    def links(self):
        """Every link, depth first: list of Link."""
        return self.root.walk()

    @property
    def joints(self):
        """Every hinge, in MuJoCo's order: list of Joint."""
        return [k.joint for k in self.links if k.joint is not None]

    @property
    def wheels(self):
        """The links that touch the ground: list of Link."""
        return [k for k in self.links if any(s.contact for s in k.shapes)]


def _disk(mass, r):
    """Principal moments of a thin disk of radius ``r`` turning about x: (m r^2/2, m r^2/4, m r^2/4)."""
    return (mass * r * r / 2, mass * r * r / 4, mass * r * r / 4)


def _block(mass, size):
    """Principal moments of a small cube of side ``size``: m size^2 / 6 about each axis."""
    m = mass * size * size / 6
    return (m, m, m)


def _wheel(name, pos, r, joint, params):
    """A wheel link: contact sphere of radius r, a drawn disk of width r/2, its drive hinge about x."""
    w = r / 4
    return Link(name, pos, 0.0, joint, params.wheel_mass, _disk(params.wheel_mass, r),
                (Shape("sphere", r, contact=True), Shape("cylinder", r, (-w, 0.0, 0.0, w, 0.0, 0.0))))


def _arms(r, *ends):
    """Drawn rods of radius r/8 between pairs of points of a link (those of length zero left out)."""
    return tuple(Shape("capsule", r / 8, tuple(a) + tuple(b)) for a, b in ends
                 if np.hypot.reduce(np.subtract(a, b)) > 1e-6 * r)


@functools.singledispatch
def unit_chain(unit, height, params=None):
    r"""The chain of bodies and joints of a wheel unit (one function per wheel kind).

    Parameters
    ----------
    unit : wheel unit
        A unit of :mod:`wmr.model.wheels` (numbers, not symbols).
    height : float
        Height of the mount plane (the steering hinges' origins) above the ground, >= the
        unit's wheel radius.
    params : Params, optional

    Returns
    -------
    Chain

    Raises
    ------
    NotImplementedError
        For a unit the physics engine cannot represent faithfully (Swedish wheels:
        :data:`SWEDISH_REFUSAL`), or a kind without a description.

    Examples
    --------
    >>> from wmr import OffsetWheel
    >>> ch = unit_chain(OffsetWheel((0.3, 0.0), r=0.05, d=0.02), height=0.05)
    >>> [(j.name, j.servo, j.rate) for j in ch.joints]
    [('steer', 'position', 0), ('drive', 'velocity', 1)]
    >>> ch.wheels[0].pos                       # H = P - d j, at the wheel's height
    (0.0, -0.02, 0.0)
    """
    raise NotImplementedError(f"wmr.sim has no physical description of wheel units of type {type(unit).__name__}")


def _root(unit, name, joint, params, children, size):
    x, y = (float(v) for v in unit.position)
    return Link(name, (x, y, 0.0), 0.0, joint, params.body_mass, _block(params.body_mass, size), (), children)


@unit_chain.register
def _offset(unit: OffsetWheel, height, params=None):
    params = params or Params()
    r, d = float(unit.r), float(unit.d)
    H = (0.0, -d, r - height)                                  # H = P - d j, wheel centre at height r
    steer = Joint("steer", (0.0, 0.0, 1.0), POSITION, rate=0, absolute=True, steering=True)   # phi = psi + beta (7)
    drive = Joint("drive", (1.0, 0.0, 0.0), VELOCITY, rate=1)
    wheel = _wheel("wheel", H, r, drive, params)
    root = _root(unit, "steer", steer, params, (wheel,), max(d, r / 2))
    return Chain(dataclasses.replace(root, shapes=_arms(r, ((0.0, 0.0, 0.0), H))))


@unit_chain.register
def _centred(unit: CentredWheel, height, params=None):
    params = params or Params()
    r = float(unit.r)
    steer = Joint("steer", (0.0, 0.0, 1.0), POSITION, steering=True)
    drive = Joint("drive", (1.0, 0.0, 0.0), VELOCITY, rate=0)
    wheel = _wheel("wheel", (0.0, 0.0, r - height), r, drive, params)
    return Chain(_root(unit, "steer", steer, params, (wheel,), r / 2))


@unit_chain.register
def _dual(unit: DualWheel, height, params=None):
    params = params or Params()
    r, b = float(unit.r), float(unit.b)
    pivot = Joint("pivot", (0.0, 0.0, 1.0), None, steering=True)
    wheels = tuple(_wheel(f"wheel{k}", (s * b, 0.0, r - height), r, Joint(f"drive{k}", (1.0, 0.0, 0.0), VELOCITY, rate=k - 1),
                          params) for k, s in ((1, 1.0), (2, -1.0)))       # wheel 1 at P + b i, wheel 2 at P - b i
    root = _root(unit, "pivot", pivot, params, wheels, r / 2)
    shapes = _arms(r, ((b, 0.0, r - height), (-b, 0.0, r - height)), ((0.0, 0.0, 0.0), (0.0, 0.0, r - height)))
    return Chain(dataclasses.replace(root, shapes=shapes))


@unit_chain.register
def _fixed(unit: FixedWheel, height, params=None):
    params = params or Params()
    r = float(unit.r)
    x, y = (float(v) for v in unit.position)
    drive = Joint("drive", (1.0, 0.0, 0.0), VELOCITY, rate=0)
    wheel = _wheel("wheel", (x, y, r - height), r, drive, params)
    return Chain(dataclasses.replace(wheel, angle=float(unit.angle)))


@unit_chain.register
def _swedish(unit: SwedishWheel, height, params=None):
    raise NotImplementedError(f"Swedish wheel at {tuple(float(v) for v in unit.position)}: {SWEDISH_REFUSAL}")


def height_of(robot):
    """Height of the mount plane: the largest wheel radius (every wheel centre at or below it).

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    float
    """
    return float(np.max([float(u.r) for u in robot.wheels]))
