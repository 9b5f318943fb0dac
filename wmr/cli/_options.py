"""Options several commands share: ``--convention`` (how angles and twists are written)."""

from __future__ import annotations

import argparse

__all__ = ["ROBOT_FILE", "add_convention", "twist_words"]

#: the help of every command's ``robot`` argument (the formats of :func:`wmr.io.load`)
ROBOT_FILE = "robot file: TOML (.toml), URDF (.urdf, .xml) or ROS 2 controller parameters (.yaml, .yml)"


def add_convention(parser: argparse.ArgumentParser) -> None:
    """Add ``--convention wmr|wpilib|ros`` (:data:`wmr.model.conventions.CONVENTIONS`) to a command.

    Parameters
    ----------
    parser : argparse.ArgumentParser

    Returns
    -------
    None
    """
    from ..model.conventions import CONVENTIONS

    parser.add_argument(
        "--convention",
        choices=list(CONVENTIONS),
        default="wmr",
        help="how angles and twists are written, in and out: "
        + "; ".join(f"{k}: {v}" for k, v in CONVENTIONS.items())
        + " (default wmr; angles in degrees on the command line)",
    )


def twist_words(twist, convention: str) -> dict:
    """A wmr twist ``[omega, vx, vy]`` as ``{name: value}`` in the order of ``convention``.

    Parameters
    ----------
    twist : sequence of 3 float
    convention : str

    Returns
    -------
    dict of str to float
    """
    from ..model.conventions import TWIST_ORDER, Twist

    return dict(zip(TWIST_ORDER[convention], Twist(*(float(x) for x in twist)).in_convention(convention)))
