r"""Chapter 1, equations (2)-(19): the platform, the rolling disk, offset, centred and dual wheels.

Every result is derived from first principles -- rigid-body velocities with 3D cross products
(:math:`\dot{\mathbf p} = \dot{\mathbf c} + \boldsymbol\omega\times\mathbf d`) and the no-slip
condition of a thin disk -- and compared with the printed form (:func:`wmr.paper.printed`) exactly
(SymPy) and with the package's builders and kernels numerically.  Frames: :mod:`wmr.conventions`
(axle :math:`\mathbf i_i`, rolling direction :math:`\mathbf j_i = \mathbf k\times\mathbf i_i`,
offset wheel centre :math:`H_i = P_i - d\,\mathbf j_i`, dual wheels at :math:`P_i \pm b\,\mathbf i_i`).
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np
import sympy as sp

from ...analysis.kinematics import inverse
from ...analysis.simulation import simulate
from ...model.backend import SYMBOLIC
from ...model.platform import E, point_row, point_velocity, rotation
from ...model.robot import Robot
from ...model.robots import paper_robot
from ...model.tolerance import TOL
from ...model.wheels import CentredWheel, DualWheel, OffsetWheel
from .. import platform_wheels as PW
from .. import printed
from .. import symbols as S
from ..text import bound
from ..verify import SEED, max_residual, symbolic_equal
from . import Derivation, equation, require

__all__ = ["k", "lift", "planar", "disk_velocity", "platform_point", "skew_matrix", "twist_layout", "platform_row",
           "rolling_disk", "steering_composition", "offset_wheel", "wheel_frame", "offset_in_body", "centred_wheel",
           "dual_no_slip", "dual_steering", "dual_integrated", "dual_average", "dual_average_angle"]

#: the vertical unit vector (3D)
k = sp.Matrix([0, 0, 1])
_t = sp.Symbol("t", real=True)


def lift(v):
    """A planar vector as a 3D vector with zero vertical component.

    Parameters
    ----------
    v : sequence of 2

    Returns
    -------
    sympy.Matrix (3, 1)
    """
    return sp.Matrix([v[0], v[1], 0])


def planar(v):
    """The planar part of a 3D vector (which must have no vertical component).

    Parameters
    ----------
    v : sympy.Matrix (3, 1)

    Returns
    -------
    sympy.Matrix (2, 1)
    """
    require(sp.simplify(v[2]) == 0, "a planar velocity has no vertical component")
    return sp.Matrix(v[:2])


@lru_cache(maxsize=None)
def disk_velocity(theta_dot, phi=PW.phi_i, phi_dot=PW.phi_dot_i, r=S.r):
    r"""Velocity of the centre of a thin disk rolling without slip, and its axes (derivation of (6)).

    The disk spins about its axle :math:`\mathbf i_i` at ``theta_dot`` and is steered about
    :math:`\mathbf k` at ``phi_dot``, :math:`\boldsymbol\Omega = \dot\theta\,\mathbf i_i + \dot\phi\,\mathbf k`;
    no slip: the material point at the contact :math:`H - r\mathbf k` is at rest,
    :math:`\dot{\mathbf h} + \boldsymbol\Omega\times(-r\mathbf k) = \mathbf 0`.

    Parameters
    ----------
    theta_dot, phi, phi_dot, r : SymPy symbols
        Rolling rate, absolute steering angle and rate, radius.

    Returns
    -------
    Derivation
        ``h_dot`` (3, 1) fixed-frame velocity of the centre, ``Omega``, the axle ``i3`` and rolling
        direction ``j3 = k x i3`` (3, 1).
    """
    i3 = sp.Matrix([sp.cos(phi), sp.sin(phi), 0])
    j3 = k.cross(i3)
    Omega = theta_dot * i3 + phi_dot * k
    v = sp.Matrix(sp.symbols("v_x v_y v_z", real=True))
    sol = sp.solve(list(v + Omega.cross(-r * k)), list(v), dict=True)[0]
    return Derivation(h_dot=v.subs(sol), Omega=Omega, i3=i3, j3=j3)


def _axes():
    d = disk_velocity(PW.theta_dot_i)
    return {PW.i_i: planar(d.i3), PW.j_i: planar(d.j3)}


def _explicit(expr, mapping):
    return sp.Matrix(expr.subs(mapping).doit())


# ----------------------------------------------------------------------------------------------- 3.1
def platform_point(n=500, seed=SEED):
    r"""(2): velocity of a platform point, :math:`\dot{\mathbf c} + \dot\psi\mathbf k\times\mathbf d_i` (3D cross product).

    Parameters
    ----------
    n : int
        Random twists and points for the check of :func:`wmr.point_velocity`.
    seed : int

    Returns
    -------
    Derivation
        ``p_dot`` (the derived velocity), finding (2).
    """
    P = printed(2)
    d_i = sp.Matrix(PW.d_i)
    p_dot = PW.c_dot + planar((S.psi_dot * k).cross(lift(d_i)))
    holds = symbolic_equal(p_dot, P.expr.rhs)
    res = max_residual(p_dot, P.expr.rhs)
    rng = np.random.default_rng(seed)
    tw, dd = rng.uniform(-2, 2, (n, 3)), rng.uniform(-2, 2, (n, 2))
    f = sp.lambdify([S.psi_dot, S.x_dot, S.y_dot, *PW.d_i], p_dot, "numpy")
    num = float(np.abs(point_velocity(tw, dd) - np.moveaxis(f(*tw.T, *dd.T)[:, 0], 0, -1)).max())
    require(num < TOL, "wmr.point_velocity equals the rigid-body velocity")
    return Derivation(p_dot=p_dot, findings=[equation(
        2, holds, rf"equal to $\dot{{\mathbf c}} + \dot\psi\,\mathbf k\times\mathbf d_i$ (3D cross product, SymPy); "
                  rf"`wmr.point_velocity` agrees at {n} random twists and points", max(res, num),
        convention=r"$\dot\psi\times\mathbf d_i$ read as $(\dot\psi\mathbf k)\times\mathbf d_i$; body-frame components",
        note=r"the extraction's undefined middle term $\dot{\mathbf c}_w$ dropped; the relation is frame-free "
             r"because $\mathbf E$ commutes with rotations")])


def skew_matrix():
    r"""(3): :math:`\mathbf E` has columns :math:`\mathbf k\times\mathbf e_1, \mathbf k\times\mathbf e_2`.

    Returns
    -------
    Derivation
        ``E`` (derived), finding (3).
    """
    P = printed(3)
    E_derived = sp.Matrix.hstack(planar(k.cross(lift([1, 0]))), planar(k.cross(lift([0, 1]))))
    M = P.expr.rhs
    holds = (symbolic_equal(E_derived, M) and symbolic_equal(M.T, -M) and symbolic_equal(rotation(sp.pi / 2, SYMBOLIC), M))
    require(symbolic_equal(E(SYMBOLIC), E_derived), "wmr.E is the derived matrix")
    res = float(np.abs(E() - np.array(E_derived, dtype=float)).max())
    return Derivation(E=E_derived, findings=[equation(
        3, holds, r"the columns $\mathbf k\times\mathbf e_1$, $\mathbf k\times\mathbf e_2$ (SymPy); skew-symmetric and "
                  r"equal to the rotation through $+90^\circ$; `wmr.E` is the same matrix", res,
        convention=r"$\mathbf k$ up, angles counter-clockwise positive")])


def twist_layout():
    r"""(4): the twist is ordered :math:`[\dot\psi\ \dot x\ \dot y]`, as the package's generalised rates are.

    Returns
    -------
    Derivation
        ``names`` (the package's first three rate names), finding (4).
    """
    P = printed(4)
    bot = Robot([CentredWheel(PW.d_i, r=S.r)])
    holds = list(bot.twist_symbols) == list(P.expr.rhs)
    return Derivation(names=bot.qdot_names[:3], findings=[equation(
        4, holds, r"`Robot.twist_symbols` is $[\dot\psi\ \dot x\ \dot y]$, the order used by "
                  r"$\mathbf J_1$, $\mathbf F$ and the kinematics", 0.0,
        convention=r"$\mathbf t = [\dot\psi\ \dot x\ \dot y]^{\mathrm T}$, $\dot{\mathbf c}$ in body components")])


def platform_row(n=5, samples=500, seed=SEED):
    r"""(5): the row :math:`[\mathbf E\mathbf d_i\ \ \mathbf 1]` (``point_row``) against the printed matrix and (2).

    Parameters
    ----------
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
    row = point_row(PW.d_i, backend=SYMBOLIC)
    bot = Robot([CentredWheel(PW.d_i, r=S.r)])
    t = sp.Matrix(bot.twist_symbols)
    p_dot = platform_point(n=1).p_dot
    holds = (symbolic_equal(row, P.extra["matrix"]) and symbolic_equal(row * t, p_dot)
             and symbolic_equal(sp.nsimplify(bot.J1()), P.extra["matrix"]))
    res = max_residual(row * t, P.expr.rhs)
    rng = np.random.default_rng(seed)
    tw, dd = rng.uniform(-2, 2, (samples, 3)), rng.uniform(-2, 2, (n, 2))
    J1 = Robot([CentredWheel(p, r=1.0) for p in dd]).J1()
    num = float(np.abs((tw[:, None, :] @ J1.T)[:, 0].reshape(-1, n, 2) - point_velocity(tw[:, None, :], dd)).max())
    require(num < TOL, "the numeric J1 times a twist equals wmr.point_velocity")
    return Derivation(row=row, findings=[equation(
        5, holds, r"`point_row` and the blocks of `Robot.J1` equal the printed row, and the row times $\mathbf t$ "
                  rf"equals the derived (2) (SymPy); the numeric $\mathbf J_1$ of a {n}-unit robot agrees with "
                  rf"`wmr.point_velocity` at {samples} random twists", max(res, num),
        convention=r"$\mathbf t$ ordered as (4)")])


# ----------------------------------------------------------------------------------------------- 3.2
def rolling_disk():
    r"""(6): the wheel centre moves along :math:`-\mathbf j_i` at :math:`r\dot\theta_i`; the steering rate drops out.

    Returns
    -------
    Derivation
        ``h_dot`` (3, 1), ``Omega``, ``along`` (components along :math:`\mathbf i_i, \mathbf j_i`), finding (6).
    """
    P = printed(6)
    d = disk_velocity(PW.theta_dot_i)
    along = sp.Matrix([sp.trigsimp(d.i3.dot(d.h_dot)), sp.trigsimp(d.j3.dot(d.h_dot))])
    rhs = _explicit(P.expr.rhs, _axes())
    holds = symbolic_equal(planar(d.h_dot), rhs)
    res = max_residual(planar(d.h_dot), rhs)
    return Derivation(h_dot=d.h_dot, Omega=d.Omega, along=along, findings=[equation(
        6, holds, r"solving $\dot{\mathbf h}_i + \boldsymbol\Omega\times(-r\mathbf k) = \mathbf 0$ with "
                  r"$\boldsymbol\Omega = \dot\theta_i\mathbf i_i + \dot\phi_i\mathbf k$ gives the printed form (SymPy)", res,
        convention=r"$\dot\theta_i$ positive about $+\mathbf i_i$ (right-hand rule); $\mathbf j_i = \mathbf k\times\mathbf i_i$")])


def steering_composition(n=200, seed=SEED):
    r"""(7)-(8): :math:`\mathbf R(\psi)\mathbf R(\beta_i) = \mathbf R(\psi+\beta_i)`, and its rate from :math:`\dot{\mathbf R}\mathbf R^{\mathrm T}`.

    Parameters
    ----------
    n : int
        Random rates for the check of ``OffsetWheel.beta_rate``.
    seed : int

    Returns
    -------
    Derivation
        ``W`` (:math:`\dot{\mathbf R}\mathbf R^{\mathrm T}`), findings (7) and (8).
    """
    P7, P8 = printed(7), printed(8)
    R_wheel = rotation(S.psi, SYMBOLIC) * rotation(PW.beta_i, SYMBOLIC)
    holds8 = symbolic_equal(R_wheel, rotation(P8.expr.rhs, SYMBOLIC))
    res8 = max_residual(R_wheel, rotation(P8.expr.rhs, SYMBOLIC))
    psi_t, beta_t = sp.Function("psi")(_t), sp.Function("beta")(_t)
    R_t = rotation(psi_t, SYMBOLIC) * rotation(beta_t, SYMBOLIC)
    W = (R_t.diff(_t) * R_t.T).applyfunc(lambda e: sp.trigsimp(sp.expand(e)))
    omega = W[1, 0]
    dots = {psi_t.diff(_t): sp.Symbol(r"\dot\psi"), beta_t.diff(_t): sp.Symbol(r"\dot\beta_i")}
    to_t = {S.psi_dot: psi_t.diff(_t), PW.beta_dot_i: beta_t.diff(_t)}
    holds7 = symbolic_equal(W, omega * E(SYMBOLIC)) and symbolic_equal(omega, P7.expr.rhs.subs(to_t))
    rng = np.random.default_rng(seed)
    psi_d, phi_d = rng.uniform(-3, 3, (2, n))
    unit = OffsetWheel((0.3, 0.1), r=0.1, d=0.05)
    num7 = float(np.abs(psi_d + unit.beta_rate(psi_d, np.stack([phi_d, 0 * phi_d], -1)) - phi_d).max())
    require(num7 < TOL, "OffsetWheel.beta_rate implements (7)")
    conv = r"$\beta_i$ relative to the platform, $\phi_i$ absolute"
    return Derivation(W=W.subs(dots), findings=[
        equation(7, holds7, r"$\dot{\mathbf R}\mathbf R^{\mathrm T} = (\dot\psi + \dot\beta_i)\mathbf E$ for "
                            r"$\mathbf R = \mathbf R(\psi(t))\mathbf R(\beta_i(t))$ (SymPy); `OffsetWheel.beta_rate` "
                            rf"implements it ({n} random rates)", num7, convention=conv),
        equation(8, holds8, r"$\mathbf R(\psi)\mathbf R(\beta_i) = \mathbf R(\psi + \beta_i)$ (SymPy)", res8,
                 convention=conv, note=r"the gloss after (8), '$\psi$ and $\beta_i$ are both zero if $\phi_i = 0$', "
                                       r"states the converse of the intended zero integration constant")])


def offset_wheel(n=50):
    r"""(9): velocity of the steering-axis point of an offset wheel, from (6) and the rigid intermediate body.

    :math:`\dot{\mathbf p}_i = \dot{\mathbf h}_i + \dot\phi_i\mathbf k\times(P_i - H_i)` with
    :math:`P_i - H_i = d\,\mathbf j_i`; the other side, :math:`H_i = P_i + d\,\mathbf j_i`, flips the sign.

    Parameters
    ----------
    n : int
        Random steering angles at which the package's wheel centre is checked.

    Returns
    -------
    Derivation
        ``p_dot`` (3, 1), ``other_side`` (printed minus the velocity with the centre on the other side), finding (9).
    """
    P = printed(9)
    d = disk_velocity(PW.theta_dot_i)
    p_dot = d.h_dot + (PW.phi_dot_i * k).cross(S.d * d.j3)
    rhs = _explicit(P.expr.rhs, _axes())
    holds = symbolic_equal(planar(p_dot), rhs)
    res = max_residual(planar(p_dot), rhs)
    other = planar(d.h_dot + (PW.phi_dot_i * k).cross(-S.d * d.j3))
    other_fails = not symbolic_equal(other, rhs)
    betas = np.random.default_rng(SEED).uniform(-np.pi, np.pi, n)
    pts = OffsetWheel((0.4, -0.2), r=0.1, d=0.07).points(betas)
    require(np.abs(pts["H"] - (pts["P"] - 0.07 * pts["j"])).max() < TOL, "the package puts H_i at P_i - d j_i")
    require(other_fails, "the other side of the offset gives another sign")
    return Derivation(p_dot=p_dot, other_side=(other - rhs).applyfunc(sp.factor), findings=[equation(
        9, holds, r"$\dot{\mathbf h}_i + \dot\phi_i\mathbf k\times d\,\mathbf j_i$ with (6) equals the printed form "
                  r"(SymPy); the centre on the other side, $P_i + d\,\mathbf j_i$, gives $+d\dot\phi_i\mathbf i_i$; "
                  r"`OffsetWheel.points` puts the centre at $P_i - d\,\mathbf j_i$", res,
        convention=r"wheel centre $H_i = P_i - d\,\mathbf j_i$; $\dot\phi_i$ the absolute steering rate",
        note="the side of the offset is not stated in the text (Fig. 4 is missing); this is the side that gives the "
             "printed sign")])


def wheel_frame():
    r"""(11): the columns of :math:`\mathbf R_{bwi}` are the wheel axes in body components.

    Returns
    -------
    Derivation
        ``R`` (the axes :math:`[\mathbf i_i\ \mathbf j_i]` in the body frame), finding (11).
    """
    P = printed(11)
    d = disk_velocity(PW.theta_dot_i)
    axes_F = sp.Matrix.hstack(planar(d.i3), planar(d.j3)).subs(PW.phi_i, S.psi + PW.beta_i)
    R = (rotation(S.psi, SYMBOLIC).T * axes_F).applyfunc(lambda e: sp.trigsimp(sp.expand_trig(e)))
    M = P.expr.rhs
    holds = (symbolic_equal(R, M) and symbolic_equal(rotation(PW.beta_i, SYMBOLIC), M)
             and symbolic_equal(M.T * M, sp.eye(2)) and symbolic_equal(M.det(), 1))
    return Derivation(R=R, findings=[equation(
        11, holds, r"the wheel axes at $\phi_i = \psi + \beta_i$ rotated back by $\psi$ are the printed columns "
                   r"(SymPy); orthogonal with determinant 1, equal to `wmr.rotation`", max_residual(R, M),
        convention=r"$\beta_i$ counter-clockwise from $\mathbf i$ to $\mathbf i_i$")])


def offset_in_body():
    r"""(10): (9) in body components, against the printed form and ``OffsetWheel.block``.

    Returns
    -------
    Derivation
        ``p_dot_B`` (body components), ``in_wheel_frame`` (components along :math:`\mathbf i_i, \mathbf j_i`), finding (10).
    """
    P = printed(10)
    d = disk_velocity(PW.theta_dot_i)
    p9 = planar(offset_wheel(n=1).p_dot)
    p_B = (rotation(S.psi, SYMBOLIC).T * p9.subs(PW.phi_i, S.psi + PW.beta_i)).applyfunc(
        lambda e: sp.trigsimp(sp.expand(sp.expand_trig(e))))
    in_wheel = sp.Matrix([planar(d.i3).dot(p9), planar(d.j3).dot(p9)]).applyfunc(sp.trigsimp)
    unit = OffsetWheel(PW.d_i, r=S.r, d=S.d)
    require(unit.rate_names(1) == ("phi_dot_1", "theta_dot_1"), "the offset unit's rates are (phi_dot, theta_dot)")
    p_wmr = unit.block(PW.beta_i) * sp.Matrix([PW.phi_dot_i, PW.theta_dot_i])
    holds = (symbolic_equal(p_B, P.expr.rhs) and symbolic_equal(p_wmr, P.expr.rhs)
             and symbolic_equal(in_wheel, sp.Matrix([-S.d * PW.phi_dot_i, -S.r * PW.theta_dot_i])))
    res = max(max_residual(p_B, P.expr.rhs), max_residual(p_wmr, P.expr.rhs))
    return Derivation(p_dot_B=p_B, in_wheel_frame=in_wheel, findings=[equation(
        10, holds, r"(9) rotated into the body frame equals $\mathbf R_{bwi}[-d\dot\phi_i\ \ -r\dot\theta_i]^{\mathrm T}$ "
                   r"and `OffsetWheel.block` times the rates (SymPy)", res,
        convention=r"$H_i = P_i - d\,\mathbf j_i$; $[\dot{\mathbf p}_i]$ in wheel-frame components")])


def centred_wheel():
    r"""(12): the offset wheel with :math:`d = 0`, against the printed form and ``CentredWheel.block``.

    Returns
    -------
    Derivation
        ``p_dot_B``, finding (12).
    """
    P = printed(12)
    p_B = offset_in_body().p_dot_B.subs(S.d, 0)
    p_wmr = CentredWheel(PW.d_i, r=S.r).block(PW.beta_i) * sp.Matrix([PW.theta_dot_i])
    holds = symbolic_equal(p_B, P.expr.rhs) and symbolic_equal(p_wmr, P.expr.rhs)
    res = max(max_residual(p_B, P.expr.rhs), max_residual(p_wmr, P.expr.rhs))
    return Derivation(p_dot_B=p_B, findings=[equation(
        12, holds, r"the derived (10) at $d = 0$ and `CentredWheel.block` equal the printed form (SymPy)", res,
        convention="(10) with $d = 0$")])


# ----------------------------------------------------------------------------------------------- dual wheel
def dual_no_slip():
    r"""(13)-(14): each wheel of a dual-wheel unit is a rolling disk on the common axle.

    Returns
    -------
    Derivation
        ``h_dot_1``, ``h_dot_2`` (3, 1), findings (13) and (14).
    """
    out, found = {}, []
    for P, th, name in ((printed(13), PW.theta_dot_i1, "h_dot_1"), (printed(14), PW.theta_dot_i2, "h_dot_2")):
        h = disk_velocity(th).h_dot
        rhs = _explicit(P.expr.rhs, _axes())
        out[name] = h
        found.append(equation(P.id, symbolic_equal(planar(h), rhs),
                              r"the derivation of (6) for this wheel's rolling rate gives the printed form (SymPy)",
                              max_residual(planar(h), rhs), convention=r"as (6), common axle $\mathbf i_i$",
                              note=("the extraction's dotted $\\dot{\\mathbf j}_i$ read as the unit vector "
                                    "$\\mathbf j_i$" if P.id == "13" else "")))
    return Derivation(**out, findings=found)


@lru_cache(maxsize=None)
def _turning_rate():
    """omega_z of the intermediate body from the two wheel velocities (rigid body): the derivation of (15)."""
    d1, d2 = disk_velocity(PW.theta_dot_i1), disk_velocity(PW.theta_dot_i2)
    omega_z = sp.Symbol(r"\omega_z", real=True)
    rigid = d1.h_dot - d2.h_dot - (omega_z * k).cross(2 * S.b * d1.i3)      # H_i1 - H_i2 = 2 b i_i
    require(sp.trigsimp(d1.i3.dot(rigid)) == 0, "the axle component of the rigid-body relation vanishes")
    return rigid, sp.solve(sp.trigsimp(d1.j3.dot(rigid)), omega_z)[0]


def dual_steering(n=500, seed=SEED, r=0.1, b=0.08, L=0.5):
    r"""(15): the wheel-rate difference fixes the *absolute* turning rate :math:`\dot\phi_i`, not :math:`\dot\beta_i`.

    Derivation: the two wheel centres belong to the intermediate body, which turns at
    :math:`\omega_z`; :math:`\dot{\mathbf h}_{i1} - \dot{\mathbf h}_{i2} = \omega_z\mathbf k\times 2b\,\mathbf i_i`.
    Counterexample: the paper's dual-wheel robot spinning about C at 1 rad/s with every axle
    through C and the units locked (:math:`\dot\beta_i = 0`): admissible, no slip, yet the printed
    law predicts :math:`\dot\beta_i = \dot\psi`.

    Parameters
    ----------
    n : int
        Random unit states for the numeric check of the corrected law.
    seed : int
    r, b, L : float
        Radius, half separation and mount radius of the counterexample robot.

    Returns
    -------
    Derivation
        ``rigid`` (the rigid-body relation), ``phi_dot`` (the derived turning rate), ``beta_dot``,
        ``difference`` (printed minus derived), ``spin`` (rows of the counterexample), finding (15).
    """
    P = printed(15)
    rigid, phi_dot = _turning_rate()
    beta_dot = phi_dot - S.psi_dot                                        # (7)
    holds = symbolic_equal(P.expr.rhs, beta_dot)
    diff = sp.simplify(P.expr.rhs - beta_dot)
    off_by_psi_dot = symbolic_equal(diff, S.psi_dot)
    # the counterexample: spin about C, axles through C, units locked
    dual = paper_robot("dual", L=L, r=r, b=b)
    beta = np.arctan2(dual.mount_points[:, 1], dual.mount_points[:, 0])
    spin = np.array([1.0, 0.0, 0.0])
    sol = inverse(dual, beta, spin)
    require(bool(sol.admissible), "the spin about C with axles through C is admissible")
    rows = []
    for i, (dp, bt) in enumerate(zip(dual.mount_points, beta)):
        ii, jj = np.array([np.cos(bt), np.sin(bt)]), np.array([-np.sin(bt), np.cos(bt)])
        v1, v2 = point_velocity(spin, dp + b * ii), point_velocity(spin, dp - b * ii)
        th1, th2 = -jj @ v1 / r, -jj @ v2 / r
        rows.append({"unit": i + 1, "sideways slip": max(abs(ii @ v1), abs(ii @ v2)), "theta1": th1, "theta2": th2,
                     "printed": -r / (2 * b) * (th1 - th2), "true": 0.0})
    require(max(x["sideways slip"] for x in rows) < TOL, "the spin needs no sideways slip")
    require(np.allclose(sol.value, [v for x in rows for v in (x["theta1"], x["theta2"])]), "wmr.inverse finds the rates")
    printed_gap = max(abs(x["printed"] - x["true"]) for x in rows)
    # the corrected law at random unit states
    rng = np.random.default_rng(seed)
    bt, psid, betad, s = rng.uniform(-np.pi, np.pi, n), rng.uniform(-3, 3, n), rng.uniform(-3, 3, n), rng.uniform(-2, 2, n)
    rr, bb = rng.uniform(0.05, 0.5, n), rng.uniform(0.05, 0.5, n)
    jj = np.stack([-np.sin(bt), np.cos(bt)], -1)
    phid = psid + betad
    v1 = (s + phid * bb)[:, None] * jj                                      # p_dot + phi_dot k x (+b i)
    v2 = (s - phid * bb)[:, None] * jj
    th1, th2 = -(v1 * jj).sum(-1) / rr, -(v2 * jj).sum(-1) / rr
    f = sp.lambdify([PW.theta_dot_i1, PW.theta_dot_i2, S.r, S.b], phi_dot)
    res = float(np.abs(f(th1, th2, rr, bb) - phid).max())
    m = min(n, 50)
    res_wmr = max(abs(DualWheel((0.0, 0.0), r=float(a), b=float(c)).beta_rate(p, np.array([x, y])) - q)
                  for a, c, p, x, y, q in zip(rr[:m], bb[:m], psid, th1, th2, betad))
    corrected = (r"\dot\phi_i = \dot\psi + \dot\beta_i = " + sp.latex(phi_dot))
    return Derivation(rigid=rigid.applyfunc(sp.factor), phi_dot=phi_dot, beta_dot=beta_dot, difference=diff,
                      spin=rows, findings=[equation(
        15, holds, r"$\dot\phi_i = -\frac{r}{2b}(\dot\theta_{i1} - \dot\theta_{i2})$ from "
                   r"$\dot{\mathbf h}_{i1} - \dot{\mathbf h}_{i2} = \dot\phi_i\mathbf k\times 2b\,\mathbf i_i$ (SymPy); "
                   rf"at {n} random unit states the rates give $\dot\psi + \dot\beta_i$ (and `DualWheel.beta_rate` "
                   rf"gives $\dot\beta_i$ at {m})", max(res, res_wmr),
        refuted=(r"printed minus derived is exactly $\dot\psi$" if off_by_psi_dot else "printed differs from the derivation")
                + rf"; a spin about C at $\dot\psi = 1$ with locked units: printed $\dot\beta_i = {printed_gap:.3g}$, true 0",
        corrected=corrected, corrected_holds=res < TOL and res_wmr < TOL, severity="wrong",
        why=r"the wheel-rate difference fixes the absolute turning rate $\dot\phi_i$ of the unit, not its rate "
            r"$\dot\beta_i$ relative to the platform; the printed form is off by $\dot\psi$",
        convention=r"wheel 1 at $P_i + b\,\mathbf i_i$, wheel 2 at $P_i - b\,\mathbf i_i$; $\beta_i$ relative to the platform")])


def dual_integrated(r=0.1, b=0.08, L=0.5, steps=100):
    r"""(16): the integral of the corrected (15), and a finite counterexample to the printed one.

    A quarter turn of the platform about C with the units locked (``wmr.simulate``): the printed
    (16) claims each unit turned by :math:`\pi/2` relative to the platform; it did not, and had it
    turned, the motion would need slip.

    Parameters
    ----------
    r, b, L : float
        The counterexample robot.
    steps : int
        Integration steps of the quarter turn.

    Returns
    -------
    Derivation
        ``phi`` (the corrected integral), ``printed_change``, ``true_change`` (arrays, rad), finding (16).
    """
    P15, P16 = printed(15), printed(16)
    _, phi_dot = _turning_rate()
    th1_t, th2_t = sp.Function("theta_1")(_t), sp.Function("theta_2")(_t)
    phi = phi_dot.subs({PW.theta_dot_i1: th1_t, PW.theta_dot_i2: th2_t})       # same linear form in the angles
    shown = phi.subs({th1_t: PW.theta_i1, th2_t: PW.theta_i2})
    rates_t = {PW.theta_dot_i1: th1_t.diff(_t), PW.theta_dot_i2: th2_t.diff(_t)}
    corrected_ok = symbolic_equal(phi.diff(_t), phi_dot.subs(rates_t))
    inherits = symbolic_equal(P16.expr.rhs.subs({PW.theta_i1: th1_t, PW.theta_i2: th2_t}).diff(_t), P15.expr.rhs.subs(rates_t))
    dual = paper_robot("dual", L=L, r=r, b=b)
    beta0 = np.arctan2(dual.mount_points[:, 1], dual.mount_points[:, 0])
    sol = inverse(dual, beta0, np.array([1.0, 0.0, 0.0]))
    T = np.pi / 2
    run = simulate(dual, sol.value, beta0, t_end=T, dt=T / steps)
    dth = (sol.value * T).reshape(3, 2)                                  # wheel angles after the turn (from zero)
    f16 = sp.lambdify([PW.theta_i1, PW.theta_i2, S.r, S.b], P16.expr.rhs, "numpy")
    printed_change = np.asarray(f16(dth[:, 0], dth[:, 1], r, b), dtype=float) * np.ones(3)
    true_change = run.beta[-1] - beta0
    jam = inverse(dual, beta0 + printed_change, np.array([1.0, 0.0, 0.0]))
    corrected_change = -r / (2 * b) * (dth[:, 0] - dth[:, 1])            # the corrected (16): the change of psi + beta_i
    res = float(np.abs(corrected_change - (run.pose[-1, 0] + true_change)).max())
    holds = bool(np.allclose(printed_change, true_change, atol=1e-6))
    return Derivation(phi=shown, printed_change=printed_change, true_change=true_change, findings=[equation(
        16, holds, r"$\phi_i = \psi + \beta_i = -\frac{r}{2b}(\theta_{i1} - \theta_{i2})$ differentiates into the "
                   rf"corrected (15) (SymPy); in a simulated quarter turn (`wmr.simulate`, {steps} steps) the change of "
                   r"$\psi + \beta_i$ equals it", res,
        refuted=(r"it differentiates into the printed (15)" if inherits else "it is not the integral of (15)")
                + rf"; a quarter turn with locked units: printed $\Delta\beta_i = {printed_change[0]:.4g}$, simulated "
                  rf"${bound(abs(true_change).max(), latex=True)}$ with slip ${bound(run.slip.max(), latex=True)}$, "
                  "and the spin is "
                  + ("not " if not jam.admissible else "") + "admissible at the printed angles",
        corrected=r"\phi_i = \psi + \beta_i = -\frac{r}{2b}\left(\theta_{i1} - \theta_{i2}\right)",
        corrected_holds=corrected_ok and run.slip.max() < TOL and not jam.admissible and res < 1e-9, severity="wrong",
        why="the integral of the printed (15), and wrong for the same reason: the wheel angles fix the absolute "
            r"heading $\phi_i$, not $\beta_i$",
        convention="as (15); all angles zero together",
        note="the residual is the integration error of the simulated turn (RK4)")])


def dual_average():
    r"""(17)-(18): the midpoint of a dual wheel moves like a centred wheel rolling at the average rate.

    Returns
    -------
    Derivation
        ``h_dot`` (3, 1), findings (17) and (18).
    """
    P17, P18 = printed(17), printed(18)
    _, phi_dot = _turning_rate()
    d1, d2 = disk_velocity(PW.theta_dot_i1), disk_velocity(PW.theta_dot_i2)
    h = planar(d1.h_dot + (phi_dot * k).cross(-S.b * d1.i3))
    axes = _axes()
    members = (_explicit(P17.extra["definition"], {PW.h_dot_i1: planar(d1.h_dot), PW.h_dot_i2: planar(d2.h_dot)}),
               _explicit(P17.expr.rhs, axes), _explicit(P17.extra["average_form"], axes).subs(PW.theta_dot_i, P18.expr.rhs))
    holds17 = all(symbolic_equal(h, x) for x in members)
    res17 = max(max_residual(h, x) for x in members)
    dual_unit, centred_unit = DualWheel(PW.d_i, r=S.r, b=S.b), CentredWheel(PW.d_i, r=S.r)
    lhs = dual_unit.block(PW.beta_i) * sp.Matrix([PW.theta_dot_i1, PW.theta_dot_i2])
    rhs = centred_unit.block(PW.beta_i) * sp.Matrix([P18.expr.rhs])
    h_B = rotation(S.psi, SYMBOLIC).T * h.subs(PW.phi_i, S.psi + PW.beta_i)
    holds18 = symbolic_equal(lhs, rhs) and symbolic_equal(lhs, h_B)
    res18 = max(max_residual(lhs, rhs), max_residual(lhs, h_B))
    return Derivation(h_dot=h, findings=[
        equation(17, holds17, "the midpoint's velocity from wheel 1 with the derived turning rate equals all three "
                              "members of the printed chain (SymPy)", res17,
                 convention=r"$H_i = P_i$, midway between the wheels"),
        equation(18, holds18, "with it, `DualWheel.block` equals `CentredWheel.block` at the average rate and the "
                              "derived (17) (SymPy)", res18, convention="definition",
                 note=r"kinematic equivalence for the velocity of $P_i$, not for the steering law (see (15))")])


def dual_average_angle():
    r"""(19): the time derivative of (19) is (18).

    Returns
    -------
    Derivation
        finding (19).
    """
    P18, P19 = printed(18), printed(19)
    th1_t, th2_t = sp.Function("theta_1")(_t), sp.Function("theta_2")(_t)
    avg = P19.expr.rhs.subs({PW.theta_i1: th1_t, PW.theta_i2: th2_t})
    rates_t = {PW.theta_dot_i1: th1_t.diff(_t), PW.theta_dot_i2: th2_t.diff(_t)}
    holds = symbolic_equal(avg.diff(_t), P18.expr.rhs.subs(rates_t))
    return Derivation(findings=[equation(19, holds, r"its time derivative is (18) (SymPy)", 0.0,
                                         convention="all angles zero together")])
