r"""The dual wheel, (13)-(19): no slip, the turning rate, its integral and the average.

Chapter 1's checks live in :mod:`edition.checks.wheels`; this module holds one group of them.  Each check
takes what the chapter derived (the wheel centres' velocities, the turning rate, ...) and compares it with
the printed form, the package and simulations.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.integration import integrate
from wmr.analysis.kinematics import inverse
from wmr.model.backend import SYMBOLIC
from wmr.model.platform import point_velocity, rotation
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL
from wmr.model.wheels import CentredWheel, DualWheel

from ... import symbols as S
from ...algebra import explicit
from ...text import bound
from ...transcription import printed
from ...verify import SEED, max_residual, symbolic_equal
from .. import Derivation, equation, require
from .frames import planar, time, unit_axes

__all__ = ["dual_no_slip", "dual_steering", "dual_integrated", "dual_average", "dual_average_angle"]


def dual_no_slip(h_dot_1, h_dot_2, i3, j3):
    r"""(13)-(14): each wheel of a dual-wheel unit is a rolling disk on the common axle.

    Parameters
    ----------
    h_dot_1, h_dot_2 : sympy.Matrix (3, 1)
        The derived centre velocities of wheels 1 and 2 (rolling rates ``S.theta_dot_i1``, ``S.theta_dot_i2``).
    i3, j3 : sympy.Matrix (3, 1)
        The common axle and rolling direction.

    Returns
    -------
    Derivation
        findings (13) and (14).
    """
    found = []
    for P, h in ((printed(13), h_dot_1), (printed(14), h_dot_2)):
        rhs = explicit(P.expr.rhs, unit_axes(i3, j3))
        found.append(
            equation(
                P.id,
                symbolic_equal(planar(h), rhs),
                r"the derivation of (6) for this wheel's rolling rate gives the printed form (SymPy)",
                max_residual(planar(h), rhs),
                convention=r"as (6), common axle $\mathbf i_i$",
                note=(
                    "the extraction's dotted $\\dot{\\mathbf j}_i$ read as the unit vector $\\mathbf j_i$"
                    if P.id == "13"
                    else ""
                ),
            )
        )
    return Derivation(findings=found)


def dual_steering(phi_dot, rigid, i3, n=500, seed=SEED, r=0.1, b=0.08, L=0.5):
    r"""(15): the wheel-rate difference fixes the *absolute* turning rate :math:`\dot\phi_i`, not :math:`\dot\beta_i`.

    Derivation: the two wheel centres belong to the intermediate body, which turns at
    :math:`\omega_z`; :math:`\dot{\mathbf h}_{i1} - \dot{\mathbf h}_{i2} = \omega_z\mathbf k\times 2b\,\mathbf i_i`.
    Counterexample: the paper's dual-wheel robot spinning about C at 1 rad/s with every axle
    through C and the units locked (:math:`\dot\beta_i = 0`): admissible, no slip, yet the printed
    law predicts :math:`\dot\beta_i = \dot\psi`.

    Parameters
    ----------
    phi_dot : SymPy expression
        The derived turning rate of the unit, in ``S.theta_dot_i1``, ``S.theta_dot_i2``, ``S.r``, ``S.b``.
    rigid : sympy.Matrix (3, 1)
        The rigid-body relation it was solved from (its axle component must vanish).
    i3 : sympy.Matrix (3, 1)
        The common axle.
    n : int
        Random unit states for the numeric check of the corrected law.
    seed : int
    r, b, L : float
        Radius, half separation and mount radius of the counterexample robot.

    Returns
    -------
    Derivation
        ``beta_dot``, ``difference`` (printed minus derived), ``spin`` (rows of the counterexample), finding (15).
    """
    P = printed(15)
    require(sp.trigsimp(i3.dot(rigid)) == 0, "the axle component of the rigid-body relation vanishes")
    beta_dot = phi_dot - S.psi_dot  # (7)
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
    for i, (dp, bt) in enumerate(zip(dual.mount_points, beta, strict=True)):
        ii, jj = np.array([np.cos(bt), np.sin(bt)]), np.array([-np.sin(bt), np.cos(bt)])
        v1, v2 = point_velocity(spin, dp + b * ii), point_velocity(spin, dp - b * ii)
        th1, th2 = -jj @ v1 / r, -jj @ v2 / r
        rows.append(
            {
                "unit": i + 1,
                "sideways slip": max(abs(ii @ v1), abs(ii @ v2)),
                "theta1": th1,
                "theta2": th2,
                "printed": -r / (2 * b) * (th1 - th2),
                "true": 0.0,
            }
        )
    require(max(x["sideways slip"] for x in rows) < TOL, "the spin needs no sideways slip")
    require(
        np.allclose(sol.value, [v for x in rows for v in (x["theta1"], x["theta2"])]), "wmr.inverse finds the rates"
    )
    printed_gap = max(abs(x["printed"] - x["true"]) for x in rows)
    # the corrected law at random unit states
    rng = np.random.default_rng(seed)
    bt, psid, betad, s = (
        rng.uniform(-np.pi, np.pi, n),
        rng.uniform(-3, 3, n),
        rng.uniform(-3, 3, n),
        rng.uniform(-2, 2, n),
    )
    rr, bb = rng.uniform(0.05, 0.5, n), rng.uniform(0.05, 0.5, n)
    jj = np.stack([-np.sin(bt), np.cos(bt)], -1)
    phid = psid + betad
    v1 = (s + phid * bb)[:, None] * jj  # p_dot + phi_dot k x (+b i)
    v2 = (s - phid * bb)[:, None] * jj
    th1, th2 = -(v1 * jj).sum(-1) / rr, -(v2 * jj).sum(-1) / rr
    f = sp.lambdify([S.theta_dot_i1, S.theta_dot_i2, S.r, S.b], phi_dot)
    res = float(np.abs(f(th1, th2, rr, bb) - phid).max())
    m = min(n, 50)
    res_wmr = max(
        abs(DualWheel((0.0, 0.0), r=float(a), b=float(c)).beta_rate(p, np.array([x, y])) - q)
        for a, c, p, x, y, q in zip(rr[:m], bb[:m], psid, th1, th2, betad, strict=False)
    )
    corrected = r"\dot\phi_i = \dot\psi + \dot\beta_i = " + sp.latex(phi_dot)
    return Derivation(
        beta_dot=beta_dot,
        difference=diff,
        spin=rows,
        findings=[
            equation(
                15,
                holds,
                r"$\dot\phi_i = -\frac{r}{2b}(\dot\theta_{i1} - \dot\theta_{i2})$ from "
                r"$\dot{\mathbf h}_{i1} - \dot{\mathbf h}_{i2} = \dot\phi_i\mathbf k\times 2b\,\mathbf i_i$ "
                r"(SymPy); "
                rf"at {n} random unit states the rates give $\dot\psi + \dot\beta_i$ (and `DualWheel.beta_rate` "
                rf"gives $\dot\beta_i$ at {m})",
                max(res, res_wmr),
                refuted=(
                    r"printed minus derived is exactly "
                    r"$\dot\psi$"
                    if off_by_psi_dot
                    else "printed differs from the derivation"
                )
                + rf"; a spin about C at $\dot\psi = 1$ with locked units: printed $\dot\beta_i = {printed_gap:.3g}$, "
                r"true 0",
                corrected=corrected,
                corrected_holds=res < TOL and res_wmr < TOL,
                severity="wrong",
                overturn=(
                    r"reading $\beta_i$ in (15) as the unit's absolute heading $\phi_i$, not the angle relative to the "
                    r"platform that (11) defines: the printed form is then the corrected one"
                ),
                why=r"the wheel-rate difference fixes the absolute turning rate $\dot\phi_i$ of the unit, not its rate "
                r"$\dot\beta_i$ relative to the platform; the printed form is off by $\dot\psi$",
                convention=r"wheel 1 at $P_i + b\,\mathbf i_i$, wheel 2 at $P_i - b\,\mathbf i_i$; $\beta_i$ relative to the "
                r"platform",
            )
        ],
    )


def dual_integrated(phi, phi_dot, r=0.1, b=0.08, L=0.5, steps=100):
    r"""(16): the integral of the corrected (15), and a finite counterexample to the printed one.

    A quarter turn of the platform about C with the units locked (``wmr.integrate``): the printed
    (16) claims each unit turned by :math:`\pi/2` relative to the platform; it did not, and had it
    turned, the motion would need slip.

    Parameters
    ----------
    phi : SymPy expression
        The derived heading :math:`\phi_i`, in ``S.theta_i1``, ``S.theta_i2``, ``S.r``, ``S.b``.
    phi_dot : SymPy expression
        The derived rate (15) it must integrate.
    r, b, L : float
        The counterexample robot.
    steps : int
        Integration steps of the quarter turn.

    Returns
    -------
    Derivation
        ``printed_change``, ``true_change`` (arrays, rad), finding (16).
    """
    P15, P16 = printed(15), printed(16)
    th1_t, th2_t = sp.Function("theta_1")(time), sp.Function("theta_2")(time)
    rates_t = {S.theta_dot_i1: th1_t.diff(time), S.theta_dot_i2: th2_t.diff(time)}
    phi_t = phi.subs({S.theta_i1: th1_t, S.theta_i2: th2_t})
    corrected_ok = symbolic_equal(phi_t.diff(time), phi_dot.subs(rates_t)) and symbolic_equal(
        phi.subs({S.theta_i1: 0, S.theta_i2: 0}), 0
    )
    inherits = symbolic_equal(
        P16.expr.rhs.subs({S.theta_i1: th1_t, S.theta_i2: th2_t}).diff(time), P15.expr.rhs.subs(rates_t)
    )
    dual = paper_robot("dual", L=L, r=r, b=b)
    beta0 = np.arctan2(dual.mount_points[:, 1], dual.mount_points[:, 0])
    sol = inverse(dual, beta0, np.array([1.0, 0.0, 0.0]))
    T = np.pi / 2
    run = integrate(dual, sol.value, beta0, t_end=T, dt=T / steps)
    dth = (sol.value * T).reshape(3, 2)  # wheel angles after the turn (from zero)
    f16 = sp.lambdify([S.theta_i1, S.theta_i2, S.r, S.b], P16.expr.rhs, "numpy")
    printed_change = np.asarray(f16(dth[:, 0], dth[:, 1], r, b), dtype=float) * np.ones(3)
    true_change = run.beta[-1] - beta0
    jam = inverse(dual, beta0 + printed_change, np.array([1.0, 0.0, 0.0]))
    # the corrected (16): the change of psi + beta_i
    corrected_change = -r / (2 * b) * (dth[:, 0] - dth[:, 1])
    res = float(np.abs(corrected_change - (run.pose[-1, 0] + true_change)).max())
    holds = bool(np.allclose(printed_change, true_change, atol=1e-6))
    return Derivation(
        printed_change=printed_change,
        true_change=true_change,
        findings=[
            equation(
                16,
                holds,
                r"$\phi_i = \psi + \beta_i = -\frac{r}{2b}(\theta_{i1} - \theta_{i2})$ differentiates into the "
                rf"corrected (15) (SymPy); in a simulated quarter turn (`wmr.integrate`, {steps} steps) the change "
                r"of $\psi + \beta_i$ equals it",
                res,
                refuted=(r"it differentiates into the printed (15)" if inherits else "it is not the integral of (15)")
                + rf"; a quarter turn with locked units: printed $\Delta\beta_i = {printed_change[0]:.4g}$, simulated "
                rf"${bound(abs(true_change).max(), latex=True)}$ with slip ${bound(run.slip.max(), latex=True)}$, "
                "and the spin is " + ("not " if not jam.admissible else "") + "admissible at the printed angles",
                corrected=r"\phi_i = \psi + \beta_i = -\frac{r}{2b}\left(\theta_{i1} - \theta_{i2}\right)",
                corrected_holds=corrected_ok and run.slip.max() < TOL and not jam.admissible and res < 1e-9,
                severity="wrong",
                overturn=(
                    r"as (15): reading $\beta_i$ as the absolute heading $\phi_i$; (16) then holds with all angles zero "
                    r"together"
                ),
                why="the integral of the printed (15), and wrong for the same reason: the wheel angles fix the absolute "
                r"heading $\phi_i$, not $\beta_i$",
                convention="as (15); all angles zero together",
                note="the residual is the integration error of the simulated turn (RK4)",
            )
        ],
    )


def dual_average(h, h_dot_1, h_dot_2, i3, j3):
    r"""(17)-(18): the midpoint of a dual wheel moves like a centred wheel rolling at the average rate.

    Parameters
    ----------
    h : sympy.Matrix (2, 1)
        The derived velocity of the midpoint :math:`H_i = P_i` (fixed frame).
    h_dot_1, h_dot_2 : sympy.Matrix (3, 1)
        The derived velocities of the two wheel centres.
    i3, j3 : sympy.Matrix (3, 1)
        The common axle and rolling direction.

    Returns
    -------
    Derivation
        findings (17) and (18).
    """
    P17, P18 = printed(17), printed(18)
    h = sp.Matrix(h)
    axes = unit_axes(i3, j3)
    members = (
        explicit(P17.extra["definition"], {S.h_dot_i1: planar(h_dot_1), S.h_dot_i2: planar(h_dot_2)}),
        explicit(P17.expr.rhs, axes),
        explicit(P17.extra["average_form"], axes).subs(S.theta_dot_i, P18.expr.rhs),
    )
    holds17 = all(symbolic_equal(h, x) for x in members)
    res17 = max(max_residual(h, x) for x in members)
    dual_unit, centred_unit = DualWheel(S.d_i, r=S.r, b=S.b), CentredWheel(S.d_i, r=S.r)
    lhs = dual_unit.block(S.beta_i) * sp.Matrix([S.theta_dot_i1, S.theta_dot_i2])
    rhs = centred_unit.block(S.beta_i) * sp.Matrix([P18.expr.rhs])
    h_B = rotation(S.psi, SYMBOLIC).T * h.subs(S.phi_i, S.psi + S.beta_i)
    holds18 = symbolic_equal(lhs, rhs) and symbolic_equal(lhs, h_B)
    res18 = max(max_residual(lhs, rhs), max_residual(lhs, h_B))
    return Derivation(
        findings=[
            equation(
                17,
                holds17,
                "the midpoint's velocity from wheel 1 with the derived turning rate equals all three "
                "members of the printed chain (SymPy)",
                res17,
                convention=r"$H_i = P_i$, midway between the wheels",
            ),
            equation(
                18,
                holds18,
                "with it, `DualWheel.block` equals `CentredWheel.block` at the average rate and the "
                "derived (17) (SymPy)",
                res18,
                convention="definition",
                note=r"kinematic equivalence for the velocity of $P_i$, not for the steering law (see (15))",
            ),
        ]
    )


def dual_average_angle():
    r"""(19): the time derivative of (19) is (18).

    Returns
    -------
    Derivation
        finding (19).
    """
    P18, P19 = printed(18), printed(19)
    th1_t, th2_t = sp.Function("theta_1")(time), sp.Function("theta_2")(time)
    avg = P19.expr.rhs.subs({S.theta_i1: th1_t, S.theta_i2: th2_t})
    rates_t = {S.theta_dot_i1: th1_t.diff(time), S.theta_dot_i2: th2_t.diff(time)}
    holds = symbolic_equal(avg.diff(time), P18.expr.rhs.subs(rates_t))
    return Derivation(
        findings=[
            equation(19, holds, r"its time derivative is (18) (SymPy)", 0.0, convention="all angles zero together")
        ]
    )
