r"""Chapter 6: dual wheels, omnidirectionality and discontinuous heading (claims of Sections 3.2, 5, 6, 7).

"Kinematically equivalent" is tested as: the same admissible platform twists at every steering
angle (:math:`\mathbf F^{\text{dual}} = \mathbf F^{\text{centred}}\mathbf T`); "mobility" as the
dimension of the admissible twists; "omnidirectional" in the paper's own sense of Section 4.2
(every twist executable at once).  Motions are integrated with :func:`wmr.simulate`, which moves
dual units by the corrected (15) and reports the slip (the residual of (21)).
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.kinematics import inverse
from wmr.analysis.mobility import admissible_twists, mobility, rank_F
from wmr.analysis.simulation import simulate
from wmr.analysis.steering import instantaneous_centre, steering_angles
from wmr.model.backend import SYMBOLIC
from wmr.model.platform import rotation
from wmr.model.robot import Robot
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL
from wmr.model.wheels import CentredWheel, DualWheel

from .. import symbols as S
from ..algebra import mod_pi
from ..text import bound
from ..verify import SEED, symbolic_equal
from . import Derivation, claim, require

__all__ = [
    "ROBOT",
    "robots",
    "equivalence",
    "mobility_dual",
    "corner",
    "curved_translation",
    "omnidirectional",
    "discontinuous_heading",
]

#: lengths of this chapter's robots (metres)
ROBOT = dict(L=0.4, r=0.1, b=0.05)


def robots():
    """The chapter's three robots on the same mount points: centred, dual (b = 0.05) and offset (d = r) wheels.

    Returns
    -------
    tuple of wmr.Robot
    """
    L, r, b = ROBOT["L"], ROBOT["r"], ROBOT["b"]
    return paper_robot("centred", L=L, r=r), paper_robot("dual", L=L, r=r, b=b), paper_robot("offset", L=L, r=r, d=r)


def equivalence(B_dual, B_centred, avg, F_dual, F_centred, T, n=300, n_paper=100, t_end=4.0, dt=0.01, seed=SEED):
    r"""Judge claim ``dual-wheel-equivalence``:
    :math:`\mathbf J_2^{\text{dual}} = \mathbf J_2^{\text{centred}}[\tfrac12\ \tfrac12]` and the same admissible twists.

    Parameters
    ----------
    B_dual, B_centred : sympy.Matrix (2, 2), (2, 1)
        One unit's blocks of :math:`\mathbf J_2` at :math:`(d_x, d_y)`, derived in Chapter 6.
    avg : sympy.Matrix (1, 2)
        The averaging row :math:`[\tfrac12\ \tfrac12]` of (18).
    F_dual, F_centred : sympy.Matrix (6, 9), (6, 6)
        :math:`\mathbf F` of the paper's dual and centred robots (symbolic L, r, b).
    T : sympy.Matrix (6, 9)
        :math:`\operatorname{diag}(\mathbf 1_3, [\tfrac12\ \tfrac12], [\tfrac12\ \tfrac12], [\tfrac12\ \tfrac12])`.
    n : int
        Configurations compared (the first ``n_paper`` on the paper's robots, the rest on random robots;
        every other one with coordinated steering).
    n_paper : int
    t_end, dt : float
        The simulated rotation about U with the corrected and the printed (15).
    seed : int

    Returns
    -------
    Derivation
        ``counts`` (rows: dims and nullities and how often), ``worst`` (largest difference of the
        projectors), ``spin`` (residual of the steer-in-place null vectors), ``steer_rate`` (per unit of
        wheel-rate difference), ``runs`` (rows of the simulation), finding ``dual-wheel-equivalence``.
    """
    du = Robot([DualWheel((S.dx, S.dy), r=S.r, b=S.b)])
    cu = Robot([CentredWheel((S.dx, S.dy), r=S.r)])
    require(symbolic_equal(B_dual, du.J2()) and symbolic_equal(B_centred, cu.J2()), "the blocks are Robot.J2's")
    require(
        symbolic_equal(F_dual, paper_robot("dual", L=S.L, r=S.r, b=S.b, exact=True).F())
        and symbolic_equal(F_centred, paper_robot("centred", L=S.L, r=S.r, exact=True).F()),
        "the functional matrices are the paper robots'",
    )
    require(symbolic_equal(avg, sp.Matrix([[sp.Rational(1, 2), sp.Rational(1, 2)]])), "avg is the mean of (18)")
    beta = du.beta_symbols[0]
    ok_block = symbolic_equal(B_dual, B_centred * avg)
    ok_J1 = symbolic_equal(du.J1(L=sp.S.One), cu.J1(L=sp.S.One))
    axle = rotation(beta, SYMBOLIC) * sp.Matrix([1, 0])
    ok_axle = symbolic_equal(axle.T * B_dual, sp.zeros(1, 2)) and symbolic_equal(axle.T * B_centred, sp.zeros(1, 1))
    ok_F = symbolic_equal(F_dual, F_centred * T)
    cen, dual, _ = robots()
    rng = np.random.default_rng(seed)
    counts: dict = {}
    worst = 0.0
    for case in range(n):
        if case < n_paper:
            rc, rd = cen, dual
        else:
            pts = rng.uniform(-1, 1, (3, 2))
            rr, bb = rng.uniform(0.05, 0.3, 2)
            rc = Robot([CentredWheel(tuple(p), r=rr) for p in pts])
            rd = Robot([DualWheel(tuple(p), r=rr, b=bb) for p in pts])
        be = rng.uniform(-np.pi, np.pi, 3) if case % 2 else steering_angles(rc, rng.normal(size=3))
        Pc = admissible_twists(rc, be) @ admissible_twists(rc, be).T
        Pd = admissible_twists(rd, be) @ admissible_twists(rd, be).T
        worst = max(worst, float(np.max(np.abs(Pc - Pd))))
        key = (int(round(np.trace(Pc))), int(round(np.trace(Pd))), int(mobility(rc, be)), int(mobility(rd, be)))
        counts[key] = counts.get(key, 0) + 1
    rows = [
        {
            "twists (centred)": k[0],
            "twists (dual)": k[1],
            r"nullity $\mathbf F$ centred": k[2],
            r"nullity $\mathbf F$ dual": k[3],
            "configurations": v,
        }
        for k, v in sorted(counts.items())
    ]
    be = rng.uniform(-np.pi, np.pi, 3)
    spin = np.zeros((3, 9))
    for i in range(3):
        spin[i, 3 + 2 * i : 5 + 2 * i] = [1.0, -1.0]  # t = 0, theta_i1 = -theta_i2
    res_spin = float(np.max(np.abs(spin @ dual.F(be).T)))
    steer_rate = float(dual.wheels[0].beta_rate(0.0, np.array([1.0, -1.0])))
    tw = np.array([0.5, 0.2, -0.1])
    beta0 = steering_angles(dual, tw)
    ok_rates = inverse(dual, beta0, tw).value
    # the printed (15): no difference when beta_dot = 0
    printed_rates = np.repeat(ok_rates.reshape(3, 2).mean(axis=1), 2)
    runs: list[dict] = []
    for name, rates in (("corrected (15)", ok_rates), ("printed (15)", printed_rates)):
        tr = simulate(dual, rates, beta0, t_end=t_end, dt=dt)
        U = tr.world(instantaneous_centre(tw).point)
        runs.append(
            {
                "steering law": name,
                "wheel-rate difference": float(np.ptp(rates.reshape(3, 2), axis=1).max()),
                "largest slip": float(tr.slip.max()),
                r"largest $|\beta - \beta_0|$": float(np.abs(tr.beta - beta0).max()),
                "drift of U": float(np.ptp(U, axis=0).max()),
            }
        )
    require(
        res_spin < TOL and abs(steer_rate + ROBOT["r"] / ROBOT["b"]) < TOL,
        "counter-rotating wheels steer a dual unit in place",
    )
    require(runs[1]["largest slip"] > TOL, "the printed (15) makes the dual robot slip")
    holds = (
        ok_block
        and ok_J1
        and ok_axle
        and ok_F
        and worst < TOL
        and all(r["twists (centred)"] == r["twists (dual)"] for r in rows)
        and all(r[r"nullity $\mathbf F$ dual"] - r[r"nullity $\mathbf F$ centred"] == 3 for r in rows)
        and runs[0]["largest slip"] < TOL
        and runs[0]["drift of U"] < TOL
    )
    return Derivation(
        counts=rows,
        worst=worst,
        spin=res_spin,
        steer_rate=steer_rate,
        runs=runs,
        n=n,
        findings=[
            claim(
                "dual-wheel-equivalence",
                holds,
                r"$\mathbf J_2^{\text{dual}} = \mathbf J_2^{\text{centred}}[\tfrac12\ \ \tfrac12]$ for one unit and "
                r"$\mathbf F^{\text{dual}} = \mathbf F^{\text{centred}}\mathbf T$ for the paper's robots (SymPy): the same "
                r"admissible "
                rf"platform twists at every $\boldsymbol\beta$, confirmed at {n} configurations of the paper's and random "
                r"robots; the dual robot steered by the corrected (15) turns about a fixed U without slip (`wmr.simulate`)",
                max(worst, runs[0]["largest slip"]),
                convention=r"equivalent = the same admissible platform twists at every $\boldsymbol\beta$, with the average "
                r"rate (18); the wheel-rate difference is the unit's steering rate, by the corrected (15) "
                r"$\dot\phi_i = \dot\psi + \dot\beta_i$",
                note=r"the nullity of $\mathbf F^{\text{dual}}$ is larger by $w = 3$: the extra rates steer the units; with "
                r"the printed (15) the same robot slips (up to "
                f"${runs[1]['largest slip']:.2g}$)",
            )
        ],
    )


def mobility_dual(T, n=2000, seed=SEED):
    r"""Claim ``mobility-dual``: mobility 1 at coordinated steering (the paper's counting, averaged rates), 0 otherwise.

    Parameters
    ----------
    T : sympy.Matrix (6, 9)
        The averaging map of :func:`equivalence` (Chapter 6), :math:`\mathbf F^{\text{dual}} =
        \mathbf F^{\text{centred}}\mathbf T`.
    n : int
        Coordinated and arbitrary configurations.
    seed : int

    Returns
    -------
    Derivation
        ``rows`` (counting, coordinated, arbitrary), finding ``mobility-dual``.
    """
    cen, dual, _ = robots()
    rng = np.random.default_rng(seed)
    be_c = steering_angles(dual, rng.normal(size=(n, 3)))
    be_r = rng.uniform(-np.pi, np.pi, (n, 3))

    def count(f):
        return sorted(set(f(be_c).tolist())), sorted(set(f(be_r).tolist()))

    rows = [
        ("nullity of $\\mathbf F$ with the averaged rates (the paper)", count(lambda b: mobility(cen, b))),
        ("nullity of $\\mathbf F^{\\text{dual}}$ with both wheel rates", count(lambda b: mobility(dual, b))),
        ("dimension of the admissible platform twists", count(lambda b: 3 - (rank_F(dual, b) - 3))),
    ]
    res = float(np.max(np.abs(dual.F(be_r) - cen.F(be_r) @ np.array(T, dtype=float))))
    holds = rows[0][1] == ([1], [0]) and rows[2][1] == ([1], [0]) and res < TOL
    require(rows[1][1] == ([4], [3]), "the dual robot's F has three more null directions")
    return Derivation(
        rows=[{"counting": a, "coordinated steering": b[0], "arbitrary steering": b[1]} for a, b in rows],
        findings=[
            claim(
                "mobility-dual",
                holds,
                rf"at the steering angles of {n} random twists the nullity of $\mathbf F$ with the "
                rf"averaged rates and the dimension of the admissible twists are 1; at {n} arbitrary "
                r"configurations 0; "
                r"$\mathbf F^{\text{dual}} = \mathbf F^{\text{centred}}\mathbf T$ numerically",
                res,
                convention=r"mobility = nullity of $\mathbf F$ with the averaged rates (18) = dimension of the admissible "
                r"platform twists, at coordinated steering angles (0 otherwise)",
                note=r"the nullity of the $6\times9$ matrix $\mathbf F^{\text{dual}}$ with both wheel rates is $1 + w = 4$; "
                r"the extra 3 are the steering rates, which also let a jammed dual-wheel robot re-steer (nullity 3 at "
                r"arbitrary $\boldsymbol\beta$)",
            )
        ],
    )


def corner(v=0.2, w_max=np.pi / 2, dt=0.01):
    r"""A 90-degree corner, exactly: drive along x for 1 s, re-steer, drive along y.  Centred, dual and offset wheels.

    Parameters
    ----------
    v : float
        Speed (m/s).
    w_max : float
        Steering rate limit of the centred wheels (rad/s).
    dt : float

    Returns
    -------
    dict
        ``Ts`` (re-steering time), ``centred`` (motion during re-steering, slip, final pose, slip if
        the new twist is commanded at once), ``dual`` (slip, motion while re-steering, final angle
        error), ``offset`` (slip, final pose, largest joint rate).
    """
    cen, dual, off = robots()
    tw_x, tw_y = np.array([0.0, v, 0.0]), np.array([0.0, 0.0, v])
    bx, by = steering_angles(cen, tw_x), steering_angles(cen, tw_y)
    Ts = float(np.max(np.abs(mod_pi(by - bx)))) / w_max
    rx, ry = inverse(cen, bx, tw_x).value, inverse(cen, by, tw_y).value
    run = simulate(
        cen,
        lambda t, s: rx if t < 1 else (np.zeros(3) if t < 1 + Ts else ry),
        bx,
        t_end=2 + Ts,
        dt=dt,
        steer=lambda t, s: (by - bx) / Ts if 1 <= t < 1 + Ts else np.zeros(3),
    )
    inside = (run.t > 1 + 1e-9) & (run.t < 1 + Ts - 1e-9)
    at_once = inverse(cen, bx, tw_y)

    def dual_rates(t, s):
        if t < 1:
            return inverse(dual, s[1], tw_x).value
        if t < 1 + Ts:
            return inverse(dual, s[1], np.zeros(3), beta_dot=(by - bx) / Ts).value
        return inverse(dual, s[1], tw_y).value

    run_d = simulate(dual, dual_rates, bx, t_end=2 + Ts, dt=dt)
    inside_d = (run_d.t > 1 + 1e-9) & (run_d.t < 1 + Ts - 1e-9)

    def off_rates(t, s):
        return inverse(off, s[1], tw_x if t < 1 else tw_y).value

    run_o = simulate(off, off_rates, np.zeros(3), t_end=2.0, dt=dt)
    top = float(np.abs([off_rates(t, (p, b)) for t, p, b in zip(run_o.t, run_o.pose, run_o.beta, strict=True)]).max())
    return {
        "Ts": Ts,
        "v": v,
        "centred": {
            "moved": float(np.ptp(run.pose[inside], axis=0).max()),
            "slip": float(run.slip.max()),
            "final": run.pose[-1],
            "at_once": float(np.abs(at_once.residual).max()),
            "admissible_at_once": bool(at_once.admissible),
        },
        "dual": {
            "slip": float(run_d.slip.max()),
            "moved": float(np.ptp(run_d.pose[inside_d], axis=0).max()),
            "angle_error": float(np.abs(mod_pi(run_d.beta[-1] - by)).max()),
        },
        "offset": {"slip": float(run_o.slip.max()), "final": run_o.pose[-1], "top_rate": top},
    }


def curved_translation(v=0.2, omega=0.5, t_end=np.pi, dt=0.01):
    r"""Steering while moving: a curvilinear translation (the paper's Fig. 8b) of three centred wheels.

    The velocity direction turns at ``omega`` while the platform does not rotate; the wheels are
    re-steered together at :math:`\dot\beta_i = \omega` and stay parallel, and the rolling rates come
    from the inverse kinematics at the current angles.

    Parameters
    ----------
    v, omega : float
        Speed (m/s) and turning rate of the velocity direction (rad/s).
    t_end, dt : float

    Returns
    -------
    dict
        ``slip`` (largest), ``miss`` (largest difference between the twist executed and the one commanded),
        ``psi`` (largest platform rotation), ``turned`` (direction change, rad),
        ``parallel`` (largest spread of the steering angles).
    """
    cen, _, _ = robots()

    def twist(t):
        return np.array([0.0, v * np.cos(omega * t), v * np.sin(omega * t)])

    beta0 = steering_angles(cen, twist(0.0))
    run = simulate(
        cen, lambda t, s: inverse(cen, s[1], twist(t)).value, beta0, t_end=t_end, dt=dt, steer=np.full(3, omega)
    )
    vel = np.diff(run.pose[:, 1:], axis=0)
    heading = np.unwrap(np.arctan2(vel[:, 1], vel[:, 0]))
    miss = float(np.max(np.abs(run.twist - np.array([twist(t) for t in run.t]))))
    return {
        "slip": float(run.slip.max()),
        "miss": miss,
        "psi": float(np.abs(run.pose[:, 0]).max()),
        "turned": float(heading[-1] - heading[0]),
        "parallel": float(np.ptp(mod_pi(run.beta - run.beta[:, :1]), axis=0).max()),
        "omega": omega,
        "t_end": t_end,
    }


def omnidirectional(n=2000, seed=SEED):
    r"""Claim ``omnidirectional``: three centred wheels are not omnidirectional; they must stop only to turn a sharp
    corner exactly.

    Parameters
    ----------
    n : int
        Random and coordinated steering configurations.
    seed : int

    Returns
    -------
    Derivation
        ``dims`` (admissible twist dimensions, centred and offset), ``corner`` (:func:`corner`),
        ``curve`` (:func:`curved_translation`), finding ``omnidirectional``.
    """
    cen, _, off = robots()
    rng = np.random.default_rng(seed)
    B = np.concatenate([rng.uniform(-np.pi, np.pi, (n, 3)), steering_angles(cen, rng.normal(size=(n, 3)))])
    dims = sorted(set((3 - (rank_F(cen, B) - 3)).tolist()))
    dims_off = sorted(set((3 - (rank_F(off, B) - 6)).tolist()))
    c = corner()
    curve = curved_translation()
    holds = dims == [3]
    proven = (
        dims == [0, 1]
        and dims_off == [3]
        and c["centred"]["slip"] < TOL
        and c["centred"]["moved"] == 0.0
        and not c["centred"]["admissible_at_once"]
        and abs(c["centred"]["at_once"] - c["v"]) < TOL
        and c["dual"]["slip"] < TOL
        and c["dual"]["moved"] < TOL
        and curve["psi"] < TOL
        and curve["slip"] < 1e-6
        and curve["miss"] < 1e-9
        and abs(curve["turned"] - curve["omega"] * curve["t_end"]) < 0.05
    )
    return Derivation(
        dims=dims,
        dims_offset=dims_off,
        corner=c,
        curve=curve,
        n=2 * n,
        findings=[
            claim(
                "omnidirectional",
                holds,
                rf"the admissible twists of three centred wheels form a space of dimension at most 1 at all {2 * n} "
                r"configurations (3 for offset wheels); a 90-degree corner followed exactly needs the wheels re-steered with "
                r"the platform at rest (commanding the new twist at once slips at the full speed), while a curvilinear "
                rf"translation whose direction turns by ${np.degrees(curve['turned']):.0f}^\circ$ is followed without "
                rf"stopping: the twist executed differs from the one commanded by ${bound(curve['miss'], latex=True)}$, slip "
                rf"${bound(curve['slip'], latex=True)}$ (`wmr.simulate`)",
                max(curve["slip"], curve["miss"]),
                refuted=f"the admissible twists have dimension {' or '.join(map(str, dims))} (never 3): a twist in another "
                "direction than the current one cannot be executed without re-steering",
                corrected=r"A WMR with three centred (or dual) wheels has mobility $\nu = 1$ ($0$ at uncoordinated steering "
                r"angles): it is not omnidirectional. It can travel in any direction, and change direction while "
                r"moving when the wheels are re-steered together (they stay parallel, as in the curvilinear "
                r"translation of Fig. 8b); it must stop only to follow a sharp corner exactly, re-steering with the "
                r"platform at rest (type $(1, 2)$ in the classification of Campion et al.)",
                corrected_holds=proven,
                severity="wrong",
                why="omnidirectional means every twist executable at once, the paper's own use in Section 4.2; decoupled "
                "steering only lets the wheels turn, one direction of motion at a time",
                convention="omnidirectional = every platform twist executable at once from any configuration (Section 4.2)",
            )
        ],
    )


def discontinuous_heading(n=2000, seed=SEED):
    r"""Claim ``discontinuous-heading``: with mobility 1 a jump in the direction of travel needs re-steering; offset
    wheels need none.

    Parameters
    ----------
    n : int
        Random twist jumps.
    seed : int

    Returns
    -------
    Derivation
        ``rows`` (executable fraction and largest residual per case), ``gain`` (largest joint-rate gain of the
        offset robot), ``bound`` (its bound), ``corner`` (:func:`corner`), finding ``discontinuous-heading``.
    """
    cen, _, off = robots()
    rng = np.random.default_rng(seed)
    t_minus, t_plus = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))
    lam = rng.choice([-1, 1], n) * rng.uniform(0.2, 3.0, n)
    b_minus = steering_angles(cen, t_minus)
    jump = inverse(cen, b_minus, t_plus)
    scaled = inverse(cen, b_minus, lam[:, None] * t_minus)
    be_off = rng.uniform(-np.pi, np.pi, (n, 3))
    sol_off = inverse(off, be_off, t_plus)
    gain = np.linalg.norm(sol_off.value, axis=-1) / np.linalg.norm(t_plus, axis=-1)
    bound_ = np.linalg.svd(off.J1(), compute_uv=False)[0] / np.linalg.svd(off.J2(be_off), compute_uv=False)[..., -1]
    c = corner()
    rows: list[dict] = [
        {
            "case": r"centred: $\mathbf t^-$ to a random $\mathbf t^+$",
            "executable": float(jump.admissible.mean()),
            "largest residual": float(np.abs(jump.residual).max()),
        },
        {
            "case": r"centred: $\mathbf t^-$ to $\lambda\mathbf t^-$ (incl. "
            r"reversal)",
            "executable": float(scaled.admissible.mean()),
            "largest residual": float(np.abs(scaled.residual).max()),
        },
        {
            "case": r"offset ($d = r$): any $\boldsymbol\beta$, random "
            r"$\mathbf t^+$",
            "executable": float(sol_off.admissible.mean()),
            "largest residual": float(np.abs(sol_off.residual).max()),
        },
    ]
    res = rows[2]["largest residual"]
    holds = (
        not jump.admissible.any()
        and bool(scaled.admissible.all())
        and bool(sol_off.admissible.all())
        and res < TOL
        and bool(np.all(gain <= bound_ * (1 + 1e-12)))
        and c["offset"]["slip"] < TOL
        and bool(np.allclose(c["offset"]["final"], [0.0, c["v"], c["v"]], atol=0.01 * c["v"]))
    )
    return Derivation(
        rows=rows,
        gain=float(gain.max()),
        bound=float(bound_.max()),
        corner=c,
        findings=[
            claim(
                "discontinuous-heading",
                holds,
                rf"of {n} random jumps of the twist, none is executable by the centred robot without re-steering, all jumps "
                r"$\mathbf t \to \lambda\mathbf t$ are; the offset robot executes all of them at once, with joint rates "
                r"bounded by "
                r"$\sigma_{\max}(\mathbf J_1)/\sigma_{\min}(\mathbf J_2)\,\|\mathbf t\|$, and turns a 90-degree corner without "
                r"stopping and without slip (`wmr.simulate`)",
                res,
                convention=r"heading = the direction of the platform twist; a jump $\mathbf t \to \lambda\mathbf t$ (same "
                r"instantaneous centre, a reversal for $\lambda < 0$) needs no delay; offset wheels ($d > 0$) "
                r"realise any twist at once",
            )
        ],
    )
