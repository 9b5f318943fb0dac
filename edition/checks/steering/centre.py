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
from .constraint import KIND_NAMES, TWIST, evaluate, robot

__all__ = ["instant_centre_velocity", "instant_centre", "centre_to_wheel"]


def instant_centre_velocity(u_t, u_dot, c_t, psi_t, time, n=2000, seed=SEED):
    r"""Judge (61)-(62): the chapter's :math:`\mathbf u(t) = \mathbf c + \mathbf R(\psi)[\mathbf u_c]_{\mathcal B}`
    and its derivative against the printed forms.

    Parameters
    ----------
    u_t : sympy.Matrix (2, 1)
        Position of the platform point at U, a function of ``time``.
    u_dot : sympy.Matrix (2, 1)
        Its derivative, derived in Chapter 5.
    c_t : sympy.Matrix (2, 1)
        Position of C, functions of ``time``.
    psi_t : sympy.Expr
        :math:`\psi(t)`.
    time : sympy.Symbol
    n : int
        Random twists and points for the comparison with ``wmr.point_velocity``.
    seed : int

    Returns
    -------
    Derivation
        findings (61) and (62).
    """
    p61, p62 = printed(61), printed(62)
    require(symbolic_equal(u_dot, u_t.diff(time)), "u_dot is the derivative of u")
    uc_world = u_t - c_t
    ok61 = symbolic_equal(
        p61.expr.subs(dict(zip(S.u, u_t, strict=True)) | dict(zip(S.c, c_t, strict=True)), simultaneous=True), uc_world
    )
    require(
        symbolic_equal(uc_world, rotation(psi_t, SYMBOLIC) * uc_world.subs(psi_t, 0)),
        "u - c is the body vector of U turned by R(psi)",
    )
    subs = {
        S.x_dot: c_t[0].diff(time),
        S.y_dot: c_t[1].diff(time),
        S.psi_dot: psi_t.diff(time),
        S.u_c[0]: uc_world[0],
        S.u_c[1]: uc_world[1],
    }
    ok_fixed = symbolic_equal(u_dot, p62.expr.subs(subs, simultaneous=True))
    ok_body = symbolic_equal(point_row(tuple(S.u_c), backend=SYMBOLIC) * TWIST, p62.expr)
    commute = symbolic_equal(E(SYMBOLIC) * rotation(S.psi, SYMBOLIC), rotation(S.psi, SYMBOLIC) * E(SYMBOLIC))
    rng = np.random.default_rng(seed)
    Tw, Uc = rng.normal(size=(n, 3)), rng.normal(size=(n, 2))
    res = float(np.max(np.abs(evaluate(p62.expr, (*TWIST, *S.u_c), *Tw.T, *Uc.T) - point_velocity(Tw, Uc))))
    return Derivation(
        findings=[
            equation(
                61,
                ok61,
                r"for the platform point at U, "
                r"$\mathbf u - \mathbf c = \mathbf R(\psi)[\mathbf u_c]_{\mathcal B}$: the printed difference is "
                r"$\overrightarrow{CU}$ in fixed components (SymPy)",
                0.0,
                convention=r"$\mathbf u$, $\mathbf c$ position vectors of U and C; "
                r"$\mathbf u_c = \overrightarrow{CU}$",
                note="a definition, used consistently in (62)-(64)",
            ),
            equation(
                62,
                ok_fixed and ok_body and commute,
                r"the time derivative of "
                r"$\mathbf c + \mathbf R(\psi)[\mathbf u_c]_{\mathcal B}$ is the printed right side in fixed "
                r"components, and, since $\mathbf E\mathbf R = \mathbf R\mathbf E$, the model's row "
                r"$[\mathbf E\mathbf u_c\ \ \mathbf 1]\mathbf t$ of (5) in body components (SymPy); "
                f"`wmr.point_velocity` agrees at {n} random twists and points",
                res,
                convention=r"$\dot{\mathbf u}$ is the velocity of the platform point that coincides with U, not the "
                r"motion of the centre itself",
            ),
        ]
    )


