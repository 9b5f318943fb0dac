r"""WPILib's kinematics objects in and out, and its values in wmr's conventions.

robotpy-wpimath's ``SwerveDrive{2,3,4,6}Kinematics``, ``MecanumDriveKinematics`` and
``DifferentialDriveKinematics`` hold a layout (:mod:`wmr.io.layouts`): module or wheel positions,
or a track width.  :func:`from_wpilib` builds the :class:`wmr.Robot`, :func:`to_wpilib` the object.
They hold no wheel radius (WPILib works in metres of ground travel): :func:`from_wpilib` takes it,
:func:`to_wpilib` drops it.

Conventions (:mod:`wmr.model.conventions` states and converts them; the same frames)
----------------------------------------------------------------------------------------
=========================  ====================================  ============================================
quantity                   WPILib                                wmr
=========================  ====================================  ============================================
chassis velocity           ``ChassisSpeeds(vx, vy, omega)``      twist :math:`[\dot\psi, \dot x, \dot y]`
                                                                 (:func:`twist_of`, :func:`chassis_speeds`)
a pose increment           ``Twist2d(dx, dy, dtheta)``           :math:`[\Delta\psi, \Delta x, \Delta y]`
module angle               :math:`\alpha` = direction of travel  :math:`\beta = \alpha + \pi/2`, the axle
module speed, distance     m/s, m along :math:`\alpha`           :math:`r\dot\theta`, :math:`r\theta`
=========================  ====================================  ============================================

A ``ChassisSpeeds`` is ``(vx, vy, omega)`` and iterates in that order; wmr's twist puts :math:`\dot\psi`
first, so ``np.asarray(speeds)`` is a twist in the wrong order, silently.  Every function of wmr that takes
a twist reads such an object by its fields (:func:`wmr.model.checks.twist_array`); :func:`twist_of` does
only that (an array's order would be a guess), and :func:`chassis_speeds` makes one.  None of these
needs wpimath but :func:`chassis_speeds`.

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

import numpy as np

from ..errors import InputTypeError, InputValueError
from ..model import validation
from ..model.conventions import Twist, angle_from, angle_to
from ..model.robot import Robot
from ..model.types import ArrayLike, FloatArray, TwistLike
from .extras import require
from .layouts import differential, mecanum, swerve
from .recognise import recognise

__all__ = [
    "from_wpilib",
    "to_wpilib",
    "twist_of",
    "chassis_speeds",
    "is_chassis_speeds",
    "module_states",
    "module_positions",
    "from_module_states",
]


_SWERVE_SIZES = (2, 3, 4, 6)


def _kinematics():
    return require("wpilib", "WPILib kinematics objects", "wpimath.kinematics")


def from_wpilib(kinematics: Any, wheel_radius: ArrayLike) -> Robot:
    """The robot of a WPILib kinematics object.

    Parameters
    ----------
    kinematics : wpimath.kinematics object
        ``SwerveDrive{2,3,4,6}Kinematics`` (centred wheels at ``getModules()``, in that order),
        ``MecanumDriveKinematics`` (Swedish wheels FL, FR, RL, RR, rollers in an X) or
        ``DifferentialDriveKinematics`` (two fixed wheels at :math:`(0, \\pm t/2)`).
    wheel_radius : float or sequence of float
        The wheels' radius (metres; one per wheel, or one for all): WPILib's objects do not hold it.

    Returns
    -------
    Robot

    Raises
    ------
    wmr.errors.InputTypeError
        If ``kinematics`` is not one of these objects.

    Examples
    --------
    >>> from wpimath.geometry import Translation2d                              # doctest: +SKIP
    >>> from wpimath.kinematics import SwerveDrive4Kinematics                   # doctest: +SKIP
    >>> kin = SwerveDrive4Kinematics(*(Translation2d(x, y) for x, y in [(0.3, 0.3), (0.3, -0.3),
    ...                                (-0.3, 0.3), (-0.3, -0.3)]))               # doctest: +SKIP
    >>> from_wpilib(kin, wheel_radius=0.0508)                                   # doctest: +SKIP
    Robot('WPILib swerve drive': centred@(0.3, 0.3), centred@(0.3, -0.3), centred@(-0.3, 0.3), centred@(-0.3, -0.3))
    """
    module = type(kinematics).__module__ or ""
    if not module.startswith("wpimath"):
        raise InputTypeError(
            f"kinematics must be a WPILib kinematics object (wpimath.kinematics "
            f"SwerveDrive*Kinematics, MecanumDriveKinematics or DifferentialDriveKinematics), got "
            f"{validation.show(kinematics)}"
        )
    k = _kinematics()
    radius = validation.finite_array("wheel_radius", wheel_radius)
    if isinstance(kinematics, k.DifferentialDriveKinematics):
        if radius.size not in (1, 2):
            raise InputValueError(f"wheel_radius must be one radius or two (left, right), got {radius.tolist()}")
        r = np.broadcast_to(radius.reshape(-1), (2,))
        return differential(float(kinematics.trackWidth), float(r[0]), float(r[1]), name="WPILib differential drive")
    if isinstance(kinematics, k.MecanumDriveKinematics):
        corners = (
            kinematics.getFrontLeft(),
            kinematics.getFrontRight(),
            kinematics.getRearLeft(),
            kinematics.getRearRight(),
        )
        return mecanum([(t.x, t.y) for t in corners], radius, name="WPILib mecanum drive")
    if hasattr(kinematics, "getModules") and type(kinematics).__name__.startswith("SwerveDrive"):
        modules = kinematics.getModules()
        return swerve([(t.x, t.y) for t in modules], radius, name="WPILib swerve drive")
    raise InputTypeError(
        f"kinematics must be SwerveDrive*Kinematics, MecanumDriveKinematics or "
        f"DifferentialDriveKinematics, got {type(kinematics).__name__}"
    )


def to_wpilib(robot: Robot) -> Any:
    """The WPILib kinematics object of ``robot``: swerve, mecanum or differential (radii are dropped).

    Parameters
    ----------
    robot : Robot
        Swerve modules only (2, 3, 4 or 6, in the robot's order); four mecanum wheels (rollers in
        an X, rolling along x); or two fixed wheels on an axle through C.  Passive castors are left out.

    Returns
    -------
    wpimath.kinematics.SwerveDrive{n}Kinematics, MecanumDriveKinematics or DifferentialDriveKinematics

    Raises
    ------
    wmr.errors.InputValueError
        If the robot is none of these layouts (the message says why, layout by layout).
    """
    layout = recognise(
        robot,
        ["swerve", "mecanum", "differential"],
        where="WPILib (SwerveDriveKinematics, MecanumDriveKinematics, DifferentialDriveKinematics)",
    )
    k = _kinematics()
    geometry = require("wpilib", "WPILib kinematics objects", "wpimath.geometry")
    points = [geometry.Translation2d(float(x), float(y)) for x, y in layout.positions]
    if layout.name == "differential":
        return k.DifferentialDriveKinematics(layout.numbers["track"])
    if layout.name == "mecanum":
        return k.MecanumDriveKinematics(*points)
    if len(points) not in _SWERVE_SIZES:
        raise InputValueError(
            f"WPILib has swerve kinematics for {', '.join(map(str, _SWERVE_SIZES))} modules; the "
            f"robot has {len(points)}"
        )
    return getattr(k, f"SwerveDrive{len(points)}Kinematics")(*points)


# ------------------------------------------------------------------------------------------ values
def _modules(kind, beta, values):
    r"""WPILib objects ``kind(value, Rotation2d(alpha))`` with :math:`\alpha = \beta - \pi/2`."""
    alpha, values = angle_to(beta, "wpilib"), validation.finite_array("speed", values)
    geometry = require("wpilib", f"WPILib {kind} objects", "wpimath.geometry")
    make = getattr(_kinematics(), kind)
    return [make(float(v), geometry.Rotation2d(float(a))) for a, v in zip(np.atleast_1d(alpha), np.atleast_1d(values))]


def module_states(beta: ArrayLike, speed: ArrayLike) -> list[Any]:
    r"""WPILib ``SwerveModuleState`` objects of wmr's angles :math:`\beta` and signed speeds :math:`r\dot\theta`.

    Parameters
    ----------
    beta, speed : array (w,)

    Returns
    -------
    list of wpimath.kinematics.SwerveModuleState
        Angle :math:`\alpha = \beta - \pi/2`, the same speed.
    """
    return _modules("SwerveModuleState", beta, speed)


def module_positions(beta: ArrayLike, distance: ArrayLike) -> list[Any]:
    r"""WPILib ``SwerveModulePosition`` objects of wmr's angles and wheel travels :math:`r\theta` (metres).

    Parameters
    ----------
    beta, distance : array (w,)

    Returns
    -------
    list of wpimath.kinematics.SwerveModulePosition
    """
    return _modules("SwerveModulePosition", beta, distance)


def from_module_states(states: Sequence[Any]) -> tuple[FloatArray, FloatArray]:
    r"""wmr's ``(beta, value)`` of WPILib ``SwerveModuleState`` (speed) or ``SwerveModulePosition`` (distance) objects.

    Parameters
    ----------
    states : sequence of SwerveModuleState or SwerveModulePosition

    Returns
    -------
    tuple of numpy.ndarray (w,)
        :math:`\beta = \alpha + \pi/2` and the speeds (or distances).
    """
    alpha, value = [], []
    for s in states:
        if not hasattr(s, "angle") or not (hasattr(s, "speed") or hasattr(s, "distance")):
            raise InputTypeError(
                f"states must be SwerveModuleState or SwerveModulePosition objects, got {validation.show(s)}"
            )
        alpha.append(float(s.angle.radians()))
        value.append(float(s.speed if hasattr(s, "speed") else s.distance))
    return angle_from(np.array(alpha), "wpilib", "alpha"), validation.finite_array("speed", np.array(value))


# ------------------------------------------------------------------------------------------ chassis speeds
def is_chassis_speeds(obj: object) -> bool:
    """True for a WPILib ``ChassisSpeeds`` or ``Twist2d`` (any object with their attributes), or a sequence of them.

    The objects are those of :data:`wmr.model.checks.TWIST_OBJECTS` (a ROS ``Twist`` too).

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

    Read by field names (:func:`wmr.model.checks.twist_array`, the one conversion every function that
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
    one = Twist.of(validation.finite_array("twist", twist, last=3))  # numbers only: an object's order is a guess
    return require("wpilib", "WPILib ChassisSpeeds", "wpimath.kinematics").ChassisSpeeds(*one.in_convention("wpilib"))
