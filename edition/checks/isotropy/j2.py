r"""Isotropy of J2, (40)-(50): its product, d = r, the dead zone of isotropy, the isotropic kinematics.

Chapter 3's checks live in :mod:`edition.checks.isotropy`; this module holds one group of them.  The chapter
derives :math:`\mathbf J_2\mathbf J_2^{\mathrm T}`, its blocks and the deviator; the checks compare and add the
numerical and simulated evidence.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.integration import integrate
from wmr.analysis.kinematics import forward, inverse
from wmr.analysis.linalg import condition_number
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL

from ... import symbols as S
from ...algebra import explicit, numeric
from ...transcription import printed
from ...verify import SEED, max_residual, symbolic_equal
from .. import Derivation, claim, equation, require
from .jl1 import general_robot

__all__ = ["J2_product", "J2_isotropy", "dead_zone_of_isotropy", "isotropic_kinematics"]


def J2_product(JJ, ptilde, ptilde2):
    r"""(40)-(43): :math:`\mathbf J_2\mathbf J_2^{\mathrm T}` is block-diagonal with
    :math:`\Upsilon_i = \mathbf R\tilde{\mathbf p}^2\mathbf R^{\mathrm T}`; the printed (42) has the wrong signs.

    Parameters
    ----------
    JJ : sympy.Matrix (6, 6)
        The derived :math:`\mathbf J_2\mathbf J_2^{\mathrm T}` of three units at the angles ``S.beta``.
    ptilde, ptilde2 : sympy.Matrix (2, 2)
        The derived local block and its square.

    Returns
    -------
    Derivation
        ``with_printed_42`` and ``with_model`` (:math:`\Upsilon_1`
        at :math:`\beta_1 = 0`, d = r = 1), findings (40)-(43).
    """
    p40, p41, p42, p43 = (printed(i) for i in (40, 41, 42, 43))
    gen = general_robot()
    require(
        symbolic_equal(gen.J2() * gen.J2().T, JJ) and symbolic_equal(gen.wheels[0].block(sp.Integer(0)), ptilde),
        "wmr's J2 and offset block give the derived product and local block",
    )
    blocks = [JJ[2 * k : 2 * k + 2, 2 * k : 2 * k + 2] for k in range(3)]
    beta = gen.beta_symbols
    ups = [explicit(p41.expr.rhs, {S.ptilde2: ptilde2, S.beta_i: b}) for b in beta]
    holds41 = all(symbolic_equal(u, blk) for u, blk in zip(ups, blocks, strict=True))
    full = explicit(p40.expr.rhs, dict(zip(S.Upsilon, ups, strict=True)))
    neg = explicit(p41.expr.rhs, {S.ptilde2: p42.expr.rhs, S.beta_i: 0}).subs({S.d: 1, S.r: 1})
    pos = blocks[0].subs({beta[0]: 0, S.d: 1, S.r: 1})
    holds42 = symbolic_equal(ptilde2, p42.expr.rhs)
    corrected42 = symbolic_equal(ptilde2, sp.diag(S.d**2, S.r**2)) and symbolic_equal(neg, -pos)
    holds43 = all(symbolic_equal(p43.expr.rhs.subs(S.beta_i, b), blk) for b, blk in zip(beta, blocks, strict=True))
    res43 = max(max_residual(p43.expr.rhs.subs(S.beta_i, b), blk) for b, blk in zip(beta, blocks, strict=True))
    return Derivation(
        with_printed_42=neg,
        with_model=pos,
        findings=[
            equation(
                40,
                symbolic_equal(JJ, full),
                r"$\mathbf J_2\mathbf J_2^{\mathrm T}$ of the model is block-diagonal "
                r"with the blocks (41) (SymPy)",
                max_residual(JJ, full),
            ),
            equation(
                41,
                holds41,
                r"each diagonal block is $\mathbf R_{bwi}\tilde{\mathbf p}^2\mathbf R_{bwi}^{\mathrm T}$ "
                r"with the model's $\tilde{\mathbf p}^2 = \tilde{\mathbf p}\tilde{\mathbf p}$ (SymPy)",
                max(max_residual(u, blk) for u, blk in zip(ups, blocks, strict=True)),
                convention=r"$\tilde{\mathbf p}^2 = \tilde{\mathbf p}\tilde{\mathbf p}$, "
                r"$\tilde{\mathbf p} = \mathrm{diag}(-d, -r)$",
            ),
            equation(
                42,
                holds42,
                r"the square of $\tilde{\mathbf p} = \mathrm{diag}(-d, -r)$ is $\mathrm{diag}(d^2, r^2)$ "
                r"(SymPy)",
                max_residual(ptilde * ptilde.T, sp.diag(S.d**2, S.r**2)),
                refuted=r"with the printed signs $\Upsilon_1 = -\mathbf 1$ at $\beta_1 = 0$, $d = r = 1$, where the "
                r"model gives $+\mathbf 1$: a negative definite block of the positive semidefinite "
                r"$\mathbf J_2\mathbf J_2^{\mathrm T}$",
                corrected=r"[\tilde{\mathbf p}^2] = \begin{bmatrix} d^2 & 0\\ 0 & "
                r"r^2\end{bmatrix}",
                corrected_holds=corrected42,
                severity="typo",
                overturn=(
                    r"a printed page whose signs differ from the extraction; no real $\tilde{\mathbf p}$ has the printed "
                    r"square, so no convention of the model does"
                ),
                why=r"a sign slip: the square of $\mathrm{diag}(-d, -r)$ has positive entries, as "
                r"(43) has",
                convention=r"$\tilde{\mathbf p} = \mathrm{diag}(-d, -r)$ as in (21)",
            ),
            equation(
                43,
                holds43,
                r"the blocks of the model's $\mathbf J_2\mathbf J_2^{\mathrm T}$ equal the printed "
                r"matrix for each wheel (SymPy); consistent with the corrected (42)",
                res43,
                convention=r"$\mathbf R_{bwi} = \mathbf R(\beta_i)$ of (11)",
            ),
        ],
    )


def J2_isotropy(U1, frob2, d_sol, J2, pairs=20, n=2000, seed=SEED):
    r"""(44)-(48) and claim ``isotropy-d-equals-r``: :math:`\Upsilon_i` is a multiple of :math:`\mathbf 1` iff d = r, at
    every angle.

    The deviatoric part of :math:`\Upsilon_i` has squared Frobenius norm :math:`(d^2 - r^2)^2/2`
    whatever :math:`\beta_i`; :math:`\mathbf J_2^{\mathrm T}\mathbf J_2 = \mathrm{diag}(d^2, r^2, \dots)`, so the
    singular values of :math:`\mathbf J_2` are d and r and :math:`\kappa(\mathbf J_2) = \max(d,r)/\min(d,r)`.

    Parameters
    ----------
    U1 : sympy.Matrix (2, 2)
        The derived :math:`\Upsilon_i` at the angle ``S.beta_i``.
    frob2 : SymPy expression
        The derived squared Frobenius norm of its deviatoric part.
    d_sol : list
        The derived offsets :math:`d` at which it vanishes.
    J2 : sympy.Matrix (6, 6)
        The derived :math:`\mathbf J_2` of three units.
    pairs : int
        Random (d, r) pairs for the numeric condition numbers.
    n : int
        Random steering configurations.
    seed : int

    Returns
    -------
    Derivation
        ``kappa_d0_infinite``, findings (44)-(48) and ``isotropy-d-equals-r``.
    """
    p44, p45, p46, p47, p48 = (printed(i) for i in (44, 45, 46, 47, 48))
    gen = general_robot()
    require(symbolic_equal(gen.J2(), J2), "Robot.J2 is the derived J2")
    dev = U1 - sp.trace(U1) / 2 * sp.eye(2)
    require(symbolic_equal(sum(e**2 for e in dev), frob2), "frob2 is the squared norm of the deviator of U1")
    dev_ok = symbolic_equal(frob2, (S.d**2 - S.r**2) ** 2 / 2) and symbolic_equal(sp.trace(U1), S.d**2 + S.r**2)
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
    return Derivation(
        findings=[
            equation(
                44,
                symbolic_equal(U1[0, 1], p44.expr.lhs),
                "the off-diagonal entry of (43) (SymPy)",
                max_residual(U1[0, 1], p44.expr.lhs),
            ),
            equation(
                45,
                symbolic_equal(U1[0, 0] - U1[1, 1], p45.expr.lhs - p45.expr.rhs),
                "the diagonal entries of (43) (SymPy)",
                max_residual(U1[0, 0] - U1[1, 1], p45.expr.lhs - p45.expr.rhs),
            ),
            equation(
                46,
                holds46,
                r"(44)-(45) hold iff "
                r"$\|\Upsilon_i - \tfrac12\mathrm{tr}\,\Upsilon_i\mathbf 1\|_F^2 = \tfrac12(d^2 - "
                r"r^2)^2$ vanishes, at every $\beta_i$ (SymPy): $d = r$ is necessary and sufficient",
                max_residual(frob2, (S.d**2 - S.r**2) ** 2 / 2),
                convention=r"$d > 0$, $r > 0$",
            ),
            equation(
                47,
                symbolic_equal(U1.subs(S.d, S.r), p47.expr.rhs),
                r"$\Upsilon_i$ at $d = r$ (SymPy)",
                max_residual(U1.subs(S.d, S.r), p47.expr.rhs),
                convention="$d = r$",
            ),
            equation(
                48,
                symbolic_equal(JJr, p48.expr.rhs) and jtj_ok,
                r"$\mathbf J_2\mathbf J_2^{\mathrm T} = r^2\mathbf "
                r"1$ at $d = r$ for every $\boldsymbol\beta$; also "
                r"$\mathbf J_2^{\mathrm T}\mathbf J_2 = \mathrm{diag}(d^2, r^2, \dots)$, equal to "
                r"$\mathbf J_2\mathbf J_2^{\mathrm T}$ iff $d = r$ (SymPy)",
                max_residual(JJr, p48.expr.rhs),
                convention=r"$d = r$, any $\boldsymbol\beta$",
            ),
            claim(
                "isotropy-d-equals-r",
                holds46 and jtj_ok and res_k < 1e-9 and bool(np.all(np.abs(k_eq - 1) <= TOL)),
                r"the singular values of $\mathbf J_2$ are $d$ and $r$ at every $\boldsymbol\beta$ (SymPy: "
                r"$\mathbf J_2^{\mathrm T}\mathbf J_2 = \mathrm{diag}(d^2, r^2, \dots)$), so "
                r"$\kappa(\mathbf J_2) = \max(d,r)/\min(d,r)$: confirmed for "
                rf"{pairs} random $(d, r)$ at {n} random "
                r"$\boldsymbol\beta$, equal to 1 at $d = r$ and infinite at $d = 0$",
                res_k,
                convention=r"offset wheel centre $H_i = P_i - d\,\mathbf j_i$; any $\boldsymbol\beta$",
            ),
        ],
        kappa_d0_infinite=bool(np.all(np.isinf(k_0))),
    )


def dead_zone_of_isotropy(iso, steps=200, omega=2.0):
    r"""Claim ``isotropy-d-zero``: the isotropic offset d = r is the largest practical offset, hence the largest dead
    zone.

    A full steering turn without driving at d = r (``wmr.integrate``): C stays at distance d from the
    fixed centroid of the contact points; :math:`\kappa(\mathbf J_2)` is 1 only at d = r and infinite
    at the drift-free d = 0.

    Parameters
    ----------
    iso : Derivation
        The result of :func:`J2_isotropy`.
    steps : int
        Integration steps of the turn.
    omega : float
        Steering rate (rad/s).

    Returns
    -------
    Derivation
        ``d`` (the offset), ``radius_min``, ``radius_max`` (range of :math:`|CC_f|`), ``radius_error``
        (:math:`\max\,\big||CC_f| - d\big|`), ``contact_drift``, ``slip``, finding ``isotropy-d-zero``.
    """
    off = paper_robot("offset", L=0.4, r=0.1)  # d = r = 0.1
    T = 2 * np.pi / omega
    run = integrate(off, [omega, 0.0] * 3, [0.3] * 3, T, T / steps)
    contacts = np.stack([run.unit_points(i, "H") for i in range(3)], axis=1)
    radius = np.linalg.norm(run.pose[:, 1:] - contacts.mean(axis=1), axis=1)
    drift = float(np.max(np.abs(contacts - contacts[:1])))
    d = off.wheels[0].parameters()["d"]
    radius_error = float(np.max(np.abs(radius - d)))
    res = max(radius_error, drift)
    holds = res < 1e-9 and iso.kappa_d0_infinite and iso["isotropy-d-equals-r"].printed_holds
    return Derivation(
        d=float(d),
        radius_min=float(radius.min()),
        radius_max=float(radius.max()),
        radius_error=radius_error,
        contact_drift=drift,
        slip=float(run.slip.max()),
        findings=[
            claim(
                "isotropy-d-zero",
                holds,
                r"$\kappa(\mathbf J_2) = \max(d,r)/\min(d,r)$ is 1 only at $d = r$ and infinite at "
                r"the drift-free $d = 0$; a simulated full steering turn without driving at $d = r$ "
                rf"(`wmr.integrate`, {steps} steps) keeps C at distance $d$ from the fixed centroid "
                r"of the contact points: the dead zone grows with $d$",
                res,
                convention=r"practical offsets $0 \le d \le r$; dead zone = the circle of radius $d$ traced by C when the "
                r"units are steered together without driving",
            )
        ],
    )


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
    scale = np.diag([L, 1.0, 1.0])  # t_L = diag(L, 1, 1) t (33)
    rng = np.random.default_rng(seed)
    res49 = res49_exact = res50 = 0.0
    slip = 0
    for _ in range(n):
        b = rng.uniform(-np.pi, np.pi, 3)
        JL1n, J2n = bot.J1(L), bot.J2(b)
        th = rng.normal(size=6)
        tL = numeric(p49.expr.rhs, {S.JL1: JL1n, S.J2_offset: J2n, S.theta_dot_offset: th[:, None]})[:, 0]
        fw = forward(bot, b, th)
        res49 = max(res49, float(np.max(np.abs(np.linalg.solve(scale, tL) - fw.value))))
        slip += int(not fw.admissible)
        tw = rng.normal(size=3)
        inv = inverse(bot, b, tw)
        th50 = numeric(p50.expr.rhs.subs(S.r, r), {S.JL1: JL1n, S.J2_offset: J2n, S.tL: (scale @ tw)[:, None]})[:, 0]
        res50 = max(res50, float(np.max(np.abs(th50 - inv.value))), float(np.max(np.abs(inv.residual))))
        back = numeric(p49.expr.rhs, {S.JL1: JL1n, S.J2_offset: J2n, S.theta_dot_offset: th50[:, None]})[:, 0]
        res49_exact = max(res49_exact, float(np.max(np.abs(np.linalg.solve(scale, back) - tw))))
    require(slip == n, "random joint rates of three offset wheels need slip")
    return Derivation(
        needs_slip=slip,
        n=n,
        findings=[
            equation(
                49,
                holds49 and res49 < 1e-9 and res49_exact < 1e-9,
                r"$\mathbf J_{L1}^{+} = \tfrac13\mathbf J_{L1}^{\mathrm T}$ under (39) (SymPy), so (49) is the "
                r"least-squares "
                f"twist: it equals `wmr.forward` at {n} random configurations and rates, and recovers the twist "
                "exactly from compatible rates",
                max(res49, res49_exact),
                convention=r"least-squares twist; exact iff the joint rates are compatible (no slip)",
                note=f"random rates always need slip ({slip} of {n})",
            ),
            equation(
                50,
                holds50 and res50 < 1e-9,
                r"$\mathbf J_2^{-1} = \mathbf J_2^{\mathrm T}/r^2$ at $d = r$ (SymPy), "
                r"so (50) "
                f"is exact for every twist: it equals `wmr.inverse` (zero residual) at {n} random "
                "configurations",
                res50,
                convention=r"$d = r$",
            ),
        ],
    )
