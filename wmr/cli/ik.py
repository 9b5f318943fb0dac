"""``wmr ik ROBOT.toml --vx VX --vy VY --omega W``: steering angles and wheel rates for a commanded twist.

Example::

    wmr ik examples/swerve4.toml --vx 1 --omega 0.8 --convention wpilib --json

The twist is body-frame: ``--vx``, ``--vy`` (m/s, the velocity of C), ``--omega`` (rad/s,
counter-clockwise).  The steering angles are :func:`wmr.steering_angles`; a centred or dual unit
takes :math:`\\beta` or :math:`\\beta+\\pi`, whichever is nearer its current angle (rolling backwards
in the second case), and a unit whose choice is free (an offset wheel, a wheel at the centre of
rotation) keeps its current angle.  The current angles are ``--current-angles`` (degrees, one per
unit, in the convention chosen), by default 0 for every unit: giving ``--current-angles 0 0 ...``
changes nothing.  Angles are in the convention of ``--convention`` (wmr: axle angles; wpilib, ros:
the direction of travel, 90 degrees less), in and out; the entries of fixed and Swedish wheels are
ignored (they keep their own angle).  The rates are :func:`wmr.inverse` at those angles, in the order
of :attr:`wmr.Robot.rate_names` (rad/s).

The twist is **admissible** when no wheel slips at those angles and the motors command it: a motion
that the passive joints (rollers, castors) would make by themselves with every motor stopped is
not (:mod:`wmr.analysis.actuation`).  It is admissible *without re-steering* when that holds at the
current angles.
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from ._numbers import clean, fmt, json_text, number, numbers, twist_words

__all__ = ["run"]


def _nearest(robot, beta, current):
    """Per unit, beta or beta + pi (the rate reversed), whichever is nearer the current angle.

    For steered units that roll in their wheel plane (centred and dual wheels): both angles put the
    plane along the mount point's velocity.
    """
    from ..model.platform import wrap_angle

    turnable = np.array([u.steered and u.rolls_in_plane for u in robot.wheels])
    flip = turnable & (np.abs(wrap_angle(beta + np.pi - current)) < np.abs(wrap_angle(beta - current)))
    return wrap_angle(np.where(flip, beta + np.pi, beta))


def _slip(sol):
    return float(np.max(np.abs(sol.residual))) if sol.residual.size else 0.0


def _verdict(robot, sol, part):
    from ..words.limitations import describe_twist

    if sol.admissible:
        return "yes"
    if not sol.no_slip:
        return "no: the wheels would slip"
    return (
        f"no: the motors do not command it (moving {describe_twist(robot, part)} needs the passive joints "
        "to move by themselves)"
    )


def run(args: argparse.Namespace) -> int:
    """Run ``wmr ik``.

    Parameters
    ----------
    args : argparse.Namespace
        The options of ``wmr ik`` (:func:`wmr.cli.main` parses them).

    Returns
    -------
    int
        0; bad input raises an input error (:mod:`wmr.errors`; :func:`wmr.cli.main` reports it in one line, status 2).
    """
    import wmr

    from ..analysis.actuation import uncontrolled
    from ..io.decimals import DEGREES, length_scale
    from ..model.conventions import angle_from, angle_to
    from ..model.platform import wrap_angle

    conv = args.convention
    robot = wmr.load(args.robot)
    twist = np.array([number(args.omega, "--omega"), number(args.vx, "--vx"), number(args.vy, "--vy")])
    given = (
        np.zeros(robot.w)
        if args.current_angles is None
        else np.radians(
            numbers(args.current_angles, "--current-angles", robot.w, "one angle in degrees per wheel unit")
        )
    )
    current = robot.effective_beta(angle_from(given, conv))  # fixed and Swedish wheels: their own angle
    beta = _nearest(robot, wmr.steering_angles(robot, twist, current), current)
    sol = wmr.inverse(robot, beta, twist)
    now = wmr.inverse(robot, current, twist)
    part, _ = uncontrolled(robot, beta, twist)
    part_now, _ = uncontrolled(robot, current, twist)
    change = wrap_angle(beta - current)
    shown_beta, shown_current = np.degrees(angle_to(beta, conv)), np.degrees(angle_to(current, conv))
    out = {
        "convention": conv,
        "twist": twist_words(twist, conv),
        "angles_deg": shown_beta.tolist(),
        "rates": dict(zip(robot.rate_names, sol.value.tolist())),
        "admissible": bool(sol.admissible),
        "no_slip": bool(sol.no_slip),
        "actuated": bool(sol.actuated),
        "slip": _slip(sol),
        "uncommanded_twist": twist_words(part, conv),
        "current_deg": shown_current.tolist(),
        "resteer_deg": np.degrees(change).tolist(),
        "admissible_without_resteering": bool(now.admissible),
        "slip_without_resteering": _slip(now),
    }
    if args.json:
        speed = float(max(abs(twist[0]) * length_scale(robot), *np.abs(twist[1:])))  # m/s
        rate = float(np.abs(sol.value).max(initial=0.0))  # rad/s
        scales = dict.fromkeys(("twist", "slip", "uncommanded_twist", "slip_without_resteering"), speed)
        scales.update(dict.fromkeys(("angles_deg", "current_deg", "resteer_deg"), DEGREES), rates=rate)
        print(json_text(out, scales=scales))
        return 0
    unit = {"m/s": ("vx", "vy"), "rad/s": ("omega",)}
    print(
        "twist: "
        + ", ".join(f"{k} = {fmt(v)} {'rad/s' if k in unit['rad/s'] else 'm/s'}" for k, v in out["twist"].items())
        + " (body frame: x forward, y left)"
    )
    head = "axle_deg" if conv == "wmr" else "heading_deg"
    rows = [("wheel", "type", head, "resteer_deg", "rates (rad/s)")]
    shown = clean(sol.value, float(np.abs(sol.value).max(initial=0.0)))  # rounding noise shown as 0
    for k, (u, sl) in enumerate(zip(robot.wheels, robot.rate_slices)):
        rates = ", ".join(f"{n} = {fmt(v)}" for n, v in zip(robot.rate_names[sl], shown[sl]))
        rows.append((str(k + 1), u.kind, fmt(shown_beta[k], 5), fmt(math.degrees(change[k]), 5), rates))
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    for r in rows:
        print("  ".join(c.ljust(wd) for c, wd in zip(r[:4], widths)) + "  " + r[4])
    # rounding noise shown as 0, next to the size of the wheel velocities J2 theta_dot (m/s)
    slip = clean(out["slip"], float(np.abs(robot.J2(beta) @ sol.value).max(initial=0.0)))
    slip_now = clean(out["slip_without_resteering"], float(np.abs(robot.J2(current) @ now.value).max(initial=0.0)))
    print(f"admissible: {_verdict(robot, sol, part)} at these angles (largest slip residual {fmt(slip, 3)} m/s)")
    print(
        f"without re-steering: {_verdict(robot, now, part_now)} at the current angles "
        f"({', '.join(fmt(a, 5) for a in out['current_deg'])}) deg (largest slip residual {fmt(slip_now, 3)} m/s)"
    )
    return 0
