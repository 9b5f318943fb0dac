r"""Drift, (28)-(29): how C and psi move when the drives are locked.

Chapter 2's checks live in :mod:`edition.checks.assembly`; this module holds one group of them.
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.model.backend import SYMBOLIC
from wmr.model.platform import E, rotation
from wmr.model.robot import Robot
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL
from wmr.model.wheels import OffsetWheel

from ... import symbols as S
from ...transcription import printed
from ...verify import SEED, symbolic_equal
from .. import Derivation, claim, equation, require
from .locked import concurrent_angles, locked_motion
from .matrices import PAPER

__all__ = ["drift_of_c", "drift_of_psi", "drift"]


def drift_of_c(c_dot, n=100, origin=(0.06, -0.04), seed=SEED):
    r"""(28): sum the three block rows of (21) with :math:`\dot\theta_i = 0` and solve for :math:`\dot{\mathbf c}`.

    The printed form needs :math:`\sum_i\mathbf d_i = \mathbf 0` (C at the centroid of the mount
    points); in general :math:`\dot{\mathbf c}` gains :math:`-\tfrac{\dot\psi}{3}\mathbf E\sum_i\mathbf d_i`.
    Numerically, on genuine locked motions (concurrent arms): the paper's robot and the same robot
    with C moved to ``origin``.

    Parameters
    ----------
    c_dot : sympy.Matrix (2, 1)
        The derived :math:`\dot{\mathbf c}` of three units at the mount points ``S.D`` (drives locked).
    n : int
        Random centres of rotation.
    origin : pair
        Where C is moved for the comparison.
    seed : int

    Returns
    -------
    Derivation
        ``extra`` (derived minus printed), ``off_centroid`` (the printed form's
        error with C moved), finding (28).
    """
    P = printed(28)
    c_dot = sp.Matrix(c_dot)
    extra = (c_dot - P.expr.rhs).applyfunc(sp.simplify)
    centroid = {S.D[2][0]: -S.D[0][0] - S.D[1][0], S.D[2][1]: -S.D[0][1] - S.D[1][1]}
    holds = symbolic_equal(c_dot.subs(centroid), P.expr.rhs)
    needs_centroid = not symbolic_equal(c_dot, P.expr.rhs)
    f28 = sp.lambdify([*S.beta, *S.phi_dot, S.d], P.expr.rhs, "numpy")
    paper = paper_robot("offset", **PAPER)
    off = paper.moved(origin=origin)
    rng = np.random.default_rng(seed)
    res, res_off = 0.0, 0.0
    for _ in range(n):
        u = rng.uniform(-0.5, 0.5, 2)
        for robot in (paper, off):
            bc = concurrent_angles(robot, u)
            x = locked_motion(robot, bc)
            x = x / x[0]
            e = float(np.abs(x[1:3] - np.ravel(f28(*bc, *x[3:], robot.wheels[0].d))).max())
            if robot is paper:
                res = max(res, e)
            else:
                res_off = max(res_off, e)
    require(needs_centroid and res_off > 1e-3, "the printed (28) fails with C off the centroid")
    return Derivation(extra=extra, off_centroid=res_off, findings=[equation(
        28, holds, r"the sum of the block rows of (21) with $\dot\theta_i = 0$, solved for $\dot{\mathbf c}$, is the "
                   r"printed form when $\sum_i\mathbf d_i = \mathbf 0$ (SymPy); it holds on "
                   f"{n} simulated drift motions of the paper's robot", res,
        convention=r"$\sum_i\mathbf d_i = \mathbf 0$ (C at the centroid of the $P_i$); $\dot{\mathbf c}$ in body "
                   r"components",
        note=r"in general $\dot{\mathbf c}$ gains $-\tfrac{\dot\psi}{3}\mathbf E\sum_i\mathbf d_i$: with C moved off "
             r"the "
             f"centroid the printed form is off by up to ${res_off:.2f}$ on the same motions. It holds on every "
             "solution, but solutions exist only for concurrent or parallel arms (see the claim `drift`)")])


def drift_of_psi(a, b, c, J1, n=100, seed=SEED):
    r"""(29): the printed quotient of two vectors, where it comes from, and the true drift rate of :math:`\psi`.

    Projecting (20) onto :math:`(\mathbf E\mathbf d_i)^{\mathrm T}` and summing with :math:`\dot\theta_i = 0`
    and :math:`\sum_i\mathbf d_i = \mathbf 0` gives :math:`\dot\psi`; the paper's route (multiplying by
    :math:`\dot{\mathbf c}^{\mathrm T}\mathbf E`) eliminates :math:`\dot{\mathbf c}`, not :math:`\dot\theta_i`.

    Parameters
    ----------
    a, b, c : SymPy expressions
        The derived coefficients of the projected sum :math:`a\dot\psi + \mathbf b^{\mathrm T}\dot{\mathbf c} + c = 0`
        (``b`` a (2, 1) matrix).
    J1 : sympy.Matrix (6, 3)
        The derived :math:`\mathbf J_1` (for the paper's route).
    n : int
        Random triangles (centroid at C) with random centres of rotation.
    seed : int

    Returns
    -------
    Derivation
        ``error`` (SymPy's message for vector / vector), ``psi_dot`` (corrected), ``gap`` (error of the
        pseudo-inverse reading of the printed quotient), finding (29).
    """
    P = printed(29)
    try:
        P.extra["numerators"][0] / P.extra["divisors"][0]
        error = None
    except TypeError as e:
        error = f"{type(e).__name__}: {e}"
    t, cdot = sp.Matrix([S.psi_dot, S.x_dot, S.y_dot]), sp.Matrix([S.x_dot, S.y_dot])
    b = sp.Matrix(b)
    centroid = {S.D[2][0]: -S.D[0][0] - S.D[1][0], S.D[2][1]: -S.D[0][1] - S.D[1][1]}
    b_vanishes = symbolic_equal(b.subs(centroid), sp.zeros(2, 1))
    psi_dot = sp.expand((-(b.T * cdot)[0] - c).subs(centroid)) / sp.expand(a.subs(centroid))
    paper_route = symbolic_equal((cdot.T * E(SYMBOLIC) * (J1 * t)[0:2, :])[0],
                                 -S.psi_dot * (cdot.T * sp.Matrix(S.D[0]))[0])
    f = sp.lambdify([*sum(S.D, ()), *S.beta, *S.phi_dot, S.d], psi_dot, "numpy")
    rng = np.random.default_rng(seed)
    res, gap = 0.0, 0.0
    for _ in range(n):
        pts = rng.uniform(-1, 1, (3, 2))
        pts -= pts.mean(0)
        arms = [OffsetWheel(tuple(p), r=0.1, d=0.05) for p in pts]
        robot, d = Robot(arms), arms[0].d
        bc = concurrent_angles(robot, rng.uniform(-0.5, 0.5, 2))
        x = locked_motion(robot, bc)
        x = x / x[0]
        D = robot.mount_points
        terms = [rotation(bb) @ np.array([-p, 0.0]) for bb, p in zip(bc, x[3:], strict=True)]
        reading = d / 3 * sum(Dk @ tk / (Dk @ Dk) for Dk, tk in zip(D, terms, strict=True))
        res = max(res, abs(x[0] - f(*D.ravel(), *bc, *x[3:], d)))
        gap = max(gap, abs(x[0] - reading))
    corrected = (r"\dot\psi = \frac{d\sum_{i=1}^{3}(\mathbf E\mathbf d_i)^{\mathrm T}\mathbf R_{bwi}"
                 r"\begin{bmatrix}-\dot\phi_i\\ 0\end{bmatrix}}{\sum_{i=1}^{3}\mathbf d_i^{\mathrm T}\mathbf d_i}")
    return Derivation(error=error, psi_dot=psi_dot, gap=gap, findings=[equation(
        29, error is None, r"projecting (20) on $(\mathbf E\mathbf d_i)^{\mathrm T}$ and summing with "
                           r"$\dot\theta_i = 0$ gives the corrected form when $\sum_i\mathbf d_i = \mathbf 0$ (SymPy); "
                           r"it equals the true "
                           rf"$\dot\psi$ on {n} simulated drift motions of random triangles", res,
        refuted=r"the right side divides the 2-vector $\mathbf R_{bwi}[-\dot\phi_i\ \ 0]^{\mathrm T}$ by the 2-vector "
                r"$\mathbf d_i$, which SymPy rejects; read with $\mathbf d_i^{\mathrm T}/\|\mathbf d_i\|^2$ it is off "
                r"by up "
                rf"to ${gap:.2f}$ rad/s when $\dot\psi = 1$",
        corrected=corrected, corrected_holds=b_vanishes and paper_route and res < TOL, severity="wrong",
        why=r"the printed form divides a vector by a vector; multiplying (20) by "
            r"$\dot{\mathbf c}^{\mathrm T}\mathbf E$ eliminates $\dot{\mathbf c}$, not $\dot\theta_i$",
        convention=r"$\dot\theta_i = 0$, $\sum_i\mathbf d_i = \mathbf 0$",
        note=r"for the paper's equilateral placement ($\mathbf d_i^{\mathrm T}\mathbf d_i = L^2$) the denominator is "
             r"$3L^2$")])


def drift(row28, row29, n_locked, J2):
    r"""Claim ``drift``: steering with the drives locked moves the platform -- a conditional that holds.

    With :math:`\dot\theta_i = 0` and :math:`\mathbf t = \mathbf 0`, (21) leaves
    :math:`\mathbf J_2[\dot\phi_i\ 0]^{\mathrm T} = \mathbf 0`, and :math:`\det\mathbf J_2 = d^3r^3 \neq 0`
    forces :math:`\dot\phi_i = 0`: whenever the wheels are steered without driving, the platform
    moves.  What fails is *free* steering: the locked system jams unless the arm lines are
    concurrent or parallel (:func:`locked_steering`).  The residual is that of (28) and (29).

    Parameters
    ----------
    row28, row29 : edition.ledger.Finding
        The findings of :func:`drift_of_c` and :func:`drift_of_psi`.
    n_locked : Derivation
        :func:`locked_steering`.
    J2 : sympy.Matrix (6, 6)
        The derived :math:`\mathbf J_2` of three units.

    Returns
    -------
    Derivation
        finding ``drift``.
    """
    locked = n_locked
    steer_only = sp.Matrix([S.phi_dot[0], 0, S.phi_dot[1], 0, S.phi_dot[2], 0])
    moved = J2 * steer_only                                   # = J1 t must vanish if t = 0
    sol = sp.solve(list(moved), list(S.phi_dot), dict=True)
    forced = sol == [{p: 0 for p in S.phi_dot}]
    det_J2 = sp.trigsimp(J2.det())
    holds = forced and symbolic_equal(det_J2, S.d**3 * S.r**3)
    return Derivation(findings=[claim(
        "drift", holds, r"with $\dot\theta_i = 0$ and $\mathbf t = \mathbf 0$, (21) leaves "
                        r"$\mathbf J_2[\dot\phi_1\ 0\ \dot\phi_2\ 0\ \dot\phi_3\ 0]^{\mathrm T} = \mathbf 0$, whose "
                        r"only solution is $\dot\phi_i = 0$ since $\det\mathbf J_2 = d^3r^3 \neq 0$ (SymPy): any "
                        r"steering without driving moves the platform, as (28) and (29) "
                        r"describe", max(row28.residual, row29.residual),
        convention=r"offset $d > 0$, non-collinear $P_i$; residual of rows (28) and (29)",
        note=r"what fails is free steering: with the drives locked the $6\times6$ system "
             r"$\mathbf M(\boldsymbol\beta)[\mathbf t;\dot{\boldsymbol\phi}] = \mathbf 0$ has "
             r"$\det\mathbf M = d^3\det[\mathbf d_i\times\mathbf j_i\ \ \mathbf j_i^{\mathrm T}]$"
             + (" (SymPy)" if locked.proven else "")
             + rf", nonzero (rank {sorted(locked.ranks)} at {locked.n} random configurations) unless the arm lines are "
               r"concurrent or all parallel; only then can the robot steer without driving, and the concurrent case "
               r"only instantaneously")])
