r"""Reading a student's answer: numbers, vectors, arrays, angles and SymPy objects, or one clear line why not.

Each reader returns the answer in the form the check computes with, or raises :class:`AnswerError`
whose message is one line naming what was expected and what was given (never a traceback); the
decorator :func:`edition.exercises.framework.exercise` turns it into a ``malformed`` result.

Examples
--------
>>> vector([0.5, 0.5, 0.5], 3, "three steering rates (rad/s)")
array([0.5, 0.5, 0.5])
>>> try:
...     vector([0.5, 0.5], 3, "three steering rates (rad/s)")
... except AnswerError as e:
...     print(e)
Expected three steering rates (rad/s); got a list of 2 numbers.
"""

from __future__ import annotations

import numbers

import numpy as np
import sympy as sp

__all__ = ["AnswerError", "describe", "number", "vector", "array", "angles", "sympy_object"]


class AnswerError(ValueError):
    """A student's answer that is not of the expected type or shape: the message is one line for the student."""


def _plural(n, word):
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def describe(obj):
    """What ``obj`` is, in a few words, for a message: "a list of 2 numbers", "text", "an array of shape (2, 3)".

    Parameters
    ----------
    obj : object

    Returns
    -------
    str

    Examples
    --------
    >>> describe([1, 2]), describe("0.5"), describe(np.zeros((2, 3))), describe(True)
    ('a list of 2 numbers', 'text (a string)', 'an array of shape (2, 3)', 'True (a truth value)')
    """
    if obj is None:
        return "None"
    if isinstance(obj, (bool, np.bool_)):
        return f"{bool(obj)} (a truth value)"
    if isinstance(obj, str):
        return "text (a string)"
    if isinstance(obj, (complex, np.complexfloating)):
        return "a complex number"
    if isinstance(obj, (numbers.Number, np.number)):
        return "one number"
    if isinstance(obj, sp.MatrixBase):
        return f"a SymPy matrix of shape {obj.shape}"
    if isinstance(obj, sp.Basic):
        return "a SymPy expression"
    if isinstance(obj, np.ndarray):
        return "one number" if obj.ndim == 0 else f"an array of shape {obj.shape}"
    if isinstance(obj, (list, tuple)):
        kind = type(obj).__name__
        try:
            a = np.asarray(obj, dtype=float)
        except (TypeError, ValueError):
            return f"a {kind} of {len(obj)} items, not all numbers"
        if a.ndim == 1:
            return f"a {kind} of {_plural(len(obj), 'number')}"
        return f"a {kind} of shape {a.shape}"
    if isinstance(obj, dict):
        return "a dict"
    if isinstance(obj, (set, frozenset)):
        return "a set (which has no order)"
    return f"a {type(obj).__name__}"


def _to_float(x):
    """One element of an answer as a float; TypeError for text, truth values, symbols and complex numbers."""
    if isinstance(x, (str, bytes, bool, np.bool_, complex, np.complexfloating)):
        raise TypeError(x)
    return float(x)  # SymPy numbers convert; an expression in symbols raises


def _float_array(answer, what):
    """``answer`` as a float array, or AnswerError (text, truth values, symbols, non-finite values)."""
    if answer is None or isinstance(answer, (str, bytes, dict, set, frozenset, bool, np.bool_)):
        raise AnswerError(f"Expected {what}; got {describe(answer)}.")
    if isinstance(answer, (sp.Basic, sp.MatrixBase)) and answer.free_symbols:
        names = ", ".join(sorted(f"${sp.latex(s)}$" for s in answer.free_symbols))
        raise AnswerError(f"Expected {what} as numbers; got an expression in {names}.")
    try:
        obj = np.asarray(sp.Matrix(answer).tolist() if isinstance(answer, sp.MatrixBase) else answer, dtype=object)
        a = np.array([_to_float(x) for x in obj.ravel()], dtype=float).reshape(obj.shape)
    except (TypeError, ValueError):
        raise AnswerError(f"Expected {what}; got {describe(answer)}.") from None
    if not np.all(np.isfinite(a)):
        raise AnswerError(f"Expected {what}; the answer has a value that is not finite (inf or NaN).")
    return a


