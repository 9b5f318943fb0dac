r"""One wheel, (6)-(12): rolling disk, steering composition, offset and centred wheels.

Chapter 1's checks live in :mod:`edition.checks.wheels`; this module holds one group of them.  Each check
takes what the chapter derived (the rolling disk's ``h_dot`` and axes ``i3``, ``j3``, ...) and compares it
with the printed form and the package.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.model.backend import SYMBOLIC
from wmr.model.platform import E, rotation
from wmr.model.tolerance import TOL
from wmr.model.wheels import CentredWheel, OffsetWheel

from ... import symbols as S
from ...algebra import explicit
from ...transcription import printed
from ...verify import SEED, max_residual, symbolic_equal
from .. import Derivation, equation, require
from .frames import k, planar, time, unit_axes

__all__ = ["rolling_disk", "steering_composition", "offset_wheel", "wheel_frame", "offset_in_body", "centred_wheel"]


def rolling_disk(h_dot, i3, j3):
    r"""(6): the wheel centre moves along :math:`-\mathbf j_i` at :math:`r\dot\theta_i`; the steering rate drops out.

    Parameters
    ----------
    h_dot : sympy.Matrix (3, 1)
        The derived velocity of the wheel centre (fixed frame), in ``S.theta_dot_i``, ``S.phi_i``, ``S.r``.
    i3, j3 : sympy.Matrix (3, 1)
        The axle and the rolling direction at the absolute angle ``S.phi_i``.

    Returns
    -------
    Derivation
        finding (6).
    """
    P = printed(6)
    require(symbolic_equal(j3, k.cross(i3)), "the rolling direction is k x i_i")
    rhs = explicit(P.expr.rhs, unit_axes(i3, j3))
    holds = symbolic_equal(planar(h_dot), rhs)
    res = max_residual(planar(h_dot), rhs)
    return Derivation(
        findings=[
            equation(
                6,
                holds,
                r"solving $\dot{\mathbf h}_i + \boldsymbol\Omega\times(-r\mathbf k) = \mathbf 0$ with "
                r"$\boldsymbol\Omega = \dot\theta_i\mathbf i_i + \dot\phi_i\mathbf k$ gives the printed form "
                r"(SymPy)",
                res,
                convention=r"$\dot\theta_i$ positive about $+\mathbf i_i$ (right-hand rule); "
                r"$\mathbf j_i = \mathbf k\times\mathbf i_i$",
            )
        ]
    )


def steering_composition(R_wheel, W, n=200, seed=SEED):
    r"""(7)-(8): :math:`\mathbf R(\psi)\mathbf R(\beta_i) = \mathbf R(\psi+\beta_i)`, and its rate from
    :math:`\dot{\mathbf R}\mathbf R^{\mathrm T}`.

    Parameters
    ----------
    R_wheel : sympy.Matrix (2, 2)
        The derived orientation of the wheel frame, in ``S.psi`` and ``S.beta_i``.
    W : sympy.Matrix (2, 2)
        The derived :math:`\dot{\mathbf R}\mathbf R^{\mathrm T}` of ``R_wheel`` with :math:`\psi(t)`,
        :math:`\beta(t)` functions of :data:`~.frames.time` named ``psi`` and ``beta``.
    n : int
        Random rates for the check of ``OffsetWheel.beta_rate``.
    seed : int

    Returns
    -------
    Derivation
        findings (7) and (8).
    """
    P7, P8 = printed(7), printed(8)
    holds8 = symbolic_equal(R_wheel, rotation(P8.expr.rhs, SYMBOLIC))
    res8 = max_residual(R_wheel, rotation(P8.expr.rhs, SYMBOLIC))
    psi_t, beta_t = sp.Function("psi")(time), sp.Function("beta")(time)
    omega = W[1, 0]
    to_t = {S.psi_dot: psi_t.diff(time), S.beta_dot_i: beta_t.diff(time)}
    holds7 = symbolic_equal(W, omega * E(SYMBOLIC)) and symbolic_equal(omega, P7.expr.rhs.subs(to_t))
    rng = np.random.default_rng(seed)
    psi_d, phi_d = rng.uniform(-3, 3, (2, n))
    unit = OffsetWheel((0.3, 0.1), r=0.1, d=0.05)
    num7 = float(np.abs(psi_d + unit.beta_rate(psi_d, np.stack([phi_d, 0 * phi_d], -1)) - phi_d).max())
    require(num7 < TOL, "OffsetWheel.beta_rate implements (7)")
    conv = r"$\beta_i$ relative to the platform, $\phi_i$ absolute"
    return Derivation(
        findings=[
            equation(
                7,
                holds7,
                r"$\dot{\mathbf R}\mathbf R^{\mathrm T} = (\dot\psi + \dot\beta_i)\mathbf E$ for "
                r"$\mathbf R = \mathbf R(\psi(t))\mathbf R(\beta_i(t))$ (SymPy); `OffsetWheel.beta_rate` "
                rf"implements it ({n} random rates)",
                num7,
                convention=conv,
            ),
            equation(
                8,
                holds8,
                r"$\mathbf R(\psi)\mathbf R(\beta_i) = \mathbf R(\psi + \beta_i)$ (SymPy)",
                res8,
                convention=conv,
                note=r"the gloss after (8), '$\psi$ and $\beta_i$ are both zero if $\phi_i = 0$', "
                r"states the converse of the intended zero integration constant",
            ),
        ]
    )


def offset_wheel(p_dot, i3, j3, n=50):
    r"""(9): velocity of the steering-axis point of an offset wheel, from (6) and the rigid intermediate body.

    :math:`\dot{\mathbf p}_i = \dot{\mathbf h}_i + \dot\phi_i\mathbf k\times(P_i - H_i)` with
    :math:`P_i - H_i = d\,\mathbf j_i`; the other side, :math:`H_i = P_i + d\,\mathbf j_i` (``p_dot`` with
    :math:`d \to -d`), must give another sign.

    Parameters
    ----------
    p_dot : sympy.Matrix (3, 1)
        The derived velocity of :math:`P_i` (fixed frame).
    i3, j3 : sympy.Matrix (3, 1)
        The wheel axes of the rolling disk.
    n : int
        Random steering angles at which the package's wheel centre is checked.

    Returns
    -------
    Derivation
        finding (9).
    """
    P = printed(9)
    rhs = explicit(P.expr.rhs, unit_axes(i3, j3))
    holds = symbolic_equal(planar(p_dot), rhs)
    res = max_residual(planar(p_dot), rhs)
    other = planar(p_dot).subs(S.d, -S.d)
    other_fails = not symbolic_equal(other, rhs)
    betas = np.random.default_rng(SEED).uniform(-np.pi, np.pi, n)
    pts = OffsetWheel((0.4, -0.2), r=0.1, d=0.07).points(betas)
    require(np.abs(pts["H"] - (pts["P"] - 0.07 * pts["j"])).max() < TOL, "the package puts H_i at P_i - d j_i")
    require(other_fails, "the other side of the offset gives another sign")
    return Derivation(
        findings=[
            equation(
                9,
                holds,
                r"$\dot{\mathbf h}_i + \dot\phi_i\mathbf k\times d\,\mathbf j_i$ with (6) equals the printed form "
                r"(SymPy); the centre on the other side of the steering axis gives another sign; "
                r"`OffsetWheel.points` puts the centre at $P_i - d\,\mathbf j_i$",
                res,
                convention=r"wheel centre $H_i = P_i - d\,\mathbf j_i$; $\dot\phi_i$ the absolute steering rate",
                note="the side of the offset is not stated in the text (Fig. 4 is missing); this is the side that gives the "
                "printed sign",
            )
        ]
    )


def wheel_frame(R):
    r"""(11): the columns of :math:`\mathbf R_{bwi}` are the wheel axes in body components.

    Parameters
    ----------
    R : sympy.Matrix (2, 2)
        The derived axes :math:`[\mathbf i_i\ \mathbf j_i]` in the body frame, in ``S.beta_i`` (and ``S.psi``).

    Returns
    -------
    Derivation
        finding (11).
    """
    P = printed(11)
    M = P.expr.rhs
    holds = (
        symbolic_equal(R, M)
        and symbolic_equal(rotation(S.beta_i, SYMBOLIC), M)
        and symbolic_equal(M.T * M, sp.eye(2))
        and symbolic_equal(M.det(), 1)
    )
    return Derivation(
        findings=[
            equation(
                11,
                holds,
                r"the wheel axes at $\phi_i = \psi + \beta_i$ rotated back by $\psi$ are the printed columns "
                r"(SymPy); orthogonal with determinant 1, equal to `wmr.rotation`",
                max_residual(R, M),
                convention=r"$\beta_i$ counter-clockwise from $\mathbf i$ to $\mathbf i_i$",
            )
        ]
    )


def offset_in_body(p_B, in_wheel):
    r"""(10): (9) in body components, against the printed form and ``OffsetWheel.block``.

    Parameters
    ----------
    p_B : sympy.Matrix (2, 1)
        The derived (9) in body components, in ``S.beta_i``.
    in_wheel : sympy.Matrix (2, 1)
        Its components along :math:`\mathbf i_i, \mathbf j_i`.

    Returns
    -------
    Derivation
        finding (10).
    """
    P = printed(10)
    unit = OffsetWheel(S.d_i, r=S.r, d=S.d)
    require(unit.rate_names(1) == ("phi_dot_1", "theta_dot_1"), "the offset unit's rates are (phi_dot, theta_dot)")
    p_wmr = unit.block(S.beta_i) * sp.Matrix([S.phi_dot_i, S.theta_dot_i])
    holds = (
        symbolic_equal(p_B, P.expr.rhs)
        and symbolic_equal(p_wmr, P.expr.rhs)
        and symbolic_equal(in_wheel, sp.Matrix([-S.d * S.phi_dot_i, -S.r * S.theta_dot_i]))
    )
    res = max(max_residual(p_B, P.expr.rhs), max_residual(p_wmr, P.expr.rhs))
    return Derivation(
        findings=[
            equation(
                10,
                holds,
                r"(9) rotated into the body frame equals "
                r"$\mathbf R_{bwi}[-d\dot\phi_i\ \ -r\dot\theta_i]^{\mathrm T}$ and `OffsetWheel.block` times the "
                r"rates (SymPy)",
                res,
                convention=r"$H_i = P_i - d\,\mathbf j_i$; $[\dot{\mathbf p}_i]$ in wheel-frame components",
            )
        ]
    )


def centred_wheel(p_B):
    r"""(12): the offset wheel with :math:`d = 0`, against the printed form and ``CentredWheel.block``.

    Parameters
    ----------
    p_B : sympy.Matrix (2, 1)
        The derived (10) at :math:`d = 0`.

    Returns
    -------
    Derivation
        finding (12).
    """
    P = printed(12)
    p_wmr = CentredWheel(S.d_i, r=S.r).block(S.beta_i) * sp.Matrix([S.theta_dot_i])
    holds = symbolic_equal(p_B, P.expr.rhs) and symbolic_equal(p_wmr, P.expr.rhs)
    res = max(max_residual(p_B, P.expr.rhs), max_residual(p_wmr, P.expr.rhs))
    return Derivation(
        findings=[
            equation(
                12,
                holds,
                r"the derived (10) at $d = 0$ and `CentredWheel.block` equal the printed form (SymPy)",
                res,
                convention="(10) with $d = 0$",
            )
        ]
    )
