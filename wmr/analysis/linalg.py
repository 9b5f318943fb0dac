r"""Linear algebra on stacks of matrices ``(..., m, n)``: singular values, rank, nullity, null space, condition number.

Every decision "is this singular value zero?" uses the one tolerance :data:`wmr.model.tolerance.TOL`
(relative to the largest singular value).  Functions accept any number of leading batch axes and
run the batched LAPACK routines over chunks on all cores (:mod:`wmr.analysis._batch`).
"""
from __future__ import annotations

import numpy as np

from ..model import validation as V
from ..model.tolerance import TOL
from ._batch import map_matrices

__all__ = ["singular_values", "rank", "nullity", "null_space", "condition_number", "gram"]


def _as_stack(A):
    """Validate a stack of matrices ``(..., m, n)`` of finite reals."""
    A = V.finite_array("A", A)
    if A.ndim < 2:
        raise ValueError(f"A must have shape (..., m, n), got shape {A.shape}")
    return A


def singular_values(A):
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
    A = _as_stack(A)
    if min(A.shape[-2:]) == 0:
        return np.zeros(A.shape[:-2] + (0,))
    return map_matrices(lambda X: np.linalg.svd(X, compute_uv=False), A)


def _rank_from_sv(s):
    if s.shape[-1] == 0:
        return np.zeros(s.shape[:-1], dtype=int)
    return np.sum(s > TOL * np.maximum(1.0, s[..., :1]), axis=-1)


def _det_small(G):
    """Determinant of a stack of p x p matrices, p <= 3, in closed form."""
    p = G.shape[-1]
    if p == 1:
        return G[..., 0, 0]
    if p == 2:
        return G[..., 0, 0] * G[..., 1, 1] - G[..., 0, 1] * G[..., 1, 0]
    return (G[..., 0, 0] * (G[..., 1, 1] * G[..., 2, 2] - G[..., 1, 2] * G[..., 2, 1])
            - G[..., 0, 1] * (G[..., 1, 0] * G[..., 2, 2] - G[..., 1, 2] * G[..., 2, 0])
            + G[..., 0, 2] * (G[..., 1, 0] * G[..., 2, 1] - G[..., 1, 1] * G[..., 2, 0]))


def _certified_full_rank(A):
    r"""Members of a stack ``(..., m, n)`` with ``p = min(m, n) <= 3`` whose rank is surely ``p``.

    With :math:`f = \|\mathbf A\|_F^2 \ge \sigma_{max}^2` and :math:`D = \prod_k\sigma_k` (for a
    square matrix :math:`|\det\mathbf A|`, otherwise :math:`\sqrt{\det\mathbf G}` with the
    :math:`p\times p` Gram matrix :math:`\mathbf G`), the smallest singular value satisfies
    :math:`\sigma_{min} \ge D / f^{(p-1)/2}`.  A member is certified when this lower bound, less a
    generous bound on the rounding error of the determinant, exceeds
    :math:`2\,\mathrm{TOL}\max(1, \sqrt f)`: then the SVD rule of :func:`rank` gives rank ``p``
    as well (its own rounding is far below the factor 2), so the certificate changes no result.
    Members that are not certified (nearly or truly rank-deficient) are left to the SVD.
    """
    m, n = A.shape[-2:]
    p = min(m, n)
    eps = np.finfo(float).eps
    with np.errstate(over="ignore", invalid="ignore"):
        f = np.einsum("...ij,...ij->...", A, A)
        if m == n:
            D = np.abs(_det_small(A))
            err = (10 * p + 100) * eps * f ** (p / 2)                   # >> rounding of det A
            ok = (D - err) > 2 * TOL * np.sqrt(np.maximum(1.0, f)) * f ** ((p - 1) / 2)
        else:
            G = np.einsum("...ki,...kj->...ij", A, A) if m > n else np.einsum("...ik,...jk->...ij", A, A)
            err = (10 * (m + n) + 100) * eps * f ** p                 # >> rounding of G and det G
            ok = (_det_small(G) - err) > (2 * TOL) ** 2 * np.maximum(1.0, f) * f ** (p - 1)
    return ok & np.isfinite(f) & (f > 0)


