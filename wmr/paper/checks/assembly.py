r"""Chapter 2, equations (20)-(29): assembling offset-wheel units, the functional matrix, mobility, drift, dead zone.

The robot's matrices come from :class:`wmr.Robot` (``J1``, ``J2``, ``F``), built for three units
at *general* mount points :math:`\mathbf d_k = (d_{kx}, d_{ky})` with symbolic steering angles,
and are compared with the printed forms of :mod:`wmr.paper.offset`.  With the drives locked
(:math:`\dot\theta_i = 0`) the unknowns are the twist and the steering rates: the square system
:math:`\mathbf M(\boldsymbol\beta)[\mathbf t;\dot{\boldsymbol\phi}] = \mathbf 0` of
:func:`locked_system` decides whether the robot can steer at all, and :func:`locked_motion` gives
the motion when it can.
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np
import sympy as sp

from ...analysis.linalg import null_space, rank
from ...analysis.mobility import admissible_twists, mobility
from ...analysis.simulation import simulate
from ...analysis.steering import steering_angles
from ...model.backend import SYMBOLIC
from ...model.platform import E, point_row, rotation
from ...model.robot import Robot
from ...model.robots import paper_robot
from ...model.tolerance import TOL
from ...model.wheels import OffsetWheel
from .. import offset as PO
from .. import platform_wheels as PW
from .. import printed
from .. import symbols as S
from ..text import bound
from ..verify import SEED, max_residual, symbolic_equal
from . import Derivation, claim, equation, require

__all__ = ["general_robot", "one_unit", "stacking", "functional_matrix", "null_space_of_F", "mobility_offset",
           "locked_system", "locked_motion", "concurrent_angles", "locked_steering", "drift_motions", "drift_of_c",
           "drift_of_psi", "drift", "dead_zone", "dead_zone_claim"]

#: the paper's offset-wheel robot used for numbers in this chapter (metres)
PAPER = dict(L=0.3, r=0.1, d=0.05)


def _exact(M):
    return M.applyfunc(sp.nsimplify)


@lru_cache(maxsize=None)
def general_robot():
    """Three offset wheels at general (symbolic) mount points, symbolic r and d.

    Returns
    -------
    wmr.Robot
    """
    return Robot([OffsetWheel(p, r=S.r, d=S.d) for p in PO.D])


def one_unit():
    r"""(20): the velocity of :math:`P_i` through the platform (5) equals that through the wheel (10).

    Returns
    -------
    Derivation
        ``lhs`` (:math:`\mathbf J_1\mathbf t`), ``rhs`` (:math:`\mathbf J_2\dot{\boldsymbol\theta}`), finding (20).
    """
    P = printed(20)
    one = Robot([OffsetWheel(PW.d_i, r=S.r, d=S.d)])
    lhs = _exact(one.J1()) * sp.Matrix(one.twist_symbols)
    rhs = one.J2([PW.beta_i]) * sp.Matrix([PW.phi_dot_i, PW.theta_dot_i])
    holds = symbolic_equal(lhs, P.expr.lhs) and symbolic_equal(rhs, P.expr.rhs)
    res = max(max_residual(lhs, P.expr.lhs), max_residual(rhs, P.expr.rhs))
    return Derivation(lhs=lhs, rhs=rhs, findings=[equation(
        20, holds, r"both sides equal the one-unit robot's $\mathbf J_1\mathbf t$ and $\mathbf J_2\dot{\boldsymbol\theta}$ "
                   r"(SymPy): the velocity of $P_i$ through the platform and through the wheel", res,
        convention=r"as (5) and (10): $H_i = P_i - d\,\mathbf j_i$, $\dot\phi_i$ absolute")])


def stacking(ws=(1, 2, 3, 4, 5), seed=SEED):
    r"""(21): ``Robot.J1``, ``Robot.J2`` and the rate vector against the printed pattern (w = 3), sizes for several w.

    Parameters
    ----------
    ws : sequence of int
        Numbers of units whose matrix sizes are checked.
    seed : int

    Returns
    -------
    Derivation
        ``J2``, ``theta_dot``, finding (21).
    """
    P = printed(21)
    bot = general_robot()
    J1, J2 = _exact(bot.J1()), bot.J2()
    t, th = sp.Matrix(bot.twist_symbols), sp.Matrix(bot.rate_symbols)
    holds = (symbolic_equal(J1, P.extra["J1"]) and symbolic_equal(J2, P.extra["J2"])
             and list(th) == list(P.extra["theta_dot"]) and symbolic_equal(J1 * t - J2 * th, P.expr.lhs - P.expr.rhs))
    rng = np.random.default_rng(seed)
    sizes = True
    for w in ws:
        b = Robot([OffsetWheel(tuple(rng.uniform(-1, 1, 2)), r=0.1, d=0.05) for _ in range(w)])
        sizes &= b.J1().shape == (2 * w, 3) and b.J2(np.zeros(w)).shape == (2 * w, 2 * w) and b.n_rates == 2 * w
    res = max_residual(J1 * t - J2 * th, P.expr.lhs - P.expr.rhs)
    return Derivation(J2=J2, theta_dot=th, findings=[equation(
        21, holds and sizes, r"`Robot.J1`, `Robot.J2` and `Robot.rate_symbols` equal the printed $\mathbf J_1$, "
                             r"$\mathbf J_2$ and the reconstructed rate vector for three units at general mount points "
                             rf"(SymPy); sizes $2w\times3$ and $2w\times2w$ for $w = {min(ws)}, \dots, {max(ws)}$", res,
        convention=r"units stacked in numbering order; rates $(\dot\phi_i, \dot\theta_i)$ per unit")])


def functional_matrix(ws=(1, 2, 3, 4, 5)):
    r"""(22)-(25): :math:`\mathbf F = [\mathbf J_1\ -\mathbf J_2]`, its columns, and the size of the zero vector of (22).

    Parameters
    ----------
    ws : sequence of int
        Numbers of units whose sizes are tabulated.

    Returns
    -------
    Derivation
        ``F``, ``qdot_names``, ``sizes`` (rows for a table), findings (22)-(25).
    """
    P22, P23, P24, P25 = (printed(i) for i in (22, 23, 24, 25))
    bot = general_robot()
    J1, J2 = _exact(bot.J1()), bot.J2()
    t, th = sp.Matrix(bot.twist_symbols), sp.Matrix(bot.rate_symbols)
    F = _exact(bot.F())
    q = sp.Matrix(bot.qdot_symbols)
    Fq = F * q
    sizes = []
    for w in ws:
        b = Robot([OffsetWheel((float(w), 0.0), r=0.1, d=0.05)] * w)
        Fw = b.F(np.zeros(w))
        sizes.append({"w": w, "F": f"${Fw.shape[0]}\\times{Fw.shape[1]}$", "entries": int((Fw @ np.ones(Fw.shape[1])).shape[0]),
                      "printed": int(P22.extra["zero_dim"].subs(PO.w_sym, w)), "shape_ok": Fw.shape == (2 * w, 3 + 2 * w)})
    dim_as_printed = all(s["entries"] == s["printed"] for s in sizes)
    dim_2w = all(s["entries"] == 2 * s["w"] for s in sizes)
    shapes = all(s["shape_ok"] for s in sizes)
    holds22 = symbolic_equal(Fq, P22.expr.lhs) and dim_as_printed
    res22 = max_residual(Fq, P22.expr.lhs)
    wlist = rf"$w = {min(ws)}, \dots, {max(ws)}$"
    return Derivation(F=F, qdot_names=bot.qdot_names, sizes=sizes, findings=[
        equation(22, holds22, r"$[\mathbf J_1\ \ -\mathbf J_2]\,\dot{\mathbf q}$ is the left side of (21) (SymPy) and has "
                              rf"$2w$ entries ({wlist})", res22,
                 refuted=r"the text calls the zero vector $(3+2w)$-dimensional; $\mathbf F\dot{\mathbf q}$ has $2w$ entries",
                 corrected=r"[\mathbf J_1\ \ -\mathbf J_2]\begin{bmatrix}\mathbf t\\ \dot{\boldsymbol\theta}\end{bmatrix} "
                           r"= \mathbf 0, \quad \mathbf 0 \in \mathbb R^{2w}",
                 corrected_holds=symbolic_equal(Fq, P22.expr.lhs) and dim_2w, severity="typo",
                 why=r"the equation holds, but the sentence after it gives the zero vector $3+2w$ entries instead of $2w$ "
                     r"(one pair of no-slip equations per unit)",
                 convention=r"$\mathbf F$ is $2w\times(3+2w)$"),
        equation(23, symbolic_equal(Fq, J1 * t - J2 * th), r"`Robot.F` times `Robot.qdot_symbols` equals "
                 r"$\mathbf J_1\mathbf t - \mathbf J_2\dot{\boldsymbol\theta}$ (SymPy)", max_residual(Fq, J1 * t - J2 * th),
                 convention=r"$\dot{\mathbf q}$ ordered as (25)"),
        equation(24, symbolic_equal(F, P24.expr.rhs) and F.shape == (6, 9) and shapes,
                 rf"`Robot.F` equals the printed block matrix for three units at general mount points (SymPy); shape "
                 rf"$2w\times(3+2w)$ for {wlist}", max_residual(F, P24.expr.rhs), convention="columns ordered as (25)"),
        equation(25, list(q) == list(P25.expr.rhs), r"`Robot.qdot_symbols` is the printed vector, the column order of "
                 r"$\mathbf F$", 0.0, convention="definition")])


def null_space_of_F(n=300, seed=SEED):
    r"""(26)-(27): :math:`\mathbf N = [\mathbf 1_3;\ \mathbf J_2^{-1}\mathbf J_1]` spans :math:`\mathcal N(\mathbf F)` exactly (d > 0).

    Parameters
    ----------
    n : int
        Random robots and configurations for the numeric check.
    seed : int

    Returns
    -------
    Derivation
        ``det_J2``, ``N``, findings (26) and (27).
    """
    P26, P27 = printed(26), printed(27)
    bot = general_robot()
    J1, J2, F = _exact(bot.J1()), bot.J2(), _exact(bot.F())
    blocks = [J2[2 * k:2 * k + 2, 2 * k:2 * k + 2] for k in range(3)]
    J2_inv = sp.diag(*[B.inv().applyfunc(sp.trigsimp) for B in blocks])
    det_J2 = sp.trigsimp(sp.prod([B.det() for B in blocks]))
    N = sp.Matrix.vstack(sp.eye(3), J2_inv * J1)
    exact = (symbolic_equal(J2 * J2_inv, sp.eye(6)) and symbolic_equal(F * N, sp.zeros(6, 3)) and N[:3, :] == sp.eye(3))
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
    return Derivation(det_J2=det_J2, N=N, nullities=nullities, findings=[
        equation(26, exact, r"$\mathbf N = [\mathbf 1_3;\ \mathbf J_2^{-1}\mathbf J_1]$ satisfies $\mathbf F\mathbf N = \mathbf 0$ "
                            rf"with $\det\mathbf J_2 = {sp.latex(det_J2)} \neq 0$ (SymPy); the SVD null vectors at {n} random "
                            r"configurations satisfy (21)", res, convention=r"$\dot{\mathbf q}$ ordered as (25); $d > 0$"),
        equation(27, exact and nullities == mob == {P27.extra["claim"]["nullity"]} and F.shape[1] == P27.extra["claim"]["q_dim"]
                 and F.shape[1] - P27.extra["claim"]["nullity"] == P27.extra["claim"]["rank_F"],
                 rf"the nullity from the SVD is 3 at all {n} random "
                 r"configurations and equals `wmr.mobility` (structured rank)", 0.0,
                 convention="definition (nullity = mobility)")])


def mobility_offset(n=200, seed=SEED):
    r"""Claim ``mobility-offset``: rank 6, nullity 3 and every twist admissible at every configuration when d > 0.

    Also what changes at d = 0: nullity 3 generically but pure steering (immobile platform), 4 with a
    one-dimensional family of twists when the axles are concurrent.

    Parameters
    ----------
    n : int
        Random steering configurations per case.
    seed : int

    Returns
    -------
    Derivation
        ``cases`` (rows for a table), finding ``mobility-offset``.
    """
    exact = null_space_of_F(n=1).findings[0]
    paper = paper_robot("offset", **PAPER)
    flat = paper_robot("offset", L=PAPER["L"], r=PAPER["r"], d=0.0)
    beta = np.random.default_rng(seed).uniform(-np.pi, np.pi, (n, 3))
    conc = steering_angles(paper_robot("centred", L=PAPER["L"], r=PAPER["r"]), [1.0, 0.2, -0.1])[None, :]
    cases = []
    for name, b, betas in ((f"$d > 0$, {n} random $\\boldsymbol\\beta$", paper, beta),
                           (f"$d = 0$, {n} random $\\boldsymbol\\beta$", flat, beta),
                           ("$d = 0$, axles concurrent", flat, conc)):
        nul = mobility(b, betas)
        cases.append({"case": name, r"rank $\mathbf F$": sorted(set((9 - nul).tolist())),
                      "nullity": sorted(set(nul.tolist())),
                      "admissible twists (dim)": sorted({admissible_twists(b, x).shape[1] for x in betas})})
    holds = (exact.printed_holds and cases[0]["nullity"] == [3] and cases[0]["admissible twists (dim)"] == [3])
    require(cases[1]["nullity"] == [3] and cases[1]["admissible twists (dim)"] == [0], "d = 0: nullity 3, immobile")
    require(cases[2]["nullity"] == [4] and cases[2]["admissible twists (dim)"] == [1], "d = 0, concurrent axles: nullity 4")
    return Derivation(cases=cases, findings=[claim(
        "mobility-offset", holds, r"for $d > 0$, $\mathbf N = [\mathbf 1_3;\ \mathbf J_2^{-1}\mathbf J_1]$ spans "
        r"$\mathcal N(\mathbf F)$ at every configuration (SymPy), so rank 6, nullity 3 and every twist admissible "
        rf"(confirmed at {n} random configurations)", exact.residual,
        convention=r"offset $d > 0$, any mount points, any steering angles",
        note=r"the count alone is not the whole story: at $d = 0$ the nullity is also 3 but the null space is pure "
             r"steering (the platform cannot move), and 4 with a one-dimensional family of twists when the axles are "
             r"concurrent")])


# ----------------------------------------------------------------------------------------------- drives locked
def locked_system(robot, beta):
    r"""The columns of :math:`\mathbf F` for the twist and the steering rates: :math:`\mathbf M(\boldsymbol\beta)` (drives locked).

    Parameters
    ----------
    robot : wmr.Robot
        Offset wheels.
    beta : array (..., w) or None (symbolic)

    Returns
    -------
    numpy.ndarray (..., 2w, 3 + w) or sympy.Matrix
    """
    F = robot.F(beta)
    keep = [c for c, name in enumerate(robot.qdot_names) if not name.startswith("theta_dot")]
    return F[:, keep] if isinstance(F, sp.MatrixBase) else F[..., keep]


def locked_motion(robot, beta):
    r"""The motion of a robot with locked drives: the null vector :math:`(\mathbf t, \dot\phi_1, \dots)` of :math:`\mathbf M`.

    Parameters
    ----------
    robot : wmr.Robot
    beta : array (w,)

    Returns
    -------
    numpy.ndarray (3 + w,)

    Raises
    ------
    ValueError
        When the locked system is not exactly one-dimensional (the steering jams, or the robot is degenerate).
    """
    Nn = null_space(locked_system(robot, np.asarray(beta, dtype=float)))
    if Nn.shape[1] != 1:
        raise ValueError(f"the locked system has nullity {Nn.shape[1]} at beta={np.asarray(beta).tolist()}, expected 1")
    return Nn[:, 0]


def concurrent_angles(robot, u):
    r"""Steering angles whose arm lines (through :math:`P_i` along :math:`\mathbf j_i`) all pass through the body point ``u``.

    Parameters
    ----------
    robot : wmr.Robot
    u : array (2,)

    Returns
    -------
    numpy.ndarray (w,)
    """
    v = robot.mount_points - np.asarray(u, dtype=float)
    return np.arctan2(-v[:, 0], v[:, 1])               # j_i = (-sin b, cos b) parallel to d_i - u


def locked_steering(robots=200, per=10, seed=SEED):
    r"""Can the robot steer with the drives locked?  :math:`\det\mathbf M = d^3\det[\mathbf d_i\times\mathbf j_i\ \ \mathbf j_i^{\mathrm T}]`.

    The rows :math:`(\mathbf d_i\times\mathbf j_i, \mathbf j_i^{\mathrm T})` are the Plücker coordinates of
    the arm lines; the determinant vanishes exactly when they are concurrent or all parallel.

    Parameters
    ----------
    robots, per : int
        Random robots, and random configurations of each, for the numeric rank of :math:`\mathbf M`.
    seed : int

    Returns
    -------
    Derivation
        ``det_M``, ``plucker`` (the rows :math:`(\mathbf d_i\times\mathbf j_i, \mathbf j_i^{\mathrm T})`),
        ``det_concurrent`` (lines 1, 2 through U, line 3 displaced by :math:`n_3`),
        ``det_parallel``, ``ranks`` (set), ``n`` (configurations), ``proven`` (bool).
    """
    bot = general_robot()
    M = locked_system(bot, None).applyfunc(sp.nsimplify)
    det_M = sp.factor(sp.expand(M.det(method="berkowitz")))
    A = sp.Matrix.vstack(*[rotation(b, SYMBOLIC)[:, 1].T * point_row(p, backend=SYMBOLIC) for p, b in zip(PO.D, S.beta)])
    plucker = symbolic_equal(det_M, S.d**3 * A.det())
    ux, uy, l1, l2, s3, n3 = sp.symbols("u_x u_y lambda_1 lambda_2 s_3 n_3", real=True)
    u = sp.Matrix([ux, uy])
    Rb = [rotation(b, SYMBOLIC) for b in S.beta]
    lines = [u + l1 * Rb[0][:, 1], u + l2 * Rb[1][:, 1], u + s3 * Rb[2][:, 1] + n3 * Rb[2][:, 0]]
    sub = dict(zip(sum(PO.D, ()), sum((tuple(v) for v in lines), ())))
    det_conc = sp.factor(sp.trigsimp(sp.expand(det_M.subs(sub))))
    det_par = sp.simplify(det_M.subs({S.beta[1]: S.beta[0], S.beta[2]: S.beta[0]}))
    geometry = symbolic_equal(det_conc, -S.d**3 * n3 * sp.sin(S.beta[0] - S.beta[1])) and det_par == 0
    rng = np.random.default_rng(seed)
    ranks = set()
    for _ in range(robots):
        b = Robot([OffsetWheel(tuple(p), r=0.1, d=0.05) for p in rng.uniform(-1, 1, (3, 2))])
        ranks |= set(rank(locked_system(b, rng.uniform(-np.pi, np.pi, (per, 3)))).tolist())
    return Derivation(det_M=det_M, plucker=A.applyfunc(sp.factor), det_concurrent=det_conc, det_parallel=det_par,
                      ranks=ranks, n=robots * per, proven=plucker and geometry)


def drift_motions(u=(0.1, 0.05), beta_parallel=0.4, t_end=0.2, dt=0.002):
    r"""The two ways a locked robot can steer: parallel arms (a translation) and concurrent arms (a rotation about U).

    Parallel: :math:`\dot\psi = 0`, all :math:`\dot\phi_i` equal, :math:`\dot{\mathbf c} = -d\dot\phi\,\mathbf i_i`.
    Concurrent at U: :math:`\dot{\mathbf c} = -\dot\psi\mathbf E\mathbf u`, :math:`\dot\phi_i = \dot\psi\lambda_i/d`
    with :math:`\mathbf d_i - \mathbf u = \lambda_i\mathbf j_i` -- instantaneously only: kept up, it needs slip.

    Parameters
    ----------
    u : pair
        The point of concurrency (body frame).
    beta_parallel : float
        The common steering angle of the parallel case.
    t_end, dt : float
        Simulated time and step of both motions.

    Returns
    -------
    Derivation
        ``parallel`` and ``concurrent`` (dicts of the twist, the steering rates and the predicted values),
        ``slip_concurrent`` (slip at the start and the end), ``slip_parallel`` (max).
    """
    paper = paper_robot("offset", **PAPER)
    d = PAPER["d"]
    u = np.asarray(u, dtype=float)
    x_par = locked_motion(paper, np.full(3, beta_parallel))
    x_par = x_par / x_par[3]                                  # phi_dot_1 = 1
    beta_c = concurrent_angles(paper, u)
    x_con = locked_motion(paper, beta_c)
    x_con = x_con / x_con[0]                                  # psi_dot = 1
    lam = np.einsum("ij,ij->i", paper.mount_points - u, np.stack([-np.sin(beta_c), np.cos(beta_c)], -1))
    pred_par = np.array([0.0, *(-d * np.array([np.cos(beta_parallel), np.sin(beta_parallel)]))])
    require(np.allclose(x_par[:3], pred_par) and np.allclose(x_par[3:], 1), "parallel arms: a translation -d phi_dot i")
    require(np.allclose(x_con[1:3], -E() @ u) and np.allclose(x_con[3:], lam / d), "concurrent arms: rotation about U")
    r_con, r_par = np.zeros(6), np.zeros(6)
    r_con[0::2], r_par[0::2] = x_con[3:], x_par[3:]
    run_con = simulate(paper, r_con, beta_c, t_end=t_end, dt=dt)
    run_par = simulate(paper, r_par, np.full(3, beta_parallel), t_end=t_end, dt=dt)
    require(run_con.slip[0] < TOL < run_con.slip[-1] and run_par.slip.max() < TOL, "concurrent drift needs slip later")
    return Derivation(parallel={"twist": x_par[:3], "phi_dot": x_par[3:], "predicted": pred_par},
                      concurrent={"twist": x_con[:3], "phi_dot": x_con[3:], "predicted": np.r_[1.0, -E() @ u],
                                  "lambda_over_d": lam / d},
                      slip_concurrent=(float(run_con.slip[0]), float(run_con.slip[-1])), t_end=t_end,
                      slip_parallel=float(run_par.slip.max()))


def drift_of_c(n=100, origin=(0.06, -0.04), seed=SEED):
    r"""(28): sum the three block rows of (21) with :math:`\dot\theta_i = 0` and solve for :math:`\dot{\mathbf c}`.

    The printed form needs :math:`\sum_i\mathbf d_i = \mathbf 0` (C at the centroid of the mount
    points); in general :math:`\dot{\mathbf c}` gains :math:`-\tfrac{\dot\psi}{3}\mathbf E\sum_i\mathbf d_i`.
    Numerically, on genuine locked motions (concurrent arms): the paper's robot and the same robot
    with C moved to ``origin``.

    Parameters
    ----------
    n : int
        Random centres of rotation.
    origin : pair
        Where C is moved for the comparison.
    seed : int

    Returns
    -------
    Derivation
        ``c_dot`` (derived), ``extra`` (derived minus printed), ``off_centroid`` (the printed form's
        error with C moved), finding (28).
    """
    P = printed(28)
    bot = general_robot()
    J1, J2 = _exact(bot.J1()), bot.J2()
    t, th = sp.Matrix(bot.twist_symbols), sp.Matrix(bot.rate_symbols)
    locked = {s: 0 for s in S.theta_dot}
    rows = sum(((J1 * t - J2 * th).subs(locked)[2 * k:2 * k + 2, :] for k in range(3)), sp.zeros(2, 1))
    sol = sp.solve(list(rows), [S.x_dot, S.y_dot], dict=True)[0]
    c_dot = sp.Matrix([sol[S.x_dot], sol[S.y_dot]])
    extra = (c_dot - P.expr.rhs).applyfunc(sp.simplify)
    centroid = {PO.D[2][0]: -PO.D[0][0] - PO.D[1][0], PO.D[2][1]: -PO.D[0][1] - PO.D[1][1]}
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
    return Derivation(c_dot=c_dot.applyfunc(sp.factor), extra=extra, off_centroid=res_off, findings=[equation(
        28, holds, r"the sum of the block rows of (21) with $\dot\theta_i = 0$, solved for $\dot{\mathbf c}$, is the printed "
                   r"form when $\sum_i\mathbf d_i = \mathbf 0$ (SymPy); it holds on "
                   rf"{n} simulated drift motions of the paper's robot", res,
        convention=r"$\sum_i\mathbf d_i = \mathbf 0$ (C at the centroid of the $P_i$); $\dot{\mathbf c}$ in body components",
        note=r"in general $\dot{\mathbf c}$ gains $-\tfrac{\dot\psi}{3}\mathbf E\sum_i\mathbf d_i$: with C moved off the "
             rf"centroid the printed form is off by up to ${res_off:.2f}$ on the same motions. It holds on every solution, "
             r"but solutions exist only for concurrent or parallel arms (see the claim `drift`)")])


def drift_of_psi(n=100, seed=SEED):
    r"""(29): the printed quotient of two vectors, where it comes from, and the true drift rate of :math:`\psi`.

    Projecting (20) onto :math:`(\mathbf E\mathbf d_i)^{\mathrm T}` and summing with :math:`\dot\theta_i = 0`
    and :math:`\sum_i\mathbf d_i = \mathbf 0` gives :math:`\dot\psi`; the paper's route (multiplying by
    :math:`\dot{\mathbf c}^{\mathrm T}\mathbf E`) eliminates :math:`\dot{\mathbf c}`, not :math:`\dot\theta_i`.

    Parameters
    ----------
    n : int
        Random triangles (centroid at C) with random centres of rotation.
    seed : int

    Returns
    -------
    Derivation
        ``error`` (SymPy's message for vector / vector), ``a``, ``b``, ``c`` (coefficients of the
        projected sum), ``psi_dot`` (corrected), ``gap`` (error of the pseudo-inverse reading of the
        printed quotient), finding (29).
    """
    P = printed(29)
    try:
        P.extra["numerators"][0] / P.extra["divisors"][0]
        error = None
    except TypeError as e:
        error = f"{type(e).__name__}: {e}"
    bot = general_robot()
    J1, J2 = _exact(bot.J1()), bot.J2()
    t, th = sp.Matrix(bot.twist_symbols), sp.Matrix(bot.rate_symbols)
    cdot = sp.Matrix([S.x_dot, S.y_dot])
    locked = {s: 0 for s in S.theta_dot}
    proj = sp.expand(sum(((PO.E * sp.Matrix(p)).T * (J1 * t - J2 * th).subs(locked)[2 * k:2 * k + 2, :]
                          for k, p in enumerate(PO.D)), sp.zeros(1, 1))[0])
    a = sp.factor(proj.coeff(S.psi_dot))
    b = sp.Matrix([proj.coeff(S.x_dot), proj.coeff(S.y_dot)]).applyfunc(sp.factor)
    c = sp.collect(sp.expand(proj - a * S.psi_dot - (b.T * cdot)[0]), S.phi_dot)
    centroid = {PO.D[2][0]: -PO.D[0][0] - PO.D[1][0], PO.D[2][1]: -PO.D[0][1] - PO.D[1][1]}
    b_vanishes = symbolic_equal(b.subs(centroid), sp.zeros(2, 1))
    psi_dot = sp.expand((-(b.T * cdot)[0] - c).subs(centroid)) / sp.expand(a.subs(centroid))
    paper_route = symbolic_equal((cdot.T * PO.E * (J1 * t)[0:2, :])[0], -S.psi_dot * (cdot.T * sp.Matrix(PO.D[0]))[0])
    f = sp.lambdify([*sum(PO.D, ()), *S.beta, *S.phi_dot, S.d], psi_dot, "numpy")
    rng = np.random.default_rng(seed)
    res, gap = 0.0, 0.0
    for _ in range(n):
        pts = rng.uniform(-1, 1, (3, 2))
        pts -= pts.mean(0)
        robot = Robot([OffsetWheel(tuple(p), r=0.1, d=0.05) for p in pts])
        bc = concurrent_angles(robot, rng.uniform(-0.5, 0.5, 2))
        x = locked_motion(robot, bc)
        x = x / x[0]
        D = robot.mount_points
        terms = [rotation(bb) @ np.array([-p, 0.0]) for bb, p in zip(bc, x[3:])]
        reading = robot.wheels[0].d / 3 * sum(Dk @ tk / (Dk @ Dk) for Dk, tk in zip(D, terms))
        res = max(res, abs(x[0] - f(*D.ravel(), *bc, *x[3:], robot.wheels[0].d)))
        gap = max(gap, abs(x[0] - reading))
    corrected = (r"\dot\psi = \frac{d\sum_{i=1}^{3}(\mathbf E\mathbf d_i)^{\mathrm T}\mathbf R_{bwi}"
                 r"\begin{bmatrix}-\dot\phi_i\\ 0\end{bmatrix}}{\sum_{i=1}^{3}\mathbf d_i^{\mathrm T}\mathbf d_i}")
    return Derivation(error=error, a=a, b=b, c=c, psi_dot=psi_dot, gap=gap, findings=[equation(
        29, error is None, r"projecting (20) on $(\mathbf E\mathbf d_i)^{\mathrm T}$ and summing with $\dot\theta_i = 0$ "
                           r"gives the corrected form when $\sum_i\mathbf d_i = \mathbf 0$ (SymPy); it equals the true "
                           rf"$\dot\psi$ on {n} simulated drift motions of random triangles", res,
        refuted=r"the right side divides the 2-vector $\mathbf R_{bwi}[-\dot\phi_i\ \ 0]^{\mathrm T}$ by the 2-vector "
                r"$\mathbf d_i$, which SymPy rejects; read with $\mathbf d_i^{\mathrm T}/\|\mathbf d_i\|^2$ it is off by up "
                rf"to ${gap:.2f}$ rad/s when $\dot\psi = 1$",
        corrected=corrected, corrected_holds=b_vanishes and paper_route and res < TOL, severity="wrong",
        why=r"the printed form divides a vector by a vector; multiplying (20) by $\dot{\mathbf c}^{\mathrm T}\mathbf E$ "
            r"eliminates $\dot{\mathbf c}$, not $\dot\theta_i$",
        convention=r"$\dot\theta_i = 0$, $\sum_i\mathbf d_i = \mathbf 0$",
        note=r"for the paper's equilateral placement ($\mathbf d_i^{\mathrm T}\mathbf d_i = L^2$) the denominator is $3L^2$")])


def drift(row28, row29, n_locked=None):
    r"""Claim ``drift``: steering with the drives locked moves the platform -- a conditional that holds.

    With :math:`\dot\theta_i = 0` and :math:`\mathbf t = \mathbf 0`, (21) leaves
    :math:`\mathbf J_2[\dot\phi_i\ 0]^{\mathrm T} = \mathbf 0`, and :math:`\det\mathbf J_2 = d^3r^3 \neq 0`
    forces :math:`\dot\phi_i = 0`: whenever the wheels are steered without driving, the platform
    moves.  What fails is *free* steering: the locked system jams unless the arm lines are
    concurrent or parallel (:func:`locked_steering`).  The residual is that of (28) and (29).

    Parameters
    ----------
    row28, row29 : wmr.paper.ledger.Finding
        The findings of :func:`drift_of_c` and :func:`drift_of_psi`.
    n_locked : Derivation, optional
        :func:`locked_steering` (computed if not given).

    Returns
    -------
    Derivation
        finding ``drift``.
    """
    locked = n_locked or locked_steering()
    bot = general_robot()
    J2 = bot.J2()
    steer_only = sp.Matrix([S.phi_dot[0], 0, S.phi_dot[1], 0, S.phi_dot[2], 0])
    moved = J2 * steer_only                                   # = J1 t must vanish if t = 0
    sol = sp.solve(list(moved), list(S.phi_dot), dict=True)
    forced = sol == [{p: 0 for p in S.phi_dot}]
    det_J2 = sp.trigsimp(J2.det())
    holds = forced and symbolic_equal(det_J2, S.d**3 * S.r**3)
    return Derivation(findings=[claim(
        "drift", holds, r"with $\dot\theta_i = 0$ and $\mathbf t = \mathbf 0$, (21) leaves "
                        r"$\mathbf J_2[\dot\phi_1\ 0\ \dot\phi_2\ 0\ \dot\phi_3\ 0]^{\mathrm T} = \mathbf 0$, whose only "
                        r"solution is $\dot\phi_i = 0$ since $\det\mathbf J_2 = d^3r^3 \neq 0$ (SymPy): any steering "
                        r"without driving moves the platform, as (28) and (29) describe", max(row28.residual, row29.residual),
        convention=r"offset $d > 0$, non-collinear $P_i$; residual of rows (28) and (29)",
        note=r"what fails is free steering: with the drives locked the $6\times6$ system "
             r"$\mathbf M(\boldsymbol\beta)[\mathbf t;\dot{\boldsymbol\phi}] = \mathbf 0$ has "
             r"$\det\mathbf M = d^3\det[\mathbf d_i\times\mathbf j_i\ \ \mathbf j_i^{\mathrm T}]$"
             + (" (SymPy)" if locked.proven else "")
             + rf", nonzero (rank {sorted(locked.ranks)} at {locked.n} random configurations) unless the arm lines are "
               r"concurrent or all parallel; only then can the robot steer without driving, and the concurrent case "
               r"only instantaneously")])


# ----------------------------------------------------------------------------------------------- dead zone
def dead_zone(robot, beta0=0.4, T=2 * np.pi, steps=200):
    r"""Steer every unit one full turn with the drives locked; fit a circle to the path of C.

    Parameters
    ----------
    robot : wmr.Robot
        Offset wheels.
    beta0 : float
        The common initial steering angle.
    T : float
        Duration of the turn (s).
    steps : int

    Returns
    -------
    dict
        ``radius`` of the fitted circle, ``circle_fit`` (largest distance from it), ``contact_drift``
        (largest motion of a contact point), ``centre_minus_Cf`` (distance of the circle's centre from
        the centroid of the contacts), ``CCf_min``, ``CCf_max`` (range of :math:`|CC_f|`),
        ``psi_drift``, ``max_slip``.
    """
    rates = np.zeros(2 * robot.w)
    rates[0::2] = 2 * np.pi / T
    run = simulate(robot, rates, np.full(robot.w, beta0), t_end=T, dt=T / steps)
    C = run.pose[:, 1:]
    a, b, c = np.linalg.lstsq(np.c_[2 * C, np.ones(len(C))], (C**2).sum(1), rcond=None)[0]
    centre, radius = np.array([a, b]), float(np.sqrt(c + a * a + b * b))
    G = np.stack([run.unit_points(i, "H") for i in range(robot.w)], axis=1)
    Cf = G.mean(axis=1)
    return {"radius": radius, "circle_fit": float(np.abs(np.linalg.norm(C - centre, axis=1) - radius).max()),
            "contact_drift": float(np.ptp(G, axis=0).max()), "centre_minus_Cf": float(np.linalg.norm(centre - Cf[0])),
            "CCf_min": float(np.linalg.norm(C - Cf, axis=1).min()), "CCf_max": float(np.linalg.norm(C - Cf, axis=1).max()),
            "psi_drift": float(np.ptp(run.pose[:, 0])), "max_slip": float(run.slip.max())}


def dead_zone_claim(origin=(0.06, -0.04), steps=200):
    r"""Claim ``dead-zone``: C traces a circle of radius :math:`|CC_f| = d` about the fixed centroid of the contacts.

    Holds for the paper's robot (C at the centroid of the mount points); with C elsewhere the
    radius is still d but the centre is :math:`C_f + (C - \bar P)` and :math:`|CC_f|` varies.

    Parameters
    ----------
    origin : pair
        Where C is moved for the comparison.
    steps : int
        Integration steps of the turn.

    Returns
    -------
    Derivation
        ``on``, ``off`` (the two :func:`dead_zone` results), ``shift``, finding ``dead-zone``.
    """
    paper = paper_robot("offset", **PAPER)
    moved = paper.moved(origin=origin)
    d = PAPER["d"]
    on, off = dead_zone(paper, steps=steps), dead_zone(moved, steps=steps)
    shift = float(np.linalg.norm(moved.mount_points.mean(0)))
    holds = (abs(on["radius"] - d) < TOL and on["contact_drift"] < TOL and on["centre_minus_Cf"] < TOL
             and abs(on["CCf_max"] - d) < TOL and abs(on["CCf_min"] - d) < TOL and on["max_slip"] < TOL
             and on["psi_drift"] < TOL and on["circle_fit"] < TOL)
    require(abs(off["radius"] - d) < TOL and off["contact_drift"] < TOL and abs(off["centre_minus_Cf"] - shift) < TOL
            and abs(off["CCf_min"] - abs(shift - d)) < 1e-3 and abs(off["CCf_max"] - (shift + d)) < 1e-3,
            "with C off the centroid: radius d, centre shifted by |C - centroid|")
    res = max(abs(on["radius"] - d), on["centre_minus_Cf"], on["contact_drift"])
    return Derivation(on=on, off=off, shift=shift, findings=[claim(
        "dead-zone", holds, rf"`wmr.simulate` ({steps} RK4 steps), all units steered one full turn with the drives "
                            rf"locked: the contact points stay fixed, the platform does not turn, and C runs once around "
                            rf"a circle of radius $d$ about their centroid $C_f$, so $|CC_f| = d$ throughout", res,
        convention=r"all $\beta_i$ equal (parallel arms), C at the centroid of the $P_i$",
        note=rf"with C moved off the centroid by ${shift:.3f}$ the radius is still $d$, but the centre is "
             r"$C_f + (C - \bar P)$ and $|CC_f|$ runs from "
             rf"${off['CCf_min']:.3f}$ to ${off['CCf_max']:.3f}$")])
