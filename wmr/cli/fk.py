"""``wmr fk ROBOT.toml --angles DEG [DEG ...] --rates RATE [RATE ...]``: the platform twist from steering angles and
wheel rates.

Example::

    wmr fk examples/swerve4.toml --angles 0 0 0 0 --rates 10 10 10 10 --convention wpilib

``--angles`` in degrees, one per unit, in the convention of ``--convention`` (wmr: axle angles;
wpilib, ros: the direction of travel); ``--rates`` in rad/s in the order of
:attr:`wmr.Robot.rate_names` (``theta_dot_i`` for a centred wheel, ``phi_dot_i theta_dot_i`` for an
offset wheel, ``theta_dot_i1 theta_dot_i2`` for a dual wheel).  The twist is the least-squares
solution of (21) (:func:`wmr.forward`), printed as ``omega`` (rad/s), ``vx``, ``vy`` (m/s, body
frame).  The slip residual :math:`\\mathbf J_1\\mathbf t - \\mathbf J_2\\dot{\\boldsymbol\\theta}` is the
velocity each wheel would slide at; measured rates never make it exactly zero, so a wheel counts as
not slipping when its slip speed is at most ``--slip-tolerance`` (m/s).  Its default is one count of
the encoder per control period at the largest wheel's rim, :math:`r\\,2\\pi/(N\\,T)` with ``N`` =
``--encoder-counts`` (default 2048 per revolution) and ``T`` = ``--period`` (default 0.02 s): about
7.8 mm/s for a 4-inch swerve wheel.  ``--slip-tolerance 0`` asks for exactly compatible rates.
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from . import ENCODER_COUNTS, PERIOD
from ._numbers import clean, fmt, json_text, number, numbers, twist_words

__all__ = ["run"]


def default_slip_tolerance(robot, counts: float = ENCODER_COUNTS, period: float = PERIOD) -> float:
    """One encoder count per control period at the largest wheel's rim: ``r 2 pi / (counts period)`` (m/s)."""
    return max(float(u.r) for u in robot.wheels) * 2 * math.pi / (counts * period)


def run(args: argparse.Namespace) -> int:
    """Run ``wmr fk``.

    Parameters
    ----------
    args : argparse.Namespace
        The options of ``wmr fk`` (:func:`wmr.cli.main` parses them).

    Returns
    -------
    int
        0; bad input raises an input error (:mod:`wmr.errors`; :func:`wmr.cli.main` reports it in one line, status 2).
    """
    import wmr

    from ..errors import InputValueError
    from ..model.conventions import angle_from

    robot = wmr.load(args.robot)
    given = np.radians(numbers(args.angles, "--angles", robot.w, "one angle in degrees per wheel unit"))
    beta = angle_from(given, args.convention)
    rates = np.array(numbers(args.rates, "--rates", robot.n_rates, " ".join(robot.rate_names)))
    counts, period = number(args.encoder_counts, "--encoder-counts"), number(args.period, "--period")
    if counts <= 0 or period <= 0:
        raise InputValueError(
            f"--encoder-counts and --period must be positive, got {args.encoder_counts!r} and {args.period!r}"
        )
    if args.slip_tolerance is None:
        tol, why = (
            default_slip_tolerance(robot, counts, period),
            (f"one count of a {counts:g}-count encoder per {period:g} s at the wheel rim"),
        )
    else:
        tol, why = number(args.slip_tolerance, "--slip-tolerance"), "--slip-tolerance"
        if tol < 0:
            raise InputValueError(f"--slip-tolerance must be >= 0 (m/s), got {args.slip_tolerance!r}")
    sol = wmr.forward(robot, beta, rates, slip_tolerance=tol if tol > 0 else None)
    size = float(np.abs(robot.mount_points).max())
    t = clean(sol.value, max(abs(sol.value[0]) * size, *np.abs(sol.value[1:])))  # rounding noise shown as 0
    res = clean(sol.residual, float(np.abs(robot.J2(beta) @ rates).max()))
    per_wheel = np.hypot(sol.residual[0::2], sol.residual[1::2])
    out = {
        **twist_words(t, args.convention),
        "convention": args.convention,
        "admissible": bool(sol.admissible),
        "slip": float(np.linalg.norm(sol.residual)),
        "slip_max_wheel": float(per_wheel.max()),
        "slip_tolerance": tol,
        "residual": sol.residual.tolist(),
    }
    if args.json:
        twist_scale = max(abs(float(t[0])) * size, *np.abs(t[1:]))  # m/s
        rate_scale = float(np.abs(robot.J2(beta) @ rates).max())  # m/s: the wheels' speeds
        slips = dict.fromkeys(("slip", "slip_max_wheel", "residual"), rate_scale)
        print(json_text(out, scales={**dict.fromkeys(twist_words(t, args.convention), twist_scale), **slips}))
        return 0
    units = {"omega": "rad/s", "vx": "m/s", "vy": "m/s"}
    rows = [(k, f"{fmt(out[k])} {units[k]}") for k in twist_words(t, args.convention)]
    rows += [
        (
            "slip",
            f"{fmt(float(np.linalg.norm(res)), 3)} m/s (norm of J1 t - J2 theta_dot); largest wheel "
            f"{fmt(float(per_wheel.max()), 3)} m/s",
        ),
        ("tolerance", f"{fmt(tol, 3)} m/s ({why})"),
        (
            "admissible",
            "yes: no wheel slips more than the tolerance" if sol.admissible else "no: the wheels would slip",
        ),
    ]
    for k, _ in enumerate(robot.wheels):
        rows.append((f"residual {k + 1}", f"({fmt(res[2 * k], 3)}, {fmt(res[2 * k + 1], 3)}) m/s"))
    width = max(len(k) for k, _ in rows)
    print("\n".join(f"{k:<{width}}  {v}" for k, v in rows))
    return 0
