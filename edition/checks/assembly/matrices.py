r"""Stacking the units, (20)-(27): J1, J2, F, its null space, the mobility of offset wheels.

Chapter 2's checks live in :mod:`edition.checks.assembly`; this module holds one group of them.  The chapter
builds :math:`\mathbf J_1`, :math:`\mathbf J_2`, :math:`\mathbf F` and :math:`\mathbf N` from Chapter 1's rows; each
check compares them with the printed forms and with the package's :class:`wmr.Robot` (the library's route).
"""

from __future__ import annotations

from functools import cache

import numpy as np
import sympy as sp

from wmr.analysis.linalg import null_space
from wmr.analysis.mobility import admissible_twists, mobility
from wmr.analysis.steering import steering_angles
from wmr.model.robot import Robot
from wmr.model.robots import Dimensions, paper_robot
from wmr.model.tolerance import TOL
from wmr.model.wheels import OffsetWheel

from ... import symbols as S
from ...algebra import exact_matrix
from ...transcription import printed
from ...verify import SEED, max_residual, symbolic_equal
from .. import Derivation, claim, equation, require

__all__ = ["general_robot", "one_unit", "stacking", "functional_matrix", "null_space_of_F", "mobility_offset"]


#: the paper's offset-wheel robot used for numbers in this chapter (metres)
PAPER = Dimensions(L=0.3, r=0.1, d=0.05)


@cache
def general_robot():
    """Three offset wheels at general (symbolic) mount points, symbolic r and d.

    Returns
    -------
    wmr.Robot
    """
    return Robot([OffsetWheel(p, r=S.r, d=S.d) for p in S.D])


def one_unit(lhs, rhs):
    r"""(20): the velocity of :math:`P_i` through the platform (5) equals that through the wheel (10).

    Parameters
    ----------
    lhs : sympy.Matrix (2, 1)
        The derived velocity through the platform, :math:`[\mathbf E\mathbf d_i\ \ \mathbf 1]\mathbf t`.
    rhs : sympy.Matrix (2, 1)
        The derived velocity through the wheel,
        :math:`\mathbf R_{bwi}\tilde{\mathbf p}[\dot\phi_i\ \dot\theta_i]^{\mathrm T}`.

    Returns
    -------
    Derivation
        finding (20).
    """
    P = printed(20)
    one = Robot([OffsetWheel(S.d_i, r=S.r, d=S.d)])
    require(
        symbolic_equal(exact_matrix(one.J1()) * sp.Matrix(one.twist_symbols), lhs)
        and symbolic_equal(one.J2([S.beta_i]) * sp.Matrix([S.phi_dot_i, S.theta_dot_i]), rhs),
        "a one-unit wmr.Robot gives the derived sides",
    )
    holds = symbolic_equal(lhs, P.expr.lhs) and symbolic_equal(rhs, P.expr.rhs)
    res = max(max_residual(lhs, P.expr.lhs), max_residual(rhs, P.expr.rhs))
    return Derivation(
        findings=[
            equation(
                20,
                holds,
                r"the printed sides equal the derived $[\mathbf E\mathbf d_i\ \ \mathbf 1]\mathbf t$ and "
                r"$\mathbf R_{bwi}\tilde{\mathbf p}[\dot\phi_i\ \dot\theta_i]^{\mathrm T}$, as do a one-unit "
                r"`wmr.Robot`'s (SymPy): the velocity of $P_i$ through the platform and "
                r"through the wheel",
                res,
                convention=r"as (5) and (10): $H_i = P_i - d\,\mathbf j_i$, $\dot\phi_i$ absolute",
            )
        ]
    )


