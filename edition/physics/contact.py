r"""What the rank of :math:`\mathbf F` means at the contacts: incompatible steering (experiment 3), braking (4).

Three centred wheels have mobility 1 when their axle lines meet in one point (rank F = 5) and 0 when
they do not (rank F = 6, Section 5.2).  wmr's least-squares inverse kinematics then leaves a residual,
the slip the wheels would need (:func:`wmr.inverse`); in a physics engine the wheels must either slide
or push against each other.  The same rank decides what happens when a parked robot is pushed with its
drives free: it rolls away if a motion is admissible, and must be dragged sideways (friction) if none
is -- the "braking" configuration of Fig. 12a.

The force needed to move a rigid robot whose wheels resist sliding with Coulomb friction
:math:`\mu N_i` (across the wheel) and rolling with :math:`c_{rr}N_i` (along it) is, by the principle of
maximum dissipation, the smallest dissipation over the motions that move C in the push's direction:

.. math:: F(\mathbf u) = \min_{\mathbf t:\ \mathbf u\cdot\dot{\mathbf c} = 1}\ \sum_i N_i\big(
          \mu\,|\mathbf i_i^{\mathrm T}[\mathbf E\mathbf d_i\ \mathbf 1]\mathbf t|
          + c_{rr}\,|\mathbf j_i^{\mathrm T}[\mathbf E\mathbf d_i\ \mathbf 1]\mathbf t|\big),

a convex piecewise-linear function of the two free components of :math:`\mathbf t`, smallest at a
point where two of its terms vanish (:func:`weakest_push`): wmr's constraint rows, with friction added.
"""

from __future__ import annotations

import itertools

import numpy as np

import wmr
from wmr.model.platform import point_row
from wmr.sim import Export, Params, Schedule, Simulation, export, run

from ..text import bound
from .common import FAILS, HOLDS, Outcome, fmt, paper, parameters, pct, run_problems, sig, twist_text

__all__ = [
    "DIRECTIONS",
    "OFF",
    "TWIST",
    "brake_experiment",
    "brake_verdict",
    "breakaway",
    "steering_experiment",
    "weakest_push",
]

#: the commanded twist of experiment 3: a turn about a point ahead-left of C, (psi_dot, x_dot, y_dot)
TWIST = (0.5, 0.2, 0.0)
#: how far the incompatible steering is off the coordinated angles (deg)
OFF = (10.0, -10.0, 5.0)
#: directions of the pushes of experiment 4 (deg)
DIRECTIONS = tuple(range(0, 360, 30))


def _late(rec, after=1.0):
    return rec.t >= after


