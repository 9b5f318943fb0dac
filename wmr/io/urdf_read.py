r"""A robot from a URDF file: its wheels, steering joints and rollers, read with yourdfpy.

The platform is the root link of the kinematic tree (``base_footprint`` or ``base_link``, z up, x
forward: REP-103 and :mod:`wmr.model.conventions`); C is its origin; everything is read with every
joint at zero.  Then:

Wheels
    A ``continuous`` joint whose axis is horizontal and whose child link has a ``<cylinder>`` (a
    ``<collision>`` one first, else a ``<visual>`` one) lying along that axis: the wheel's centre is
    the joint's origin, its radius the cylinder's, its axle :math:`\mathbf i` the joint axis
    (:math:`\dot\theta > 0` turning about it, as in wmr).  ``wheel_joints`` names the wheel joints
    instead (any other joint is then no wheel), and may give radii for wheels drawn as meshes.
Steering joints
    A ``revolute`` or ``continuous`` joint about a vertical axis between the platform and a wheel.
    Prismatic joints on the way (a suspension) are read at zero; any other moving joint there is an
    error (wmr's robots are planar).
Rollers
    ``continuous`` joints below a wheel: the free rollers of a Swedish wheel; their angle
    :math:`\gamma` to the axle is read from any of them (:math:`\tan\gamma = \mathbf a\cdot\mathbf t /
    \mathbf a\cdot\mathbf i`, :math:`\mathbf t` the rim's direction of motion at the roller).

Each steering joint, or each wheel without one, is a unit of the kind its joints make:

==============  ============================  ==========================================================
steering joint  wheels below it               unit
==============  ============================  ==========================================================
none            one, no rollers               :class:`~wmr.FixedWheel` at its centre, angle of its axle
none            one, with rollers             :class:`~wmr.SwedishWheel`, roller angle :math:`\gamma`
at :math:`P`    one, centre on the axis       :class:`~wmr.CentredWheel` at :math:`P`
at :math:`P`    one, centre :math:`d` behind  :class:`~wmr.OffsetWheel` at :math:`P`, offset :math:`d`
at :math:`P`    two on one axle about P       :class:`~wmr.DualWheel` at :math:`P`, :math:`b` = half their distance
==============  ============================  ==========================================================

Units come in the order of their first wheel joint in the file.  Actuation: when the file has a
``<ros2_control>`` or ``<transmission>`` element, the joints it commands (a ``<command_interface>``,
or a transmission's ``<joint>``) are driven and every other joint is passive; without one, each
kind's defaults hold.  URDF files write :math:`\pi/2` rounded (``1.5708``), so directions are read
with components below :data:`~wmr.io.urdf_tree.AXIS_SNAP` set to zero (:mod:`wmr.io.urdf_tree`).

Bad input raises :class:`~wmr.errors.RobotFileError` naming the file, the line of the joint or link
and what is wrong: no wheels, a wheel without a cylinder, an axle that is not horizontal, a
cylinder across its axle, a steering joint over three wheels, ...
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from ..errors import InputError, InputTypeError, InputValueError, RobotFileError
from ..model import validation as V
from ..model.robot import Robot
from ..model.types import PathLike, WheelJoints
from ..model.wheels import CentredWheel, DualWheel, FixedWheel, OffsetWheel, SwedishWheel
from .urdf_tree import AXIS_SNAP, UrdfTree, is_horizontal, is_vertical, suggest

__all__ = ["from_urdf", "read_urdf", "parse_wheel_joints"]


def parse_wheel_joints(text):
    """``--wheel-joints`` of the command line: ``"a,b=0.05"`` -> ``{"a": None, "b": 0.05}``.

    Parameters
    ----------
    text : str
        Joint names separated by commas, each optionally ``=RADIUS`` (metres).

    Returns
    -------
    dict of str to float or None

    Examples
    --------
    >>> parse_wheel_joints("left_wheel_joint, right_wheel_joint=0.05")
    {'left_wheel_joint': None, 'right_wheel_joint': 0.05}
    """
    if not isinstance(text, str):
        raise InputTypeError(f"wheel joints must be a string 'name[=radius],...', got {V.show(text)}")
    out: dict[str, float | None] = {}
    for item in filter(None, (s.strip() for s in text.split(","))):
        name, _, radius = (part.strip() for part in item.partition("="))
        try:
            value = float(radius) if radius else None
        except ValueError:
            raise InputValueError(f"the radius of wheel joint {name!r} must be a number, got {radius!r}") from None
        out[name] = None if value is None else V.positive(f"the radius of wheel joint {name!r}", value)
    if not out:
        raise InputValueError(f"wheel joints must name at least one joint, got {text!r}")
    return out


def _wheels(rd: UrdfTree, wheel_joints):
    """``[(joint name, radius)]`` of the wheel joints, in the file's order."""
    if wheel_joints is not None:
        out = []
        for name, radius in wheel_joints.items():
            if name not in rd.joints:
                rd.fail(
                    rd.line("robot", ""),
                    f"joint {name!r}",
                    "wheel_joints names a joint the file does not define" + suggest(name, rd.joints),
                )
            out.append((name, radius))
        order = list(rd.joints)
        return sorted(out, key=lambda item: order.index(item[0]))
    out, seen = [], []
    for name, j in rd.joints.items():
        if j.type != "continuous" or not is_horizontal(rd.axis(name)):
            continue
        if any(p.name in {w for w, _ in out} for p in rd.path(name)):
            continue  # a roller of a wheel above it
        radius, shapes = rd.cylinder(name)
        if radius is None:
            seen.append((name, shapes))
            continue
        out.append((name, None))
    rollers_of = {w for w, _ in out}
    for name, shapes in seen:
        if not any(p.name in rollers_of for p in rd.path(name)):
            what = f"a {shapes[0]}" if shapes else "no geometry"
            rd.fail(
                rd.line("joint", name),
                f"joint {name!r}",
                f"turns about a horizontal axis like a wheel, but its "
                f"link {rd.joints[name].child!r} has {what}, no <cylinder>: wmr reads a wheel's radius from its "
                f"cylinder; name the wheel joints and radii instead (wheel_joints={{{name!r}: RADIUS, ...}}, on "
                f"the command line --wheel-joints {name}=RADIUS,...)",
            )
    return out


