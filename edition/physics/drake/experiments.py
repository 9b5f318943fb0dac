r"""Four of chapter 9's experiments in Drake: the same robots, commands, measurements and criteria as in MuJoCo.

Each function runs one experiment at the nominal point of :class:`wmr.sim.Params` with one contact model
(:mod:`edition.physics.drake.model`) and returns a :class:`Result`: the measurement, rounded as
:mod:`edition.physics.common` rounds MuJoCo's (:func:`~edition.physics.common.sig`), and the verdict computed from it
by the criterion function of the MuJoCo experiment (:func:`~edition.physics.drift.dead_zone_verdict`,
:func:`~edition.physics.drift.jam_verdict`, :func:`~edition.physics.contact.brake_verdict`,
:func:`~edition.physics.friction.reorient_verdict`); a run with a validity problem
(:mod:`edition.physics.drake.run`) gives ``invalid run`` instead.

The dual-wheel experiment's "torsional part" is, in MuJoCo, the torque with its torsional friction on minus the torque
with it off.  Drake has no torsional coefficient: a point contact resists no spin, and a hydroelastic contact resists
it over its patch.  The part here is therefore the torque with hydroelastic contact minus the torque with point
contact, the same difference (what the contact's resistance to spin adds), and the criterion the same.  The torque is
the servos' power over the turning rate, averaged over t = 1 to 3 s: in steady state what the contacts take.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

import wmr
from wmr.sim import Params, export

from ..common import INVALID, SIZE, fmt, fmt_above, paper, pct, sig
from ..contact import brake_verdict
from ..drift import GENERIC, TURN, circle_error, dead_zone_verdict, jam_does, jam_verdict
from ..friction import RATE, reorient_verdict
from .model import build
from .run import simulate

__all__ = ["BRAKE_DIRECTIONS", "Result", "brake", "dead_zone", "dual_wheel", "jam"]

#: directions of the pushes (deg).  MuJoCo's experiment pushes every 30 degrees; the robot of Fig. 12a has threefold
#: symmetry and a mirror symmetry in its x axis (mount points at 180, 60 and -60 degrees), under which these three
#: stand for all twelve, and the parked robot's weakest direction, along its wheels, is 90 (or 270, its mirror image)
BRAKE_DIRECTIONS = (0, 90, 180)
#: C's speed that counts as moving (m/s), as in MuJoCo's experiment
SPEED = 0.005


@dataclass(frozen=True)
class Result:
    """One experiment in one engine with one contact model: one row of ``engines.csv``.

    Attributes
    ----------
    key : str
        The experiment (``physics.csv``'s key: ``dead-zone``, ``jam``, ``braking``, ``dual-wheel``).
    contact : str
        The contact model, in words.
    measurement : str
        What was measured (rounded numbers).
    verdict : str
        Computed by the experiment's criterion function, or ``invalid run (...)``.
    problems : tuple of str
        The runs' validity problems.
    data : dict
        The rounded numbers.
    """

    key: str
    contact: str
    measurement: str
    verdict: str
    problems: tuple = ()
    data: dict = field(default_factory=dict, repr=False, compare=False)


def _problems(label, rec, saturating=()):
    return tuple(f"{label}: {x}" for x in rec.validity.problems(saturating))


def _judged(verdict, problems):
    return f"{INVALID} ({'; '.join(problems)})" if problems else verdict


def contact_text(contact, modulus):
    """The contact model in words (the ``contact`` column).

    Parameters
    ----------
    contact : str
    modulus : float

    Returns
    -------
    str
    """
    return "point" if contact == "point" else f"hydroelastic, E = {modulus:.0e} Pa".replace("e+0", "e")


def _turn(robot, beta0, contact, modulus, params, seconds=TURN, lock=True):
    """Steer every unit one full turn in ``seconds`` with the drives locked (:func:`edition.physics.drift.turn_locked`)."""
    rates = {f"u{i + 1}_steer": 2 * np.pi / seconds for i in range(robot.w)}
    m = build(robot, beta0, params, contact, modulus, locked_drives=lock, ramp=(rates, seconds))
    return m, simulate(m, seconds + 0.25)


def dead_zone(contact="point", modulus=1e7, params=None):
    """Experiment 1 in Drake (:func:`edition.physics.drift.dead_zone_experiment`).

    Parameters
    ----------
    contact : {"point", "hydroelastic"}
    modulus : float
    params : Params, optional

    Returns
    -------
    Result
    """
    robot, d = paper("offset"), SIZE["r"]
    m, rec = _turn(robot, np.zeros(robot.w), contact, modulus, params)
    C = rec.pose[:, 1:]
    Cf = rec.point[0].mean(axis=0)
    err, centre, radius, dist = circle_error(C, Cf, d)
    err = sig(err)
    drift = float(np.max(np.linalg.norm(rec.point - rec.point[0], axis=-1)))
    text = (
        f"|CC_f| from {fmt(dist.min(), 3)} to {fmt(dist.max(), 3)} m; fitted circle radius {fmt(radius, 3)} m; contact "
        f"points moved {fmt(drift * 1000)} mm; largest deviation from the circle {pct(err)} of d"
    )
    problems = _problems("turn", rec)
    return Result(
        "dead-zone",
        contact_text(contact, modulus),
        text,
        _judged(dead_zone_verdict(err), problems),
        problems,
        {"error": err, "C": C, "Cf": Cf, "model": (contact, modulus)},
    )


def jam(contact="point", modulus=1e7, params=None):
    """Experiment 2 in Drake (:func:`edition.physics.drift.jam_experiment`): generic, equal, and strong servos.

    Parameters
    ----------
    contact : {"point", "hydroelastic"}
    modulus : float
    params : Params, optional

    Returns
    -------
    Result
    """
    robot, d = paper("offset"), SIZE["r"]
    p = params or Params()
    scrub = p.sliding * d / 3 / SIZE["r"]
    out, problems = {}, ()
    runs = [("generic", np.radians(GENERIC), p), ("equal", np.zeros(robot.w), p)]
    runs.append(("strong", np.radians(GENERIC), p.replace(steer_torque=3 * scrub)))
    for name, beta0, q in runs:
        m, rec = _turn(robot, beta0, contact, modulus, q)
        steer = [n for n in m.servo_names if n.endswith("steer")]
        ang = np.array([rec.joints[n] for n in steer]).T
        tau = rec.torque[:, m.steering]
        problems += _problems(name, rec, saturating=steer if name != "equal" else ())
        out[name] = {
            "travel": sig(np.abs(ang[-1] - ang[0]).max() / (2 * np.pi)),
            "moved": sig(np.linalg.norm(rec.pose[-1, 1:] - rec.pose[0, 1:]) / d),
            "torque": sig(np.abs(tau).max() / m.limit[m.steering].max()),
        }
    g, e, s = out["generic"], out["equal"], out["strong"]
    s["does"] = jam_does(s)
    text = (
        f"generic: steering turned {pct(g['travel'])} of the commanded turn, C moved {pct(g['moved'])} of d, torque "
        f"{pct(g['torque'])} of its limit; equal: turned {pct(e['travel'])}; servos of 3 mu N d: it {s['does']} "
        f"(turned {pct(s['travel'])}, C moved {pct(s['moved'])} of d)"
    )
    data = {**out, "model": (contact, modulus)}
    return Result("jam", contact_text(contact, modulus), text, _judged(jam_verdict(g, e), problems), problems, data)


def _breakaway(robot, beta, angle, contact, modulus, params, below=np.inf, start=1e-3, end=2.0, seconds=3.0):
    """Push the parked robot (drives free) at C with a force growing geometrically: the fraction of W that moves it.

    As :func:`edition.physics.contact.breakaway`: from ``start`` to ``end`` times the weight over ``seconds``, updated
    every 5 ms, "moves" meaning C faster than 5 mm/s.  The run stops early once the force passes ``below`` (a weaker
    push in another direction already moved it: this one cannot be the weakest), returning inf.
    """
    m = build(robot, beta, params, contact, modulus, free_drives=True)
    u = np.array([np.cos(angle), np.sin(angle)])

    def force(t):
        return start * (end / start) ** (t / seconds)

    moved = {}

    def stop(rows):
        if len(rows["pose"]) < 2:
            return False
        v = np.hypot(*np.subtract(rows["pose"][-1][1:], rows["pose"][-2][1:])) / (rows["t"][-1] - rows["t"][-2])
        if v > SPEED:
            moved["f"] = force(rows["t"][-2])
            return True
        return force(rows["t"][-1]) > below

    rec = simulate(m, seconds, push=lambda t: force(t) * m.weight * u, stop=stop)
    return moved.get("f", np.inf), rec


def brake(contact="point", modulus=1e7, params=None, directions=BRAKE_DIRECTIONS):
    """Experiment 4 in Drake (:func:`edition.physics.contact.brake_experiment`), without the braked reference.

    Parameters
    ----------
    contact : {"point", "hydroelastic"}
    modulus : float
    params : Params, optional
    directions : sequence of float
        Degrees.

    Returns
    -------
    Result
    """
    robot = paper("centred")
    dpts = robot.mount_points
    configs = {"fig12a": np.arctan2(-dpts[:, 0], dpts[:, 1]), "parked": np.zeros(robot.w)}
    out, problems = {}, ()
    for name, beta in configs.items():
        runs, weakest = [], np.inf
        order = sorted(directions, key=lambda a: -abs(np.sin(np.radians(a) - beta[0])))  # rolling first: others stop
        for a in order:  # early (the minimum over the directions is the same in any order)
            runs.append(_breakaway(robot, beta, np.radians(a), contact, modulus, params, below=weakest))
            weakest = min(weakest, runs[-1][0])
        problems += tuple(x for a, (_, rec) in zip(order, runs) for x in _problems(f"{name} {a:g} deg", rec))
        out[name] = {"weakest": sig(min(f for f, _ in runs)), "measured": [f for f, _ in runs]}
    a, b = out["fig12a"], out["parked"]
    text = (
        f"weakest push that moves it: {fmt(a['weakest'])} W in Fig. 12a, {fmt(b['weakest'])} W parked (drives free), "
        f"{len(directions)} directions; ratio {fmt(sig(a['weakest'] / b['weakest']))}"
    )
    verdict = brake_verdict(a["weakest"], b["weakest"])
    data = {**out, "model": (contact, modulus)}
    return Result("braking", contact_text(contact, modulus), text, _judged(verdict, problems), problems, data)


def reorient(kind, contact, modulus, params=None, rate=RATE, seconds=3.0):
    """Reorient every unit in place at ``rate`` (:func:`edition.physics.friction.reorient`): torque per unit, N m.

    Parameters
    ----------
    kind : {"centred", "dual"}
    contact : {"point", "hydroelastic"}
    modulus : float
    params : Params, optional
    rate : float
    seconds : float

    Returns
    -------
    tuple (float, Recording)
        The servos' power over ``rate`` per unit (t = 1 s to the end), and the run.
    """
    robot = paper(kind)
    beta0 = np.zeros(robot.w)
    if kind == "centred":  # rolling disabled: the drives locked, the steering servos turn
        rates = {f"u{i + 1}_steer": rate for i in range(robot.w)}
    else:  # the drives at the rates of wmr.inverse for a still platform; the swivels passive
        value = wmr.inverse(robot, beta0, [0.0, 0.0, 0.0], beta_dot=np.full(robot.w, rate)).value
        hinges = export(robot, beta0).hinges()  # each joint's column of the rate vector, as wmr.sim maps them
        rates = {f"u{i + 1}_{j.name}": float(value[c]) for i, j, c in hinges if c is not None and j.kind == "drive"}
    m = build(robot, beta0, params, contact, modulus, locked_drives=kind == "centred", ramp=(rates, seconds + 1.0))
    use = [n for n in m.servo_names if n in rates]
    rec = simulate(m, seconds)
    late = rec.t >= 1.0
    power = rec.power(use)[late].mean()
    return power / rate / robot.w, rec


def dual_wheel(modulus=1e7, params=None, point=None):
    """Experiment 5 in Drake: the torque to reorient centred and dual wheels, hydroelastic minus point contact.

    Parameters
    ----------
    modulus : float
        The hydroelastic modulus, Pa.
    params : Params, optional
    point : dict, optional
        The point-contact torques ``{"centred": ..., "dual": ...}`` (with their recordings), if already run.

    Returns
    -------
    tuple (Result, dict)
        The result, and the point-contact torques (to reuse for another modulus).
    """
    if point is None:
        point = {k: reorient(k, "point", 0.0, params) for k in ("centred", "dual")}
    hydro = {k: reorient(k, "hydroelastic", modulus, params) for k in ("centred", "dual")}
    problems: tuple[str, ...] = ()
    for label, runs in (("point", point), ("hydroelastic", hydro)):
        problems += tuple(x for k, (_, rec) in runs.items() for x in _problems(f"{k} {label}", rec))
    t = {(k, c): sig(runs[k][0]) for c, runs in (("point", point), ("hydro", hydro)) for k in ("centred", "dual")}
    floor = 0.01 * max(t.values())  # a hundredth of the largest torque: creep and round-off, not friction
    problems += tuple(f"{k} {c}: the contacts gave energy ({fmt(v)} N m)" for (k, c), v in t.items() if v < -floor)
    shown = {key: fmt_above(v, floor) for key, v in t.items()}
    t = {key: (v if v >= floor else 0.0) for key, v in t.items()}
    dry_c = sig(t[("centred", "hydro")] - t[("centred", "point")])
    dry_d = sig(t[("dual", "hydro")] - t[("dual", "point")])
    text = (
        f"torque to reorient at {RATE:g} rad/s, hydroelastic / point contact: centred {shown[('centred', 'hydro')]} / "
        f"{shown[('centred', 'point')]} N m, dual {shown[('dual', 'hydro')]} / {shown[('dual', 'point')]} N m; the "
        f"dual wheel's spin-resisting part {fmt(dry_d)} N m is {pct(sig(dry_d / dry_c)) if dry_c else 'n/a'} of the "
        f"centred wheel's {fmt(dry_c)} N m"
    )
    data = {"torque": t, "dry": {"centred": dry_c, "dual": dry_d}, "model": ("hydroelastic", modulus)}
    res = Result(
        "dual-wheel",
        contact_text("hydroelastic", modulus) + " against point",
        text,
        _judged(reorient_verdict(dry_d, dry_c), problems),
        problems,
        data,
    )
    return res, point
