r"""Input checks for arrays: numeric batches (finite reals of a given last axis) and SymPy vectors and matrices.

The scalar, point and object checks, and the rule of the two exception types, are in
:mod:`wmr.model.validation` (which also gives access to these: ``validation.finite_array``).

Examples
--------
>>> finite_array("beta", ["0.7", "0.1"])
Traceback (most recent call last):
    ...
wmr.errors.InputTypeError: beta must be an array of real numbers, got strings: ['0.7', '0.1']
"""

from __future__ import annotations

import numbers
from collections.abc import Mapping

import numpy as np

from ..errors import InputTypeError, InputValueError
from .checks import finite_float, kind_error, real, show
from .lazysympy import is_sympy, sp
from .types import ArrayLike, FloatArray, Numbers, Symbolic, TwistLike

__all__ = [
    "finite_array",
    "twist_array",
    "twist_kind",
    "TWIST_OBJECTS",
    "batch_shape",
    "symbolic_vector",
    "symbolic_matrix",
]

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
    """The entry of :data:`TWIST_OBJECTS` that ``value`` is, or None (arrays, numbers and sequences are none).

    Parameters
    ----------
    value : object

    Returns
    -------
    str or None
    """
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

    Parameters
    ----------
    name : str
    value : array_like (..., 3), a twist object, or a sequence of twist objects

    Returns
    -------
    numpy.ndarray (..., 3)

    Examples
    --------
    >>> class ChassisSpeeds:                      # what WPILib's looks like to wmr
    ...     vx, vy, omega = 1.0, 2.0, 0.5
    >>> twist_array("twist", ChassisSpeeds()).tolist(), twist_array("twist", [0.5, 1.0, 2.0]).tolist()
    ([0.5, 1.0, 2.0], [0.5, 1.0, 2.0])
    """
    kind = twist_kind(value)
    if kind is not None:
        return finite_array(name, [float(x) for x in TWIST_OBJECTS[kind][1](value)], last=3)
    if isinstance(value, (list, tuple)) and value and twist_kind(value[0]) is not None:
        return np.stack([twist_array(f"{name}[{k}]", v) for k, v in enumerate(value)])
    return finite_array(name, value, last=3)


def batch_shape(arrays: Mapping[str, FloatArray | None], core: int = 1) -> tuple[int, ...]:
    """The common batch shape of named arrays (each with ``core`` trailing axes), or a ``ValueError`` naming them.

    Parameters
    ----------
    arrays : dict of str to numpy.ndarray or None
        Arguments by name (``None`` entries are skipped).
    core : int, optional
        Trailing axes of each array that are not batch axes.

    Returns
    -------
    tuple of int

    Examples
    --------
    >>> batch_shape({"beta": np.zeros((5, 3)), "rates": np.zeros(3)})
    (5,)
    >>> batch_shape({"beta": np.zeros((2, 3)), "rates": np.zeros((4, 3))})
    Traceback (most recent call last):
        ...
    wmr.errors.InputValueError: beta and rates must have broadcastable batch shapes, got beta (2,) and rates (4,)
    """
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
    """Convert to a SymPy column of the given length (entries: real SymPy expressions or numbers).

    Parameters
    ----------
    name : str
    value : sequence or sympy.Matrix
    size : int

    Returns
    -------
    sympy.Matrix (size, 1)

    Examples
    --------
    >>> symbolic_vector("beta", [sp.Symbol("x"), 0], 2).shape
    (2, 1)
    """
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
    """Return ``value`` as a ``sympy.Matrix`` (2-D, entries real SymPy expressions or numbers).

    Parameters
    ----------
    name : str
    value : sympy.Matrix or array_like (m, n)

    Returns
    -------
    sympy.Matrix

    Examples
    --------
    >>> symbolic_matrix("M", [[1, sp.Symbol("x")]]).shape
    (1, 2)
    """
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
