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
from .platform import rotation
from .tolerance import TOL


def singular_values(A):
    """Singular values, descending, of a stack of matrices.

    Parameters
    ----------
    A : array (..., m, n)

    Returns
    -------
    numpy.ndarray (..., min(m, n))
    """
    A = np.asarray(A, dtype=float)
    if A.ndim < 2:
        raise ValueError(f"A must have shape (..., m, n), got shape {A.shape}")
    A = V.finite_array("A", A)
    if min(A.shape[-2:]) == 0:
        return np.zeros(A.shape[:-2] + (0,))
    return map_matrices(lambda X: np.linalg.svd(X, compute_uv=False), A)


def _rank_from_sv(s):
    if s.shape[-1] == 0:
        return np.zeros(s.shape[:-1], dtype=int)
    return np.sum(s > TOL * np.maximum(1.0, s[..., :1]), axis=-1)


def rank(A):
    """Numerical rank of a stack of matrices (singular values above ``TOL * max(1, s_max)``).

    Parameters
    ----------
    A : array (..., m, n)

    Returns
    -------
    numpy.ndarray of int (...)

    Examples
    --------
    >>> int(rank([[1.0, 2.0], [2.0, 4.0]]))
    1
    """
    return _rank_from_sv(singular_values(A))


def nullity(A):
    """Nullity ``n - rank(A)`` (27) of a stack of matrices ``(..., m, n)``."""
    A = np.asarray(A, dtype=float)
    return A.shape[-1] - rank(A)


def null_space(A):
    """Orthonormal basis of the null space of one matrix.

    Parameters
    ----------
    A : array (m, n)

    Returns
    -------
    numpy.ndarray (n, nullity)
    """
    A = V.finite_array("A", A)
    if A.ndim != 2:
        raise ValueError(f"null_space takes one matrix (m, n); got shape {A.shape} (loop over a batch yourself)")
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
    """
    beta = V.finite_array("beta", beta, last=robot.w)
    J1 = robot.J1()
    rows, base_rank = [], 0
    for i, u in enumerate(robot.wheels):
        L = u._local_block(NUMERIC)
        N = _left_null(L)                       # (2, k_i), constant
        base_rank += 2 - N.shape[1]             # rank L_i
        if N.shape[1] == 0:
            continue
        R = rotation(beta[..., i], NUMERIC)     # (..., 2, 2)
        # rows N_i^T R^T [E d_i 1]
        rows.append(np.swapaxes(R @ N, -1, -2) @ J1[2 * i:2 * i + 2])
    if not rows:
        return np.zeros(beta.shape[:-1] + (0, 3)), base_rank
    return np.concatenate(rows, axis=-2), base_rank


def rank_F(robot, beta):
    r"""Rank of the functional matrix :math:`\mathbf F(\boldsymbol\beta)` for a batch of configurations.

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)

    Returns
    -------
    numpy.ndarray of int (...)
    """
    A, base = twist_constraints(robot, beta)
    return base + rank(A)


def mobility(robot, beta):
    r"""Mobility :math:`\nu(\mathbf F) = (3 + n) - \operatorname{rank}\mathbf F` (27), batched.

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
    joint rates realise without slip.
    """
    beta = V.finite_array("beta", beta, last=robot.w)
    if beta.ndim != 1:
        raise ValueError(f"admissible_twists takes one configuration (w,), got shape {beta.shape}")
    A, _ = twist_constraints(robot, beta)
    if A.shape[0] == 0:
        return np.eye(3)
    return null_space(A)
