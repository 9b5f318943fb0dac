r"""Input checks of scalars, points, flags and arrays: the base of :mod:`wmr.model.validation`.

Two kinds of bad input, two exception types (:mod:`wmr.errors`), and every message names the
argument and shows the value it got:

* :class:`~wmr.errors.InputTypeError` (a ``TypeError``): the wrong *kind* of thing (a string, a
  bool, a complex number, ``None``, a SymPy symbol where numbers are needed, the class ``Robot``
  instead of a robot);
* :class:`~wmr.errors.InputValueError` (a ``ValueError``): the right kind with a bad *value*
  (negative radius, NaN, infinity, a wrong shape, a number too large for double precision such as
  ``10**400`` or ``np.longdouble('1e400')``).

Numbers are checked in the unit of the caller.  The robot checks are in :mod:`wmr.model.validation`,
which gathers these with them; the modules a robot is built from (platform, wheels, robot) import this
one, so that no import goes round in a circle.

Examples
--------
>>> positive("r", -1)
Traceback (most recent call last):
    ...
wmr.errors.InputValueError: r must be positive, got -1
>>> finite_array("beta", ["0.7", "0.1"])
Traceback (most recent call last):
    ...
wmr.errors.InputTypeError: beta must be an array of real numbers, got strings: ['0.7', '0.1']
"""

from __future__ import annotations

import difflib
import math
import numbers
import os
from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np

from ..errors import InputTypeError, InputValueError
from .lazysympy import is_sympy, sp
from .types import ArrayLike, FloatArray, Numbers, Symbolic, TwistLike

__all__ = ["number", "positive", "finite_array"]


def show(value: Any, limit: int = 80) -> str:
    """A one-line text form of ``value`` for error messages, at most ``limit`` characters (cut with "...")."""
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
    """The error (for the caller to raise) of an argument of the wrong kind: its name, its value, what was wanted."""
    kind = type(value).__name__
    if isinstance(value, type):
        kind = f"the class {value.__name__}"
    return InputTypeError(f"{name} must be {wanted}, got {show(value)} ({kind})")