def stacking(J1, J2, theta_dot, ws=(1, 2, 3, 4, 5), seed=SEED):
    r"""(21): the stacked J1, J2 and rate vector against the printed pattern and ``Robot`` (w = 3), sizes for several w.

    Parameters
    ----------
    J1 : sympy.Matrix (6, 3)
        The derived :math:`\mathbf J_1` of three units at the mount points ``S.D``.
    J2 : sympy.Matrix (6, 6)
        The derived :math:`\mathbf J_2` at the steering angles ``S.beta``.
    theta_dot : sympy.Matrix (6, 1)
        The rates :math:`(\dot\phi_1, \dot\theta_1, \dots)`.
    ws : sequence of int
        Numbers of units whose matrix sizes are checked.
    seed : int

    Returns
    -------
    Derivation
        finding (21).
    """
    P = printed(21)
    bot = general_robot()
    t, th = sp.Matrix(bot.twist_symbols), sp.Matrix(theta_dot)
    require(
        symbolic_equal(exact_matrix(bot.J1()), J1)
        and symbolic_equal(bot.J2(), J2)
        and list(th) == list(bot.rate_symbols),
        "wmr.Robot stacks the units as derived",
    )
    holds = (
        symbolic_equal(J1, P.extra["J1"])
        and symbolic_equal(J2, P.extra["J2"])
        and list(th) == list(P.extra["theta_dot"])
        and symbolic_equal(J1 * t - J2 * th, P.expr.lhs - P.expr.rhs)
    )
    rng = np.random.default_rng(seed)
    sizes = True
    for w in ws:
        b = Robot([OffsetWheel(tuple(rng.uniform(-1, 1, 2)), r=0.1, d=0.05) for _ in range(w)])
        sizes &= b.J1().shape == (2 * w, 3) and b.J2(np.zeros(w)).shape == (2 * w, 2 * w) and b.n_rates == 2 * w
    res = max_residual(J1 * t - J2 * th, P.expr.lhs - P.expr.rhs)
    return Derivation(
        findings=[
            equation(
                21,
                holds and sizes,
                r"the stacked $\mathbf J_1$, $\mathbf J_2$, `Robot.J1`, `Robot.J2` and the rates "
                r"equal the printed $\mathbf J_1$, "
                r"$\mathbf J_2$ and the reconstructed rate vector for three units at general mount points "
                rf"(SymPy); sizes $2w\times3$ and $2w\times2w$ for $w = {min(ws)}, \dots, {max(ws)}$",
                res,
                convention=r"units stacked in numbering order; rates $(\dot\phi_i, \dot\theta_i)$ per unit",
            )
        ]
    )


