r"""A robot as a URDF file: the kinematic tree that :func:`wmr.io.from_urdf` reads back as the same robot.

Every unit is written from what it answers (its joints, :meth:`~wmr.model.wheels.WheelUnit.points`
and :meth:`~wmr.model.wheels.WheelUnit.parts`), so every wheel kind is written without a case of its own:

* ``base_footprint`` on the ground at C, ``base_link`` above it at the height of the largest wheel
  radius (the mount plane);
* a steered unit: a ``continuous`` joint about z at :math:`P_i` (``wheel{i}_steer`` or
  ``wheel{i}_swivel``, the unit's joint name; at zero :math:`\beta_i = 0`) carrying ``wheel{i}_body``;
  a unit without one hangs its wheel from ``base_link`` at its own angle;
* each wheel: a ``continuous`` joint ``wheel{i}_{joint}`` at the wheel's centre, turning about the
  axle :math:`\mathbf i_i` (wmr's sign of :math:`\dot\theta`), and a link with a ``<cylinder>`` of
  the wheel's radius along it;
* a Swedish wheel's rollers: :data:`ROLLERS` ``continuous`` joints ``wheel{i}_roller{k}`` on the rim,
  each about :math:`\cos\gamma\,\mathbf i + \sin\gamma\,\mathbf t_k` (:math:`\mathbf t_k` the rim's
  direction of motion there), with a small visual cylinder;
* a ``<ros2_control>`` block (hardware ``mock_components/GenericSystem``) commanding the driven
  joints: steering by position, wheels by velocity.  Passive joints are not listed.

The file is kinematic: no inertias, no meshes; numbers are written as the shortest text that
reads back as the same double, so writing a robot twice gives the same bytes.
"""
from __future__ import annotations

import os
from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from ..errors import InputTypeError, InputValueError
from ..model import validation as V
from ..model.wheels.parts import Rollers

__all__ = ["ROLLERS", "joint_name", "to_urdf"]

#: rollers written around each Swedish wheel's rim
ROLLERS = 8


def joint_name(i, joint):
    """The URDF name of joint ``joint`` (e.g. ``"drive"``) of wheel unit ``i`` (1-based): ``wheel{i}_{joint}``.

    The names :func:`to_urdf` and :func:`wmr.io.to_ros2` write, so that the two files agree.

    Parameters
    ----------
    i : int
    joint : str

    Returns
    -------
    str

    Examples
    --------
    >>> joint_name(2, "steer")
    'wheel2_steer'
    """
    return f"wheel{i}_{joint}"


def _f(x):
    text = repr(float(x))
    return "0" if text in ("0.0", "-0.0") else text[:-2] if text.endswith(".0") else text


def _v(*xs):
    return " ".join(_f(x) for x in xs)


def _origin(xyz, rpy=(0.0, 0.0, 0.0)):
    out = f'<origin xyz="{_v(*xyz)}"'
    return out + (f' rpy="{_v(*rpy)}"/>' if any(rpy) else "/>")


def _rpy_z_to(a):
    """rpy turning a link's z axis onto the unit vector ``a`` (URDF: R = Rz(yaw) Ry(pitch) Rx(roll))."""
    return (0.0, float(np.arccos(np.clip(a[2], -1.0, 1.0))), float(np.arctan2(a[1], a[0])))


def _cylinder_link(name, radius, length, rpy, collision=True):
    geometry = f'<geometry><cylinder radius="{_f(radius)}" length="{_f(length)}"/></geometry>'
    body = [f'    <visual>{_origin((0, 0, 0), rpy)}{geometry}</visual>']
    if collision:
        body.append(f'    <collision>{_origin((0, 0, 0), rpy)}{geometry}</collision>')
    return [f"  <link name={quoteattr(name)}>", *body, "  </link>"]


def _joint(name, parent, child, xyz, axis, rpy=(0.0, 0.0, 0.0)):
    return [f"  <joint name={quoteattr(name)} type=\"continuous\">",
            f"    <parent link={quoteattr(parent)}/>", f"    <child link={quoteattr(child)}/>",
            f"    {_origin(xyz, rpy)}", f'    <axis xyz="{_v(*axis)}"/>', "  </joint>"]


def _rollers(i, wheel_link, r, gamma):
    """The roller joints and links of a Swedish wheel (wheel frame: x the axle, the bottom roller at -z)."""
    out, rho = [], r / 5                                   # roller radius; its centre r - rho from the axle
    for k in range(ROLLERS):
        phi = 2 * np.pi * k / ROLLERS
        p = (r - rho) * np.array([0.0, np.sin(phi), -np.cos(phi)])
        t = np.array([0.0, np.cos(phi), np.sin(phi)])       # x cross p/|p|: the rim's motion at the roller
        a = np.cos(gamma) * np.array([1.0, 0.0, 0.0]) + np.sin(gamma) * t
        p, a = np.where(np.abs(p) < 1e-12 * r, 0.0, p), np.where(np.abs(a) < 1e-12, 0.0, a)   # round-off: 0
        name = joint_name(i, f"roller{k}")
        out += _joint(name, wheel_link, name + "_link", p, a)
        out += _cylinder_link(name + "_link", rho, 2 * rho, _rpy_z_to(a), collision=False)
    return out


