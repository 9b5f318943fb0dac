r"""Singular configurations, (58): :math:`\det\mathbf J` as the wheel-plane lines make it, and the printed determinant.

Chapter 4's checks live in :mod:`edition.checks.centred`; this module holds one group of them (the paper's
list (59) is :mod:`edition.checks.centred.zero_set`).
"""

from __future__ import annotations

import re

import numpy as np
import sympy as sp

from wmr.analysis.linalg import condition_number
from wmr.model.backend import SYMBOLIC
from wmr.model.platform import E
from wmr.model.robot import Robot
from wmr.model.robots import equilateral_mounts, paper_robot
from wmr.model.wheels import CentredWheel

from ... import symbols as S
from ...transcription import printed
from ...verify import SEED, max_residual, symbolic_equal
from .. import Derivation, equation, require
from .mobility import L_NUM, R_NUM, u_point

__all__ = ["singular_configurations", "printed_determinant", "factored_sum"]


def singular_configurations(det_J, lines, robot, n=20000, seed=SEED):
    r"""Judge (58): :math:`\det\mathbf J = -\tfrac{r^3}{L}\det[\mathbf i_i^{\mathrm T}\ \ \mathbf i_i\cdot\mathbf d_i]`:
    zero iff the wheel-plane lines are concurrent or parallel.

    Parameters
    ----------
    det_J : sympy.Expr
        :math:`\det\mathbf J` for general mount points, derived in Chapter 4.
    lines : sympy.Matrix (3, 3)
        Rows :math:`[\mathbf i_i^{\mathrm T}\ \ \mathbf i_i\cdot\mathbf d_i]`: the wheel-plane lines.
    robot : wmr.Robot
        Three centred wheels at the general mount points :data:`edition.symbols.D`.
    n : int
        Random configurations (:math:`\kappa` finite there) and parallel ones (:math:`\kappa = \infty`).
    seed : int

    Returns
    -------
    Derivation
        finding (58).
    """
    axle = [sp.Matrix(lines[k, :2]).T for k in range(3)]
    Jg = robot.J(L=S.L)
    require(symbolic_equal(det_J, Jg.det()), "det_J is the determinant of Robot.J")
    tL_rot = sp.Matrix([S.L * S.psi_dot, *(-S.psi_dot * E(SYMBOLIC) * u_point)])
    rows = symbolic_equal(
        Jg.T * tL_rot, sp.Matrix([-S.r * S.psi_dot * (axle[k].T * (sp.Matrix(S.D[k]) - u_point))[0] for k in range(3)])
    )
    holds = rows and symbolic_equal(det_J, -(S.r**3) / S.L * lines.det())
    bot = paper_robot("centred", L=L_NUM, r=R_NUM)
    B = np.random.default_rng(seed).uniform(-np.pi, np.pi, (n, 3))
    k_par = condition_number(bot.J(np.c_[B[:, :1], B[:, :1] + np.pi, B[:, :1]], L=L_NUM))
    k_gen = condition_number(bot.J(B, L=L_NUM))
    require(np.all(np.isinf(k_par)) and np.all(np.isfinite(k_gen)), "kappa is infinite exactly on the singular set")
    return Derivation(
        findings=[
            equation(
                58,
                holds,
                r"$\mathbf J^{\mathrm T}\mathbf t_L$ of the rotation about $U$ has rows "
                r"$-r\dot\psi\,\mathbf i_i\cdot(\mathbf d_i - \mathbf u)$, and "
                r"$\det\mathbf J = -\tfrac{r^3}{L}\det[\mathbf i_i^{\mathrm T}\ \ \mathbf i_i\cdot\mathbf d_i]$ for "
                r"general mount points (SymPy): zero iff the wheel-plane lines are concurrent or all parallel; "
                rf"$\kappa(\mathbf J)$ is infinite on {n} parallel configurations and finite on {n} random ones",
                max_residual(det_J, -(S.r**3) / S.L * lines.det()),
                convention=r"$\mathbf J = \mathbf J_{L1}^{\mathrm T}\mathbf "
                r"J_2$ (56), three centred wheels",
            )
        ]
    )