def functional_matrix(F, q, J1, J2, ws=(1, 2, 3, 4, 5)):
    r"""(22)-(25): :math:`\mathbf F = [\mathbf J_1\ -\mathbf J_2]`, its columns, and the size of the zero vector of
    (22).

    Parameters
    ----------
    F : sympy.Matrix (6, 9)
        The derived functional matrix.
    q : sympy.Matrix (9, 1)
        The derived :math:`\dot{\mathbf q}`.
    J1, J2 : sympy.Matrix
        The derived Jacobians it is made of.
    ws : sequence of int
        Numbers of units whose sizes are tabulated.

    Returns
    -------
    Derivation
        ``sizes`` (rows for a table), findings (22)-(25).
    """
    P22, P23, P24, P25 = (printed(i) for i in (22, 23, 24, 25))
    bot = general_robot()
    t, th = sp.Matrix(q[:3]), sp.Matrix(q[3:])
    require(
        symbolic_equal(exact_matrix(bot.F()), F) and list(q) == list(bot.qdot_symbols),
        "Robot.F and Robot.qdot_symbols are the derived F and q",
    )
    Fq = F * q
    sizes = []
    for w in ws:
        b = Robot([OffsetWheel((float(w), 0.0), r=0.1, d=0.05)] * w)
        Fw = b.F(np.zeros(w))
        sizes.append(
            {
                "w": w,
                "F": f"${Fw.shape[0]}\\times{Fw.shape[1]}$",
                "entries": int((Fw @ np.ones(Fw.shape[1])).shape[0]),
                "printed": int(P22.extra["zero_dim"].subs(S.w, w)),
                "shape_ok": Fw.shape == (2 * w, 3 + 2 * w),
            }
        )
    dim_as_printed = all(s["entries"] == s["printed"] for s in sizes)
    dim_2w = all(s["entries"] == 2 * s["w"] for s in sizes)
    shapes = all(s["shape_ok"] for s in sizes)
    holds22 = symbolic_equal(Fq, P22.expr.lhs) and dim_as_printed
    res22 = max_residual(Fq, P22.expr.lhs)
    wlist = rf"$w = {min(ws)}, \dots, {max(ws)}$"
    return Derivation(
        sizes=sizes,
        findings=[
            equation(
                22,
                holds22,
                r"$[\mathbf J_1\ \ -\mathbf J_2]\,\dot{\mathbf q}$ is the left side of (21) (SymPy) and "
                r"has "
                f"$2w$ entries ({wlist})",
                res22,
                refuted=r"the text calls the zero vector $(3+2w)$-dimensional; $\mathbf F\dot{\mathbf q}$ has $2w$ "
                r"entries",
                corrected=r"[\mathbf J_1\ \ -\mathbf J_2]\begin{bmatrix}\mathbf t\\ "
                r"\dot{\boldsymbol\theta}\end{bmatrix} = \mathbf 0, \quad \mathbf 0 \in \mathbb R^{2w}",
                corrected_holds=symbolic_equal(Fq, P22.expr.lhs) and dim_2w,
                severity="typo",
                overturn=(
                    r"a printed page that gives the zero vector $2w$ entries (the slip is in the sentence after the "
                    r"equation, and the extraction is the only witness of it); the equation itself holds"
                ),
                why="the equation holds, but the sentence after it gives the zero vector $3+2w$ entries instead of "
                "$2w$ (one pair of no-slip equations per unit)",
                convention=r"$\mathbf F$ is $2w\times(3+2w)$",
            ),
            equation(
                23,
                symbolic_equal(Fq, J1 * t - J2 * th),
                r"$\mathbf F\dot{\mathbf q}$ equals "
                r"$\mathbf J_1\mathbf t - \mathbf J_2\dot{\boldsymbol\theta}$ "
                r"(SymPy)",
                max_residual(Fq, J1 * t - J2 * th),
                convention=r"$\dot{\mathbf q}$ ordered as (25)",
            ),
            equation(
                24,
                symbolic_equal(F, P24.expr.rhs) and F.shape == (6, 9) and shapes,
                r"the derived $\mathbf F$ and `Robot.F` equal the printed block matrix for three units at "
                r"general mount points (SymPy); shape "
                rf"$2w\times(3+2w)$ for {wlist}",
                max_residual(F, P24.expr.rhs),
                convention="columns ordered as (25)",
            ),
            equation(
                25,
                list(q) == list(P25.expr.rhs),
                r"the derived $\dot{\mathbf q}$ is the printed vector, the "
                r"column order of "
                r"$\mathbf F$",
                0.0,
                convention="definition",
            ),
        ],
    )


def null_space_of_F(N, det_J2, F, J2, n=300, seed=SEED):
    r"""(26)-(27): :math:`\mathbf N = [\mathbf 1_3;\ \mathbf J_2^{-1}\mathbf J_1]` spans :math:`\mathcal N(\mathbf F)`
    exactly (d > 0).

    Parameters
    ----------
    N : sympy.Matrix (9, 3)
        The derived null-space basis.
    det_J2 : SymPy expression
        The derived :math:`\det\mathbf J_2`.
    F, J2 : sympy.Matrix
        The derived functional matrix and :math:`\mathbf J_2`.
    n : int
        Random robots and configurations for the numeric check.
    seed : int

    Returns
    -------
    Derivation
        ``nullities``, findings (26) and (27).
    """
    P27 = printed(27)  # (26) is a statement: checked through its consequences
    exact = (
        symbolic_equal(F * N, sp.zeros(6, 3))
        and N[:3, :] == sp.eye(3)
        and symbolic_equal(J2.det(), det_J2)
        and symbolic_equal(det_J2, S.d**3 * S.r**3)
    )
    rng = np.random.default_rng(seed)
    nullities, mob, res = set(), set(), 0.0
    for _ in range(n):
        r_, d_ = rng.uniform(0.02, 0.3, 2)
        b = Robot([OffsetWheel(tuple(p), r=r_, d=d_) for p in rng.uniform(-1, 1, (3, 2))])
        beta = rng.uniform(-np.pi, np.pi, 3)
        Nn = null_space(b.F(beta))
        nullities.add(Nn.shape[1])
        res = max(res, float(np.abs(b.J1() @ Nn[:3] - b.J2(beta) @ Nn[3:]).max()))
        mob.add(int(mobility(b, beta)))
    require(res < TOL, "the numeric null vectors satisfy (21)")
    return Derivation(
        nullities=nullities,
        findings=[
            equation(
                26,
                exact,
                r"$\mathbf N = [\mathbf 1_3;\ \mathbf J_2^{-1}\mathbf J_1]$ satisfies "
                r"$\mathbf F\mathbf N = \mathbf 0$ "
                rf"with $\det\mathbf J_2 = {sp.latex(det_J2)} \neq 0$ (SymPy); the SVD null vectors at {n} "
                r"random configurations satisfy "
                r"(21)",
                res,
                convention=r"$\dot{\mathbf q}$ ordered as (25); $d > 0$",
            ),
            equation(
                27,
                exact
                and nullities == mob == {P27.extra["claim"]["nullity"]}
                and F.shape[1] == P27.extra["claim"]["q_dim"]
                and F.shape[1] - P27.extra["claim"]["nullity"] == P27.extra["claim"]["rank_F"],
                rf"the nullity from the SVD is 3 at all {n} random "
                r"configurations and equals `wmr.mobility` (structured rank)",
                0.0,
                convention="definition (nullity = mobility)",
            ),
        ],
    )


