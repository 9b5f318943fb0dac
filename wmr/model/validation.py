"""Input checks shared by the package: bad input raises ``ValueError`` naming it."""
from __future__ import annotations

import numbers

import numpy as np
import sympy as sp


def _scalar(value):
    """Unwrap 0-d NumPy arrays; keep everything else."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        return value.item()
    return value


def _number(value):
    """A validated real number as ``int`` (exact, so SymPy products stay exact) or ``float``."""
    return int(value) if isinstance(value, numbers.Integral) else float(value)


def real(name, value):
    """Return ``value`` if it is a finite real number (or a SymPy expression not known to be non-real)."""
    value = _scalar(value)
    if isinstance(value, sp.Basic):
        if value.is_real is False or value.is_finite is False:
            raise ValueError(f"{name} must be a finite real number, got {value!r}")
        return value
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} must be a real number, got {value!r}")
    if not np.isfinite(value):
        raise ValueError(f"{name} must be a finite real number, got {value!r}")
    return _number(value)


def positive(name, value):
    """Return ``value`` if it is a positive finite number (or a SymPy expression not known to be <= 0).

    Integers stay integers (so that SymPy expressions built from them stay exact).
    """
    value = _scalar(value)
    if isinstance(value, sp.Basic):
        if value.is_positive is False or value.is_finite is False:
            raise ValueError(f"{name} must be positive, got {value!r}")
        return value
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} must be a real number, got {value!r}")
    if not np.isfinite(value) or value <= 0:
        raise ValueError(f"{name} must be a positive finite number, got {value!r}")
    return _number(value)


def nonnegative(name, value):
    """Return ``value`` if it is a finite number >= 0 (or a SymPy expression not known to be < 0)."""
    value = _scalar(value)
    if isinstance(value, sp.Basic):
        if value.is_nonnegative is False or value.is_finite is False:
            raise ValueError(f"{name} must be non-negative, got {value!r}")
        return value
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} must be a real number, got {value!r}")
    if not np.isfinite(value) or value < 0:
        raise ValueError(f"{name} must be a finite number >= 0, got {value!r}")
    return _number(value)


def point(name, value):
    """Return a 2-tuple of finite reals (or SymPy expressions)."""
    try:
        items = tuple(value)
    except TypeError:
        raise ValueError(f"{name} must be a pair (x, y), got {value!r}") from None
    if len(items) != 2:
        raise ValueError(f"{name} must be a pair (x, y), got {value!r}")
    out = []
    for v in items:
        if isinstance(v, sp.Basic):
            out.append(v)
        elif isinstance(v, numbers.Real) and not isinstance(v, bool) and np.isfinite(v):
            out.append(float(v))
        else:
            raise ValueError(f"{name} must hold two finite real numbers, got {value!r}")
    return tuple(out)


def _short(arr):
    """A short text form of an array for error messages."""
    arr = np.asarray(arr)
    if arr.size <= 6:
        return np.array2string(arr, precision=4, separator=", ").replace("\n", "")
    return "first values " + np.array2string(arr.ravel()[:6], precision=4, separator=", ")[:-1] + ", ...]"


def finite_array(name, value, last=None):
    """Convert to a float array, require finiteness and (optionally) the size of the last axis."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be an array of real numbers, got {value!r}") from None
    if last is not None and (arr.ndim == 0 or arr.shape[-1] != last):
        raise ValueError(
            f"{name} must have shape (..., {last}), got shape {arr.shape}: {_short(arr)}")
    if not np.all(np.isfinite(arr)):
        bad = arr[~np.isfinite(arr)].ravel()[:3]
        raise ValueError(f"{name} must be finite, got non-finite values {bad.tolist()}")
    return arr


def symbolic_vector(name, value, size):
    """Convert to a SymPy column of the given length."""
    M = sp.Matrix(list(value)) if not isinstance(value, sp.MatrixBase) else sp.Matrix(value)
    if M.shape not in ((size, 1), (1, size)):
        raise ValueError(f"{name} must have {size} entries, got shape {M.shape}")
    return M.reshape(size, 1)
