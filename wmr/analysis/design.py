r"""Design by conditioning: the worst-case :math:`\kappa(\mathbf J)` of a wheel layout and a search over layouts.

The measure (Section 4.3 of the paper, (30)-(33) and (56))
---------------------------------------------------------
The kinematic model (21) is :math:`\mathbf J_{L1}\mathbf t_L = \mathbf J_2\dot{\boldsymbol\theta}` with the
homogeneous platform Jacobian :math:`\mathbf J_{L1}` (32) (rows :math:`[\tfrac1L\mathbf E\mathbf d_i\ \ \mathbf 1]`)
and the homogeneous twist :math:`\mathbf t_L = [L\dot\psi\ \dot{\mathbf c}^T]^T` (33).  The map of the
forward kinematics is :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` (56) (:meth:`wmr.Robot.J`), and a
design is judged by its condition number :math:`\kappa(\mathbf J) = \sigma_l/\sigma_s` (30) in the
**worst** steering configuration,

.. math:: \bar\kappa = \sup_{\boldsymbol\beta}\ \kappa\big(\mathbf J(\boldsymbol\beta, L)\big),

with the characteristic length :math:`L` the root-mean-square distance of the mount points from C
(:func:`wmr.characteristic_length`: the :math:`L` of (36) that makes :math:`\mathbf J_{L1}` isotropic when
C is the centroid).  :math:`\kappa(\mathbf J)` has period :math:`\pi` in every :math:`\beta_i`:
:math:`\mathbf R(\beta_i + \pi) = -\mathbf R(\beta_i)` only changes the sign of unit i's columns, so the
configurations are taken in :math:`[0, \pi)^w`.

Two facts frame the search.  :math:`\kappa\ge 1` (31).  And for offset wheels :math:`\mathbf J_2` is square
and invertible (:math:`d > 0`), so :math:`\sigma_s(\mathbf J)\ge\sigma_s(\mathbf J_{L1})\sigma_s(\mathbf J_2)`
and :math:`\kappa(\mathbf J)\le\kappa(\mathbf J_{L1})\,\kappa(\mathbf J_2)` with
:math:`\kappa(\mathbf J_2) = \max(d/r,\ r/d)` at every :math:`\boldsymbol\beta` (the blocks are
:math:`\mathbf R(\beta_i)\,\mathrm{diag}(-d, -r)`, (21)).

The design space of three offset wheels
---------------------------------------
:math:`\kappa(\mathbf J)` does not change when every length is scaled (:math:`\mathbf J_{L1}` depends on
:math:`\mathbf d_i/L`, :math:`\kappa(\mathbf J_2)` on :math:`d/r`) nor when the body frame is rotated.  So
wheel 1 is put at :math:`\mathbf d_1 = (-1, 0)` (the paper's wheel 1) and the radius at :math:`r = 1`; a
design is the vector :math:`\mathbf p = (x_2, y_2, x_3, y_3, \log_2(d/r))`.  :func:`search` screens a
seeded random sample of designs on a coarse grid of configurations, refines the best few by a
compass (pattern) search, and evaluates the winner and the paper's answer -- the equilateral
triangle centred at C with :math:`d = r` ((37), (38), (46)) -- with :func:`worst_kappa` on a fine grid.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model import validation as V
from ..model.robot import Robot
from ..model.wheels import OffsetWheel
from .isotropy import characteristic_length
from .linalg import condition_number
from .sweep import Grid, sweep

__all__ = ["WorstCase", "worst_kappa", "WheelDesign", "equilateral_design", "worst_kappa_designs", "DesignSearch",
           "search", "Landscape", "landscape"]

#: configurations of the screening grid (per angle, over [0, pi)) and of the final evaluation
COARSE_STEPS, FINE_STEPS = 6, 24
_P1 = (-1.0, 0.0)                      # wheel 1 of every searched design (fixes rotation and scale)


# ------------------------------------------------------------------------------- worst case of one robot
@dataclass(frozen=True)
class WorstCase:
    r"""The worst steering configuration of a robot.

    Attributes
    ----------
    kappa : float
        :math:`\bar\kappa`, the largest :math:`\kappa(\mathbf J)` found (``inf``: singular somewhere).
    beta : numpy.ndarray (w,)
        A configuration where it is attained.
    grid_kappa : float
        The largest value on the grid alone (before the local refinement), <= ``kappa``.
    count : int
        Configurations evaluated on the grid.
    """

    kappa: float
    beta: np.ndarray
    grid_kappa: float
    count: int


def _compass(f, x0, step, lo, hi, tol, max_iter=400):
    """Minimise ``f`` (batched: (k, n) -> (k,)) from ``x0`` by compass search: the 2n axis moves of the
    current step are evaluated at once; the best improving move is taken, else the step is halved."""
    x = np.array(x0, dtype=float)
    fx = float(f(x[None])[0])
    n = x.size
    dirs = np.vstack([np.eye(n), -np.eye(n)])
    step = np.broadcast_to(np.asarray(step, dtype=float), (n,)).copy()
    for _ in range(max_iter):
        if step.max() <= tol:
            break
        cand = np.clip(x + dirs * step, lo, hi)
        fc = f(cand)
        k = int(np.argmin(fc))
        if fc[k] < fx:
            x, fx = cand[k], float(fc[k])
        else:
            step /= 2
    return x, fx


def worst_kappa(robot, angles=None, L=None, refine=True):
    r"""The worst-case condition number :math:`\bar\kappa = \sup_{\boldsymbol\beta}\kappa(\mathbf J)` of a robot.

    :func:`wmr.sweep` evaluates :math:`\kappa(\mathbf J(\boldsymbol\beta, L))` (30), (56) on a grid of
    :math:`[0, \pi)^w` (see the module notes for the period :math:`\pi`), then a compass search
    climbs from the grid's worst configuration, so that the value is not limited by the grid's
    spacing.

    Parameters
    ----------
    robot : Robot
        A numeric robot.
    angles : Grid, Sample or array_like (N, w), optional
        The configurations of the sweep (default ``Grid(FINE_STEPS, 0, pi)`` for ``w <= 3``, else
        ``Grid(COARSE_STEPS * 2, 0, pi)``).
    L : float, optional
        Characteristic length (default :func:`wmr.characteristic_length`).
    refine : bool, optional
        Climb from the grid's worst configuration (default True).

    Returns
    -------
    WorstCase

    Examples
    --------
    >>> import wmr
    >>> res = worst_kappa(wmr.paper_robot("offset", L=0.3, r=0.1, d=0.05))   # equilateral, d = r/2
    >>> round(res.kappa, 9)                                                   # = kappa(J2) = r/d
    2.0
    """
    robot = V.numeric_robot(robot)
    L = characteristic_length(robot) if L is None else V.number("L", V.positive("L", L))
    if angles is None:
        angles = Grid(FINE_STEPS if robot.w <= 3 else 2 * COARSE_STEPS, 0.0, np.pi)
    res = sweep(robot, "kappa_J", angles, L=L, quantiles=(1.0,))
    beta, kappa = np.array(res.worst_angles, dtype=float), float(res.worst)
    if V.flag("refine", refine) and np.isfinite(kappa):
        def f(b):
            k = condition_number(robot.J(b, L=L))
            return -np.where(np.isfinite(k), k, 1.0 / np.finfo(float).eps)
        beta, neg = _compass(f, beta, np.pi / 24, -np.inf, np.inf, 1e-7)
        kappa = max(kappa, -neg)
    return WorstCase(kappa=kappa, beta=np.mod(beta, np.pi), grid_kappa=float(res.worst), count=res.count)


# ------------------------------------------------------------------------------- designs of offset wheels
@dataclass(frozen=True)
class WheelDesign:
    r"""A layout of offset wheels: mount points, offset and radius (one length unit, any unit).

    Attributes
    ----------
    mounts : numpy.ndarray (w, 2)
        :math:`\mathbf d_i = \overrightarrow{CP_i}`, body frame.
    d : float
        Offset, >= 0.
    r : float
        Wheel radius, > 0.
    """

    mounts: np.ndarray
    d: float
    r: float = 1.0

    def __post_init__(self):
        m = V.finite_array("mounts", self.mounts, last=2)
        if m.ndim != 2 or m.shape[0] < 1:
            raise ValueError(f"mounts must have shape (w, 2) with w >= 1, got shape {m.shape}")
        object.__setattr__(self, "mounts", m)
        object.__setattr__(self, "d", float(V.number("d (offset)", V.nonnegative("d (offset)", self.d))))
        object.__setattr__(self, "r", float(V.number("r (radius)", V.positive("r (radius)", self.r))))

    @property
    def ratio(self):
        """The offset ratio :math:`d/r`."""
        return self.d / self.r

    def robot(self, name="design"):
        """The design as a :class:`wmr.Robot` of :class:`wmr.OffsetWheel` units.

        Parameters
        ----------
        name : str, optional

        Returns
        -------
        Robot
        """
        return Robot([OffsetWheel(tuple(p), r=self.r, d=self.d) for p in self.mounts], name=name)

    def scaled(self, k):
        """The same design with every length multiplied by ``k`` (same :math:`\\kappa`).

        Parameters
        ----------
        k : float
            > 0.

        Returns
        -------
        WheelDesign
        """
        k = float(V.number("k", V.positive("k", k)))
        return WheelDesign(self.mounts * k, self.d * k, self.r * k)

    def centroid_offset(self):
        """Distance from C to the centroid of the mount points, over their RMS distance from C.

        Returns
        -------
        float
        """
        rms = float(np.sqrt(np.mean(np.sum(self.mounts ** 2, axis=1))))
        return float(np.linalg.norm(self.mounts.mean(axis=0))) / rms

    def sides(self):
        """Lengths of the sides :math:`|P_iP_{i+1}|` of the mount polygon, array (w,).

        Returns
        -------
        numpy.ndarray (w,)
        """
        return np.linalg.norm(self.mounts - np.roll(self.mounts, -1, axis=0), axis=1)


def equilateral_design(ratio=1.0):
    r"""Three offset wheels at the vertices of an equilateral triangle centred at C, :math:`|\mathbf d_i| = r = 1`, :math:`d/r` = ``ratio``.

    With ``ratio = 1`` this is the answer of the paper ((37), (38) and (46)), in its numbering
    (:func:`wmr.equilateral_mounts`).

    Parameters
    ----------
    ratio : float, optional
        The offset ratio :math:`d/r`, >= 0.

    Returns
    -------
    WheelDesign
    """
    from ..model.robots import equilateral_mounts
    return WheelDesign(np.array(equilateral_mounts(1.0)), V.number("ratio", V.nonnegative("ratio", ratio)), 1.0)


def _design(p, ratio):
    """The design of parameter vector p: (x2, y2, x3, y3[, log2 d/r]); ``ratio`` fixes d/r when given."""
    mounts = np.array([_P1, p[0:2], p[2:4]], dtype=float)
    return WheelDesign(mounts, float(2.0 ** p[4]) if ratio is None else ratio, 1.0)


def worst_kappa_designs(designs, beta):
    r"""The largest :math:`\kappa(\mathbf J)` of each design over the same configurations (batched).

    For each design, :math:`\mathbf J(\boldsymbol\beta, L)` (56) of all configurations comes from
    :meth:`wmr.Robot.J` with the design's characteristic length; :math:`\kappa(\mathbf J)` is
    :math:`\sqrt{\kappa(\mathbf J\mathbf J^T)}`, the :math:`3\times3` Gram matrix's closed-form condition
    number (:func:`wmr.condition_number`), all designs in one call.  A screening measure:
    :func:`worst_kappa` gives the value of record.

    Parameters
    ----------
    designs : sequence of WheelDesign
    beta : array_like (K, w)
        Steering angles.

    Returns
    -------
    numpy.ndarray (len(designs),)
        The largest :math:`\kappa(\mathbf J)` over the K configurations (``inf`` if singular).
    """
    designs = list(designs)
    if not designs or not all(isinstance(x, WheelDesign) for x in designs):
        raise TypeError(f"designs must be a non-empty sequence of WheelDesign, got {V.show(designs)}")
    beta = V.finite_array("beta", beta, last=designs[0].mounts.shape[0]).reshape(-1, designs[0].mounts.shape[0])
    if beta.shape[0] == 0:
        raise ValueError(f"beta must hold at least one configuration, got shape {np.shape(beta)}")
    out = np.empty(len(designs))
    step = max(1, (1 << 17) // beta.shape[0])                      # designs per chunk: bounded memory
    for a in range(0, len(designs), step):
        Js = []
        for x in designs[a:a + step]:
            bot = x.robot()
            Js.append(bot.J(beta, L=characteristic_length(bot)))
        J = np.stack(Js)                                           # (chunk, K, 3, n_rates)
        G = J @ np.swapaxes(J, -1, -2)                             # J J^T (chunk, K, 3, 3)
        out[a:a + step] = np.sqrt(condition_number(G)).max(axis=1)
    return out


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
    def paper_optimal(self):
        """The paper's design is as good as the best found, within ``rtol``."""
        return bool(self.paper_kappa <= self.best_kappa * (1.0 + self.rtol))

    @property
    def reference_optimal(self):
        """The equilateral placement is as good as the best found at the same offset, within ``rtol``."""
        return bool(self.reference_kappa <= self.best_kappa * (1.0 + self.rtol))