def instant_centre(u_c, det, n=2000, seed=SEED):
    r"""Judge (63): the platform point at rest, derived in the chapter from :math:`\dot{\mathbf u} = \mathbf 0`;
    its limits.

    Parameters
    ----------
    u_c : sympy.Matrix (2, 1)
        The derived point at rest, in the twist symbols.
    det : sympy.Expr
        Determinant of the (affine) velocity field's coefficients.
    n : int
        Random rotations (:math:`|\dot\psi| \ge 0.2`).
    seed : int

    Returns
    -------
    Derivation
        ``limits`` (rows: case, kind, centre, direction), finding (63).
    """
    p63 = printed(63)
    vel = point_row(tuple(u_c), backend=SYMBOLIC) * TWIST
    require(
        symbolic_equal(vel, sp.zeros(2, 1)) and symbolic_equal(det, S.psi_dot**2),
        "the model's velocity vanishes at u_c, and only there for psi_dot != 0",
    )
    holds = symbolic_equal(u_c, p63.expr)
    norm_ok = symbolic_equal(sum(e**2 for e in p63.expr), (S.x_dot**2 + S.y_dot**2) / S.psi_dot**2)
    rng = np.random.default_rng(seed)
    Tw = rng.normal(size=(n, 3))
    Tw[:, 0] = np.sign(Tw[:, 0]) * rng.uniform(0.2, 2.0, n)
    ic = instantaneous_centre(Tw)
    res = float(
        max(
            np.max(np.abs(evaluate(p63.expr, tuple(TWIST), *Tw.T) - ic.point)),
            np.max(np.abs(point_velocity(Tw, ic.point))),
        )
    )
    require(np.all(ic.kind == FINITE), "rotations have a finite centre")
    cases = {
        "translation": [0.0, 0.3, -0.4],
        "nearly a translation": [1e-7, 0.3, -0.4],
        "no motion": [0.0, 0.0, 0.0],
        "rotation about C": [0.7, 0.0, 0.0],
    }
    ics = {k: instantaneous_centre(v) for k, v in cases.items()}
    require(
        int(ics["translation"].kind) == AT_INFINITY
        and int(ics["no motion"].kind) == STILL
        and np.allclose(ics["translation"].direction, ics["nearly a translation"].direction, atol=1e-6)
        and np.allclose(ics["rotation about C"].point, 0.0),
        "the limits of (63)",
    )
    limits = [
        {
            "twist": k,
            "centre": KIND_NAMES[Meet(int(c.kind))],
            r"$\mathbf u_c$": np.round(c.point, 3),
            "direction of U": np.round(c.direction, 6),
        }
        for k, c in ics.items()
    ]
    return Derivation(
        limits=limits,
        findings=[
            equation(
                63,
                holds and norm_ok,
                r"the velocity field is affine in the point with determinant $\dot\psi^2$, so for "
                r"$\dot\psi \neq 0$ exactly one point is at rest, "
                r"$\mathbf u_c = \mathbf E\dot{\mathbf c}/\dot\psi$ "
                f"(SymPy); `wmr.instantaneous_centre` agrees at {n} random rotations, with zero "
                "velocity there",
                res,
                convention=r"$\dot\psi \neq 0$; in translation the centre is at infinity along "
                r"$\mathbf E\dot{\mathbf c}$, for a "
                "twist of zero it is undefined; any frame, with $\\dot{\\mathbf c}$ and $\\mathbf u_c$ in the "
                "same components",
            )
        ],
    )


def centre_to_wheel(u_i, n=2000, seed=SEED):
    r"""Judge (64): the chapter's :math:`\mathbf u_i = \mathbf u_c - \mathbf d_i`; the mount point moves perpendicular
    to it.

    Parameters
    ----------
    u_i : sympy.Matrix (2, 1)
        Derived in Chapter 5, in the twist symbols and :math:`d_x, d_y`.
    n : int
    seed : int

    Returns
    -------
    Derivation
        finding (64).
    """
    p64 = printed(64)
    p_dot = point_row((S.dx, S.dy), backend=SYMBOLIC) * TWIST
    rot = symbolic_equal(p_dot, -S.psi_dot * E(SYMBOLIC) * u_i)
    rng = np.random.default_rng(seed)
    Tw = rng.normal(size=(n, 3))
    Tw[:, 0] = np.sign(Tw[:, 0]) * rng.uniform(0.2, 2.0, n)
    D = robot().mount_points
    ui_pr = np.stack([evaluate(p64.expr, (*TWIST, S.dx, S.dy), *Tw.T, D[i, 0], D[i, 1]) for i in range(3)], 1)
    res = float(np.max(np.abs(ui_pr - centre_to_wheels(Tw, D))))
    return Derivation(
        findings=[
            equation(
                64,
                symbolic_equal(u_i, p64.expr) and rot,
                r"$\overrightarrow{P_iU} = \overrightarrow{CU} - "
                r"\overrightarrow{CP_i}$ with the derived (63), and the model's "
                r"velocity of $P_i$ is $-\dot\psi\mathbf E\mathbf u_i$, a rotation "
                r"about U (SymPy); "
                f"`wmr.centre_to_wheels` agrees at {n} random rotations",
                res,
                convention=r"$\dot\psi \neq 0$; $\mathbf d_i$ and $\mathbf u_c$ in body components",
            )
        ]
    )
