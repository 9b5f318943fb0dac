r"""Centred wheels, (51)-(57): kinematics, F, mobility and the isotropic kinematics.

Chapter 4's checks live in :mod:`edition.checks.centred`; this module holds one group of them.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.kinematics import forward, inverse
from wmr.analysis.linalg import rank
from wmr.analysis.mobility import rank_F, twist_constraints
from wmr.analysis.steering import steering_angles
from wmr.model.backend import SYMBOLIC
from wmr.model.platform import E
from wmr.model.robot import Robot
from wmr.model.robots import paper_robot
from wmr.model.wheels import CentredWheel, OffsetWheel

from ... import symbols as S
from ...algebra import explicit, numeric
from ...transcription import printed
from ...verify import SEED, max_residual, symbolic_equal
from .. import Derivation, claim, equation, require

__all__ = ["kinematics", "functional_matrix", "mobility_centred", "isotropic_kinematics"]


#: the numeric robot of this chapter (metres)
L_NUM, R_NUM = 0.4, 0.1
#: a general point U of the plane (body frame): the centre of a rotation
u_point = sp.Matrix(sp.symbols("u_x u_y", real=True))


def _blocks(robot):
    """The nonzero 2x1 blocks of a centred-wheel robot's J2 (one column per wheel)."""
    J2 = robot.J2()
    return [J2[2 * k : 2 * k + 2, k] for k in range(len(robot.wheels))]


def kinematics(lhs, rhs, robot):
    r"""Judge (51): the chapter's one-wheel no-slip equation against the printed one.

    Parameters
    ----------
    lhs, rhs : sympy.Matrix (2, 1)
        :math:`\mathbf J_1\mathbf t` and :math:`\mathbf J_2\dot\theta_i` of one centred wheel at
        :data:`edition.symbols.d_i`, derived in Chapter 4.
    robot : wmr.Robot
        The chapter's three centred wheels at general mount points: its ``J2`` must be the printed
        block-diagonal :math:`\mathbf J_2` (6, 3).

    Returns
    -------
    Derivation
        finding (51).
    """
    p51 = printed(51)
    J2 = robot.J2()
    off0 = OffsetWheel(S.d_i, r=S.r, d=sp.Integer(0))
    holds = (
        symbolic_equal(lhs - rhs, p51.expr.lhs - p51.expr.rhs)
        and symbolic_equal(J2, p51.extra["J2"])
        and symbolic_equal(off0.block(S.beta_i)[:, 1], CentredWheel(S.d_i, r=S.r).block(S.beta_i))
        and symbolic_equal(off0.block(S.beta_i)[:, 0], sp.zeros(2, 1))
    )
    res = max(max_residual(lhs - rhs, p51.expr.lhs - p51.expr.rhs), max_residual(J2, p51.extra["J2"]))
    return Derivation(
        findings=[
            equation(
                51,
                holds,
                r"the one-wheel robot's $\mathbf J_1\mathbf t = \mathbf J_2\dot\theta_i$ is the printed equation, "
                r"and `Robot.J2` of three wheels is the block-diagonal $\mathbf J_2$ that follows it (SymPy); the "
                r"offset-wheel block at $d = 0$ has a zero steering column",
                res,
                convention=r"$\dot{\mathbf h}_i = -r\dot\theta_i\mathbf j_i$, $\mathbf R_{bwi} = \mathbf R(\beta_i)$; contact "
                r"point at $P_i$",
            )
        ]
    )


def functional_matrix(F, robot):
    r"""Judge (52)-(53): the chapter's :math:`\mathbf F = [\mathbf J_1\ -\mathbf J_2]` against the printed matrix.

    Parameters
    ----------
    F : sympy.Matrix (6, 6)
        Derived in Chapter 4 (``robot.F()``).
    robot : wmr.Robot
        Three centred wheels at general mount points.

    Returns
    -------
    Derivation
        findings (52) and (53).
    """
    p52, p53 = printed(52), printed(53)
    q = sp.Matrix(robot.qdot_symbols)
    t = sp.Matrix(robot.twist_symbols)
    holds53 = list(q) == list(p53.expr.rhs) and symbolic_equal(
        F * q, robot.J1(sp.Integer(1)) * t - robot.J2() * sp.Matrix(robot.rate_symbols)
    )
    return Derivation(
        findings=[
            equation(
                52,
                symbolic_equal(F, p52.expr.rhs),
                r"`Robot.F` for general mount points equals the printed matrix "
                r"(SymPy): the wheel blocks are "
                r"$-\mathbf R_{bwi}[0\ \ -r]^{\mathrm T} = \mathbf R_{bwi}[0\ \ r]^{\mathrm T}$",
                max_residual(F, p52.expr.rhs),
                convention=r"$\mathbf F = [\mathbf J_1\ \ -\mathbf J_2]$",
            ),
            equation(
                53,
                holds53,
                r"`Robot.qdot_symbols` is the printed vector, and $\mathbf F\dot{\mathbf q} = "
                r"\mathbf J_1\mathbf t - \mathbf J_2\dot{\boldsymbol\theta}$ (SymPy)",
                0.0,
                convention=r"the column order of $\mathbf F$",
            ),
        ]
    )


