r"""Isotropy of J_L1, (32)-(39): the homogeneous Jacobian, its Gram matrix, the isotropy conditions, the placement, L.

Chapter 3's checks live in :mod:`edition.checks.isotropy`; this module holds one group of them.  The chapter
derives :math:`\mathbf J_{L1}`, its Gram matrix and the isotropy conditions; each check compares them with the
printed forms and the package, and adds the numerical evidence (the condition number (30)-(31) is
:mod:`edition.checks.isotropy.condition`).
"""

from __future__ import annotations

from functools import cache

import numpy as np
import sympy as sp

from wmr.analysis.isotropy import characteristic_length
from wmr.analysis.linalg import condition_number
from wmr.model.robot import Robot
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL
from wmr.model.wheels import OffsetWheel

from ... import symbols as S
from ...transcription import printed
from ...verify import SEED, max_residual, symbolic_equal
from .. import Derivation, claim, equation, require
from .condition import RHO

__all__ = ["general_robot", "homogeneous_jacobian", "gram", "isotropy_conditions", "placement", "isotropic_gram"]


@cache
def general_robot():
    """Three offset wheels at general (symbolic) mount points :data:`edition.symbols.D`.

    Returns
    -------
    wmr.Robot
    """
    return Robot([OffsetWheel(d, r=S.r, d=S.d) for d in S.D])


def homogeneous_jacobian(JL1, tL):
    r"""(32)-(33): the derived :math:`\mathbf J_{L1}` for general mount points (and ``Robot.J1(L)``), and
    :math:`\mathbf J_1\mathbf t = \mathbf J_{L1}\mathbf t_L`.

    Parameters
    ----------
    JL1 : sympy.Matrix (6, 3)
        The derived :math:`\mathbf J_{L1}` of three units at ``S.D``.
    tL : sympy.Matrix (3, 1)
        The derived :math:`\mathbf t_L`.

    Returns
    -------
    Derivation
        findings (32) and (33).
    """
    p32, p33 = printed(32), printed(33)
    gen = general_robot()
    require(symbolic_equal(gen.J1(S.L), JL1), "Robot.J1(L) is the derived J_L1")
    J1 = JL1.subs(S.L, 1)
    t = sp.Matrix(gen.twist_symbols)
    return Derivation(
        findings=[
            equation(
                32,
                symbolic_equal(JL1, p32.expr.rhs),
                r"the derived $\mathbf J_{L1}$ and `Robot.J1(L)` for three "
                r"general mount points equal the printed matrix (SymPy)",
                max_residual(JL1, p32.expr.rhs),
                convention=r"rows $[\mathbf E\mathbf d_i/L\ \ \mathbf 1]$ in the wheel numbering; "
                r"$\mathbf d_i = \overrightarrow{CP_i}$ in the body frame",
            ),
            equation(
                33,
                symbolic_equal(J1 * t, JL1 * tL) and symbolic_equal(tL, p33.expr.rhs),
                r"$\mathbf J_1\mathbf t = \mathbf J_{L1}\mathbf t_L$ for every "
                r"twist, placement and $L$ (SymPy), so (21) reads "
                r"$\mathbf J_{L1}\mathbf t_L = \mathbf J_2\dot{\boldsymbol\theta}$",
                max_residual(J1 * t, JL1 * tL),
                convention=r"$\mathbf t = [\dot\psi\ \dot x\ \dot y]^{\mathrm T}$, "
                r"body frame",
            ),
        ]
    )


def gram(G):
    r"""(34): :math:`\mathbf J_{L1}^{\mathrm T}\mathbf J_{L1}` for general mount points.

    Parameters
    ----------
    G : sympy.Matrix (3, 3)
        The derived Gram matrix.

    Returns
    -------
    Derivation
        finding (34).
    """
    p34 = printed(34)
    JL1 = general_robot().J1(S.L)
    require(symbolic_equal(JL1.T * JL1, G), "the Gram matrix of Robot.J1(L) is the derived one")
    return Derivation(
        findings=[
            equation(
                34,
                symbolic_equal(G, p34.expr.rhs),
                r"the product of the model's "
                r"$\mathbf J_{L1}$ (general mount points) with its transpose equals the "
                r"printed blocks (SymPy)",
                max_residual(G, p34.expr.rhs),
                convention="general mount points, three wheels",
            )
        ]
    )


