"""Robot files of every format, by their suffix: :func:`load` and :func:`dump`.

==============  =======================  ========================================================
format          suffix                   reader / writer
==============  =======================  ========================================================
``toml``        ``.toml`` (and any       :func:`wmr.io.toml.load` / :func:`wmr.io.toml.dump`, wmr's own robot file
                other)
``urdf``        ``.urdf``, ``.xml``      :func:`wmr.io.from_urdf` / :func:`wmr.io.to_urdf`
``ros2``        ``.yaml``, ``.yml``      :func:`wmr.io.from_ros2` / :func:`wmr.io.to_ros2`
==============  =======================  ========================================================

So ``wmr analyze robot.urdf`` and ``wmr analyze controllers.yaml`` read the robot as
``wmr analyze robot.toml`` does.
"""

from __future__ import annotations

import os
from pathlib import Path

from ..errors import InputValueError
from ..model import validation
from ..model.robot import Robot
from ..model.types import JointNames, PathLike, WheelJoints
from . import ros2, toml, urdf_read, urdf_write

__all__ = ["FORMATS", "format_of", "load", "dump"]

#: format -> its suffixes (a suffix not listed reads as TOML)
FORMATS = {"toml": (".toml",), "urdf": (".urdf", ".xml"), "ros2": (".yaml", ".yml")}


def format_of(path: PathLike) -> str:
    """The format of a robot file, from its suffix (case-insensitive; unknown suffixes are TOML).

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    str
        A key of :data:`FORMATS`.

    Examples
    --------
    >>> format_of("robot.URDF"), format_of("bot.yaml"), format_of("bot.cfg")
    ('urdf', 'ros2', 'toml')
    """
    validation.file_path(path)
    suffix = Path(path).suffix.lower()
    return next((f for f, suffixes in FORMATS.items() if suffix in suffixes), "toml")


def load(path: PathLike, wheel_joints: WheelJoints | None = None, controller: str | None = None) -> Robot:
    """The robot described by a robot file: TOML, URDF or ROS 2 parameters, by its suffix (:data:`FORMATS`).

    Parameters
    ----------
    path : str or os.PathLike
    wheel_joints : optional
        URDF only: the wheel joints (:func:`wmr.io.from_urdf`).
    controller : str, optional
        ROS 2 only: the drive controller's node name (:func:`wmr.io.from_ros2`).

    Returns
    -------
    Robot

    Raises
    ------
    wmr.errors.RobotFileError
        If the file is malformed: ``FILE:LINE: key: what is wrong``.
    wmr.errors.MissingDependencyError
        If the format's optional package is not installed.
    OSError
        If the file cannot be read.
    """
    fmt = format_of(path)
    if wheel_joints is not None and fmt != "urdf":
        raise InputValueError(f"wheel_joints applies to URDF files (.urdf, .xml), not to {os.fspath(path)!r}")
    if controller is not None and fmt != "ros2":
        raise InputValueError(f"controller applies to ROS 2 parameter files (.yaml, .yml), not to {os.fspath(path)!r}")
    if fmt == "urdf":
        return urdf_read.from_urdf(path, wheel_joints)
    if fmt == "ros2":
        return ros2.from_ros2(path, controller)
    return toml.load(path)


def dump(
    robot: Robot, path: PathLike | None = None, format: str | None = None, joint_names: JointNames | None = None
) -> str:
    """The text of a robot file for ``robot`` (and write it to ``path`` if given), TOML unless told otherwise.

    Parameters
    ----------
    robot : Robot
    path : str or os.PathLike, optional
        Where to write; its suffix chooses the format (:data:`FORMATS`) unless ``format`` is given.
    format : {"toml", "urdf", "ros2"}, optional
    joint_names : sequence of mapping, optional
        ROS 2 only: the joints' names (:func:`wmr.io.to_ros2`).

    Returns
    -------
    str

    Raises
    ------
    wmr.errors.InputValueError
        If the format cannot express the robot (URDF expresses every robot; ROS 2's controllers
        the layouts of :mod:`wmr.io.ros2_controllers`).

    Examples
    --------
    >>> import wmr
    >>> dump(wmr.Robot([wmr.CentredWheel((0.3, 0.0), r=0.05)]), format="urdf").splitlines()[0]
    '<?xml version="1.0"?>'
    """
    if format is None:
        format = "toml" if path is None else format_of(path)
    if format not in FORMATS:
        raise InputValueError(f"format must be one of {', '.join(FORMATS)}, got {validation.show(format)}")
    if format == "ros2":
        return ros2.to_ros2(robot, path, joint_names=joint_names)
    if joint_names is not None:
        raise InputValueError(f"joint_names applies to ROS 2 parameter files, not to format {format!r}")
    return {"toml": toml.dump, "urdf": urdf_write.to_urdf}[format](robot, path)
