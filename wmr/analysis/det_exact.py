r"""The exact side of :math:`\det\mathbf J` (58)-(59): its SymPy derivation, its polynomial form, and the
wheel-plane-line identity :math:`\det\mathbf J = -(r_1r_2r_3/L)\det\mathbf W` (see :mod:`wmr.analysis.singularities`
for the numeric side: batched determinants, singularity tests and the classification).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.backend import NUMERIC, SYMBOLIC, Backend, choose
from ..model.lazysympy import is_sympy, sp
from ..model.robot import Robot
from ..model.types import Matrix, Numbers, Point, Symbolic
from ..model.wheels import CentredWheel
from .square import default_L, exact_robot, require_square

__all__ = ["det_J_symbolic", "det_J_polynomial", "exact_zero", "plane_line_matrix", "characterisation"]


def det_J_symbolic(robot: Robot, L: Numbers | None = None) -> Symbolic:
    r"""Exact :math:`\det\mathbf J` as a SymPy expression in the robot's :math:`\beta_i` symbols.

    Derived from :meth:`wmr.Robot.J`, expanded into a polynomial in :math:`\cos\beta_i,\sin\beta_i`
    (of degree one in each wheel's pair) and factored.

    Parameters
    ----------
    robot : Robot
        Numeric (use ``paper_robot(..., exact=True)`` for exact coefficients) or symbolic.
    L : float or sympy.Expr, optional

    Returns
    -------
    sympy.Expr
    """
    require_square(robot)
    robot = exact_robot(robot)
    L = default_L(robot, L, numeric=False)
    if isinstance(L, float):
        L = sp.nsimplify(L, [sp.sqrt(2), sp.sqrt(3)])
    J = robot.J(None, L=L)
    return sp.factor(sp.expand(sp.expand_trig(J.det())))


def plane_line_matrix(robot: Robot, beta: Numbers, L: Numbers = 1, backend: Backend | None = None) -> Matrix:
    r"""The matrix :math:`\mathbf W` whose columns are the Plücker vectors of the wheel-plane lines.

    Column i is :math:`[m_i/L,\ \mathbf j_i^T]^T`.

    :math:`m_i = \mathbf d_i^T\mathbf i_i = \mathbf d_i\times\mathbf j_i` is the moment of the line
    about C.  For three centred wheels :math:`\mathbf J = -\mathbf W\,\mathrm{diag}(r_i)`.

    Parameters
    ----------
    robot : Robot
    beta : array (..., w) or sequence of SymPy expressions (None: the symbols)
    L : float or sympy.Expr
    backend : NUMERIC or SYMBOLIC, optional
        Default: SymPy when ``beta`` is None or symbolic or the robot is symbolic, else NumPy.

    Returns
    -------
    numpy.ndarray (..., 3, w) or sympy.Matrix (3, w)
    """
    symbolic = (
        beta is None
        or validation.robot(robot).is_symbolic
        or any(is_sympy(b) for b in np.ravel(np.asarray(beta, dtype=object)))
    )
    bk = choose(backend=backend) if backend is not None else (SYMBOLIC if symbolic else NUMERIC)
    if symbolic and bk is NUMERIC:
        raise InputValueError(
            f"backend NUMERIC needs numeric beta and a numeric robot, got beta = {validation.show(beta)}, "
            f"robot = {validation.show(robot)}"
        )
    symbolic = bk is SYMBOLIC
    if symbolic:
        b = list(robot.beta_symbols) if beta is None else list(validation.symbolic_vector("beta", beta, robot.w))
        b = [
            bi if u.steered else sp.sympify(u.constant_angle)  # unsteered: its own angle
            for bi, u in zip(b, robot.wheels)
        ]
    else:
        beta = validation.robot(robot).effective_beta(beta)
        b = [beta[..., i] for i in range(robot.w)]
    L = validation.positive("L", L) if symbolic else validation.number("L", validation.positive("L", L))
    columns = []
    with np.errstate(over="ignore", invalid="ignore"):
        for u, bi in zip(robot.wheels, b):
            jx, jy = -bk.sin(bi), bk.cos(bi)  # j_i = R_bwi [0 1]^T, (11)
            px, py = u.position
            columns.append([(px * jy - py * jx) / L, jx, jy])  # [m_i / L, j_i], m_i = d_i x j_i
        W = bk.matrix([list(row) for row in zip(*columns)])
    if bk is NUMERIC and not np.isfinite(W).all():
        raise InputValueError(f"L = {L!r} is too small for the mount points: the moments m_i / L overflow")
    return W


def characterisation(robot: Robot, L: Numbers | None = None) -> dict[str, Any]:
    r"""Exact statements about the zero set of :math:`\det\mathbf J`, derived from the model.

    Parameters
    ----------
    robot : Robot
        Three centred wheels, numeric (made exact with :func:`exact_robot`) or symbolic.
    L : float or sympy.Expr, optional
        Characteristic length; default a positive symbol ``L`` for a symbolic robot, else
        :func:`wmr.characteristic_length`.

    Returns
    -------
    dict
        ``"det_J"``: the factored :math:`\det\mathbf J` of ``robot``;
        ``"lines_form"``: :math:`-(r_1r_2r_3/L)\sum_{\rm cyc} m_i\sin(\beta_k-\beta_j)`;
        ``"identity_general"``: True when :math:`\det\mathbf J = -(r_1r_2r_3/L)\det\mathbf W`
        holds exactly for three centred wheels at **symbolic** mount points;
        ``"identity_robot"``: the same identity for ``robot``;
        ``"independent_of_L"``: True when ``det_J`` does not contain the symbol L;
        ``"irreducible"``: True when the trilinear form has no factor other than constants.
    """
    require_square(robot)
    Ls = sp.Symbol("L", positive=True)
    if L is None:
        L = Ls if robot.is_symbolic else default_L(robot, None)

    def lines_form(bot, L):
        b = bot.beta_symbols
        m = [u.position[0] * sp.cos(bi) + u.position[1] * sp.sin(bi) for u, bi in zip(bot.wheels, b)]
        rr = sp.Mul(*[u.r for u in bot.wheels])
        return -(rr / L) * (m[0] * sp.sin(b[2] - b[1]) + m[1] * sp.sin(b[0] - b[2]) + m[2] * sp.sin(b[1] - b[0]))

    xs, ys = sp.symbols("x1:4", real=True), sp.symbols("y1:4", real=True)
    rs = sp.symbols("r1:4", positive=True)
    gen = Robot([CentredWheel((x, y), r=ri) for x, y, ri in zip(xs, ys, rs)])
    gdet = gen.J(None, L=Ls).det()
    ident_general = sp.expand(sp.expand_trig(gdet - lines_form(gen, Ls))) == 0
    ident_w = sp.expand(sp.expand_trig(gdet + sp.Mul(*rs) * plane_line_matrix(gen, None, Ls).det())) == 0
    det = det_J_symbolic(robot, L)
    lf = lines_form(robot, L)
    ident_robot = sp.expand(sp.expand_trig(det - lf)) == 0
    # irreducibility: write det J as a polynomial in c_i, s_i and factor over Q(sqrt 3)
    cs = sp.symbols("c1:4 s1:4", real=True)
    b = robot.beta_symbols
    poly = sp.expand(sp.expand_trig(det)).subs(
        {**{sp.cos(bi): cs[i] for i, bi in enumerate(b)}, **{sp.sin(bi): cs[3 + i] for i, bi in enumerate(b)}}
    )
    fl = sp.factor_list(sp.expand(poly), extension=sp.sqrt(3))
    nontrivial = [f for f, _ in fl[1] if f.free_symbols & set(cs)]
    return {
        "det_J": det,
        "lines_form": lf,
        "identity_general": bool(ident_general and ident_w),
        "identity_robot": bool(ident_robot),
        "independent_of_L": Ls not in det.free_symbols,
        "irreducible": len(nontrivial) == 1,
        "polynomial": poly,
    }


def det_J_polynomial(
    robot: Robot, L: Numbers | None = None
) -> tuple[Symbolic, tuple[Symbolic, ...], tuple[Symbolic, ...]]:
    r""":math:`\det\mathbf J` as a polynomial in :math:`c_i = \cos\beta_i`, :math:`s_i = \sin\beta_i`.

    Of degree 1 in each pair :math:`(c_i, s_i)`.

    Parameters
    ----------
    robot : Robot
        Three centred wheels (made exact with :func:`exact_robot`).
    L : float or sympy.Expr, optional
        As for :func:`det_J_symbolic`.

    Returns
    -------
    poly : sympy.Expr
    c, s : tuple of 3 sympy.Symbol
        The symbols :math:`c_i`, :math:`s_i`.
    """
    det = sp.expand(sp.expand_trig(det_J_symbolic(robot, L)))
    c = sp.symbols("c1:4", real=True)
    s = sp.symbols("s1:4", real=True)
    b = robot.beta_symbols
    poly = det.subs({**{sp.cos(bi): c[i] for i, bi in enumerate(b)}, **{sp.sin(bi): s[i] for i, bi in enumerate(b)}})
    return sp.expand(poly), c, s


def exact_zero(poly: Symbolic, c: Sequence[Symbolic], s: Sequence[Symbolic], dirs: Sequence[Point]) -> bool:
    r"""True when the polynomial form of :math:`\det\mathbf J` vanishes identically on a parameterised family.

    :math:`\det\mathbf J` is homogeneous of degree one in each wheel's :math:`(\cos\beta_i,\sin\beta_i)`,
    so substituting unnormalised axle directions multiplies it by a non-zero factor: the zero test
    is exact without square roots.

    Parameters
    ----------
    poly, c, s : sympy.Expr, tuples of sympy.Symbol
        From :func:`det_J_polynomial`.
    dirs : list of 3 pairs of sympy.Expr
        Axle direction of each wheel (unnormalised), in the family's free symbols.

    Returns
    -------
    bool
    """
    e = poly.subs({**{c[i]: dirs[i][0] for i in range(3)}, **{s[i]: dirs[i][1] for i in range(3)}}, simultaneous=True)
    e = sp.expand(sp.expand_trig(e))
    if e == 0:
        return True
    num, _ = sp.fraction(sp.cancel(sp.together(e)))
    return sp.expand(num) == 0 or sp.simplify(e) == 0
