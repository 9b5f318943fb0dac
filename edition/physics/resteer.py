r"""Swerve re-steering: wmr's rate-limited simulator against MuJoCo, strategy by strategy (experiment 7).

Chapter 8 compares ways of commanding the modules of a swerve drive through a change of direction
(:func:`wmr.swerve.resteer_study`): each period the modules turn towards their targets at most at the
steering rate, the wheels roll at the commanded speeds and the platform moves with the least-squares
twist of (21), whose residual is the slip.  Here the same commands -- each module's angle, ramped over
the period as the rate limit turns it, and its wheel speed -- drive the swerve in MuJoCo, already moving
at the first command (one second of lead-in); its slip (the wheels' contact velocities, stacked as the
residual of (21)) and the distance of C from the commanded path are measured the same way.

The kinematic simulator assumes, as the paper does (Section 2), that friction is large enough to
prevent slipping: the platform takes the least-squares twist at once.  A real platform needs a force to
change its velocity, and its wheels can give at most :math:`\mu N`.
"""

from __future__ import annotations

import functools

import numpy as np

from wmr import swerve
from wmr.sim import Schedule, Simulation, run

from ..design_study import swerve as swerve_robot
from .common import SIZE, Outcome, fmt, parameters, pct, relative_pose, run_problems, sig, verdict

__all__ = ["PROFILE", "replay", "resteer_experiment"]

#: the profile of chapter 8: 1 m/s along x, then along y, spinning at 0.5 rad/s; 20 ms periods; 360 deg/s steering
PROFILE = {"speed": 1.0, "spin": 0.5, "dt": 0.02}
STEER_RATE = 2 * np.pi


def replay(robot, transient, params=None, lead_in=1.0):
    r"""Drive ``robot`` in MuJoCo with the commands of one of wmr's transients; measure slip and path error.

    Parameters
    ----------
    robot : Robot
        The swerve (centred wheels).
    transient : wmr.swerve.Transient
    params : Params, optional
    lead_in : float
        Seconds at the first command before the profile starts.

    Returns
    -------
    dict
        ``t`` (N,), ``pose`` (N, 3) seen from the start, ``slip`` (N,) m/s, ``path_error`` (N,) m,
        ``slip_distance`` m, ``final_path_error`` m.
    """
    r = np.array([float(u.r) for u in robot.wheels])
    n, dt = len(transient.speed), float(transient.t[1] - transient.t[0])
    t = transient.t
    knots = np.repeat(t[:-1], 2)
    knots[1::2] += dt * (1 - 1e-6)  # speeds held over each period
    beta = np.stack([np.interp(knots, t, transient.beta[:, i]) for i in range(robot.w)], axis=-1)  # turning over it
    s = Schedule(knots, beta, np.repeat(transient.speed / r, 2, axis=0))
    sim = Simulation(robot, beta=transient.beta[0], params=params)
    run(sim, Schedule.constant(transient.beta[0], transient.speed[0] / r), lead_in, every=10)
    rec = run(sim, s, n * dt, every=5)
    pose = relative_pose(rec.pose, rec.pose[0])
    tt = rec.t - rec.t[0]
    ref = np.stack([np.interp(tt, t, transient.reference[:, j]) for j in range(3)], axis=-1)
    err = np.hypot(*(pose[:, 1:] - ref[:, 1:]).T)
    slip = np.linalg.norm(rec.slip.reshape(len(tt), -1), axis=1)
    area = float(np.sum((slip[1:] + slip[:-1]) * np.diff(tt)) / 2)
    return {
        "t": tt,
        "pose": pose,
        "slip": slip,
        "path_error": err,
        "slip_distance": area,
        "final_path_error": float(err[-1]),
        "validity": rec.validity,
    }


@functools.lru_cache(maxsize=4)
def _study(r):
    """The swerve and wmr's re-steering study of it: no physical parameter enters, so it is computed once per size."""
    robot = swerve_robot(0.6, 0.4, r=r)
    return robot, swerve.resteer_study(robot, swerve.direction_change(**PROFILE), steer_rate=STEER_RATE)


def _best(values):
    """The labels with the least value (ties at the rounded value)."""
    low = min(values.values())
    return sorted(k for k, v in values.items() if v == low)


def resteer_experiment(params=None):
    r"""Experiment 7: chapter 8's re-steering study, wmr's simulator against MuJoCo, for every strategy.

    Criterion: the largest relative difference, over the strategies, of the slip distance and the final
    path error: at most :data:`~edition.physics.common.RESOLVED` (2 %) holds, at most 25 % holds within it.

    Parameters
    ----------
    params : Params, optional

    Returns
    -------
    Outcome
    """
    from .common import RESOLVED

    robot, study = _study(SIZE["r"])
    rows = {}
    for tr in study.runs:
        m = replay(robot, tr, params)
        rows[tr.label] = {
            "wmr": (sig(tr.slip_distance), sig(tr.final_path_error)),
            "mujoco": (sig(m["slip_distance"]), sig(m["final_path_error"])),
            "run": m,
            "transient": tr,
        }
    err = max(abs(v["mujoco"][k] / v["wmr"][k] - 1) for v in rows.values() for k in (0, 1))
    best = {
        who: {
            "slip": _best({s: v[who][0] for s, v in rows.items()}),
            "path": _best({s: v[who][1] for s, v in rows.items()}),
        }
        for who in ("wmr", "mujoco")
    }
    same = {k: bool(set(best["wmr"][k]) & set(best["mujoco"][k])) for k in ("slip", "path")}

    def listing(who):
        return "; ".join(f"{s}: slip {fmt(v[who][0])} m, path error {fmt(v[who][1])} m" for s, v in rows.items())

    def names(x):
        return " = ".join(x)

    return Outcome(
        "resteer",
        "swerve re-steering transients",
        "Chapter 8, its kinematic transient simulator",
        "wmr's rate-limited kinematic simulator predicts, strategy by strategy, how far a swerve's wheels slide and "
        "how far C strays when the modules re-steer",
        f"wmr.swerve.resteer_study: {listing('wmr')}",
        f"MuJoCo, same commands: {listing('mujoco')}",
        f"largest difference {pct(sig(err))}; least slip: wmr {names(best['wmr']['slip'])}, MuJoCo "
        f"{names(best['mujoco']['slip'])} ({'the same' if same['slip'] else 'not the same'}); least path error: wmr "
        f"{names(best['wmr']['path'])}, MuJoCo {names(best['mujoco']['path'])} "
        f"({'the same' if same['path'] else 'not the same'})",
        verdict(err, RESOLVED, 0.25),
        f"<= {pct(RESOLVED)}: holds; <= 25 %: holds within it",
        parameters(
            robot,
            params,
            profile=f"{fmt(PROFILE['speed'])} m/s along x then along y, spin "
            f"{PROFILE['spin']:g} rad/s, {PROFILE['dt'] * 1000:g} ms periods",
            steering=f"{np.degrees(STEER_RATE):g} deg/s",
            lead_in="1 s at the first command",
        ),
        rests_on="two models of one robot: wmr's kinematic simulator (the least-squares twist of (21)) against "
        "MuJoCo's contacts, with the servo and friction parameters of the run; not a claim of the paper",
        overturn="a contact model or servo tuning under which the two simulators agree within 25 % (the box runs other "
        "contact parameters and actuator limits)",
        problems=sum((run_problems(s, v["run"]["validity"]) for s, v in rows.items()), ()),
        data={"rows": rows, "best": best, "same": same, "study": study},
    )
