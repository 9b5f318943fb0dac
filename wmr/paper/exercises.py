r"""The exercises of the chapters: one check function each, that says whether an answer is right and why not.

Each chapter ends with two or three exercises (cells tagged ``exercise``) and their worked
solutions (tagged ``solution``; ``make student`` drops them).  A student writes an answer and
calls the exercise's check, e.g.::

    answer = sp.Matrix([...])
    exercises.offset_other_side(answer)

The check returns a :class:`Feedback` (shown as a Markdown paragraph): right, or not yet with
the reason -- computed from the model, never compared with a typed-in answer.  ``None`` (the
template's placeholder) gives "no answer yet" without failing, so the student notebooks run.

Chapter by chapter:

=====  ==============================  =====================================================================
ch.    check                           the exercise
=====  ==============================  =====================================================================
1      :func:`offset_other_side`       the velocity of :math:`P_i` with the wheel centre on the other side
1      :func:`dual_counterexample`     a slip-free motion that refutes the printed (15)
1      :func:`dual_spin_in_place`      wheel rates that turn a dual wheel on the spot
2      :func:`locked_steering`         steering angles at which the locked robot can still steer
2      :func:`drift_of_c_general`      (28) with C anywhere, not only at the centroid   
3      :func:`isotropic_placement`     move wheel 2 and find the L that makes :math:`\mathbf J_{L1}` isotropic
3      :func:`printed_42_signs`        show that the printed (42) has the wrong signs
3      :func:`offset_for_kappa`        the offset that gives :math:`\kappa(\mathbf J_2) = 2`
4      :func:`unlisted_singularity`    a singular configuration the paper does not list
4      :func:`mobile_and_singular`     steering angles where the robot moves although :math:`\mathbf J` is singular
5      :func:`translation_angles`      steering angles for a translation, and the slip of the printed (60)
5      :func:`rotation_angles`         steering angles for a rotation about a given point
5      :func:`printed_65_region`       where the centre must lie for the printed (65) to hold
6      :func:`curved_translation`      steering while translating, without stopping
6      :func:`reversal`                a discontinuous heading that needs no re-steering
=====  ==============================  =====================================================================

"Your own robot" cells use :func:`describe_robot`.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from ..analysis.kinematics import inverse
from ..analysis.linalg import condition_number, rank
from ..analysis.mobility import admissible_twists, mobility, rank_F
from ..model.platform import point_velocity
from ..model.robot import Robot
from ..model.robots import paper_robot
from ..model.tolerance import TOL
from ..model.wheels import CentredWheel, DualWheel, OffsetWheel
from . import platform_wheels as PW
from . import symbols as S
from .verify import symbolic_equal

__all__ = ["Feedback", "offset_other_side", "dual_counterexample", "dual_spin_in_place", "locked_steering",
           "drift_of_c_general", "isotropic_placement", "printed_42_signs", "offset_for_kappa", "unlisted_singularity",
           "mobile_and_singular", "translation_angles", "rotation_angles", "printed_65_region", "curved_translation",
           "reversal", "describe_robot"]


@dataclass(frozen=True)
class Feedback:
    """The verdict on a student's answer.

    Attributes
    ----------
    correct : bool
    message : str
        Markdown: what is right, or why not.
    """

    correct: bool
    message: str

    def __bool__(self):
        return self.correct

    def _repr_markdown_(self):
        return ("**Right.** " if self.correct else "**Not yet.** ") + self.message

    def __repr__(self):
        return f"Feedback(correct={self.correct}, message={self.message!r})"


def _none(answer, what):
    if answer is None:
        return Feedback(False, f"No answer yet: replace `None` by {what}.")
    return None


def _matrix(answer, shape, what):
    try:
        M = sp.Matrix(answer)
    except (TypeError, ValueError, sp.SympifyError):
        return None, Feedback(False, f"{what} must be a SymPy matrix (or a list) of shape {shape}, got {answer!r}.")
    if M.shape != shape:
        return None, Feedback(False, f"{what} must have shape {shape}, got {M.shape}.")
    return M, None


# ----------------------------------------------------------------------------------------------- chapter 1
def offset_other_side(answer):
    r"""Exercise 1.1: the velocity of :math:`P_i` when the wheel centre is at :math:`H_i = P_i + d\,\mathbf j_i`.

    The answer is the fixed-frame 2-vector in the symbols of :mod:`wmr.paper.platform_wheels`
    (:math:`\phi_i`, :math:`\dot\phi_i`, :math:`\dot\theta_i`) and :math:`r, d`.

    Parameters
    ----------
    answer : sympy.Matrix (2, 1) or None

    Returns
    -------
    Feedback
    """
    from .checks.wheels import disk_velocity, k, planar
    fb = _none(answer, r"the 2-vector $\dot{\mathbf p}_i$")
    if fb is not None:
        return fb
    M, fb = _matrix(answer, (2, 1), "the answer")
    if fb is not None:
        return fb
    disk = disk_velocity(PW.theta_dot_i)
    truth = planar(disk.h_dot + (PW.phi_dot_i * k).cross(-S.d * disk.j3))       # P - H = -d j
    if symbolic_equal(M, truth):
        return Feedback(True, r"With the centre ahead of the steering axis the steering term changes sign: "
                              r"$\dot{\mathbf p}_i = -r\dot\theta_i\mathbf j_i + d\dot\phi_i\mathbf i_i$.")
    printed_side = planar(disk.h_dot + (PW.phi_dot_i * k).cross(S.d * disk.j3))
    if symbolic_equal(M, printed_side):
        return Feedback(False, r"That is (9) itself, the centre at $P_i - d\,\mathbf j_i$. Here "
                               r"$P_i - H_i = -d\,\mathbf j_i$: redo the cross product $\dot\phi_i\mathbf k\times(P_i - H_i)$.")
    if not symbolic_equal(M.subs(PW.phi_dot_i, 0), truth.subs(PW.phi_dot_i, 0)):
        return Feedback(False, r"The rolling term is off: the wheel centre moves as (6), $-r\dot\theta_i\mathbf j_i$.")
    return Feedback(False, r"Start from $\dot{\mathbf p}_i = \dot{\mathbf h}_i + \dot\phi_i\mathbf k\times(P_i - H_i)$ "
                           r"with $\dot{\mathbf h}_i$ from (6) and $P_i - H_i = -d\,\mathbf j_i$; your answer differs by "
                           f"${sp.latex(sp.simplify(M - truth))}$.")


def dual_counterexample(beta, twist, robot=None):
    r"""Exercise 1.2: a slip-free motion with the units locked (:math:`\dot\beta_i = 0`) for which the printed (15) predicts :math:`\dot\beta_i \neq 0`.

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
    fb = _none(None if beta is None or twist is None else 0, "steering angles `beta` and a `twist`")
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
    printed = [-u.r / (2 * u.b) * (sol.value[sl][0] - sol.value[sl][1]) for u, sl in zip(robot.wheels, robot.rate_slices)]
    worst = max(abs(p) for p in printed)
    if worst <= TOL:
        return Feedback(False, r"Here the printed (15) also gives $\dot\beta_i = 0$: it fails only when the platform "
                               r"turns. Try a twist with $\dot\psi \neq 0$.")
    return Feedback(True, rf"The motion needs no slip and keeps every unit locked, yet the printed (15) predicts "
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
    fb = _none(rates, r"the pair $(\dot\theta_{i1}, \dot\theta_{i2})$")
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
        return Feedback(False, rf"The unit turns at ${turn:.3g}$ rad/s, not ${beta_dot:g}$: use the corrected (15), "
                               r"$\dot\phi_i = -\frac{r}{2b}(\dot\theta_{i1} - \dot\theta_{i2})$ (here $\dot\psi = 0$).")
    return Feedback(True, rf"$P_i$ stays still and the unit turns at ${beta_dot:g}$ rad/s.")


# ----------------------------------------------------------------------------------------------- your own robot
def describe_robot(robot, beta=None, twist=None):
    r"""A Markdown summary of any robot: its units, the sizes of its matrices, rank F and mobility, and a twist's feasibility.

    For the "your own robot" cells of the chapters.

    Parameters
    ----------
    robot : wmr.Robot
    beta : array (w,), optional
        Steering angles (default: zeros).
    twist : array (3,), optional
        A platform twist to test (default: none).

    Returns
    -------
    str
        Markdown.
    """
    if not isinstance(robot, Robot):
        raise TypeError(f"robot must be a wmr.Robot, got {type(robot).__name__}")
    beta = np.zeros(robot.w) if beta is None else np.asarray(beta, dtype=float)
    F = robot.F(beta)
    rk = int(rank(F))
    tw = admissible_twists(robot, beta)
    kinds = ", ".join(f"{u.kind} at $({u.position[0]:.3g}, {u.position[1]:.3g})$" for u in robot.wheels)
    lines = [f"**Your robot:** {robot.w} units ({kinds}).",
             rf"$\mathbf F$ is ${F.shape[0]}\times{F.shape[1]}$ with rank {rk}: nullity {F.shape[1] - rk}; "
             rf"the platform can follow a {tw.shape[1]}-dimensional set of twists at these steering angles."]
    if twist is not None:
        sol = inverse(robot, beta, np.asarray(twist, dtype=float))
        lines.append(("The twist is executable without slip; joint rates "
                      + ", ".join(f"${v:.3g}$" for v in np.ravel(sol.value)) + ".") if bool(sol.admissible) else
                     f"The twist needs slip (residual ${np.abs(sol.residual).max():.3g}$).")
    return "\n\n".join(lines)


# ----------------------------------------------------------------------------------------------- chapter 2
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
    from .checks.assembly import PAPER, locked_system
    fb = _none(beta, "three steering angles")
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
    from .checks.assembly import locked_motion
    x = locked_motion(robot, beta)
    x = x / x[0] if abs(x[0]) > TOL else x
    U = np.array([-x[2], x[1]]) if abs(x[0]) > TOL else None        # c_dot = -psi_dot E u  =>  u = E c_dot / psi_dot
    where = (f"about $U = ({U[0]:.3g}, {U[1]:.3g})$" if U is not None else "")
    return Feedback(True, rf"The locked robot can steer here: its arm lines are concurrent, and it turns {where} "
                          r"(instantaneously: held longer, it needs slip).")


def drift_of_c_general(answer):
    r"""Exercise 2.2: :math:`\dot{\mathbf c}` of the locked robot for general mount points (C anywhere).

    The answer is a SymPy 2-vector in :data:`wmr.paper.symbols` (``d``, ``beta``, ``phi_dot``, ``psi_dot``)
    and the mount points :data:`wmr.paper.offset.D`.

    Parameters
    ----------
    answer : sympy.Matrix (2, 1) or None

    Returns
    -------
    Feedback
    """
    from . import printed
    from .checks.assembly import drift_of_c
    fb = _none(answer, r"the 2-vector $\dot{\mathbf c}$")
    if fb is not None:
        return fb
    M, fb = _matrix(answer, (2, 1), "the answer")
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
    return Feedback(False, r"Sum the three block rows of $\mathbf J_1\mathbf t = \mathbf J_2\dot{\boldsymbol\theta}$ with "
                           r"$\dot\theta_i = 0$ and solve for $\dot x, \dot y$; your answer differs from it by "
                           f"${sp.latex(sp.simplify(M - truth).T)}^{{\\mathrm T}}$.")


# ----------------------------------------------------------------------------------------------- chapter 3
def isotropic_placement(points, L, fixed=((-0.4, 0.0), (0.1, 0.5))):
    r"""Exercise 3.1: with wheel 2 moved, place wheel 3 and choose L so that :math:`\mathbf J_{L1}` is isotropic.

    Parameters
    ----------
    points : array (3, 2) or None
        The three mount points (body frame, metres); wheels 1 and 2 must stay at ``fixed``.
    L : float or None
        The characteristic length.
    fixed : pair of points
        Where wheels 1 and 2 are.

    Returns
    -------
    Feedback
    """
    fb = _none(None if points is None or L is None else 0, "the three mount points and $L$")
    if fb is not None:
        return fb
    pts = np.asarray(points, dtype=float)
    if pts.shape != (3, 2):
        return Feedback(False, "Give three mount points, an array of shape (3, 2).")
    if not np.allclose(pts[:2], np.asarray(fixed, dtype=float)):
        return Feedback(False, f"Wheels 1 and 2 must stay at {fixed[0]} and {fixed[1]}: move wheel 3 only.")
    if not float(L) > 0:
        return Feedback(False, "$L$ must be a positive length.")
    bot = Robot([OffsetWheel(tuple(p), r=0.1, d=0.1) for p in pts])
    k = float(condition_number(bot.J1(float(L))))
    s = pts.sum(axis=0)
    if np.abs(s).max() > 1e-9:
        return Feedback(False, rf"$\kappa(\mathbf J_{{L1}}) = {k:.4g}$. The off-diagonal blocks (35) are "
                               rf"$\tfrac1L\mathbf E\sum_i\mathbf d_i \neq \mathbf 0$: $\sum_i\mathbf d_i = ({s[0]:.3g}, {s[1]:.3g})$. "
                               "Put C at the centroid of the three mount points (37).")
    L_iso = float(np.sqrt(np.mean(np.sum(pts**2, axis=1))))
    if abs(k - 1) > 1e-9:
        return Feedback(False, rf"The centroid is right, but $\kappa(\mathbf J_{{L1}}) = {k:.4g}$: (36) asks for "
                               rf"$L^2 = \tfrac13\sum_i\|\mathbf d_i\|^2$, the mean squared distance.")
    return Feedback(True, rf"$\kappa(\mathbf J_{{L1}}) = 1$ with $L = {L_iso:.4g}$, although the triangle is not equilateral "
                          rf"(distances ${', '.join(f'{v:.3g}' for v in np.linalg.norm(pts, axis=1))}$): (38) is sufficient, "
                          "not necessary.")


def printed_42_signs(answer):
    r"""Exercise 3.2: the square :math:`\tilde{\mathbf p}^2` of the model's :math:`\tilde{\mathbf p}` -- and why the printed (42) cannot be it.

    Parameters
    ----------
    answer : sympy.Matrix (2, 2) or None
        :math:`\tilde{\mathbf p}^2` in the symbols ``S.d``, ``S.r``.

    Returns
    -------
    Feedback
    """
    from . import printed
    fb = _none(answer, r"the $2\times2$ matrix $\tilde{\mathbf p}^2$")
    if fb is not None:
        return fb
    M, fb = _matrix(answer, (2, 2), "the answer")
    if fb is not None:
        return fb
    ptilde = OffsetWheel((0, 0), r=S.r, d=S.d).block(sp.Integer(0))        # R(0) p~ = p~
    truth = ptilde * ptilde
    if symbolic_equal(M, truth):
        return Feedback(True, r"$\tilde{\mathbf p}^2 = \mathrm{diag}(d^2, r^2)$. With the printed $\mathrm{diag}(-d^2, -r^2)$, "
                              r"$\Upsilon_i = \mathbf R\tilde{\mathbf p}^2\mathbf R^{\mathrm T}$ would be negative definite, "
                              r"impossible for a block of $\mathbf J_2\mathbf J_2^{\mathrm T}$, whose quadratic form is "
                              r"$\|\mathbf J_2^{\mathrm T}\mathbf x\|^2 \geq 0$.")
    if symbolic_equal(M, printed(42).expr.rhs):
        return Feedback(False, r"That is the printed (42). Square $\tilde{\mathbf p} = \mathrm{diag}(-d, -r)$ yourself "
                               r"(`OffsetWheel((0, 0), r=S.r, d=S.d).block(0)` is $\tilde{\mathbf p}$).")
    return Feedback(False, rf"Not $\tilde{{\mathbf p}}\tilde{{\mathbf p}}$: the model's $\tilde{{\mathbf p}}$ is ${sp.latex(ptilde)}$.")


def offset_for_kappa(offsets, r=0.1, kappa=2.0, n=200):
    r"""Exercise 3.3: every offset d that gives :math:`\kappa(\mathbf J_2) =` ``kappa`` for wheels of radius r.

    Parameters
    ----------
    offsets : sequence of float or None
    r : float
    kappa : float
    n : int
        Random steering configurations tested.

    Returns
    -------
    Feedback
    """
    fb = _none(offsets, "a list of offsets $d$")
    if fb is not None:
        return fb
    ds = sorted(float(d) for d in np.atleast_1d(offsets))
    B = np.random.default_rng(0).uniform(-np.pi, np.pi, (n, 3))
    wrong = []
    for d in ds:
        k = condition_number(paper_robot("offset", L=0.4, r=r, d=d).J2(B))
        if not np.allclose(k, kappa, atol=1e-9):
            wrong.append(rf"$d = {d:g}$ gives $\kappa(\mathbf J_2)$ from ${k.min():.4g}$ to ${k.max():.4g}$")
    if wrong:
        return Feedback(False, "; ".join(wrong) + r". The singular values of $\mathbf J_2$ are $d$ and $r$ (48).")
    if len(ds) < 2:
        return Feedback(False, rf"$d = {ds[0]:g}$ works; there is one more offset with the same condition number.")
    return Feedback(True, rf"$\kappa(\mathbf J_2) = \max(d, r)/\min(d, r) = {kappa:g}$ for $d = {r / kappa:g}$ and "
                          rf"$d = {r * kappa:g}$, at every steering angle.")


# ----------------------------------------------------------------------------------------------- chapter 4
def unlisted_singularity(beta_deg):
    r"""Exercise 4.1: a singular configuration of the paper's centred-wheel robot that its list (i)-(v) does not state.

    Parameters
    ----------
    beta_deg : array (3,) or None
        Steering angles in degrees.

    Returns
    -------
    Feedback
    """
    from ..analysis.singularities import classify
    from .families import paper_item
    fb = _none(beta_deg, "three steering angles in degrees")
    if fb is not None:
        return fb
    beta = np.radians(np.asarray(beta_deg, dtype=float))
    if beta.shape != (3,):
        return Feedback(False, "Give three angles.")
    bot = paper_robot("centred", L=1.0, r=1.0)
    c = classify(bot, beta)
    if not c.singular:
        return Feedback(False, rf"$\det\mathbf J = {c.det_J:.3g} \neq 0$: not singular. The wheel-plane lines must be "
                               "concurrent or all parallel.")
    item = paper_item(c.family)
    if item:
        return Feedback(False, f"Singular, but the paper lists it: item {item} (family `{c.family}`). Look for one the "
                               "literal list misses.")
    return Feedback(True, rf"$\det\mathbf J = 0$ (family `{c.family}`, rank $\mathbf F = {c.rank_F}$), and no item of the "
                          r"printed list states it: a wheel turned by $180^\circ$ keeps its wheel-plane line.")


def mobile_and_singular(beta_deg):
    r"""Exercise 4.2: steering angles at which :math:`\mathbf J` is singular although the robot can move.

    Parameters
    ----------
    beta_deg : array (3,) or None
        Steering angles in degrees.

    Returns
    -------
    Feedback
    """
    from ..analysis.singularities import det_J
    fb = _none(beta_deg, "three steering angles in degrees")
    if fb is not None:
        return fb
    beta = np.radians(np.asarray(beta_deg, dtype=float))
    bot = paper_robot("centred", L=1.0, r=1.0)
    dj = float(det_J(bot, beta))
    rk = int(rank_F(bot, beta))
    if abs(dj) > 1e-9:
        return Feedback(False, rf"$\det\mathbf J = {dj:.3g}$: $\mathbf J$ is not singular here.")
    if rk != 5:
        return Feedback(False, r"$\mathbf J$ is singular, but rank $\mathbf F = 6$: the robot cannot move. The axle lines "
                               "must be concurrent too.")
    return Feedback(True, r"$\det\mathbf J = 0$ and rank $\mathbf F = 5$: the robot can move although $\mathbf J$ is singular "
                          r"(all planes parallel, or the planes meet on the circle through the $P_i$).")


# ----------------------------------------------------------------------------------------------- chapter 5
def translation_angles(beta, velocity=(0.3, 0.4), psi_deg=30.0):
    r"""Exercise 5.1: steering angles :math:`\beta_i` for a translation with fixed-frame velocity ``velocity`` at heading ``psi_deg``.

    Parameters
    ----------
    beta : array (3,) or None
        Radians.
    velocity : pair
        :math:`(\dot X, \dot Y)` in the fixed frame (m/s).
    psi_deg : float
        Platform orientation :math:`\psi` (degrees).

    Returns
    -------
    Feedback
    """
    from .checks.steering import robot
    fb = _none(beta, "three steering angles (radians)")
    if fb is not None:
        return fb
    beta = np.asarray(beta, dtype=float)
    psi = np.radians(psi_deg)
    v = np.asarray(velocity, dtype=float)
    c = np.array([[np.cos(psi), np.sin(psi)], [-np.sin(psi), np.cos(psi)]]) @ v      # body components R(psi)^T v
    twist = np.r_[0.0, c]
    sol = inverse(robot(), beta, twist)
    if bool(sol.admissible):
        return Feedback(True, r"Every axle is perpendicular to the velocity and the wheels roll along it: "
                              r"$\phi_i = \psi + \beta_i = \operatorname{atan2}(\dot Y, \dot X) + \pi/2$ (mod $\pi$).")
    from .notebook import mod_pi
    if np.allclose(mod_pi(beta + psi - np.arctan2(v[1], v[0])), 0.0, atol=1e-9):
        return Feedback(False, r"These are the angles of the printed (60): the *axles* point along the velocity and the "
                               rf"wheels would slide sideways at the full speed (${np.linalg.norm(v):.3g}$ m/s).")
    return Feedback(False, rf"The wheels would slip (residual ${np.abs(sol.residual).max():.3g}$ m/s). In translation every "
                           r"point moves with $\dot{\mathbf c}$: each axle $\mathbf i_i$ (absolute angle $\psi + \beta_i$) must "
                           "be perpendicular to it.")


def rotation_angles(beta, U=(0.5, 0.3)):
    r"""Exercise 5.2: steering angles for a rotation about the body point ``U``.

    Parameters
    ----------
    beta : array (3,) or None
        Radians.
    U : pair
        The instantaneous centre, body frame (m).

    Returns
    -------
    Feedback
    """
    from .checks.steering import robot
    fb = _none(beta, "three steering angles (radians)")
    if fb is not None:
        return fb
    beta = np.asarray(beta, dtype=float)
    u = np.asarray(U, dtype=float)
    twist = np.r_[1.0, np.array([u[1], -u[0]])]          # c_dot = -psi_dot E u
    sol = inverse(robot(), beta, twist)
    if bool(sol.admissible):
        return Feedback(True, r"Every axle points at U: $\beta_i = \operatorname{atan2}(u_{iy}, u_{ix})$ (mod $\pi$) with "
                              r"$\mathbf u_i = \mathbf u_c - \mathbf d_i$ (64).")
    return Feedback(False, rf"The wheels would slip (residual ${np.abs(sol.residual).max():.3g}$ m/s at $\dot\psi = 1$): each "
                           r"axle $\mathbf i_i$ must be parallel to $\mathbf u_i = \overrightarrow{P_iU}$, the angle measured "
                           r"from the body axis $\mathbf i$, not from $\overrightarrow{CU}$ as the printed (65) does.")


def printed_65_region(U):
    r"""Exercise 5.3: a centre U (not C) at which the printed (65), with the better sign of arccos per wheel, steers correctly.

    Parameters
    ----------
    U : pair or None
        Body frame (m).

    Returns
    -------
    Feedback
    """
    from .checks.steering import robot
    fb = _none(U, "a point $U = (u_x, u_y)$")
    if fb is not None:
        return fb
    u = np.asarray(U, dtype=float)
    if np.linalg.norm(u) < 1e-9:
        return Feedback(False, r"At U = C the printed (65) is $0/0$: undefined. Try another point.")
    bot = robot()
    ui = u - bot.mount_points
    cos_pr = (ui @ u) / (np.linalg.norm(ui, axis=1) * np.linalg.norm(u))
    b = np.arccos(np.clip(cos_pr, -1, 1))
    lateral = lambda x: np.abs(ui[:, 1] * np.cos(x) - ui[:, 0] * np.sin(x))
    b = np.where(lateral(b) <= lateral(-b), b, -b)
    twist = np.r_[1.0, np.array([u[1], -u[0]])]
    if bool(inverse(bot, b, twist).admissible):
        return Feedback(True, r"Here the printed angle between $\overrightarrow{CU}$ and $\overrightarrow{P_iU}$ is the angle "
                              r"from the body axis $\mathbf i$: U lies on the positive body $x$-axis, the only place where "
                              "the printed (65) works.")
    return Feedback(False, r"At this U the printed angles leave the axles off U: the robot is jammed. The printed angle "
                           r"is measured from $\overrightarrow{CU}$; where does that line coincide with the body axis $\mathbf i$?")


# ----------------------------------------------------------------------------------------------- chapter 6
def curved_translation(beta_dot, v=0.2, omega=0.5, t_end=2.0):
    r"""Exercise 6.1: the steering rates that keep a centred-wheel robot translating while its velocity direction turns at ``omega``.

    Parameters
    ----------
    beta_dot : array (3,) or None
        Steering rates (rad/s), held constant.
    v, omega : float
        Speed and turning rate of the velocity direction.
    t_end : float
        Simulated time.

    Returns
    -------
    Feedback
    """
    from ..analysis.simulation import simulate
    from ..analysis.steering import steering_angles
    fb = _none(beta_dot, "three steering rates (rad/s)")
    if fb is not None:
        return fb
    bd = np.asarray(beta_dot, dtype=float) * np.ones(3)
    cen = paper_robot("centred", L=0.4, r=0.1)
    twist = lambda t: np.array([0.0, v * np.cos(omega * t), v * np.sin(omega * t)])
    run = simulate(cen, lambda t, s: inverse(cen, s[1], twist(t)).value, steering_angles(cen, twist(0.0)),
                   t_end=t_end, dt=0.01, steer=bd)
    miss = float(np.max(np.abs(run.twist - np.array([twist(t) for t in run.t]))))
    slip = float(run.slip.max())
    if miss < 1e-6 and slip < 1e-6:
        return Feedback(True, rf"The robot follows the turning velocity (largest error ${miss:.1g}$ m/s) without slip: the "
                              r"wheels turn together at $\omega$, stay parallel, and the robot changes direction without "
                              "stopping. Mobility 1 is not the same as having to stop.")
    return Feedback(False, rf"The robot misses the commanded velocity by up to ${miss:.3g}$ m/s after {t_end:g} s: the axles "
                           r"must stay perpendicular to the velocity, whose direction turns at $\omega$.")


def reversal(twist_plus, twist_minus=(0.0, 0.2, 0.1)):
    r"""Exercise 6.2: a jump of the twist that a centred-wheel robot executes without re-steering, and that changes the heading.

    Parameters
    ----------
    twist_plus : array (3,) or None
        The new twist.
    twist_minus : array (3,)
        The current twist; the wheels are steered for it.

    Returns
    -------
    Feedback
    """
    from ..analysis.steering import steering_angles
    fb = _none(twist_plus, "a twist")
    if fb is not None:
        return fb
    cen = paper_robot("centred", L=0.4, r=0.1)
    tm, tp = np.asarray(twist_minus, dtype=float), np.asarray(twist_plus, dtype=float)
    sol = inverse(cen, steering_angles(cen, tm), tp)
    if not bool(sol.admissible):
        return Feedback(False, rf"At the current steering angles this twist needs slip (${np.abs(sol.residual).max():.3g}$): "
                               r"only multiples of the current twist share its instantaneous centre.")
    lam = float(tp @ tm / (tm @ tm))
    if lam > 0:
        return Feedback(False, "Executable, but it is the same heading at another speed: make the heading jump.")
    return Feedback(True, rf"$\mathbf t^+ = {lam:.3g}\,\mathbf t^-$: a reversal, the heading jumps by $180^\circ$ and the "
                          "wheels simply roll the other way. Every other jump needs re-steering.")
