"""``wmr convert ROBOT OUTPUT``: a robot from one format to another (TOML, URDF, ROS 2 parameters).

Example::

    wmr convert examples/tricycle.toml --to ros2              # to standard output

Each file's format is its suffix (``.toml``; ``.urdf`` or ``.xml``; ``.yaml`` or ``.yml``:
:data:`wmr.io.FORMATS`).  From a URDF to ROS 2 parameters, the controller gets the URDF's joint
names.  A format that cannot express the robot (ROS 2 parameters for a robot that is no
controller's layout) is refused with a one-line reason (exit status 2).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import argparse

__all__ = ["run"]


def run(args: argparse.Namespace) -> int:
    """Run ``wmr convert``.

    Parameters
    ----------
    args : argparse.Namespace
        The options of ``wmr convert`` (:func:`wmr.cli.main` parses them).

    Returns
    -------
    int
        0; bad input raises an input error (:mod:`wmr.errors`; :func:`wmr.cli.main` reports it in one line, status 2).
    """
    from ..errors import InputValueError
    from ..io import dump, format_of, load
    from ..io.urdf_read import read_urdf

    if args.output is None and args.to is None:
        raise InputValueError("give an output file or --to FORMAT (toml, urdf, ros2) to print it")
    names = None
    if format_of(args.robot) == "urdf":  # a URDF's joint names go on into ROS 2 parameters
        robot, names = read_urdf(args.robot, args.wheel_joints)
    else:
        robot = load(args.robot, wheel_joints=args.wheel_joints, controller=args.controller)
    ros2 = (args.to or format_of(args.output)) == "ros2"
    text = dump(robot, args.output, format=args.to, joint_names=names if ros2 else None)
    if args.output is None:
        print(text, end="")
    return 0
