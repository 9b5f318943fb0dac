"""The ``wmr`` command line, ``wmr COMMAND`` (also ``python -m wmr``).

This module is the whole command line as a user sees it: every command's arguments and help, built
without importing the commands.  Each command's code is the module of this package that
:data:`COMMANDS` names, imported only when that command runs; it provides ``run(args) -> int``, the
exit status (0 ok).  Bad input raises an :class:`~wmr.errors.InputError` (a malformed robot file
:class:`~wmr.errors.RobotFileError`, an unreadable file ``OSError``; a missing optional package a file
format needs, :class:`~wmr.errors.MissingDependencyError`); :func:`main` turns it into one line on
stderr, ``wmr COMMAND: message``, and exit status 2, without a traceback.  Any other exception is a
bug in wmr: :func:`main` prints its traceback and a one-line request to report it, and returns 1.

A command's ``--json`` is printed by ``wmr.cli._numbers.json_text``: every float by the rule of
:mod:`wmr.io.decimals`, at the scale of its quantity, so that the same input prints the same JSON on
every CPU.
"""

from __future__ import annotations

import argparse
import importlib
import sys
import traceback
from collections.abc import Sequence

from ..analysis.overview import GRID_ANGLES, GRID_SIZE, TWISTS
from ..analysis.sweep import ANALYSES, CHUNK, QUANTILES
from ..errors import InputError, MissingDependencyError
from ..model.conventions import CONVENTIONS

__all__ = ["COMMANDS", "main"]

#: command name -> module of this package that implements it, in the order ``wmr --help`` shows
COMMANDS = {
    "analyze": "analyze",
    "ik": "ik",
    "fk": "fk",
    "sweep": "sweep",
    "simulate": "simulate",
    "convert": "convert",
    "explain": "explain",
}

#: the help of every command's ``robot`` argument (the formats of :func:`wmr.io.load`)
ROBOT_FILE = "robot file: TOML (.toml), URDF (.urdf, .xml) or ROS 2 controller parameters (.yaml, .yml)"
#: encoder counts per wheel revolution assumed by ``wmr fk``'s default slip tolerance (a common FRC motor's)
ENCODER_COUNTS = 2048
#: control period in seconds assumed by ``wmr fk``'s default slip tolerance (WPILib's 20 ms loop)
PERIOD = 0.02


def _version():
    """``wmr --version``: the version, the distribution that provides it, and where it is installed."""
    import os
    import platform

    from .._version import DISTRIBUTION, __version__

    where = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    return f"wmr {__version__} ({DISTRIBUTION}, {where}, Python {platform.python_version()})"


class _Version(argparse.Action):
    """``--version``: print :func:`_version` on one line (argparse's own action wraps it) and exit."""

    def __init__(self, option_strings, dest, **kwargs):
        super().__init__(
            option_strings,
            dest,
            nargs=0,
            default=argparse.SUPPRESS,
            help="show the version, the distribution and where it is installed, and exit",
        )

    def __call__(self, parser, namespace, values, option_string=None):
        print(_version())
        parser.exit()


def _convention(parser: argparse.ArgumentParser) -> None:
    """``--convention wmr|wpilib|ros`` (:data:`wmr.model.conventions.CONVENTIONS`), shared by several commands."""
    parser.add_argument(
        "--convention",
        choices=list(CONVENTIONS),
        default="wmr",
        help="how angles and twists are written, in and out: "
        + "; ".join(f"{k}: {v}" for k, v in CONVENTIONS.items())
        + " (default wmr; angles in degrees on the command line)",
    )


def _analyze(parser: argparse.ArgumentParser) -> None:
    """Arguments of ``wmr analyze`` (the defaults of :func:`wmr.analysis.overview.overview`)."""
    parser.add_argument("robot", help=ROBOT_FILE)
    parser.add_argument("--wheel-joints", metavar="NAMES", help="URDF only: the wheel joints, NAME[=RADIUS],...")
    parser.add_argument("--json", action="store_true", help="print JSON instead of a table")
    parser.add_argument(
        "--grid",
        type=int,
        default=None,
        metavar="N",
        help=f"about N grid configurations of the steered angles (default {GRID_SIZE}, fewer for more than "
        f"{GRID_ANGLES // GRID_SIZE} steered units: at most {GRID_ANGLES:,} angles)",
    )
    parser.add_argument(
        "--twists",
        type=int,
        default=TWISTS,
        metavar="N",
        help=f"sample N twists for the drivable configurations (default {TWISTS})",
    )
    parser.add_argument(
        "--seed", type=int, default=0, help="seed of the random twists and of the generic configuration"
    )
    parser.add_argument("--brief", action="store_true", help="the table without the notes under it")
    _convention(parser)