def _wheel(rd: UrdfTree, name, radius):
    """(centre (3,), axle (3,), radius, steering joint or None, rollers' angle or None) of one wheel joint."""
    j, line, key = rd.joints[name], rd.line("joint", name), f"joint {name!r}"
    if j.type not in ("continuous", "revolute"):
        rd.fail(line, key, f"a wheel joint must be continuous (or revolute), got {j.type!r}")
    axle = rd.axis(name)
    if not is_horizontal(axle):
        rd.fail(
            line,
            key,
            f"a wheel's axis must be horizontal (the platform's z is up), got {axle.round(6).tolist()} "
            "in the platform frame",
        )
    cyl_r, cyl_axis = rd.cylinder(name)
    if radius is None:
        if cyl_r is None:
            what = f"a {cyl_axis[0]}" if cyl_axis else "no geometry"
            rd.fail(
                rd.line("link", j.child),
                f"link {j.child!r}",
                f"the wheel of joint {name!r} has {what}, no <cylinder>: give its radius ({name}=RADIUS)",
            )
        if np.linalg.norm(np.cross(cyl_axis, axle)) > AXIS_SNAP:
            rd.fail(
                rd.line("link", j.child),
                f"link {j.child!r}",
                f"its cylinder lies along "
                f"{cyl_axis.round(6).tolist()}, not along the axis of its joint {name!r} "
                f"({axle.round(6).tolist()}): a wheel's cylinder lies along its axle (turn its <origin rpy>)",
            )
        radius = cyl_r
    if not radius > 0:
        rd.fail(rd.line("link", j.child), f"link {j.child!r}", f"the wheel's radius must be positive, got {radius!r}")
    steering = None
    for p in rd.path(name):
        if p.type == "fixed" or p.type == "prismatic":
            continue
        if p.type in ("revolute", "continuous") and is_vertical(rd.axis(p.name)):
            if steering is not None:
                rd.fail(
                    rd.line("joint", p.name),
                    f"joint {p.name!r}",
                    f"a second steering joint above wheel joint {name!r} (after {steering!r}): a wheel unit has one",
                )
            steering = p.name
            continue
        rd.fail(
            rd.line("joint", p.name),
            f"joint {p.name!r}",
            f"a {p.type} joint about "
            f"{rd.axis(p.name).round(6).tolist()} between the platform and wheel joint {name!r}: only a vertical "
            "steering joint (and prismatic suspension) can be there",
        )
    return rd.centre(name), axle, float(radius), steering, _rollers(rd, name, axle)


def _below(rd: UrdfTree, wheel):
    """The continuous joints below a wheel joint (its rollers), in the file's order."""
    return [n for n, j in rd.joints.items() if j.type == "continuous" and wheel in {p.name for p in rd.path(n)}]


