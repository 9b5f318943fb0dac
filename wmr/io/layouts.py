r"""The standard drive layouts that controllers and WPILib describe by a few numbers, and their robots.

A ROS 2 controller's parameters or a WPILib kinematics object do not list wheel units: they name a
layout and give a few lengths.  Each layout is written here once: how to build its :class:`wmr.Robot`
from those numbers (wheels in the layout's order); :mod:`wmr.io.recognise` finds a layout in a robot, with the reason
when a robot is not one.  Frames are wmr's
(:mod:`wmr.model.conventions`), which are REP-103's and WPILib's: x forward, y left, C the origin.

================  =============================================================================  =================
layout            wheels, in the layout's order                                                  numbers
================  =============================================================================  =================
``differential``  left and right fixed wheels at :math:`(0, \pm t/2)`, angle 90 deg              track t
``mecanum``       Swedish wheels FL, FR, RL, RR, angle 90 deg, rollers +45, -45, -45, +45 deg    4 mount points
``omni``          n >= 3 Swedish wheels, rollers 90 deg, at :math:`R(\cos a_k, \sin a_k)`,       n, R, :math:`a_0`
                  :math:`a_k = a_0 + 2\pi k/n`, axle radial (angle :math:`a_k`)
``swerve``        centred (swerve) wheels anywhere                                               mount points
``bicycle``       steered centred wheel at :math:`(l, 0)`, fixed wheel at C (angle 90 deg)       wheelbase l
``tricycle``      steered centred wheel at :math:`(l, 0)`, fixed wheels at :math:`(0, \pm t/2)`  l, t
``ackermann``     steered centred wheels at :math:`(l, \pm s/2)`, fixed wheels at                l, t, s
                  :math:`(0, \pm t/2)` (left before right)
================  =============================================================================  =================

The mecanum rollers are those whose wheel speeds WPILib's ``MecanumDriveKinematics`` and ROS 2's
``mecanum_drive_controller`` compute (FL: :math:`v_x - v_y - (l_x + l_y)\omega`, ...): an X seen from
above.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.platform import wrap_angle
from ..model.robot import Robot
from ..model.types import ArrayLike, FloatArray, Point
from ..model.wheels import CentredWheel, FixedWheel, SwedishWheel

__all__ = ["differential", "mecanum", "omni", "swerve", "car", "rectangle"]

#: every layout, and the wheel units it takes (for messages)
LAYOUTS = {
    "differential": "two fixed wheels on one axle through C, rolling along x",
    "mecanum": "four mecanum wheels (Swedish, rollers at +-45 deg in an X), rolling along x",
    "omni": "three or more omni wheels (Swedish, rollers at 90 deg) evenly spaced on a circle about C",
    "swerve": "centred steered wheels only (swerve modules)",
    "bicycle": "one steered centred wheel ahead of one fixed wheel at C",
    "tricycle": "one steered centred wheel ahead of two fixed wheels on an axle through C",
    "ackermann": "two steered centred wheels ahead of two fixed wheels on an axle through C",
}
_HALF_PI, _QUARTER_PI = np.pi / 2, np.pi / 4


# ------------------------------------------------------------------------------------------ building
def _radii(radius, n):
    """One radius per wheel: ``radius`` given once or ``n`` times."""
    r = validation.finite_array("radius", radius)
    if r.size not in (1, n):
        raise InputValueError(f"radius must be one radius or one per wheel ({n}), got {r.size}: {r.tolist()}")
    return np.broadcast_to(r.reshape(-1), (n,))


def differential(
    track: float, radius: float, radius_right: float | None = None, name: str = "differential drive"
) -> Robot:
    """A differential drive: left and right fixed wheels at ``(0, +-track/2)``, rolling along x.

    Parameters
    ----------
    track : float
        The distance between the wheels, > 0.
    radius : float
        The left wheel's radius (and the right one's unless ``radius_right`` is given), > 0.
    radius_right : float, optional
        The right wheel's radius.
    name : str, optional

    Returns
    -------
    Robot

    Examples
    --------
    >>> differential(0.4, 0.05).mount_points.tolist()
    [[0.0, 0.2], [0.0, -0.2]]
    """
    half = validation.positive("track", track) / 2
    right = radius if radius_right is None else radius_right
    return Robot(
        [FixedWheel((0.0, half), r=radius, angle=_HALF_PI), FixedWheel((0.0, -half), r=right, angle=_HALF_PI)],
        name=name,
    )


def rectangle(length: float, width: float, centre: Point = (0.0, 0.0)) -> FloatArray:
    """The corners FL, FR, RL, RR of a ``length`` (along x) by ``width`` rectangle about ``centre``.

    Parameters
    ----------
    length, width : float
        Its sides, > 0 (a wheelbase and a track).
    centre : pair, optional

    Returns
    -------
    numpy.ndarray (4, 2)

    Examples
    --------
    >>> rectangle(0.5, 0.4).tolist()
    [[0.25, 0.2], [0.25, -0.2], [-0.25, 0.2], [-0.25, -0.2]]
    """
    a, b = validation.positive("length", length) / 2, validation.positive("width", width) / 2
    cx, cy = validation.point("centre", centre)
    return np.array([[cx + a, cy + b], [cx + a, cy - b], [cx - a, cy + b], [cx - a, cy - b]], dtype=float)


def mecanum(positions: ArrayLike, radius: ArrayLike, name: str = "mecanum drive") -> Robot:
    """Four mecanum wheels FL, FR, RL, RR at ``positions``, rolling along x, rollers in an X (+45, -45, -45, +45 deg).

    Parameters
    ----------
    positions : array (4, 2)
        Mount points FL, FR, RL, RR (e.g. :func:`rectangle`).
    radius : float or array (4,)
    name : str, optional

    Returns
    -------
    Robot
    """
    positions = validation.finite_array("positions", positions, last=2).reshape(-1, 2)
    if positions.shape != (4, 2):
        raise InputValueError(f"positions must be the four mount points FL, FR, RL, RR, got shape {positions.shape}")
    radii = _radii(radius, 4)
    rollers = (_QUARTER_PI, -_QUARTER_PI, -_QUARTER_PI, _QUARTER_PI)
    return Robot(
        [SwedishWheel(tuple(p), r=float(r), angle=_HALF_PI, roller=g) for p, r, g in zip(positions, radii, rollers)],
        name=name,
    )


def omni(n: int, ring: float, radius: float, offset: float = 0.0, name: str = "omni drive") -> Robot:
    r"""``n`` omni wheels evenly on a circle of radius ``ring`` about C, the first at angle ``offset``, anticlockwise.

    Wheel k is at :math:`R(\cos a_k, \sin a_k)`, :math:`a_k = a_0 + 2\pi k/n`, its axle radial
    (angle :math:`a_k`), so it rolls tangentially (ROS 2's ``omni_wheel_drive_controller``).

    Parameters
    ----------
    n : int
        Number of wheels, >= 3.
    ring : float
        Distance from C to the wheels, > 0.
    radius : float
        Wheel radius.
    offset : float, optional
        :math:`a_0`, radians.
    name : str, optional

    Returns
    -------
    Robot

    Examples
    --------
    >>> np.degrees([u.angle for u in omni(3, 0.2, 0.03).wheels]).round(9).tolist()
    [0.0, 120.0, -120.0]
    """
    n = validation.integer("n", n, minimum=3)
    ring = validation.positive("ring", ring)
    angles = wrap_angle(validation.number("offset", offset) + 2 * np.pi * np.arange(n) / n)
    return Robot(
        [SwedishWheel((ring * np.cos(a), ring * np.sin(a)), r=radius, angle=float(a), roller=_HALF_PI) for a in angles],
        name=name,
    )


def swerve(positions: ArrayLike, radius: ArrayLike, name: str = "swerve drive") -> Robot:
    """Swerve modules (centred steered wheels) at ``positions``.

    Parameters
    ----------
    positions : array (w, 2)
    radius : float or array (w,)
    name : str, optional

    Returns
    -------
    Robot
    """
    positions = validation.finite_array("positions", positions, last=2).reshape(-1, 2)
    radii = _radii(radius, len(positions))
    return Robot([CentredWheel(tuple(p), r=float(r)) for p, r in zip(positions, radii)], name=name)


def car(
    wheelbase: float,
    traction_track: float,
    steering_track: float,
    traction_radius: float,
    steering_radius: float | None = None,
    name: str = "car-like robot",
) -> Robot:
    """A car-like robot: steered centred wheels ``wheelbase`` ahead of fixed wheels on an axle through C.

    A track of 0 puts one wheel on that axle (bicycle: both 0; tricycle: ``steering_track`` 0;
    Ackermann: neither).  The steered wheels' drive joints are passive (the controllers of
    :mod:`wmr.io.ros2` drive the traction wheels only); wheels in the order steered (left, right),
    then traction (left, right).

    Parameters
    ----------
    wheelbase : float
        > 0: the steered axle is ahead of C.
    traction_track, steering_track : float
        >= 0.
    traction_radius : float
    steering_radius : float, optional
        Default: ``traction_radius``.
    name : str, optional

    Returns
    -------
    Robot

    Examples
    --------
    >>> [u.kind for u in car(0.5, 0.5, 0.0, 0.1).wheels]
    ['centred', 'fixed', 'fixed']
    """
    base = validation.positive("wheelbase", wheelbase)
    t, s = (
        validation.nonnegative("traction_track", traction_track) / 2,
        validation.nonnegative("steering_track", steering_track) / 2,
    )
    rs = traction_radius if steering_radius is None else steering_radius
    steered = [CentredWheel((base, y), r=rs, driven={"drive": False}) for y in ((s, -s) if s else (0.0,))]
    traction = [FixedWheel((0.0, y), r=traction_radius, angle=_HALF_PI) for y in ((t, -t) if t else (0.0,))]
    return Robot([*steered, *traction], name=name)
