r"""The instantaneous centre, (61)-(64).

Chapter 5's checks live in :mod:`edition.checks.steering`; this module holds one group of them.
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.lines import Meet
from wmr.analysis.steering import AT_INFINITY, FINITE, STILL, centre_to_wheels, instantaneous_centre
from wmr.model.backend import SYMBOLIC
from wmr.model.platform import E, point_row, point_velocity, rotation

from ... import symbols as S
from ...transcription import printed
from ...verify import SEED, symbolic_equal
from .. import Derivation, equation, require
from .constraint import KIND_NAMES, evaluate, no_slip, robot

__all__ = ["instant_centre_velocity", "instant_centre", "centre_to_wheel"]


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
    ok61 = symbolic_equal(p61.expr.subs(dict(zip(S.u, u_t, strict=True)) | dict(zip(S.c, c_t, strict=True)),
                                        simultaneous=True),
                          rotation(psi_t, SYMBOLIC) * ucB)
    u_dot = u_t.diff(time)
    subs = {S.x_dot: c_t[0].diff(time), S.y_dot: c_t[1].diff(time), S.psi_dot: psi_t.diff(time),
            S.u_c[0]: uc_world[0], S.u_c[1]: uc_world[1]}
    ok_fixed = symbolic_equal(u_dot, p62.expr.subs(subs, simultaneous=True))
    ok_body = symbolic_equal(point_row(tuple(S.u_c), backend=SYMBOLIC) * ns.t, p62.expr)
    commute = symbolic_equal(E(SYMBOLIC) * rotation(S.psi, SYMBOLIC), rotation(S.psi, SYMBOLIC) * E(SYMBOLIC))
    rng = np.random.default_rng(seed)
    Tw, Uc = rng.normal(size=(n, 3)), rng.normal(size=(n, 2))
    res = float(np.max(np.abs(evaluate(p62.expr, (*ns.t, *S.u_c), *Tw.T, *Uc.T) - point_velocity(Tw, Uc))))
    shown = u_dot.subs({psi_t.diff(time): S.psi_dot, psi_t: S.psi, c_t[0].diff(time): S.X_dot,
                        c_t[1].diff(time): S.Y_dot})
    return Derivation(u_dot=shown, findings=[
        equation(61, ok61, r"for the platform point at U, "
                 r"$\mathbf u - \mathbf c = \mathbf R(\psi)[\mathbf u_c]_{\mathcal B}$: the printed difference is "
                 r"$\overrightarrow{CU}$ in fixed components (SymPy)", 0.0,
                 convention=r"$\mathbf u$, $\mathbf c$ position vectors of U and C; "
                            r"$\mathbf u_c = \overrightarrow{CU}$",
                 note="a definition, used consistently in (62)-(64)"),
        equation(62, ok_fixed and ok_body and commute, r"the time derivative of "
                 r"$\mathbf c + \mathbf R(\psi)[\mathbf u_c]_{\mathcal B}$ is the printed right side in fixed "
                 r"components, and, since $\mathbf E\mathbf R = \mathbf R\mathbf E$, the model's row "
                 r"$[\mathbf E\mathbf u_c\ \ \mathbf 1]\mathbf t$ of (5) in body components (SymPy); "
                 f"`wmr.point_velocity` agrees at {n} random twists and points", res,
                 convention=r"$\dot{\mathbf u}$ is the velocity of the platform point that coincides with U, not the "
                            r"motion of the centre itself")])


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
    vel = point_row(tuple(S.u_c), backend=SYMBOLIC) * ns.t
    coeffs = sp.Matrix([[vel[k].diff(S.u_c[j]) for j in range(2)] for k in range(2)])
    sol = sp.solve(list(vel), list(S.u_c), dict=True)
    require(len(sol) == 1, "one point at rest")
    uc = S.u_c.subs(sol[0])
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
    limits = [{"twist": k, "centre": KIND_NAMES[Meet(int(c.kind))], r"$\mathbf u_c$": np.round(c.point, 3),
               "direction of U": np.round(c.direction, 6)} for k, c in ics.items()]
    return Derivation(det=coeffs.det(), u_c=uc, limits=limits, findings=[equation(
        63, holds and norm_ok, r"the velocity field is affine in the point with determinant $\dot\psi^2$, so for "
                               r"$\dot\psi \neq 0$ exactly one point is at rest, "
                               r"$\mathbf u_c = \mathbf E\dot{\mathbf c}/\dot\psi$ "
                               f"(SymPy); `wmr.instantaneous_centre` agrees at {n} random rotations, with zero "
                               "velocity there",
        res, convention=r"$\dot\psi \neq 0$; in translation the centre is at infinity along "
                        r"$\mathbf E\dot{\mathbf c}$, for a "
                        "twist of zero it is undefined; any frame, with $\\dot{\\mathbf c}$ and $\\mathbf u_c$ in the "
                        "same components")])


def centre_to_wheel(n=2000, seed=SEED):
    r"""(64): :math:`\mathbf u_i = \mathbf u_c - \mathbf d_i`; the mount point moves perpendicular to it.

    Parameters
    ----------
    n : int
    seed : int

    Returns
    -------
    Derivation
        ``u_i``, ``rotation_check`` (the model's velocity of :math:`P_i` plus :math:`\dot\psi\mathbf E\mathbf u_i`),
        finding (64).
    """
    p64 = printed(64)
    ns = no_slip()
    uc = instant_centre(n=1).u_c
    d = sp.Matrix([S.dx, S.dy])
    ui = uc - d
    p_dot = point_row((S.dx, S.dy), backend=SYMBOLIC) * ns.t
    rot = symbolic_equal(p_dot, -S.psi_dot * E(SYMBOLIC) * ui)
    rng = np.random.default_rng(seed)
    Tw = rng.normal(size=(n, 3))
    Tw[:, 0] = np.sign(Tw[:, 0]) * rng.uniform(0.2, 2.0, n)
    D = robot().mount_points
    ui_pr = np.stack([evaluate(p64.expr, (*ns.t, S.dx, S.dy), *Tw.T, D[i, 0], D[i, 1]) for i in range(3)], 1)
    res = float(np.max(np.abs(ui_pr - centre_to_wheels(Tw, D))))
    return Derivation(u_i=ui, rotation_check=sp.simplify(p_dot + S.psi_dot * E(SYMBOLIC) * ui), findings=[equation(
        64, symbolic_equal(ui, p64.expr) and rot, r"$\overrightarrow{P_iU} = \overrightarrow{CU} - "
                                                  r"\overrightarrow{CP_i}$ with the derived (63), and the model's "
                                                  r"velocity of $P_i$ is $-\dot\psi\mathbf E\mathbf u_i$, a rotation "
                                                  r"about U (SymPy); "
                                                  f"`wmr.centre_to_wheels` agrees at {n} random rotations", res,
        convention=r"$\dot\psi \neq 0$; $\mathbf d_i$ and $\mathbf u_c$ in body components")])