def steering_experiment(params=None, twist=TWIST, off=OFF, seconds=3.0):
    r"""Experiment 3: incompatible steering (rank F = 6) against coordinated steering (rank F = 5).

    Both runs command the twist ``twist`` by wmr's inverse kinematics (least squares where it is not
    admissible); the incompatible one with the steering angles moved by ``off``.  Measured over the
    last two seconds: the slip (norm of the wheels' contact velocities, stacked as the residual of (21)
    is), the "fight" (the horizontal contact forces that cancel each other, :math:`\sum_i\|\mathbf f_i\| -
    \|\sum_i\mathbf f_i\|`) and the platform twist.

    Criterion: holds when the coordinated slip is at most a tenth of the incompatible one and the
    incompatible fight at least three times the coordinated one.

    Parameters
    ----------
    params : Params, optional
    twist : triple
    off : triple
        Degrees.
    seconds : float

    Returns
    -------
    Outcome
    """
    robot = paper("centred")
    twist = np.asarray(twist, dtype=float)
    ok = wmr.steering_angles(robot, twist)
    out, problems = {}, ()
    for name, beta in (("coordinated", ok), ("incompatible", ok + np.radians(off))):
        sol = wmr.inverse(robot, beta, twist)
        rec = run(Simulation(robot, beta=beta, params=params), Schedule.constant(beta, sol.value), seconds)
        problems += run_problems(name, rec)
        late = _late(rec)
        f = rec.force[late][..., :2]
        fight = np.linalg.norm(f, axis=-1).sum(axis=1) - np.linalg.norm(f.sum(axis=1), axis=-1)
        out[name] = {
            "rank": int(wmr.rank_F(robot, beta)),
            "predicted_slip": float(np.linalg.norm(sol.residual)),
            "ls_twist": wmr.forward(robot, beta, sol.value).value,
            "slip": sig(np.linalg.norm(rec.slip[late].reshape(late.sum(), -1), axis=1).mean()),
            "fight": sig(fight.mean()),
            "twist": rec.twist[late].mean(axis=0),
            "rec": rec,
        }
    c, i = out["coordinated"], out["incompatible"]
    holds = c["slip"] <= 0.1 * i["slip"] and i["fight"] >= 3 * c["fight"]
    size = np.array([float(np.abs(robot.mount_points).max()), 1.0, 1.0])  # psi_dot as a speed at the wheels
    twist_err = sig(np.abs((i["twist"] - i["ls_twist"]) * size).max() / np.abs(i["ls_twist"] * size).max())
    ratio = sig(i["slip"] / i["predicted_slip"])
    return Outcome(
        "incompatible-steering",
        "incompatible steering",
        "5.2, 5.4, 6",
        "steering angles and driving rates must be compatible to prevent skidding: with axles not concurrent "
        "(rank F = 6) the wheels skid and fight each other, with coordinated steering (rank F = 5) they do not",
        f"coordinated: rank F = {c['rank']}, slip {bound(c['predicted_slip'])} m/s; incompatible (angles off by "
        f"{', '.join(f'{a:g}' for a in off)} deg): rank F = {i['rank']}, least-squares slip "
        f"{fmt(i['predicted_slip'])} m/s",
        f"slip {fmt(c['slip'])} m/s coordinated, {fmt(i['slip'])} m/s incompatible; contact forces fighting each other "
        f"{fmt(c['fight'])} N coordinated, {fmt(i['fight'])} N incompatible",
        f"incompatible slip {fmt(ratio)} times wmr's least-squares slip; platform twist within {pct(twist_err)} of "
        "wmr's least-squares twist",
        HOLDS if holds else FAILS,
        "coordinated slip <= 1/10 of incompatible; incompatible fight >= 3 x coordinated",
        parameters(robot, params, twist=twist_text(twist), averaged=f"t = 1 to {seconds:g} s"),
        rests_on="MuJoCo's friction cone (elliptic, the coefficients of the run) and its soft contacts, which creep a "
        "little under static friction; the drive servos' torque limit bounds how hard the wheels fight",
        overturn="a friction model under which coordinated steering also slips by more than a tenth of the "
        "incompatible slip, or incompatible wheels stop fighting (the box runs other friction cones and coefficients)",
        quote="In both cases, the steering angles and the driving rates must be compatible to prevent singularities "
        "and skidding, which is undesirable.",
        problems=problems,
        data=out | {"twist": twist},
    )


