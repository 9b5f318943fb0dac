r"""How a wheel unit looks from above, as data: the parts :meth:`WheelUnit.parts` returns.

A unit describes its parts in the body frame at one steering angle; :mod:`wmr.plot.robot` draws
each part by its type, so it draws every wheel kind without asking which kind it is.  No
matplotlib here, and no style: sizes are the unit's own (its wheel radius), colours and line
widths are the drawing's.

================  =====================================================================================
part              what it is
================  =====================================================================================
:class:`Disc`     a wheel: from above a rounded rectangle :math:`2r` long along the rolling direction
:class:`Link`     a rigid bar of the intermediate body (an offset wheel's arm, a dual wheel's axle bar)
:class:`Rollers`  the free rollers in contact on a Swedish wheel, at their angle to the axle
:class:`Pivot`    a vertical joint (steering axis) at :math:`P_i`
================  =====================================================================================

Examples
--------
>>> from wmr import OffsetWheel
>>> [type(p).__name__ for p in OffsetWheel((1.0, 0.0), r=0.1, d=0.2).parts(0.0)]
['Link', 'Disc', 'Pivot']
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TypeAlias

import numpy as np

__all__ = ["Disc", "Link", "Rollers", "Pivot", "Part"]


@dataclass(frozen=True)
class Disc:
    r"""A wheel seen from above.

    Parameters
    ----------
    centre : numpy.ndarray (2,)
        Its centre (body frame).
    heading : float
        The angle :math:`\beta` of its wheel frame in the body frame: the disc is :math:`2r` long
        along :math:`\mathbf j = \mathbf R(\beta)[0\ 1]^T`.
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
        Drawn over the wheels (an arm from the steering axis to the wheel) or under them (a bar
        between two wheels).
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
        The wheel's centre (body frame).
    heading : float
        The angle :math:`\beta` of the wheel frame (body frame).
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


#: any of the parts (what :meth:`wmr.model.wheels.WheelUnit.parts` returns a tuple of)
Part: TypeAlias = Disc | Link | Rollers | Pivot
