r"""The reduction of a sweep: what is kept of a chunk of values, and how two of them merge.

Count, minimum, maximum and minimum magnitude with the first configuration attaining each
(ties go to the lower configuration index), exact counts of integer values, and for real values
a logarithmic bucket sketch whose quantiles are within a relative :data:`SKETCH_ACCURACY`.
Merging is associative, so the result does not depend on how the configurations were chunked.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ...io.decimals import quantise
from ...model.types import FloatArray
from .result import Sweep

__all__ = ["SKETCH_ACCURACY", "first_written"]

#: Relative accuracy of the quantiles of real-valued analyses (see :class:`~wmr.analysis.sweep.Sweep`).
SKETCH_ACCURACY = 1e-4


def first_written(x: FloatArray, v: float) -> int:
    """Index of the first value of ``x`` written as ``v`` is (:func:`wmr.io.decimals.quantise`, scale 1).

    ``v`` is a value of ``x``; writing is monotone in the value, so only values before its first
    occurrence and within a quantum of it (at most :math:`10^{-11}` of :math:`\\max(|v|, 1)`, ten
    times that in the next decade) can be written as ``v`` is: those few are rounded, not the chunk.

    Parameters
    ----------
    x : numpy.ndarray (k,)
        A chunk of an analysis's values.
    v : float
        One of them (its minimum or maximum, say).

    Returns
    -------
    int
        The first ``i`` with ``quantise(x[i], 1.0) == quantise(v, 1.0)``.
    """
    if math.isnan(v):
        return int(np.flatnonzero(np.isnan(x))[0])
    first = int(np.argmax(x == v))
    if math.isinf(v):
        return first
    near = np.flatnonzero(np.abs(x[:first] - v) <= 2e-10 * max(abs(v), 1.0))
    if near.size == 0:
        return first
    hit = np.flatnonzero(quantise(x[near], 1.0) == quantise(v, 1.0))
    return int(near[hit[0]]) if hit.size else first


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
            grown[self.offset - new_lo : self.offset - new_lo + self.counts.size] = self.counts
            self.offset, self.counts = new_lo, grown
        self.counts[lo - self.offset : lo - self.offset + part.size] += part

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
class Partial:
    """The reduction of a set of configurations (associative: see :meth:`merge`)."""

    count: int = 0  # configurations reduced
    lo: float = math.nan  # minimum and its configuration index (nan: nothing yet)
    lo_at: int = -1
    hi: float = math.nan  # maximum
    hi_at: int = -1
    small: float = math.nan  # minimum magnitude
    small_at: int = -1
    integers: _Counts = field(default_factory=_Counts)  # integer analyses: value -> count
    positive: _Counts = field(default_factory=_Counts)  # real analyses: sketch bucket of the positive values -> count
    negative: _Counts = field(default_factory=_Counts)  # ... of the negative values
    zeros: int = 0
    infinite: int = 0  # +inf (a condition number at a singular configuration)
    values: list = field(default_factory=list)  # (start, array) when kept

    def add(self, start: int, x: FloatArray, integer: bool, keep: bool) -> Partial:
        """Fold in the values ``x (k,)`` of configurations ``start .. start + k - 1`` and return this reduction."""
        self.count += x.size
        lo, hi, ax = float(x.min()), float(x.max()), np.abs(x)
        small = float(ax.min())
        self._lo(lo, start + first_written(x, lo))
        self._hi(hi, start + first_written(x, hi))
        self._small(small, start + first_written(ax, small))
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
        return self

    @staticmethod
    def _first(v, at, best, best_at, sign):
        """The better value of ``v`` and ``best`` (sign * value smaller), and where: the lower index of a tie.

        The index is chosen from the values as :mod:`wmr.io.decimals` writes them (12 digits at the scale 1), so
        that values equal but for round-off (a constant analysis; another CPU's last bits) are ties and the
        configuration reported is the first of them wherever the sweep runs; the value is the exact extreme.
        """
        if best_at < 0:
            return v, at
        value = min(v, best) if sign > 0 else max(v, best)
        qv, qb = quantise(v, 1.0), quantise(best, 1.0)
        if sign * qv < sign * qb or (qv == qb and at < best_at):
            return value, at
        return value, best_at

    def _lo(self, v, at):
        self.lo, self.lo_at = self._first(v, at, self.lo, self.lo_at, 1)

    def _hi(self, v, at):
        self.hi, self.hi_at = self._first(v, at, self.hi, self.hi_at, -1)

    def _small(self, v, at):
        self.small, self.small_at = self._first(v, at, self.small, self.small_at, 1)

    def merge(self, other: Partial) -> Partial:
        """Fold in another reduction and return this one (associative: the order of the chunks does not matter)."""
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

    def quantile(self, q: float, integer: bool) -> float:
        """The order statistic of rank floor(q (count - 1)): exact for integers, else within :data:`SKETCH_ACCURACY`."""
        return min(max(self._quantile(q, integer), self.lo), self.hi)

    def _quantile(self, q, integer):
        if q == 0.0:
            return self.lo
        if q == 1.0:
            return self.hi
        rank = math.floor(q * (self.count - 1))
        if integer:
            return float(self.integers.locate(rank)[0])
        k, rank = self.negative.locate(rank, descending=True)  # most negative first
        if k is not None:
            return -_bucket_value(k)
        if rank < self.zeros:
            return 0.0
        k, rank = self.positive.locate(rank - self.zeros)
        return math.inf if k is None else _bucket_value(k)


def finish(part, name, an, source, w, qs, keep, covers, complete=True):
    """The :class:`Sweep` of the reduction ``part`` of analysis ``name`` (entry ``an``) over ``source``.

    ``qs``: the quantiles to report; ``covers``: the configurations in words; ``complete`` False: interrupted.
    """
    worst, at = {"min": (part.lo, part.lo_at), "max": (part.hi, part.hi_at), "min_abs": (part.small, part.small_at)}[
        an.worst
    ]
    values = None
    if keep:
        values = np.empty(part.count)
        for start, x in part.values:
            values[start : start + x.size] = x
    quantiles = {q: part.quantile(q, an.integer) for q in qs}
    argmin, argmax, worst_angles = (
        source[k] if isinstance(source, np.ndarray) else source.configurations(w, k, k + 1)[0]
        for k in (part.lo_at, part.hi_at, at)
    )
    return Sweep(
        analysis=name,
        count=part.count,
        min=part.lo,
        max=part.hi,
        argmin=argmin,
        argmax=argmax,
        worst=worst,
        worst_angles=worst_angles,
        worst_index=at,
        quantiles=quantiles,
        counts=dict(part.integers.items()) if an.integer else {},
        infinite=part.infinite,
        values=values,
        covers=covers,
        complete=complete,
    )