def _rollers(rd: UrdfTree, wheel, axle):
    """The angle gamma of the rollers below a wheel (None: no rollers), checked to agree."""
    below = _below(rd, wheel)
    gammas = []
    for name in below:
        a = rd.axis(name)
        p = rd.centre(name) - rd.centre(wheel)
        p = p - (p @ axle) * axle
        if np.linalg.norm(p) == 0:
            rd.fail(
                rd.line("joint", name),
                f"joint {name!r}",
                f"a roller of wheel {wheel!r} on its axle: rollers sit on the rim",
            )
        t = np.cross(axle, p / np.linalg.norm(p))  # the rim's direction of motion at the roller
        g = float(np.arctan2(a @ t, a @ axle))
        g = g - np.pi if g > np.pi / 2 + AXIS_SNAP else g + np.pi if g <= -np.pi / 2 + AXIS_SNAP else g  # a line
        gammas.append((name, g))
    if not gammas:
        return None
    name0, g0 = gammas[0]
    for name, g in gammas[1:]:
        if abs(g - g0) > AXIS_SNAP:
            rd.fail(
                rd.line("joint", name),
                f"joint {name!r}",
                f"roller at {np.degrees(g):.6g} deg to the axle, "
                f"{name0!r} at {np.degrees(g0):.6g} deg: the rollers of one wheel are all at one angle",
            )
    if abs(g0) <= AXIS_SNAP:
        rd.fail(rd.line("joint", name0), f"joint {name0!r}", "rollers parallel to the axle roll nothing")
    return g0


def _joints_of(cls, steering, wheels, roller_joints):
    """``{kind's joint name: [URDF joints]}``: the steering joint, the wheels in order, the rollers."""
    drives = iter(wheels)
    return {
        j.name: [steering] if j.steering else [next(drives)] if j.kind == "drive" else list(roller_joints)
        for j in cls.JOINTS
    }


def _driven(rd: UrdfTree, cls, steering, wheels, roller_joints):
    """The ``driven`` of a unit: its joints commanded in the file (None: no ros2_control, kind defaults)."""
    if rd.commanded is None:
        return None
    return {
        name: bool(set(urdf) & rd.commanded) for name, urdf in _joints_of(cls, steering, wheels, roller_joints).items()
    }


def _unit(rd: UrdfTree, steering, wheels, info):
    """The wheel unit of one steering joint (or one unsteered wheel) and its wheels."""
    first = wheels[0]
    centre, axle, radius, _, gamma = info[first]
    key, line = f"joint {first!r}", rd.line("joint", first)
    a = axle[:2] / np.linalg.norm(axle[:2])
    rollers = _below(rd, first)
    if steering is None:
        angle = float(np.arctan2(a[1], a[0]))
        if gamma is None:
            return FixedWheel(
                tuple(centre[:2]), r=radius, angle=angle, driven=_driven(rd, FixedWheel, None, wheels, ())
            )
        return SwedishWheel(
            tuple(centre[:2]),
            r=radius,
            angle=angle,
            roller=gamma,
            driven=_driven(rd, SwedishWheel, None, wheels, rollers),
        )
    P = rd.centre(steering)[:2]
    skey, sline = f"joint {steering!r}", rd.line("joint", steering)
    if any(info[w][4] is not None for w in wheels):
        rd.fail(sline, skey, "steers a Swedish wheel (rollers below it): wmr has no steered Swedish wheel")
    size = max(radius, float(np.linalg.norm(centre[:2] - P)))
    if len(wheels) == 1:
        v = centre[:2] - P
        lateral, along = float(v @ a), float(v @ np.array([-a[1], a[0]]))
        if abs(lateral) > AXIS_SNAP * size:
            rd.fail(
                line,
                key,
                f"the wheel's centre is {lateral:.6g} along its axle from the steering axis of "
                f"{steering!r}: wmr's steered wheels have their centre on the axis or behind it",
            )
        if abs(along) <= AXIS_SNAP * size:
            return CentredWheel(tuple(P), r=radius, driven=_driven(rd, CentredWheel, steering, wheels, ()))
        return OffsetWheel(tuple(P), r=radius, d=abs(along), driven=_driven(rd, OffsetWheel, steering, wheels, ()))
    if len(wheels) > 2:
        rd.fail(sline, skey, f"steers {len(wheels)} wheels ({', '.join(wheels)}): a wmr unit has one or two")
    (c1, a1, r1, *_), (c2, a2, r2, *_) = info[wheels[0]], info[wheels[1]]
    axis = (c1 - c2)[:2]
    b = float(np.linalg.norm(axis)) / 2
    if (
        not b > 0
        or abs(r1 - r2) > AXIS_SNAP * r1
        or np.linalg.norm(np.cross(a1, a2)) > AXIS_SNAP
        or np.linalg.norm(np.cross(np.append(axis / (2 * b), 0.0), a1)) > AXIS_SNAP
        or np.linalg.norm((c1 + c2)[:2] / 2 - P) > AXIS_SNAP * b
    ):
        rd.fail(
            sline,
            skey,
            f"steers two wheels ({wheels[0]!r}, {wheels[1]!r}) that are not a dual-wheel unit: one "
            "radius, one axle, centres symmetric about the steering axis",
        )
    return DualWheel(tuple(P), r=radius, b=b, driven=_driven(rd, DualWheel, steering, wheels, ()))


