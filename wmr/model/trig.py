r"""Matrices linear in the cosines and sines of the steering angles, evaluated for many configurations.

Every steering-dependent matrix of the model is a constant plus a sum of wheel blocks
:math:`\mathbf R(\beta_i)\mathbf M_i = \cos\beta_i\,\mathbf M_i + \sin\beta_i\,\mathbf E\mathbf M_i` (11)
(:func:`wmr.model.platform.rotated`), placed in the matrix and multiplied by constants:
:math:`\mathbf J_2`, :math:`\mathbf F`, :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` and the twist
constraints of :mod:`wmr.analysis.mobility`.  :func:`trig_combination` evaluates such a sum for a
batch of configurations.
"""

from __future__ import annotations

import numpy as np

from .platform import cos_sin, rotated
from .types import ArrayLike, FloatArray

__all__ = ["trig_combination"]

#: Configurations per chunk of :func:`trig_combination` (its temporaries stay in cache).
CHUNK = 8192


def trig_combination(beta: ArrayLike, P: FloatArray, Q: FloatArray, const: FloatArray | None = None) -> FloatArray:
    r"""Matrices linear in the cosines and sines of the angles.

    :math:`\mathbf C + \sum_i(\cos\beta_i\,\mathbf P_i + \sin\beta_i\,\mathbf Q_i)`.

    Every steering-dependent matrix of the model has this form, because each unit's block is
    :math:`\mathbf B_i(\beta_i) = \cos\beta_i\,\mathbf L_i + \sin\beta_i\,\mathbf E\mathbf L_i` (11):
    :math:`\mathbf J_2`, :math:`\mathbf F`, :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` and the
    twist constraints of :mod:`wmr.analysis.mobility` only place (and multiply by constants)
    the pairs :math:`(\mathbf L_i, \mathbf E\mathbf L_i)`.  This evaluates the sum for a batch,
    entry by entry over chunks of :data:`CHUNK` configurations, skipping the coefficients that
    are zero (most are: a unit touches only its own rows or columns), with no matrix product;
    each unit's term is :func:`~wmr.model.platform.rotated` of its coefficients.

    Parameters
    ----------
    beta : numpy.ndarray (..., w)
        Finite angles.
    P, Q : numpy.ndarray (w, \*shape)
        The coefficients of :math:`\cos\beta_i` and :math:`\sin\beta_i`.
    const : numpy.ndarray (\*shape), optional
        The constant term (default 0).

    Returns
    -------
    numpy.ndarray (..., \*shape)

    Notes
    -----
    The result is laid out entry-major in memory (its batch axes are the fastest: entry ``j`` of
    every matrix is one contiguous run), a view of an array ``(prod(shape), N)``.  Indexing and
    arithmetic see an ordinary array; the closed-form kernels of :mod:`wmr.analysis.linalg` read
    such stacks without copying them, and ``np.ascontiguousarray`` gives the usual layout.

    Examples
    --------
    >>> P = np.array([[[1.0, 0.0]], [[0.0, 0.0]]]); Q = np.array([[[0.0, 0.0]], [[0.0, 2.0]]])
    >>> trig_combination(np.array([[0.0, np.pi / 2]]), P, Q, const=np.array([[0.5, 0.5]])).tolist()
    [[[1.5, 2.5]]]
    """
    beta = np.asarray(beta, dtype=float)
    w = beta.shape[-1]
    shape = P.shape[1:]
    m = int(np.prod(shape))
    Pf, Qf = np.asarray(P, dtype=float).reshape(w, m), np.asarray(Q, dtype=float).reshape(w, m)
    flat = beta.reshape(-1, w)
    N = flat.shape[0]
    out = np.empty((m, N))  # entry-major: see Notes
    const = np.zeros(m) if const is None else np.asarray(const, dtype=float).reshape(m)
    # for each entry, the angles that enter it and their two coefficients (most pairs are zero:
    # a unit touches only its own rows or columns)
    terms = [[(i, Pf[i, j], Qf[i, j]) for i in range(w) if Pf[i, j] != 0.0 or Qf[i, j] != 0.0] for j in range(m)]
    ct, st = np.empty((w, CHUNK)), np.empty((w, CHUNK))
    for a in range(0, N, CHUNK):
        z = min(a + CHUNK, N)
        c, s = cos_sin(flat[a:z].T, out=(ct[:, : z - a], st[:, : z - a]))
        r = out[:, a:z]  # every update below is contiguous
        r[...] = const[:, None]
        for j, tj in enumerate(terms):
            for i, p, q in tj:  # (11): R(beta_i) M_i = cos M_i + sin E M_i
                r[j] += rotated((c[i], s[i]), p, q, axes=0)
    return out.T.reshape(beta.shape[:-1] + shape)
