r"""The worst-case :math:`\kappa(\mathbf J)` of one robot, layouts of offset wheels, and the batched screening kernel.

See :mod:`wmr.analysis.design` for the measure and its notation.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from ...errors import InputTypeError, InputValueError
from ...model import validation
from ...model.robot import Robot
from ...model.types import ArrayLike, FloatArray
from ...model.wheels import OffsetWheel
from ..isotropy import characteristic_length
from ..linalg import condition_number
from ..sweep import Grid, sweep
from ..sweep.execute import Angles

__all__ = [
    "WorstCase",
    "worst_kappa",
    "WheelDesign",
    "equilateral_design",
    "worst_kappa_designs",
    "COARSE_STEPS",
    "FINE_STEPS",
]

#: configurations of the screening grid (per angle, over [0, pi)) and of the final evaluation
COARSE_STEPS, FINE_STEPS = 6, 24


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


def compass_search(
    f: Callable[[FloatArray], FloatArray],
    x0: ArrayLike,
    step: ArrayLike,
    lo: ArrayLike,
    hi: ArrayLike,
    tol: float,
    max_iter: int = 400,
) -> tuple[FloatArray, float]:
    """Minimise ``f`` from ``x0`` by compass search: ``(x, f(x))``.

    The 2n axis moves of the current step (points clipped to ``[lo, hi]``) are evaluated at once by the
    batched ``f`` ((k, n) -> (k,)); the best improving move is taken, else the step is halved, until
    every step is at most ``tol``.
    """
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


def worst_kappa(robot: Robot, angles: Angles | None = None, L: float | None = None, refine: bool = True) -> WorstCase:
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
    robot = validation.numeric_robot(robot)
    L = characteristic_length(robot) if L is None else validation.number("L", validation.positive("L", L))
    if angles is None:
        angles = Grid(FINE_STEPS if robot.w <= 3 else 2 * COARSE_STEPS, 0.0, np.pi)
    res = sweep(robot, "kappa_J", angles, L=L, quantiles=(1.0,))
    beta, kappa = np.array(res.worst_angles, dtype=float), float(res.worst)
    if validation.flag("refine", refine) and np.isfinite(kappa):

        def f(b):
            k = condition_number(robot.J(b, L=L))
            return -np.where(np.isfinite(k), k, 1.0 / np.finfo(float).eps)

        beta, neg = compass_search(f, beta, np.pi / 24, -np.inf, np.inf, 1e-7)
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
        m = validation.finite_array("mounts", self.mounts, last=2)
        if m.ndim != 2 or m.shape[0] < 1:
            raise InputValueError(f"mounts must have shape (w, 2) with w >= 1, got shape {m.shape}")
        object.__setattr__(self, "mounts", m)
        object.__setattr__(
            self, "d", float(validation.number("d (offset)", validation.nonnegative("d (offset)", self.d)))
        )
        object.__setattr__(self, "r", float(validation.number("r (radius)", validation.positive("r (radius)", self.r))))

    @property
    def ratio(self) -> float:
        """The offset ratio :math:`d/r`."""
        return self.d / self.r

    def robot(self, name: str = "design") -> Robot:
        """The design as a :class:`wmr.Robot` of :class:`wmr.OffsetWheel` units.

        Parameters
        ----------
        name : str, optional

        Returns
        -------
        Robot
        """
        return Robot([OffsetWheel(tuple(p), r=self.r, d=self.d) for p in self.mounts], name=name)

    def scaled(self, k: float) -> WheelDesign:
        """The same design with every length multiplied by ``k`` (same :math:`\\kappa`).

        Parameters
        ----------
        k : float
            > 0.

        Returns
        -------
        WheelDesign
        """
        k = float(validation.number("k", validation.positive("k", k)))
        return WheelDesign(self.mounts * k, self.d * k, self.r * k)

    def centroid_offset(self) -> float:
        """Distance from C to the centroid of the mount points, over their RMS distance from C.

        Returns
        -------
        float
        """
        rms = float(np.sqrt(np.mean(np.sum(self.mounts**2, axis=1))))
        return float(np.linalg.norm(self.mounts.mean(axis=0))) / rms

    def sides(self) -> FloatArray:
        """Lengths of the sides :math:`|P_iP_{i+1}|` of the mount polygon, array (w,).

        Returns
        -------
        numpy.ndarray (w,)
        """
        return np.linalg.norm(self.mounts - np.roll(self.mounts, -1, axis=0), axis=1)


def equilateral_design(ratio: float = 1.0) -> WheelDesign:
    r"""Three offset wheels at the vertices of an equilateral triangle centred at C.

    :math:`|\mathbf d_i| = r = 1` and :math:`d/r` = ``ratio``.

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
    from ...model.robots import equilateral_mounts

    return WheelDesign(
        np.array(equilateral_mounts(1.0)), validation.number("ratio", validation.nonnegative("ratio", ratio)), 1.0
    )


def worst_kappa_designs(designs: Sequence[WheelDesign], beta: ArrayLike) -> FloatArray:
    r"""The largest :math:`\kappa(\mathbf J)` of each design over the same configurations (batched).

    :math:`\kappa(\mathbf J)` is :math:`\sqrt{\kappa(\mathbf J\mathbf J^T)}` (56) at each design's
    characteristic length, all designs in one call.  A screening measure: :func:`worst_kappa` gives the
    value of record.

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
        raise InputTypeError(f"designs must be a non-empty sequence of WheelDesign, got {validation.show(designs)}")
    beta = validation.finite_array("beta", beta, last=designs[0].mounts.shape[0]).reshape(
        -1, designs[0].mounts.shape[0]
    )
    if beta.shape[0] == 0:
        raise InputValueError(f"beta must hold at least one configuration, got shape {np.shape(beta)}")
    out = np.empty(len(designs))
    step = max(1, (1 << 17) // beta.shape[0])  # designs per chunk: bounded memory
    for a in range(0, len(designs), step):
        Js = []
        for x in designs[a : a + step]:
            bot = x.robot()
            Js.append(bot.J(beta, L=characteristic_length(bot)))
        J = np.stack(Js)  # (chunk, K, 3, n_rates)
        G = J @ np.swapaxes(J, -1, -2)  # J J^T (chunk, K, 3, 3)
        out[a : a + step] = np.sqrt(condition_number(G)).max(axis=1)
    return out
