r"""Small algebra helpers of the derivations: substitute named objects, angles modulo pi."""

from __future__ import annotations

import numpy as np
import sympy as sp

__all__ = ["explicit", "numeric", "mod_pi", "exact_matrix"]


def explicit(expr, mapping):
    """Substitute explicit matrices for the named objects (MatrixSymbols) of a printed form.

    Parameters
    ----------
    expr : SymPy expression or Matrix
    mapping : dict
        Named object -> SymPy matrix or expression.

    Returns
    -------
    sympy.Matrix
    """
    return sp.Matrix(sp.sympify(expr).subs(mapping).doit())


def numeric(expr, mapping):
    """:func:`explicit` with NumPy matrices; returns a float array.

    Parameters
    ----------
    expr : SymPy expression or Matrix
    mapping : dict
        Named object -> array.

    Returns
    -------
    numpy.ndarray
    """
    return np.array(explicit(expr, {k: sp.Matrix(v) for k, v in mapping.items()}), dtype=float)


def mod_pi(angle):
    r"""An angle modulo :math:`\pi`, in :math:`[-\pi/2, \pi/2)`: a wheel rolls either way, so axle angles count mod
    :math:`\pi`.

    Parameters
    ----------
    angle : array_like
        Radians.

    Returns
    -------
    numpy.ndarray

    Examples
    --------
    >>> float(mod_pi(np.pi + 0.25))
    0.25
    """
    return (np.asarray(angle, dtype=float) + np.pi / 2) % np.pi - np.pi / 2


def exact_matrix(M):
    """A matrix with its floating-point entries replaced by the exact numbers they print as (``nsimplify``).

    Parameters
    ----------
    M : sympy.Matrix

    Returns
    -------
    sympy.Matrix
        Same shape.

    Examples
    --------
    >>> exact_matrix(sp.Matrix([[0.5, 1.0]]))
    Matrix([[1/2, 1]])
    """
    return M.applyfunc(sp.nsimplify)
