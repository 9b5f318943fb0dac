"""The ``wmr`` command line, ``wmr COMMAND`` (also ``python -m wmr``).

Each command lives in its own module of this package (one file per command) and provides

* ``HELP``: one line for ``wmr --help``;
* ``add_arguments(parser)``: its options (an :class:`argparse.ArgumentParser`);
* ``run(args) -> int``: the exit status (0 ok).  Bad input raises ``ValueError`` or ``TypeError``
  (an unreadable file ``OSError``); :func:`main` turns it into one line on stderr,
  ``wmr COMMAND: message``, and exit status 2, without a traceback.

:data:`COMMANDS` lists them in the order ``wmr --help`` shows.
"""
from __future__ import annotations

import argparse
import importlib
import sys

__all__ = ["COMMANDS", "main"]

#: command name -> module of this package that implements it
COMMANDS = {
    "analyze": "analyze",
    "ik": "ik",
    "fk": "fk",
    "sweep": "sweep",
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
        super().__init__(option_strings, dest, nargs=0, default=argparse.SUPPRESS,
                         help="show the version, the distribution and where it is installed, and exit")

    def __call__(self, parser, namespace, values, option_string=None):
        print(_version())
        parser.exit()


def _parser():
    p = argparse.ArgumentParser(prog="wmr", description="Kinematics of wheeled mobile robots: mobility, "
                                "isotropy, singularities and kinematics of a robot described in a TOML file.")
    p.add_argument("--version", action=_Version)
    sub = p.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name, module in COMMANDS.items():
        mod = importlib.import_module(f"{__name__}.{module}")
        mod.add_arguments(sub.add_parser(name, help=mod.HELP, description=mod.HELP))
    return p


def main(argv=None):
    """Run the command line.

    Parameters
    ----------
    argv : list of str, optional
        Arguments after the program name (default ``sys.argv[1:]``).

    Returns
    -------
    int
        Exit status.
    """
    args = _parser().parse_args(sys.argv[1:] if argv is None else argv)
    mod = importlib.import_module(f"{__name__}.{COMMANDS[args.command]}")
    try:
        return mod.run(args)
    except (ValueError, TypeError, OSError) as exc:               # bad input: one line, no traceback
        print(f"wmr {args.command}: {' '.join(str(exc).split())}", file=sys.stderr)
        return 2
