r"""A wheel unit's mechanism (:func:`wmr.io.mechanism.mechanism`) as MJCF bodies, knowing no wheel kind.

A driven steering joint gets a position servo (:data:`POSITION`), a driven drive joint a velocity servo
(:data:`VELOCITY`), a passive joint none.  A wheel body is a thin disk of ``params.wheel_mass``, an intermediate
body a small cube of ``params.body_mass``.  A wheel touches the ground through one sphere of its radius centred on
the wheel centre (a single contact point below it, the paper's thin disk); its geom has the higher ``priority`` so
that its friction and contact stiffness are the ones MuJoCo uses.  Drawn disks and rods (no contact) show the
wheels and bodies.
"""

from __future__ import annotations

import functools

import numpy as np

from ..io.decimals import float_text, quantise
from ..io.mechanism import Body, Mechanism, mechanism
from ..model.wheels.joints import Joint
from .params import Params

__all__ = ["POSITION", "VELOCITY", "height_of", "mechanisms", "num", "servo"]

#: the servo of a driven steering joint: MuJoCo's ``position`` actuator
POSITION = "position"
#: the servo of a driven drive joint: MuJoCo's ``velocity`` actuator
VELOCITY = "velocity"


def servo(joint: Joint) -> str | None:
    """The servo a joint of a unit gets: :data:`POSITION`, :data:`VELOCITY`, or None for a passive joint.

    Parameters
    ----------
    joint : Joint
        A joint of a unit, with the unit's actuation (``unit.joints``).

    Returns
    -------
    str or None

    Raises
    ------
    NotImplementedError
        For a driven joint of another kind (a driven roller).
    """
    if not joint.driven:
        return None
    if joint.steering:
        return POSITION
    if joint.kind == "drive":
        return VELOCITY
    raise NotImplementedError(f"wmr.sim has no servo for a driven {joint.kind} joint ({joint.name!r})")


def height_of(robot) -> float:
    """Height of the mount plane: the largest wheel radius (every wheel centre at or below it).

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    float
    """
    return float(np.max([float(u.r) for u in robot.wheels]))


def mechanisms(robot, height: float) -> tuple[Mechanism, ...]:
    """Every unit's mechanism, each checked for a servo on its driven joints.

    Parameters
    ----------
    robot : Robot
        Numbers, not symbols.
    height : float
        Height of the mount plane (:func:`height_of`).

    Returns
    -------
    tuple of Mechanism
        One per unit, in the robot's order.

    Raises
    ------
    NotImplementedError
        If a unit has no mechanism a physics engine can take (its kind says why: a Swedish wheel's
        rollers), naming the wheel.
    """
    out = []
    for i, u in enumerate(robot.wheels):
        try:
            m = mechanism(u, height)
            for j in m.joints:
                servo(j)
        except NotImplementedError as e:
            raise NotImplementedError(f"wheel {i + 1} ({type(u).__name__}): {e}") from None
        out.append(m)
    return tuple(out)


@functools.lru_cache(maxsize=8192)  # a robot's numbers recur in every export of it (the edition exports hundreds)
def num(x, scale: float | None = None) -> str:
    """A float as MJCF text by the rule of :mod:`wmr.io.decimals`, without a trailing ``.0`` (no negative zero).

    12 significant digits of every value (:func:`~wmr.io.decimals.float_text`); with ``scale=1`` (metres, unit
    vectors, radians) a value that rounds to 0 at that scale (round-off of a zero coordinate) is written 0.  The
    other values keep their digits: contact physics is chaotic at the last bit, so fewer digits would move the
    edition's committed measurements.

    Parameters
    ----------
    x : float
    scale : float, optional
        The scale below whose quantum a value is round-off (default: none, every value kept to 12 digits).

    Returns
    -------
    str

    Examples
    --------
    >>> num(0.1 + 0.2), num(-1.85e-17, scale=1.0), num(2.0), num(1e-5), num(0.0433012701892219, scale=1.0)
    ('0.3', '0', '2', '1e-05', '0.0433012701892')
    """
    text = float_text(x) if scale is None or quantise(x, scale) != 0 else "0"
    return text[:-2] if text.endswith(".0") else text


def nums(*xs, scale: float | None = None) -> str:
    """Floats as MJCF text, separated by spaces (:func:`num`)."""
    return " ".join(num(x, scale) for x in xs)


def _disk(mass, r):
    """Principal moments of a thin disk of radius ``r`` turning about x: (m r^2/2, m r^2/4, m r^2/4)."""
    return (mass * r * r / 2, mass * r * r / 4, mass * r * r / 4)


def _block(mass, size):
    """Principal moments of a small cube of side ``size``: m size^2 / 6 about each axis."""
    m = mass * size * size / 6
    return (m, m, m)


def _geoms(body, name, r_unit, params, pad):
    """The geoms of a body: a wheel's contact sphere and drawn disk, then its rods (those of length zero left out)."""
    out = []
    if body.wheel is not None:
        r = body.wheel
        mu_t, mu_r = params.torsional * r, params.rolling * r
        out.append(
            f'{pad}<geom name="{name}" type="sphere" size="{num(r)}" condim="6" '
            f'friction="{nums(params.sliding, mu_t, mu_r)}" solref="{nums(params.contact_time, 1.0)}" '
            f'contype="1" conaffinity="0" priority="1" group="3"/>'
        )
        out.append(
            f'{pad}<geom type="cylinder" size="{num(r)}" fromto="{nums(-r / 4, 0.0, 0.0, r / 4, 0.0, 0.0, scale=1.0)}" '
            f'contype="0" conaffinity="0" group="1"/>'
        )
    for a, b in body.rods:
        if np.hypot.reduce(np.subtract(a, b)) > 1e-6 * r_unit:
            out.append(
                f'{pad}<geom type="capsule" size="{num(r_unit / 8)}" fromto="{nums(*a, *b, scale=1.0)}" '
                f'contype="0" conaffinity="0" group="1"/>'
            )
    return out


def body_xml(body: Body, name, r_unit: float, params: Params, depth: int) -> list[str]:
    """The MJCF lines of a body and its descendants, indented ``depth`` levels.

    ``name(part)`` is the MuJoCo name of a body or joint of the unit (``u<i>_<part>``); ``r_unit``, the unit's
    wheel radius, sizes the drawn rods.
    """
    pad = "  " * depth
    turn = nums(np.cos(body.angle / 2), 0.0, 0.0, np.sin(body.angle / 2), scale=1.0)
    quat = f' quat="{turn}"' if turn != "1 0 0 0" else ""
    lines = [f'{pad}<body name="{name(body.name)}" pos="{nums(*body.pos, scale=1.0)}"{quat}>']
    if body.joint is not None:
        axis = nums(*body.axis or (), scale=1.0)
        lines.append(f'{pad}  <joint name="{name(body.joint.name)}" type="hinge" axis="{axis}"/>')
    mass = params.body_mass if body.wheel is None else params.wheel_mass
    inertia = _block(mass, body.size) if body.wheel is None else _disk(mass, body.wheel)
    lines.append(f'{pad}  <inertial pos="0 0 0" mass="{num(mass)}" diaginertia="{nums(*inertia)}"/>')
    lines += _geoms(body, name(body.name), r_unit, params, pad + "  ")
    for c in body.children:
        lines += body_xml(c, name, r_unit, params, depth + 1)
    lines.append(f"{pad}</body>")
    return lines
