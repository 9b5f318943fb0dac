r"""WPILib's chassis velocities as wmr twists: :func:`twist_of` and :func:`chassis_speeds`, without wpimath at import.

A ``ChassisSpeeds`` is ``(vx, vy, omega)`` and iterates in that order; wmr's twist is
:math:`[\dot\psi, \dot x, \dot y]`, the turning rate first.  ``np.asarray(speeds)`` of a ``ChassisSpeeds``
is therefore a twist read in the wrong order, silently.  :func:`twist_of` reads the attributes by
name (any object with ``vx, vy, omega``, or a ``Twist2d``'s ``dx, dy, dtheta``), so it needs no
wpimath, and :func:`is_chassis_speeds` tells such an object from an array: a function that takes a
twist can refuse or convert it.  This module imports nothing of :mod:`wmr.swerve`, which may use it.

Examples
--------
>>> from types import SimpleNamespace
>>> speeds = SimpleNamespace(vx=1.0, vy=2.0, omega=3.0)          # what a ChassisSpeeds(1, 2, 3) holds
>>> twist_of(speeds).tolist(), is_chassis_speeds(speeds), is_chassis_speeds([3.0, 1.0, 2.0])
([3.0, 1.0, 2.0], True, False)
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ..errors import InputTypeError
from ..model import validation
from ..model.types import FloatArray, TwistLike
from .extras import require

__all__ = ["twist_of", "chassis_speeds", "is_chassis_speeds"]


def is_chassis_speeds(obj: object) -> bool:
    """True for a WPILib ``ChassisSpeeds`` or ``Twist2d`` (any object with their attributes), or a sequence of them.

    The objects are those of :data:`wmr.model.arrays.TWIST_OBJECTS` (a ROS ``Twist`` too).

    Parameters
    ----------
    obj : object

    Returns
    -------
    bool
    """
    if isinstance(obj, Sequence) and not isinstance(obj, str):
        return bool(obj) and all(validation.twist_kind(x) is not None for x in obj)
    return validation.twist_kind(obj) is not None


def twist_of(speeds: Any) -> FloatArray:
    r"""wmr's twist :math:`[\dot\psi, \dot x, \dot y]` of a ``ChassisSpeeds`` (or the increment of a ``Twist2d``).

    Read by field names (:func:`wmr.model.arrays.twist_array`, the one conversion every function that
    takes a twist uses).

    Parameters
    ----------
    speeds : ChassisSpeeds, Twist2d, or a sequence of them
        Any object with ``vx, vy, omega`` (or ``dx, dy, dtheta``) attributes: wpimath is not imported.

    Returns
    -------
    numpy.ndarray (3,) or (n, 3)

    Raises
    ------
    wmr.errors.InputTypeError
        If ``speeds`` is neither (an array is not accepted: its order would be a guess).
    """
    if not is_chassis_speeds(speeds):
        raise InputTypeError(
            f"speeds must be a WPILib ChassisSpeeds(vx, vy, omega) or Twist2d(dx, dy, dtheta), "
            f"or a sequence of them, got {validation.show(speeds)}"
        )
    return validation.twist_array("speeds", speeds)


def chassis_speeds(twist: TwistLike) -> Any:
    r"""WPILib's ``ChassisSpeeds(vx, vy, omega)`` of a wmr twist :math:`[\dot\psi, \dot x, \dot y]`.

    Parameters
    ----------
    twist : array (3,)

    Returns
    -------
    wpimath.kinematics.ChassisSpeeds
    """
    psi_dot, vx, vy = validation.finite_array("twist", twist, last=3).reshape(3)
    kinematics = require("wpilib", "WPILib ChassisSpeeds", "wpimath.kinematics")
    return kinematics.ChassisSpeeds(float(vx), float(vy), float(psi_dot))
