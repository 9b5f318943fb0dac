r"""The platform, (1)-(5): the velocity of C in two bases, point velocities, E, the twist layout, the row of a point.

Chapter 1's checks live in :mod:`edition.checks.wheels`; this module holds one group of them.  Each check
takes what the chapter derived and compares it with the printed form and the package.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.model.backend import SYMBOLIC
from wmr.model.platform import E, point_row, point_velocity, rotation
from wmr.model.robot import Robot
from wmr.model.tolerance import TOL
from wmr.model.wheels import CentredWheel

from ... import symbols as S
from ...transcription import printed
from ...verify import SEED, max_residual, symbolic_equal
from .. import Derivation, equation, require

__all__ = ["centre_velocity", "platform_point", "skew_matrix", "twist_layout", "platform_row"]


def centre_velocity(i_B, j_B, n=500, seed=SEED):
    r"""(1): the velocity of C in body and in fixed components,
    :math:`\dot x\,\mathbf i + \dot y\,\mathbf j = \dot X\,\mathbf i_{\mathcal F} + \dot Y\,\mathbf j_{\mathcal F}`.

    The body axes in fixed components (``i_B``, ``j_B``: derived by turning :math:`\mathbf i_{\mathcal F}`,
    :math:`\mathbf j_{\mathcal F}` about :math:`\mathbf k` by :math:`\psi`) define the body components
    :math:`\dot x = \dot{\mathbf c}\cdot\mathbf i`, :math:`\dot y = \dot{\mathbf c}\cdot\mathbf j` of
    :math:`\dot{\mathbf c} = [\dot X\ \dot Y]^{\mathrm T}`; the printed identity holds when
    :math:`\dot x\,\mathbf i + \dot y\,\mathbf j`, with those components, is :math:`\dot{\mathbf c}` again.

    Parameters
    ----------
    i_B, j_B : sympy.Matrix (2, 1)
        The body axes in fixed-frame components, functions of ``S.psi``.
    n : int
        Random poses and velocities for the check of the package's body-to-fixed map.
    seed : int

    Returns
    -------
    Derivation
        ``body`` (the body components :math:`[\dot x\ \dot y]` of :math:`\dot{\mathbf c}`), finding (1).
    """
    P = printed(1)
    i_B, j_B = sp.Matrix(i_B), sp.Matrix(j_B)
    c_F = sp.Matrix([S.X_dot, S.Y_dot])
    body = sp.Matrix([c_F.dot(i_B), c_F.dot(j_B)])
    require(
        symbolic_equal(sp.Matrix([[i_B.dot(i_B), i_B.dot(j_B)], [j_B.dot(i_B), j_B.dot(j_B)]]), sp.eye(2))
        and sp.simplify(i_B[0] * j_B[1] - i_B[1] * j_B[0]) == 1,
        "the derived body axes are orthonormal and right-handed (i x j = k)",
    )
    subs = {S.x_dot: body[0], S.y_dot: body[1]}
    lhs, rhs = P.expr.lhs.subs(subs), P.expr.rhs
    holds = symbolic_equal(lhs, rhs) and symbolic_equal(i_B * body[0] + j_B * body[1], c_F)
    res = max_residual(lhs, rhs)
    # the package's map from body to fixed components (the pose rates of wmr.integrate: R(psi) [x_dot y_dot])
    rng = np.random.default_rng(seed)
    psi, v = rng.uniform(-np.pi, np.pi, n), rng.uniform(-2, 2, (n, 2))
    f = sp.lambdify([S.psi, S.x_dot, S.y_dot], i_B * S.x_dot + j_B * S.y_dot, "numpy")
    num = float(np.abs(np.einsum("nij,nj->ni", rotation(psi), v) - np.moveaxis(f(psi, *v.T)[:, 0], 0, -1)).max())
    require(num < TOL, "wmr.rotation(psi) maps body components to fixed components as the derived axes do")
    return Derivation(
        body=body,
        findings=[
            equation(
                1,
                holds,
                r"with $\mathbf i$, $\mathbf j$ the fixed axes turned by $\psi$ about $\mathbf k$ and "
                r"$\dot x = \dot{\mathbf c}\cdot\mathbf i$, $\dot y = \dot{\mathbf c}\cdot\mathbf j$, "
                r"$\dot x\,\mathbf i + \dot y\,\mathbf j = \dot X\,\mathbf i_{\mathcal F} + \dot Y\,\mathbf j_{\mathcal F}$ "
                rf"(SymPy); `wmr.rotation` maps body to fixed components alike at {n} random poses",
                max(res, num),
                convention=r"$\psi$ the angle from $\mathbf i_{\mathcal F}$ to $\mathbf i$, counter-clockwise positive; "
                r"$(\dot x, \dot y)$ body components, $(\dot X, \dot Y)$ fixed components of one vector",
            )
        ],
    )


def platform_point(p_dot, n=500, seed=SEED):
    r"""(2): velocity of a platform point, :math:`\dot{\mathbf c} + \dot\psi\mathbf k\times\mathbf d_i` (3D cross
    product).

    Parameters
    ----------
    p_dot : sympy.Matrix (2, 1)
        The derived velocity, in ``S.psi_dot``, ``S.c_dot`` and ``S.d_i``.
    n : int
        Random twists and points for the check of :func:`wmr.point_velocity`.
    seed : int

    Returns
    -------
    Derivation
        ``p_dot`` (the derived velocity), finding (2).
    """
    P = printed(2)
    p_dot = sp.Matrix(p_dot)
    holds = symbolic_equal(p_dot, P.expr.rhs)
    res = max_residual(p_dot, P.expr.rhs)
    rng = np.random.default_rng(seed)
    tw, dd = rng.uniform(-2, 2, (n, 3)), rng.uniform(-2, 2, (n, 2))
    f = sp.lambdify([S.psi_dot, S.x_dot, S.y_dot, *S.d_i], p_dot, "numpy")
    num = float(np.abs(point_velocity(tw, dd) - np.moveaxis(f(*tw.T, *dd.T)[:, 0], 0, -1)).max())
    require(num < TOL, "wmr.point_velocity equals the rigid-body velocity")
    return Derivation(
        p_dot=p_dot,
        findings=[
            equation(
                2,
                holds,
                rf"equal to $\dot{{\mathbf c}} + \dot\psi\,\mathbf k\times\mathbf d_i$ (3D cross product, SymPy); "
                rf"`wmr.point_velocity` agrees at {n} random twists and points",
                max(res, num),
                convention=r"$\dot\psi\times\mathbf d_i$ read as $(\dot\psi\mathbf k)\times\mathbf d_i$; body-frame components",
                note=r"the extraction's undefined middle term $\dot{\mathbf c}_w$ dropped; the relation is frame-free "
                r"because $\mathbf E$ commutes with rotations",
            )
        ],
    )


def skew_matrix(E_derived):
    r"""(3): :math:`\mathbf E` has columns :math:`\mathbf k\times\mathbf e_1, \mathbf k\times\mathbf e_2`.

    Parameters
    ----------
    E_derived : sympy.Matrix (2, 2)
        The matrix derived from the cross products.

    Returns
    -------
    Derivation
        ``E`` (derived), finding (3).
    """
    P = printed(3)
    E_derived = sp.Matrix(E_derived)
    M = P.expr.rhs
    holds = (
        symbolic_equal(E_derived, M) and symbolic_equal(M.T, -M) and symbolic_equal(rotation(sp.pi / 2, SYMBOLIC), M)
    )
    require(symbolic_equal(E(SYMBOLIC), E_derived), "wmr.E is the derived matrix")
    res = float(np.abs(E() - np.array(E_derived, dtype=float)).max())
    return Derivation(
        E=E_derived,
        findings=[
            equation(
                3,
                holds,
                r"the columns $\mathbf k\times\mathbf e_1$, $\mathbf k\times\mathbf e_2$ (SymPy); skew-symmetric and "
                r"equal to the rotation through $+90^\circ$; `wmr.E` is the same matrix",
                res,
                convention=r"$\mathbf k$ up, angles counter-clockwise positive",
            )
        ],
    )


def twist_layout():
    r"""(4): the twist is ordered :math:`[\dot\psi\ \dot x\ \dot y]`, as the package's generalised rates are.

    Returns
    -------
    Derivation
        ``names`` (the package's first three rate names), finding (4).
    """
    P = printed(4)
    bot = Robot([CentredWheel(S.d_i, r=S.r)])
    holds = list(bot.twist_symbols) == list(P.expr.rhs)
    return Derivation(
        names=bot.qdot_names[:3],
        findings=[
            equation(
                4,
                holds,
                r"`Robot.twist_symbols` is $[\dot\psi\ \dot x\ \dot y]$, the order used by "
                r"$\mathbf J_1$, $\mathbf F$ and the kinematics",
                0.0,
                convention=r"$\mathbf t = [\dot\psi\ \dot x\ \dot y]^{\mathrm T}$, $\dot{\mathbf c}$ in body components",
            )
        ],
    )


def platform_row(row, p_dot, n=5, samples=500, seed=SEED):
    r"""(5): the row :math:`[\mathbf E\mathbf d_i\ \ \mathbf 1]` against the printed matrix, (2) and ``point_row``.

    Parameters
    ----------
    row : sympy.Matrix (2, 3)
        The derived row.
    p_dot : sympy.Matrix (2, 1)
        The derived (2), which the row times the twist must equal.
    n : int
        Units of the numeric robot whose :math:`\mathbf J_1` is checked.
    samples : int
        Random twists.
    seed : int

    Returns
    -------
    Derivation
        ``row`` (2, 3), finding (5).
    """
    P = printed(5)
    row = sp.Matrix(row)
    bot = Robot([CentredWheel(S.d_i, r=S.r)])
    t = sp.Matrix(bot.twist_symbols)
    require(symbolic_equal(point_row(S.d_i, backend=SYMBOLIC), row), "wmr's point_row is the derived row")
    holds = (
        symbolic_equal(row, P.extra["matrix"])
        and symbolic_equal(row * t, p_dot)
        and symbolic_equal(sp.nsimplify(bot.J1()), P.extra["matrix"])
    )
    res = max_residual(row * t, P.expr.rhs)
    rng = np.random.default_rng(seed)
    tw, dd = rng.uniform(-2, 2, (samples, 3)), rng.uniform(-2, 2, (n, 2))
    J1 = Robot([CentredWheel(p, r=1.0) for p in dd]).J1()
    num = float(np.abs((tw[:, None, :] @ J1.T)[:, 0].reshape(-1, n, 2) - point_velocity(tw[:, None, :], dd)).max())
    require(num < TOL, "the numeric J1 times a twist equals wmr.point_velocity")
    return Derivation(
        row=row,
        findings=[
            equation(
                5,
                holds,
                r"the derived row, `point_row` and the blocks of `Robot.J1` equal the printed row, and the row "
                rf"times $\mathbf t$ equals the derived (2) (SymPy); the numeric $\mathbf J_1$ of a {n}-unit robot "
                rf"agrees with `wmr.point_velocity` at {samples} random twists",
                max(res, num),
                convention=r"$\mathbf t$ ordered as (4)",
            )
        ],
    )