def weakest_push(robot, beta, direction, mu=1.0, crr=0.01, load=None):
    r"""The force that starts a robot with free drives moving along ``direction``, by limit analysis (module docstring).

    Parameters
    ----------
    robot : Robot
        Centred, dual or fixed wheels (one contact per unit at :math:`P_i`).
    beta : array (w,)
    direction : pair
        Unit vector of the push (body frame).
    mu, crr : float
        Sliding friction and rolling resistance coefficients.
    load : array (w,), optional
        Normal forces as fractions of the weight (default: equal shares).

    Returns
    -------
    float
        The force as a fraction of the weight.

    Examples
    --------
    >>> import wmr
    >>> bot = wmr.paper_robot("centred", L=0.3, r=0.05)
    >>> round(weakest_push(bot, [0.0, 0.0, 0.0], (0.0, 1.0)), 6)     # wheels along y: it rolls
    0.01
    """
    beta = robot.effective_beta(beta)
    u = np.asarray(direction, dtype=float)
    N = np.full(robot.w, 1.0 / robot.w) if load is None else np.asarray(load, dtype=float)
    rows, cost = [], []
    for i, d in enumerate(robot.mount_points):
        P = point_row(d)  # [E d_i  1]: p_dot_i = P t
        ii, jj = np.array([np.cos(beta[i]), np.sin(beta[i])]), np.array([-np.sin(beta[i]), np.cos(beta[i])])
        rows += [ii @ P, jj @ P]
        cost += [mu * N[i], crr * N[i]]
    R, weights = np.array(rows), np.array(cost)
    move = np.r_[0.0, u]  # u . c_dot = 1
    best = np.inf
    for k, m in itertools.combinations(range(len(R)), 2):
        A = np.array([R[k], R[m], move])
        if abs(np.linalg.det(A)) < 1e-12 * np.abs(A).max() ** 3:
            continue
        t = np.linalg.solve(A, [0.0, 0.0, 1.0])
        best = min(best, float(weights @ np.abs(R @ t)))
    return best


def breakaway(robot, beta, angle, free=True, params=None, start=1e-3, end=2.0, seconds=3.0, speed=0.005, dt=0.005):
    r"""Push a parked robot at C with a growing force until it moves: the force then, as a fraction of its weight.

    The force grows geometrically from ``start`` to ``end`` times the weight over ``seconds`` (so that
    its relative growth per step is the same at every size), and "moves" means C's speed exceeds
    ``speed`` (m/s); the steering servos hold their angles.

    Parameters
    ----------
    robot : Robot or wmr.sim.Export
        The robot, or its export at ``beta`` (exported once for many pushes).
    beta : array (w,)
    angle : float
        Direction of the push, radians (fixed frame = body frame at rest).
    free : bool
        Drive servos switched off (True) or the drives locked (False, braked).
    params : Params, optional
    start, end : float
        Force at the start and at the end, fractions of the weight.
    seconds : float
    speed : float
    dt : float
        Time between force updates, s.

    Returns
    -------
    tuple (float, wmr.sim.Validity)
        The fraction of the weight at which C started to move (inf if it did not), and the run's validity.
    """
    sim = Simulation(robot if isinstance(robot, Export) else export(robot, beta, params), beta=beta, params=params)
    if free:
        sim.release([n for n in sim.servo_names if n in sim.export.drive_names])
    else:
        sim.lock(sim.export.drive_names)
    W = sim.export.weight
    u = np.array([np.cos(angle), np.sin(angle)])
    n = round(seconds / dt)
    steps = max(1, round(dt / sim.model.opt.timestep))
    for k in range(n):
        f = start * (end / start) ** (k / n)
        sim.push(f * W * u)
        sim.step(steps)
        if k % 4 == 0:
            sim.watch()  # the validity monitor sees the run every fourth update
        if np.hypot(*sim.data.qvel[:2]) > speed:
            return f, sim.validity()
    return np.inf, sim.validity()


def brake_verdict(fig12a, parked):
    """Experiment 4's criterion: Fig. 12a's weakest push at least ten times the parked robot's.

    Parameters
    ----------
    fig12a, parked : float
        The weakest pushes that move each (rounded), fractions of the weight.

    Returns
    -------
    str
    """
    return HOLDS if fig12a >= 10 * parked else FAILS