def mobility_centred(A, axle, robot, n=20000, n_coord=300, grid=36, seed=SEED):
    r"""Judge claim ``mobility-centred``: rank F = 3 + rank A(β); 5 (mobility 1) iff the axle lines are concurrent or
    parallel.

    The chapter derives :math:`\mathbf A` by multiplying block row i of :math:`\mathbf F` by the axle
    :math:`\mathbf i_i`, which annihilates the wheel column :math:`-r\mathbf j_i`.  This function checks that
    step, the rows of :math:`\mathbf A\mathbf t` for a rotation and a translation, the :math:`2\times2` minors
    (rank A = 1 needs collinear mount points), and the ranks numerically.

    Parameters
    ----------
    A : sympy.Matrix (3, 3)
        Rows :math:`\mathbf i_i^{\mathrm T}[\mathbf E\mathbf d_i\ \mathbf 1]`, derived in Chapter 4.
    axle : list of 3 sympy.Matrix (2, 1)
        :math:`\mathbf i_i = \mathbf R(\beta_i)[1\ 0]^{\mathrm T}`.
    robot : wmr.Robot
        Three centred wheels at the general mount points :data:`edition.symbols.D`.
    n : int
        Random steering configurations.
    n_coord : int
        Random twists whose steering angles (axles through the IC) are tested.
    grid : int
        Grid points per angle of the exhaustive grid (``grid**3``).
    seed : int

    Returns
    -------
    Derivation
        ``summary`` (rows for a table), finding ``mobility-centred``.
    """
    cols = _blocks(robot)
    jdir = [-b / S.r for b in cols]
    beta = robot.beta_symbols
    require(
        all(symbolic_equal(a.T * b, sp.zeros(1, 1)) for a, b in zip(axle, cols, strict=True)),
        "the axle annihilates the wheel column",
    )
    require(
        all(symbolic_equal(a, E(SYMBOLIC) * b / S.r) for a, b in zip(axle, cols, strict=True)), "E b_i / r is the axle"
    )
    J1 = robot.J1(sp.Integer(1))
    require(
        symbolic_equal(A, sp.Matrix.vstack(*[axle[k].T * J1[2 * k : 2 * k + 2, :] for k in range(3)])),
        "A stacks the axle components of the rows of J1",
    )
    t_rot = sp.Matrix([S.psi_dot, *(-S.psi_dot * E(SYMBOLIC) * u_point)])
    t_tra = sp.Matrix([0, S.x_dot, S.y_dot])
    rot = symbolic_equal(
        A * t_rot, sp.Matrix([-S.psi_dot * (jdir[k].T * (sp.Matrix(S.D[k]) - u_point))[0] for k in range(3)])
    )
    tra = symbolic_equal(A * t_tra, sp.Matrix([(axle[k].T * t_tra[1:, :])[0] for k in range(3)]))
    m23 = sp.trigsimp(A[[0, 1], 1:].det())
    b_ = sp.Symbol("b", real=True)
    minors = symbolic_equal(m23, sp.sin(beta[1] - beta[0]))
    for k in (0, 1):  # beta_2 = beta_1 + k pi
        A12 = A[:2, :].subs({beta[0]: b_, beta[1]: b_ + k * sp.pi})
        m2 = sum(A12[:, list(c)].det() ** 2 for c in ((0, 1), (0, 2), (1, 2)))
        minors &= symbolic_equal(m2, ((jdir[0].subs(beta[0], b_).T * (sp.Matrix(S.D[0]) - sp.Matrix(S.D[1])))[0]) ** 2)
    bot = paper_robot("centred", L=L_NUM, r=R_NUM)
    rng = np.random.default_rng(seed)
    B = rng.uniform(-np.pi, np.pi, (n, 3))
    A_fun = sp.lambdify([*beta, *[s for d in S.D for s in d]], A, "numpy")
    A_num, _ = twist_constraints(bot, B[:300])
    res = max(
        float(np.max(np.abs(np.abs(np.array(A_fun(*b, *bot.mount_points.ravel()), dtype=float)) - np.abs(An))))
        for b, An in zip(B[:300], A_num, strict=True)
    )
    tw = np.vstack(
        [rng.normal(size=(n_coord * 2 // 3, 3)), np.c_[np.zeros(n_coord // 3), rng.normal(size=(n_coord // 3, 2))]]
    )
    Bc = steering_angles(bot, tw)
    require(
        np.array_equal(rank(bot.F(np.vstack([B[:300], Bc]))), rank_F(bot, np.vstack([B[:300], Bc]))),
        "the SVD rank of F equals wmr.rank_F",
    )
    g = np.linspace(-np.pi, np.pi, grid, endpoint=False)
    G = np.stack(np.meshgrid(g, g, g, indexing="ij"), axis=-1).reshape(-1, 3)
    line = Robot([CentredWheel((x, 0.0), r=R_NUM) for x in (-0.4, 0.1, 0.4)])
    r_rand, r_coord, r_grid = (set(rank_F(bot, x).tolist()) for x in (B, Bc, G))
    r_line = int(rank_F(line, [0.0, np.pi, 0.0]))
    summary = [
        {
            "configurations": f"random $\\boldsymbol\\beta$ ({n})",
            r"rank $\mathbf F$": r_rand,
            "mobility": {6 - x for x in r_rand},
        },
        {
            "configurations": f"axles through the IC of random twists ({len(tw)})",
            r"rank $\mathbf F$": r_coord,
            "mobility": {6 - x for x in r_coord},
        },
        {
            "configurations": f"grid of ${grid}^3$ angles",
            r"rank $\mathbf F$": r_grid,
            "mobility": {6 - x for x in r_grid},
        },
        {
            "configurations": "collinear $P_i$, axles on their line",
            r"rank $\mathbf F$": {r_line},
            "mobility": {6 - r_line},
        },
    ]
    holds = rot and tra and minors and r_rand == {6} and r_coord == {5} and r_grid == {5, 6} and r_line == 4
    return Derivation(
        summary=summary,
        findings=[
            claim(
                "mobility-centred",
                holds,
                r"$\operatorname{rank}\mathbf F = 3 + \operatorname{rank}\mathbf "
                r"A(\boldsymbol\beta)$; $\mathbf A\mathbf t = \mathbf 0$ for the rotation about $U$ iff $U$ is on every axle "
                r"line, for a translation iff the axles are parallel; the $2\times2$ minors of $\mathbf A$ vanish only for "
                r"parallel axles through collinear mount points (SymPy). Numerically: rank 6 at "
                f"{n} random configurations, 5 at the steering angles of {len(tw)} random twists, 5 or 6 on a ${grid}^3$ grid, "
                "4 only for collinear mount points",
                res,
                convention="three centred wheels at non-collinear mount points",
                note=r"the residual compares $\mathbf A(\boldsymbol\beta)$ derived here with "
                r"`twist_constraints` (rows up to sign)",
            )
        ],
    )


def isotropic_kinematics(J2tJ2, J, pinv_JL1, pinv_J2, paper, n=25, seed=SEED):
    r"""Judge (54)-(57): :math:`\mathbf J_2^{\mathrm T}\mathbf J_2 = r^2\mathbf 1`; (55), (57) are least-squares maps
    through :math:`\mathbf J = \mathbf J_{L1}^{\mathrm T}\mathbf J_2`.

    Parameters
    ----------
    J2tJ2 : sympy.Matrix (3, 3)
        :math:`\mathbf J_2^{\mathrm T}\mathbf J_2` for general mount points, derived in Chapter 4.
    J : sympy.Matrix (3, 3)
        :math:`\mathbf J_{L1}^{\mathrm T}\mathbf J_2` of the paper's placement (symbolic L, r).
    pinv_JL1 : sympy.Matrix (3, 6)
        :math:`(\mathbf J_{L1}^{\mathrm T}\mathbf J_{L1})^{-1}\mathbf J_{L1}^{\mathrm T}`.
    pinv_J2 : sympy.Matrix (3, 6)
        :math:`(\mathbf J_2^{\mathrm T}\mathbf J_2)^{-1}\mathbf J_2^{\mathrm T}`.
    paper : wmr.Robot
        ``wmr.paper_robot("centred", L=S.L, r=S.r, exact=True)``.
    n : int
        Random configurations (random and coordinated angles).
    seed : int

    Returns
    -------
    Derivation
        ``exact_random`` (forward, inverse cases without slip at random angles), ``exact_coordinated``,
        ``n``, findings (54)-(57).
    """
    p54, p55, p56, p57 = (printed(i) for i in (54, 55, 56, 57))
    JL1p, J2p = paper.J1(S.L), paper.J2()
    require(symbolic_equal(J, paper.J(L=S.L)), "J_L1^T J_2 is Robot.J")
    th = sp.Matrix(paper.rate_symbols)
    tLs = sp.Matrix(sp.symbols("t_L1:4", real=True))
    holds56 = symbolic_equal(J, explicit(p56.expr.rhs, {S.JL1: JL1p, S.J2_centred: J2p}))
    holds55 = symbolic_equal(pinv_JL1, JL1p.T / 3) and symbolic_equal(
        explicit(p55.expr.rhs, {S.J: J, S.theta_dot_centred: th}), pinv_JL1 * J2p * th
    )
    holds57 = symbolic_equal(pinv_J2, J2p.T / S.r**2) and symbolic_equal(
        explicit(p57.expr.rhs, {S.J: J, S.tL: tLs}), pinv_J2 * JL1p * tLs
    )
    bot = paper_robot("centred", L=L_NUM, r=R_NUM)
    scale = np.diag([L_NUM, 1.0, 1.0])
    rng = np.random.default_rng(seed)
    res55 = res57 = res_exact = 0.0
    fw_ok = inv_ok = coord_ok = 0
    for _ in range(n):
        b = rng.uniform(-np.pi, np.pi, 3)
        Jn = bot.J(b, L=L_NUM)
        thr = rng.normal(size=3)
        fw = forward(bot, b, thr)
        t55 = np.linalg.solve(scale, numeric(p55.expr.rhs, {S.J: Jn, S.theta_dot_centred: thr[:, None]})[:, 0])
        tw = rng.normal(size=3)
        inv = inverse(bot, b, tw)
        th57 = numeric(p57.expr.rhs.subs(S.r, R_NUM), {S.J: Jn, S.tL: (scale @ tw)[:, None]})[:, 0]
        res55 = max(res55, float(np.max(np.abs(t55 - fw.value))))
        res57 = max(res57, float(np.max(np.abs(th57 - inv.value))))
        fw_ok, inv_ok = fw_ok + int(fw.admissible), inv_ok + int(inv.admissible)
        bc = steering_angles(bot, tw)
        Jc = bot.J(bc, L=L_NUM)
        thc = numeric(p57.expr.rhs.subs(S.r, R_NUM), {S.J: Jc, S.tL: (scale @ tw)[:, None]})[:, 0]
        back = np.linalg.solve(scale, numeric(p55.expr.rhs, {S.J: Jc, S.theta_dot_centred: thc[:, None]})[:, 0])
        ic = inverse(bot, bc, tw)
        coord_ok += int(ic.admissible and forward(bot, bc, thc).admissible)
        res_exact = max(res_exact, float(np.max(np.abs(back - tw))), float(np.max(np.abs(ic.residual))))
    require(fw_ok == inv_ok == 0 and coord_ok == n, "random data need slip; coordinated data are exact")
    return Derivation(
        exact_random=(fw_ok, inv_ok),
        exact_coordinated=coord_ok,
        n=n,
        findings=[
            equation(
                54,
                symbolic_equal(J2tJ2, p54.expr.rhs),
                r"$\mathbf J_2$ has orthogonal columns $-r\mathbf j_i$ in "
                r"disjoint rows, so $\mathbf J_2^{\mathrm T}\mathbf J_2 = r^2\mathbf 1$ for every $\boldsymbol\beta$ "
                r"and placement (SymPy)",
                max_residual(J2tJ2, p54.expr.rhs),
                convention=r"any $\boldsymbol\beta$, any mount points ($\mathbf J_2$ is $6\times3$, so "
                r"$\mathbf J_2^{\mathrm T}\mathbf J_2$ is the right product)",
            ),
            equation(
                55,
                holds55 and res55 < 1e-9 and res_exact < 1e-9,
                r"$\mathbf J_{L1}^{+} = \tfrac13\mathbf J_{L1}^{\mathrm T}$ (SymPy), so (55) is the least-squares "
                r"twist: it equals `wmr.forward` at "
                f"{n} random configurations, and is exact for the rates of an admissible motion at coordinated "
                "angles",
                max(res55, res_exact),
                convention=r"least-squares twist ($\mathbf J_{L1}^{+} = \mathbf J_{L1}^{\mathrm T}/3$, isotropic "
                r"placement); exact only for compatible rates at coordinated angles",
                note="at generic angles the mobility is 0 and random rates always need slip",
            ),
            equation(
                56,
                holds56,
                r"`Robot.J` equals $\mathbf J_{L1}^{\mathrm T}\mathbf J_2$ of the paper's placement "
                r"(SymPy)",
                0.0,
                convention=r"$\mathbf J_{L1}$ of (32) with the isotropic $L$",
            ),
            equation(
                57,
                holds57 and res57 < 1e-9,
                r"$\mathbf J_2^{+} = \mathbf J_2^{\mathrm T}/r^2$ by (54) (SymPy), so (57) is the least-squares joint "
                r"rate: it equals `wmr.inverse` at "
                f"{n} random configurations, and is exact with the steering angles of "
                "`wmr.steering_angles`",
                max(res57, res_exact),
                convention=r"least-squares rates; exact iff the twist is admissible "
                r"($\mathbf A\mathbf t = \mathbf 0$)",
            ),
        ],
    )
