r"""What a wheel kind offers design: its dead zone, the change that makes its block isotropic, its other builds.

A wheel kind answers for its mathematics (:mod:`wmr.model.wheels`); what the design analyses make of it
is this module's, one entry per kind and question (:func:`functools.singledispatch` on the unit's
class, so a subclass takes its base's entry, and a kind with nothing to say takes the default: no
dead zone, no change, no other build).

=============================  ====================================================================
kind                           entries
=============================  ====================================================================
:class:`~wmr.OffsetWheel`      dead zone :math:`d`; isotropic with :math:`d = r` (the paper's (46))
:class:`~wmr.SwedishWheel`     isotropic with omni rollers (:math:`\gamma = \pi/2`); the other hand
=============================  ====================================================================

Examples
--------
>>> import wmr
>>> dead_zone(wmr.OffsetWheel((0, 0), r=0.1, d=0.03)), dead_zone(wmr.CentredWheel((0, 0), r=0.1))
(0.03, None)
"""

from __future__ import annotations

import enum
import functools
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..model.tolerance import TOL
from ..model.wheels import OffsetWheel, SwedishWheel, WheelUnit

__all__ = ["ChangeKind", "Change", "dead_zone", "isotropic_change", "other_builds"]


class ChangeKind(enum.Enum):
    """What a :class:`Change` changes."""

    OFFSET_EQUALS_RADIUS = "offset = radius"  #: an offset wheel's d set to its r (the paper's (46))
    OMNI_ROLLERS = "omni rollers"  #: a Swedish wheel's rollers at 90 deg
    OTHER_HAND = "other hand"  #: a Swedish wheel's rollers at minus their angle


@dataclass(frozen=True)
class Change:
    """A unit changed (in words: :func:`wmr.words.advice.change`).

    Attributes
    ----------
    kind : ChangeKind
        What is changed.
    unit : WheelUnit
        The changed unit.
    """

    kind: ChangeKind
    unit: WheelUnit


@functools.singledispatch
def dead_zone(unit: Any) -> float | None:
    """The radius of C's circle when every unit is steered with its drives locked, if this unit has one.

    The paper's dead zone of a robot on offset wheels (:func:`dead_zone_radius`).

    Parameters
    ----------
    unit : WheelUnit

    Returns
    -------
    float or None
        None: steering the unit does not move the platform (or the unit is not steered).
    """
    return None


@dead_zone.register
def _offset_dead_zone(unit: OffsetWheel) -> float | None:
    """Steered with the drives locked, offset wheels carry C on a circle of radius d."""
    return float(unit.d)


def dead_zone_radius(robot) -> float | None:
    """Radius d of the dead zone of a robot on offset wheels of one offset d: C's circle when steered without driving.

    None when some unit has no :func:`dead_zone` or the offsets differ.
    """
    zones = [dead_zone(u) for u in robot.wheels]
    if any(z is None for z in zones):
        return None
    d = np.array(zones, dtype=float)
    return float(d[0]) if np.all(np.abs(d - d[0]) <= TOL * d.max()) else None


@functools.singledispatch
def isotropic_change(unit: Any) -> Change | None:
    """The change that makes this unit's block isotropic (equal singular values), if one does and is needed.

    Parameters
    ----------
    unit : WheelUnit

    Returns
    -------
    Change or None
        None when the block is isotropic already or no choice of the kind's parameters makes it so.
    """
    return None


@isotropic_change.register
def _offset_isotropic(unit: OffsetWheel) -> Change | None:
    r"""``d = r`` (the paper's (46)) makes :math:`\mathbf L_i = -r\mathbf 1`."""
    d, r = float(unit.d), float(unit.r)
    if abs(d - r) <= TOL * max(d, r):
        return None
    return Change(ChangeKind.OFFSET_EQUALS_RADIUS, replace(unit, d=unit.r))


@isotropic_change.register
def _swedish_isotropic(unit: SwedishWheel) -> Change | None:
    r"""Omni rollers (:math:`\gamma = \pi/2`) make the block :math:`r\,\mathbf R`."""
    if abs(np.cos(float(unit.roller))) <= TOL:
        return None
    return Change(ChangeKind.OMNI_ROLLERS, replace(unit, roller=np.pi / 2))


@functools.singledispatch
def other_builds(unit: Any) -> tuple[Change, ...]:
    """Other ways to build this unit that change which motions its motors drive.

    The design advice tries them when the motors of a robot cannot drive every motion it can make
    (:func:`wmr.analysis.advice.actuation_advice`).

    Parameters
    ----------
    unit : WheelUnit

    Returns
    -------
    tuple of Change
        Empty for the kinds without such a choice.
    """
    return ()


@other_builds.register
def _swedish_builds(unit: SwedishWheel) -> tuple[Change, ...]:
    r"""The wheel of the other hand (rollers at :math:`-\gamma`), unless it is an omni wheel."""
    if abs(np.cos(float(unit.roller))) <= TOL:
        return ()
    return (Change(ChangeKind.OTHER_HAND, replace(unit, roller=-unit.roller)),)