def brake_experiment(params=None, directions=DIRECTIONS, reference=True):
    r"""Experiment 4: "can be exploited for braking when the WMR is at rest" (Fig. 12a, item (v) at C).

    Three centred wheels with every wheel plane through C (Fig. 12a: rank F = 6, no admissible motion)
    against the robot parked ready to translate (all wheels parallel: rank F = 5, it can roll along
    them), the drives free in both; for reference, the parked robot with its drives braked.  Each is
    pushed at C in the directions ``directions``; the weakest direction decides (:func:`breakaway`).
    Prediction: :func:`weakest_push` with equal loads.

    Criterion: holds when the weakest push that moves the Fig. 12a robot is at least ten times the one
    that moves the parked robot.

    Parameters
    ----------
    params : Params, optional
    directions : sequence of float
        Degrees.
    reference : bool
        Also push the parked robot with its drives braked (for the text and the figure; not in the
        criterion).

    Returns
    -------
    Outcome
    """
    robot = paper("centred")
    p = params or Params()
    d = robot.mount_points
    configs = {
        "fig12a": (np.arctan2(-d[:, 0], d[:, 1]), True),  # j_i along d_i: every wheel plane through C
        "parked": (np.zeros(robot.w), True),
        "braked": (np.zeros(robot.w), False),
    }
    if not reference:
        del configs["braked"]
    out, problems = {}, ()
    for name, (beta, free) in configs.items():
        ex = export(robot, beta, params)  # one model for every direction
        runs = [breakaway(ex, beta, np.radians(a), free, params) for a in directions]
        measured = np.array([f for f, _ in runs])
        problems += tuple(x for a, (_, v) in zip(directions, runs) for x in run_problems(f"{name} {a:g} deg", v))
        predicted = (
            None
            if not free
            else np.array(
                [  # (braked drives: friction on |p_dot_i|, not modelled)
                    weakest_push(robot, beta, (np.cos(np.radians(a)), np.sin(np.radians(a))), p.sliding, p.rolling)
                    for a in directions
                ]
            )
        )
        out[name] = {
            "beta": beta,
            "rank": int(wmr.rank_F(robot, beta)),
            "measured": measured,
            "predicted": predicted,
            "weakest": sig(measured.min()),
            "predicted_weakest": None if predicted is None else sig(predicted.min()),
        }
    a, b = out["fig12a"], out["parked"]
    k = out.get("braked", {"weakest": np.nan})
    return Outcome(
        "braking",
        "braking by steering",
        "5.3, Fig. 12a",
        "the singular configuration of Fig. 12a (every wheel plane through C) can be exploited for braking when the "
        "WMR is at rest",
        f"Fig. 12a: rank F = {a['rank']}, no motion without sliding; weakest push {fmt(a['predicted_weakest'])} W "
        f"(limit analysis, equal loads); parked with parallel wheels: rank F = {b['rank']}, it rolls under "
        f"{fmt(b['predicted_weakest'])} W",
        f"weakest push that moves it: {fmt(a['weakest'])} W in Fig. 12a, {fmt(b['weakest'])} W parked, "
        f"{fmt(k['weakest'])} W parked with the drives braked",
        f"Fig. 12a holds {fmt(sig(a['weakest'] / b['weakest']))} times the parked robot's push and "
        f"{pct(sig(a['weakest'] / k['weakest']))} of the braked one's; limit analysis within "
        f"{pct(sig(abs(a['weakest'] / a['predicted_weakest'] - 1)))} (Fig. 12a) and "
        f"{pct(sig(abs(b['weakest'] / b['predicted_weakest'] - 1)))} (parked)",
        brake_verdict(a["weakest"], b["weakest"]),
        "Fig. 12a's weakest push >= 10 x the parked robot's",
        parameters(
            robot,
            params,
            pushes=f"at C in {len(directions)} directions, force growing geometrically from 0.001 W to 2 W in 3 s",
            moving="C faster than 5 mm/s",
            drives="free (switched off), or locked (braked)",
        ),
        rests_on="Coulomb friction at point contacts (MuJoCo's elliptic cone, the coefficients of the run); the limit "
        "analysis assumes equal loads, and MuJoCo's soft contacts creep before they slide, so 'moves' means C "
        "faster than 5 mm/s",
        overturn="a contact model or load distribution under which the robot of Fig. 12a starts moving under "
        "less than ten times the parked robot's push (the box runs other contact parameters and masses)",
        quote="The singular configuration shown in Fig. 12a can be exploited for braking when the WMR is at rest.",
        problems=problems,
        data=out | {"directions": np.asarray(directions, dtype=float)},
    )