def _unit(i, u, height):
    """The URDF lines of wheel unit ``i`` (1-based) and its driven joints ``[(name, interface)]``."""
    r = float(u.r)
    pts = u.points(0.0)
    P = np.asarray(pts["P"], dtype=float)
    joints = u.joints
    steer = [j for j in joints if j.steering]
    drives = [j for j in joints if j.kind == "drive"]
    rollers = [p for p in u.parts(0.0) if isinstance(p, Rollers)]
    commanded, lines = [], []
    parent, origin, yaw = "base_link", np.zeros(2), 0.0
    if steer:
        body = joint_name(i, "body")
        lines += _joint(joint_name(i, steer[0].name), "base_link", body, (*P, 0.0), (0.0, 0.0, 1.0))
        lines += [f"  <link name={quoteattr(body)}/>"]
        commanded += [(joint_name(i, steer[0].name), "position")] if steer[0].driven else []
        parent, origin = body, P
    else:
        yaw = float(np.arctan2(pts["i"][1], pts["i"][0]))
    wheels = np.asarray(pts["wheels"], dtype=float).reshape(-1, 2)
    if len(wheels) != len(drives):
        raise InputValueError(f"wheel {i} ({u.kind}) has {len(wheels)} wheels and {len(drives)} drive joints: URDF "
                              "needs one drive joint per wheel")
    for c, j in zip(wheels, drives):
        name = joint_name(i, j.name)
        link = name + "_link"
        lines += _joint(name, parent, link, (*(c - origin), r - height), (1.0, 0.0, 0.0), (0.0, 0.0, yaw))
        lines += _cylinder_link(link, r, r / 2, (0.0, np.pi / 2, 0.0))
        commanded += [(name, "velocity")] if j.driven else []
        if rollers:
            lines += _rollers(i, link, r, float(rollers[0].angle))
    roller = [j for j in joints if j.kind == "roller" and j.driven]
    if roller and rollers:
        commanded += [(joint_name(i, f"roller{k}"), "velocity") for k in range(ROLLERS)]
    return lines, commanded


def to_urdf(robot, path=None):
    """The URDF text of ``robot`` (and write it to ``path`` if given); :func:`wmr.io.from_urdf` reads it back.

    Parameters
    ----------
    robot : Robot
        Any numeric robot (every wheel kind: module notes).
    path : str or os.PathLike, optional

    Returns
    -------
    str

    Examples
    --------
    >>> import wmr
    >>> text = to_urdf(wmr.Robot([wmr.CentredWheel((0.3, 0.0), r=0.05)], name="one"))
    >>> [line.strip() for line in text.splitlines() if "<joint" in line and "type=" in line]
    ['<joint name="base_joint" type="fixed">', '<joint name="wheel1_steer" type="continuous">', \
'<joint name="wheel1_drive" type="continuous">']
    """
    robot = V.numeric_robot(robot)
    if path is not None and not isinstance(path, (str, os.PathLike)):
        raise InputTypeError(f"path must be a file name (str or os.PathLike) or None, got {V.show(path)}")
    height = max(float(u.r) for u in robot.wheels)
    span = np.abs(robot.mount_points).max(axis=0) * 2 + height
    lines = ['<?xml version="1.0"?>',
             "<!-- written by wmr (wmr.io.to_urdf): x forward, y left, z up; the joints at zero are beta = 0 -->",
             f"<robot name={quoteattr(robot.name)}>", '  <link name="base_footprint"/>',
             '  <joint name="base_joint" type="fixed">', '    <parent link="base_footprint"/>',
             '    <child link="base_link"/>', f"    {_origin((0.0, 0.0, height))}", "  </joint>",
             '  <link name="base_link">',
             f'    <visual><geometry><box size="{_v(span[0], span[1], height / 2)}"/></geometry></visual>',
             "  </link>"]
    commanded = []
    for i, u in enumerate(robot.wheels, 1):
        unit_lines, unit_commanded = _unit(i, u, height)
        lines += unit_lines
        commanded += unit_commanded
    lines += ['  <ros2_control name="wmr" type="system">',
              "    <hardware><plugin>mock_components/GenericSystem</plugin></hardware>"]
    for name, interface in commanded:
        lines += [f"    <joint name={quoteattr(name)}>", f'      <command_interface name="{interface}"/>',
                  '      <state_interface name="position"/>', '      <state_interface name="velocity"/>',
                  "    </joint>"]
    lines += ["  </ros2_control>", "</robot>"]
    text = "\n".join(lines) + "\n"
    if path is not None:
        Path(path).write_text(text, encoding="utf-8")
    return text
