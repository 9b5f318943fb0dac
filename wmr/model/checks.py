r"""Input checks for scalars, points and flags: the base of :mod:`wmr.model.validation`.

Two kinds of bad input, two exception types (:mod:`wmr.errors`), and every message names the
argument and shows the value it got:

* :class:`~wmr.errors.InputTypeError` (a ``TypeError``): the wrong *kind* of thing (a string, a
  bool, a complex number, ``None``, a SymPy symbol where numbers are needed, the class ``Robot``
  instead of a robot);
* :class:`~wmr.errors.InputValueError` (a ``ValueError``): the right kind with a bad *value*
  (negative radius, NaN, infinity, a wrong shape, a number too large for double precision such as
  ``10**400`` or ``np.longdouble('1e400')``).

Numbers are checked in the unit of the caller: nothing here depends on the unit of length.
The array checks are in :mod:`wmr.model.arrays`, the robot checks in :mod:`wmr.model.robot_checks`;
:mod:`wmr.model.validation` gathers all three under one name.  The modules the robot is built from
(platform, wheels, robot) import these two directly, so that no import goes round in a circle.

Examples
--------
>>> positive("r", 0.1)
0.1
>>> positive("r", -1)
Traceback (most recent call last):
    ...
wmr.errors.InputValueError: r must be positive, got -1
>>> real("angle", "0.7")
Traceback (most recent call last):
    ...
wmr.errors.InputTypeError: angle must be a real number, got '0.7' (str)
"""

from __future__ import annotations

import math
import numbers
from typing import Any

import numpy as np

from ..errors import InputTypeError, InputValueError
from .lazysympy import is_sympy, sp
from .types import Numbers

__all__ = [
    "real",
    "number",
    "positive",
    "nonnegative",
    "point",
    "flag",
    "optional_text",
    "integer",
    "show",
    "kind_error",
    "finite_float",
]


