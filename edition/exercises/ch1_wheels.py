r"""Chapter 1's exercises (platform and wheels), on the fair-check framework (:mod:`.framework`).

======  ===========================  ======================================================================
number  check                        the exercise
======  ===========================  ======================================================================
1.1     :func:`offset_other_side`    :math:`\dot{\mathbf p}_i` with the wheel centre ahead of the steering axis
1.2     :func:`dual_counterexample`  a locked, slip-free motion about a point other than C that refutes (15)
1.3     :func:`dual_spin_in_place`   the wheel rates that turn a dual wheel on the spot
======  ===========================  ======================================================================

Every expected value is computed from the package's model (``OffsetWheel.block``, ``DualWheel``,
``wmr.steering_angles``), not typed in and not taken from the chapter's derivation.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.steering import steering_angles
from wmr.model.robots import Dimensions, paper_robot
from wmr.model.wheels import DualWheel, OffsetWheel

from .. import symbols as S
from ..text import number
from . import answers
from .feedback import right, undecided, wrong
from .framework import exercise
from .symbolic import compare, equivalent
from .tolerance import angle_gap, sig_figs, within

__all__ = [
    "offset_other_side",
    "dual_counterexample",
    "dual_spin_in_place",
    "SYMBOLS_1_1",
    "DUAL_1_2",
    "TOL_1_2",
    "TOL_1_3",
]

#: 1.1: the symbols the answer may use (the student's own are mapped onto these by name)
SYMBOLS_1_1 = (S.phi_i, S.phi_dot_i, S.theta_dot_i, S.r, S.d)
#: 1.2: the paper's dual-wheel robot
DUAL_1_2 = Dimensions(L=0.5, r=0.1, b=0.08)
#: 1.2: each steering angle within 1e-3 rad of an angle at which the motion needs no slip
TOL_1_2 = within("to within $10^{-3}$ rad", abs=1e-3)
#: 1.3: the two rates to 3 significant figures
TOL_1_3 = sig_figs(3)
_WHAT_1_1 = r"the 2-vector $\dot{\mathbf p}_i$ (a SymPy `Matrix`, fixed-frame components)"
_WHAT_1_2 = r"a pair `(beta, twist)`: three steering angles in radians and a twist $(\dot\psi, \dot x, \dot y)$"


def _offset_velocity():
    r"""The model's velocity of :math:`P_i` of an offset wheel in fixed components (``OffsetWheel.block`` with the
    platform at :math:`\psi = 0`, so that :math:`\beta_i = \phi_i`): the printed side,
    :math:`H_i = P_i - d\mathbf j_i`."""
    return OffsetWheel((0, 0), r=S.r, d=S.d).block(S.phi_i) * sp.Matrix([S.phi_dot_i, S.theta_dot_i])


@exercise("1.1", answer=_WHAT_1_1)
def offset_other_side(answer):
    r"""Exercise 1.1: the velocity of :math:`P_i` when the wheel centre is at :math:`H_i = P_i + d\,\mathbf j_i`.

    Parameters
    ----------
    answer : sympy.Matrix (2, 1)
        In the symbols :data:`SYMBOLS_1_1` (or the student's own of the same names).

    Returns
    -------
    Result
    """
    printed_side = _offset_velocity()
    truth = printed_side.subs(S.d, -S.d)  # the centre on the other side: d -> -d
    M, same = compare(answer, truth, SYMBOLS_1_1, _WHAT_1_1)
    if same:
        return right(
            r"With the centre ahead of the steering axis the steering term changes sign: "
            r"$\dot{\mathbf p}_i = -r\dot\theta_i\mathbf j_i + d\dot\phi_i\mathbf i_i$."
        )
    if equivalent(M, printed_side):
        return wrong(
            r"That is (9) itself, the centre at $P_i - d\,\mathbf j_i$. Here $P_i - H_i = -d\,\mathbf j_i$: "
            r"redo the cross product $\dot\phi_i\mathbf k\times(P_i - H_i)$."
        )
    rolling = equivalent(M.subs(S.phi_dot_i, 0), truth.subs(S.phi_dot_i, 0))
    steering = equivalent(M.subs(S.theta_dot_i, 0), truth.subs(S.theta_dot_i, 0))
    if same is None or rolling is None or steering is None:
        return undecided(
            "This check cannot tell whether your expression equals the velocity (it could not be "
            "simplified or evaluated); write it with `sp.sin`, `sp.cos` and the symbols of the chapter."
        )
    if rolling and not steering:
        return wrong(
            r"The rolling term is right; the steering term is not: it is "
            r"$\dot\phi_i\mathbf k\times(P_i - H_i)$ with $P_i - H_i = -d\,\mathbf j_i$."
        )
    if steering and not rolling:
        return wrong(r"The steering term is right; the rolling term is off: the wheel centre moves as (6).")
    return wrong(
        r"Both terms are off. Start from $\dot{\mathbf p}_i = \dot{\mathbf h}_i + \dot\phi_i\mathbf k\times"
        r"(P_i - H_i)$ with $\dot{\mathbf h}_i$ from (6) and $P_i - H_i = -d\,\mathbf j_i$."
    )


def _motion(answer):
    """(beta, twist) of exercise 1.2 as two float arrays, or AnswerError."""
    if not isinstance(answer, (tuple, list)) or len(answer) != 2:
        raise answers.AnswerError(f"Expected {_WHAT_1_2}; got {answers.describe(answer)}.")
    return answers.vector(answer[0], 3, "three steering angles in radians"), answers.vector(
        answer[1], 3, r"a twist $(\dot\psi, \dot x, \dot y)$"
    )


@exercise("1.2", answer=_WHAT_1_2, tolerance=TOL_1_2)
def dual_counterexample(motion):
    r"""Exercise 1.2: a slip-free motion of the paper's dual-wheel robot with its units locked
    (:math:`\dot\beta_i = 0`), about a point other than C, for which the printed (15) predicts
    :math:`\dot\beta_i \neq 0`.

    Parameters
    ----------
    motion : pair
        ``(beta, twist)``: three steering angles (radians), held fixed, and the twist.

    Returns
    -------
    Result
    """
    beta, twist = _motion(motion)
    robot = paper_robot("dual", **DUAL_1_2)
    scale = DUAL_1_2["L"] * abs(twist[0]) + float(np.hypot(twist[1], twist[2]))  # m/s at the wheels
    if scale == 0:
        return wrong("The robot must move: a zero twist predicts nothing.")
    if abs(twist[0]) * DUAL_1_2["L"] <= TOL_1_2.abs * scale:
        return wrong(
            r"This twist does not turn the platform ($\dot\psi = 0$); then the printed (15) also gives "
            r"$\dot\beta_i = 0$. It fails only when the platform turns."
        )
    if float(np.hypot(twist[1], twist[2])) <= TOL_1_2.abs * scale:
        return wrong(
            "This motion is a spin about C: the chapter's own counterexample. Find one that turns about another point."
        )
    want = steering_angles(robot, twist)
    gap = angle_gap(beta, want)
    if gap <= TOL_1_2.abs:
        return right(
            r"The motion needs no slip and keeps every unit locked, yet the printed (15) predicts "
            rf"$\dot\beta_i = \dot\psi = {number(twist[0], 3)}$ rad/s: the difference of the wheel rates "
            r"measures the absolute turning rate $\dot\phi_i = \dot\psi + \dot\beta_i$."
        )
    if angle_gap(np.radians(beta), want) <= TOL_1_2.abs:
        return wrong("These angles would be right in degrees; the question asks for radians.")
    return wrong(
        r"At these angles the twist needs sideways slip: every axle must pass through the instantaneous "
        r"centre of the motion (`wmr.steering_angles(robot, twist)` gives such angles)."
    )


def _dual_rates(r, b, beta_dot):
    """The rates (theta_1, theta_2) that keep P_i still and turn the unit at beta_dot: solved with the model."""
    unit = DualWheel((0.0, 0.0), r=r, b=b)
    A = np.vstack([unit.block(0.0), [[float(unit.beta_rate(0.0, e)) for e in np.eye(2)]]])
    return np.linalg.lstsq(A, np.array([0.0, 0.0, beta_dot]), rcond=None)[0], unit


@exercise(
    "1.3",
    answer=r"two wheel rates $(\dot\theta_{i1}, \dot\theta_{i2})$ in rad/s",
    tolerance=TOL_1_3,
    units={"rates": "rad"},
)
def dual_spin_in_place(rates, r=0.1, b=0.05, beta_dot=1.0):
    r"""Exercise 1.3: the wheel rates that turn a dual wheel (``r``, ``b``) at ``beta_dot`` with :math:`P_i` still.

    Parameters
    ----------
    rates : pair of float
        :math:`(\dot\theta_{i1}, \dot\theta_{i2})`, rad/s.
    r, b, beta_dot : float

    Returns
    -------
    Result
    """
    x = answers.vector(rates, 2, r"two wheel rates $(\dot\theta_{i1}, \dot\theta_{i2})$ in rad/s")
    want, unit = _dual_rates(r, b, beta_dot)
    if TOL_1_3.accepts(x, want):
        return right(
            r"$\dot\theta_{i1} = -\dot\theta_{i2}$ keeps the average rate (18), and so $P_i$, at rest; the "
            r"difference turns the unit at $\dot\beta_i = \dot\phi_i = -\frac{r}{2b}(\dot\theta_{i1} - "
            r"\dot\theta_{i2})$ = "
            f"${number(beta_dot, 3)}$ rad/s."
        )
    speed = float(np.linalg.norm(unit.block(0.0) @ x))
    turn = float(unit.beta_rate(0.0, x))
    if speed > TOL_1_3.rel * r * float(np.abs(want).max()):
        return wrong(
            r"With these rates $P_i$ moves: the average rate (18) must be zero, "
            r"$\dot\theta_{i1} = -\dot\theta_{i2}$."
        )
    if abs(turn) <= TOL_1_3.rel * abs(beta_dot):
        return wrong("With these rates the unit stands still: the two wheels must turn in opposite directions.")
    return wrong(
        f"$P_i$ stays still, but the unit turns at ${number(turn, 3)}$ rad/s instead of "
        f"${number(beta_dot, 3)}$ rad/s: use the corrected (15)."
    )
