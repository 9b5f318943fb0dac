r"""Chapter 3, equations (30)-(50): the condition number, isotropy of :math:`\mathbf J_{L1}` and :math:`\mathbf J_2`, robustness.

The Jacobians come from :class:`wmr.Robot` (``J1(L)`` is :math:`\mathbf J_{L1}`, ``J2``, ``J``) for
general (symbolic) mount points or the paper's placement, and are compared with the printed forms
of :mod:`wmr.paper.isotropy`.  The last check, :func:`robust_control`, asks whether isotropic
factors make the composite map :math:`\mathbf J = \mathbf J_{L1}^{\mathrm T}\mathbf J_2` (56) well
conditioned, and proves a bound: for three centred wheels, wherever the robot can move,
:math:`\kappa(\mathbf J) \ge \sqrt 2`.
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np
import sympy as sp

from ...analysis.isotropy import characteristic_length
from ...analysis.kinematics import forward, inverse
from ...analysis.linalg import condition_number
from ...analysis.mobility import rank_F, twist_constraints
from ...analysis.simulation import simulate
from ...analysis.steering import steering_angles
from ...model.robot import Robot
from ...model.robots import paper_robot
from ...model.tolerance import TOL
from ...model.wheels import CentredWheel, OffsetWheel
from .. import isotropy as P
from .. import printed
from .. import symbols as S
from ..notebook import explicit, numeric
from ..verify import SEED, max_residual, symbolic_equal
from . import Derivation, claim, equation, require

__all__ = ["general_robot", "condition_number_def", "homogeneous_jacobian", "gram", "isotropy_conditions",
           "placement", "isotropic_gram", "J2_product", "J2_isotropy", "dead_zone_of_isotropy",
           "isotropic_kinematics", "robust_control", "RHO"]

#: the mount radius symbol of the paper's placement with L left free
RHO = sp.Symbol("rho", positive=True)


@lru_cache(maxsize=None)
def general_robot():
    """Three offset wheels at general (symbolic) mount points :data:`wmr.paper.isotropy.D`.

    Returns
    -------
    wmr.Robot
    """
    return Robot([OffsetWheel(d, r=S.r, d=S.d) for d in P.D])


def condition_number_def(n_pairs=50, n_random=2000, seed=SEED):
    r"""(30)-(31): the definition applied exactly to :math:`\mathbf J_{L1}` of the paper's placement with L free.

    :math:`\kappa(\mathbf J_{L1}) = \max(\rho/L, L/\rho)` for mount radius :math:`\rho`; both ends of
    (31) are attained (L = :math:`\rho`; all mount points at C).

    Parameters
    ----------
    n_pairs : int
        Random :math:`(\rho, L)` for the comparison with ``wmr.condition_number``.
    n_random : int
        Random 6x3 matrices compared with ``numpy.linalg.cond``.
    seed : int

    Returns
    -------
    Derivation
        ``singular_values``, ``kappa`` (exact), ``k_min`` (smallest kappa of the random matrices),
        findings (30) and (31).
    """
    p30, p31 = printed(30), printed(31)
    JL1 = paper_robot("offset", L=RHO, r=S.r, exact=True).J1(S.L)
    sv = JL1.singular_values()
    kappa = p30.expr.rhs.subs({P.sigma_l: sp.Max(*sv), P.sigma_s: sp.Min(*sv)})
    key = sp.default_sort_key
    holds30 = symbolic_equal(sp.Matrix(sorted([s**2 for s in sv], key=key)),
                             sp.Matrix(sorted((JL1.T * JL1).eigenvals(multiple=True), key=key)))
    kfun = sp.lambdify((RHO, S.L), kappa, "numpy")
    rng = np.random.default_rng(seed)
    res = 0.0
    for rho, L in rng.uniform(0.2, 2.0, (n_pairs, 2)):
        res = max(res, abs(condition_number(paper_robot("offset", L=rho, r=0.1).J1(L)) - kfun(rho, L)))
    A = rng.normal(size=(n_random, 6, 3))
    k_rand = condition_number(A)
    res = max(res, float(np.max(np.abs(k_rand - np.linalg.cond(A)))))
    sv0 = Robot([CentredWheel((0, 0), r=1)] * 3).J1(sp.Integer(1)).singular_values()
    k_iso = condition_number(paper_robot("offset", L=0.4, r=0.1).J1(0.4))
    lower, upper = p31.expr
    holds31 = (min(sv0) == 0 and upper == sp.oo and sp.simplify(kappa.subs(S.L, RHO)) == lower
               and bool(np.all(k_rand >= lower)) and abs(k_iso - 1) <= TOL)
    return Derivation(singular_values=sv, kappa=kappa, k_min=float(k_rand.min()), findings=[
        equation(30, holds30, r"the squared singular values of $\mathbf J_{L1}$ (paper placement, radius $\rho$, $L$ free) are "
                              r"the eigenvalues of $\mathbf J_{L1}^{\mathrm T}\mathbf J_{L1}$ (SymPy), giving "
                              r"$\kappa = \max(\rho/L, L/\rho)$; `wmr.condition_number` agrees at "
                              rf"{n_pairs} random $(\rho, L)$ and with `numpy.linalg.cond` on {n_random} random matrices",
                 res, convention=r"$\sigma_l$, $\sigma_s$ the largest and smallest singular values",
                 note=r"`wmr.condition_number` returns $\infty$ when $\sigma_s \le 10^{-9}\sigma_l$"),
        equation(31, holds31, r"$\kappa = 1$ is attained ($\mathbf J_{L1}$ at $L = \rho$) and $\kappa = \infty$ too (all "
                              r"mount points at C: $\sigma_s = 0$ exactly); every random matrix has $\kappa \geq 1$", 0.0)])


def homogeneous_jacobian():
    r"""(32)-(33): ``Robot.J1(L)`` for general mount points, and :math:`\mathbf J_1\mathbf t = \mathbf J_{L1}\mathbf t_L`.

    Returns
    -------
    Derivation
        ``JL1``, ``difference`` (:math:`\mathbf J_1\mathbf t - \mathbf J_{L1}\mathbf t_L`), findings (32) and (33).
    """
    p32, p33 = printed(32), printed(33)
    gen = general_robot()
    JL1, J1 = gen.J1(S.L), gen.J1(sp.Integer(1))
    t, tL = sp.Matrix(gen.twist_symbols), p33.expr.rhs
    return Derivation(JL1=JL1, difference=sp.expand(J1 * t - JL1 * tL), findings=[
        equation(32, symbolic_equal(JL1, p32.expr.rhs), r"`Robot.J1(L)` for three general mount points equals the "
                 r"printed matrix (SymPy)", max_residual(JL1, p32.expr.rhs),
                 convention=r"rows $[\mathbf E\mathbf d_i/L\ \ \mathbf 1]$ in the wheel numbering; $\mathbf d_i = \overrightarrow{CP_i}$ in the body frame"),
        equation(33, symbolic_equal(J1 * t, JL1 * tL), r"$\mathbf J_1\mathbf t = \mathbf J_{L1}\mathbf t_L$ for every "
                 r"twist, placement and $L$ (SymPy), so (21) reads $\mathbf J_{L1}\mathbf t_L = \mathbf J_2\dot{\boldsymbol\theta}$",
                 max_residual(J1 * t, JL1 * tL), convention=r"$\mathbf t = [\dot\psi\ \dot x\ \dot y]^{\mathrm T}$, body frame")])


def gram():
    r"""(34): :math:`\mathbf J_{L1}^{\mathrm T}\mathbf J_{L1}` for general mount points.

    Returns
    -------
    Derivation
        ``G``, finding (34).
    """
    p34 = printed(34)
    JL1 = general_robot().J1(S.L)
    G = JL1.T * JL1
    return Derivation(G=G, findings=[equation(34, symbolic_equal(G, p34.expr.rhs), r"the product of the model's "
                                              r"$\mathbf J_{L1}$ (general mount points) with its transpose equals the "
                                              r"printed blocks (SymPy)", max_residual(G, p34.expr.rhs),
                                              convention="general mount points, three wheels")])


def isotropy_conditions():
    r"""(35)-(37): the off-diagonal blocks of (34) vanish and its corner equals 3; (35) is equivalent to (37).

    Returns
    -------
    Derivation
        ``solution`` (:math:`\mathbf d_3` from (35)), findings (35), (36), (37).
    """
    p35, p36, p37 = printed(35), printed(36), printed(37)
    G = gram().G
    lam = G[1, 1]
    require(G[1:, 1:] == lam * sp.eye(2) and lam == 3, "the lower block of (34) is 3 1 for every placement")
    off_col, off_row, corner = G[1:, 0], G[0, 1:], sp.Eq(G[0, 0], lam)
    d3 = list(P.D[2])
    sol35 = sp.solve(list(off_col), d3, dict=True)
    sol37 = sp.solve(list(p37.expr.lhs - p37.expr.rhs), d3, dict=True)
    res37 = max_residual((p37.expr.lhs - p37.expr.rhs).subs(sol35[0]))
    return Derivation(solution=sol35[0], findings=[
        equation(35, symbolic_equal(off_col, p35.expr.lhs) and symbolic_equal(off_row, p35.extra["row_form"].lhs),
                 r"the off-diagonal blocks of (34) are the printed expressions (SymPy); with (36), necessary and "
                 r"sufficient for isotropy", max_residual(off_col, p35.expr.lhs)),
        equation(36, symbolic_equal(corner.lhs - corner.rhs, p36.expr.lhs - p36.expr.rhs),
                 r"the corner entry of (34) equal to the 3 of its lower block (SymPy); with (35), necessary and sufficient",
                 max_residual(corner.lhs - corner.rhs, p36.expr.lhs - p36.expr.rhs)),
        equation(37, sol35 == sol37, r"(35) and (37) have the same solution for $\mathbf d_3$ given $\mathbf d_1, \mathbf d_2$ "
                 r"(SymPy): equivalent since $\mathbf E$ is invertible and $L > 0$", res37,
                 convention=r"C at the centroid of $P_1P_2P_3$")])


def placement(counterexample=((2, 0), (-1, 1), (-1, -1)), n=200, seed=SEED):
    r"""(38) and claim ``isotropy-placement``: equal distances are sufficient, not necessary.

    Given (37), (36) fixes only the *mean* squared distance :math:`L^2 = \tfrac13\sum_i\mathbf d_i^{\mathrm T}\mathbf d_i`.
    The counterexample (an isosceles triangle with centroid C) is isotropic exactly.

    Parameters
    ----------
    counterexample : three integer points
    n : int
        Random triangles with centroid C and L the RMS distance, checked numerically.
    seed : int

    Returns
    -------
    Derivation
        ``G``, ``norms``, ``sides``, ``L2``, ``kappa`` (numeric), findings (38) and ``isotropy-placement``.
    """
    p38 = printed(38)
    pts = [tuple(map(sp.Integer, q)) for q in counterexample]
    norms = [sum(c**2 for c in q) for q in pts]
    L2 = sp.Rational(sum(norms), 3)
    ce = Robot([OffsetWheel(q, r=S.r, d=S.d) for q in pts])
    G = ce.J1(sp.sqrt(L2)).T * ce.J1(sp.sqrt(L2))
    sides = [sp.sqrt(sum((a - b)**2 for a, b in zip(pts[i], pts[j]))) for i, j in ((0, 1), (1, 2), (2, 0))]
    num = Robot([OffsetWheel(tuple(map(float, q)), r=0.1, d=0.1) for q in counterexample])
    L_num = characteristic_length(num)
    k_ce = float(condition_number(num.J1(L_num)))
    at = {s_: v for p_, q in zip(P.D, pts) for s_, v in zip(p_, q)} | {S.L: sp.sqrt(L2)}
    printed_holds = all(bool(sp.simplify((e.lhs - e.rhs).subs(at)) == 0) for e in p38.expr)   # (38) at the isotropic example
    rng = np.random.default_rng(seed)
    res = 0.0
    for _ in range(n):
        d12 = rng.normal(size=(2, 2))
        tri = np.vstack([d12, -d12.sum(axis=0)])
        bot = Robot([OffsetWheel(q, r=0.1, d=0.1) for q in tri])
        res = max(res, abs(float(condition_number(bot.J1(np.sqrt(np.mean(np.sum(tri**2, axis=1)))))) - 1.0))
    proven = G == 3 * sp.eye(3) and abs(k_ce - 1) <= TOL and res < 1e-9 and abs(L_num**2 - float(L2)) < 1e-12
    ce_text = ", ".join(f"$({a}, {b})$" for a, b in counterexample)
    refuted = (rf"$P_i$ = {ce_text}, an isosceles triangle with sides ${', '.join(sp.latex(s) for s in sides)}$ and centroid C, "
               rf"has $\mathbf J_{{L1}}^{{\mathrm T}}\mathbf J_{{L1}} = 3\cdot\mathbf 1$ exactly at $L^2 = {sp.latex(L2)}$ "
               rf"while $\mathbf d_i^{{\mathrm T}}\mathbf d_i = {', '.join(map(str, norms))}$")
    proof = (r"with (37), $\mathbf J_{L1}$ is isotropic iff $L^2 = \tfrac13\sum_i\mathbf d_i^{\mathrm T}\mathbf d_i$ (SymPy on the "
             rf"counterexample); $\kappa(\mathbf J_{{L1}}) = 1$ at {n} random triangles with centroid C and $L$ their RMS distance")
    return Derivation(G=G, norms=norms, sides=sides, L2=L2, kappa=k_ce, findings=[
        equation(38, printed_holds, proof, res, refuted=refuted,
                 corrected=r"L^2 = \frac13\sum_{i=1}^{3}\mathbf d_i^{\mathrm T}\mathbf d_i",
                 corrected_holds=proven, severity="wrong",
                 why=r"(36) with (37) fixes only the mean of $\mathbf d_i^{\mathrm T}\mathbf d_i$: equal distances are "
                     r"sufficient, not necessary", convention="C at the centroid (37)"),
        claim("isotropy-placement", len(set(sides)) == 1 and proven, proof, res, refuted=refuted,
              corrected=r"$\mathbf J_{L1}$ is isotropic if and only if $\sum_i\mathbf d_i = \mathbf 0$ and "
                        r"$L^2 = \tfrac13\sum_i\|\mathbf d_i\|^2$: any triangle with its centroid at C will do; the "
                        r"equilateral triangle is the special case with $L$ its circumradius",
              corrected_holds=proven, severity="wrong",
              why="isotropy does not need an equilateral triangle, only the centroid at C and the right $L$",
              convention=r"isotropy of $\mathbf J_{L1}$ with the characteristic length $L$ free")])


def isotropic_gram(rho=0.4, n=20, seed=SEED):
    r"""(39) and claim ``isotropy-L``: the paper's placement gives :math:`3\cdot\mathbf 1` at L = mount radius, and only there.

    Parameters
    ----------
    rho : float
        Mount radius of the numeric robot.
    n : int
        Random L values (each robot built at that L) for the numeric check of (39).
    seed : int

    Returns
    -------
    Derivation
        ``G``, ``L_iso`` (solutions of kappa = 1), ``L_grid``, ``kappa_grid``, findings (39) and ``isotropy-L``.
    """
    p39 = printed(39)
    paper = paper_robot("offset", L=S.L, r=S.r, exact=True)
    G = paper.J1(S.L).T * paper.J1(S.L)
    rng = np.random.default_rng(seed)
    res39 = 0.0
    for L in rng.uniform(0.1, 3.0, n):
        J = paper_robot("offset", L=L, r=0.1).J1(L)
        res39 = max(res39, float(np.max(np.abs(J.T @ J - 3 * np.eye(3)))))
    L_iso = sp.solve(sp.Eq(RHO / S.L, S.L / RHO), S.L)
    grid = np.round(np.linspace(0.1, 1.0, 91), 12)
    bot = paper_robot("offset", L=rho, r=0.1)
    kap = np.array([condition_number(bot.J1(L)) for L in grid])
    resL = abs(characteristic_length(bot) - rho)
    at = float(grid[kap.argmin()])
    return Derivation(G=G, L_iso=L_iso, L_grid=grid, kappa_grid=kap, findings=[
        equation(39, symbolic_equal(G, p39.expr.rhs), r"$\mathbf J_{L1}^{\mathrm T}\mathbf J_{L1}$ of the paper's placement "
                 r"with symbolic $L$ equals $3\cdot\mathbf 1$ (SymPy); numerically at " rf"{n} random $L$", res39,
                 convention=r"paper placement $\mathbf d_1 = L(-1, 0)$, $\mathbf d_{2,3} = L(\tfrac12, \pm\tfrac{\sqrt3}{2})$; "
                            "holds for every placement satisfying (35)-(36)"),
        claim("isotropy-L", L_iso == [RHO] and abs(at - rho) < 1e-12 and resL < 1e-12,
              r"$\kappa(\mathbf J_{L1}) = \max(\rho/L, L/\rho)$ exactly, which is 1 only at $L = \rho$; on a grid of "
              rf"{len(grid)} values of $L$ the minimum is at $L = {at:g} = \rho$; `wmr.characteristic_length` returns it", resL,
              convention=r"equilateral placement with centroid C; in general $L$ is the RMS distance "
                         r"$\sqrt{\tfrac13\sum_i\|\mathbf d_i\|^2}$")])


def J2_product():
    r"""(40)-(43): :math:`\mathbf J_2\mathbf J_2^{\mathrm T}` is block-diagonal with :math:`\Upsilon_i = \mathbf R\tilde{\mathbf p}^2\mathbf R^{\mathrm T}`; the printed (42) has the wrong signs.

    Returns
    -------
    Derivation
        ``ptilde``, ``ptilde2``, ``Upsilon1``, ``with_printed_42`` and ``with_model`` (:math:`\Upsilon_1`
        at :math:`\beta_1 = 0`, d = r = 1), findings (40)-(43).
    """
    p40, p41, p42, p43 = (printed(i) for i in (40, 41, 42, 43))
    gen = general_robot()
    J2 = gen.J2()
    JJ = J2 * J2.T
    blocks = [JJ[2 * k:2 * k + 2, 2 * k:2 * k + 2] for k in range(3)]
    ptilde = gen.wheels[0].block(sp.Integer(0))                  # R(0) p~ = p~
    ptilde2 = ptilde * ptilde
    beta = gen.beta_symbols
    ups = [explicit(p41.expr.rhs, {P.ptilde2: ptilde2, P.beta_i: b}) for b in beta]
    holds41 = all(symbolic_equal(u, blk) for u, blk in zip(ups, blocks))
    full = explicit(p40.expr.rhs, dict(zip(P.Upsilon, ups)))
    neg = explicit(p41.expr.rhs, {P.ptilde2: p42.expr.rhs, P.beta_i: 0}).subs({S.d: 1, S.r: 1})
    pos = blocks[0].subs({beta[0]: 0, S.d: 1, S.r: 1})
    holds42 = symbolic_equal(ptilde2, p42.expr.rhs)
    corrected42 = symbolic_equal(ptilde2, sp.diag(S.d**2, S.r**2)) and symbolic_equal(neg, -pos)
    holds43 = all(symbolic_equal(p43.expr.rhs.subs(P.beta_i, b), blk) for b, blk in zip(beta, blocks))
    res43 = max(max_residual(p43.expr.rhs.subs(P.beta_i, b), blk) for b, blk in zip(beta, blocks))
    return Derivation(ptilde=ptilde, ptilde2=ptilde2, Upsilon1=blocks[0].applyfunc(sp.trigsimp), with_printed_42=neg,
                      with_model=pos, findings=[
        equation(40, symbolic_equal(JJ, full), r"$\mathbf J_2\mathbf J_2^{\mathrm T}$ of the model is block-diagonal with the "
                 "blocks (41) (SymPy)", max_residual(JJ, full)),
        equation(41, holds41, r"each diagonal block is $\mathbf R_{bwi}\tilde{\mathbf p}^2\mathbf R_{bwi}^{\mathrm T}$ with the "
                 r"model's $\tilde{\mathbf p}^2 = \tilde{\mathbf p}\tilde{\mathbf p}$ (SymPy)",
                 max(max_residual(u, blk) for u, blk in zip(ups, blocks)),
                 convention=r"$\tilde{\mathbf p}^2 = \tilde{\mathbf p}\tilde{\mathbf p}$, $\tilde{\mathbf p} = \mathrm{diag}(-d, -r)$"),
        equation(42, holds42, r"the square of $\tilde{\mathbf p} = \mathrm{diag}(-d, -r)$ is $\mathrm{diag}(d^2, r^2)$ (SymPy)",
                 max_residual(ptilde * ptilde.T, sp.diag(S.d**2, S.r**2)),
                 refuted=r"with the printed signs $\Upsilon_1 = -\mathbf 1$ at $\beta_1 = 0$, $d = r = 1$, where the model "
                         r"gives $+\mathbf 1$: a negative definite block of the positive semidefinite $\mathbf J_2\mathbf J_2^{\mathrm T}$",
                 corrected=r"[\tilde{\mathbf p}^2] = \begin{bmatrix} d^2 & 0\\ 0 & r^2\end{bmatrix}", corrected_holds=corrected42,
                 severity="typo", why=r"a sign slip: the square of $\mathrm{diag}(-d, -r)$ has positive entries, as (43) has",
                 convention=r"$\tilde{\mathbf p} = \mathrm{diag}(-d, -r)$ as in (21)"),
        equation(43, holds43, r"the blocks of the model's $\mathbf J_2\mathbf J_2^{\mathrm T}$ equal the printed matrix for each "
                 "wheel (SymPy); consistent with the corrected (42)", res43,
                 convention=r"$\mathbf R_{bwi} = \mathbf R(\beta_i)$ of (11)")])


def J2_isotropy(pairs=20, n=2000, seed=SEED):
    r"""(44)-(48) and claim ``isotropy-d-equals-r``: :math:`\Upsilon_i` is a multiple of :math:`\mathbf 1` iff d = r, at every angle.

    The deviatoric part of :math:`\Upsilon_i` has squared Frobenius norm :math:`(d^2 - r^2)^2/2`
    whatever :math:`\beta_i`; :math:`\mathbf J_2^{\mathrm T}\mathbf J_2 = \mathrm{diag}(d^2, r^2, \dots)`, so the
    singular values of :math:`\mathbf J_2` are d and r and :math:`\kappa(\mathbf J_2) = \max(d,r)/\min(d,r)`.

    Parameters
    ----------
    pairs : int
        Random (d, r) pairs for the numeric condition numbers.
    n : int
        Random steering configurations.
    seed : int

    Returns
    -------
    Derivation
        ``deviator`` (its squared norm), ``d_solutions``, ``JtJ``, findings (44)-(48) and ``isotropy-d-equals-r``.
    """
    p44, p45, p46, p47, p48 = (printed(i) for i in (44, 45, 46, 47, 48))
    gen = general_robot()
    J2 = gen.J2()
    U1 = (J2 * J2.T)[0:2, 0:2].subs(gen.beta_symbols[0], P.beta_i)
    dev = U1 - sp.trace(U1) / 2 * sp.eye(2)
    frob2 = sum(e**2 for e in dev)
    dev_ok = symbolic_equal(frob2, (S.d**2 - S.r**2)**2 / 2) and symbolic_equal(sp.trace(U1), S.d**2 + S.r**2)
    d_sol = sp.solve(sp.Eq((S.d**2 - S.r**2)**2 / 2, 0), S.d)
    JJr = (J2 * J2.T).subs(S.d, S.r)
    JtJ = J2.T * J2
    jtj_ok = symbolic_equal(JtJ, sp.diag(*[S.d**2, S.r**2] * 3)) and symbolic_equal(JtJ.subs(S.d, S.r), JJr)
    rng = np.random.default_rng(seed)
    B = rng.uniform(-np.pi, np.pi, (n, 3))
    res_k = 0.0
    for d_v, r_v in rng.uniform(0.02, 0.2, (pairs, 2)):
        k = condition_number(paper_robot("offset", L=0.4, r=r_v, d=d_v).J2(B))
        res_k = max(res_k, float(np.max(np.abs(k - max(d_v, r_v) / min(d_v, r_v)))))
    k_eq = condition_number(paper_robot("offset", L=0.4, r=0.1, d=0.1).J2(B))
    k_0 = condition_number(paper_robot("offset", L=0.4, r=0.1, d=0.0).J2(B))
    holds46 = dev_ok and d_sol == [p46.expr.rhs]
    return Derivation(deviator=sp.factor(sp.trigsimp(frob2)), d_solutions=d_sol, JtJ=sp.trigsimp(JtJ), findings=[
        equation(44, symbolic_equal(U1[0, 1], p44.expr.lhs), "the off-diagonal entry of (43) (SymPy)",
                 max_residual(U1[0, 1], p44.expr.lhs)),
        equation(45, symbolic_equal(U1[0, 0] - U1[1, 1], p45.expr.lhs - p45.expr.rhs), "the diagonal entries of (43) (SymPy)",
                 max_residual(U1[0, 0] - U1[1, 1], p45.expr.lhs - p45.expr.rhs)),
        equation(46, holds46, r"(44)-(45) hold iff $\|\Upsilon_i - \tfrac12\mathrm{tr}\,\Upsilon_i\mathbf 1\|_F^2 = "
                              r"\tfrac12(d^2 - r^2)^2$ vanishes, at every $\beta_i$ (SymPy): $d = r$ is necessary and sufficient",
                 max_residual(frob2, (S.d**2 - S.r**2)**2 / 2), convention=r"$d > 0$, $r > 0$"),
        equation(47, symbolic_equal(U1.subs(S.d, S.r), p47.expr.rhs), r"$\Upsilon_i$ at $d = r$ (SymPy)",
                 max_residual(U1.subs(S.d, S.r), p47.expr.rhs), convention="$d = r$"),
        equation(48, symbolic_equal(JJr, p48.expr.rhs) and jtj_ok, r"$\mathbf J_2\mathbf J_2^{\mathrm T} = r^2\mathbf 1$ at "
                 r"$d = r$ for every $\boldsymbol\beta$; also $\mathbf J_2^{\mathrm T}\mathbf J_2 = \mathrm{diag}(d^2, r^2, \dots)$, "
                 r"equal to $\mathbf J_2\mathbf J_2^{\mathrm T}$ iff $d = r$ (SymPy)", max_residual(JJr, p48.expr.rhs),
                 convention=r"$d = r$, any $\boldsymbol\beta$"),
        claim("isotropy-d-equals-r", holds46 and jtj_ok and res_k < 1e-9 and bool(np.all(np.abs(k_eq - 1) <= TOL)),
              r"the singular values of $\mathbf J_2$ are $d$ and $r$ at every $\boldsymbol\beta$ (SymPy: "
              r"$\mathbf J_2^{\mathrm T}\mathbf J_2 = \mathrm{diag}(d^2, r^2, \dots)$), so "
              r"$\kappa(\mathbf J_2) = \max(d,r)/\min(d,r)$: confirmed for " rf"{pairs} random $(d, r)$ at {n} random "
              r"$\boldsymbol\beta$, equal to 1 at $d = r$ and infinite at $d = 0$", res_k,
              convention=r"offset wheel centre $H_i = P_i - d\,\mathbf j_i$; any $\boldsymbol\beta$")],
        kappa_d0_infinite=bool(np.all(np.isinf(k_0))))


def dead_zone_of_isotropy(steps=200, omega=2.0, pairs=20, n=2000, seed=SEED):
    r"""Claim ``isotropy-d-zero``: the isotropic offset d = r is the largest practical offset, hence the largest dead zone.

    A full steering turn without driving at d = r (``wmr.simulate``): C stays at distance d from the
    fixed centroid of the contact points; :math:`\kappa(\mathbf J_2)` is 1 only at d = r and infinite
    at the drift-free d = 0.

    Parameters
    ----------
    steps : int
        Integration steps of the turn.
    omega : float
        Steering rate (rad/s).
    pairs, n, seed
        As in :func:`J2_isotropy`.

    Returns
    -------
    Derivation
        ``radius_min``, ``radius_max``, ``contact_drift``, ``slip``, finding ``isotropy-d-zero``.
    """
    iso = J2_isotropy(pairs=pairs, n=n, seed=seed)
    off = paper_robot("offset", L=0.4, r=0.1)                       # d = r = 0.1
    T = 2 * np.pi / omega
    run = simulate(off, [omega, 0.0] * 3, [0.3] * 3, T, T / steps)
    contacts = np.stack([run.unit_points(i, "H") for i in range(3)], axis=1)
    radius = np.linalg.norm(run.pose[:, 1:] - contacts.mean(axis=1), axis=1)
    drift = float(np.max(np.abs(contacts - contacts[:1])))
    d = off.wheels[0].d
    res = max(float(np.max(np.abs(radius - d))), drift)
    holds = res < 1e-9 and iso.kappa_d0_infinite and iso["isotropy-d-equals-r"].printed_holds
    return Derivation(radius_min=float(radius.min()), radius_max=float(radius.max()), contact_drift=drift,
                      slip=float(run.slip.max()), findings=[claim(
        "isotropy-d-zero", holds, r"$\kappa(\mathbf J_2) = \max(d,r)/\min(d,r)$ is 1 only at $d = r$ and infinite at the "
                                  r"drift-free $d = 0$; a simulated full steering turn without driving at $d = r$ "
                                  rf"(`wmr.simulate`, {steps} steps) keeps C at distance $d$ from the fixed centroid of the "
                                  r"contact points: the dead zone grows with $d$", res,
        convention=r"practical offsets $0 \le d \le r$; dead zone = the circle of radius $d$ traced by C when the units "
                   r"are steered together without driving")])


def isotropic_kinematics(L=0.4, r=0.1, n=25, seed=SEED):
    r"""(49)-(50): the isotropic forward map is the least-squares twist; the inverse is exact at d = r.

    Parameters
    ----------
    L, r : float
        The numeric robot (d = r).
    n : int
        Random configurations and rates.
    seed : int

    Returns
    -------
    Derivation
        ``needs_slip`` (random rates that need slip, of ``n``), findings (49) and (50).
    """
    p49, p50 = printed(49), printed(50)
    paper = paper_robot("offset", L=S.L, r=S.r, exact=True)
    JL1 = paper.J1(S.L)
    holds49 = symbolic_equal((JL1.T * JL1).inv() * JL1.T, JL1.T / 3)
    J2 = paper.J2()
    holds50 = symbolic_equal((J2.T * J2).subs(S.d, S.r), S.r**2 * sp.eye(6))
    bot = paper_robot("offset", L=L, r=r)
    scale = np.diag([L, 1.0, 1.0])                                # t_L = diag(L, 1, 1) t (33)
    rng = np.random.default_rng(seed)
    res49 = res49_exact = res50 = 0.0
    slip = 0
    for _ in range(n):
        b = rng.uniform(-np.pi, np.pi, 3)
        JL1n, J2n = bot.J1(L), bot.J2(b)
        th = rng.normal(size=6)
        tL = numeric(p49.expr.rhs, {P.JL1: JL1n, P.J2: J2n, P.theta_dot: th[:, None]})[:, 0]
        fw = forward(bot, b, th)
        res49 = max(res49, float(np.max(np.abs(np.linalg.solve(scale, tL) - fw.value))))
        slip += int(not fw.admissible)
        tw = rng.normal(size=3)
        inv = inverse(bot, b, tw)
        th50 = numeric(p50.expr.rhs.subs(S.r, r), {P.JL1: JL1n, P.J2: J2n, P.tL: (scale @ tw)[:, None]})[:, 0]
        res50 = max(res50, float(np.max(np.abs(th50 - inv.value))), float(np.max(np.abs(inv.residual))))
        back = numeric(p49.expr.rhs, {P.JL1: JL1n, P.J2: J2n, P.theta_dot: th50[:, None]})[:, 0]
        res49_exact = max(res49_exact, float(np.max(np.abs(np.linalg.solve(scale, back) - tw))))
    require(slip == n, "random joint rates of three offset wheels need slip")
    return Derivation(needs_slip=slip, n=n, findings=[
        equation(49, holds49 and res49 < 1e-9 and res49_exact < 1e-9,
                 r"$\mathbf J_{L1}^{+} = \tfrac13\mathbf J_{L1}^{\mathrm T}$ under (39) (SymPy), so (49) is the least-squares "
                 rf"twist: it equals `wmr.forward` at {n} random configurations and rates, and recovers the twist exactly "
                 "from compatible rates", max(res49, res49_exact),
                 convention=r"least-squares twist; exact iff the joint rates are compatible (no slip)",
                 note=f"random rates always need slip ({slip} of {n})"),
        equation(50, holds50 and res50 < 1e-9, r"$\mathbf J_2^{-1} = \mathbf J_2^{\mathrm T}/r^2$ at $d = r$ (SymPy), so (50) "
                 rf"is exact for every twist: it equals `wmr.inverse` (zero residual) at {n} random configurations", res50,
                 convention=r"$d = r$")])


def _mobile_configurations(bot, n, seed):
    """Steering angles of n random rotations (about random U) and n random translations: every motion the robot can make."""
    rng = np.random.default_rng(seed)
    tw = rng.normal(size=(2 * n, 3))
    tw[n:, 0] = 0.0                                             # translations
    return steering_angles(bot, tw), tw


def robust_control(n=100000, grid=400, seed=SEED):
    r"""Claim ``robust-control``: isotropic factors do not make :math:`\mathbf J = \mathbf J_{L1}^{\mathrm T}\mathbf J_2` robust for centred wheels.

    Offset wheels, d = r: :math:`\mathbf J\mathbf J^{\mathrm T} = 3r^2\mathbf 1` at every configuration.
    Centred wheels, isotropic placement: with :math:`\mathbf A` the axle constraints
    (``twist_constraints``, rows :math:`\mathbf i_i^{\mathrm T}[\mathbf E\mathbf d_i/L\ \ \mathbf 1]`),

    .. math:: \mathbf J\mathbf J^{\mathrm T} = r^2\,(\mathbf J_{L1}^{\mathrm T}\mathbf J_{L1} - \mathbf A^{\mathrm T}\mathbf A)
              = r^2\,(3\cdot\mathbf 1 - \mathbf A^{\mathrm T}\mathbf A),

    because the rows of :math:`\mathbf J^{\mathrm T}/(-r)` and of :math:`\mathbf A` are the components of
    the same rows along :math:`\mathbf j_i` and :math:`\mathbf i_i`.  The robot can move iff
    :math:`\operatorname{rank}\mathbf A \le 2`; then :math:`\sigma_{\max}(\mathbf J)^2 = 3r^2` and, since
    :math:`\mathbf A^{\mathrm T}\mathbf A` has at most two nonzero eigenvalues and trace
    :math:`3 + \sum_i(\mathbf j_i\cdot\mathbf d_i)^2/L^2 \ge 3`, its largest is :math:`\ge 3/2`:
    :math:`\sigma_{\min}(\mathbf J)^2 \le 3r^2/2` and :math:`\kappa(\mathbf J) \ge \sqrt 2`, with equality
    only when every axle passes through C (the rotation about C).

    Parameters
    ----------
    n : int
        Random rotations, and as many random translations, at their steering angles.
    grid : int
        Grid points per axis of the random-angle sample (``grid**2`` configurations) for the
        misleading minimum over all angles.
    seed : int

    Returns
    -------
    Derivation
        ``identity`` (bool), ``kappa_mobile_min``, ``at`` (its steering angles, degrees), ``kappa_about_C``
        (exact), ``translations_infinite`` (bool), ``kappa_random_min`` (all angles, mostly immobile),
        ``example`` (kappa and rank F at :math:`(-135^\circ, 105^\circ, -15^\circ)`), finding ``robust-control``.
    """
    # offset wheels, d = r: J J^T = 3 r^2 1
    off = paper_robot("offset", L=S.L, r=S.r, exact=True)
    Jo = off.J(L=S.L)
    offset_robust = symbolic_equal(Jo * Jo.T, 3 * S.r**2 * sp.eye(3))
    # centred wheels: J J^T = r^2 (J_L1^T J_L1 - A^T A) for general mount points
    gen = Robot([CentredWheel(d, r=S.r) for d in P.D])
    J, JL1 = gen.J(L=S.L), gen.J1(S.L)
    beta = gen.beta_symbols
    axle = [sp.Matrix([sp.cos(b), sp.sin(b)]) for b in beta]
    A = sp.Matrix.vstack(*[axle[k].T * JL1[2 * k:2 * k + 2, :] for k in range(3)])
    identity = symbolic_equal(J * J.T, S.r**2 * (JL1.T * JL1 - A.T * A))
    # numbers on the paper's robot
    bot = paper_robot("centred", L=1.0, r=1.0)
    B, tw = _mobile_configurations(bot, n, seed)
    k = condition_number(bot.J(B, L=1.0))
    rot, tra = k[:n], k[n:]
    i = int(np.argmin(rot))
    A_num, _ = twist_constraints(bot, B[:n])
    Jn = bot.J(B[:n], L=1.0)
    res = float(np.abs(Jn @ np.swapaxes(Jn, -1, -2) - (3 * np.eye(3) - np.swapaxes(A_num, -1, -2) @ A_num)).max())
    mobile = bool(np.all(rank_F(bot, B) == 5))
    smax = np.linalg.svd(bot.J(B[:n], L=1.0), compute_uv=False)[:, 0]
    about_C = steering_angles(paper_robot("centred", L=1, r=1, exact=False), [1.0, 0.0, 0.0])
    exact = paper_robot("centred", L=1, r=1, exact=True)
    Jc = exact.J([sp.nsimplify(round(float(np.degrees(b)))) * sp.pi / 180 for b in about_C], L=1)
    sv = sorted(sp.sqrt(e) for e in (Jc * Jc.T).eigenvals(multiple=True))
    k_about_C = sp.nsimplify(sp.simplify(sv[-1] / sv[0]))
    g = -np.pi + (np.arange(grid) + 0.5) * 2 * np.pi / grid
    rng = np.random.default_rng(seed)
    Br = np.c_[rng.uniform(-np.pi, np.pi, grid * grid), np.stack(np.meshgrid(g, g), -1).reshape(-1, 2)]
    k_rand = condition_number(bot.J(Br, L=1.0))
    ex = np.radians([-135.0, 105.0, -15.0])
    example = {"kappa": float(condition_number(bot.J(ex, L=1.0))), "rank_F": int(rank_F(bot, ex))}
    bound_holds = bool(rot.min() >= np.sqrt(2) - 1e-9) and bool(np.all(np.isinf(tra)))
    require(mobile and bool(np.all(np.abs(smax - np.sqrt(3)) < 1e-9)), "at mobile configurations sigma_max(J) = sqrt(3) r")
    return Derivation(identity=identity, kappa_mobile_min=float(rot.min()), at=np.degrees(B[i]),
                      kappa_about_C=k_about_C, translations_infinite=bool(np.all(np.isinf(tra))),
                      kappa_random_min=float(k_rand[np.isfinite(k_rand)].min()), example=example, n=n, findings=[claim(
        "robust-control", False,
        r"offset wheels, $d = r$: $\mathbf J\mathbf J^{\mathrm T} = 3r^2\mathbf 1$ at every $\boldsymbol\beta$ (SymPy). "
        r"Centred wheels: $\mathbf J\mathbf J^{\mathrm T} = r^2(\mathbf J_{L1}^{\mathrm T}\mathbf J_{L1} - \mathbf A^{\mathrm T}\mathbf A)$ "
        r"for general mount points (SymPy), hence $\kappa(\mathbf J) \geq \sqrt2$ wherever the robot can move; "
        rf"$\kappa(\mathbf J) = {sp.latex(k_about_C)}$ exactly for the rotation about C; over {n} random rotations the "
        rf"smallest $\kappa$ is ${rot.min():.4f}$ and all {n} random translations give $\kappa = \infty$",
        res,
        refuted=r"three centred wheels with isotropic $\mathbf J_{L1}$ and $\mathbf J_2$ have $\kappa(\mathbf J) \geq \sqrt2$ "
                r"at every configuration where they can move, and $\kappa(\mathbf J) = \infty$ in every translation",
        corrected=r"Offset wheels with $d = r$: $\mathbf J\mathbf J^{\mathrm T} = 3r^2\mathbf 1$ for every $\boldsymbol\beta$, "
                  r"robust as claimed. Centred wheels: $\mathbf J\mathbf J^{\mathrm T} = r^2(3\cdot\mathbf 1 - "
                  r"\mathbf A^{\mathrm T}\mathbf A)$ with $\mathbf A$ the axle constraints, so wherever the robot can move "
                  r"(axles concurrent, $\operatorname{rank}\mathbf F = 5$) $\kappa(\mathbf J) \geq \sqrt2$, with equality "
                  r"only for the rotation about C, and $\kappa(\mathbf J) = \infty$ in every translation (all wheel planes "
                  r"parallel); $\mathbf J$ is isotropic only at configurations where the robot cannot move",
        corrected_holds=offset_robust and identity and bound_holds and k_about_C == sp.sqrt(2), severity="wrong",
        why=r"isotropy of the factors $\mathbf J_{L1}$ and $\mathbf J_2$ does not make the composite $\mathbf J$ isotropic "
            r"for centred wheels: it depends on $\boldsymbol\beta$ and is never better than $\sqrt2$ where the robot moves",
        convention=r"robustness read as the condition number of the composite $\mathbf J = \mathbf J_{L1}^{\mathrm T}\mathbf J_2$ "
                   r"(56) used by (49) and (55); paper placement, $L$ the mount radius",
        note=rf"over all steering angles (mostly immobile ones) the smallest $\kappa$ found is ${k_rand[np.isfinite(k_rand)].min():.3f}$, "
             rf"and $(-135^\circ, 105^\circ, -15^\circ)$ even gives $\kappa = {example['kappa']:.3f}$, but with "
             rf"$\operatorname{{rank}}\mathbf F = {example['rank_F']}$: the robot cannot move there")])