def number(answer, what="a number"):
    """The answer as one finite float.

    Parameters
    ----------
    answer : int, float, NumPy or SymPy number
    what : str
        What the answer should be, in words (Markdown), for the message.

    Returns
    -------
    float

    Examples
    --------
    >>> number(sp.sqrt(2)) == np.sqrt(2), number(np.float32(0.5))
    (True, 0.5)
    """
    a = _float_array(answer, what)
    if a.size != 1 or (a.ndim > 0 and not isinstance(answer, (sp.Basic, sp.MatrixBase))):
        raise AnswerError(f"Expected {what}; got {describe(answer)}.")
    return float(a.ravel()[0])


def vector(answer, n, what):
    """The answer as ``n`` finite floats (a list, tuple, array, or a SymPy row or column).

    Parameters
    ----------
    answer : array_like
    n : int
        How many numbers.
    what : str
        What the answer should be, in words, e.g. ``"three steering angles in degrees"``.

    Returns
    -------
    numpy.ndarray (n,)
    """
    a = _float_array(answer, what)
    if a.ndim == 2 and 1 in a.shape:
        a = a.ravel()
    if a.shape != (n,):
        raise AnswerError(f"Expected {what}; got {describe(answer)}.")
    return a


def array(answer, shape, what):
    """The answer as a float array of ``shape``.

    Parameters
    ----------
    answer : array_like
    shape : tuple of int
    what : str
        What the answer should be, in words, e.g. ``"three mount points, an array of shape (3, 2)"``.

    Returns
    -------
    numpy.ndarray
    """
    a = _float_array(answer, what)
    if a.shape != tuple(shape):
        raise AnswerError(f"Expected {what}; got {describe(answer)}.")
    return a


def angles(answer, n, unit, what=None):
    """The answer as ``n`` angles in radians; ``unit`` is the unit the question asks for.

    Parameters
    ----------
    answer : array_like
    n : int
    unit : {"deg", "rad"}
    what : str, optional
        Default "n angles in degrees" / "... in radians".

    Returns
    -------
    numpy.ndarray (n,)
        Radians.
    """
    if unit not in ("deg", "rad"):
        raise ValueError(f"unit must be 'deg' or 'rad', got {unit!r}")
    words = {1: "one angle", 2: "two angles", 3: "three angles", 4: "four angles"}.get(n, f"{n} angles")
    what = what or f"{words} in {'degrees' if unit == 'deg' else 'radians'}"
    a = vector(answer, n, what) if n > 1 or np.ndim(answer) else np.array([number(answer, what)])
    return np.radians(a) if unit == "deg" else a


def sympy_object(answer, what):
    """The answer as a SymPy expression or matrix (numbers and lists of them are converted), or AnswerError.

    Parameters
    ----------
    answer : SymPy object, number, or (nested) list of them
    what : str

    Returns
    -------
    sympy.Expr or sympy.Matrix
    """
    if answer is None or isinstance(answer, (str, bytes, bool, np.bool_, dict, set, frozenset)):
        hint = " (write it with SymPy symbols, not as text)" if isinstance(answer, str) else ""
        raise AnswerError(f"Expected {what}; got {describe(answer)}{hint}.")
    obj = answer
    if not isinstance(answer, (sp.Basic, sp.MatrixBase)):
        try:
            listed = isinstance(answer, (list, tuple, np.ndarray))
            obj = sp.Matrix(answer) if listed else sp.sympify(answer, strict=True)
        except (TypeError, ValueError, sp.SympifyError):
            raise AnswerError(f"Expected {what}; got {describe(answer)}.") from None
    if obj.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise AnswerError(f"Expected {what}; the answer has a value that is not finite (infinity or NaN).")
    return obj
