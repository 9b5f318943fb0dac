"""``wmr convert ROBOT OUTPUT``: a robot from one format to another (TOML, URDF, ROS 2 parameters).

Examples::

    wmr convert examples/urdf/diffbot.urdf diffbot.toml
    wmr convert examples/swerve4.toml swerve4.urdf
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

__all__ = ["HELP", "add_arguments", "run"]

HELP = "convert a robot between TOML, URDF and ROS 2 controller parameters (formats by file suffix)"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Options of ``wmr convert``.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The sub-command's parser.

    Returns
    -------
    None
    """
    parser.add_argument("robot", help="robot file: .toml, .urdf/.xml or .yaml/.yml (ROS 2 parameters)")
    parser.add_argument(
        "output",
        nargs="?",
        help="file to write (its suffix chooses the format); default: standard output in the format of --to",
    )
    parser.add_argument("--to", choices=("toml", "urdf", "ros2"), help="output format (default: the output's suffix)")
    parser.add_argument(
        "--wheel-joints",
        metavar="NAMES",
        help="URDF input: the wheel joints, comma-separated, each NAME or NAME=RADIUS (for wheels without a cylinder)",
    )
    parser.add_argument(
        "--controller", metavar="NAME", help="ROS 2 input: the drive controller's node name, when the file has several"
    )


def run(args: argparse.Namespace) -> int:
    """Run ``wmr convert``.

    Parameters
    ----------
    args : argparse.Namespace

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
