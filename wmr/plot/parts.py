r"""How a wheel unit looks from above, as data: each kind's parts (no matplotlib, no style).

:func:`unit_parts` has one entry per kind (:func:`functools.singledispatch` on the unit's class, so a subclass takes
its base's entry), giving the unit's parts in the body frame at one steering angle; :mod:`wmr.plot.units` draws each
part by its type.  **A new kind of wheel** registers its entry here (``@unit_parts.register``), as it does in
:mod:`wmr.sim` and :mod:`wmr.io`.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any, TypeAlias

import numpy as np

from ..model import checks
from ..model.wheels import CentredWheel, DualWheel, FixedWheel, OffsetWheel, SwedishWheel, WheelUnit

__all__ = ["Disc", "Link", "Rollers", "Pivot", "Part", "unit_parts", "drawn_angle"]


@dataclass(frozen=True)
class Disc:
    r"""A wheel seen from above: :math:`2r` long along :math:`\mathbf j = \mathbf R(\beta)[0\ 1]^T`.

    Parameters
    ----------
    centre : numpy.ndarray (2,)
        Its centre (body frame).
    heading : float
        The angle :math:`\beta` of its wheel frame in the body frame.
    r : float
        Wheel radius.
    arrow : bool, optional
        Mark the rolling direction :math:`+\mathbf j` (not on a Swedish wheel, which rolls every way).
    """

    centre: np.ndarray
    heading: float
    r: float
    arrow: bool = True


@dataclass(frozen=True)
class Link:
    """A rigid bar of the intermediate body between two points.

    Parameters
    ----------
    ends : numpy.ndarray (2, 2)
        Its two end points (body frame).
    over : bool
        Drawn over the wheels (an arm to the wheel) or under them (a bar between two wheels).
    r : float
        Wheel radius of the unit (the scale of the drawing).
    """

    ends: np.ndarray
    over: bool
    r: float


@dataclass(frozen=True)
class Rollers:
    r"""The free rollers in contact on the rim of a Swedish wheel.

    Parameters
    ----------
    centre : numpy.ndarray (2,)
    heading : float
        The wheel's centre and wheel-frame angle :math:`\beta` (body frame).
    r : float
        Wheel radius.
    angle : float
        :math:`\gamma`, the angle of the roller axes to the axle :math:`\mathbf i` (counter-clockwise).
    """

    centre: np.ndarray
    heading: float
    r: float
    angle: float


@dataclass(frozen=True)
class Pivot:
    """A vertical joint (a steering axis) seen from above.

    Parameters
    ----------
    point : numpy.ndarray (2,)
        :math:`P_i` (body frame).
    r : float
        Wheel radius of the unit (the scale of the drawing).
    """

    point: np.ndarray
    r: float


#: any of the parts (what :func:`unit_parts` returns a tuple of)
Part: TypeAlias = Disc | Link | Rollers | Pivot


def drawn_angle(unit: WheelUnit, beta: float) -> float:
    """The angle a unit is drawn at: ``beta``, or the unit's own constant angle.

    Parameters
    ----------
    unit : WheelUnit
    beta : float

    Returns
    -------
    float
    """
    own = unit.constant_angle
    return checks.number("beta", beta) if own is None else float(own)


def _discs(unit: WheelUnit, angle: float, arrow: bool = True) -> tuple[Part, ...]:
    """A disc per wheel of the unit at its drawn ``angle``; a pivot at :math:`P_i` for a steered unit."""
    discs = tuple(Disc(c, angle, float(unit.r), arrow) for c in unit.points(angle)["wheels"])
    return discs + ((Pivot(np.asarray(unit.position, dtype=float), float(unit.r)),) if unit.steered else ())


@functools.singledispatch
def unit_parts(unit: Any, beta: float) -> tuple[Part, ...]:
    r"""The parts of a wheel unit seen from above at steering angle ``beta``, body frame.

    Parameters
    ----------
    unit : WheelUnit
        Of a kind with an entry here.
    beta : float
        The unit's steering angle :math:`\beta_i` (a unit with a constant angle uses its own).

    Returns
    -------
    tuple of Disc, Link, Rollers or Pivot
        In drawing order: bars under the wheels, a disc per wheel, an arm over them, a pivot at
        :math:`P_i` for a steered unit.

    Raises
    ------
    NotImplementedError
        For a kind without an entry (the message says how to register one).

    Examples
    --------
    >>> from wmr import CentredWheel
    >>> [type(p).__name__ for p in unit_parts(CentredWheel((1.0, 0.0), r=0.1), 0.3)]
    ['Disc', 'Pivot']
    """
    raise NotImplementedError(
        f"{type(unit).__name__} has no drawing entry: register one with @wmr.plot.parts.unit_parts.register"
    )


@unit_parts.register(CentredWheel)
@unit_parts.register(FixedWheel)
def _plain(unit: WheelUnit, beta: float) -> tuple[Part, ...]:
    """A disc (and a pivot when steered)."""
    return _discs(unit, drawn_angle(unit, beta))


@unit_parts.register
def _offset(unit: OffsetWheel, beta: float) -> tuple[Part, ...]:
    """The arm from the steering axis to the wheel, the wheel, the steering axis."""
    angle = drawn_angle(unit, beta)
    pts = unit.points(angle)
    return (Link(np.stack([pts["P"], pts["H"]]), over=True, r=float(unit.r)),) + _discs(unit, angle)


@unit_parts.register
def _dual(unit: DualWheel, beta: float) -> tuple[Part, ...]:
    """The bar between the two wheels, the wheels, the swivel."""
    angle = drawn_angle(unit, beta)
    return (Link(unit.points(angle)["wheels"], over=False, r=float(unit.r)),) + _discs(unit, angle)


@unit_parts.register
def _swedish(unit: SwedishWheel, beta: float) -> tuple[Part, ...]:
    """The wheel without a rolling arrow (it rolls every way), and its rollers."""
    angle = drawn_angle(unit, beta)
    centre = unit.points(angle)["H"]
    return _discs(unit, angle, arrow=False) + (Rollers(centre, angle, float(unit.r), float(unit.roller)),)


def has_parts(kind: type) -> bool:
    """Whether a wheel kind has an entry in :func:`unit_parts` (its own or a base class's): the contract test's ask."""
    return unit_parts.dispatch(kind) is not unit_parts.dispatch(object)
