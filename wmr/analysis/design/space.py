r"""The search over designs of three offset wheels, and two slices of the design space (data of a figure).

See :mod:`wmr.analysis.design` for the measure and the parametrisation.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...model import validation
from ...model.types import ArrayLike
from ..sweep import Grid
from .worst_case import COARSE_STEPS, WheelDesign, compass_search, equilateral_design, worst_kappa, worst_kappa_designs

__all__ = ["DesignSearch", "search", "Landscape", "landscape"]

_P1 = (-1.0, 0.0)  # wheel 1 of every searched design (fixes rotation and scale)


def _design(p, ratio):
    """The design of parameter vector p: (x2, y2, x3, y3[, log2 d/r]); ``ratio`` fixes d/r when given."""
    mounts = np.array([_P1, p[0:2], p[2:4]], dtype=float)
    return WheelDesign(mounts, float(2.0 ** p[4]) if ratio is None else ratio, 1.0)


# ------------------------------------------------------------------------------------------ the search
@dataclass(frozen=True)
class DesignSearch:
    r"""The result of :func:`search`.

    Attributes
    ----------
    best : WheelDesign
        The best design found (wheel 1 at (-1, 0), r = 1).
    best_kappa : float
        Its :math:`\bar\kappa` (:func:`worst_kappa`, fine grid and refinement).
    paper : WheelDesign
        The paper's answer: equilateral, C at the centroid, :math:`d = r`.
    paper_kappa : float
        Its :math:`\bar\kappa`.
    reference : WheelDesign
        The equilateral placement at the best design's offset ratio.
    reference_kappa : float
        Its :math:`\bar\kappa`.
    ratio_fixed : bool
        True when the offset ratio was given, not searched.
    evaluated : int
        Designs evaluated (screening and refinement).
    rtol : float
        The relative tolerance of :attr:`paper_optimal`.
    """

    best: WheelDesign
    best_kappa: float
    paper: WheelDesign
    paper_kappa: float
    reference: WheelDesign
    reference_kappa: float
    ratio_fixed: bool
    evaluated: int
    rtol: float

    @property
    def paper_optimal(self) -> bool:
        """The paper's design is as good as the best found, within ``rtol``."""
        return bool(self.paper_kappa <= self.best_kappa * (1.0 + self.rtol))

    @property
    def reference_optimal(self) -> bool:
        """The equilateral placement is as good as the best found at the same offset, within ``rtol``."""
        return bool(self.reference_kappa <= self.best_kappa * (1.0 + self.rtol))


def search(
    ratio: float | None = None, n: int = 600, starts: int = 3, seed: int = 0, rtol: float = 0.001
) -> DesignSearch:
    r"""Search three-offset-wheel designs for the smallest worst-case :math:`\kappa(\mathbf J)`.

    1. ``n`` designs :math:`\mathbf p = (x_2, y_2, x_3, y_3, \log_2 d/r)` drawn uniformly from
       :math:`[-2, 2]^4\times[-2, 2]` (``numpy.random.default_rng(seed)``; wheel 1 at (-1, 0), r = 1),
       screened by :func:`worst_kappa_designs` on ``Grid(COARSE_STEPS, 0, pi)``;
    2. the best ``starts`` designs refined by a compass search (same grid) down to a step of 1e-4;
    3. the winner, the paper's design and the equilateral placement at the winner's ratio evaluated
       by :func:`worst_kappa` (``Grid(FINE_STEPS, 0, pi)`` and a local climb).

    Parameters
    ----------
    ratio : float, optional
        Fix the offset ratio :math:`d/r` (> 0) and search the placement only; default: search it too.
    n : int, optional
        Designs screened, >= starts.
    starts : int, optional
        Designs refined, >= 1.
    seed : int, optional
        Seed of the screening sample.
    rtol : float, optional
        Relative tolerance of :attr:`DesignSearch.paper_optimal`.

    Returns
    -------
    DesignSearch

    Examples
    --------
    >>> res = search(n=60, starts=1)
    >>> res.paper_kappa < 1 + 1e-9, res.best_kappa < 1.01
    (True, True)
    """
    if ratio is not None:
        ratio = float(validation.number("ratio", validation.positive("ratio", ratio)))
    starts = validation.integer("starts", starts, minimum=1)
    n = validation.integer("n", n, minimum=starts)
    seed = validation.integer("seed", seed, minimum=0)
    rtol = float(validation.number("rtol", validation.positive("rtol", rtol)))
    dim = 4 if ratio is not None else 5
    beta = Grid(COARSE_STEPS, 0.0, np.pi).configurations(3, 0, COARSE_STEPS**3)
    count = [0]

    def f(P):
        count[0] += len(P)
        return worst_kappa_designs([_design(p, ratio) for p in P], beta)

    P = np.random.default_rng(seed).uniform(-2.0, 2.0, (n, dim))
    order = np.argsort(f(P), kind="stable")[:starts]
    refined = [compass_search(f, P[k], 0.25, -2.0, 2.0, 1e-4) for k in order]
    p_best = min(refined, key=lambda xf: xf[1])[0]
    best = _design(p_best, ratio)
    paper, reference = equilateral_design(1.0), equilateral_design(best.ratio)
    return DesignSearch(
        best=best,
        best_kappa=worst_kappa(best.robot()).kappa,
        paper=paper,
        paper_kappa=worst_kappa(paper.robot()).kappa,
        reference=reference,
        reference_kappa=worst_kappa(reference.robot()).kappa,
        ratio_fixed=ratio is not None,
        evaluated=count[0],
        rtol=rtol,
    )


