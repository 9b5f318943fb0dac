"""The ``wmr`` command line, ``wmr COMMAND`` (also ``python -m wmr``).

Each command lives in its own module of this package (one file per command) and provides

* ``HELP``: one line for ``wmr --help``;
* ``add_arguments(parser)``: its options (an :class:`argparse.ArgumentParser`);
* ``run(args) -> int``: the exit status (0 ok).  Bad input raises an :class:`~wmr.errors.InputError`
  (a malformed robot file :class:`~wmr.errors.RobotFileError`, an unreadable file ``OSError``; an
  optional package a file format needs and that is missing, :class:`~wmr.errors.MissingDependencyError`);
  :func:`main` turns it into one line on stderr, ``wmr COMMAND: message``, and exit status 2,
  without a traceback.  Any other exception is a bug in wmr: :func:`main` prints its traceback
  and a one-line request to report it, and returns 1.

A command's ``--json`` is printed by ``wmr.cli._numbers.json_text``: every float by the rule of
:mod:`wmr.io.decimals`, at the scale of its quantity, so that the same input prints the same JSON on
every CPU.

:data:`COMMANDS` lists them in the order ``wmr --help`` shows.
"""

from __future__ import annotations

import argparse
import importlib
import sys
import traceback
from collections.abc import Sequence

from ..errors import InputError, MissingDependencyError

__all__ = ["COMMANDS", "main"]

#: command name -> module of this package that implements it
COMMANDS = {
    "analyze": "analyze",
    "ik": "ik",
    "fk": "fk",
    "sweep": "sweep",
    "simulate": "simulate",
    "convert": "convert",
    "explain": "explain",
}


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


def _parser():
    p = argparse.ArgumentParser(
        prog="wmr",
        description="Kinematics of wheeled mobile robots: mobility, "
        "isotropy, singularities and kinematics of a robot described in a TOML file.",
    )
    p.add_argument("--version", action=_Version)
    sub = p.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name, module in COMMANDS.items():
        mod = importlib.import_module(f"{__name__}.{module}")
        mod.add_arguments(sub.add_parser(name, help=mod.HELP, description=mod.HELP))
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
