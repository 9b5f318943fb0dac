"""``wmr simulate ROBOT.toml --vx VX --vy VY --omega W --seconds T``: the robot in MuJoCo, driven by wmr's kinematics.

Examples::

    wmr simulate examples/swerve4.toml --vx 1.0 --vy 0.3 --omega 0.5 --seconds 3
    wmr simulate examples/differential.toml --vx 0.5 --omega 1 --mjcf differential.xml --json
    wmr simulate examples/tricycle.toml --mjcf tricycle.xml --seconds 0        # only write the model

The robot is exported with :func:`wmr.sim.to_mjcf` (default parameters, :mod:`wmr.sim.params`;
``--param name=value`` changes one) and its servos follow the joint commands of the constant body
twist (:func:`wmr.sim.twist_schedule`: wmr's inverse kinematics along the model's run).  Printed:
the commanded twist; the simulated one (mean over the second half of the run); the twist wmr's
forward kinematics recovers from the simulated encoders and its slip residual; the mean slip
speed of the wheels at their contacts; the largest servo torque as a fraction of its limit.
Needs MuJoCo (``pip install 'wmr-kinematics[sim]'``).  Swedish wheels are refused (exit status 2).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..errors import InputValueError
from ._numbers import fmt, number
from ._options import ROBOT_FILE

if TYPE_CHECKING:
    import argparse

__all__ = ["HELP", "add_arguments", "run"]

HELP = "the robot in MuJoCo following a commanded twist (needs mujoco); --mjcf writes the model"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Options of ``wmr simulate``.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The sub-command's parser.

    Returns
    -------
    None
    """
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


def _params(items):
    from ..sim import Params

    out = {}
    for item in items:
        name, eq, value = str(item).partition("=")
        if not eq or name not in Params.__dataclass_fields__:
            raise InputValueError(
                f"--param must be NAME=VALUE with NAME one of {sorted(Params.__dataclass_fields__)}, got {item!r}"
            )
        out[name] = number(value, f"--param {name}")
    return Params(**out)


def run(args: argparse.Namespace) -> int:
    """Run ``wmr simulate``.

    Parameters
    ----------
    args : argparse.Namespace

    Returns
    -------
    int
        0; bad input raises a :class:`~wmr.errors.InputError` (:func:`wmr.cli.main` reports it in one line,
        status 2), a robot wmr.sim cannot export (a Swedish wheel) too.
    """
    import wmr

    from .. import sim

    robot = wmr.load(args.robot)
    twist = np.array([number(args.omega, "--omega"), number(args.vx, "--vx"), number(args.vy, "--vy")])
    seconds = number(args.seconds, "--seconds")
    if seconds < 0:
        raise InputValueError(f"--seconds must be >= 0, got {args.seconds!r}")
    params = _params(args.param)
    try:
        beta0 = sim.start_angles(robot, twist)
        ex = sim.export(robot, beta0, params=params)
    except NotImplementedError as e:
        raise InputValueError(f"cannot export {args.robot}: {e}") from None
    if args.mjcf:
        Path(args.mjcf).write_text(ex.xml, encoding="utf-8")
    if seconds == 0:
        if not args.json:
            print(f"wrote {args.mjcf}" if args.mjcf else "nothing to do (--seconds 0 and no --mjcf)")
        return 0
    try:
        s = sim.Simulation(ex)
    except ImportError as e:
        raise OSError(str(e)) from None
    rec = sim.run(s, sim.twist_schedule(robot, twist, seconds, beta0), seconds)
    late = rec.t >= seconds / 2
    fk, residual = rec.kinematic_slip()
    limits = np.abs(s.model.actuator_forcerange[:, 1]) if s.model.nu else np.ones(0)
    load = float((np.abs(rec.torque[late]) / limits).max()) if s.model.nu else 0.0
    out = {
        "commanded": dict(zip(("omega", "vx", "vy"), twist.tolist())),
        "simulated": dict(zip(("omega", "vx", "vy"), rec.twist[late].mean(axis=0).tolist())),
        "forward_from_encoders": dict(zip(("omega", "vx", "vy"), fk[late].mean(axis=0).tolist())),
        "encoder_slip_residual": float(residual[late].mean()),
        "contact_slip_speed": float(rec.slip_speed[late].mean()),
        "final_pose": dict(zip(("psi", "X", "Y"), rec.pose[-1].tolist())),
        "servo_load": load,
        "seconds": seconds,
        "mjcf": args.mjcf,
    }
    if args.json:
        print(json.dumps(out, indent=2))
        return 0

    def tw(d):
        return f"omega = {fmt(d['omega'], 4)} rad/s, vx = {fmt(d['vx'], 4)} m/s, vy = {fmt(d['vy'], 4)} m/s"

    rows = [
        ("commanded", tw(out["commanded"])),
        ("simulated", tw(out["simulated"]) + f" (mean over t >= {fmt(seconds / 2)} s)"),
        ("from encoders", tw(out["forward_from_encoders"]) + " (wmr.forward)"),
        ("slip residual", f"{fmt(out['encoder_slip_residual'], 3)} m/s (encoders, J1 t - J2 theta_dot)"),
        ("contact slip", f"{fmt(out['contact_slip_speed'], 3)} m/s (mean slip speed of the wheels)"),
        (
            "final pose",
            f"psi = {fmt(rec.pose[-1, 0], 4)} rad, X = {fmt(rec.pose[-1, 1], 4)} m, Y = {fmt(rec.pose[-1, 2], 4)} m",
        ),
        ("servo load", f"{fmt(100 * load, 3)} % of the torque limit at most"),
    ]
    if args.mjcf:
        rows.append(("model", args.mjcf))
    width = max(len(k) for k, _ in rows)
    print("\n".join(f"{k:<{width}}  {v}" for k, v in rows))
    return 0
