r"""Which configurations a sweep visits: a :class:`Grid` or a :class:`Sample` of all steering angles.

Every source numbers its configurations ``0 .. size(w) - 1`` and hands out any range of them
(``configurations(w, start, stop)``, shape ``(stop - start, w)``) without generating the others,
so chunks can be made anywhere, in any order.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass
from typing import cast

import numpy as np

from ...errors import InputTypeError, InputValueError
from ...model import validation
from ...model.types import FloatArray

__all__ = ["Grid", "Sample"]

#: random samples are drawn in blocks of this size (see Sample): a chunk is a whole number of blocks
BLOCK = 1 << 16


def _bounds(lo, hi):
    lo, hi = validation.real("lo", lo), validation.real("hi", hi)
    if not hi > lo:
        raise InputValueError(f"hi must be greater than lo, got lo = {lo!r}, hi = {hi!r}")
    return float(lo), float(hi)


def count(name: str, value: object, minimum: int = 1) -> int:
    """``value`` as an ``int`` of at least ``minimum``: an integer, or a float with an integral value (``1e6``)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        if isinstance(value, float) and value.is_integer():
            value = int(value)
        else:
            raise InputTypeError(f"{name} must be an integer, got {value!r}")
    if value < minimum:
        raise InputValueError(f"{name} must be at least {minimum}, got {value!r}")
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
            steps = tuple(count("steps", s) for s in steps)
            if not steps:
                raise InputValueError("steps must not be empty")
        else:
            steps = count("steps", steps)
        object.__setattr__(self, "steps", steps)
        lo, hi = _bounds(self.lo, self.hi)
        object.__setattr__(self, "lo", lo)
        object.__setattr__(self, "hi", hi)

    @property
    def covers(self):
        """The set of configurations, in words (for the reductions)."""
        steps = "x".join(map(str, self.steps)) if isinstance(self.steps, tuple) else f"{self.steps} per angle"
        return (
            f"all steering angles (drivable or not): a grid of {steps} over "
            f"[{math.degrees(self.lo):g}, {math.degrees(self.hi):g}) deg"
        )

    def shape(self, w: int) -> tuple[int, ...]:
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
                raise InputValueError(f"Grid.steps has {len(self.steps)} entries, the robot has w = {w} angles")
            return cast(tuple[int, ...], self.steps)  # (ints: checked when the grid was made)
        return (cast(int, self.steps),) * w

    def size(self, w: int) -> int:
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

    def configurations(self, w: int, start: int, stop: int) -> FloatArray:
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
        object.__setattr__(self, "n", count("n", self.n))
        object.__setattr__(self, "seed", count("seed", self.seed, minimum=0))
        lo, hi = _bounds(self.lo, self.hi)
        object.__setattr__(self, "lo", lo)
        object.__setattr__(self, "hi", hi)

    @property
    def covers(self):
        """The set of configurations, in words (for the reductions)."""
        return (
            f"all steering angles (drivable or not): {self.n:,} configurations drawn uniformly from "
            f"[{math.degrees(self.lo):g}, {math.degrees(self.hi):g}) deg per angle (seed {self.seed})"
        )

    def size(self, w: int) -> int:
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

    def configurations(self, w: int, start: int, stop: int) -> FloatArray:
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
        first, last = start // BLOCK, (stop - 1) // BLOCK
        rows = [(j, max(start - j * BLOCK, 0), min(stop - j * BLOCK, BLOCK)) for j in range(first, last + 1)]
        return np.concatenate([self._rows(w, j, a, b) for j, a, b in rows])

    def _rows(self, w, j, a, b):
        """Rows ``a .. b-1`` of block ``j``: ``default_rng([seed, j]).uniform(lo, hi, (BLOCK, w))[a:b]``, drawn alone.

        ``uniform`` takes one 64-bit draw per value: the generator is advanced past the ``a * w`` values before row ``a``.
        """
        bits = np.random.PCG64(np.random.SeedSequence([self.seed, j]))  # the generator of default_rng([seed, j])
        bits.advance(a * w)
        return np.random.Generator(bits).uniform(self.lo, self.hi, (b - a, w))