def isotropy_conditions(G, solution):
    r"""(35)-(37): the off-diagonal blocks of (34) vanish and its corner equals 3; (35) is equivalent to (37).

    Parameters
    ----------
    G : sympy.Matrix (3, 3)
        The derived Gram matrix.
    solution : dict
        The derived solution of (35) for :math:`\mathbf d_3`.

    Returns
    -------
    Derivation
        findings (35), (36), (37).
    """
    p35, p36, p37 = printed(35), printed(36), printed(37)
    lam = G[1, 1]
    require(G[1:, 1:] == lam * sp.eye(2) and lam == 3, "the lower block of (34) is 3 1 for every placement")
    off_col, off_row, corner = G[1:, 0], G[0, 1:], sp.Eq(G[0, 0], lam)
    d3 = list(S.D[2])
    sol35 = [solution]
    require(symbolic_equal(off_col.subs(solution), sp.zeros(2, 1)), "the derived d_3 solves (35)")
    sol37 = sp.solve(list(p37.expr.lhs - p37.expr.rhs), d3, dict=True)
    res37 = max_residual((p37.expr.lhs - p37.expr.rhs).subs(sol35[0]))
    return Derivation(
        findings=[
            equation(
                35,
                symbolic_equal(off_col, p35.expr.lhs) and symbolic_equal(off_row, p35.extra["row_form"].lhs),
                r"the off-diagonal blocks of (34) are the printed expressions (SymPy); with (36), necessary and "
                r"sufficient for isotropy",
                max_residual(off_col, p35.expr.lhs),
            ),
            equation(
                36,
                symbolic_equal(corner.lhs - corner.rhs, p36.expr.lhs - p36.expr.rhs),
                "the corner entry of (34) equal to the 3 of its lower block (SymPy); with (35), necessary and "
                "sufficient",
                max_residual(corner.lhs - corner.rhs, p36.expr.lhs - p36.expr.rhs),
            ),
            equation(
                37,
                sol35 == sol37,
                r"(35) and (37) have the same solution for $\mathbf d_3$ given "
                r"$\mathbf d_1, \mathbf d_2$ (SymPy): equivalent since $\mathbf E$ is invertible and $L > 0$",
                res37,
                convention=r"C at the centroid of $P_1P_2P_3$",
            ),
        ]
    )


def placement(counterexample, G, L2, n=200, seed=SEED):
    r"""(38) and claim ``isotropy-placement``: equal distances are sufficient, not necessary.

    Given (37), (36) fixes only the *mean* squared distance
    :math:`L^2 = \tfrac13\sum_i\mathbf d_i^{\mathrm T}\mathbf d_i`.
    The counterexample (an isosceles triangle with centroid C) is isotropic exactly.

    Parameters
    ----------
    counterexample : three integer points
    G : sympy.Matrix (3, 3)
        The derived Gram matrix at the counterexample with :math:`L^2` = ``L2``.
    L2 : sympy.Rational
        The derived :math:`L^2`, the mean squared distance.
    n : int
        Random triangles with centroid C and L the RMS distance, checked numerically.
    seed : int

    Returns
    -------
    Derivation
        ``norms``, ``sides``, ``kappa`` (numeric), findings (38) and ``isotropy-placement``.
    """
    p38 = printed(38)
    pts = [tuple(map(sp.Integer, q)) for q in counterexample]
    norms = [sum(c**2 for c in q) for q in pts]
    require(L2 == sp.Rational(sum(norms), 3), "L^2 is the mean squared distance")
    ce = Robot([OffsetWheel(q, r=S.r, d=S.d) for q in pts])
    require(symbolic_equal(ce.J1(sp.sqrt(L2)).T * ce.J1(sp.sqrt(L2)), G), "wmr gives the derived Gram matrix")
    sides = [
        sp.sqrt(sum((a - b) ** 2 for a, b in zip(pts[i], pts[j], strict=True))) for i, j in ((0, 1), (1, 2), (2, 0))
    ]
    num = Robot([OffsetWheel(tuple(map(float, q)), r=0.1, d=0.1) for q in counterexample])
    L_num = characteristic_length(num)
    k_ce = float(condition_number(num.J1(L_num)))
    at = {s_: v for p_, q in zip(S.D, pts, strict=True) for s_, v in zip(p_, q, strict=True)} | {S.L: sp.sqrt(L2)}
    # (38) at the isotropic example
    printed_holds = all(bool(sp.simplify((e.lhs - e.rhs).subs(at)) == 0) for e in p38.expr)
    rng = np.random.default_rng(seed)
    res = 0.0
    for _ in range(n):
        d12 = rng.normal(size=(2, 2))
        tri = np.vstack([d12, -d12.sum(axis=0)])
        bot = Robot([OffsetWheel(q, r=0.1, d=0.1) for q in tri])
        res = max(res, abs(float(condition_number(bot.J1(np.sqrt(np.mean(np.sum(tri**2, axis=1)))))) - 1.0))
    proven = G == 3 * sp.eye(3) and abs(k_ce - 1) <= TOL and res < 1e-9 and abs(L_num**2 - float(L2)) < 1e-12
    ce_text = ", ".join(f"$({a}, {b})$" for a, b in counterexample)
    refuted = (
        rf"$P_i$ = {ce_text}, an isosceles triangle with sides ${', '.join(sp.latex(s) for s in sides)}$ and "
        rf"centroid C, has $\mathbf J_{{L1}}^{{\mathrm T}}\mathbf J_{{L1}} = 3\cdot\mathbf 1$ exactly at "
        rf"$L^2 = {sp.latex(L2)}$ while $\mathbf d_i^{{\mathrm T}}\mathbf d_i = {', '.join(map(str, norms))}$"
    )
    proof = (
        r"with (37), $\mathbf J_{L1}$ is isotropic iff $L^2 = \tfrac13\sum_i\mathbf d_i^{\mathrm T}\mathbf d_i$ "
        r"(SymPy on the "
        rf"counterexample); $\kappa(\mathbf J_{{L1}}) = 1$ at {n} random triangles with centroid C and $L$ their "
        r"RMS distance"
    )
    return Derivation(
        norms=norms,
        sides=sides,
        kappa=k_ce,
        findings=[
            equation(
                38,
                printed_holds,
                proof,
                res,
                refuted=refuted,
                corrected=r"L^2 = \frac13\sum_{i=1}^{3}\mathbf d_i^{\mathrm T}\mathbf d_i",
                corrected_holds=proven,
                severity="wrong",
                overturn=(
                    r"reading (38) as a sufficient condition (a placement that makes $\mathbf J_{L1}$ isotropic), not the "
                    r"condition (36) and (37) impose: as a sufficient condition it holds"
                ),
                why=r"(36) with (37) fixes only the mean of $\mathbf d_i^{\mathrm T}\mathbf d_i$: equal distances are "
                r"sufficient, not necessary",
                convention="C at the centroid (37)",
            ),
            claim(
                "isotropy-placement",
                len(set(sides)) == 1 and proven,
                proof,
                res,
                refuted=refuted,
                corrected=r"$\mathbf J_{L1}$ is isotropic if and only if $\sum_i\mathbf d_i = \mathbf 0$ and "
                r"$L^2 = \tfrac13\sum_i\|\mathbf d_i\|^2$: any triangle with its centroid at C will do; the "
                r"equilateral triangle is the special case with $L$ its circumradius",
                corrected_holds=proven,
                severity="wrong",
                overturn=(
                    r"reading *must* as *may*: the equilateral triangle is one placement that makes $\mathbf J_{L1}$ "
                    r"isotropic, and as such the claim holds"
                ),
                why="isotropy does not need an equilateral triangle, only the centroid at C and the right $L$",
                convention=r"isotropy of $\mathbf J_{L1}$ with the characteristic length $L$ free",
            ),
        ],
    )


