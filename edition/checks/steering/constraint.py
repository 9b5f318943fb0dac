r"""The no-slip constraint of a centred wheel and the feasibility of a twist.

Chapter 5's checks live in :mod:`edition.checks.steering`; this module holds one group of them.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.kinematics import inverse
from wmr.analysis.linalg import rank
from wmr.analysis.mobility import rank_F, twist_constraints
from wmr.analysis.steering import AT_INFINITY, FINITE, STILL
from wmr.model.backend import SYMBOLIC
from wmr.model.platform import rotation
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL

from ... import symbols as S
from ...verify import SEED, symbolic_equal
from .. import require

__all__ = ["robot", "TWIST", "no_slip", "feasibility", "evaluate", "KIND_NAMES"]


#: names of the kinds of :func:`wmr.instantaneous_centre`
KIND_NAMES = {FINITE: "finite", AT_INFINITY: "at infinity", STILL: "undefined (still)"}


def robot():
    """The paper's three-centred-wheel robot of this chapter (L = 0.4 m, r = 0.1 m).

    Returns
    -------
    wmr.Robot
    """
    return paper_robot("centred", L=0.4, r=0.1)


def evaluate(expr, syms, *cols):
    """Evaluate a SymPy expression (array (...)) or column vector (array (..., k)) on arrays.

    Parameters
    ----------
    expr : sympy.Expr or sympy.Matrix (k, 1)
    syms : sequence of Symbol
    *cols : arrays
        One per symbol, broadcast together.

    Returns
    -------
    numpy.ndarray
    """
    exprs = list(expr) if isinstance(expr, sp.MatrixBase) else [expr]
    vals = sp.lambdify(syms, exprs, "numpy")(*cols)
    out = np.stack(np.broadcast_arrays(*[np.asarray(v, dtype=float) for v in vals]), axis=-1)
    return out if isinstance(expr, sp.MatrixBase) else out[..., 0]


#: the twist :math:`[\dot\psi\ \dot x\ \dot y]^{\mathrm T}` (symbols of :class:`wmr.Robot`)
TWIST = sp.Matrix([S.psi_dot, S.x_dot, S.y_dot])


def no_slip(g, beta, J2, n=2000, seed=SEED):
    r"""Check the chapter's no-slip scalar :math:`g_i` of one centred wheel against the package.

    The axle :math:`\mathbf i_i` must annihilate the wheel's block of :math:`\mathbf J_2` and
    :math:`\mathbf j_i` must give :math:`-r`; the three :math:`g_i` of the paper's robot must be the rows of
    ``twist_constraints`` (up to sign) at random configurations.

    Parameters
    ----------
    g : sympy.Expr
        :math:`\mathbf i_i^{\mathrm T}[\mathbf E\mathbf d_i\ \ \mathbf 1]\mathbf t` for a wheel at
        :math:`(d_x, d_y)` with steering angle ``beta``, derived in Chapter 5.
    beta : sympy.Symbol
    J2 : sympy.Matrix (2, 1)
        The wheel's block.
    n : int
    seed : int

    Returns
    -------
    float
        The largest difference (checked below ``TOL``).
    """
    axle = rotation(beta, SYMBOLIC) * sp.Matrix([1, 0])
    roll = rotation(beta, SYMBOLIC) * sp.Matrix([0, 1])
    require(symbolic_equal(axle.T * J2, sp.zeros(1, 1)), "the wheel cannot move P_i along its axle")
    require(symbolic_equal(roll.T * J2, sp.Matrix([[-S.r]])), "the wheel rolls P_i along j_i at -r theta_dot")
    bot = robot()
    rng = np.random.default_rng(seed)
    B, T = rng.uniform(-np.pi, np.pi, (n, 3)), rng.normal(size=(n, 3))
    A, base = twist_constraints(bot, B)
    d = bot.mount_points
    g_num = np.stack([evaluate(g, (beta, S.dx, S.dy, *TWIST), B[:, i], d[i, 0], d[i, 1], *T.T) for i in range(3)], -1)
    res = float(np.max(np.abs(np.abs(g_num) - np.abs(np.einsum("nij,nj->ni", A, T)))))
    require(res < TOL and base == 3, "g_i are the rows of the twist constraints")
    return res


def feasibility(beta, twist, bot=None):
    r"""Can ``twist`` be executed without slip at steering angles ``beta``?  A summary over a batch.

    Parameters
    ----------
    beta : array (..., 3)
    twist : array (..., 3)
    bot : wmr.Robot, optional
        Default :func:`robot`.

    Returns
    -------
    dict
        ``rank_F``, ``rank_J2``, ``rank_J2_J1t`` (sets of the ranks of :math:`\mathbf F`, :math:`\mathbf J_2`
        and :math:`[\mathbf J_2\ \ \mathbf J_1\mathbf t]`), ``admissible`` (fraction), ``min_rel_residual``
        (smallest slip relative to the speed of the mount points), ``max_residual``.
    """
    bot = bot or robot()
    sol = inverse(bot, beta, twist)
    J2 = bot.J2(beta)
    J1t = np.asarray(twist) @ bot.J1().T
    speed = np.linalg.norm(J1t, axis=-1)
    return {
        "rank_F": set(np.atleast_1d(rank_F(bot, beta)).tolist()),
        "rank_J2": set(np.atleast_1d(rank(J2)).tolist()),
        "rank_J2_J1t": set(np.atleast_1d(rank(np.concatenate([J2, J1t[..., None]], -1))).tolist()),
        "admissible": float(np.mean(sol.admissible)),
        "min_rel_residual": float(np.min(np.linalg.norm(sol.residual, axis=-1) / speed)),
        "max_residual": float(np.max(np.abs(sol.residual))),
    }
