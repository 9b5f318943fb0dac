r"""ROS 2 controller parameter files in and out: the robot a drive controller's parameters describe.

:func:`from_ros2` finds the drive controller in a parameter file (by the ``type`` the
``controller_manager`` block gives it, else by its parameters) and builds its robot;
:func:`to_ros2` writes the parameters of the controller whose layout the robot is, with a
``controller_manager`` block, ready for ``ros2_control_node``.  The controllers, their parameters
and what they cannot express: :mod:`wmr.io.ros2_controllers`.

Examples
--------
>>> import wmr
>>> from wmr.io.layouts import differential
>>> text = to_ros2(differential(0.4, 0.05, name="diffbot"))
>>> [line.strip() for line in text.splitlines() if "wheel_separation" in line or "DiffDrive" in line]
['type: diff_drive_controller/DiffDriveController', 'wheel_separation: 0.4']
"""

from __future__ import annotations

import json
import os
import re
from collections.abc import Mapping
from pathlib import Path

from ..errors import InputError, InputTypeError, InputValueError, RobotFileError
from ..model import validation
from ..model.checks import suggest
from ..model.robot import Robot
from ..model.types import JointNames, PathLike
from .decimals import float_text, length_scale
from .recognise import recognise
from .ros2_controllers import CONTROLLERS
from .ros2_params import Params, parse
from .urdf_write import joint_name

__all__ = ["from_ros2", "to_ros2"]


def _controllers(blocks, source):
    """``[(block, Controller)]`` of the drive controllers in the file."""
    types = {}
    for b in blocks:
        if b.node.split("/")[-1] == "controller_manager":
            types.update(
                {k: v["type"] for k, v in b.params.items() if isinstance(v, dict) and isinstance(v.get("type"), str)}
            )
    by_plugin = {c.plugin.split("/")[0]: c for c in CONTROLLERS.values()}
    out = []
    for b in blocks:
        if b.node.split("/")[-1] == "controller_manager":
            continue
        if b.node in types:
            c = by_plugin.get(types[b.node].split("/")[0])
        else:
            params = Params(source, b)
            c = next(
                (c for c in CONTROLLERS.values() if any(all(params.has(k) for k in keys) for keys in c.signature)),
                None,
            )
        if c is not None:
            out.append((b, c))
    named = {b.node for b, _ in out}
    for node, plugin in types.items():
        if plugin.split("/")[0] in by_plugin and node not in named:
            raise RobotFileError(
                source,
                1,
                node,
                f"the controller manager names a {plugin} {node!r}, but the file has no parameters for it",
            )
    return out


def from_ros2(path: PathLike, controller: str | None = None) -> Robot:
    """The robot of the drive controller in a ROS 2 parameter file (YAML).

    Parameters
    ----------
    path : str or os.PathLike
    controller : str, optional
        The controller's node name, when the file has several drive controllers.

    Returns
    -------
    Robot
        Named by the file's name; wheels in the layout's order (:mod:`wmr.io.layouts`).

    Raises
    ------
    wmr.errors.RobotFileError
        ``FILE:LINE: node.key: what is wrong`` (a key missing: the line of the node's ``ros__parameters``).
    wmr.errors.MissingDependencyError
        Without PyYAML (``pip install 'wmr-kinematics[ros]'``).
    OSError
        If the file cannot be read.
    """
    validation.file_path(path)
    if controller is not None and not isinstance(controller, str):
        raise InputTypeError(f"controller must be a node name (str), got {validation.show(controller)}")
    source = os.fspath(path)
    blocks = parse(Path(path).read_bytes(), source)
    found = _controllers(blocks, source)
    if controller is not None:
        chosen = [(b, c) for b, c in found if b.node == controller]
        if not chosen:
            names = [b.node for b, _ in found]
            raise RobotFileError(
                source,
                1,
                controller,
                f"no drive controller of that name (the file has {names or 'none'})" + suggest(controller, names),
            )
        found = chosen
    if not found:
        raise RobotFileError(
            source,
            blocks[0].line,
            blocks[0].node,
            "no drive controller wmr reads in the file "
            f"(nodes: {', '.join(b.node for b in blocks)}; wmr reads {', '.join(CONTROLLERS)})",
        )
    if len(found) > 1:
        raise RobotFileError(
            source,
            found[1][0].line,
            found[1][0].node,
            "the file has several drive controllers ("
            + ", ".join(b.node for b, _ in found)
            + "): choose one (controller=NAME)",
        )
    block, ctrl = found[0]
    params = Params(source, block)
    try:
        robot = ctrl.read(params)
    except RobotFileError:
        raise
    except InputError as exc:
        raise RobotFileError(source, block.line, block.node, str(exc)) from None
    return Robot(robot.wheels, name=Path(source).stem or robot.name)


# ------------------------------------------------------------------------------------------ writing
_PLAIN = re.compile(r"[A-Za-z_][A-Za-z0-9_/]*")
_KEYWORDS = {"yes", "no", "on", "off", "true", "false", "null", "y", "n"}  # YAML 1.1 reads these as bool/null
#: the parameters that are angles (rad, scale 1 for :func:`wmr.io.decimals.float_text`); the others are lengths
_ANGLES = {"wheel_offset", "theta"}


