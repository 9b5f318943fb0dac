"""``wmr simulate ROBOT.toml --vx VX --vy VY --omega W --seconds T``: the robot in MuJoCo, driven by wmr's kinematics.

Example::

    wmr simulate examples/differential.toml --vx 0.5 --omega 1 --mjcf differential.xml --json

The robot is exported with :func:`wmr.sim.to_mjcf` (default parameters, :mod:`wmr.sim.params`;
``--param name=value`` changes one) and its servos follow the joint commands of the constant body
twist (:func:`wmr.sim.twist_schedule`: wmr's inverse kinematics along the model's run).  Printed:
the commanded twist; the simulated one (mean over the second half of the run); the twist wmr's
forward kinematics recovers from the simulated encoders and its slip residual; the mean slip
speed of the wheels at their contacts; the largest servo torque as a fraction of its limit; and
**warnings**: a twist that is not admissible at the start angles (the wheels must slip), a robot
that does not stand on its contacts (the platform tilts more than :data:`TILT` degrees or a wheel
is off the ground for most of the run's second half), and every validity problem of the run
(:mod:`wmr.sim.validity`: a saturated or chattering servo, energy from nowhere, a wheel sinking
into the ground).  Needs MuJoCo (``pip install 'wmr-kinematics[sim]'``).  Swedish wheels are refused (exit status 2).

``--json`` writes the inputs by the rule of :mod:`wmr.io.decimals` (12 digits) and MuJoCo's
measurements with :data:`SIM_DIGITS` significant digits at the scale of the commanded speed (m/s;
the final pose and the servo load at the scale 1): moving every input of the model by one ulp
moves them by about 2e-15 of their scale (another CPU's MuJoCo by more), nine orders of magnitude
below a rounding boundary at six digits.  A run at the onset of sliding is chaotic: no number of
digits makes its text the same everywhere.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..errors import InputValueError
from ..io.decimals import length_scale, quantise_all
from ._numbers import fmt, json_text, number

#: significant digits of MuJoCo's measurements in ``--json`` (module notes)
SIM_DIGITS = 6
#: the platform's largest tilt, degrees, for a robot that stands on its contacts
TILT = 10.0

if TYPE_CHECKING:
    import argparse

__all__ = ["run"]


def _params(items):
    from ..sim import Params

    out: dict[str, float | str] = {}
    for item in items:
        name, eq, value = str(item).partition("=")
        if not eq or name not in Params.__dataclass_fields__:
            raise InputValueError(
                f"--param must be NAME=VALUE with NAME one of {sorted(Params.__dataclass_fields__)}, got {item!r}"
            )
        text = isinstance(getattr(Params(), name), str)  # the integrator and the friction cone are names
        out[name] = value if text else number(value, f"--param {name}")
    return Params().replace(**out)


def run_warnings(robot, beta0, twist, sim, rec) -> list[str]:
    """What makes a run of ``wmr simulate`` doubtful, in words (module docstring).

    ``beta0`` (w,) the start angles, ``twist`` (3,) the commanded twist, ``sim`` at the end of the run ``rec``.
    """
    from ..analysis.kinematics import inverse

    out = []
    sol = inverse(robot, beta0, twist)
    if not bool(np.all(sol.admissible)):
        out.append(
            f"the twist is not admissible at the start angles: the wheels must slip (wmr.inverse leaves a residual "
            f"of {fmt(float(np.linalg.norm(sol.residual)), 3)})"
        )
    w, x, y, z = sim.data.qpos[3:7]
    tilt = float(np.degrees(np.arccos(np.clip(1 - 2 * (x * x + y * y), -1.0, 1.0))))
    off = bool((np.isnan(rec.point[len(rec.t) // 2 :, :, 0]).mean(axis=0) > 0.5).any())  # off most of the time
    if tilt > TILT or off:
        out.append(
            f"the robot does not stand on its contacts: the platform tilted {fmt(tilt, 2)} deg"
            + (" and a wheel is off the ground" if off else "")
        )
    out += [f"the run is not valid: {p}" for p in rec.validity.problems()] if rec.validity is not None else []
    return out


def run(args: argparse.Namespace) -> int:
    """Run ``wmr simulate``.

    Parameters
    ----------
    args : argparse.Namespace
        The options of ``wmr simulate`` (:func:`wmr.cli.main` parses them).

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
    speed = float(max(abs(twist[0]) * length_scale(robot), *np.abs(twist[1:]))) or 1.0  # m/s

    def measured(x, scale):  # MuJoCo's numbers at SIM_DIGITS (the module notes say why)
        return quantise_all(x, scale, SIM_DIGITS)

    out = {
        "commanded": dict(zip(("omega", "vx", "vy"), twist.tolist())),
        "simulated": measured(dict(zip(("omega", "vx", "vy"), rec.twist[late].mean(axis=0).tolist())), speed),
        "forward_from_encoders": measured(dict(zip(("omega", "vx", "vy"), fk[late].mean(axis=0).tolist())), speed),
        "encoder_slip_residual": measured(float(residual[late].mean()), speed),
        "contact_slip_speed": measured(float(rec.slip_speed[late].mean()), speed),
        "final_pose": measured(dict(zip(("psi", "X", "Y"), rec.pose[-1].tolist())), 1.0),
        "servo_load": measured(load, 1.0),
        "warnings": run_warnings(robot, beta0, twist, s, rec),
        "seconds": seconds,
        "mjcf": args.mjcf,
    }
    if args.json:
        print(json_text(out, scale=None))  # the inputs at 12 digits; the measurements are on their coarser grid
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
    rows += [("warning", w) for w in out["warnings"]]
    width = max(len(k) for k, _ in rows)
    print("\n".join(f"{k:<{width}}  {v}" for k, v in rows))
    return 0
