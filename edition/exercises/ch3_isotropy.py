r"""Chapter 3's exercises (kinetostatic isotropy), on the fair-check framework (:mod:`.framework`).

======  ============================  =====================================================================
number  check                         the exercise
======  ============================  =====================================================================
3.1     :func:`isotropic_placement`   move wheel 2; where must wheel 3 go, and which L makes J_L1 isotropic
3.2     :func:`dual_upsilon`          :math:`\Upsilon_i` of a dual-wheel unit: can its J2 be isotropic?
3.3     :func:`offset_for_kappa`      every offset d that gives :math:`\kappa(\mathbf J_2) = 2` at r = 0.1 m
======  ============================  =====================================================================

Expected values are computed with ``wmr`` (``Robot.J1``, ``DualWheel.block``, ``wmr.condition_number``).
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.linalg import condition_number
from wmr.model.robot import Robot
from wmr.model.robots import paper_robot
from wmr.model.wheels import DualWheel, OffsetWheel

from .. import symbols as S
from ..text import number
from . import answers
from .feedback import right, undecided, wrong
from .framework import exercise
from .symbolic import compare, equivalent
from .tolerance import sig_figs

__all__ = [
    "isotropic_placement",
    "dual_upsilon",
    "offset_for_kappa",
    "FIXED_3_1",
    "TOL_3_1",
    "TOL_3_3",
    "SYMBOLS_3_2",
    "R_3_3",
]

#: 3.1: wheels 1 and 2 (metres)
FIXED_3_1 = ((-0.4, 0.0), (0.1, 0.5))
#: 3.1: coordinates and L to 4 significant figures (relative to the size of the robot)
TOL_3_1 = sig_figs(4)
#: 3.2: the symbols the answer may use
SYMBOLS_3_2 = (S.r, S.b, S.beta_i)
#: 3.3: the wheel radius (m) and the tolerance of the offsets
R_3_3 = 0.1
TOL_3_3 = sig_figs(3)
_WHAT_3_1 = "a pair `(points, L)`: the three mount points (an array of shape (3, 2), metres) and $L$ in metres"
_WHAT_3_2 = r"the $2\times2$ SymPy `Matrix` $\Upsilon_i$"


def _placement(answer):
    if not isinstance(answer, (tuple, list)) or len(answer) != 2:
        raise answers.AnswerError(f"Expected {_WHAT_3_1}; got {answers.describe(answer)}.")
    return (
        answers.array(answer[0], (3, 2), "the three mount points, an array of shape (3, 2) in metres"),
        answers.number(answer[1], "the characteristic length $L$ in metres"),
    )


@exercise("3.1", answer=_WHAT_3_1, tolerance=TOL_3_1)
def isotropic_placement(placement):
    r"""Exercise 3.1: keep wheel 1 at (-0.4, 0) and move wheel 2 to (0.1, 0.5); wheel 3 and the isotropic L.

    Parameters
    ----------
    placement : pair
        ``(points, L)``.

    Returns
    -------
    Result
    """
    pts, L = _placement(placement)
    fixed = np.array(FIXED_3_1)
    size = float(np.sqrt(np.mean(np.sum(fixed**2, axis=1))))  # the scale of the robot (m)
    if np.abs(pts[:2] - fixed).max() > TOL_3_1.rel * size:  # 4 significant figures of the robot's size
        return wrong(
            "Wheels 1 and 2 must stay at $(-0.4, 0)$ and $(0.1, 0.5)$, in that order; only wheel 3 and "
            "$L$ are yours to choose."
        )
    if L <= 0:
        return wrong("$L$ is a length: it must be positive.")
    rms = float(np.sqrt(np.mean(np.sum(pts**2, axis=1))))
    centroid = float(np.linalg.norm(pts.sum(axis=0)))
    if TOL_3_1.coarse(pts[2], -fixed.sum(axis=0)):
        return wrong(TOL_3_1.close("position of wheel 3"))
    if centroid > 3 * TOL_3_1.rel * size:
        return wrong(
            r"With this wheel 3, C is not the centroid of the mount points "
            r"($\sum_i\mathbf d_i \neq \mathbf 0$): the off-diagonal blocks of "
            r"$\mathbf J_{L1}^{\mathrm T}\mathbf J_{L1}$ (35) cannot vanish for any $L$."
        )
    if TOL_3_1.coarse(L, rms):
        return wrong(TOL_3_1.close("$L$"))
    if not TOL_3_1.accepts(L, rms):
        return wrong(
            r"Wheel 3 is right, but not $L$: (36) fixes $L^2$ as the mean squared distance of the mount "
            r"points from C."
        )
    kappa = float(condition_number(Robot([OffsetWheel(tuple(p), r=0.1, d=0.05) for p in pts]).J1(L)))
    sides = np.linalg.norm(pts - np.roll(pts, -1, axis=0), axis=1)
    shape = "equilateral" if np.ptp(sides) <= TOL_3_1.rel * sides.max() else "not equilateral"
    return right(
        f"Wheel 3 at $({number(pts[2, 0], 4)}, {number(pts[2, 1], 4)})$ puts C at the centroid, and "
        f"$L = {number(L, 4)}$ m (the root-mean-square distance) makes $\\mathbf J_{{L1}}$ isotropic "
        f"($\\kappa = {number(kappa, 4)}$). The triangle is {shape}: equal distances are not needed."
    )


@exercise("3.2", answer=_WHAT_3_2)
def dual_upsilon(answer):
    r"""Exercise 3.2: :math:`\Upsilon_i = \mathbf B\mathbf B^{\mathrm T}` of a dual-wheel unit's block
    :math:`\mathbf B` (``DualWheel.block``).

    Parameters
    ----------
    answer : sympy.Matrix (2, 2)
        In :data:`SYMBOLS_3_2` (or the student's own symbols of the same names).

    Returns
    -------
    Result
    """
    B = DualWheel((0, 0), r=S.r, b=S.b).block(S.beta_i)
    truth = (B * B.T).applyfunc(sp.trigsimp)
    M, same = compare(answer, truth, SYMBOLS_3_2, _WHAT_3_2)
    if same:
        return right(
            r"$\Upsilon_i = \tfrac{r^2}{2}\mathbf j_i\mathbf j_i^{\mathrm T}$ has rank 1 at every "
            r"$\beta_i$: it is never a multiple of $\mathbf 1$, so $\mathbf J_2$ of dual wheels is "
            r"singular ($\kappa = \infty$), whatever $r$ and $b$."
        )
    if same is None:
        return undecided(
            "This check cannot tell whether your matrix equals $\\Upsilon_i$ (it could not be "
            "simplified or evaluated); write it with `sp.sin`, `sp.cos` and the symbols `r`, `b`, "
            "`beta_i`."
        )
    if equivalent(M, (B.T * B).applyfunc(sp.trigsimp)):
        return wrong(
            r"That is $\mathbf B^{\mathrm T}\mathbf B$; (41) multiplies the other way round, "
            r"$\Upsilon_i = \mathbf B\mathbf B^{\mathrm T}$."
        )
    offset = OffsetWheel((0, 0), r=S.r, d=S.b).block(S.beta_i)
    if equivalent(M, offset * offset.T) or equivalent(M, sp.eye(2) * S.r**2):
        return wrong(
            r"That is the $\Upsilon_i$ of an offset wheel; a dual-wheel unit has its own block "
            r"$\mathbf B$ (both wheels roll, neither is steered)."
        )
    if not equivalent(M, M.T):
        return wrong(
            r"Your matrix is not symmetric, and $\mathbf B\mathbf B^{\mathrm T}$ always is: form (41) from "
            r"the dual-wheel unit's block $\mathbf B$ and its transpose."
        )
    return wrong(
        r"Not $\mathbf B\mathbf B^{\mathrm T}$ of a dual-wheel unit: build its block $\mathbf B$ from the "
        r"no-slip rows of its two wheels (Chapter 1: each rolls at $\pm b$ along the axle), then form (41)."
    )


@exercise("3.3", answer="a list of offsets $d$ in metres", tolerance=TOL_3_3)
def offset_for_kappa(offsets, n=200):
    r"""Exercise 3.3: every offset :math:`d` for which :math:`\kappa(\mathbf J_2) = 2` at every steering angle,
    with wheels of radius :data:`R_3_3`.

    Parameters
    ----------
    offsets : sequence of float
        Metres.
    n : int
        Random steering configurations at which each offset is tried.

    Returns
    -------
    Result
    """
    what = "a list of offsets $d$ in metres"
    listed = isinstance(offsets, (list, tuple)) or (isinstance(offsets, np.ndarray) and offsets.ndim > 0)
    d = answers.vector(offsets, len(offsets), what) if listed else np.array([answers.number(offsets, what)])
    if d.size == 0:
        return wrong("Give at least one offset.")
    if np.any(d <= 0):
        return wrong("An offset is a distance: every $d$ must be positive.")
    beta = np.random.default_rng(3).uniform(-np.pi, np.pi, (n, 3))

    def kappa(x):
        return float(np.max(condition_number(paper_robot("offset", L=0.4, r=R_3_3, d=float(x)).J2(beta))))

    kappas = [kappa(x) for x in d]
    good = [TOL_3_3.accepts(k, 2.0) for k in kappas]
    if not all(good):
        if all(TOL_3_3.accepts(kappa(x / 1000), 2.0) for x in d):
            return wrong("These would be right in millimetres; the question asks for metres.")
        i = good.index(False)
        return wrong(f"At $d = {number(d[i], 3)}$ m, $\\kappa(\\mathbf J_2) = {number(kappas[i], 3)}$, not 2.")
    if np.ptp(d) <= TOL_3_3.rel * d.max():
        return wrong(
            r"Right, but there is one more offset: $\kappa = \max(d, r)/\min(d, r)$ is 2 on both sides of "
            r"$d = r$."
        )
    return right(
        r"The singular values of $\mathbf J_2$ are $d$ and $r$ at every steering angle, so "
        r"$\kappa = \max(d, r)/\min(d, r) = 2$ at $d = r/2$ and at $d = 2r$."
    )
