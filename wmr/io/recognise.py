r"""Which standard layout (:mod:`wmr.io.layouts`) a robot is: :func:`recognise`, with the reason when it is none.

A layout is recognised up to the order of the wheels: :class:`Layout` lists the robot's wheels in
the layout's order (left before right, front before rear).  **Passive castors** -- units whose
joints are all passive and which put no constraint on the twist (an offset wheel with :math:`d > 0`
and no motor, :func:`free_passive`) -- are no part of any layout: a controller does not command them
and they constrain nothing, so :func:`recognise` leaves them out (:attr:`Layout.dropped`) and a robot
read back has none.  Positions and angles are compared with :data:`~wmr.model.tolerance.TOL`,
relative to the robot's size.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..analysis.linalg import rank
from ..errors import InputValueError
from ..model import validation
from ..model.platform import wrap_angle
from ..model.robot import Robot
from ..model.tolerance import TOL
from ..model.types import ArrayLike, FloatArray
from ..model.wheels import CentredWheel, FixedWheel, SwedishWheel
from ..model.wheels.unit import WheelUnit
from .layouts import LAYOUTS, rectangle

__all__: list[str] = []  # what the bridges (ROS 2, WPILib) recognise a robot with

_HALF_PI, _QUARTER_PI = np.pi / 2, np.pi / 4


@dataclass(frozen=True)
class Layout:
    """A robot recognised as the standard layout ``name`` (one of :data:`~wmr.io.layouts.LAYOUTS`).

    ``wheels`` are the robot's wheels (0-based) in the layout's places and order, ``positions`` (k, 2) and
    ``radii`` (k,) theirs; ``numbers`` the layout's (``track``; ``wheelbase``, ``traction_track``,
    ``steering_track``; ``ring``, ``offset`` of an omni ring; none for mecanum and swerve); ``dropped`` the
    passive castors left out.
    """

    name: str
    wheels: tuple
    positions: np.ndarray
    radii: np.ndarray
    numbers: dict
    dropped: tuple = ()


# ------------------------------------------------------------------------------------------ recognising
class _NotIt(Exception):
    """The robot is not this layout (the message says why)."""


def free_passive(unit: WheelUnit) -> bool:
    """True for a passive castor: every joint passive, and no constraint on the twist (its block has rank 2)."""
    return not any(unit.driven) and int(rank(np.asarray(unit.local_block(), dtype=float))) == 2


def _angle_is(angle, target):
    return abs(float(wrap_angle(float(angle) - target))) <= TOL


def _same(a, b, scale):
    return bool(np.all(np.abs(np.asarray(a, dtype=float) - np.asarray(b, dtype=float)) <= TOL * scale))


def _at(idx):
    return ", ".join(f"wheel {i + 1}" for i in idx)


def _of(units, cls):
    return [i for i, u in units if isinstance(u, cls)]


def _rolling_along_x(units, idx, what):
    bad = [i for i in idx if not _angle_is(dict(units)[i].angle, _HALF_PI)]
    if bad:
        raise _NotIt(f"{what} must roll along x (angle 90 deg, axle along y); {_at(bad)} does not")


def _differential(units, scale):
    fixed = _of(units, FixedWheel)
    if len(units) != 2 or len(fixed) != 2:
        raise _NotIt(f"needs exactly two fixed wheels, has {len(fixed)} of {len(units)} units")
    _rolling_along_x(units, fixed, "the wheels")
    u = dict(units)
    left, right = sorted(fixed, key=lambda i: -u[i].position[1])
    (xl, yl), (xr, yr) = u[left].position, u[right].position
    if not (_same([xl, xr, yl + yr], 0.0, scale) and yl > 0):
        raise _NotIt(
            f"the wheels must be at (0, +-t/2), the axle's midpoint at C; they are at ({xl:g}, {yl:g}) and "
            f"({xr:g}, {yr:g})"
        )
    return (left, right), {"track": float(yl - yr)}


def _mecanum(units, scale):
    sw = _of(units, SwedishWheel)
    if len(units) != 4 or len(sw) != 4:
        raise _NotIt(f"needs exactly four Swedish wheels, has {len(sw)} of {len(units)} units")
    _rolling_along_x(units, sw, "the wheels")
    u = dict(units)
    plus = [i for i in sw if _angle_is(u[i].roller, _QUARTER_PI)]
    minus = [i for i in sw if _angle_is(u[i].roller, -_QUARTER_PI)]
    if len(plus) != 2 or len(minus) != 2:
        raise _NotIt(
            "needs two wheels with rollers at +45 deg and two at -45 deg, has rollers "
            f"{[round(float(np.degrees(u[i].roller)), 6) for i in sw]} deg"
        )
    fl, rr = sorted(plus, key=lambda i: (-u[i].position[0], -u[i].position[1]))
    fr, rl = sorted(minus, key=lambda i: (-u[i].position[0], -u[i].position[1]))
    return (fl, fr, rl, rr), {}


def _omni(units, scale):
    sw = _of(units, SwedishWheel)
    n = len(units)
    if n < 3 or len(sw) != n:
        raise _NotIt(f"needs three or more Swedish wheels and nothing else, has {len(sw)} of {n} units")
    u = dict(units)
    if not all(_angle_is(u[i].roller, _HALF_PI) for i in sw):
        raise _NotIt("needs omni wheels (rollers at 90 deg)")
    p = np.array([u[i].position for i in sw], dtype=float)
    ring, a0 = float(np.hypot(*p[0])), float(np.arctan2(p[0, 1], p[0, 0]))
    want = ring * np.stack([np.cos(a0 + 2 * np.pi * np.arange(n) / n), np.sin(a0 + 2 * np.pi * np.arange(n) / n)], -1)
    if not ring > 0 or not _same(p, want, scale):
        raise _NotIt("the wheels must be evenly spaced on a circle about C, anticlockwise in their order")
    if not all(_angle_is(u[i].angle, a0 + 2 * np.pi * k / n) for k, i in enumerate(sw)):
        raise _NotIt("each axle must point away from C (angle = the mount point's polar angle)")
    return tuple(sw), {"ring": ring, "offset": a0}


def _swerve(units, scale):
    cw = _of(units, CentredWheel)
    if len(cw) != len(units):
        raise _NotIt(f"needs centred wheels only, has {len(units) - len(cw)} other units")
    if len(cw) < 2:
        raise _NotIt(f"needs two swerve modules or more, has {len(cw)}")
    return tuple(cw), {}


def _car(units, scale, n_steered, n_traction):
    steered, fixed = _of(units, CentredWheel), _of(units, FixedWheel)
    if (len(steered), len(fixed), len(units)) != (n_steered, n_traction, n_steered + n_traction):
        raise _NotIt(
            f"needs {n_steered} centred and {n_traction} fixed wheels, has {len(steered)} centred and "
            f"{len(fixed)} fixed of {len(units)} units"
        )
    _rolling_along_x(units, fixed, "the fixed wheels")
    u = dict(units)
    steered = sorted(steered, key=lambda i: -u[i].position[1])
    fixed = sorted(fixed, key=lambda i: -u[i].position[1])
    ps, pf = np.array([u[i].position for i in steered]), np.array([u[i].position for i in fixed])
    base = float(ps[0, 0])
    if not (_same(pf[:, 0], 0.0, scale) and _same(pf[:, 1].sum(), 0.0, scale)):
        raise _NotIt("the fixed wheels must be on the y axis, symmetric about C (C at the traction axle's middle)")
    if not (_same(ps[:, 0], base, scale) and _same(ps[:, 1].sum(), 0.0, scale) and base > 0):
        raise _NotIt("the steered wheels must be on one axle ahead of C (x > 0), symmetric about the x axis")
    numbers = {
        "wheelbase": base,
        "traction_track": float(pf[0, 1] - pf[-1, 1]),
        "steering_track": float(ps[0, 1] - ps[-1, 1]),
    }
    apart = (numbers["traction_track"] > 0 or n_traction == 1) and (numbers["steering_track"] > 0 or n_steered == 1)
    if not apart:
        raise _NotIt("two wheels on one axle must be apart")
    return tuple(steered) + tuple(fixed), numbers


_RECOGNISERS = {
    "differential": _differential,
    "mecanum": _mecanum,
    "omni": _omni,
    "swerve": _swerve,
    "bicycle": lambda units, scale: _car(units, scale, 1, 1),
    "tricycle": lambda units, scale: _car(units, scale, 1, 2),
    "ackermann": lambda units, scale: _car(units, scale, 2, 2),
}


def recognise(robot: Robot, names: Sequence[str], where: str = "this format") -> Layout:
    """The first of the layouts ``names`` that ``robot`` is (passive castors left out), else an error with the reasons.

    ``where`` names what needs the layout, for the message (e.g. ``"WPILib"``).
    """
    robot = validation.numeric_robot(robot)
    unknown = [n for n in names if n not in LAYOUTS]
    if unknown:
        raise InputValueError(f"names must be layouts ({', '.join(LAYOUTS)}), got {unknown}")
    dropped = tuple(i for i, u in enumerate(robot.wheels) if free_passive(u))
    units = [(i, u) for i, u in enumerate(robot.wheels) if i not in dropped]
    scale = max(float(np.abs(robot.mount_points).max()), max(float(u.r) for u in robot.wheels))
    why = []
    for name in names:
        try:
            wheels, numbers = _RECOGNISERS[name](units, scale)
        except _NotIt as exc:
            why.append(f"not {name}: {exc}")
            continue
        u = dict(units)
        return Layout(
            name,
            tuple(wheels),
            np.array([u[i].position for i in wheels], dtype=float),
            np.array([float(u[i].r) for i in wheels]),
            numbers,
            dropped,
        )
    kinds = [u.kind for u in robot.wheels]
    motors = [i + 1 for i, u in units if u.steered and int(rank(np.asarray(u.local_block(), dtype=float))) == 2]
    hint = (
        (
            f" (wheel {', '.join(map(str, motors))} constrains nothing but has motors: a castor has every joint "
            "passive, e.g. driven = {steer = false, drive = false})"
        )
        if motors
        else ""
    )
    raise InputValueError(
        f"{where} cannot express robot {robot.name!r} (units {kinds}"
        + (f", passive castors {[i + 1 for i in dropped]} left out" if dropped else "")
        + f"){hint}: "
        + "; ".join(why)
    )


def rectangle_of(positions: ArrayLike) -> tuple[tuple[int, int, int, int], float, float, FloatArray]:
    """``(order, length, width, centre)`` of four points (4, 2) on an axis-aligned rectangle, or an input error.

    ``order`` indexes the corners FL, FR, RL, RR (front: larger x; left: larger y); ``length`` is along x,
    ``width`` along y, ``centre`` (2,), as :func:`~wmr.io.layouts.rectangle` takes them.
    """
    p = validation.finite_array("positions", positions, last=2).reshape(-1, 2)
    if p.shape != (4, 2):
        raise InputValueError(f"positions must be four points, got shape {p.shape}")
    by_x = sorted(range(4), key=lambda i: (-p[i, 0], -p[i, 1]))
    front = sorted(by_x[:2], key=lambda i: -p[i, 1])
    rear = sorted(by_x[2:], key=lambda i: -p[i, 1])
    order = (front[0], front[1], rear[0], rear[1])
    c = p[list(order)]
    centre = c.mean(axis=0)
    length, width = float(c[0, 0] - c[2, 0]), float(c[0, 1] - c[1, 1])
    scale = float(np.abs(p).max())
    if not (length > 0 and width > 0 and _same(c, rectangle(length, width, centre), scale)):
        raise InputValueError(
            f"the four mount points {p.tolist()} are not the corners of a rectangle with sides along x and y"
        )
    return order, length, width, centre
