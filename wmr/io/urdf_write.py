r"""A robot as a URDF file: the kinematic tree that :func:`wmr.io.from_urdf` reads back as the same robot.

Every unit is written from its **mechanism**, the tree of bodies on its joints that its kind describes
(:func:`~wmr.io.mechanism.mechanism`, each kind's entry in :mod:`wmr.io.mechanism`, the description
:mod:`wmr.sim` gives MuJoCo), so this module knows no wheel kind:

* ``base_footprint`` on the ground at C, ``base_link`` above it on the mount plane (at the height of
  the largest wheel radius);
* a body: a link ``wheel{i}_{body}_link``; its joint: ``wheel{i}_{joint}`` (the unit's joint names:
  ``steer``, ``swivel``, ``drive``, ``drive1``, ...), ``continuous`` about the body's axis, or
  ``fixed`` for a welded body; the joints at zero are :math:`\beta_i = 0`;
* a wheel body: a ``<cylinder>`` of the wheel's radius along its axle (its x axis), which spins
  with wmr's sign of :math:`\dot\theta`; an arm (a rod of the mechanism): a thin visual cylinder;
* a ``<ros2_control>`` block (hardware ``mock_components/GenericSystem``) commanding the driven
  joints: steering joints by position, wheels by velocity.  Passive joints are not listed.

A Swedish wheel has no mechanism (a physics engine has no roller contact: its kind says why), but
URDF can still say what it is: the wheel on its drive joint as a fixed wheel's, and :data:`ROLLERS`
``continuous`` joints ``wheel{i}_roller{k}`` on the rim, each about :math:`\cos\gamma\,\mathbf i +
\sin\gamma\,\mathbf t_k` (:math:`\mathbf t_k` the rim's direction of motion there, the unit's
:class:`~wmr.model.wheels.parts.Rollers`).

The file is kinematic (no inertias, no meshes); numbers are written by the rule of
:mod:`wmr.io.decimals` (12 significant digits, nothing below :math:`10^{-11}` of the robot's size for
lengths or of 1 for angles and axis directions; a trailing ``.0`` dropped), so the same robot gives
the same bytes on every CPU.
"""

from __future__ import annotations

from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.robot import Robot
from ..model.types import PathLike
from .decimals import float_text, length_scale, quantise
from .mechanism import Mechanism, mechanism, wheel

__all__ = ["to_urdf"]

#: rollers written around each Swedish wheel's rim
ROLLERS = 8


def joint_name(i: int, joint: str) -> str:
    """The URDF name ``wheel{i}_{joint}`` of joint ``joint`` of unit ``i`` (1-based): what to_urdf and to_ros2 write."""
    return f"wheel{i}_{joint}"


def _f(x, scale):
    """A number as URDF text: :func:`wmr.io.decimals.float_text` at ``scale`` (the robot's size for a length,
    1 for an angle or a direction), without a trailing ``.0``."""
    text = float_text(x, scale)
    return text[:-2] if text.endswith(".0") else text


def _v(xs, scale):
    return " ".join(_f(x, scale) for x in xs)


def _origin(xyz, size, rpy=(0.0, 0.0, 0.0)):
    out, angles = f'<origin xyz="{_v(xyz, size)}"', _v(rpy, 1.0)
    return out + (f' rpy="{angles}"/>' if angles != "0 0 0" else "/>")


def _rpy_z_to(a):
    """rpy turning a link's z axis onto the unit vector ``a`` (URDF: R = Rz(yaw) Ry(pitch) Rx(roll))."""
    # round-off off the direction first (an axis along z has no yaw), and the pitch from atan2, not arccos:
    # arccos(1 - 1e-16) = 1.5e-8 would turn round-off into a visible angle
    a = quantise(a, 1.0)
    return (0.0, float(np.arctan2(abs(np.hypot(a[0], a[1])), a[2])), float(np.arctan2(a[1], a[0])))


def _cylinder_link(name, radius, length, rpy, size, collision=True):
    geometry = f'<geometry><cylinder radius="{_f(radius, size)}" length="{_f(length, size)}"/></geometry>'
    body = [f"    <visual>{_origin((0, 0, 0), size, rpy)}{geometry}</visual>"]
    if collision:
        body.append(f"    <collision>{_origin((0, 0, 0), size, rpy)}{geometry}</collision>")
    return [f"  <link name={quoteattr(name)}>", *body, "  </link>"]


def _joint(name, parent, child, xyz, axis, size, rpy=(0.0, 0.0, 0.0)):
    head = f'  <joint name={quoteattr(name)} type="{"fixed" if axis is None else "continuous"}">'
    axis_line = [f'    <axis xyz="{_v(axis, 1.0)}"/>'] if axis is not None else []
    return [
        head,
        f"    <parent link={quoteattr(parent)}/>",
        f"    <child link={quoteattr(child)}/>",
        f"    {_origin(xyz, size, rpy)}",
        *axis_line,
        "  </joint>",
    ]


