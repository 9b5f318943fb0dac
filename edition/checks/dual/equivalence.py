r"""Dual wheels against centred wheels (Section 3.2): "kinematically equivalent" tested as the same admissible
platform twists at every steering angle (:math:`\mathbf F^{\text{dual}} = \mathbf F^{\text{centred}}\mathbf T`), and
the mobility of a dual-wheel robot counted as the paper counts it.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.integration import integrate
from wmr.analysis.kinematics import inverse
from wmr.analysis.mobility import admissible_twists, mobility, rank_F
from wmr.analysis.steering import instantaneous_centre, steering_angles
from wmr.model.backend import SYMBOLIC
from wmr.model.platform import rotation
from wmr.model.robot import Robot
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL
from wmr.model.wheels import CentredWheel, DualWheel

from ... import symbols as S
from ...verify import SEED, symbolic_equal
from .. import Derivation, claim, require
from .robots import ROBOT, robots

__all__ = ["equivalence", "mobility_dual"]


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
        tr = integrate(dual, rates, beta0, t_end=t_end, dt=dt)
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
                r"robots; the dual robot steered by the corrected (15) turns about a fixed U without slip (`wmr.integrate`)",
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