def _scalar(v, scale=1.0):
    """A YAML 1.1 scalar; a float by :func:`wmr.io.decimals.float_text` at ``scale``, with a '.'."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return v if _PLAIN.fullmatch(v) and v.lower() not in _KEYWORDS else json.dumps(v)
    if isinstance(v, int):  # ROS 2 parameters are typed: an int stays an int
        return str(v)
    text = float_text(v, scale)
    if "." not in text and "inf" not in text and "nan" not in text:  # YAML 1.1 floats have a '.'
        text = text.replace("e", ".0e") if "e" in text else text + ".0"
    return text


def _yaml(value, indent, size=1.0):
    """YAML lines of a mapping; floats at the scale ``size`` (the robot's) unless their key names an angle."""
    pad = " " * indent
    out = []
    for key, v in value.items():
        scale = 1.0 if key in _ANGLES else size
        if isinstance(v, dict):
            out += [f"{pad}{key}:"] + _yaml(v, indent + 2, size)
        elif isinstance(v, list):
            items = (json.dumps(x) if isinstance(x, str) else _scalar(x, scale) for x in v)
            out.append(f"{pad}{key}: [" + ", ".join(items) + "]")
        else:
            out.append(f"{pad}{key}: {_scalar(v, scale)}")
    return out


def _namer(robot, joint_names):
    """``names(i, joint)``: the given names (checked), or wmr's URDF names."""
    if joint_names is None:
        return joint_name
    if (
        isinstance(joint_names, (str, bytes))
        or len(joint_names) != robot.w
        or not all(isinstance(m, Mapping) and all(isinstance(v, str) and v for v in m.values()) for m in joint_names)
    ):
        raise InputTypeError(
            f"joint_names must be one mapping {{joint: name}} per wheel unit ({robot.w}), got {validation.show(joint_names)}"
        )

    def names(i, joint):
        if joint not in joint_names[i - 1]:
            raise InputValueError(f"joint_names[{i - 1}] has no name for joint {joint!r} of wheel {i}")
        return joint_names[i - 1][joint]

    return names


def to_ros2(
    robot: Robot, path: PathLike | None = None, controller: str | None = None, joint_names: JointNames | None = None
) -> str:
    """The ROS 2 parameters of the drive controller that fits ``robot`` (and write them to ``path`` if given).

    Parameters
    ----------
    robot : Robot
        A robot of one of the layouts of :mod:`wmr.io.ros2_controllers` (passive castors are left out).
    path : str or os.PathLike, optional
    controller : str, optional
        The controller to write (a key of :data:`~wmr.io.ros2_controllers.CONTROLLERS`); default:
        the one whose layout the robot is.
    joint_names : sequence of mapping, optional
        ``joint_names[i][joint]``: the name of joint ``joint`` (``"steer"``, ``"drive"``, ...) of wheel
        unit ``i + 1``, e.g. those :func:`wmr.io.urdf_read.read_urdf` reads; default
        :func:`wmr.io.urdf_write.joint_name` (``wheel{i}_{joint}``, the names :func:`wmr.io.to_urdf` writes).

    Returns
    -------
    str
        The YAML text: a ``controller_manager`` block and the controller's block; joint names are
        those of :func:`wmr.io.to_urdf`.

    Raises
    ------
    wmr.errors.InputValueError
        If no controller (or not ``controller``) expresses the robot: the message says why, layout by layout.
    """
    robot = validation.numeric_robot(robot)
    validation.file_path(path, optional=True)
    if controller is not None and controller not in CONTROLLERS:
        raise InputValueError(f"controller must be one of {', '.join(CONTROLLERS)}, got {validation.show(controller)}")
    chosen = [CONTROLLERS[controller]] if controller else list(CONTROLLERS.values())
    layout = recognise(
        robot,
        [c.layout for c in chosen],
        where=controller or "ROS 2's drive controllers (" + ", ".join(CONTROLLERS) + ")",
    )
    ctrl = next(c for c in chosen if c.layout == layout.name)
    params, notes = ctrl.write(layout, robot, _namer(robot, joint_names))
    notes = notes + (
        [f"passive castors (wheel {', '.join(str(i + 1) for i in layout.dropped)}) are not joints of the controller"]
        if layout.dropped
        else []
    )
    params.update({"base_frame_id": "base_link", "odom_frame_id": "odom"})
    origin = "given" if joint_names is not None else "as in wmr.io.to_urdf"
    head = [
        f"# ROS 2 parameters written by wmr (wmr.io.to_ros2) for the robot {json.dumps(robot.name)}",
        f"# {ctrl.name}: layout {layout.name}; joint names {origin}",
    ] + [f"# {n}" for n in notes]
    manager = {
        "controller_manager": {
            "ros__parameters": {
                "update_rate": 100,
                "joint_state_broadcaster": {"type": "joint_state_broadcaster/JointStateBroadcaster"},
                ctrl.name: {"type": ctrl.plugin},
            }
        }
    }
    text = (
        "\n".join(
            head + _yaml(manager, 0) + [""] + _yaml({ctrl.name: {"ros__parameters": params}}, 0, length_scale(robot))
        )
        + "\n"
    )
    if path is not None:
        Path(path).write_text(text, encoding="utf-8")
    return text
