"""``wmr fk ROBOT.toml --angles DEG [DEG ...] --rates RATE [RATE ...]``: the platform twist from steering angles and
wheel rates.

Examples::

    wmr fk examples/swerve4.toml --angles 0 0 0 0 --rates -10 -10 -10 -10
    wmr fk examples/paper_offset.toml --angles 10 20 30 --rates 1 2 1 2 1 2 --json

``--angles`` in degrees, one per unit; ``--rates`` in rad/s in the order of
:attr:`wmr.Robot.rate_names` (``theta_dot_i`` for a centred wheel, ``phi_dot_i theta_dot_i`` for an
offset wheel, ``theta_dot_i1 theta_dot_i2`` for a dual wheel).  The twist is the least-squares
solution of (21) (:func:`wmr.forward`), printed as ``omega`` (rad/s), ``vx``, ``vy`` (m/s, body
frame); the slip residual :math:`\\mathbf J_1\\mathbf t - \\mathbf J_2\\dot{\\boldsymbol\\theta}` is zero
exactly when the rates are compatible.
"""
from __future__ import annotations

import json
from typing import TYPE_CHECKING

import numpy as np

from ._numbers import clean, fmt, numbers

if TYPE_CHECKING:
    import argparse

__all__ = ["HELP", "add_arguments", "run"]

HELP = "the platform twist (least squares) and the slip residual for steering angles and wheel rates"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Options of ``wmr fk``.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The sub-command's parser.

    Returns
    -------
    None
    """
    parser.add_argument("robot", help="robot file (TOML)")
    parser.add_argument("--angles", nargs="+", metavar="DEG", required=True,
                        help="steering angles in degrees, one per unit (space- or comma-separated)")
    parser.add_argument("--rates", nargs="+", metavar="RATE", required=True,
                        help="joint rates in rad/s, in the order of the robot's rate names")
    parser.add_argument("--json", action="store_true", help="print JSON instead of a table")


def run(args: argparse.Namespace) -> int:
    """Run ``wmr fk``.

    Parameters
    ----------
    args : argparse.Namespace

    Returns
    -------
    int
        0; bad input raises an input error (:mod:`wmr.errors`; :func:`wmr.cli.main` reports it in one line, status 2).
    """
    import wmr
    robot = wmr.load(args.robot)
    beta = np.radians(numbers(args.angles, "--angles", robot.w, "one angle in degrees per wheel unit"))
    rates = np.array(numbers(args.rates, "--rates", robot.n_rates, " ".join(robot.rate_names)))
    sol = wmr.forward(robot, beta, rates)
    size = float(np.abs(robot.mount_points).max())
    t = clean(sol.value, max(abs(sol.value[0]) * size, *np.abs(sol.value[1:])))      # rounding noise shown as 0
    res = clean(sol.residual, float(np.abs(robot.J2(beta) @ rates).max()))
    out = {"omega": float(t[0]), "vx": float(t[1]), "vy": float(t[2]), "admissible": bool(sol.admissible),
           "slip": float(np.linalg.norm(sol.residual)), "residual": sol.residual.tolist()}
    if args.json:
        print(json.dumps(out, indent=2))
        return 0
    rows = [("omega", f"{fmt(t[0])} rad/s"), ("vx", f"{fmt(t[1])} m/s"), ("vy", f"{fmt(t[2])} m/s"),
            ("slip", f"{fmt(float(np.linalg.norm(res)), 3)} m/s (norm of J1 t - J2 theta_dot)"),
            ("admissible", "yes: the rates are compatible" if sol.admissible else "no: the wheels would slip")]
    for k, _ in enumerate(robot.wheels):
        rows.append((f"residual {k + 1}", f"({fmt(res[2 * k], 3)}, {fmt(res[2 * k + 1], 3)}) m/s"))
    width = max(len(k) for k, _ in rows)
    print("\n".join(f"{k:<{width}}  {v}" for k, v in rows))
    return 0