def isotropic_gram(G, L_iso, rho=0.4, n=20, seed=SEED):
    r"""(39) and claim ``isotropy-L``: the paper's placement gives :math:`3\cdot\mathbf 1` at L = mount radius, and only
    there.

    Parameters
    ----------
    G : sympy.Matrix (3, 3)
        The derived Gram matrix of the paper's placement at mount radius ``S.L``.
    L_iso : list
        The derived solutions :math:`L` of :math:`\kappa(\mathbf J_{L1}) = 1` (mount radius :data:`RHO`).
    rho : float
        Mount radius of the numeric robot.
    n : int
        Random L values (each robot built at that L) for the numeric check of (39).
    seed : int

    Returns
    -------
    Derivation
        ``L_grid``, ``kappa_grid``, findings (39) and ``isotropy-L``.
    """
    p39 = printed(39)
    paper = paper_robot("offset", L=S.L, r=S.r, exact=True)
    require(symbolic_equal(paper.J1(S.L).T * paper.J1(S.L), G), "wmr gives the derived Gram matrix")
    rng = np.random.default_rng(seed)
    res39 = 0.0
    for L in rng.uniform(0.1, 3.0, n):
        J = paper_robot("offset", L=L, r=0.1).J1(L)
        res39 = max(res39, float(np.max(np.abs(J.T @ J - 3 * np.eye(3)))))
    grid = np.round(np.linspace(0.1, 1.0, 91), 12)
    bot = paper_robot("offset", L=rho, r=0.1)
    kap = np.array([condition_number(bot.J1(L)) for L in grid])
    resL = abs(characteristic_length(bot) - rho)
    at = float(grid[kap.argmin()])
    return Derivation(
        L_grid=grid,
        kappa_grid=kap,
        findings=[
            equation(
                39,
                symbolic_equal(G, p39.expr.rhs),
                r"$\mathbf J_{L1}^{\mathrm T}\mathbf J_{L1}$ of the paper's placement "
                r"with symbolic $L$ equals $3\cdot\mathbf 1$ (SymPy); numerically at "
                rf"{n} random $L$",
                res39,
                convention=r"paper placement $\mathbf d_1 = L(-1, 0)$, "
                r"$\mathbf d_{2,3} = L(\tfrac12, \pm\tfrac{\sqrt3}{2})$; holds for every placement "
                r"satisfying (35)-(36)",
            ),
            claim(
                "isotropy-L",
                L_iso == [RHO] and abs(at - rho) < 1e-12 and resL < 1e-12,
                r"$\kappa(\mathbf J_{L1}) = \max(\rho/L, L/\rho)$ exactly, which is 1 only at $L = \rho$; on a grid of "
                rf"{len(grid)} values of $L$ the minimum is at $L = {at:g} = \rho$; `wmr.characteristic_length` returns "
                r"it",
                resL,
                convention=r"equilateral placement with centroid C; in general $L$ is the RMS distance "
                r"$\sqrt{\tfrac13\sum_i\|\mathbf d_i\|^2}$",
            ),
        ],
    )
