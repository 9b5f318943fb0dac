r"""Chapter 2's exercises (assembly, mobility, drift), on the fair-check framework (:mod:`.framework`).

======  ===========================  ======================================================================
number  check                        the exercise
======  ===========================  ======================================================================
2.1     :func:`locked_steering`      steering angles, not all parallel, at which the locked robot can steer
2.2     :func:`drift_of_c_general`   :math:`\dot{\mathbf c}` of a locked robot with four offset wheels
======  ===========================  ======================================================================

The expected values come from the package (``wmr.Robot.J1``, ``J2``; the arm lines of the units),
not from the chapter's derivation, which covers three wheels.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.model.robot import Robot
from wmr.model.robots import Dimensions, paper_robot
from wmr.model.wheels import OffsetWheel

from .. import symbols as S
from ..text import number
from . import answers
from .feedback import right, undecided, wrong
from .framework import exercise
from .symbolic import compare, equivalent
from .tolerance import within

__all__ = [
    "locked_steering",
    "drift_of_c_general",
    "PAPER_2_1",
    "TOL_2_1",
    "D4",
    "BETA4",
    "PHI_DOT4",
    "SYMBOLS_2_2",
    "locked_c_dot",
]

#: 2.1: the paper's offset-wheel robot of the chapter
PAPER_2_1 = Dimensions(L=0.3, r=0.1, d=0.05)
#: 2.1: every arm line within 1e-3 rad of passing through one point
TOL_2_1 = within("to within $10^{-3}$ rad", abs=1e-3)
#: 2.2: the symbols of the four-wheel robot (the student's own are mapped onto these by name)
D4 = tuple((sp.Symbol(f"d_{{{k}x}}", real=True), sp.Symbol(f"d_{{{k}y}}", real=True)) for k in range(1, 5))
BETA4 = tuple(sp.Symbol(f"beta{k}", real=True) for k in range(1, 5))
PHI_DOT4 = tuple(sp.Symbol(rf"\dot{{\phi}}_{{{k}}}", real=True) for k in range(1, 5))
SYMBOLS_2_2 = (*sum(D4, ()), *BETA4, *PHI_DOT4, S.d, S.psi_dot)
_WHAT_2_2 = r"the 2-vector $\dot{\mathbf c}$ (a SymPy `Matrix`)"


def _arms(beta, robot):
    """Unit directions j_i of the arm lines (through P_i) and the point closest to all of them (least squares)."""
    j = np.stack([-np.sin(beta), np.cos(beta)], -1)
    n = np.stack([np.cos(beta), np.sin(beta)], -1)  # normals i_i
    P = robot.mount_points.astype(float)
    u, *_ = np.linalg.lstsq(n, np.einsum("ij,ij->i", n, P), rcond=None)
    return j, n, P, u


@exercise("2.1", answer="three steering angles in radians", tolerance=TOL_2_1, units={"beta": "rad"})
def locked_steering(beta):
    r"""Exercise 2.1: steering angles of the paper's offset-wheel robot, not all parallel, at which it can steer
    with its drives locked (the arm lines concurrent).

    Parameters
    ----------
    beta : array (3,)
        Radians.

    Returns
    -------
    Result
    """
    b = answers.angles(beta, 3, "rad")
    robot = paper_robot("offset", **PAPER_2_1)
    j, n, P, u = _arms(b, robot)
    cross = np.abs(j[:, None, 0] * j[None, :, 1] - j[:, None, 1] * j[None, :, 0])  # |sin| between arm pairs
    if cross.max() <= TOL_2_1.abs:
        return wrong(
            "All three arms are parallel: then the robot can steer with its drives locked, but it only "
            "translates. The exercise asks for arms that are not all parallel."
        )
    dist = np.abs(np.einsum("ij,ij->i", n, P - u))  # distance of each arm line from u
    reach = np.linalg.norm(P - u, axis=1)
    tilt = np.arcsin(np.minimum(1.0, dist / np.maximum(reach, 1e-300)))
    if float(tilt.max()) <= TOL_2_1.abs:
        where = f"$({number(u[0], 3)}, {number(u[1], 3)})$ m"
        return right(
            rf"The three arm lines meet at {where} (body frame): the platform turns about that point while "
            r"the units steer with the drives locked, for an instant only, as the chapter shows."
        )
    return wrong(
        r"The arm lines (through $P_i$ along $\mathbf j_i$) do not meet in one point and are not all "
        r"parallel: $\det\mathbf M \neq 0$ and the steering jams."
    )


def locked_c_dot(points, betas, phi_dots):
    r""":math:`\dot{\mathbf c}` of a locked robot of offset wheels at ``points`` (symbols), from ``wmr.Robot``.

    The block rows of :math:`\mathbf J_1\mathbf t = \mathbf J_2\dot{\boldsymbol\theta}` with
    :math:`\dot\theta_i = 0`, summed and solved for :math:`(\dot x, \dot y)`.

    Parameters
    ----------
    points : sequence of (Symbol, Symbol)
    betas, phi_dots : sequence of Symbol
        Steering angles and rates, one per unit.

    Returns
    -------
    sympy.Matrix (2, 1)
    """
    bot = Robot([OffsetWheel(p, r=S.r, d=S.d) for p in points])
    w = len(points)
    rates = sp.Matrix([x for k in range(w) for x in (phi_dots[k], 0)])
    residual = bot.J1() * sp.Matrix(bot.twist_symbols) - bot.J2(list(betas)) * rates
    rows = sum((residual[2 * k : 2 * k + 2, :] for k in range(w)), sp.zeros(2, 1))
    sol = sp.solve(list(rows), [S.x_dot, S.y_dot], dict=True)[0]
    return sp.Matrix([sol[S.x_dot], sol[S.y_dot]])


@exercise("2.2", answer=_WHAT_2_2)
def drift_of_c_general(answer):
    r"""Exercise 2.2: :math:`\dot{\mathbf c}` of the locked robot with four offset wheels at general mount points.

    Parameters
    ----------
    answer : sympy.Matrix (2, 1)
        In the symbols :data:`SYMBOLS_2_2` (or the student's own of the same names).

    Returns
    -------
    Result
    """
    truth = locked_c_dot(D4, BETA4, PHI_DOT4)
    M, same = compare(answer, truth, SYMBOLS_2_2, _WHAT_2_2)
    if same:
        return right(
            r"$\dot{\mathbf c} = \frac d4\sum_i\mathbf R_{bwi}[-\dot\phi_i\ \ 0]^{\mathrm T} - "
            r"\frac{\dot\psi}{4}\mathbf E\sum_i\mathbf d_i$: with C at the centroid of the four mount points "
            r"the last term drops, as in (28)."
        )
    if same is None:
        return undecided(
            "This check cannot tell whether your expression equals the drift (it could not be "
            "simplified or evaluated); write it with `sp.sin`, `sp.cos` and the exercise's symbols."
        )
    if equivalent(M, truth * sp.Rational(4, 3)):
        return wrong("You divided by 3, as for three wheels: here the sum has four block rows.")
    if equivalent(M, truth.subs(S.psi_dot, 0)):
        return wrong(
            r"The steering part is right, but the platform rows $\dot\psi\,\mathbf E\mathbf d_i$ are missing: "
            r"(28) drops them only when C is the centroid of the mount points."
        )
    if equivalent(M.subs(S.psi_dot, 0), truth.subs(S.psi_dot, 0)):
        return wrong(r"The steering part is right; the platform part (the terms in $\dot\psi$) is not.")
    return wrong(
        r"Sum the four block rows of $\mathbf J_1\mathbf t = \mathbf J_2\dot{\boldsymbol\theta}$ with "
        r"$\dot\theta_i = 0$ and solve for $\dot x$ and $\dot y$."
    )
