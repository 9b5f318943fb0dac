r"""Cosine and sine of many steering angles at once, and the matrices that are linear in them.

Every batched kernel starts from :math:`\cos\beta_i` and :math:`\sin\beta_i` (the rotation
:math:`\mathbf R(\beta) = \cos\beta\,\mathbf I + \sin\beta\,\mathbf E` of (11)).  NumPy evaluates
``np.cos`` and ``np.sin`` of float64 arrays one element at a time (about 12 ns each on the
reference machine) but ``np.tan`` with SIMD (about 1.4 ns), so :func:`cos_sin` uses the half-angle
tangent :math:`t = \tan(\beta/2)`:

.. math:: \cos\beta = \frac{2}{1 + t^2} - 1,\qquad \sin\beta = \frac{2t}{1 + t^2}.

Both are within one unit in the last place of 1 of the exact values (an absolute error of
:math:`2.2\times10^{-16}`, the size of the rounding of :math:`\beta` itself), which is all the
kernels need; exact at :math:`\beta = 0`, :math:`\pm\pi` gives :math:`\cos = -1` and the float
:math:`\sin\pi`.  Symbolic work uses SymPy's ``cos`` and ``sin`` (:mod:`wmr.model.backend`).
"""
from __future__ import annotations

import numpy as np

__all__ = ["cos_sin", "trig_combination"]

#: Configurations per chunk of :func:`trig_combination` (its temporaries stay in cache).
CHUNK = 8192


def cos_sin(beta, out=None):
    r""":math:`(\cos\beta, \sin\beta)` of an array of angles, from :math:`\tan(\beta/2)`.

    Parameters
    ----------
    beta : numpy.ndarray (...)
        Finite angles in radians.
    out : tuple of two numpy.ndarray (...), optional
        Arrays to write the cosines and sines into.

    Returns
    -------
    c, s : numpy.ndarray (...)

    Examples
    --------
    >>> c, s = cos_sin(np.array([0.0, np.pi / 3, -np.pi]))
    >>> bool(np.allclose(c, [1.0, 0.5, -1.0], rtol=0, atol=3e-16)), bool(np.allclose(s, np.sin([0.0, np.pi / 3, -np.pi]), rtol=0, atol=3e-16))
    (True, True)
    """
    t = np.multiply(beta, 0.5)
    np.tan(t, out=t)
    h = np.multiply(t, t)
    h += 1.0
    np.divide(2.0, h, out=h)                       # h = 2 / (1 + t^2)
    if out is None:
        out = (np.empty_like(h), np.empty_like(h))
    c, s = out
    np.subtract(h, 1.0, out=c)
    np.multiply(t, h, out=s)
    return c, s


def trig_combination(beta, P, Q, const=None):
    r"""Matrices linear in the cosines and sines of the angles: :math:`\mathbf C + \sum_i(\cos\beta_i\,\mathbf P_i + \sin\beta_i\,\mathbf Q_i)`.

    Every steering-dependent matrix of the model has this form, because each unit's block is
    :math:`\mathbf B_i(\beta_i) = \cos\beta_i\,\mathbf L_i + \sin\beta_i\,\mathbf E\mathbf L_i` (11):
    :math:`\mathbf J_2`, :math:`\mathbf F`, :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` and the
    twist constraints of :mod:`wmr.analysis.mobility` only place (and multiply by constants)
    the pairs :math:`(\mathbf L_i, \mathbf E\mathbf L_i)`.  This evaluates the sum for a batch,
    entry by entry over chunks of :data:`CHUNK` configurations, skipping the coefficients that
    are zero (most are: a unit touches only its own rows or columns), with no matrix product.

    Parameters
    ----------
    beta : numpy.ndarray (..., w)
        Finite angles.
    P, Q : numpy.ndarray (w, *shape)
        The coefficients of :math:`\cos\beta_i` and :math:`\sin\beta_i`.
    const : numpy.ndarray (*shape), optional
        The constant term (default 0).

    Returns
    -------
    numpy.ndarray (..., *shape)

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
    out = np.empty((N, m))
    out[...] = 0.0 if const is None else np.asarray(const, dtype=float).reshape(m)
    # for each entry j, the angles that enter it and their two coefficients
    terms = [[(i, Pf[i, j], Qf[i, j]) for i in range(w) if Pf[i, j] != 0.0 or Qf[i, j] != 0.0] for j in range(m)]
    ct, st = np.empty((w, CHUNK)), np.empty((w, CHUNK))
    for a in range(0, N, CHUNK):
        z = min(a + CHUNK, N)
        c, s = cos_sin(flat[a:z].T, out=(ct[:, :z - a], st[:, :z - a]))
        for j, tj in enumerate(terms):
            col = out[a:z, j]
            for i, p, q in tj:
                if p != 0.0:
                    col += p * c[i]
                if q != 0.0:
                    col += q * s[i]
    return out.reshape(beta.shape[:-1] + shape)