def mobility_offset(row26, n=200, seed=SEED):
    r"""Claim ``mobility-offset``: rank 6, nullity 3 and every twist admissible at every configuration when d > 0.

    Also what changes at d = 0: nullity 3 generically but pure steering (immobile platform), 4 with a
    one-dimensional family of twists when the axles are concurrent.

    Parameters
    ----------
    row26 : edition.ledger.Finding
        The finding (26) of :func:`null_space_of_F` (the exact null space).
    n : int
        Random steering configurations per case.
    seed : int

    Returns
    -------
    Derivation
        ``cases`` (rows for a table), finding ``mobility-offset``.
    """
    exact = row26
    paper = paper_robot("offset", **PAPER)
    flat = paper_robot("offset", L=PAPER["L"], r=PAPER["r"], d=0.0)
    beta = np.random.default_rng(seed).uniform(-np.pi, np.pi, (n, 3))
    conc = steering_angles(paper_robot("centred", L=PAPER["L"], r=PAPER["r"]), [1.0, 0.2, -0.1])[None, :]
    cases = []
    for name, b, betas in (
        (f"$d > 0$, {n} random $\\boldsymbol\\beta$", paper, beta),
        (f"$d = 0$, {n} random $\\boldsymbol\\beta$", flat, beta),
        ("$d = 0$, axles concurrent", flat, conc),
    ):
        nul = mobility(b, betas)
        cases.append(
            {
                "case": name,
                r"rank $\mathbf F$": sorted(set((9 - nul).tolist())),
                "nullity": sorted(set(nul.tolist())),
                "admissible twists (dim)": sorted({admissible_twists(b, x).shape[1] for x in betas}),
            }
        )
    holds = exact.printed_holds and cases[0]["nullity"] == [3] and cases[0]["admissible twists (dim)"] == [3]
    require(cases[1]["nullity"] == [3] and cases[1]["admissible twists (dim)"] == [0], "d = 0: nullity 3, immobile")
    require(
        cases[2]["nullity"] == [4] and cases[2]["admissible twists (dim)"] == [1], "d = 0, concurrent axles: nullity 4"
    )
    return Derivation(
        cases=cases,
        findings=[
            claim(
                "mobility-offset",
                holds,
                r"for $d > 0$, $\mathbf N = [\mathbf 1_3;\ \mathbf J_2^{-1}\mathbf J_1]$ spans "
                r"$\mathcal N(\mathbf F)$ at every configuration (SymPy), so rank 6, nullity 3 and every twist admissible "
                rf"(confirmed at {n} random configurations)",
                exact.residual,
                convention=r"offset $d > 0$, any mount points, any steering angles",
                note=r"the count alone is not the whole story: at $d = 0$ the nullity is also 3 but the null space is pure "
                r"steering (the platform cannot move), and 4 with a one-dimensional family of twists when the axles are "
                r"concurrent",
            )
        ],
    )
