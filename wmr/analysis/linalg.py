r"""Linear algebra on stacks of matrices ``(..., m, n)``: singular values, rank, nullity, null space, condition number.

Every decision "is this singular value zero?" uses the one tolerance :data:`wmr.model.tolerance.TOL`,
relative to the largest singular value; ranks are taken after each column is divided by its
length (:func:`~wmr.model.tolerance.column_norms`), so that they do not depend on the units of the
unknowns.  For matrices with at most three rows or columns, :func:`det`, :func:`rank` and
:func:`condition_number` use closed forms (:mod:`wmr.analysis._closed`) for every member they can vouch
for and the SVD for the others, so their decisions are the SVD's.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.tolerance import column_norms
from ..model.types import ArrayLike, FloatArray, IntArray
from . import _closed
from .sv_decisions import kappa_from_singular_values, rank_from_singular_values

__all__ = ["singular_values", "rank", "nullity", "null_space", "condition_number", "det"]


def _stack(A: ArrayLike) -> FloatArray:
    """The entry check of this module: a stack of matrices ``(..., m, n)`` of finite reals."""
    A = validation.finite_array("A", A)
    if A.ndim < 2:
        raise InputValueError(f"A must have shape (..., m, n), got shape {A.shape}")
    return A


def singular_values(A: ArrayLike) -> FloatArray:
    """Singular values, descending, of a stack of matrices.

    Parameters
    ----------
    A : array_like (..., m, n)

    Returns
    -------
    numpy.ndarray (..., min(m, n))

    Examples
    --------
    >>> singular_values([[3.0, 0.0], [0.0, -4.0]]).tolist()
    [4.0, 3.0]
    """
    A = _stack(A)
    if min(A.shape[-2:]) == 0:
        return np.zeros(A.shape[:-2] + (0,))
    big = np.max(np.abs(A), axis=(-2, -1))
    if np.any(big > 1e150) or np.any((big < 1e-150) & (big > 0)):  # far from 1: scaled, so LAPACK sees no overflow
        m = np.where(big > 0, big, 1.0)[..., None]
        with np.errstate(over="ignore"):  # overflow is reported by _finite
            sv = singular_values(A / m[..., None]) * m
        return _finite("A", sv, "its singular values")
    # one LAPACK call over the stack: chunks on the thread pool gained 1.0x on 10^6 3x6 matrices (python -m tools.bench.fastpaths)
    return np.linalg.svd(A, compute_uv=False)


def _finite(name, result, what):
    """Overflow is detected, not propagated: a result from finite input is finite or the call raises."""
    if not np.isfinite(result).all():
        raise InputValueError(f"{name} is too large: {what} overflow double precision")
    return result


def _scaled(A: FloatArray, scale: FloatArray | None) -> FloatArray:
    """``A`` with column j divided by ``scale[..., j]`` (default: the column lengths)."""
    scale = column_norms(A) if scale is None else scale
    with np.errstate(over="ignore", under="ignore"):
        out = A / scale[..., None, :]
    if not np.isfinite(out).all():
        raise InputValueError(f"scale is too small for A: A / scale overflows (scale = {validation.show(scale)})")
    return out


def rank(A: ArrayLike, scale: ArrayLike | None = None) -> IntArray:
    """Numerical rank of a stack of matrices, independent of the units of the unknowns.

    Each column is divided by its size (default: its length, :func:`column_norms`), then the
    singular values above ``TOL`` times the largest one are counted (:mod:`wmr.model.tolerance`).
    So ``rank(A) == rank(A @ D)`` for every positive diagonal ``D``; a column that is small only
    next to the others is not neglected (give ``scale`` to say what "small" means instead).

    Parameters
    ----------
    A : array_like (..., m, n)
    scale : array_like (n,) or (..., n), optional
        Positive size of each column (in the unit of its entries).  Default: the column lengths.

    Returns
    -------
    numpy.ndarray of int (...)

    Examples
    --------
    >>> int(rank([[1.0, 2.0], [2.0, 4.0]]))
    1
    >>> rank(np.stack([np.eye(3), np.ones((3, 3))])).tolist()
    [3, 1]
    >>> int(rank(np.diag([1.0, 1e-12]))), int(rank(np.diag([1.0, 1e-12]), scale=[1.0, 1.0]))
    (2, 1)
    """
    A = _stack(A)
    if scale is not None:
        scale = validation.finite_array("scale", scale, last=A.shape[-1])
        if np.any(scale <= 0):
            raise InputValueError(f"scale must hold positive column sizes, got {validation.show(scale)}")
    p = min(A.shape[-2:])
    if p == 0 or p > 3 or scale is None or scale.ndim != 1:
        A = _scaled(A, scale)  # column sizes per matrix: one pass over the stack
        scale = None  # else one size per column: applied chunk by chunk
    if p == 0 or p > 3:
        return rank_from_singular_values(singular_values(A))
    flat = A.reshape((-1,) + A.shape[-2:])
    out = np.full(flat.shape[0], p, dtype=int)
    todo = np.flatnonzero(~_closed.certified_full_rank(flat, scale))
    if todo.size:
        rest = flat[todo] if scale is None else _scaled(flat[todo], scale)
        out[todo] = rank_from_singular_values(singular_values(rest))
    return out.reshape(A.shape[:-2])


def nullity(A: ArrayLike, scale: ArrayLike | None = None) -> IntArray:
    """Nullity ``n - rank(A)`` (27) of a stack of matrices (rank as in :func:`rank`).

    Parameters
    ----------
    A : array_like (..., m, n)
    scale : array_like (n,) or (..., n), optional
        As for :func:`rank`.

    Returns
    -------
    numpy.ndarray of int (...)

    Examples
    --------
    >>> int(nullity([[1.0, 2.0, 3.0]]))
    2
    """
    r = rank(A, scale)  # (checks A)
    return np.shape(A)[-1] - r


def null_space(A: ArrayLike, scale: ArrayLike | None = None) -> FloatArray:
    """Orthonormal basis of the null space of one matrix (rank as in :func:`rank`).

    The dimension is ``nullity(A, scale)``; the basis is the last right singular vectors of
    ``A`` itself (orthonormal in the coordinates of ``A``, and as accurate as its own SVD).

    Parameters
    ----------
    A : array (m, n)
    scale : array_like (n,), optional
        As for :func:`rank`.

    Returns
    -------
    numpy.ndarray (n, nullity)

    Examples
    --------
    >>> null_space([[1.0, 0.0, 0.0]]).shape
    (3, 2)
    >>> (null_space([[1e6, 1.0]]).round(9) + 0.0).tolist()          # x = -1e-6 y
    [[-1e-06], [1.0]]
    """
    A = validation.finite_array("A", A)
    if A.ndim != 2:
        raise InputValueError(f"A must be one matrix (m, n) for null_space, got shape {A.shape} (loop over a batch)")
    r = int(rank(A, scale))
    if A.shape[0] == 0:
        return np.eye(A.shape[1])  # no equations: every vector
    big = np.abs(A).max() if A.size else 0.0
    full = A.shape[0] < A.shape[1]  # Vt (n, n) either way; no (m, m) U for tall matrices
    _, _, Vt = np.linalg.svd(A / big if big > 0 else A, full_matrices=full)  # (scaled: the same vectors, no overflow)
    return Vt[r:].T.copy()


def left_null_space(A: ArrayLike) -> FloatArray:
    r"""Orthonormal ``(m, m - rank A)`` with :math:`\mathbf u^T\mathbf A = \mathbf 0`, columns scaled as for :func:`rank`."""
    r = int(rank(A))  # (checks A)
    A = np.asarray(A, dtype=float)
    if A.ndim != 2:
        raise InputValueError(f"A must be one matrix (m, n) for left_null_space, got shape {A.shape}")
    return np.linalg.svd(_scaled(A, None))[0][:, r:]


def condition_number(A: ArrayLike) -> FloatArray:
    r"""Condition number :math:`\kappa = \sigma_l/\sigma_s` (30) of a stack of matrices.

    Rank-deficient matrices (smallest singular value at most ``TOL * sigma_l``, i.e.
    :math:`\kappa \ge 1/\mathrm{TOL}`) get ``inf``, as (31) prescribes; the matrix is taken as
    given (no column scaling: :math:`\kappa` is the paper's measure, made homogeneous by L).

    Parameters
    ----------
    A : array (..., m, n)

    Returns
    -------
    numpy.ndarray (...)

    Examples
    --------
    >>> float(condition_number([[2.0, 0.0], [0.0, 1.0]]))
    2.0
    >>> condition_number([np.diag([3.0, 2.0, 1.0]), np.ones((3, 3))]).tolist()
    [3.0, inf]
    """
    A = _stack(A)
    if min(A.shape[-2:]) == 0:
        raise InputValueError(
            f"A must have at least one row and one column for a condition number, got shape {A.shape}"
        )
    if A.shape[-2:] != (3, 3):
        return kappa_from_singular_values(singular_values(A))
    flat = A.reshape(-1, 3, 3)
    kappa, accepted = _closed.condition_number_3x3(flat)
    todo = np.flatnonzero(~accepted)
    if todo.size:
        kappa[todo] = kappa_from_singular_values(singular_values(flat[todo]))
    return kappa.reshape(A.shape[:-2])


def det(A: ArrayLike) -> FloatArray:
    r"""Determinant of each matrix of a stack of square matrices.

    Parameters
    ----------
    A : array_like (..., n, n)

    Returns
    -------
    numpy.ndarray (...)

    Raises
    ------
    ValueError
        If the matrices are not square or not finite.

    Examples
    --------
    >>> float(det([[2.0, 1.0], [1.0, 3.0]]))
    5.0
    >>> det(np.stack([np.eye(3), 2 * np.eye(3)])).tolist()
    [1.0, 8.0]
    """
    A = _stack(A)
    n = A.shape[-1]
    if A.shape[-2] != n:
        raise InputValueError(f"A must be a stack of square matrices (..., n, n), got shape {A.shape}")
    if n == 0:
        return np.ones(A.shape[:-2])
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.linalg.det(A) if n > 3 else _closed.det(A.reshape(-1, n, n)).reshape(A.shape[:-2])
    return _finite("A", out, "its determinants")
