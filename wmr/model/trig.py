r"""Matrices linear in the cosines and sines of the steering angles, evaluated for many configurations.

Every steering-dependent matrix of the model is a constant plus a sum of wheel blocks
:math:`\mathbf R(\beta_i)\mathbf M_i = \cos\beta_i\,\mathbf M_i + \sin\beta_i\,\mathbf E\mathbf M_i` (11)
(:func:`wmr.model.platform.rotated`), placed in the matrix and multiplied by constants:
:math:`\mathbf J_2`, :math:`\mathbf F`, :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` and the twist
constraints of :mod:`wmr.analysis.mobility`.  Each entry of such a matrix depends on the angles
of a few units only (a unit touches its own rows or columns), so the sum is stored by its
non-zero terms (:class:`Terms`: which entry, which unit, the two coefficients) and
:func:`trig_combination` evaluates it for a batch of configurations.  The work and the memory
grow with the number of terms, never with (units x entries).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .checks import finite_array
from .types import ArrayLike, FloatArray, IntArray

__all__ = ["Terms", "trig_combination"]

#: Configurations per chunk of :func:`trig_combination` (its temporaries stay in cache).
CHUNK = 8192
#: At most this many result entries per chunk (large matrices of large robots: fewer configurations a chunk).
CHUNK_ENTRIES = 2**22


@dataclass(frozen=True)
class Terms:
    r"""A matrix :math:`\mathbf C + \sum_i(\cos\beta_i\,\mathbf P_i + \sin\beta_i\,\mathbf Q_i)` by its non-zero terms.

    Attributes
    ----------
    shape : tuple of int
        The shape of one matrix.
    entry : numpy.ndarray of int (k,)
        The flat (C-order) index of each term's entry.
    unit : numpy.ndarray of int (k,)
        The unit :math:`i` whose angle enters the term.
    p : numpy.ndarray (k,)
        The coefficient of :math:`\cos\beta_i`.
    q : numpy.ndarray (k,)
        The coefficient of :math:`\sin\beta_i`.
    const : numpy.ndarray (\*shape) or None
        The constant term :math:`\mathbf C` (None: zero).
    """

    shape: tuple[int, ...]
    entry: IntArray
    unit: IntArray
    p: FloatArray
    q: FloatArray
    const: FloatArray | None = None

    @classmethod
    def dense(cls, P: FloatArray, Q: FloatArray, const: FloatArray | None = None) -> Terms:
        r"""The terms of dense coefficients :math:`\mathbf P, \mathbf Q` (w, \*shape) (their non-zero entries).

        Parameters
        ----------
        P, Q : numpy.ndarray (w, \*shape)
            The coefficients of :math:`\cos\beta_i` and :math:`\sin\beta_i`.
        const : numpy.ndarray (\*shape), optional

        Returns
        -------
        Terms

        Examples
        --------
        >>> t = Terms.dense(np.array([[[1.0, 0.0]], [[0.0, 0.0]]]), np.array([[[0.0, 0.0]], [[0.0, 2.0]]]))
        >>> t.shape, t.entry.tolist(), t.unit.tolist()
        ((1, 2), [0, 1], [0, 1])
        """
        P, Q = np.asarray(P, dtype=float), np.asarray(Q, dtype=float)
        w = P.shape[0]
        Pf, Qf = P.reshape(w, -1), Q.reshape(w, -1)
        unit, entry = np.nonzero((Pf != 0.0) | (Qf != 0.0))
        return cls(P.shape[1:], entry, unit, Pf[unit, entry], Qf[unit, entry], const)


def trig_combination(beta: ArrayLike, terms: Terms) -> FloatArray:
    r"""Matrices linear in the cosines and sines of the angles, for a batch of configurations.

    :math:`\mathbf C + \sum_i(\cos\beta_i\,\mathbf P_i + \sin\beta_i\,\mathbf Q_i)`, from its
    non-zero terms (:class:`Terms`), over chunks of configurations, term by term
    (:func:`~wmr.model.platform.rotated` of its two coefficients), with no matrix product.

    Parameters
    ----------
    beta : numpy.ndarray (..., w)
        Finite angles.
    terms : Terms
        The matrix, :math:`\mathbf C` and the non-zero entries of :math:`\mathbf P_i, \mathbf Q_i`.

    Returns
    -------
    numpy.ndarray (..., \*terms.shape)

    Notes
    -----
    The result is laid out entry-major in memory (entry ``j`` of every matrix is one contiguous run), a
    view of an array ``(prod(shape), N)``, which the kernels of :mod:`wmr.analysis.linalg` read without a copy.

    Examples
    --------
    >>> P = np.array([[[1.0, 0.0]], [[0.0, 0.0]]]); Q = np.array([[[0.0, 0.0]], [[0.0, 2.0]]])
    >>> t = Terms.dense(P, Q, const=np.array([[0.5, 0.5]]))
    >>> trig_combination(np.array([[0.0, np.pi / 2]]), t).tolist()
    [[[1.5, 2.5]]]
    """
    return combine_checked(finite_array("beta", beta), terms)


def combine_checked(beta: FloatArray, terms: Terms) -> FloatArray:
    """:func:`trig_combination` of finite float angles (..., w) the caller checked (a robot's ``effective_beta``)."""
    w = beta.shape[-1]
    m = int(np.prod(terms.shape))
    flat = beta.reshape(-1, w)
    N = flat.shape[0]
    out = np.empty((m, N))  # entry-major: see trig_combination's Notes
    const = np.zeros(m) if terms.const is None else np.asarray(terms.const, dtype=float).reshape(m)
    used, unit = np.unique(terms.unit, return_inverse=True)  # only the angles that enter
    listed = list(zip(terms.entry.tolist(), unit.tolist(), terms.p.tolist(), terms.q.tolist()))
    k = max(1, min(CHUNK, CHUNK_ENTRIES // max(m, 1)))
    ct, st = np.empty((used.size, k)), np.empty((used.size, k))
    for a in range(0, N, k):
        z = min(a + k, N)
        angles = flat[a:z, used].T
        c, s = np.cos(angles, out=ct[:, : z - a]), np.sin(angles, out=st[:, : z - a])
        r = out[:, a:z]  # every update below is contiguous
        r[...] = const[:, None]
        for j, i, p, q in listed:  # (11): R(beta_i) M_i = cos M_i + sin E M_i
            r[j] += c[i] * p + s[i] * q
    return out.T.reshape(beta.shape[:-1] + terms.shape)
