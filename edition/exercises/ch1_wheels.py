r"""Chapter 1 exercises (platform and wheels): checks that say whether an answer is right and why not.

See :mod:`edition.exercises` for how the checks are used.
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.kinematics import inverse
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL
from wmr.model.wheels import DualWheel

from .. import symbols as S
from ..verify import symbolic_equal
from .feedback import Feedback, as_matrix, missing

__all__ = ["offset_other_side", "dual_counterexample", "dual_spin_in_place"]


def offset_other_side(answer):
    r"""Exercise 1.1: the velocity of :math:`P_i` when the wheel centre is at :math:`H_i = P_i + d\,\mathbf j_i`.

    The answer is the fixed-frame 2-vector in the symbols of :mod:`edition.symbols`
    (:math:`\phi_i`, :math:`\dot\phi_i`, :math:`\dot\theta_i`) and :math:`r, d`.

    Parameters
    ----------
    answer : sympy.Matrix (2, 1) or None

    Returns
    -------
    Feedback
    """
    from ..checks.wheels import disk_velocity, k, planar
    M, fb = as_matrix(answer, (2, 1), r"the 2-vector $\dot{\mathbf p}_i$")
    if fb is not None:
        return fb
    disk = disk_velocity(S.theta_dot_i)
    truth = planar(disk.h_dot + (S.phi_dot_i * k).cross(-S.d * disk.j3))       # P - H = -d j
    if symbolic_equal(M, truth):
        return Feedback(True, r"With the centre ahead of the steering axis the steering term changes sign: "
                              r"$\dot{\mathbf p}_i = -r\dot\theta_i\mathbf j_i + d\dot\phi_i\mathbf i_i$.")
    printed_side = planar(disk.h_dot + (S.phi_dot_i * k).cross(S.d * disk.j3))
    if symbolic_equal(M, printed_side):
        return Feedback(False, r"That is (9) itself, the centre at $P_i - d\,\mathbf j_i$. Here "
                               r"$P_i - H_i = -d\,\mathbf j_i$: redo the cross product "
                               r"$\dot\phi_i\mathbf k\times(P_i - H_i)$.")
    if not symbolic_equal(M.subs(S.phi_dot_i, 0), truth.subs(S.phi_dot_i, 0)):
        return Feedback(False, r"The rolling term is off: the wheel centre moves as (6), $-r\dot\theta_i\mathbf j_i$.")
    return Feedback(False, r"Start from $\dot{\mathbf p}_i = \dot{\mathbf h}_i + \dot\phi_i\mathbf k\times(P_i - H_i)$ "
                           r"with $\dot{\mathbf h}_i$ from (6) and $P_i - H_i = -d\,\mathbf j_i$; your answer differs "
                           r"by "
                           f"${sp.latex(sp.simplify(M - truth))}$.")


def dual_counterexample(beta, twist, robot=None):
    r"""Exercise 1.2: a slip-free motion with the units locked (:math:`\dot\beta_i = 0`) for which the printed (15)
    predicts :math:`\dot\beta_i \neq 0`.

    Parameters
    ----------
    beta : array (3,) or None
        Steering angles of the paper's dual-wheel robot (radians), held fixed.
    twist : array (3,) or None
        The platform twist :math:`(\dot\psi, \dot x, \dot y)`.
    robot : wmr.Robot, optional
        Default ``wmr.paper_robot("dual", L=0.5, r=0.1, b=0.08)``.

    Returns
    -------
    Feedback
    """
    fb = missing(None if beta is None or twist is None else 0, "steering angles `beta` and a `twist`")
    if fb is not None:
        return fb
    robot = robot or paper_robot("dual", L=0.5, r=0.1, b=0.08)
    beta, twist = np.asarray(beta, dtype=float), np.asarray(twist, dtype=float)
    if beta.shape != (robot.w,) or twist.shape != (3,):
        return Feedback(False, f"`beta` must have {robot.w} angles and `twist` 3 components.")
    if not np.any(twist):
        return Feedback(False, "The robot must move: a zero twist predicts nothing.")
    sol = inverse(robot, beta, twist)
    if not bool(sol.admissible):
        return Feedback(False, r"At these angles the twist needs sideways slip: every axle must pass through the "
                               r"instantaneous centre (try `wmr.steering_angles(robot, twist)`).")
    printed = [-u.r / (2 * u.b) * (sol.value[sl][0] - sol.value[sl][1]) for u, sl in zip(robot.wheels,
                                                                                         robot.rate_slices,
                                                                                         strict=True)]
    worst = max(abs(p) for p in printed)
    if worst <= TOL:
        return Feedback(False, r"Here the printed (15) also gives $\dot\beta_i = 0$: it fails only when the platform "
                               r"turns. Try a twist with $\dot\psi \neq 0$.")
    return Feedback(True, r"The motion needs no slip and keeps every unit locked, yet the printed (15) predicts "
                          rf"$\dot\beta_i$ up to ${worst:.3g}$ rad/s $= \dot\psi$: the wheel-rate difference measures "
                          r"the absolute turning rate $\dot\phi_i = \dot\psi + \dot\beta_i$.")


def dual_spin_in_place(rates, r=0.1, b=0.05, beta_dot=1.0):
    r"""Exercise 1.3: wheel rates :math:`(\dot\theta_{i1}, \dot\theta_{i2})` that turn a dual wheel on the spot.

    With the platform at rest, the unit must turn at ``beta_dot`` while its mount point
    :math:`P_i` stays still.

    Parameters
    ----------
    rates : sequence of 2 floats or None
    r, b : float
        Wheel radius and half separation.
    beta_dot : float
        The wanted steering rate (rad/s).

    Returns
    -------
    Feedback
    """
    fb = missing(rates, r"the pair $(\dot\theta_{i1}, \dot\theta_{i2})$")
    if fb is not None:
        return fb
    rates = np.asarray(rates, dtype=float)
    if rates.shape != (2,):
        return Feedback(False, "Give two wheel rates.")
    unit = DualWheel((0.0, 0.0), r=r, b=b)
    v_P = unit.block(0.0) @ rates                       # velocity of P_i (any beta: rotate)
    turn = float(unit.beta_rate(0.0, rates))
    if np.abs(v_P).max() > TOL:
        return Feedback(False, rf"$P_i$ moves at ${np.linalg.norm(v_P):.3g}$ m/s: the average rate (18) must be zero, "
                               r"$\dot\theta_{i1} = -\dot\theta_{i2}$.")
    if abs(turn - beta_dot) > TOL:
        return Feedback(False, f"The unit turns at ${turn:.3g}$ rad/s, not ${beta_dot:g}$: use the corrected (15), "
                               r"$\dot\phi_i = -\frac{r}{2b}(\dot\theta_{i1} - \dot\theta_{i2})$ (here "
                               r"$\dot\psi = 0$).")
    return Feedback(True, rf"$P_i$ stays still and the unit turns at ${beta_dot:g}$ rad/s.")
