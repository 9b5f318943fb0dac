r"""Mobility: rank, nullity and null space of the functional matrix (23)-(27).

The mobility of a WMR is the nullity :math:`\nu(\mathbf F) = \dim\mathcal N(\mathbf F)` (27): the number
of generalised rates :math:`\dot{\mathbf q}` (25) that can be assigned freely without violating the
no-slip constraints.  All rank decisions use :data:`wmr.tolerance.TOL`.

For batches of configurations, :func:`mobility` does not take an SVD of every
:math:`2w\times(3+n)` matrix :math:`\mathbf F`.  It uses the structure
:math:`\mathbf F = [\mathbf J_1\ \ -\mathrm{blockdiag}(\mathbf R_{bwi}\mathbf L_i)]`, where the
:math:`\mathbf L_i` are the units' constant local blocks, to write exactly

.. math:: \operatorname{rank}\mathbf F = \sum_i\operatorname{rank}\mathbf L_i
          + \operatorname{rank}\mathbf A(\boldsymbol\beta),\qquad
          \mathbf A = \begin{bmatrix}\vdots\\ \mathbf N_i^T\mathbf R_{bwi}^T[\mathbf E\mathbf d_i\ \ \mathbf 1]\\
          \vdots\end{bmatrix},

with :math:`\mathbf N_i` an orthonormal basis of the left null space of :math:`\mathbf L_i` (for a
centred or dual wheel, the axle direction).  The rows of :math:`\mathbf A` are the constraints the
platform twist must satisfy; :math:`\mathbf A` is :math:`k\times 3` with :math:`k` small.
"""
from __future__ import annotations

import numpy as np

from . import _validate as V
from ._batch import map_matrices
from .backend import NUMERIC
from .platform import E
from .tolerance import TOL


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


def twist_constraints(robot, beta):
    r"""The constraint rows :math:`\mathbf A(\boldsymbol\beta)` on the platform twist (see module notes).

    A twist :math:`\mathbf t` is admissible (some joint rates realise it without slip) exactly when
    :math:`\mathbf A\mathbf t = \mathbf 0`.

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)

    Returns
    -------
    A : numpy.ndarray (..., k, 3)
    base_rank : int
        :math:`\sum_i \operatorname{rank}\mathbf L_i`.

    Examples
    --------
    >>> from wmr.robots import paper_robot
    >>> A, base = twist_constraints(paper_robot("centred"), [0.0, 0.0, 0.0])
    >>> A.shape, base
    ((3, 3), 3)
    """
    beta = V.finite_array("beta", beta, last=robot.w)
    J1 = robot.J1()
    # R(beta) = cos(beta) I + sin(beta) E (11), so the rows N_i^T R^T [E d_i 1] are
    # cos(beta_i) P_i + sin(beta_i) Q_i with constant P_i, Q_i: no batched 2x2 products needed.
    Et = E(NUMERIC).T
    parts, base_rank = [], 0
    for i, u in enumerate(robot.wheels):
        N = _left_null(u._local_block(NUMERIC))  # (2, k_i), constant
        base_rank += 2 - N.shape[1]             # rank L_i
        if N.shape[1] == 0:
            continue
        Ji = J1[2 * i:2 * i + 2]
        parts.append((i, N.T @ Ji, N.T @ Et @ Ji))
    k = sum(P.shape[0] for _, P, _ in parts)
    A = np.empty(beta.shape[:-1] + (k, 3))
    row = 0
    for i, P, Q in parts:
        b = beta[..., i, None, None]
        A[..., row:row + P.shape[0], :] = np.cos(b) * P + np.sin(b) * Q
        row += P.shape[0]
    return A, base_rank


def rank_F(robot, beta):
    r"""Rank of the functional matrix :math:`\mathbf F(\boldsymbol\beta)` for a batch of configurations.

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)

    Returns
    -------
    numpy.ndarray of int (...)

    Examples
    --------
    >>> from wmr.robots import paper_robot
    >>> rank_F(paper_robot("centred"), [[0.0, 0.0, 0.0], [0.1, 0.2, 0.3]]).tolist()
    [5, 6]
    """
    A, base = twist_constraints(robot, beta)
    return base + rank(A)


def mobility(robot, beta):
    r"""Mobility :math:`\nu(\mathbf F) = (3 + n) - \operatorname{rank}\mathbf F` (27), batched.

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)
        Steering angles.

    Returns
    -------
    numpy.ndarray of int (...)

    Examples
    --------
    >>> from wmr.robots import paper_robot
    >>> int(mobility(paper_robot("offset", d=0.5), [0.1, 0.2, 0.3]))
    3
    >>> int(mobility(paper_robot("centred"), [0.0, 0.0, 0.0]))   # parallel wheels: translation
    1
    """
    return 3 + robot.n_rates - rank_F(robot, beta)


def admissible_twists(robot, beta):
    r"""Orthonormal basis (3, m) of the admissible platform twists at one configuration.

    The projection of :math:`\mathcal N(\mathbf F)` onto the twist coordinates: the twists that some
    joint rates realise without slip (the null space of :func:`twist_constraints`).

    Parameters
    ----------
    robot : Robot
    beta : array (w,)
        Steering angles of one configuration.

    Returns
    -------
    numpy.ndarray (3, m)

    Examples
    --------
    >>> from wmr.robots import paper_robot
    >>> basis = admissible_twists(paper_robot("centred"), [0.0, 0.0, 0.0])   # axles along x
    >>> np.abs(basis.ravel()).round(12).tolist()                              # only y translation
    [0.0, 0.0, 1.0]
    """
    beta = V.finite_array("beta", beta, last=robot.w)
    if beta.ndim != 1:
        raise ValueError(f"beta must be one configuration of shape ({robot.w},) for admissible_twists, "
                         f"got shape {beta.shape}")
    A, _ = twist_constraints(robot, beta)
    if A.shape[0] == 0:
        return np.eye(3)
    return null_space(A)
