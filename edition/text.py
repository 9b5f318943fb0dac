r"""How the edition prints numbers: angles in degrees, round-off residuals as bounds, values to meaningful digits.

Every number that reaches a caption, a CSV, a figure or the report goes through these helpers, so
the artefacts are the same on every machine: a result that is zero up to round-off is printed as
a bound at the stated resolution (:data:`RESOLUTION`), never with its round-off digits; other
values are printed with a few significant digits (:func:`number`) or, in data files, rounded to
:data:`DECIMALS` places (:func:`rounded`).
"""

from __future__ import annotations

import numpy as np

__all__ = ["RESOLUTION", "SMALL", "DECIMALS", "degrees", "bound", "residual", "number", "rounded"]

#: Residuals below this are printed as ``< 1e-12``: round-off of the 6x9 matrices built here is
#: about 1e-15, so the bound holds on any IEEE-754 machine while the printed text does not change.
RESOLUTION = 1e-12
#: Residuals from :data:`RESOLUTION` up to this are accumulated round-off of longer computations
#: (an optimiser's stopping test, a sum over thousands of configurations): their digits differ
#: between machines, so they are printed as the next power of ten above them (``< 1e-10``).
SMALL = 1e-9
#: Decimal places kept by :func:`rounded`: far above round-off (about 1e-15 for the quantities of
#: order one printed here: lengths in units of L, angles in degrees), far below what is meaningful.
DECIMALS = 10


def degrees(angle, digits=6):
    r"""An angle given in radians, printed in degrees: an integer when it is one (to 1e-6 deg), else ``digits`` digits.

    Parameters
    ----------
    angle : float
        Radians.
    digits : int, optional

    Returns
    -------
    str

    Examples
    --------
    >>> degrees(np.pi / 3), degrees(np.radians(12.5)), degrees(-np.pi), degrees(np.radians(-15.5241), 4)
    ('60', '12.5', '-180', '-15.52')
    """
    v = round(float(np.degrees(angle)), 6) + 0.0
    if abs(v - round(v)) <= 1e-6:
        return str(int(round(v)))
    return f"{v:.{digits}g}"


def bound(value, resolution=RESOLUTION, latex=False):
    r"""A non-negative residual printed as a bound ``< 1e-12`` when it is round-off, else with 2 digits.

    A floating-point residual that is exactly 0 on one machine is a few ulps on another, so 0 is
    printed as the same bound as any other round-off (the text is then the same everywhere); an
    exact zero (SymPy) is printed by the caller, not here.  A small residual above the resolution
    (below :data:`SMALL`) is printed as the power of ten above it: ``3.4e-11`` becomes ``< 1e-10``.

    Parameters
    ----------
    value : float
        A residual, :math:`\ge 0`.
    resolution : float, optional
        Values below it are round-off and printed as ``< resolution``.
    latex : bool, optional
        Print ``< 10^{-12}`` in LaTeX (for ``$...$``) instead of ``< 1e-12``.

    Returns
    -------
    str

    Examples
    --------
    >>> bound(0.0), bound(4.2e-16), bound(3.4e-11), bound(3.14159e-3)
    ('< 1e-12', '< 1e-12', '< 1e-10', '3.1e-03')
    >>> bound(4.2e-16, latex=True), bound(2e-10, latex=True), bound(3.14159e-5, latex=True)
    ('< 10^{-12}', '< 10^{-9}', '3.1\\times10^{-5}')
    """
    v = float(value)
    if not np.isfinite(v) or v < 0:
        raise ValueError(f"value must be a finite residual >= 0, got {value!r}")
    if v < max(resolution, SMALL):
        k = int(round(np.log10(resolution))) if v < resolution else int(np.floor(np.log10(v))) + 1
        return f"< 10^{{{k}}}" if latex else f"< 1e{k}"
    return number(v, 2) if latex else f"{v:.1e}"


def residual(symbol, value, resolution=RESOLUTION):
    r"""A residual as a LaTeX relation: ``symbol < 10^{-12}`` (round-off) or ``symbol = 3.1\times10^{-5}``.

    Parameters
    ----------
    symbol : str
        LaTeX of the quantity, e.g. ``r"|\det\mathbf{J}|"``.
    value : float
        The residual.
    resolution : float, optional
        Below this the value is round-off and shown as a bound (:func:`bound`).

    Returns
    -------
    str
        LaTeX (no ``$``).

    Examples
    --------
    >>> residual(r"|\det\mathbf{J}|", 4.2e-18), residual("e", 2.5e-7)
    ('|\\det\\mathbf{J}| < 10^{-12}', 'e = 2.5\\times10^{-7}')
    """
    b = bound(value, resolution, latex=True)
    return f"{symbol} {b}" if b.startswith("<") else f"{symbol} = {b}"


def number(value, digits=3):
    r"""A meaningful value in LaTeX with ``digits`` significant digits (scientific below 1e-3 and from 1e4).

    For values whose digits mean something (a fitted radius, an integration error, a condition
    number); round-off residuals go through :func:`bound` instead.

    Parameters
    ----------
    value : float
    digits : int, optional

    Returns
    -------
    str
        ``0``, ``\infty``, ``0.3``, ``-1.25`` or ``4.9\times10^{-11}``.

    Examples
    --------
    >>> number(0.3), number(-1.2345), number(4.93e-11, 2), number(float("inf"))
    ('0.3', '-1.23', '4.9\\times10^{-11}', '\\infty')
    """
    x = float(value)
    if not np.isfinite(x):
        return "\\infty" if x > 0 else ("-\\infty" if x < 0 else "\\mathrm{NaN}")
    if x == 0:
        return "0"
    if abs(x) < 1e-3 or abs(x) >= 1e4:
        m, e = f"{x:.{digits - 1}e}".split("e")
        return rf"{m}\times10^{{{int(e)}}}"
    return f"{x:.{digits}g}"


def rounded(value, decimals=DECIMALS):
    """A value for a data file (JSON): floats rounded to ``decimals`` places, recursively; no ``-0.0``.

    Non-finite floats become the strings ``"inf"``, ``"-inf"``, ``"nan"`` (JSON has no such
    numbers); tuples and arrays become lists; ints, bools, strings and None pass unchanged.

    Parameters
    ----------
    value : object
        A number, or a dict, list, tuple or array of them (nested).
    decimals : int, optional
        Decimal places kept.

    Returns
    -------
    object
        The same structure, ready for :func:`json.dumps`.

    Examples
    --------
    >>> rounded([0.12345678901234, -1e-17, 2, float("inf")])
    [0.123456789, 0.0, 2, 'inf']
    """
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        v = float(value)
        if not np.isfinite(v):
            return "nan" if v != v else ("inf" if v > 0 else "-inf")
        return round(v, decimals) + 0.0
    if isinstance(value, np.ndarray):
        return rounded(value.tolist(), decimals)
    if isinstance(value, (list, tuple)):
        return [rounded(v, decimals) for v in value]
    if isinstance(value, dict):
        return {str(k): rounded(v, decimals) for k, v in value.items()}
    return value
