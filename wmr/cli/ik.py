"""``wmr ik ROBOT.toml --vx VX --vy VY --omega W``: steering angles and wheel rates for a commanded twist.

Examples::

    wmr ik examples/swerve4.toml --vx 1.0 --vy 0.5 --omega 0.8
    wmr ik examples/swerve4.toml --vx 1 --omega 0.8 --current-angles 0 0 0 0 --json

The twist is body-frame: ``--vx``, ``--vy`` (m/s, the velocity of C), ``--omega`` (rad/s,
counter-clockwise); wmr orders it :math:`[\\dot\\psi, \\dot x, \\dot y]` (:mod:`wmr.conventions`).
The steering angles are :func:`wmr.steering_angles` (the angle with a positive rolling rate; where
a unit's choice is free, e.g. an offset wheel, its current angle is kept; with ``--current-angles``,
a centred or dual unit takes :math:`\\beta` or :math:`\\beta+\\pi`, whichever is nearer its current
angle, and rolls backwards in the second case) and the rates
:func:`wmr.inverse` at those angles, in the order of :attr:`wmr.Robot.rate_names` (rad/s).  The
twist is admissible when no wheel slips at those angles (a fixed-wheel robot cannot realise every
twist); it is admissible *without re-steering* when no wheel slips at the current angles
(``--current-angles``, degrees, one per unit; default 0; the entries of fixed and Swedish wheels are
ignored: they keep their own angle).
"""
from __future__ import annotations

import json
import math
from typing import TYPE_CHECKING

import numpy as np

from ._numbers import clean, fmt, number, numbers

if TYPE_CHECKING:
    import argparse

__all__ = ["HELP", "add_arguments", "run"]

HELP = "steering angles and wheel rates for a commanded twist (inverse kinematics)"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Options of ``wmr ik``.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The sub-command's parser.

    Returns
    -------
    None
    """
    parser.add_argument("robot", help="robot file (TOML)")
    parser.add_argument("--vx", default="0", help="velocity of C along the body x axis, m/s (default 0)")
    parser.add_argument("--vy", default="0", help="velocity of C along the body y axis, m/s (default 0)")
    parser.add_argument("--omega", default="0", help="turning rate, rad/s, counter-clockwise (default 0)")
    parser.add_argument("--current-angles", nargs="+", metavar="DEG", default=None,
                        help="the units' current steering angles in degrees, one per unit (default 0)")
    parser.add_argument("--json", action="store_true", help="print JSON instead of a table")


def _wrap(a):
    return (a + np.pi) % (2 * np.pi) - np.pi


def _nearest(robot, beta, current):
    """Per unit, beta or beta + pi (the rate reversed), whichever is nearer the current angle.

    For steered units that roll in their wheel plane (centred and dual wheels): both angles put the
    plane along the mount point's velocity.
    """
    turnable = np.array([u.steered and u.rolls_in_plane for u in robot.wheels])
    flip = turnable & (np.abs(_wrap(beta + np.pi - current)) < np.abs(_wrap(beta - current)))
    return _wrap(np.where(flip, beta + np.pi, beta))


def _slip(sol):
    return float(np.max(np.abs(sol.residual))) if sol.residual.size else 0.0


def run(args: argparse.Namespace) -> int:
    """Run ``wmr ik``.

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
    twist = np.array([number(args.omega, "--omega"), number(args.vx, "--vx"), number(args.vy, "--vy")])
    current = np.zeros(robot.w) if args.current_angles is None else np.radians(
        numbers(args.current_angles, "--current-angles", robot.w, "one angle in degrees per wheel unit"))
    current = robot.effective_beta(current)                   # fixed and Swedish wheels: their own angle
    beta = wmr.steering_angles(robot, twist, current)
    if args.current_angles is not None:
        beta = _nearest(robot, beta, current)
    sol = wmr.inverse(robot, beta, twist)
    now = wmr.inverse(robot, current, twist)
    change = _wrap(beta - current)
    out = {"twist": {"omega": twist[0], "vx": twist[1], "vy": twist[2]}, "angles_deg": np.degrees(beta).tolist(),
           "rates": dict(zip(robot.rate_names, sol.value.tolist())), "admissible": bool(sol.admissible),
           "slip": _slip(sol), "current_deg": np.degrees(current).tolist(), "resteer_deg": np.degrees(change).tolist(),
           "admissible_without_resteering": bool(now.admissible), "slip_without_resteering": _slip(now)}
    if args.json:
        print(json.dumps(out, indent=2))
        return 0
    print(f"twist: omega = {fmt(twist[0])} rad/s, vx = {fmt(twist[1])} m/s, vy = {fmt(twist[2])} m/s (body frame)")
    rows = [("wheel", "type", "angle_deg", "resteer_deg", "rates (rad/s)")]
    shown = clean(sol.value, float(np.abs(sol.value).max(initial=0.0)))           # rounding noise shown as 0
    for k, (u, sl) in enumerate(zip(robot.wheels, robot.rate_slices)):
        rates = ", ".join(f"{n} = {fmt(v)}" for n, v in zip(robot.rate_names[sl], shown[sl]))
        rows.append((str(k + 1), u.kind, fmt(math.degrees(beta[k]), 5), fmt(math.degrees(change[k]), 5), rates))
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    for r in rows:
        print("  ".join(c.ljust(wd) for c, wd in zip(r[:4], widths)) + "  " + r[4])
    # rounding noise shown as 0, next to the size of the wheel velocities J2 theta_dot (m/s)
    slip = clean(out["slip"], float(np.abs(robot.J2(beta) @ sol.value).max(initial=0.0)))
    slip_now = clean(out["slip_without_resteering"], float(np.abs(robot.J2(current) @ now.value).max(initial=0.0)))
    print(f"admissible: {'yes' if sol.admissible else 'no'} at these angles (largest slip residual {fmt(slip, 3)})")
    print(f"without re-steering: {'yes' if now.admissible else 'no'} at the current angles "
          f"({', '.join(fmt(a, 5) for a in out['current_deg'])}) deg (largest slip residual {fmt(slip_now, 3)})")
    return 0
