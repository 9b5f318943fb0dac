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

The wheels are found and read by :mod:`wmr.io.urdf_wheels`; this module makes them into units.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from ..errors import InputError, InputTypeError, InputValueError, RobotFileError
from ..model import validation
from ..model.robot import Robot
from ..model.types import PathLike, WheelJoints
from ..model.wheels import CentredWheel, DualWheel, FixedWheel, OffsetWheel, SwedishWheel
from .urdf_tree import AXIS_SNAP, UrdfTree
from .urdf_wheels import find_wheels, read_wheel, rollers_below

__all__ = ["from_urdf"]


def parse_wheel_joints(text):
    """``--wheel-joints`` of the command line: ``"a,b=0.05"`` -> ``{"a": None, "b": 0.05}`` (radii in metres)."""
    if not isinstance(text, str):
        raise InputTypeError(f"wheel joints must be a string 'name[=radius],...', got {validation.show(text)}")
    out: dict[str, float | None] = {}
    for item in filter(None, (s.strip() for s in text.split(","))):
        name, _, radius = (part.strip() for part in item.partition("="))
        try:
            value = float(radius) if radius else None
        except ValueError:
            raise InputValueError(f"the radius of wheel joint {name!r} must be a number, got {radius!r}") from None
        out[name] = None if value is None else validation.positive(f"the radius of wheel joint {name!r}", value)
    if not out:
        raise InputValueError(f"wheel joints must name at least one joint, got {text!r}")
    return out


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
    rollers = rollers_below(rd, first)
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

    ``names[i]`` of ``(robot, names)`` is ``{joint of unit i+1 (its kind's name): URDF joint name}`` (a Swedish
    wheel's ``roller``: its first roller joint), for a controller's parameters with the file's names
    (:func:`wmr.io.to_ros2`'s ``joint_names``); ``wheel_joints`` and the errors are :func:`from_urdf`'s.
    """
    validation.file_path(path)
    if isinstance(wheel_joints, str):
        wheel_joints = parse_wheel_joints(wheel_joints)
    elif wheel_joints is not None and not isinstance(wheel_joints, Mapping):
        if not all(isinstance(n, str) for n in wheel_joints):
            raise InputTypeError(f"wheel_joints must be joint names, got {validation.show(wheel_joints)}")
        wheel_joints = dict.fromkeys(wheel_joints)
    source = os.fspath(path)
    rd = UrdfTree(Path(path).read_bytes(), source)
    wheels = find_wheels(rd, wheel_joints)
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
    info = {name: read_wheel(rd, name, radius) for name, radius in wheels}
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
        rollers = rollers_below(rd, members[0])
        names.append(
            {j: urdf[0] for j, urdf in _joints_of(type(units[-1]), steering, members, rollers).items() if urdf}
        )
    try:
        return Robot(units, name=rd.name), names
    except InputError as exc:
        rd.fail(rd.line("robot", ""), "robot", str(exc))
