r"""Steering with the drives locked: the dead zone (experiment 1) and jamming (experiment 2).

With :math:`\dot\theta_i = 0` the no-slip equations of three offset wheels leave the twist and the
steering rates, six unknowns, in the six equations of the locked-drive system
:math:`\mathbf M(\boldsymbol\beta)\,[\mathbf t;\ \dot{\boldsymbol\phi}] = \mathbf 0` (the columns of
:math:`\mathbf F` without the drive rates, :func:`edition.checks.assembly.locked_system`).  Each locked
wheel pivots about its fixed contact point, so :math:`P_i` can only move across its arm; the platform
can move only if the arm lines are concurrent (a rotation about their common point) or parallel (a
translation), where :math:`\mathbf M` loses rank.  With every :math:`\beta_i` equal the arms stay parallel
and C runs around the dead-zone circle (28)-(29); at generic angles :math:`\mathbf M` is nonsingular: no
motion at all, and the steering servos can only stall.
"""

from __future__ import annotations

import numpy as np

from wmr.analysis.linalg import rank
from wmr.sim import Params, Schedule, Simulation, run

from ..checks.assembly.dead_zone import dead_zone
from ..checks.assembly.locked import locked_system
from .common import (
    FAILS,
    HOLDS,
    RESOLVED,
    SIZE,
    Outcome,
    fmt,
    paper,
    parameters,
    pct,
    run_problems,
    sig,
    verdict,
)

__all__ = [
    "GENERIC",
    "JAM_TURN",
    "circle_error",
    "dead_zone_experiment",
    "dead_zone_verdict",
    "jam_does",
    "jam_experiment",
    "jam_verdict",
    "turn_locked",
]

#: steering angles at which the arm lines of the paper's offset robot are neither concurrent nor parallel (deg)
GENERIC = (20.0, 75.0, 140.0)
#: one full turn of every steering servo takes this long (s)
TURN = 4.0
#: The largest part of the commanded turn a jammed robot makes (the jam's criterion; exercise 9.1 uses it too)
JAM_TURN = 0.02


def turn_locked(robot, beta0, seconds=TURN, params=None):
    """Steer every unit one full turn (at a constant rate) with every drive locked (:meth:`wmr.sim.Simulation.lock`).

    Parameters
    ----------
    robot : Robot
        Offset wheels.
    beta0 : array (w,)
        Initial steering angles.
    seconds : float
        Time of the turn; the run lasts a quarter second more.
    params : Params, optional

    Returns
    -------
    Recording
    """
    beta0 = np.asarray(beta0, dtype=float)
    s = Schedule(np.array([0.0, seconds]), np.array([beta0, beta0 + 2 * np.pi]), np.zeros((2, robot.n_rates)))
    sim = Simulation(robot, beta=beta0, params=params)
    sim.lock(sim.export.drive_names)
    return run(sim, s, seconds + 0.25)


def _circle(C):
    """Least-squares circle through points (N, 2): centre (2,), radius."""
    a, b, c = np.linalg.lstsq(np.c_[2 * C, np.ones(len(C))], (C**2).sum(1), rcond=None)[0]
    return np.array([a, b]), float(np.sqrt(c + a * a + b * b))


def circle_error(C, Cf, d):
    """How far a path of C is from the dead-zone circle of radius ``d`` about ``Cf`` (experiment 1's measurement).

    Parameters
    ----------
    C : array (N, 2)
        The path of C.
    Cf : array (2,)
        The centroid of the contact points at the start.
    d : float
        The offset.

    Returns
    -------
    tuple
        ``(error, centre, radius, distances)``: the largest of the deviations of ``|CC_f|`` from ``d`` and of the
        fitted circle's centre from ``Cf``, relative to ``d``; the fitted circle; ``|CC_f|`` along the path.
    """
    centre, radius = _circle(C)
    dist = np.linalg.norm(C - Cf, axis=1)
    err = max(abs(dist.max() - d), abs(dist.min() - d), float(np.linalg.norm(centre - Cf))) / d
    return err, centre, radius, dist


def dead_zone_verdict(error):
    """Experiment 1's criterion: the verdict from the relative error of :func:`circle_error`.

    Parameters
    ----------
    error : float

    Returns
    -------
    str
        At most :data:`~edition.physics.common.RESOLVED` holds, at most 10 % holds within it.
    """
    return verdict(error, RESOLVED, 0.10)


