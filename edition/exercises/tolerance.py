r"""The tolerance an exercise states and applies, and the hint for degrees given as radians (or the reverse).

A :class:`Tolerance` is written once per exercise: its :attr:`~Tolerance.statement` is what the question
says ("to 3 significant figures"), :meth:`~Tolerance.accepts` what the check applies, and
:meth:`~Tolerance.show` how a value is printed so that the printed value itself passes (a student who
copies a number from a success message, or rounds to the stated figures, is right).

* :func:`sig_figs` -- relative, for a quantity with a scale (a length, a rate, a condition number):
  any value rounded to ``n`` significant figures passes, :math:`|x - x^*| \le \tfrac12 10^{1-n}|x^*|`.
* :func:`decimals` -- absolute, :math:`|x - x^*| \le \tfrac12 10^{-n}` (angles in degrees, values of order one).
* :func:`within` -- an absolute and/or relative bound stated in the question's own words.

Examples
--------
>>> t = sig_figs(3)
>>> t.accepts(0.5033, 0.50332), t.accepts(0.50, 0.50332), t.show(0.5033189)
(True, False, '0.503')
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Tolerance", "sig_figs", "decimals", "within", "angle_gap", "unit_hint"]

_EPS = 4 * np.finfo(float).eps  # round-off of the comparison itself


@dataclass(frozen=True)
class Tolerance:
    """A stated tolerance: an absolute bound, a relative one (to the expected value), or both (the larger applies).

    Attributes
    ----------
    statement : str
        How the question states it (Markdown), e.g. ``"to 3 significant figures"``.
    rel : float
        Relative bound: :math:`|x - x^*| \\le` ``rel`` :math:`\\cdot |x^*|`.
    abs : float
        Absolute bound.
    digits : int
        Significant figures (relative) or decimals (absolute only) that :meth:`show` prints.
    rounding : bool
        True when the tolerance is stated in digits (:func:`sig_figs`, :func:`decimals`): then an answer
        rounded to fewer digits is recognised (:meth:`coarse`).
    """

    statement: str
    rel: float = 0.0
    abs: float = 0.0
    digits: int = 3
    rounding: bool = False

    def __post_init__(self):
        if not (self.rel >= 0 and self.abs >= 0 and self.rel + self.abs > 0):
            raise ValueError(f"a tolerance needs rel >= 0, abs >= 0, not both 0; got rel={self.rel}, abs={self.abs}")

    def allowed(self, expected):
        """The largest accepted deviation from ``expected`` (elementwise).

        Parameters
        ----------
        expected : float or array_like

        Returns
        -------
        numpy.ndarray
        """
        e = np.abs(np.asarray(expected, dtype=float))
        return np.maximum(self.abs, self.rel * e) * (1 + 1e-9) + _EPS * e

    def excess(self, value, expected):
        """The largest deviation in units of :meth:`allowed`: at most 1 when the value passes.

        Parameters
        ----------
        value, expected : float or array_like (same shape)

        Returns
        -------
        float
        """
        v, e = np.asarray(value, dtype=float), np.asarray(expected, dtype=float)
        return float(np.max(np.abs(v - e) / self.allowed(e)))

    def accepts(self, value, expected):
        """True when every entry of ``value`` is within the tolerance of ``expected``.

        Parameters
        ----------
        value, expected : float or array_like (same shape)

        Returns
        -------
        bool
        """
        return self.excess(value, expected) <= 1.0

    def coarse(self, value, expected, period=None):
        """True when ``value`` is the right value rounded to fewer digits than stated: a right method rounded
        too far, which the feedback tells apart from a wrong method (:meth:`close`).

        Every entry must equal ``expected`` rounded to ``k`` digits (figures for a relative tolerance, decimals
        for an absolute one), for one ``k`` below :attr:`digits`.  Only a tolerance stated in digits
        (:func:`sig_figs`, :func:`decimals`) has a coarse rounding; any other says False.

        Parameters
        ----------
        value, expected : float or array_like (same shape)
        period : float, optional
            For angles known modulo ``period`` (e.g. :math:`\\pi` for a wheel's line): ``expected`` is first
            moved by the multiple of ``period`` nearest ``value``.

        Returns
        -------
        bool

        Examples
        --------
        >>> t = sig_figs(4)
        >>> t.coarse(0.50, 0.50332), t.coarse(0.498, 0.50332), t.coarse(0.5033, 0.50332), t.coarse(-0.49, -0.5)
        (True, False, False, False)
        """
        if not self.rounding:
            return False
        v = np.atleast_1d(np.asarray(value, dtype=float))
        e = np.atleast_1d(np.asarray(expected, dtype=float))
        if period is not None:
            e = e + np.round((v - e) / period) * period
        if self.accepts(v, e):
            return False  # within the stated tolerance: right, not coarse
        for k in range(self.digits - 1, 0 if self.rel > 0 else -1, -1):
            shown = np.array([float(f"{x:.{k - 1}e}") for x in e]) if self.rel > 0 else np.round(e, k)
            if np.all(np.abs(v - shown) <= _EPS * np.maximum(np.abs(shown), 1.0)):
                return True
        return False

    def close(self, what):
        """The feedback for an answer that is :meth:`coarse`: close, outside the stated tolerance (Markdown).

        Parameters
        ----------
        what : str
            What was rounded too far, e.g. ``"$L$"`` or ``"angles of wheels 1, 2"``.

        Returns
        -------
        str
        """
        return (
            f"Close, but outside the stated tolerance ({self.statement}): you gave the right {what}, rounded to "
            "fewer digits than asked. Keep more digits."
        )

    def show(self, value):
        """``value`` printed (LaTeX) at the stated precision: the printed number passes :meth:`accepts`.

        Parameters
        ----------
        value : float

        Returns
        -------
        str
        """
        from ..text import number

        x = float(value)
        if self.rel > 0:
            return number(x, self.digits)
        return f"{x:.{self.digits}f}"


def sig_figs(n):
    """A relative tolerance: the answer to ``n`` significant figures.

    Parameters
    ----------
    n : int
        At least 1.

    Returns
    -------
    Tolerance
    """
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise ValueError(f"n must be an int >= 1, got {n!r}")
    return Tolerance(f"to {n} significant figures", rel=0.5 * 10.0 ** (1 - n), digits=n, rounding=True)


def decimals(n, unit=""):
    """An absolute tolerance: the answer to ``n`` decimal places (of ``unit``, e.g. ``"degrees"``).

    Parameters
    ----------
    n : int
        At least 0.
    unit : str, optional

    Returns
    -------
    Tolerance
    """
    if isinstance(n, bool) or not isinstance(n, int) or n < 0:
        raise ValueError(f"n must be an int >= 0, got {n!r}")
    places = "decimal place" if n == 1 else "decimal places"
    of = f" of {unit}" if unit else ""
    return Tolerance(f"to {n} {places}{of}", abs=0.5 * 10.0 ** (-n), digits=n, rounding=True)


def within(statement, abs=0.0, rel=0.0):
    """A tolerance stated in the question's own words, e.g. ``within("within 1 mm", abs=1e-3)``.

    Parameters
    ----------
    statement : str
    abs, rel : float
        Absolute and relative bounds (at least one positive).

    Returns
    -------
    Tolerance
    """
    digits = max(0, math.ceil(-math.log10(abs)) + 1) if abs > 0 else max(1, math.ceil(-math.log10(rel)) + 1)
    return Tolerance(statement, rel=rel, abs=abs, digits=digits)


def angle_gap(beta, expected, period=np.pi):
    """The largest difference between angles modulo ``period`` (radians): 0 for the same lines when ``period = pi``.

    Parameters
    ----------
    beta, expected : array_like (n,)
        Radians.
    period : float, optional
        :math:`\\pi` for lines (a wheel turned round is the same wheel-plane line), :math:`2\\pi` for directions.

    Returns
    -------
    float
        Radians, in :math:`[0, \\text{period}/2]`.
    """
    d = np.mod(np.asarray(beta, dtype=float) - np.asarray(expected, dtype=float) + period / 2, period) - period / 2
    return float(np.max(np.abs(d)))


def unit_hint(values, unit):
    """A hint when angles look like the other unit (degrees given as radians, or the reverse), else "".

    Used when the answer failed and the same numbers read in the other unit fail too: it says only what is
    true of the numbers (larger than :math:`2\\pi`, or all small).

    Parameters
    ----------
    values : array_like
        The numbers as given.
    unit : {"deg", "rad"}
        The unit the question asks for.

    Returns
    -------
    str
        Markdown, or "".
    """
    try:
        v = np.abs(np.asarray(values, dtype=float)).ravel()
    except (TypeError, ValueError):
        return ""
    if v.size == 0 or not np.all(np.isfinite(v)):
        return ""
    if unit == "rad" and v.max() > 2 * np.pi + 1e-9:
        return r"Some of these numbers are larger than $2\pi$: are they degrees? The question asks for radians."
    if unit == "deg" and v.max() <= 2 * np.pi and np.any(v != np.round(v)):
        return (
            r"All these numbers are at most $2\pi$ in size: if they are radians, convert them with `np.degrees`; "
            "the question asks for degrees."
        )
    return ""