def search(ratio=None, n=600, starts=3, seed=0, rtol=1e-3):
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
        ratio = float(V.number("ratio", V.positive("ratio", ratio)))
    starts = V.integer("starts", starts, minimum=1)
    n = V.integer("n", n, minimum=starts)
    seed = V.integer("seed", seed, minimum=0)
    rtol = float(V.number("rtol", V.positive("rtol", rtol)))
    dim = 4 if ratio is not None else 5
    beta = Grid(COARSE_STEPS, 0.0, np.pi).configurations(3, 0, COARSE_STEPS ** 3)
    count = [0]

    def f(P):
        count[0] += len(P)
        return worst_kappa_designs([_design(p, ratio) for p in P], beta)

    P = np.random.default_rng(seed).uniform(-2.0, 2.0, (n, dim))
    order = np.argsort(f(P), kind="stable")[:starts]
    refined = [_compass(f, P[k], 0.25, -2.0, 2.0, 1e-4) for k in order]
    p_best = min(refined, key=lambda xf: xf[1])[0]
    best = _design(p_best, ratio)
    paper, reference = equilateral_design(1.0), equilateral_design(best.ratio)
    return DesignSearch(best=best, best_kappa=worst_kappa(best.robot()).kappa,
                        paper=paper, paper_kappa=worst_kappa(paper.robot()).kappa,
                        reference=reference, reference_kappa=worst_kappa(reference.robot()).kappa,
                        ratio_fixed=ratio is not None, evaluated=count[0], rtol=rtol)


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