def suggest(word: str, choices: Iterable[str]) -> str:
    """The hint ``" (did you mean 'x'?)"`` naming the closest of ``choices`` to ``word``, or an empty string."""
    close = difflib.get_close_matches(word, list(choices), n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


def finite_float(name: str, value: Any) -> float:
    """``float(value)`` of a real number (its kind checked by the caller); an input error if not finite as a double."""
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
    """``value`` if it is a finite real number (``int`` stays ``int``) or a SymPy expression that may be one."""
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
        The argument's name, for the message.
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
        The argument's name, for the message.
    value : object

    Returns
    -------
    int, float or sympy.Expr

    Examples
    --------
    >>> positive("L", 2), positive("r", 0.1)
    (2, 0.1)
    """
    return _signed(name, value, strict=True)


def nonnegative(name: str, value: Any) -> Numbers:
    """``value`` if it is a finite number >= 0 (or a SymPy expression not known to be < 0)."""
    return _signed(name, value, strict=False)


def point(name: str, value: Any) -> tuple[Numbers, Numbers]:
    """A pair ``(x, y)`` of finite reals (as floats) or SymPy expressions."""
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
    """``value`` as ``bool`` if it is a bool (Python or NumPy)."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise kind_error(name, value, "True or False")


def file_path(value: Any, optional: bool = False) -> Any:
    """``value`` if it is a file name (``str`` or ``os.PathLike``), or None when ``optional``: the argument ``path``."""
    if (optional and value is None) or isinstance(value, (str, os.PathLike)):
        return value
    wanted = "a file name (str or os.PathLike)" + (" or None" if optional else "")
    raise InputTypeError(f"path must be {wanted}, got {show(value)}")


def integer(name: str, value: Any, minimum: int | None = None) -> int:
    """``value`` as ``int`` if it is an integer (not a bool), at least ``minimum``."""
    value = _scalar(value)
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise kind_error(name, value, "an integer")
    if minimum is not None and value < minimum:
        raise InputValueError(f"{name} must be at least {minimum}, got {show(value)}")
    return int(value)


# --- arrays ---------------------------------------------------------------------------------------
#: twist objects of other libraries, read by their fields into wmr's order [psi_dot, x_dot, y_dot]:
#: name -> (the fields that identify it, how to read it)
TWIST_OBJECTS = {
    "WPILib ChassisSpeeds(vx, vy, omega)": (("vx", "vy", "omega"), lambda o: (o.omega, o.vx, o.vy)),
    "WPILib Twist2d(dx, dy, dtheta)": (("dx", "dy", "dtheta"), lambda o: (o.dtheta, o.dx, o.dy)),
    "ROS geometry_msgs/Twist (linear, angular)": (
        ("linear", "angular"),
        lambda o: (o.angular.z, o.linear.x, o.linear.y),
    ),
}


def twist_kind(value):
    """The entry of :data:`TWIST_OBJECTS` that ``value`` is, or None (arrays, numbers and sequences are none)."""
    if isinstance(value, (np.ndarray, numbers.Number, str, bytes, list, tuple)) or value is None:
        return None
    for kind, (fields, _) in TWIST_OBJECTS.items():
        if all(hasattr(value, f) for f in fields):
            return kind
    return None


def _object_array(name, raw, value):
    """Floats from an object array whose entries are real numbers (Fraction, int, ...)."""
    out = np.empty(raw.shape)
    flat = out.reshape(-1)
    for k, v in enumerate(raw.flat):
        if is_sympy(v):
            raise InputTypeError(
                f"{name} must be an array of numbers, got SymPy entries in {show(value)} "
                "(use the SymPy backend for symbolic work)"
            )
        if isinstance(v, (bool, np.bool_)) or not isinstance(v, numbers.Real):
            raise kind_error(name, value, "an array of real numbers") from None
        flat[k] = finite_float(name, v)
    return out


def finite_array(name: str, value: ArrayLike, last: int | None = None) -> FloatArray:
    """Convert to a float array; require finite real entries and (optionally) the size of the last axis.

    Parameters
    ----------
    name : str
        The argument's name, for the message.
    value : array_like
    last : int, optional
        Required length of the last axis.

    Returns
    -------
    numpy.ndarray of float64

    Raises
    ------
    TypeError
        Strings, bools, complex numbers, None, SymPy entries.
    ValueError
        Ragged nesting, a wrong last axis, NaN, infinity, entries too large for double precision.

    Examples
    --------
    >>> finite_array("twist", [1, 2, 3], last=3)
    array([1., 2., 3.])
    """
    if isinstance(value, np.ndarray) and value.dtype == np.float64:
        arr = value
    else:
        if value is None or isinstance(value, (str, bytes)):
            raise kind_error(name, value, "an array of real numbers")
        kind = twist_kind(value)
        if kind is not None:  # never read a twist object's fields in an order of its own
            raise InputTypeError(
                f"{name} must be an array of real numbers, got a {kind.split('(')[0].strip()} "
                f"(twist objects are accepted where a twist is expected): {show(value)}"
            )
        try:
            raw = np.asarray(value)
        except (ValueError, TypeError):
            raise InputValueError(
                f"{name} must be a regular (not ragged) array of real numbers, got {show(value)}"
            ) from None
        kind = raw.dtype.kind
        if kind in "iuf":
            with np.errstate(over="ignore"):
                arr = raw.astype(np.float64)
            if kind == "f" and raw.dtype.itemsize > 8 and not np.all(np.isfinite(arr)) and np.all(np.isfinite(raw)):
                raise InputValueError(f"{name} has entries too large for double precision: {show(raw)}")
        elif kind == "O":
            arr = _object_array(name, raw, value)
        else:
            what = {"b": "booleans", "c": "complex numbers", "U": "strings", "S": "strings"}.get(kind, raw.dtype.name)
            raise InputTypeError(f"{name} must be an array of real numbers, got {what}: {show(value)}")
    if last is not None and (arr.ndim == 0 or arr.shape[-1] != last):
        raise InputValueError(f"{name} must have shape (..., {last}), got shape {arr.shape}: {show(arr)}")
    if not np.isfinite(arr).all():
        bad = arr[~np.isfinite(arr)].ravel()[:3]
        raise InputValueError(f"{name} must be finite, got non-finite values {bad.tolist()}")
    return arr


def twist_array(name: str, value: TwistLike) -> FloatArray:
    r"""A twist :math:`[\dot\psi, \dot x, \dot y]` (..., 3): numbers in wmr's order, or twist objects read by field.

    A WPILib ``ChassisSpeeds(vx, vy, omega)`` becomes ``[omega, vx, vy]``, a WPILib ``Twist2d`` ``[dtheta, dx,
    dy]``, a ROS ``geometry_msgs/Twist`` ``[angular.z, linear.x, linear.y]`` (:data:`TWIST_OBJECTS`), also
    in a list; everything else goes through :func:`finite_array` with a last axis of 3.
    """
    kind = twist_kind(value)
    if kind is not None:
        return finite_array(name, [float(x) for x in TWIST_OBJECTS[kind][1](value)], last=3)
    if isinstance(value, (list, tuple)) and value and twist_kind(value[0]) is not None:
        return np.stack([twist_array(f"{name}[{k}]", v) for k, v in enumerate(value)])
    return finite_array(name, value, last=3)


def batch_shape(arrays: Mapping[str, FloatArray | None], core: int = 1) -> tuple[int, ...]:
    """The common batch shape of named arrays (``core`` trailing axes each; None skipped), or an error naming them."""
    given = {k: v for k, v in arrays.items() if v is not None}
    try:
        return np.broadcast_shapes(*[np.shape(v)[: np.ndim(v) - core] for v in given.values()])
    except ValueError:
        names = list(given)
        shapes = " and ".join(f"{k} {np.shape(v)[: np.ndim(v) - core]}" for k, v in given.items())
        raise InputValueError(
            f"{', '.join(names[:-1])} and {names[-1]} must have broadcastable batch shapes, got {shapes}"
        ) from None


def symbolic_vector(name: str, value: Numbers, size: int) -> Symbolic:
    """A SymPy column (size, 1) of real SymPy expressions or numbers, from ``size`` entries (a sequence or a matrix)."""
    if is_sympy(value, "MatrixBase"):
        entries = list(value)
        shape = value.shape
    else:
        if isinstance(value, (str, bytes)) or is_sympy(value):
            raise kind_error(name, value, f"a sequence of {size} entries")
        try:
            entries = list(value)
        except TypeError:
            raise kind_error(name, value, f"a sequence of {size} entries") from None
        shape = (len(entries), 1)
    if shape not in ((size, 1), (1, size)):
        raise InputValueError(f"{name} must have {size} entries, got shape {shape}")
    return sp.Matrix([real(f"{name}[{k}]", v) for k, v in enumerate(entries)])


def symbolic_matrix(name: str, value: Numbers) -> Symbolic:
    """``value`` as a 2-D ``sympy.Matrix`` whose entries are real SymPy expressions or numbers."""
    if isinstance(value, (str, bytes)) or value is None:
        raise kind_error(name, value, "a matrix")
    try:
        if not is_sympy(value, "MatrixBase") and any(
            isinstance(e, (str, bytes)) for e in np.asarray(value, dtype=object).ravel()
        ):
            raise kind_error(name, value, "a matrix of numbers or SymPy expressions")
        M = sp.Matrix(value)
    except (TypeError, ValueError, NotImplementedError, sp.SympifyError):
        raise kind_error(name, value, "a matrix (m, n)") from None
    for k, e in enumerate(M):
        real(f"{name} entry {k}", e)
    return M
