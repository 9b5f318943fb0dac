r"""Chapter 3 exercises (kinetostatic isotropy): checks that say whether an answer is right and why not.

See :mod:`edition.exercises` for how the checks are used.
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.linalg import condition_number
from wmr.model.robot import Robot
from wmr.model.robots import paper_robot
from wmr.model.wheels import OffsetWheel

from .. import symbols as S
from ..verify import symbolic_equal
from .feedback import Feedback, as_matrix, missing

__all__ = ["isotropic_placement", "printed_42_signs", "offset_for_kappa"]


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
    fb = missing(None if points is None or L is None else 0, "the three mount points and $L$")
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
                               r"$\tfrac1L\mathbf E\sum_i\mathbf d_i \neq \mathbf 0$: "
                               rf"$\sum_i\mathbf d_i = ({s[0]:.3g}, {s[1]:.3g})$. Put C at the centroid of the three "
                               r"mount points (37).")
    L_iso = float(np.sqrt(np.mean(np.sum(pts**2, axis=1))))
    if abs(k - 1) > 1e-9:
        return Feedback(False, rf"The centroid is right, but $\kappa(\mathbf J_{{L1}}) = {k:.4g}$: (36) asks for "
                               r"$L^2 = \tfrac13\sum_i\|\mathbf d_i\|^2$, the mean squared distance.")
    return Feedback(True, rf"$\kappa(\mathbf J_{{L1}}) = 1$ with $L = {L_iso:.4g}$, although the triangle is not "
                          rf"equilateral (distances ${', '.join(f'{v:.3g}' for v in np.linalg.norm(pts, axis=1))}$): "
                          r"(38) is sufficient, not necessary.")


def printed_42_signs(answer):
    r"""Exercise 3.2: the square :math:`\tilde{\mathbf p}^2` of the model's :math:`\tilde{\mathbf p}` -- and why the
    printed (42) cannot be it.

    Parameters
    ----------
    answer : sympy.Matrix (2, 2) or None
        :math:`\tilde{\mathbf p}^2` in the symbols ``S.d``, ``S.r``.

    Returns
    -------
    Feedback
    """
    from ..transcription import printed
    M, fb = as_matrix(answer, (2, 2), r"the $2\times2$ matrix $\tilde{\mathbf p}^2$")
    if fb is not None:
        return fb
    ptilde = OffsetWheel((0, 0), r=S.r, d=S.d).block(sp.Integer(0))        # R(0) p~ = p~
    truth = ptilde * ptilde
    if symbolic_equal(M, truth):
        return Feedback(True, r"$\tilde{\mathbf p}^2 = \mathrm{diag}(d^2, r^2)$. With the printed "
                              r"$\mathrm{diag}(-d^2, -r^2)$, "
                              r"$\Upsilon_i = \mathbf R\tilde{\mathbf p}^2\mathbf R^{\mathrm T}$ would be negative "
                              r"definite, impossible for a block of $\mathbf J_2\mathbf J_2^{\mathrm T}$, whose "
                              r"quadratic form is $\|\mathbf J_2^{\mathrm T}\mathbf x\|^2 \geq 0$.")
    if symbolic_equal(M, printed(42).expr.rhs):
        return Feedback(False, r"That is the printed (42). Square $\tilde{\mathbf p} = \mathrm{diag}(-d, -r)$ yourself "
                               r"(`OffsetWheel((0, 0), r=S.r, d=S.d).block(0)` is $\tilde{\mathbf p}$).")
    return Feedback(False, rf"Not $\tilde{{\mathbf p}}\tilde{{\mathbf p}}$: the model's $\tilde{{\mathbf p}}$ is "
                           rf"${sp.latex(ptilde)}$.")


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
    fb = missing(offsets, "a list of offsets $d$")
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