def printed_determinant(det_J, n=200, seed=SEED):
    r"""Judge (59): which placement and numbering the printed determinant belongs to, and the missing factor
    :math:`r^3`.

    Every equilateral placement with a vertex at a multiple of :math:`30^\circ` and both numbering
    senses is compared with :math:`\pm` the printed form at random angles; then the chapter's
    :math:`\det\mathbf J` of the paper's placement is compared exactly, with symbolic L and r.

    Parameters
    ----------
    det_J : sympy.Expr
        :math:`\det\mathbf J` of ``wmr.paper_robot("centred", L=S.L, r=S.r, exact=True)``, derived in Chapter 4.
    n : int
        Random steering configurations.
    seed : int

    Returns
    -------
    Derivation
        ``placements`` (rows: first vertex, sense, errors against +/- (59)), ``matches`` (those that
        hold with the printed sign), finding (59).
    """
    p59 = printed(59)
    f59 = sp.lambdify(S.beta, p59.expr.rhs.subs(S.r, 1), "numpy")  # the search robots have r = 1
    Bs = np.random.default_rng(seed).uniform(-np.pi, np.pi, (n, 3))
    P59 = f59(*Bs.T)
    rows: list[dict] = []
    for first in range(0, 360, 30):
        for cw in (True, False):
            rb = Robot([CentredWheel(q, r=1.0) for q in equilateral_mounts(1.0, first, cw)])
            dJ = np.linalg.det(rb.J(Bs, L=1.0))
            rows.append(
                {
                    "first": first,
                    "sense": "clockwise" if cw else "counter-clockwise",
                    "plus": float(np.max(np.abs(dJ - P59))),
                    "minus": float(np.max(np.abs(dJ + P59))),
                }
            )
    matches = [(x["first"], x["sense"]) for x in rows if x["plus"] < 1e-9]
    paper = paper_robot("centred", L=S.L, r=S.r, exact=True)
    require(symbolic_equal(det_J, paper.J(L=S.L).det()), "det_J is the determinant of the paper's J")
    det_paper = sp.expand(sp.expand_trig(det_J))
    holds = symbolic_equal(det_paper, p59.expr.rhs)
    r3 = (
        symbolic_equal(det_paper, S.r**3 * p59.expr.rhs)
        and S.L not in det_paper.free_symbols
        and symbolic_equal(det_paper.subs(S.r, 1), p59.expr.rhs)
    )
    return Derivation(
        placements=rows,
        matches=matches,
        findings=[
            equation(
                59,
                holds,
                r"for the paper's placement, $\det\mathbf J$ with symbolic $L$ and $r$ is $r^3$ times the printed "
                r"form and does not depend on $L$ (SymPy)",
                max_residual(det_paper, S.r**3 * p59.expr.rhs),
                refuted=r"the printed form is $\det\mathbf J$ at $r = 1$ only",
                corrected=factored_sum(
                    p59.latex,
                    r"\det(\mathbf "
                    r"J)",
                    "r^3",
                    per_line=2,
                ),
                corrected_holds=r3 and len(matches) == 1,
                severity="typo",
                overturn=(
                    r"another numbering or placement of the wheels (24 were tried, and only the one stated gives the "
                    r"printed signs), or a unit wheel radius $r = 1$ assumed without being stated: then the printed form "
                    r"is exact"
                ),
                why=r"the factor $r^3$ is missing: the printed form is the determinant for $r = 1$",
                convention=rf"wheel 1 at $L(-1, 0)$, numbered clockwise: $\mathbf d_2 = L(\tfrac12, \tfrac{{\sqrt3}}{{2}})$, "
                rf"$\mathbf d_3 = L(\tfrac12, -\tfrac{{\sqrt3}}{{2}})$, the only one of the {len(rows)} placements "
                r"tried that gives the printed sign; $\det\mathbf J$ does not depend on $L$",
            )
        ],
    )


def factored_sum(latex, lhs, factor, per_line):
    r"""A printed sum ``\begin{aligned}lhs = &t_1 + t_2 ...\end{aligned}`` as ``lhs = factor(...)``, ``per_line`` terms
    a line.

    The terms are taken from the printed LaTeX as they are (split before each top-level `` + ``
    or `` - ``), so the corrected form shows the printed terms, in the printed order.

    Parameters
    ----------
    latex : str
        The printed form, an ``aligned`` body whose right side is a sum.
    lhs : str
        LaTeX of the left side to print.
    factor : str
        LaTeX of the factor, e.g. ``"r^3"``.
    per_line : int
        Terms per line.

    Returns
    -------
    str
        A LaTeX body (no ``$``).

    Examples
    --------
    >>> factored_sum(r"\begin{aligned}y = &- a + b\\ &- c\end{aligned}", "y", "k", 2)
    '\\begin{aligned}y = k\\Big(&- a + b\\\\ &- c\\Big)\\end{aligned}'
    """
    body = latex.removeprefix(r"\begin{aligned}").removesuffix(r"\end{aligned}")
    terms = re.split(r" (?=[+-] )", body.split(" = &", 1)[1].replace(r"\\ &", " "))
    lines = [" ".join(terms[i : i + per_line]) for i in range(0, len(terms), per_line)]
    return rf"\begin{{aligned}}{lhs} = {factor}\Big(&" + r"\\ &".join(lines) + r"\Big)\end{aligned}"