def show(value: Any, limit: int = 80) -> str:
    """A short one-line text form of ``value`` for error messages.

    Parameters
    ----------
    value : object
    limit : int, optional
        Longest text returned (longer forms are cut with "...").

    Returns
    -------
    str

    Examples
    --------
    >>> show(np.zeros(100))
    'array of shape (100,), first values [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, ...]'
    """
    if isinstance(value, np.ndarray) and value.ndim > 0 and value.dtype.kind in "biufc":
        if value.size <= 6:
            text = np.array2string(value, precision=4, separator=", ").replace("\n", "")
        else:
            head = ", ".join(repr(x) for x in value.ravel()[:6].tolist())
            text = f"array of shape {value.shape}, first values [{head}, ...]"
    else:
        try:
            text = repr(value)
        except Exception:  # a broken __repr__ must not hide the error
            text = f"<{type(value).__name__} object>"
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _scalar(value):
    """Unwrap 0-d NumPy arrays; keep everything else."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        return value[()]
    return value


def kind_error(name: str, value: Any, wanted: str) -> InputTypeError:
    """The error for an argument of the wrong kind: names it, shows it and says what was wanted.

    Parameters
    ----------
    name : str
        The argument's name.
    value : object
        What it got.
    wanted : str
        What it should be, e.g. ``"a real number"``.

    Returns
    -------
    wmr.errors.InputTypeError
        To be raised by the caller.

    Examples
    --------
    >>> print(kind_error("r", "0.1", "a real number"))
    r must be a real number, got '0.1' (str)
    """
    kind = type(value).__name__
    if isinstance(value, type):
        kind = f"the class {value.__name__}"
    return InputTypeError(f"{name} must be {wanted}, got {show(value)} ({kind})")


def finite_float(name: str, value: Any) -> float:
    """``float(value)`` for a real number; an input error if it is not finite in double precision.

    Parameters
    ----------
    name : str
        The argument's name, for the message.
    value : numbers.Real or sympy.Expr
        A real number (not checked for its kind: see :func:`real`).

    Returns
    -------
    float

    Examples
    --------
    >>> finite_float("x", 10**400)
    Traceback (most recent call last):
        ...
    wmr.errors.InputValueError: x must be a finite real number, got 1000... (too large for double precision)
    """
    with np.errstate(over="ignore"):
        try:
            f = float(value)
        except OverflowError:
            f = math.inf
    if not math.isfinite(f):
        big = (
            isinstance(value, numbers.Rational)
            or (isinstance(value, np.floating) and bool(np.isfinite(value)))
            or (is_sympy(value) and value.is_finite)
        )  # finite as written: 10**400, 1e400L
        raise InputValueError(
            f"{name} must be a finite real number, got {show(value)}"
            + (" (too large for double precision)" if big else "")
        )
    return f


def _number(name, value):
    """A finite real number: ``int`` stays ``int`` (SymPy products stay exact), others become ``float``."""
    value = _scalar(value)
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise kind_error(name, value, "a real number")
    f = finite_float(name, value)
    return int(value) if isinstance(value, numbers.Integral) else f


def _symbolic(name, value, wanted="a real number"):
    """A SymPy expression that may stand for a finite real number (checked as far as SymPy knows)."""
    if not is_sympy(value, "Expr"):
        raise kind_error(name, value, wanted)
    if value.has(sp.nan, sp.zoo, sp.oo, -sp.oo) or value.is_finite is False:
        raise InputValueError(f"{name} must be finite, got {show(value)}")
    if value.is_real is False or (value.is_real is None and value.has(sp.I)):
        raise InputValueError(f"{name} must be real, got {show(value)}")
    if value.is_number:
        finite_float(name, value)  # exact numbers must fit a double too
    return value


def real(name: str, value: Any) -> Numbers:
    """Return ``value`` if it is a finite real number (or a SymPy expression that may be one).

    Parameters
    ----------
    name : str
        The argument's name, for the message.
    value : object

    Returns
    -------
    int, float or sympy.Expr

    Raises
    ------
    TypeError
        Not a real number (bool, string, complex, None, ...).
    ValueError
        NaN, infinite, too large for double precision, or a SymPy expression known not to be real.

    Examples
    --------
    >>> real("angle", np.float32(0.5)), real("angle", 3)
    (0.5, 3)
    """
    value = _scalar(value)
    if is_sympy(value):
        return _symbolic(name, value)
    return _number(name, value)


def _signed(name, value, strict):
    """``real`` and > 0 (``strict``) or >= 0; for SymPy, not known to be otherwise."""
    value = real(name, value)
    wanted = "positive" if strict else "non-negative (>= 0)"
    if is_sympy(value):
        bad = (value.is_positive if strict else value.is_nonnegative) is False
    else:
        bad = value <= 0 if strict else value < 0
    if bad:
        raise InputValueError(f"{name} must be {wanted}, got {show(value)}")
    return value


def number(name: str, value: Any) -> float:
    """Return ``value`` as a ``float`` if it is a finite real number (SymPy numbers too, not symbols).

    Parameters
    ----------
    name : str
    value : object

    Returns
    -------
    float

    Examples
    --------
    >>> number("angle", sp.pi / 2)
    1.5707963267948966
    """
    value = real(name, value)
    if is_sympy(value):
        if value.free_symbols:
            raise InputTypeError(f"{name} must be a number here, got the expression {show(value)}")
        value = finite_float(name, value)
    return float(value)


def positive(name: str, value: Any) -> Numbers:
    """Return ``value`` if it is a positive finite number (or a SymPy expression not known to be <= 0).

    Integers stay integers (so that SymPy expressions built from them stay exact).

    Parameters
    ----------
    name : str
    value : object

    Returns
    -------
    int, float or sympy.Expr

    Examples
    --------
    >>> positive("L", 2)
    2
    """
    return _signed(name, value, strict=True)


def nonnegative(name: str, value: Any) -> Numbers:
    """Return ``value`` if it is a finite number >= 0 (or a SymPy expression not known to be < 0).

    Parameters
    ----------
    name : str
    value : object

    Returns
    -------
    int, float or sympy.Expr

    Examples
    --------
    >>> nonnegative("d", 0)
    0
    """
    return _signed(name, value, strict=False)


def point(name: str, value: Any) -> tuple[Numbers, Numbers]:
    """Return a pair ``(x, y)`` of finite reals (floats) or SymPy expressions.

    Parameters
    ----------
    name : str
    value : pair

    Returns
    -------
    tuple of 2 float or sympy.Expr

    Examples
    --------
    >>> point("position", np.array([1, 2]))
    (1.0, 2.0)
    """
    if isinstance(value, (str, bytes, dict, set)) or is_sympy(value):
        raise kind_error(name, value, "a pair (x, y)")
    try:
        items = tuple(value)
    except TypeError:
        raise kind_error(name, value, "a pair (x, y)") from None
    if len(items) != 2:
        raise InputValueError(f"{name} must be a pair (x, y), got {show(value)} ({len(items)} entries)")
    out = []
    for k, v in enumerate(items):
        v = real(f"{name}[{k}] (of {show(value, 40)})", v)
        out.append(v if is_sympy(v) else float(v))
    return out[0], out[1]


def flag(name: str, value: Any) -> bool:
    """Return ``value`` as ``bool`` if it is a bool (Python or NumPy).

    Parameters
    ----------
    name : str
    value : object

    Returns
    -------
    bool

    Examples
    --------
    >>> flag("exact", np.True_)
    True
    """
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise kind_error(name, value, "True or False")


def optional_text(name: str, value: Any) -> str | None:
    """Return ``value`` if it is a string or None.

    Parameters
    ----------
    name : str
    value : object

    Returns
    -------
    str or None
    """
    if value is None or isinstance(value, str):
        return value
    raise kind_error(name, value, "a string or None")


def integer(name: str, value: Any, minimum: int | None = None) -> int:
    """Return ``value`` as ``int`` if it is an integer (not a bool), at least ``minimum``.

    Parameters
    ----------
    name : str
    value : object
    minimum : int, optional

    Returns
    -------
    int

    Examples
    --------
    >>> integer("n", np.int64(3), minimum=1)
    3
    """
    value = _scalar(value)
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise kind_error(name, value, "an integer")
    if minimum is not None and value < minimum:
        raise InputValueError(f"{name} must be at least {minimum}, got {show(value)}")
    return int(value)