def _ik(parser: argparse.ArgumentParser) -> None:
    """Arguments of ``wmr ik``."""
    parser.add_argument("robot", help=ROBOT_FILE)
    parser.add_argument("--vx", default="0", help="velocity of C along the body x axis (forward), m/s (default 0)")
    parser.add_argument("--vy", default="0", help="velocity of C along the body y axis (left), m/s (default 0)")
    parser.add_argument("--omega", default="0", help="turning rate, rad/s, counter-clockwise (default 0)")
    parser.add_argument(
        "--current-angles",
        nargs="+",
        metavar="DEG",
        default=None,
        help="the units' current steering angles in degrees, one per unit, in the convention "
        "chosen (default: 0 for every unit, the same as giving 0 0 ...)",
    )
    parser.add_argument("--json", action="store_true", help="print JSON instead of a table")
    _convention(parser)


def _fk(parser: argparse.ArgumentParser) -> None:
    """Arguments of ``wmr fk``."""
    parser.add_argument("robot", help=ROBOT_FILE)
    parser.add_argument(
        "--angles",
        nargs="+",
        metavar="DEG",
        required=True,
        help="steering angles in degrees, one per unit (space- or comma-separated), in the convention chosen",
    )
    parser.add_argument(
        "--rates",
        nargs="+",
        metavar="RATE",
        required=True,
        help="joint rates in rad/s, in the order of the robot's rate names",
    )
    parser.add_argument(
        "--slip-tolerance",
        metavar="M_PER_S",
        default=None,
        help="slip speed (m/s) below which a wheel counts as not slipping (default: one encoder "
        "count per control period at the largest wheel's rim, see --encoder-counts, --period)",
    )
    parser.add_argument(
        "--encoder-counts",
        metavar="N",
        default=str(ENCODER_COUNTS),
        help=f"encoder counts per wheel revolution for the default slip tolerance (default {ENCODER_COUNTS})",
    )
    parser.add_argument(
        "--period",
        metavar="S",
        default=str(PERIOD),
        help=f"control period in seconds for the default slip tolerance (default {PERIOD})",
    )
    parser.add_argument("--json", action="store_true", help="print JSON instead of a table")
    _convention(parser)


def _sweep(parser: argparse.ArgumentParser) -> None:
    """Arguments of ``wmr sweep`` (the analyses and defaults of :func:`wmr.analysis.sweep.sweep`)."""
    parser.add_argument("robot", help=ROBOT_FILE)
    parser.add_argument("analysis", choices=sorted(ANALYSES), help="what to evaluate at each configuration")
    parser.add_argument(
        "--angles",
        choices=("drivable", "any"),
        default=None,
        help="drivable: the steering angles of sampled twists, where the robot can move (the "
        "default); any: every steering angle, drivable or not (the default with --grid)",
    )
    which = parser.add_mutually_exclusive_group()
    which.add_argument(
        "--grid",
        metavar="STEPS",
        help="with --angles any: a regular grid of STEPS values per "
        "steered angle (default 36), or one count per wheel separated by commas",
    )
    which.add_argument(
        "--sample",
        metavar="N",
        help="N sampled twists (drivable, default 1e6) or N random configurations (any), e.g. 1e6",
    )
    parser.add_argument("--seed", type=int, default=0, help="seed of --sample (default 0)")
    parser.add_argument(
        "--range",
        nargs=2,
        type=float,
        metavar=("LO", "HI"),
        default=None,
        help="with --angles any: range of every steering angle in degrees, in the convention chosen (default -180 180)",
    )
    parser.add_argument(
        "--length",
        type=float,
        default=None,
        metavar="L",
        help="characteristic length of J_L1 (default: the robot's characteristic length)",
    )
    parser.add_argument(
        "--quantiles", default=",".join(f"{q:g}" for q in QUANTILES), help="quantile levels, comma-separated"
    )
    parser.add_argument("--chunk", type=int, default=CHUNK, help=f"configurations per chunk (default {CHUNK})")
    parser.add_argument(
        "--dask",
        metavar="SCHEDULER",
        default=None,
        help="run the chunks on Dask: a scheduler address, or local:N for N local workers",
    )
    parser.add_argument("--json", action="store_true", help="print JSON instead of a table")
    parser.add_argument(
        "--progress",
        action=argparse.BooleanOptionalAction,
        default=None,
        help="show a progress bar on stderr (default: when stderr is a terminal)",
    )
    _convention(parser)


