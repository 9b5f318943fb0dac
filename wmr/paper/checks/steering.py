r"""Chapter 5, equations (60)-(65): steering three centred wheels, and the instantaneous centre.

Everything rests on one scalar per wheel: the axle component of the mount point's velocity,
:math:`g_i = \mathbf i_i^{\mathrm T}[\mathbf E\mathbf d_i\ \ \mathbf 1]\,\mathbf t`, which a centred wheel
cannot produce (:func:`no_slip`).  A twist is executable iff every :math:`g_i = 0`.  The printed
steering laws are substituted into :math:`g_i` exactly and tested numerically with the package's
inverse kinematics (:func:`feasibility`); the instantaneous centre is derived by differentiating
the position of a platform point.
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np
import sympy as sp

from ...analysis.kinematics import inverse
from ...analysis.linalg import rank
from ...analysis.mobility import rank_F, twist_constraints
from ...analysis.steering import AT_INFINITY, FINITE, STILL, centre_to_wheels, instantaneous_centre, steering_angles
from ...model.backend import SYMBOLIC
from ...model.platform import point_row, point_velocity, rotation
from ...model.robot import Robot
from ...model.robots import paper_robot
from ...model.tolerance import TOL
from ...model.wheels import CentredWheel
from .. import printed
from .. import steering as P
from .. import symbols as S
from ..notebook import mod_pi
from ..verify import SEED, symbolic_equal
from . import Derivation, equation, require

__all__ = ["robot", "no_slip", "feasibility", "evaluate", "translation", "instant_centre_velocity", "instant_centre",
           "centre_to_wheel", "rotation_angles", "KIND_NAMES"]

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


@lru_cache(maxsize=None)
def no_slip():
    r"""The axle component :math:`g_i` of the velocity of a centred wheel's mount point, symbolic.

    Returns
    -------
    Derivation
        ``J1t`` (:math:`[\mathbf E\mathbf d_i\ \mathbf 1]\mathbf t`), ``J2`` (the wheel's block), ``g``,
        ``beta`` and ``t`` (the symbols), ``axle``.
    """
    one = Robot([CentredWheel((S.dx, S.dy), r=S.r)])
    beta = one.beta_symbols[0]
    t = sp.Matrix(one.twist_symbols)
    J1, J2 = one.J1(L=sp.S.One), one.J2()
    axle = rotation(beta, SYMBOLIC) * sp.Matrix([1, 0])
    roll = rotation(beta, SYMBOLIC) * sp.Matrix([0, 1])
    require(symbolic_equal(axle.T * J2, sp.zeros(1, 1)), "the wheel cannot move P_i along its axle")
    require(symbolic_equal(roll.T * J2, sp.Matrix([[-S.r]])), "the wheel rolls P_i along j_i at -r theta_dot")
    g = sp.expand((axle.T * J1 * t)[0])
    return Derivation(J1t=J1 * t, J2=J2, g=g, beta=beta, t=t, axle=axle)


def no_slip_matches_constraints(n=2000, seed=SEED):
    r"""The three :math:`g_i` are the rows of ``twist_constraints`` (up to sign) at random configurations.

    Parameters
    ----------
    n : int
    seed : int

    Returns
    -------
    float
        The largest difference (checked below ``TOL``).
    """
    ns, bot = no_slip(), robot()
    rng = np.random.default_rng(seed)
    B, T = rng.uniform(-np.pi, np.pi, (n, 3)), rng.normal(size=(n, 3))
    A, base = twist_constraints(bot, B)
    d = bot.mount_points
    g = np.stack([evaluate(ns.g, (ns.beta, S.dx, S.dy, *ns.t), B[:, i], d[i, 0], d[i, 1], *T.T) for i in range(3)], -1)
    res = float(np.max(np.abs(np.abs(g) - np.abs(np.einsum("nij,nj->ni", A, T)))))
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
    return {"rank_F": set(np.atleast_1d(rank_F(bot, beta)).tolist()),
            "rank_J2": set(np.atleast_1d(rank(J2)).tolist()),
            "rank_J2_J1t": set(np.atleast_1d(rank(np.concatenate([J2, J1t[..., None]], -1))).tolist()),
            "admissible": float(np.mean(sol.admissible)),
            "min_rel_residual": float(np.min(np.linalg.norm(sol.residual, axis=-1) / speed)),
            "max_residual": float(np.max(np.abs(sol.residual)))}


def translation(n=2000, seed=SEED):
    r"""(60): in translation the **axle** must be perpendicular to the velocity; the printed angle is the velocity's own.

    :math:`g_i = 0` with :math:`\dot\psi = 0` reads :math:`\dot X\cos\phi_i + \dot Y\sin\phi_i = 0`, so
    :math:`\phi_i = \operatorname{atan2}(\dot Y, \dot X) + \pi/2` (mod :math:`\pi`).

    Parameters
    ----------
    n : int
        Random translations (random heading, random velocity).
    seed : int

    Returns
    -------
    Derivation
        ``g`` (the condition in translation), ``g_true``, ``g_printed_squared``, ``phi_true``,
        ``printed``, ``derived`` (:func:`feasibility` of each), ``alt`` (printed minus the angle of
        :math:`\mathbf j_i`, mod :math:`\pi`), finding (60).
    """
    p60 = printed(60)
    ns = no_slip()
    phi = p60.expr.lhs
    v = sp.Matrix([S.X_dot, S.Y_dot])
    c_body = rotation(S.psi, SYMBOLIC).T * v
    g60 = ns.g.subs({S.psi_dot: 0, S.x_dot: c_body[0], S.y_dot: c_body[1], ns.beta: phi - S.psi}, simultaneous=True)
    g60 = sp.collect(sp.expand(sp.expand_trig(sp.expand(g60))), [S.X_dot, S.Y_dot], sp.trigsimp)
    phi_true = sp.atan2(S.Y_dot, S.X_dot) + sp.pi / 2
    g_true = g60.subs(phi, phi_true)
    g_pr2 = sp.simplify(g60.subs(phi, p60.expr.rhs)**2)
    true_ok = symbolic_equal(g_true, 0)
    printed_fails = symbolic_equal(g_pr2, S.X_dot**2 + S.Y_dot**2)          # the whole speed is lateral
    rng = np.random.default_rng(seed)
    psi = rng.uniform(-np.pi, np.pi, n)
    V = rng.normal(size=(n, 2))
    tw = np.column_stack([np.zeros(n), np.einsum("nji,nj->ni", rotation(psi), V)])
    ph_pr = evaluate(p60.expr.rhs, (S.X_dot, S.Y_dot), V[:, 0], V[:, 1])
    ph_tr = evaluate(phi_true, (S.X_dot, S.Y_dot), V[:, 0], V[:, 1])
    beta_of = lambda ph: np.repeat((ph - psi)[:, None], 3, axis=1)        # (8): beta_i = phi_i - psi
    rep_pr, rep_tr = feasibility(beta_of(ph_pr), tw), feasibility(beta_of(ph_tr), tw)
    dev = float(np.max(np.abs(mod_pi(steering_angles(robot(), tw) - beta_of(ph_tr)))))
    alt = float(np.max(np.abs(mod_pi(ph_tr + np.pi / 2 - ph_pr))))
    holds = not printed_fails and rep_pr["admissible"] == 1.0
    proven = (true_ok and rep_tr["rank_J2_J1t"] == {3} and rep_tr["admissible"] == 1.0 and rep_tr["max_residual"] < TOL
              and dev < TOL)
    require(rep_pr["rank_J2_J1t"] == {4} and abs(rep_pr["min_rel_residual"] - 1) < TOL and alt < TOL,
            "printed angles: slip equal to the full speed; they are the angles of j_i")
    return Derivation(g=g60, g_true=g_true, g_printed_squared=g_pr2, phi_true=phi_true, printed=rep_pr, derived=rep_tr,
                      alt=alt, n=n, findings=[equation(
        60, holds, r"$g_i = 0$ in translation gives $\dot X\cos\phi_i + \dot Y\sin\phi_i = 0$, solved by "
                   r"$\phi_i = \operatorname{atan2}(\dot Y, \dot X) + \pi/2$ (SymPy); at these angles all "
                   rf"{n} random translations are executable with zero residual, as at `wmr.steering_angles`",
        rep_tr["max_residual"],
        refuted=r"with the printed angle the axle lies along the velocity: $g_i^2 = \dot X^2 + \dot Y^2$ (SymPy), and "
                rf"none of the {n} random translations is executable (rank $[\mathbf J_2\ \ \mathbf J_1\mathbf t] = 4$, "
                r"slip equal to the full speed)",
        corrected=r"\phi_i = \operatorname{atan2}(\dot Y, \dot X) + \frac{\pi}{2} \pmod{\pi}, \quad "
                  r"\text{i.e.}\quad \tan\phi_i = -\frac{\dot X}{\dot Y}",
        corrected_holds=proven, severity="wrong",
        why=r"the printed angle is the direction of the velocity, but by (6), (8) and (11) $\phi_i$ is the angle of the "
            r"axle $\mathbf i_i$, which must be perpendicular to it",
        convention=r"$\phi_i = \psi + \beta_i$ is the angle of the axle $\mathbf i_i$ ((6), (8), (11)); the printed form "
                   r"holds if $\phi_i$ is measured to the rolling direction $\mathbf j_i$ (the wheel's heading) instead",
        note=r"the printed $\tan^{-1}$ also needs $\dot X \neq 0$; with `atan2` the formula holds for every nonzero "
             r"velocity. Rank $\mathbf F = 5$ with either angles: the axles are parallel in both cases")])


def instant_centre_velocity(n=2000, seed=SEED):
    r"""(61)-(62): :math:`\mathbf u - \mathbf c = \mathbf R(\psi)[\mathbf u_c]_{\mathcal B}`, differentiated.

    Parameters
    ----------
    n : int
        Random twists and points for the comparison with ``wmr.point_velocity``.
    seed : int

    Returns
    -------
    Derivation
        ``u_dot`` (derived), findings (61) and (62).
    """
    p61, p62 = printed(61), printed(62)
    ns = no_slip()
    time = sp.Symbol("t", real=True)
    psi_t = sp.Function(r"\psi", real=True)(time)
    c_t = sp.Matrix([sp.Function("c_X", real=True)(time), sp.Function("c_Y", real=True)(time)])
    ucB = sp.Matrix(sp.symbols(r"u_{cx}^{\mathcal{B}} u_{cy}^{\mathcal{B}}", real=True))
    u_t = c_t + rotation(psi_t, SYMBOLIC) * ucB
    uc_world = u_t - c_t
    ok61 = symbolic_equal(p61.expr.subs(dict(zip(P.u, u_t)) | dict(zip(P.c, c_t)), simultaneous=True),
                          rotation(psi_t, SYMBOLIC) * ucB)
    u_dot = u_t.diff(time)
    subs = {S.x_dot: c_t[0].diff(time), S.y_dot: c_t[1].diff(time), S.psi_dot: psi_t.diff(time),
            P.u_c[0]: uc_world[0], P.u_c[1]: uc_world[1]}
    ok_fixed = symbolic_equal(u_dot, p62.expr.subs(subs, simultaneous=True))
    ok_body = symbolic_equal(point_row(tuple(P.u_c), backend=SYMBOLIC) * ns.t, p62.expr)
    commute = symbolic_equal(S.E * rotation(S.psi, SYMBOLIC), rotation(S.psi, SYMBOLIC) * S.E)
    rng = np.random.default_rng(seed)
    Tw, Uc = rng.normal(size=(n, 3)), rng.normal(size=(n, 2))
    res = float(np.max(np.abs(evaluate(p62.expr, (*ns.t, *P.u_c), *Tw.T, *Uc.T) - point_velocity(Tw, Uc))))
    shown = u_dot.subs({psi_t.diff(time): S.psi_dot, psi_t: S.psi, c_t[0].diff(time): S.X_dot, c_t[1].diff(time): S.Y_dot})
    return Derivation(u_dot=shown, findings=[
        equation(61, ok61, r"for the platform point at U, $\mathbf u - \mathbf c = \mathbf R(\psi)[\mathbf u_c]_{\mathcal B}$: "
                 r"the printed difference is $\overrightarrow{CU}$ in fixed components (SymPy)", 0.0,
                 convention=r"$\mathbf u$, $\mathbf c$ position vectors of U and C; $\mathbf u_c = \overrightarrow{CU}$",
                 note="a definition, used consistently in (62)-(64)"),
        equation(62, ok_fixed and ok_body and commute, r"the time derivative of $\mathbf c + \mathbf R(\psi)[\mathbf u_c]_{\mathcal B}$ "
                 r"is the printed right side in fixed components, and, since $\mathbf E\mathbf R = \mathbf R\mathbf E$, the "
                 r"model's row $[\mathbf E\mathbf u_c\ \ \mathbf 1]\mathbf t$ of (5) in body components (SymPy); "
                 rf"`wmr.point_velocity` agrees at {n} random twists and points", res,
                 convention=r"$\dot{\mathbf u}$ is the velocity of the platform point that coincides with U, not the motion of "
                            r"the centre itself")])


def instant_centre(n=2000, seed=SEED):
    r"""(63): the platform point at rest, from :math:`\dot{\mathbf u} = \mathbf 0`; its limits.

    Parameters
    ----------
    n : int
        Random rotations (:math:`|\dot\psi| \ge 0.2`).
    seed : int

    Returns
    -------
    Derivation
        ``det`` (of the affine velocity field), ``u_c`` (derived), ``limits`` (rows: case, kind, centre,
        direction), finding (63).
    """
    p63 = printed(63)
    ns = no_slip()
    vel = point_row(tuple(P.u_c), backend=SYMBOLIC) * ns.t
    coeffs = sp.Matrix([[vel[k].diff(P.u_c[j]) for j in range(2)] for k in range(2)])
    sol = sp.solve(list(vel), list(P.u_c), dict=True)
    require(len(sol) == 1, "one point at rest")
    uc = P.u_c.subs(sol[0])
    holds = symbolic_equal(uc, p63.expr)
    norm_ok = symbolic_equal(sum(e**2 for e in p63.expr), (S.x_dot**2 + S.y_dot**2) / S.psi_dot**2)
    rng = np.random.default_rng(seed)
    Tw = rng.normal(size=(n, 3))
    Tw[:, 0] = np.sign(Tw[:, 0]) * rng.uniform(0.2, 2.0, n)
    ic = instantaneous_centre(Tw)
    res = float(max(np.max(np.abs(evaluate(p63.expr, tuple(ns.t), *Tw.T) - ic.point)),
                    np.max(np.abs(point_velocity(Tw, ic.point)))))
    require(np.all(ic.kind == FINITE), "rotations have a finite centre")
    cases = {"translation": [0.0, 0.3, -0.4], "nearly a translation": [1e-7, 0.3, -0.4],
             "no motion": [0.0, 0.0, 0.0], "rotation about C": [0.7, 0.0, 0.0]}
    ics = {k: instantaneous_centre(v) for k, v in cases.items()}
    require(int(ics["translation"].kind) == AT_INFINITY and int(ics["no motion"].kind) == STILL
            and np.allclose(ics["translation"].direction, ics["nearly a translation"].direction, atol=1e-6)
            and np.allclose(ics["rotation about C"].point, 0.0), "the limits of (63)")
    limits = [{"twist": k, "centre": KIND_NAMES[int(c.kind)], r"$\mathbf u_c$": np.round(c.point, 3),
               "direction of U": np.round(c.direction, 6)} for k, c in ics.items()]
    return Derivation(det=coeffs.det(), u_c=uc, limits=limits, findings=[equation(
        63, holds and norm_ok, r"the velocity field is affine in the point with determinant $\dot\psi^2$, so for "
                               r"$\dot\psi \neq 0$ exactly one point is at rest, $\mathbf u_c = \mathbf E\dot{\mathbf c}/\dot\psi$ "
                               rf"(SymPy); `wmr.instantaneous_centre` agrees at {n} random rotations, with zero velocity there",
        res, convention=r"$\dot\psi \neq 0$; in translation the centre is at infinity along $\mathbf E\dot{\mathbf c}$, for a "
                        "twist of zero it is undefined; any frame, with $\\dot{\\mathbf c}$ and $\\mathbf u_c$ in the same "
                        "components")])


def centre_to_wheel(n=2000, seed=SEED):
    r"""(64): :math:`\mathbf u_i = \mathbf u_c - \mathbf d_i`; the mount point moves perpendicular to it.

    Parameters
    ----------
    n : int
    seed : int

    Returns
    -------
    Derivation
        ``u_i``, ``rotation_check`` (the model's velocity of :math:`P_i` plus :math:`\dot\psi\mathbf E\mathbf u_i`), finding (64).
    """
    p64 = printed(64)
    ns = no_slip()
    uc = instant_centre(n=1).u_c
    d = sp.Matrix([S.dx, S.dy])
    ui = uc - d
    p_dot = point_row((S.dx, S.dy), backend=SYMBOLIC) * ns.t
    rot = symbolic_equal(p_dot, -S.psi_dot * S.E * ui)
    rng = np.random.default_rng(seed)
    Tw = rng.normal(size=(n, 3))
    Tw[:, 0] = np.sign(Tw[:, 0]) * rng.uniform(0.2, 2.0, n)
    D = robot().mount_points
    ui_pr = np.stack([evaluate(p64.expr, (*ns.t, S.dx, S.dy), *Tw.T, D[i, 0], D[i, 1]) for i in range(3)], 1)
    res = float(np.max(np.abs(ui_pr - centre_to_wheels(Tw, D))))
    return Derivation(u_i=ui, rotation_check=sp.simplify(p_dot + S.psi_dot * S.E * ui), findings=[equation(
        64, symbolic_equal(ui, p64.expr) and rot, r"$\overrightarrow{P_iU} = \overrightarrow{CU} - \overrightarrow{CP_i}$ with "
                                                  r"the derived (63), and the model's velocity of $P_i$ is "
                                                  r"$-\dot\psi\mathbf E\mathbf u_i$, a rotation about U (SymPy); "
                                                  rf"`wmr.centre_to_wheels` agrees at {n} random rotations", res,
        convention=r"$\dot\psi \neq 0$; $\mathbf d_i$ and $\mathbf u_c$ in body components")])


def rotation_angles(n=2000, seed=SEED, eps=1e-7):
    r"""(65): in rotation about U each axle must point at U, :math:`\beta_i = \operatorname{atan2}(u_{iy}, u_{ix})` (mod :math:`\pi`).

    The printed formula measures the angle between :math:`\overrightarrow{CU}` and :math:`\overrightarrow{P_iU}`
    instead; it agrees only when U lies on the positive body x-axis.

    Parameters
    ----------
    n : int
        Random rotations.
    seed : int
    eps : float
        :math:`\dot\psi` of the nearly translating twists (the limit to (60)).

    Returns
    -------
    Derivation
        ``g`` (the condition in rotation about U), ``counterexample`` (rows: wheel, slip of the
        printed angle with either sign), ``reports`` (feasibility of printed, derived and printed
        with U on the +x axis), ``limit`` (of tan beta as psi_dot -> 0), ``at_C`` (printed right
        side at U = C), finding (65).
    """
    p64, p65 = printed(64), printed(65)
    ns = no_slip()
    ui = P.u_i
    d = sp.Matrix([S.dx, S.dy])
    c_dot = -S.psi_dot * S.E * (ui + d)                       # from u_dot = 0 with u_c = u_i + d_i
    g65 = sp.factor(sp.expand(ns.g.subs({S.x_dot: c_dot[0], S.y_dot: c_dot[1]}, simultaneous=True)))
    beta_true = sp.atan2(ui[1], ui[0])
    true_ok = symbolic_equal(g65.subs(ns.beta, beta_true), 0)
    a = sp.Symbol("a", positive=True)
    on_axis = symbolic_equal(p65.expr.rhs.subs({P.u_c[0]: a, P.u_c[1]: 0}), sp.cos(beta_true))
    exact = paper_robot("centred", L=1, r=1, exact=True)
    U = sp.Matrix([0, 1])
    rows = []
    for i, unit in enumerate(exact.wheels, 1):
        u_i = U - sp.Matrix(unit.position)
        sub = {P.u_c[0]: U[0], P.u_c[1]: U[1], P.u_i[0]: u_i[0], P.u_i[1]: u_i[1]}
        b_pr = sp.acos(sp.nsimplify(p65.expr.rhs.subs(sub)))
        slips = [float(g65.subs(sub).subs({ns.beta: s * b_pr, S.psi_dot: 1})) for s in (1, -1)]
        rows.append({"wheel": i, "printed": float(b_pr * 180 / sp.pi), "derived": float(beta_true.subs(sub) * 180 / sp.pi),
                     "slip_plus": slips[0], "slip_minus": slips[1]})
    cex = any(min(abs(x["slip_plus"]), abs(x["slip_minus"])) > TOL for x in rows)
    bot = robot()
    D = bot.mount_points
    rng = np.random.default_rng(seed)
    Tw = rng.normal(size=(n, 3))
    Tw[:, 0] = np.sign(Tw[:, 0]) * rng.uniform(0.2, 2.0, n)
    uc_n, ui_n = instantaneous_centre(Tw).point, centre_to_wheels(Tw, D)
    cos_pr = evaluate(p65.expr.rhs, (*P.u_c, *P.u_i), uc_n[:, None, 0], uc_n[:, None, 1], ui_n[..., 0], ui_n[..., 1])
    lateral = lambda b: np.abs(ui_n[..., 1] * np.cos(b) - ui_n[..., 0] * np.sin(b))
    b_pr = np.arccos(np.clip(cos_pr, -1, 1))
    b_pr = np.where(lateral(b_pr) <= lateral(-b_pr), b_pr, -b_pr)        # the better sign, wheel by wheel
    b_tr = np.arctan2(ui_n[..., 1], ui_n[..., 0])
    Tx = Tw.copy()
    Tx[:, 1] = 0.0
    Tx[:, 2] = -np.abs(Tx[:, 2]) * Tx[:, 0]                             # u_c = (-y_dot/psi_dot, 0) on the +x axis
    ui_x, uc_x = centre_to_wheels(Tx, D), instantaneous_centre(Tx).point
    cos_x = evaluate(p65.expr.rhs, (*P.u_c, *P.u_i), uc_x[:, None, 0], uc_x[:, None, 1], ui_x[..., 0], ui_x[..., 1])
    b_x = np.sign(ui_x[..., 1]) * np.arccos(np.clip(cos_x, -1, 1))
    reports = {"printed (65)": feasibility(b_pr, Tw), "derived": feasibility(b_tr, Tw),
               "printed, U on the positive x-axis": feasibility(b_x, Tx)}
    dev = float(np.max(np.abs(mod_pi(steering_angles(bot, Tw) - b_tr))))
    res = max(reports["derived"]["max_residual"], dev)
    tan_beta = p64.expr[1] / p64.expr[0]
    lim = sp.limit(tan_beta, S.psi_dot, 0)
    T_ = sp.Symbol("T")
    tan60 = sp.solve(ns.g.subs(S.psi_dot, 0).subs(sp.sin(ns.beta), T_ * sp.cos(ns.beta)), T_)[0]
    small = Tw.copy()
    small[:, 0] = eps
    dev_lim = float(np.max(np.abs(mod_pi(steering_angles(bot, small) - steering_angles(bot, small * [0, 1, 1])))))
    radial = float(np.max(np.abs(mod_pi(steering_angles(bot, [1.0, 0.0, 0.0]) - np.arctan2(D[:, 1], D[:, 0])))))
    limit_ok = symbolic_equal(lim, tan60) and dev_lim < 100 * eps and radial < TOL
    holds = reports["printed (65)"]["admissible"] == 1.0
    require(reports["printed, U on the positive x-axis"]["rank_F"] == {5}
            and reports["printed, U on the positive x-axis"]["admissible"] == 1.0 and on_axis,
            "the printed (65) holds with U on the positive x-axis")
    proven = (true_ok and reports["derived"]["rank_F"] == {5} and reports["derived"]["admissible"] == 1.0
              and res < TOL and limit_ok)
    return Derivation(g=g65, counterexample=rows, reports=reports, limit=lim, dev_lim=dev_lim, radial=radial,
                      at_C=p65.expr.rhs.subs({P.u_c[0]: 0, P.u_c[1]: 0}), n=n, findings=[equation(
        65, holds, r"$g_i = \dot\psi(u_{iy}\cos\beta_i - u_{ix}\sin\beta_i)$ in rotation about U, zero for "
                   r"$\beta_i = \operatorname{atan2}(u_{iy}, u_{ix})$ (SymPy); at these angles all " rf"{n} random rotations "
                   r"are executable (rank $\mathbf F = 5$, zero residual), they equal `wmr.steering_angles` mod $\pi$, and "
                   r"they tend to the corrected (60) as $\dot\psi \to 0$", res,
        refuted=r"the paper's robot rotating about $U = (0, 1)$: for wheels 2 and 3 neither sign of the printed angle points "
                rf"the axle at U (exact); at the printed angles none of {n} random rotations is executable "
                r"(rank $\mathbf F = 6$: jammed)" if cex else "the printed angles fail",
        corrected=r"\beta_i = \operatorname{atan2}(u_{iy}, u_{ix}) \pmod{\pi}, \quad \text{i.e.}\quad "
                  r"\cos\beta_i = \pm\frac{\mathbf i^{\mathrm T}\mathbf u_i}{\|\mathbf u_i\|},\ "
                  r"\sin\beta_i = \pm\frac{\mathbf j^{\mathrm T}\mathbf u_i}{\|\mathbf u_i\|}",
        corrected_holds=proven, severity="wrong",
        why=r"the printed formula gives the angle between $\overrightarrow{CU}$ and $\overrightarrow{P_iU}$; with $\beta_i$ "
            r"measured from the body axis $\mathbf i$ (11) the axle must be parallel to $\mathbf u_i$",
        convention=r"$\beta_i$ measured from the body axis $\mathbf i$ (11); the printed form holds only if $\beta_i$ is "
                   r"measured from the line CU (U on the positive body $x$-axis), up to the sign that $\arccos$ loses",
        note="the printed form is undefined for a rotation about C, where the corrected rule makes every axle radial")])