def jam_verdict(generic, equal):
    """Experiment 2's criterion, from the two runs' rounded measurements (``travel``, ``moved``, ``torque``).

    Parameters
    ----------
    generic, equal : dict
        ``travel`` (fraction of the commanded turn), ``moved`` (C's displacement over d), ``torque`` (largest
        steering torque over its limit).

    Returns
    -------
    str
        Holds when at the generic angles the turn is at most :data:`JAM_TURN`, C moves at most 10 % of d and the
        torque reaches 95 % of its limit, while with equal angles at least 98 % of the turn is made.
    """
    g, e = generic, equal
    jam = g["travel"] <= JAM_TURN and g["moved"] <= 0.10 and g["torque"] >= 0.95
    return HOLDS if jam and e["travel"] >= 0.98 else FAILS


def jam_does(strong):
    """What the robot with strong steering servos does: ``stalls``, ``scrubs`` or ``scrubs and drifts``.

    Parameters
    ----------
    strong : dict
        ``travel`` and ``moved`` as for :func:`jam_verdict`.

    Returns
    -------
    str
    """
    return "stalls" if strong["travel"] <= JAM_TURN else "scrubs" if strong["moved"] <= 0.10 else "scrubs and drifts"


def dead_zone_experiment(params=None):
    r"""Experiment 1: the dead zone (Fig. 7, (28)-(29)).

    Every offset wheel of the paper's robot (:math:`d = r`) is steered one full turn with the drives
    locked.  wmr's model: C runs once around a circle of radius :math:`d` about :math:`C_f`, the centroid
    of the (fixed) contact points.  MuJoCo: the path of C, the circle fitted to it, its centre against
    the centroid of the contact points measured at the start.

    Criterion: the largest of :math:`|\,|CC_f| - d\,|` and the distance from the fitted centre to
    :math:`C_f`, relative to :math:`d`: at most :data:`~edition.physics.common.RESOLVED` (2 %) holds, at
    most 10 % holds within that error.

    Parameters
    ----------
    params : Params, optional

    Returns
    -------
    Outcome
    """
    robot = paper("offset")
    d = SIZE["r"]
    beta0 = np.zeros(robot.w)
    model = dead_zone(robot, beta0=0.0)
    rec = turn_locked(robot, beta0, params=params)
    C = rec.pose[:, 1:]
    Cf = np.nanmean(rec.point[0, :, :2], axis=0)  # centroid of the contacts at the start
    err, centre, radius, dist = circle_error(C, Cf, d)
    drift = float(np.nanmax(np.linalg.norm(rec.point[:, :, :2] - rec.point[0, :, :2], axis=-1)))
    v = dead_zone_verdict(err)
    return Outcome(
        "dead-zone",
        "the dead zone",
        "4.2, Fig. 7, (28)-(29)",
        "steered one full turn with the drives locked, C traces a circle of radius d about the centroid C_f of the "
        "contact points, which stay fixed",
        f"wmr.integrate: a circle of radius {fmt(model['radius'], 3)} m about C_f (d = {fmt(d)} m); contact points "
        f"fixed, heading fixed",
        f"|CC_f| from {fmt(dist.min(), 3)} to {fmt(dist.max(), 3)} m; fitted circle radius {fmt(radius, 3)} m, centre "
        f"{fmt(np.linalg.norm(centre - Cf) * 1000)} mm from C_f; contact points moved {fmt(drift * 1000)} mm; heading "
        f"{fmt(np.degrees(np.ptp(rec.pose[:, 0])))} deg",
        f"largest deviation from the circle {pct(err)} of d",
        v,
        f"error <= {pct(RESOLVED)} of d: holds; <= 10 %: holds within it",
        parameters(robot, params, start="beta = 0 for all", turn=f"2 pi in {TURN:g} s, drives locked"),
        rests_on="the wheels rolling without slip while they are steered: MuJoCo's soft contacts (elliptic "
        "friction cone, the coefficients of the run) hold them, and the steering servos turn them",
        overturn="a contact that lets the wheels creep or slide while steered (lower friction, softer contacts, "
        "another friction cone): C's path would then leave the circle by more than 2 % of d (the box runs them)",
        quote="when all the wheels are steered one full turn without driving, point C will trace a circle whose "
        "radius equals the distance between point C and point C_f, the centroid of the triangle whose vertices are "
        "the points of contact between the wheels and the ground; C_f remains fixed during steering",
        problems=run_problems("turn", rec),
        data={
            "C": C,
            "Cf": Cf,
            "centre": centre,
            "radius": radius,
            "model": model,
            "d": d,
            "t": rec.t,
            "points": rec.point[:, :, :2],
        },
    )


