r"""Chapter 2 exercises (offset wheels and mobility): checks that say whether an answer is right and why not.

See :mod:`edition.exercises` for how the checks are used.
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.linalg import rank
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL

from ..verify import symbolic_equal
from .feedback import Feedback, as_matrix, missing

__all__ = ["locked_steering", "drift_of_c_general"]


def locked_steering(beta, robot=None):
    r"""Exercise 2.1: steering angles, not all parallel, at which the robot can steer with its drives locked.

    Parameters
    ----------
    beta : array (3,) or None
        Steering angles of the paper's offset-wheel robot (radians).
    robot : wmr.Robot, optional
        Default ``wmr.paper_robot("offset", L=0.3, r=0.1, d=0.05)``.

    Returns
    -------
    Feedback
    """
    from ..checks.assembly import PAPER, locked_system
    fb = missing(beta, "three steering angles")
    if fb is not None:
        return fb
    robot = robot or paper_robot("offset", **PAPER)
    beta = np.asarray(beta, dtype=float)
    if beta.shape != (robot.w,):
        return Feedback(False, f"Give {robot.w} angles.")
    nullity = robot.w + 3 - int(rank(locked_system(robot, beta)))
    if nullity == 0:
        return Feedback(False, r"At these angles the locked system has only the zero solution: the steering jams. "
                               r"The arm lines (through $P_i$ along $\mathbf j_i$) must meet in one point.")
    if np.all(np.abs(np.sin(beta - beta[0])) <= TOL):
        return Feedback(False, "All arms are parallel: that is the translation of Fig. 7. Find the other family.")
    from ..checks.assembly import locked_motion
    x = locked_motion(robot, beta)
    x = x / x[0] if abs(x[0]) > TOL else x
    U = np.array([-x[2], x[1]]) if abs(x[0]) > TOL else None        # c_dot = -psi_dot E u  =>  u = E c_dot / psi_dot
    where = (f"about $U = ({U[0]:.3g}, {U[1]:.3g})$" if U is not None else "")
    return Feedback(True, rf"The locked robot can steer here: its arm lines are concurrent, and it turns {where} "
                          r"(instantaneously: held longer, it needs slip).")


def drift_of_c_general(answer):
    r"""Exercise 2.2: :math:`\dot{\mathbf c}` of the locked robot for general mount points (C anywhere).

    The answer is a SymPy 2-vector in :data:`edition.symbols` (``d``, ``beta``, ``phi_dot``, ``psi_dot``)
    and the mount points :data:`edition.symbols.D`.

    Parameters
    ----------
    answer : sympy.Matrix (2, 1) or None

    Returns
    -------
    Feedback
    """
    from ..checks.assembly import drift_of_c
    from ..transcription import printed
    M, fb = as_matrix(answer, (2, 1), r"the 2-vector $\dot{\mathbf c}$")
    if fb is not None:
        return fb
    truth = drift_of_c(n=1).c_dot
    if symbolic_equal(M, truth):
        return Feedback(True, r"$\dot{\mathbf c} = \frac d3\sum_i\mathbf R_{bwi}[-\dot\phi_i\ \ 0]^{\mathrm T} - "
                              r"\frac{\dot\psi}{3}\mathbf E\sum_i\mathbf d_i$: the printed (28) is the case "
                              r"$\sum_i\mathbf d_i = \mathbf 0$.")
    if symbolic_equal(M, printed(28).expr.rhs):
        return Feedback(False, r"That is the printed (28), which assumes $\sum_i\mathbf d_i = \mathbf 0$. Keep the "
                               r"platform rows $\dot\psi\mathbf E\mathbf d_i$ when you sum.")
    return Feedback(False, r"Sum the three block rows of $\mathbf J_1\mathbf t = \mathbf J_2\dot{\boldsymbol\theta}$ "
                           r"with $\dot\theta_i = 0$ and solve for $\dot x, \dot y$; your answer differs from it by "
                           f"${sp.latex(sp.simplify(M - truth).T)}^{{\\mathrm T}}$.")