def landscape(n=41, m=41, moved=(0.2, 1.2)):
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
    n, m = V.integer("n", n, minimum=2), V.integer("m", m, minimum=2)
    moved = np.array(V.point("moved", moved), dtype=float)
    beta = Grid(COARSE_STEPS, 0.0, np.pi).configurations(3, 0, COARSE_STEPS ** 3)
    paper = equilateral_design(1.0)
    ratios = np.logspace(-2, 2, n, base=2.0)
    shifted = paper.mounts.copy()
    shifted[1] = moved
    kp = worst_kappa_designs([WheelDesign(paper.mounts, q) for q in ratios], beta)
    km = worst_kappa_designs([WheelDesign(shifted, q) for q in ratios], beta)
    x, y = np.linspace(-1.4, 2.0, m), np.linspace(-1.2, 2.2, m)
    X, Y = np.meshgrid(x, y)
    designs = [WheelDesign(np.array([paper.mounts[0], (a, b), paper.mounts[2]]), 1.0) for a, b in zip(X.ravel(), Y.ravel())]
    K = worst_kappa_designs(designs, beta).reshape(m, m)
    return Landscape(ratios=ratios, kappa_paper=kp, kappa_moved=km, moved=moved, x=x, y=y, kappa_map=K,
                     mounts=paper.mounts)