def _simulate(parser: argparse.ArgumentParser) -> None:
    """Arguments of ``wmr simulate`` (the parameters of :class:`wmr.sim.Params`)."""
    parser.add_argument("robot", help=ROBOT_FILE)
    parser.add_argument("--vx", default="0", help="velocity of C along the body x axis, m/s (default 0)")
    parser.add_argument("--vy", default="0", help="velocity of C along the body y axis, m/s (default 0)")
    parser.add_argument("--omega", default="0", help="turning rate, rad/s, counter-clockwise (default 0)")
    parser.add_argument("--seconds", default="3", help="simulated time, s (default 3; 0: only write --mjcf)")
    parser.add_argument("--mjcf", metavar="FILE", default=None, help="write the MuJoCo model (MJCF) to FILE")
    parser.add_argument(
        "--param",
        nargs="+",
        metavar="NAME=VALUE",
        default=(),
        help="change physical parameters (wmr.sim.Params), e.g. sliding=0.6 torsional=0",
    )
    parser.add_argument("--json", action="store_true", help="print JSON instead of a table")


def _convert(parser: argparse.ArgumentParser) -> None:
    """Arguments of ``wmr convert`` (the formats of :data:`wmr.io.FORMATS`)."""
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


def _explain(parser: argparse.ArgumentParser) -> None:
    """Arguments of ``wmr explain`` (the terms of :mod:`wmr.words.glossary`)."""
    parser.add_argument(
        "term", nargs="?", default=None, help="the term (case, spaces, - and _ do not matter); none: list every term"
    )


#: command -> its line in ``wmr --help`` (also its description in ``wmr COMMAND --help``), its arguments
_COMMAND_LINE = {
    "analyze": (
        "class, actuated mobility, limitations, mobility (rank F), isotropy and singular configurations of a robot",
        _analyze,
    ),
    "ik": ("steering angles and wheel rates for a commanded twist (inverse kinematics)", _ik),
    "fk": ("the platform twist (least squares) and the slip residual for steering angles and wheel rates", _fk),
    "sweep": (
        "evaluate rank F, mobility, actuated mobility, det J or a condition number over the drivable "
        "configurations (or all)",
        _sweep,
    ),
    "simulate": ("the robot in MuJoCo following a commanded twist (needs mujoco); --mjcf writes the model", _simulate),
    "convert": (
        "convert a robot between TOML, URDF and ROS 2 controller parameters (formats by file suffix)",
        _convert,
    ),
    "explain": (
        "explain a term of wmr's output (rank-F, nullity, J_L1, J2, kappa, through-P, actuated-mobility, ...)",
        _explain,
    ),
}


def _parser() -> argparse.ArgumentParser:
    """The parser of ``wmr``: every command's arguments and help, in the order of :data:`COMMANDS`."""
    p = argparse.ArgumentParser(
        prog="wmr",
        description="Kinematics of wheeled mobile robots: mobility, "
        "isotropy, singularities and kinematics of a robot described in a TOML file.",
    )
    p.add_argument("--version", action=_Version)
    sub = p.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name in COMMANDS:
        text, arguments = _COMMAND_LINE[name]
        arguments(sub.add_parser(name, help=text, description=text))
    return p


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line.

    Parameters
    ----------
    argv : list of str, optional
        Arguments after the program name (default ``sys.argv[1:]``).

    Returns
    -------
    int
        Exit status: 0 ok, 2 bad input (one line on stderr), 1 a bug in wmr (its traceback on stderr).
    """
    args = _parser().parse_args(sys.argv[1:] if argv is None else argv)
    mod = importlib.import_module(f"{__name__}.{COMMANDS[args.command]}")
    try:
        return mod.run(args)
    except BrokenPipeError:  # the reader stopped (wmr ... | head): not an error
        sys.stderr.close()
        return 0
    except (InputError, MissingDependencyError, OSError) as exc:  # bad input, a missing extra: one line
        print(f"wmr {args.command}: {' '.join(str(exc).split())}", file=sys.stderr)
        return 2
    except Exception:  # a bug in wmr: show it, ask for a report
        traceback.print_exc()
        print(
            f"wmr {args.command}: internal error: this is a bug in wmr, not a problem with your input; please "
            f"report it with the command line and the robot file",
            file=sys.stderr,
        )
        return 1