def jam_experiment(params=None, generic=GENERIC):
    r"""Experiment 2: steering with the drives locked at generic angles jams.

    wmr's model: :math:`\operatorname{rank}\mathbf M = 6` at the generic angles (no motion), 5 with all
    :math:`\beta_i` equal (the dead-zone motion).  MuJoCo: the same one-turn steering command at both;
    the steering travel, the motion of C and the steering torques.  The set-up's steering servos are weaker
    than the friction moment :math:`\mu N d` that dragging a wheel sideways about its pivot takes, so a
    stall is built in; a third run, at the generic angles with steering servos three times :math:`\mu N d`,
    says what a robot that can overcome friction does: it **stalls**, **scrubs** (the wheels turn, sliding,
    and C stays within 10 % of d) or **scrubs and drifts** (C moves further).

    Criterion: holds when, at the generic angles, the steering turns by at most 2 % of the commanded turn,
    C moves by at most 10 % of :math:`d` and the steering torque reaches 95 % of its limit, while with equal
    angles the steering completes at least 98 % of the turn.

    Parameters
    ----------
    params : Params, optional
    generic : triple of float
        The generic steering angles, degrees.

    Returns
    -------
    Outcome
    """
    robot = paper("offset")
    d = SIZE["r"]
    p = params or Params()
    scrub = p.sliding * d / 3 / SIZE["r"]  # mu N d in units of W r, N = W / 3 on each of three wheels
    cols = [c for c, name in enumerate(robot.qdot_names) if not name.startswith("theta_dot")]
    scale = robot.F_column_norms[cols]
    out, problems = {}, ()
    runs = [("generic", np.radians(generic), p), ("equal", np.zeros(robot.w), p)]
    runs.append(("strong", np.radians(generic), p.replace(steer_torque=3 * scrub)))
    for name, beta0, q in runs:
        rec = turn_locked(robot, beta0, params=q)
        steer = [k for k, n in enumerate(rec.export.servo_names) if n.endswith("steer")]
        limit = q.steer_torque * rec.export.weight * SIZE["r"]
        stalls = [n for n in rec.export.servo_names if n.endswith("steer")] if name != "equal" else []
        problems += run_problems(name, rec, saturating=stalls)
        out[name] = {
            "rank": int(rank(locked_system(robot, beta0), scale=scale)),
            "travel": sig(np.abs(rec.beta[-1] - rec.beta[0]).max() / (2 * np.pi)),
            "moved": sig(np.linalg.norm(rec.pose[-1, 1:] - rec.pose[0, 1:]) / d),
            "torque": sig(np.abs(rec.torque[:, steer]).max() / limit),
            "slid": sig(np.sum(rec.slip_speed[1:] * np.diff(rec.t)[:, None], axis=0).max() / d),
            "rec": rec,
        }
    g, e, s = out["generic"], out["equal"], out["strong"]
    v = jam_verdict(g, e)
    s["does"] = jam_does(s)
    angles = ", ".join(f"{a:g}" for a in generic)
    return Outcome(
        "jam",
        "jamming with the drives locked",
        "Chapter 2, in place of the drift claim of Section 4.2",
        "with the drives locked at generic angles (arm lines neither concurrent nor parallel) three offset wheels "
        "cannot be steered: the robot jams (this edition's own result, not a claim of the paper)",
        f"rank M = {g['rank']} at beta = ({angles}) deg: no motion; rank M = {e['rank']} with all beta equal: the "
        "dead-zone motion",
        f"generic: steering turned {pct(g['travel'])} of the commanded turn, C moved {pct(g['moved'])} of d, steering "
        f"torque {pct(g['torque'])} of its limit; equal: steering turned {pct(e['travel'])}, torque "
        f"{pct(e['torque'])} of its limit; generic with steering servos of {fmt(3 * scrub)} W r (3 mu N d): it "
        f"{s['does']} (steering turned {pct(s['travel'])}, the wheels slid up to {fmt(s['slid'])} d, C moved "
        f"{pct(s['moved'])} of d)",
        f"generic angles stall at the torque limit ({pct(g['torque'])}) with {pct(g['travel'])} of the turn made; "
        f"servos stronger than mu N d: the platform {s['does']}",
        v,
        f"generic: turn <= {pct(JAM_TURN)}, C moved <= 10 % of d, torque >= 95 % of the limit; equal: turn >= 98 %",
        parameters(robot, params, turn=f"2 pi in {TURN:g} s, drives locked", generic=f"beta = ({angles}) deg"),
        rests_on=f"the steering servos' torque limit, {p.steer_torque:g} W r, below the friction moment "
        f"mu N d = {fmt(scrub, 2)} W r that dragging a wheel sideways about its pivot needs (mu = {p.sliding:g}, "
        f"N = W/3, d = r): a stall is built into the set-up; with servos of 3 mu N d the platform {s['does']}",
        overturn="steering servos stronger than mu N d (run: see the measurement): the wheels then scrub sideways "
        "and the robot does not jam; the kinematic jam (rank M = 6, Chapter 2) is proven and does not depend on it",
        problems=problems,
        data={k: {kk: vv for kk, vv in val.items()} for k, val in out.items()} | {"d": d, "limit": p.steer_torque},
    )