def _rod(a, b, radius, size):
    """A thin visual cylinder from ``a`` to ``b`` (a link's frame): an arm of a mechanism."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    length = float(np.linalg.norm(b - a))
    rpy = _rpy_z_to((b - a) / length)
    return (
        f'    <visual>{_origin((a + b) / 2, size, rpy)}<geometry><cylinder radius="{_f(radius, size)}" '
        f'length="{_f(length, size)}"/></geometry></visual>'
    )


def _rollers(i, wheel_link, r, gamma, size):
    """The roller joints and links of a Swedish wheel (wheel frame: x the axle, the bottom roller at -z)."""
    out, rho = [], r / 5  # roller radius; its centre r - rho from the axle
    for k in range(ROLLERS):
        phi = 2 * np.pi * k / ROLLERS
        p = (r - rho) * np.array([0.0, np.sin(phi), -np.cos(phi)])
        t = np.array([0.0, np.cos(phi), np.sin(phi)])  # x cross p/|p|: the rim's motion at the roller
        a = np.cos(gamma) * np.array([1.0, 0.0, 0.0]) + np.sin(gamma) * t
        p, a = np.where(np.abs(p) < 1e-12 * r, 0.0, p), np.where(np.abs(a) < 1e-12, 0.0, a)  # round-off: 0
        name = joint_name(i, f"roller{k}")
        out += _joint(name, wheel_link, name + "_link", p, a, size)
        out += _cylinder_link(name + "_link", rho, 2 * rho, _rpy_z_to(a), size, collision=False)
    return out


def _mechanism(i, u, height):
    """The unit's mechanism; a unit without one (a Swedish wheel) as a fixed wheel's, with its rollers."""
    try:
        return mechanism(u, height), None
    except NotImplementedError as exc:
        gamma = getattr(u, "roller", None)  # the rollers' angle to the axle (a Swedish wheel's)
        drives = [j for j in u.joints if j.kind == "drive"]
        if u.steered or len(drives) != 1 or gamma is None:
            raise InputValueError(f"URDF cannot describe wheel {i} ({u.kind}): {exc}") from None
        x, y = (float(v) for v in u.position)
        body = wheel("wheel", (x, y, float(u.r) - height), float(u.r), drives[0], angle=float(u.constant_angle))
        return Mechanism(body), float(gamma)


def _unit(i, u, height, size):
    """The URDF lines of wheel unit ``i`` (1-based) and its driven joints ``[(name, interface)]``."""
    mech, gamma = _mechanism(i, u, height)
    lines, commanded = [], []

    def body(b, parent):
        link = joint_name(i, b.name) + "_link"
        name = joint_name(i, b.joint.name if b.joint else b.name + "_weld")
        lines.extend(_joint(name, parent, link, b.pos, b.axis if b.joint else None, size, (0.0, 0.0, float(b.angle))))
        if b.joint is not None and b.joint.driven:
            commanded.append((joint_name(i, b.joint.name), "velocity" if b.wheel is not None else "position"))
        if b.wheel is not None:
            lines.extend(_cylinder_link(link, b.wheel, b.wheel / 2, (0.0, np.pi / 2, 0.0), size))
            if gamma is not None:
                lines.extend(_rollers(i, link, b.wheel, gamma, size))
                roller = [j for j in u.joints if j.kind == "roller"]
                if roller and roller[0].driven:
                    commanded.extend((joint_name(i, f"roller{k}"), "velocity") for k in range(ROLLERS))
        else:
            rods = [_rod(a, c, float(u.r) / 8, size) for a, c in b.rods if np.linalg.norm(np.subtract(c, a)) > 0]
            lines.extend(
                [f"  <link name={quoteattr(link)}>", *rods, "  </link>"]
                if rods
                else [f"  <link name={quoteattr(link)}/>"]
            )
        for child in b.children:
            body(child, link)

    body(mech.root, "base_link")
    return lines, commanded


def to_urdf(robot: Robot, path: PathLike | None = None) -> str:
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
    robot = validation.numeric_robot(robot)
    validation.file_path(path, optional=True)
    height, size = max(float(u.r) for u in robot.wheels), length_scale(robot)
    span = np.abs(robot.mount_points).max(axis=0) * 2 + height
    lines = [
        '<?xml version="1.0"?>',
        "<!-- written by wmr (wmr.io.to_urdf): x forward, y left, z up; the joints at zero are beta = 0 -->",
        f"<robot name={quoteattr(robot.name)}>",
        '  <link name="base_footprint"/>',
        '  <joint name="base_joint" type="fixed">',
        '    <parent link="base_footprint"/>',
        '    <child link="base_link"/>',
        f"    {_origin((0.0, 0.0, height), size)}",
        "  </joint>",
        '  <link name="base_link">',
        f'    <visual><geometry><box size="{_v((span[0], span[1], height / 2), size)}"/></geometry></visual>',
        "  </link>",
    ]
    commanded = []
    for i, u in enumerate(robot.wheels, 1):
        unit_lines, unit_commanded = _unit(i, u, height, size)
        lines += unit_lines
        commanded += unit_commanded
    lines += [
        '  <ros2_control name="wmr" type="system">',
        "    <hardware><plugin>mock_components/GenericSystem</plugin></hardware>",
    ]
    for name, interface in commanded:
        lines += [
            f"    <joint name={quoteattr(name)}>",
            f'      <command_interface name="{interface}"/>',
            '      <state_interface name="position"/>',
            '      <state_interface name="velocity"/>',
            "    </joint>",
        ]
    lines += ["  </ros2_control>", "</robot>"]
    text = "\n".join(lines) + "\n"
    if path is not None:
        Path(path).write_text(text, encoding="utf-8")
    return text