# ------------------------------------------------------------------------------------ the design space
@dataclass(frozen=True)
class Landscape:
    r"""Worst-case :math:`\kappa(\mathbf J)` over two slices of the design space (data of a figure).

    Attributes
    ----------
    ratios : numpy.ndarray (n,)
        Offset ratios :math:`d/r`.
    kappa_paper : numpy.ndarray (n,)
        :math:`\bar\kappa` of the equilateral placement at each ratio.
    kappa_moved : numpy.ndarray (n,)
        :math:`\bar\kappa` of the placement with wheel 2 moved to ``moved``.
    moved : numpy.ndarray (2,)
        That position of wheel 2.
    x : numpy.ndarray (m,)
        Abscissae of wheel 2 (wheels 1 and 3 at the paper's points, :math:`d = r`).
    y : numpy.ndarray (m,)
        Ordinates of wheel 2.
    kappa_map : numpy.ndarray (m, m)
        :math:`\bar\kappa` with wheel 2 at ``(x[j], y[i])`` (row i, column j).
    mounts : numpy.ndarray (3, 2)
        The paper's mount points.
    """

    ratios: np.ndarray
    kappa_paper: np.ndarray
    kappa_moved: np.ndarray
    moved: np.ndarray
    x: np.ndarray
    y: np.ndarray
    kappa_map: np.ndarray
    mounts: np.ndarray


def landscape(n: int = 41, m: int = 41, moved: ArrayLike = (0.2, 1.2)) -> Landscape:
    r"""The data of the design-space figure: :math:`\bar\kappa` against :math:`d/r`, and over wheel 2's position.

    Both slices pass through the paper's design (equilateral, :math:`|\mathbf d_i| = r = 1`); the
    worst case is taken over ``Grid(COARSE_STEPS, 0, pi)`` (:func:`worst_kappa_designs`).

    Parameters
    ----------
    n : int, optional
        Ratios, log-spaced over :math:`[1/4, 4]` (odd n includes 1).
    m : int, optional
        Positions of wheel 2 per axis, over :math:`[-1.4, 2]\times[-1.2, 2.2]`.
    moved : pair, optional
        Wheel 2's position in the second curve.

    Returns
    -------
    Landscape
    """
    n, m = validation.integer("n", n, minimum=2), validation.integer("m", m, minimum=2)
    moved = np.array(validation.point("moved", moved), dtype=float)
    beta = Grid(COARSE_STEPS, 0.0, np.pi).configurations(3, 0, COARSE_STEPS**3)
    paper = equilateral_design(1.0)
    ratios = np.logspace(-2, 2, n, base=2.0)
    shifted = paper.mounts.copy()
    shifted[1] = moved
    kp = worst_kappa_designs([WheelDesign(paper.mounts, q) for q in ratios], beta)
    km = worst_kappa_designs([WheelDesign(shifted, q) for q in ratios], beta)
    x, y = np.linspace(-1.4, 2.0, m), np.linspace(-1.2, 2.2, m)
    X, Y = np.meshgrid(x, y)
    designs = [
        WheelDesign(np.array([paper.mounts[0], (a, b), paper.mounts[2]]), 1.0) for a, b in zip(X.ravel(), Y.ravel())
    ]
    K = worst_kappa_designs(designs, beta).reshape(m, m)
    return Landscape(
        ratios=ratios, kappa_paper=kp, kappa_moved=km, moved=moved, x=x, y=y, kappa_map=K, mounts=paper.mounts
    )