def from_urdf(path: PathLike, wheel_joints: WheelJoints | None = None) -> Robot:
    """The robot a URDF file describes (rules: module notes); :func:`read_urdf` gives its joint names too.

    Parameters
    ----------
    path : str or os.PathLike
        The URDF file (no xacro: expand it first, ``xacro robot.urdf.xacro > robot.urdf``).
    wheel_joints : mapping of str to float or None, sequence of str, or str, optional
        The wheel joints, when the automatic reading does not find them: names, or
        ``{name: radius or None}`` (a radius for a wheel without a cylinder), or the command line's
        ``"name[=radius],..."``.

    Returns
    -------
    Robot
        Named by the ``<robot name>``.

    Raises
    ------
    wmr.errors.RobotFileError
        ``FILE:LINE: joint 'name': what is wrong`` (module notes).
    wmr.errors.MissingDependencyError
        Without yourdfpy (``pip install 'wmr-kinematics[urdf]'``).
    OSError
        If the file cannot be read.
    """
    return read_urdf(path, wheel_joints)[0]


def read_urdf(path: PathLike, wheel_joints: WheelJoints | None = None) -> tuple[Robot, list[dict[str, str]]]:
    """The robot a URDF file describes, and the name in the file of each of its units' joints.

    Parameters
    ----------
    path : str or os.PathLike
    wheel_joints : optional
        As for :func:`from_urdf`.

    Returns
    -------
    tuple
        ``(robot, names)``: ``names[i]`` is ``{joint of unit i+1 (its kind's name): URDF joint name}``
        (a Swedish wheel's ``roller``: its first roller joint), for writing a controller's parameters
        with the file's names (:func:`wmr.io.to_ros2`'s ``joint_names``).

    Raises
    ------
    wmr.errors.RobotFileError
        As :func:`from_urdf`.

    Examples
    --------
    >>> robot, names = read_urdf("examples/urdf/diffbot.urdf")       # doctest: +SKIP
    >>> names                                                       # doctest: +SKIP
    [{'drive': 'left_wheel_joint'}, {'drive': 'right_wheel_joint'}, {'steer': 'caster_swivel_joint', \
'drive': 'caster_wheel_joint'}]
    """
    if not isinstance(path, (str, os.PathLike)):
        raise InputTypeError(f"path must be a file name (str or os.PathLike), got {V.show(path)}")
    if isinstance(wheel_joints, str):
        wheel_joints = parse_wheel_joints(wheel_joints)
    elif wheel_joints is not None and not isinstance(wheel_joints, Mapping):
        if not all(isinstance(n, str) for n in wheel_joints):
            raise InputTypeError(f"wheel_joints must be joint names, got {V.show(wheel_joints)}")
        wheel_joints = dict.fromkeys(wheel_joints)
    source = os.fspath(path)
    rd = UrdfTree(Path(path).read_bytes(), source)
    wheels = _wheels(rd, wheel_joints)
    if not wheels:
        moving = [
            f"{n} ({j.type}, axis {rd.axis(n).round(3).tolist()})" for n, j in rd.joints.items() if j.type != "fixed"
        ]
        seen = f"moving joints: {', '.join(moving)}" if moving else "the file has no moving joints"
        rd.fail(
            rd.line("robot", ""),
            "robot",
            "no wheels: no continuous joint with a horizontal axis turns a link "
            f"with a <cylinder> ({seen}); name them with wheel_joints (--wheel-joints)",
        )
    info = {name: _wheel(rd, name, radius) for name, radius in wheels}
    groups: dict[str, list[str]] = {}
    for name, *_ in wheels:
        steering = info[name][3]
        groups.setdefault(name if steering is None else steering, []).append(name)
    units, names = [], []
    for head, members in groups.items():
        steering = info[members[0]][3]
        try:
            units.append(_unit(rd, steering, members, info))
        except InputError as exc:
            if isinstance(exc, RobotFileError):
                raise
            rd.fail(rd.line("joint", head), f"joint {head!r}", str(exc))
        rollers = _below(rd, members[0])
        names.append(
            {j: urdf[0] for j, urdf in _joints_of(type(units[-1]), steering, members, rollers).items() if urdf}
        )
    try:
        return Robot(units, name=rd.name), names
    except InputError as exc:
        rd.fail(rd.line("robot", ""), "robot", str(exc))
