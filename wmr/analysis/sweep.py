r"""Sweeps: one analysis evaluated over millions of configurations, in chunks, with bounded memory.

A design study asks questions such as "what is the largest :math:`\kappa(\mathbf J)` over all
steering angles?" or "where does :math:`\operatorname{rank}\mathbf F` drop?".  :func:`sweep` answers
them for a grid (:class:`Grid`) or a random sample (:class:`Sample`) of configurations
:math:`\boldsymbol\beta\in\mathbb R^w` without ever holding all of them: the configurations of one
chunk are generated, the analysis is evaluated on them with the batched kernels, and the chunk
is folded into a running reduction (count, minimum, maximum, the extreme configurations, the
distribution of values).  Peak memory is that of one chunk plus the reduction, whatever the
number of configurations.

The chunks are independent, so the same code runs on a Dask cluster when ``client`` is given
(``pip install wmr[dask]``); the reduction is associative and ties go to the lower
configuration index, so the result does not depend on the chunk size, on the order in which
chunks finish, or on where they ran.

Analyses (:data:`ANALYSES`):

=============  ====================================================================  =================
name           value at a configuration                                                "worst" end
=============  ====================================================================  =================
``rank_F``     :math:`\operatorname{rank}\mathbf F` (24)                              smallest
``mobility``   :math:`\nu = (3+n) - \operatorname{rank}\mathbf F` (27)                 largest
``det_J``      :math:`\det\mathbf J`, :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` (56), (58)   smallest magnitude
``kappa_J``    :math:`\kappa(\mathbf J)` (30), ``inf`` where singular                  largest
``kappa_JL1``  :math:`\kappa(\mathbf J_{L1})` (32): independent of :math:`\boldsymbol\beta`   largest
=============  ====================================================================  =================

The "worst" end is the one closest to a singularity: a rank drop of :math:`\mathbf F` (so a
mobility gain), a vanishing :math:`\det\mathbf J`, a diverging condition number.
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field

import numpy as np

from ..model import validation as V

__all__ = ["ANALYSES", "Grid", "Sample", "Sweep", "sweep", "QUANTILES", "SKETCH_ACCURACY"]

#: Quantiles reported by default.
QUANTILES = (0.0, 0.01, 0.05, 0.5, 0.95, 0.99, 1.0)
#: Relative accuracy of the quantiles of real-valued analyses (see :class:`Sweep`).
SKETCH_ACCURACY = 1e-4
#: Configurations per chunk (a multiple of the random-sample block).
CHUNK = 1 << 18
_BLOCK = 1 << 16                     # random samples are drawn in blocks of this size (see Sample)


# ------------------------------------------------------------------------------------ analyses
def _J_length(robot, L):
    from .isotropy import characteristic_length
    return characteristic_length(robot) if L is None else V.number("L", V.positive("L", L))


def _rank_F(robot, beta, L):
    from .mobility import rank_F
    return rank_F(robot, beta)


def _mobility(robot, beta, L):
    from .mobility import mobility
    return mobility(robot, beta)


def _det_J(robot, beta, L):
    from .linalg import det
    return det(robot.J(beta, L=L))


def _kappa_J(robot, beta, L):
    from .linalg import condition_number
    return condition_number(robot.J(beta, L=L))


def _kappa_JL1(robot, beta, L):
    from .linalg import condition_number
    return np.full(beta.shape[:-1], float(condition_number(robot.J1(L))))


@dataclass(frozen=True)
class _Analysis:
    title: str
    evaluate: object          # (robot, beta (k, w), L) -> (k,)
    integer: bool
    worst: str                # "min", "max" or "min_abs"
    uses_L: bool = False
    square: bool = False


#: The analyses :func:`sweep` knows, by name.
ANALYSES = {
    "rank_F": _Analysis("rank F", _rank_F, True, "min"),
    "mobility": _Analysis("mobility", _mobility, True, "max"),
    "det_J": _Analysis("det J", _det_J, False, "min_abs", uses_L=True, square=True),
    "kappa_J": _Analysis("kappa(J)", _kappa_J, False, "max", uses_L=True),
    "kappa_JL1": _Analysis("kappa(J_L1)", _kappa_JL1, False, "max", uses_L=True),
}


# ---------------------------------------------------------------------------- configurations
def _bounds(lo, hi):
    lo, hi = V.real("lo", lo), V.real("hi", hi)
    if not hi > lo:
        raise ValueError(f"hi must be greater than lo, got lo = {lo!r}, hi = {hi!r}")
    return float(lo), float(hi)


def _count(name, value, minimum=1):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        if isinstance(value, float) and value.is_integer():
            value = int(value)
        else:
            raise TypeError(f"{name} must be an integer, got {value!r}")
    if value < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {value!r}")
    return int(value)


@dataclass(frozen=True)
class Grid:
    r"""Every combination of regularly spaced steering angles.

    Angle :math:`\beta_i` takes the ``steps_i`` values :math:`lo + k\,(hi - lo)/steps_i`,
    :math:`k = 0, \dots, steps_i - 1` (``hi`` excluded: the angles are periodic), so a robot with
    ``w`` units has :math:`\prod_i steps_i` configurations, numbered with the last angle varying
    fastest.

    Parameters
    ----------
    steps : int or sequence of int
        Values per angle (one number for every angle, or one per unit), each >= 1.
    lo, hi : float, optional
        The range of every angle (default :math:`[-\pi, \pi)`).

    Examples
    --------
    >>> g = Grid(4)
    >>> g.size(2), g.configurations(2, 0, 3).round(4).tolist()
    (16, [[-3.1416, -3.1416], [-3.1416, -1.5708], [-3.1416, 0.0]])
    """

    steps: object = 72
    lo: float = -math.pi
    hi: float = math.pi

    def __post_init__(self):
        steps = self.steps
        if isinstance(steps, (list, tuple, np.ndarray)):
            steps = tuple(_count("steps", s) for s in steps)
            if not steps:
                raise ValueError("steps must not be empty")
        else:
            steps = _count("steps", steps)
        object.__setattr__(self, "steps", steps)
        lo, hi = _bounds(self.lo, self.hi)
        object.__setattr__(self, "lo", lo)
        object.__setattr__(self, "hi", hi)

    def shape(self, w):
        """Values per angle.

        Parameters
        ----------
        w : int
            Number of steering angles (wheel units).

        Returns
        -------
        tuple of w ints
        """
        if isinstance(self.steps, tuple):
            if len(self.steps) != w:
                raise ValueError(f"Grid.steps has {len(self.steps)} entries, the robot has w = {w} angles")
            return self.steps
        return (self.steps,) * w

    def size(self, w):
        """Number of configurations, :math:`\\prod_i steps_i`.

        Parameters
        ----------
        w : int
            Number of steering angles.

        Returns
        -------
        int
        """
        return math.prod(self.shape(w))

    def configurations(self, w, start, stop):
        """Configurations ``start .. stop-1`` of the grid's numbering.

        Parameters
        ----------
        w : int
            Number of steering angles.
        start, stop : int
            A range of configuration numbers, ``0 <= start < stop <= size(w)``.

        Returns
        -------
        numpy.ndarray (stop - start, w)
        """
        shape = self.shape(w)
        digits = np.unravel_index(np.arange(start, stop, dtype=np.int64), shape)
        out = np.empty((stop - start, w))
        for i, (n, k) in enumerate(zip(shape, digits)):
            out[:, i] = self.lo + k * ((self.hi - self.lo) / n)
        return out


@dataclass(frozen=True)
class Sample:
    r"""``n`` configurations drawn uniformly from :math:`[lo, hi)^w`, reproducibly.

    Configuration ``k`` is row ``k mod B`` of block ``k // B`` (``B`` = 65536), and block ``j`` is
    drawn by ``numpy.random.default_rng([seed, j])``: a configuration depends only on ``seed``
    and ``k``, never on the chunk size or on the worker that drew it.

    Parameters
    ----------
    n : int
        Number of configurations, >= 1.
    seed : int, optional
        Non-negative seed.
    lo, hi : float, optional
        The range of every angle (default :math:`[-\pi, \pi)`).

    Examples
    --------
    >>> s = Sample(10, seed=1)
    >>> s.size(3), s.configurations(3, 2, 4).shape
    (10, (2, 3))
    >>> bool(np.array_equal(s.configurations(3, 0, 10)[2:4], s.configurations(3, 2, 4)))
    True
    """

    n: int
    seed: int = 0
    lo: float = -math.pi
    hi: float = math.pi

    def __post_init__(self):
        object.__setattr__(self, "n", _count("n", self.n))
        object.__setattr__(self, "seed", _count("seed", self.seed, minimum=0))
        lo, hi = _bounds(self.lo, self.hi)
        object.__setattr__(self, "lo", lo)
        object.__setattr__(self, "hi", hi)

    def size(self, w):
        """Number of configurations (``n``, whatever ``w``).

        Parameters
        ----------
        w : int
            Number of steering angles.

        Returns
        -------
        int
        """
        return self.n

    def configurations(self, w, start, stop):
        """Configurations ``start .. stop-1`` of the sample.

        Parameters
        ----------
        w : int
            Number of steering angles.
        start, stop : int
            A range of configuration numbers, ``0 <= start < stop <= n``.

        Returns
        -------
        numpy.ndarray (stop - start, w)
        """
        first, last = start // _BLOCK, (stop - 1) // _BLOCK
        blocks = [np.random.default_rng([self.seed, j]).uniform(self.lo, self.hi, (_BLOCK, w))
                  for j in range(first, last + 1)]
        return np.concatenate(blocks)[start - first * _BLOCK: stop - first * _BLOCK]


@dataclass(frozen=True)
class _Explicit:
    beta: np.ndarray

    def size(self, w):
        return self.beta.shape[0]

    def configurations(self, w, start, stop):
        return self.beta[start:stop]


def _source(angles, w):
    if isinstance(angles, (Grid, Sample)):
        if angles.size(w) < 1:
            raise ValueError(f"angles has no configurations: {angles!r}")
        return angles
    if isinstance(angles, (str, bytes)) or angles is None:
        raise TypeError(f"angles must be a Grid, a Sample or an array (N, {w}) of steering angles, got {angles!r}")
    beta = V.finite_array("angles", angles, last=w)
    beta = beta.reshape(-1, w)
    if beta.shape[0] == 0:
        raise ValueError(f"angles must hold at least one configuration, got shape {np.shape(angles)}")
    return _Explicit(beta)


# ---------------------------------------------------------------------------------- reduction
@dataclass
class _Counts:
    """Counts of integer bins ``offset .. offset + len(counts) - 1`` (grows as needed; mergeable)."""

    offset: int = 0
    counts: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))

    def add(self, keys, counts=None):
        if keys.size == 0:
            return
        lo, hi = int(keys.min()), int(keys.max())
        part = np.bincount(keys - lo, weights=counts, minlength=hi - lo + 1).astype(np.int64)
        self._add_dense(lo, part)

    def _add_dense(self, lo, part):
        if part.size == 0:
            return
        if self.counts.size == 0:
            self.offset, self.counts = lo, part.copy()
            return
        new_lo = min(lo, self.offset)
        new_hi = max(lo + part.size, self.offset + self.counts.size)
        if new_lo != self.offset or new_hi != self.offset + self.counts.size:
            grown = np.zeros(new_hi - new_lo, dtype=np.int64)
            grown[self.offset - new_lo: self.offset - new_lo + self.counts.size] = self.counts
            self.offset, self.counts = new_lo, grown
        self.counts[lo - self.offset: lo - self.offset + part.size] += part

    def merge(self, other):
        self._add_dense(other.offset, other.counts)

    def items(self):
        nz = np.flatnonzero(self.counts)
        return [(int(self.offset + k), int(self.counts[k])) for k in nz]

    def locate(self, rank, descending=False):
        """The bin holding the member of 0-based ``rank`` in bin order: ``(bin, 0)``, or ``(None, rank - total)``."""
        counts = self.counts[::-1] if descending else self.counts
        cum = np.cumsum(counts)
        if cum.size == 0 or rank >= cum[-1]:
            return None, rank - (int(cum[-1]) if cum.size else 0)
        i = int(np.searchsorted(cum, rank, side="right"))
        return self.offset + (self.counts.size - 1 - i if descending else i), 0


_GAMMA = (1 + SKETCH_ACCURACY) / (1 - SKETCH_ACCURACY)
_LOG_GAMMA = math.log(_GAMMA)


def _bucket(x):
    """Bucket k of positive finite x: gamma^(k-1) < x <= gamma^k (a relative-accuracy sketch)."""
    return np.ceil(np.log(x) / _LOG_GAMMA).astype(np.int64)


def _bucket_value(k):
    """The value that represents bucket k: within SKETCH_ACCURACY of every member."""
    return 2.0 * math.exp(k * _LOG_GAMMA) / (_GAMMA + 1.0)


@dataclass
class _Partial:
    """The reduction of a set of configurations (associative: see :meth:`merge`)."""

    count: int = 0
    lo: float = math.nan           # minimum and its configuration index (nan: nothing yet)
    lo_at: int = -1
    hi: float = math.nan           # maximum
    hi_at: int = -1
    small: float = math.nan        # minimum magnitude
    small_at: int = -1
    integers: _Counts = field(default_factory=_Counts)     # integer analyses: value -> count
    positive: _Counts = field(default_factory=_Counts)     # real analyses: bucket -> count
    negative: _Counts = field(default_factory=_Counts)
    zeros: int = 0
    infinite: int = 0              # +inf (a condition number at a singular configuration)
    values: list = field(default_factory=list)             # (start, array) when kept

    def add(self, start, x, integer, keep):
        self.count += x.size
        i = int(np.argmin(x))
        self._lo(float(x[i]), start + i)
        i = int(np.argmax(x))
        self._hi(float(x[i]), start + i)
        ax = np.abs(x)
        i = int(np.argmin(ax))
        self._small(float(ax[i]), start + i)
        if integer:
            self.integers.add(x.astype(np.int64))
        else:
            inf = np.isinf(x)
            n_inf = int(np.count_nonzero(inf))
            self.infinite += n_inf
            fin = x[~inf] if n_inf else x
            pos, neg = fin[fin > 0], fin[fin < 0]
            self.zeros += fin.size - pos.size - neg.size
            self.positive.add(_bucket(pos))
            self.negative.add(_bucket(-neg))
        if keep:
            self.values.append((start, x.copy()))

    @staticmethod
    def _first(v, at, best, best_at, sign):
        """Keep the better of (v, at) and (best, best_at): sign * value smaller, ties to the lower index."""
        if best_at < 0 or sign * v < sign * best or (v == best and at < best_at):
            return v, at
        return best, best_at

    def _lo(self, v, at):
        self.lo, self.lo_at = self._first(v, at, self.lo, self.lo_at, 1)

    def _hi(self, v, at):
        self.hi, self.hi_at = self._first(v, at, self.hi, self.hi_at, -1)

    def _small(self, v, at):
        self.small, self.small_at = self._first(v, at, self.small, self.small_at, 1)

    def merge(self, other):
        self.count += other.count
        if other.count:
            self._lo(other.lo, other.lo_at)
            self._hi(other.hi, other.hi_at)
            self._small(other.small, other.small_at)
        self.integers.merge(other.integers)
        self.positive.merge(other.positive)
        self.negative.merge(other.negative)
        self.zeros += other.zeros
        self.infinite += other.infinite
        self.values.extend(other.values)
        return self

    def quantile(self, q, integer):
        """The order statistic of rank floor(q (count - 1)) (exact for integers, else from the sketch)."""
        return min(max(self._quantile(q, integer), self.lo), self.hi)

    def _quantile(self, q, integer):
        if q == 0.0:
            return self.lo
        if q == 1.0:
            return self.hi
        rank = math.floor(q * (self.count - 1))
        if integer:
            return float(self.integers.locate(rank)[0])
        k, rank = self.negative.locate(rank, descending=True)   # most negative first
        if k is not None:
            return -_bucket_value(k)
        if rank < self.zeros:
            return 0.0
        k, rank = self.positive.locate(rank - self.zeros)
        return math.inf if k is None else _bucket_value(k)


def _evaluate(robot, name, source, w, L, start, stop, keep, threads):
    """Evaluate analysis ``name`` on configurations ``start .. stop-1``: a :class:`_Partial`.

    Runs in this process or on a Dask worker; ``threads`` limits the kernels' threads.
    """
    from ._batch import limit_threads
    an = ANALYSES[name]
    beta = source.configurations(w, start, stop)
    with limit_threads(threads):
        x = np.asarray(an.evaluate(robot, beta, L))
    part = _Partial()
    part.add(start, x.astype(np.int64) if an.integer else x.astype(float), an.integer, keep)
    return part


# ------------------------------------------------------------------------------------- result
@dataclass(frozen=True)
class Sweep:
    r"""The result of :func:`sweep`.

    Attributes
    ----------
    analysis : str
        The analysis' name (a key of :data:`ANALYSES`).
    count : int
        Configurations evaluated.
    min : float
        Smallest value (exact).
    max : float
        Largest value (exact).
    argmin : numpy.ndarray (w,)
        The first configuration, in the sweep's numbering, where the minimum is attained.
    argmax : numpy.ndarray (w,)
        The first configuration where the maximum is attained.
    worst : float
        The value at the end closest to a singularity (see the module notes): the minimum of
        rank F, the maximum of the mobility and of condition numbers, the smallest
        :math:`|\det\mathbf J|`.
    worst_angles : numpy.ndarray (w,)
        The first configuration where ``worst`` is attained.
    worst_index : int
        Its number in the sweep.
    quantiles : dict of float -> float
        The order statistic of rank :math:`\lfloor q(\text{count}-1)\rfloor` for each requested
        ``q``: exact for the integer analyses (rank F, mobility) and for ``q`` = 0 or 1, within a
        relative error of :data:`SKETCH_ACCURACY` for the real-valued ones (a logarithmic
        bucket sketch that needs no sorted copy of the values).
    counts : dict of int -> int
        Integer analyses: how many configurations take each value; empty otherwise.
    infinite : int
        Configurations where the value is ``inf`` (a singular matrix's condition number).
    values : numpy.ndarray (count,) or None
        Every value, in the sweep's numbering, when ``keep=True``.
    """

    analysis: str
    count: int
    min: float
    max: float
    argmin: np.ndarray
    argmax: np.ndarray
    worst: float
    worst_angles: np.ndarray
    worst_index: int
    quantiles: dict
    counts: dict
    infinite: int
    values: np.ndarray | None = None

    def summary(self):
        """A few lines of text that state the result (used by ``wmr sweep``).

        Returns
        -------
        str
        """
        an = ANALYSES[self.analysis]
        deg = np.degrees(self.worst_angles)
        lines = [f"{an.title} over {self.count:,} configurations",
                 f"  min {self.min:.6g}   max {self.max:.6g}",
                 "  quantiles  " + "   ".join(f"{q:g}: {v:.6g}" for q, v in self.quantiles.items())]
        if self.counts:
            lines.append("  counts     " + "   ".join(f"{k}: {n:,}" for k, n in self.counts.items()))
        if self.infinite:
            lines.append(f"  singular (inf) at {self.infinite:,} configurations")
        lines.append(f"  worst {self.worst:.6g} at configuration {self.worst_index}: beta = ("
                     + ", ".join(f"{a:.4f}" for a in deg) + ") deg")
        return "\n".join(lines)


# -------------------------------------------------------------------------------------- sweep
def sweep(robot, analysis, angles, *, L=None, quantiles=QUANTILES, keep=False, chunk=CHUNK,
          progress=None, client=None):
    r"""Evaluate an analysis over a grid or sample of configurations, chunk by chunk.

    Each chunk of configurations :math:`\boldsymbol\beta_k\in\mathbb R^w` is evaluated with the
    batched kernels (:func:`wmr.rank_F`, :func:`wmr.mobility`, :meth:`wmr.Robot.J` with
    :func:`wmr.analysis.linalg.det` and :func:`wmr.condition_number`) and folded into the
    reduction; peak memory is that of one chunk (``chunk`` configurations) plus the reduction,
    about ``chunk * (w + 20) * 8`` bytes plus a few MB, independent of the number of
    configurations (unless ``keep``).

    Parameters
    ----------
    robot : Robot
        A numeric robot.
    analysis : str
        A key of :data:`ANALYSES`: ``"rank_F"``, ``"mobility"``, ``"det_J"`` (square
        :math:`\mathbf J` only, i.e. ``robot.n_rates == 3``), ``"kappa_J"`` or ``"kappa_JL1"``.
    angles : Grid, Sample or array_like (N, w)
        The configurations: a :class:`Grid`, a :class:`Sample`, or explicit steering angles.
    L : float, optional
        Characteristic length of :math:`\mathbf J_{L1}` for ``det_J``, ``kappa_J`` and
        ``kappa_JL1`` (default :func:`wmr.characteristic_length`).
    quantiles : sequence of float, optional
        Quantile levels in [0, 1].
    keep : bool, optional
        Also return every value (``Sweep.values``, ``8 N`` bytes).
    chunk : int, optional
        Configurations per chunk (rounded up to a multiple of 65536 for a :class:`Sample`).
    progress : callable, optional
        Called as ``progress(done, total)`` after each chunk.
    client : dask.distributed.Client, optional
        Evaluate the chunks on this Dask cluster (one kernel thread per task) instead of in
        this process; the result is the same.

    Returns
    -------
    Sweep

    Raises
    ------
    TypeError
        If ``robot`` is not a :class:`~wmr.Robot`, ``analysis`` not a string, ``angles`` not a
        grid, sample or array, or ``progress`` not callable.
    ValueError
        If ``analysis`` is unknown, ``det_J`` is asked of a non-square :math:`\mathbf J`, the
        robot is symbolic, or a number is out of range.

    Examples
    --------
    >>> import wmr
    >>> bot = wmr.paper_robot("centred")
    >>> res = wmr.sweep(bot, "mobility", Grid(12))
    >>> res.count, res.counts                    # mobility 1 where the axles meet (or are parallel)
    (1728, {0: 1408, 1: 320})
    >>> float(wmr.sweep(bot, "det_J", Grid(12)).worst)
    0.0
    """
    from ..model.robot import Robot
    if not isinstance(robot, Robot):
        raise TypeError(f"robot must be a wmr.Robot, got {robot!r}")
    if robot.is_symbolic:
        raise ValueError(f"robot must be numeric for a sweep, got a symbolic robot {robot!r}")
    if not isinstance(analysis, str):
        raise TypeError(f"analysis must be a string, one of {sorted(ANALYSES)}, got {analysis!r}")
    if analysis not in ANALYSES:
        raise ValueError(f"analysis must be one of {sorted(ANALYSES)}, got {analysis!r}")
    an = ANALYSES[analysis]
    if an.square and robot.n_rates != 3:
        raise ValueError(f"analysis 'det_J' needs a square J (n_rates = 3), got n_rates = {robot.n_rates} "
                         f"for {robot!r}; use 'kappa_J' for a non-square J")
    L = _J_length(robot, L) if an.uses_L else None
    w = robot.w
    source = _source(angles, w)
    qs = tuple(float(V.real("quantiles", q)) for q in np.atleast_1d(np.asarray(quantiles, dtype=object)))
    if any(not 0.0 <= q <= 1.0 for q in qs):
        raise ValueError(f"quantiles must lie in [0, 1], got {list(quantiles)}")
    chunk = _count("chunk", chunk)
    if isinstance(source, Sample):
        chunk = -(-chunk // _BLOCK) * _BLOCK
    if progress is not None and not callable(progress):
        raise TypeError(f"progress must be callable as progress(done, total), got {progress!r}")
    if client is not None and not callable(getattr(client, "map", None)):
        raise TypeError(f"client must be a dask.distributed.Client, got {client!r}")
    keep = bool(keep)

    total = source.size(w)
    bounds = [(a, min(a + chunk, total)) for a in range(0, total, chunk)]
    result = _Partial()
    done = 0
    if client is None:
        for a, b in bounds:
            result.merge(_evaluate(robot, analysis, source, w, L, a, b, keep, None))
            done += b - a
            if progress is not None:
                progress(done, total)
    else:
        from dask.distributed import as_completed
        futures = client.map(_evaluate, [robot] * len(bounds), [analysis] * len(bounds),
                             [source] * len(bounds), [w] * len(bounds), [L] * len(bounds),
                             [a for a, _ in bounds], [b for _, b in bounds], [keep] * len(bounds),
                             [1] * len(bounds), pure=False)
        for fut in as_completed(futures):
            part = fut.result()
            result.merge(part)
            done += part.count
            fut.release()
            if progress is not None:
                progress(done, total)
    return _finish(result, analysis, an, source, w, qs, keep)


def _finish(part, name, an, source, w, qs, keep):
    def angles_at(k):
        return source.configurations(w, k, k + 1)[0]

    worst, at = {"min": (part.lo, part.lo_at), "max": (part.hi, part.hi_at),
                 "min_abs": (part.small, part.small_at)}[an.worst]
    values = None
    if keep:
        values = np.empty(part.count)
        for start, x in part.values:
            values[start:start + x.size] = x
    return Sweep(
        analysis=name, count=part.count, min=part.lo, max=part.hi,
        argmin=angles_at(part.lo_at), argmax=angles_at(part.hi_at),
        worst=worst, worst_angles=angles_at(at), worst_index=at,
        quantiles={q: part.quantile(q, an.integer) for q in qs},
        counts=dict(part.integers.items()) if an.integer else {},
        infinite=part.infinite, values=values)
