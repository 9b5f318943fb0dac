r"""The drives locked: the system M(beta), its motion, and when the robot can steer.

Chapter 2's checks live in :mod:`edition.checks.assembly`; this module holds one group of them.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.integration import integrate
from wmr.analysis.linalg import null_space, rank
from wmr.model.backend import SYMBOLIC
from wmr.model.platform import E, rotation
from wmr.model.robot import Robot
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL
from wmr.model.wheels import OffsetWheel

from ... import symbols as S
from ...verify import SEED, symbolic_equal
from .. import Derivation, require
from .matrices import PAPER, general_robot

__all__ = ["locked_system", "locked_motion", "concurrent_angles", "locked_steering", "drift_motions"]


def locked_system(robot, beta):
    r"""The columns of :math:`\mathbf F` for the twist and the steering rates: :math:`\mathbf M(\boldsymbol\beta)`
    (drives locked).

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
    r"""The motion of a robot with locked drives: the null vector :math:`(\mathbf t, \dot\phi_1, \dots)` of
    :math:`\mathbf M`.

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
    r"""Steering angles whose arm lines (through :math:`P_i` along :math:`\mathbf j_i`) all pass through the body point
    ``u``.

    Parameters
    ----------
    robot : wmr.Robot
    u : array (2,)

    Returns
    -------
    numpy.ndarray (w,)
    """
    v = robot.mount_points - np.asarray(u, dtype=float)
    return np.arctan2(-v[:, 0], v[:, 1])  # j_i = (-sin b, cos b) parallel to d_i - u


def locked_steering(det_M, plucker, robots=200, per=10, seed=SEED):
    r"""Can the robot steer with the drives locked?

    :math:`\det\mathbf M = d^3\det[\mathbf d_i\times\mathbf j_i\ \ \mathbf j_i^{\mathrm T}]`.

    The rows :math:`(\mathbf d_i\times\mathbf j_i, \mathbf j_i^{\mathrm T})` are the Plücker coordinates of
    the arm lines; the determinant vanishes exactly when they are concurrent or all parallel.

    Parameters
    ----------
    det_M : SymPy expression
        The derived :math:`\det\mathbf M` of three units at the mount points ``S.D`` and angles ``S.beta``.
    plucker : sympy.Matrix (3, 3)
        The derived rows :math:`\mathbf j_i^{\mathrm T}[\mathbf E\mathbf d_i\ \ \mathbf 1]`.
    robots, per : int
        Random robots, and random configurations of each, for the numeric rank of :math:`\mathbf M`.
    seed : int

    Returns
    -------
    Derivation
        ``det_concurrent`` (lines 1, 2 through U, line 3 displaced by :math:`n_3`),
        ``det_parallel``, ``ranks`` (set), ``n`` (configurations), ``proven`` (bool).
    """
    M = locked_system(general_robot(), None).applyfunc(sp.nsimplify)
    require(symbolic_equal(M.det(method="berkowitz"), det_M), "det M of wmr's F is the derived determinant")
    plucker_ok = symbolic_equal(det_M, S.d**3 * plucker.det())
    ux, uy, l1, l2, s3, n3 = sp.symbols("u_x u_y lambda_1 lambda_2 s_3 n_3", real=True)
    u = sp.Matrix([ux, uy])
    Rb = [rotation(b, SYMBOLIC) for b in S.beta]
    lines = [u + l1 * Rb[0][:, 1], u + l2 * Rb[1][:, 1], u + s3 * Rb[2][:, 1] + n3 * Rb[2][:, 0]]
    sub = dict(zip(sum(S.D, ()), sum((tuple(v) for v in lines), ()), strict=True))
    det_conc = sp.factor(sp.trigsimp(sp.expand(det_M.subs(sub))))
    det_par = sp.simplify(det_M.subs({S.beta[1]: S.beta[0], S.beta[2]: S.beta[0]}))
    geometry = symbolic_equal(det_conc, -(S.d**3) * n3 * sp.sin(S.beta[0] - S.beta[1])) and det_par == 0
    rng = np.random.default_rng(seed)
    ranks = set()
    for _ in range(robots):
        b = Robot([OffsetWheel(tuple(p), r=0.1, d=0.05) for p in rng.uniform(-1, 1, (3, 2))])
        ranks |= set(rank(locked_system(b, rng.uniform(-np.pi, np.pi, (per, 3)))).tolist())
    return Derivation(
        det_concurrent=det_conc, det_parallel=det_par, ranks=ranks, n=robots * per, proven=plucker_ok and geometry
    )


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
    x_par = x_par / x_par[3]  # phi_dot_1 = 1
    beta_c = concurrent_angles(paper, u)
    x_con = locked_motion(paper, beta_c)
    x_con = x_con / x_con[0]  # psi_dot = 1
    lam = np.einsum("ij,ij->i", paper.mount_points - u, np.stack([-np.sin(beta_c), np.cos(beta_c)], -1))
    pred_par = np.array([0.0, *(-d * np.array([np.cos(beta_parallel), np.sin(beta_parallel)]))])
    require(np.allclose(x_par[:3], pred_par) and np.allclose(x_par[3:], 1), "parallel arms: a translation -d phi_dot i")
    require(np.allclose(x_con[1:3], -E() @ u) and np.allclose(x_con[3:], lam / d), "concurrent arms: rotation about U")
    r_con, r_par = np.zeros(6), np.zeros(6)
    r_con[0::2], r_par[0::2] = x_con[3:], x_par[3:]
    run_con = integrate(paper, r_con, beta_c, t_end=t_end, dt=dt)
    run_par = integrate(paper, r_par, np.full(3, beta_parallel), t_end=t_end, dt=dt)
    require(run_con.slip[0] < TOL < run_con.slip[-1] and run_par.slip.max() < TOL, "concurrent drift needs slip later")
    return Derivation(
        parallel={"twist": x_par[:3], "phi_dot": x_par[3:], "predicted": pred_par},
        concurrent={
            "twist": x_con[:3],
            "phi_dot": x_con[3:],
            "predicted": np.r_[1.0, -E() @ u],
            "lambda_over_d": lam / d,
        },
        slip_concurrent=(float(run_con.slip[0]), float(run_con.slip[-1])),
        t_end=t_end,
        slip_parallel=float(run_par.slip.max()),
    )
