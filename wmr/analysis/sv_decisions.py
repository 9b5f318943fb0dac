r"""How singular values decide, with the one tolerance :data:`wmr.model.tolerance.TOL`: the rank (the singular values
above ``TOL`` times the largest) and the condition number (30)-(31) (largest over smallest, ``inf`` when the smallest
is at most ``TOL`` times the largest).

These two rules are the only place where a singular value is judged zero; :mod:`wmr.analysis.linalg` applies them
(:func:`~wmr.analysis.linalg.rank`, :func:`~wmr.analysis.linalg.condition_number`), and so does the plain reference
:mod:`wmr.analysis.reference`.
"""

from __future__ import annotations

import numpy as np

from ..model.tolerance import TOL
from ..model.types import FloatArray, IntArray

__all__ = ["rank_from_singular_values", "kappa_from_singular_values"]


def rank_from_singular_values(s: FloatArray) -> IntArray:
    """The rule of :func:`~wmr.analysis.linalg.rank`: the singular values above ``TOL`` times the largest one.

    A zero matrix has rank 0.

    Parameters
    ----------
    s : numpy.ndarray (..., k)
        Singular values, descending (:func:`~wmr.analysis.linalg.singular_values`).

    Returns
    -------
    numpy.ndarray of int (...)

    Examples
    --------
    >>> rank_from_singular_values(np.array([[2.0, 1e-12], [2.0, 1.0]])).tolist()
    [1, 2]
    """
    if s.shape[-1] == 0:
        return np.zeros(s.shape[:-1], dtype=int)
    return np.sum(s > TOL * s[..., :1], axis=-1)


def kappa_from_singular_values(s: FloatArray) -> FloatArray:
    """The rule of :func:`~wmr.analysis.linalg.condition_number`: largest over smallest singular value.

    ``inf`` when they are at most ``TOL`` apart (31).

    Parameters
    ----------
    s : numpy.ndarray (..., k)
        Singular values, descending (:func:`~wmr.analysis.linalg.singular_values`).

    Returns
    -------
    numpy.ndarray (...)

    Examples
    --------
    >>> kappa_from_singular_values(np.array([[2.0, 1.0], [1.0, 1e-12]])).tolist()
    [2.0, inf]
    """
    smax, smin = s[..., 0], s[..., -1]
    singular = smin <= TOL * smax
    return np.where(singular, np.inf, smax / np.where(singular, 1.0, smin))  # smin > TOL smax >= 0: no zero division