def rank(A):
    """Numerical rank of a stack of matrices (singular values above ``TOL * max(1, s_max)``).

    For matrices with at most 3 rows or columns, members of full rank are recognised in
    closed form (a certified bound, see :func:`_certified_full_rank`) and only the others go
    through the SVD; the result is the same as the SVD rule for every member.

    Parameters
    ----------
    A : array_like (..., m, n)

    Returns
    -------
    numpy.ndarray of int (...)

    Examples
    --------
    >>> int(rank([[1.0, 2.0], [2.0, 4.0]]))
    1
    >>> rank(np.stack([np.eye(3), np.ones((3, 3))])).tolist()
    [3, 1]
    """
    A = _as_stack(A)
    p = min(A.shape[-2:])
    if p == 0 or p > 3:
        return _rank_from_sv(singular_values(A))
    flat = A.reshape((-1,) + A.shape[-2:])
    out = np.full(flat.shape[0], p, dtype=int)
    todo = ~_certified_full_rank(flat)
    if np.any(todo):
        out[todo] = _rank_from_sv(singular_values(flat[todo]))
    return out.reshape(A.shape[:-2])


def nullity(A):
    """Nullity ``n - rank(A)`` (27) of a stack of matrices.

    Parameters
    ----------
    A : array_like (..., m, n)

    Returns
    -------
    numpy.ndarray of int (...)

    Examples
    --------
    >>> int(nullity([[1.0, 2.0, 3.0]]))
    2
    """
    A = _as_stack(A)
    return A.shape[-1] - rank(A)


def null_space(A):
    """Orthonormal basis of the null space of one matrix.

    Parameters
    ----------
    A : array (m, n)

    Returns
    -------
    numpy.ndarray (n, nullity)

    Examples
    --------
    >>> null_space([[1.0, 0.0, 0.0]]).shape
    (3, 2)
    """
    A = V.finite_array("A", A)
    if A.ndim != 2:
        raise ValueError(f"A must be one matrix (m, n) for null_space, got shape {A.shape} (loop over a batch)")
    _, s, Vt = np.linalg.svd(A)
    r = int(_rank_from_sv(s[None, :])[0]) if s.size else 0
    return Vt[r:].T.copy()


def _left_null(L):
    """Orthonormal basis (2, k) of the left null space of a constant 2 x n block."""
    L = np.asarray(L, dtype=float)
    U, s, _ = np.linalg.svd(L)
    r = int(_rank_from_sv(s[None, :])[0]) if s.size else 0
    return U[:, r:]


def condition_number(A):
    r"""Condition number :math:`\kappa = \sigma_l/\sigma_s` (30) of a stack of matrices.

    Rank-deficient matrices (smallest singular value at most ``TOL * max(1, sigma_l)``)
    get ``inf``, as (31) prescribes.

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
    """
    A = _as_stack(A)
    return _kappa_from_sv(singular_values(A))


def _kappa_from_sv(s):
    smax, smin = s[..., 0], s[..., -1]
    singular = smin <= TOL * np.maximum(1.0, smax)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(singular, np.inf, smax / np.where(singular, 1.0, smin))


def gram(A):
    r"""The product :math:`\mathbf A^T\mathbf A` of each matrix of a stack, as in (34), (40) and (54).

    Parameters
    ----------
    A : array_like (..., m, n)

    Returns
    -------
    numpy.ndarray (..., n, n)

    Examples
    --------
    >>> gram([[1.0, 2.0], [0.0, 1.0]]).tolist()
    [[1.0, 2.0], [2.0, 5.0]]
    """
    A = _as_stack(A)
    return np.swapaxes(A, -1, -2) @ A
