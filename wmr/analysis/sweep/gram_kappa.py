r"""The condition number of a 3-row matrix from its Gram matrix :math:`\mathbf G` and :math:`\det\mathbf G`, certified.

With :math:`q = \operatorname{tr}\mathbf G/3`, :math:`\mathbf B = \mathbf G - q\mathbf I`,
:math:`p = \sqrt{\operatorname{tr}\mathbf B^2/6}` and :math:`r = \det\mathbf B/(2p^3)`, the two
largest eigenvalues are :math:`\lambda_1 = q + 2p\cos\phi`, :math:`\lambda_2 = q + 2p\cos(\phi - 2\pi/3)`,
:math:`\phi = \tfrac13\arccos r` (:func:`wmr.analysis._closed.condition_number_3x3`), and
:math:`\kappa = \sqrt{\lambda_1/\lambda_3} = \lambda_1\sqrt{\lambda_2/\det\mathbf G}` with
:math:`\det\mathbf G` given to a known relative accuracy (Cauchy-Binet, by the caller).

The first-order error bound of :math:`\kappa` is
:math:`\tfrac12E(1/\lambda_1 + 1/\lambda_2) + \tfrac12\delta_{\det}`, where the eigenvalues' error
:math:`E = e + \min(2p,\ e/\sqrt{1 - r^2})` is the rounding :math:`e` of :math:`\mathbf G` amplified where
two eigenvalues nearly meet (the arccos is ill-conditioned at :math:`r = \pm1`).  Every part is a
worst-case bound, so a margin of 1.5 covers the neglected second order.  A member is accepted when
the bound is within ``KAPPA_ERROR eps kappa`` or :data:`~wmr.analysis._closed.ACCURACY`, and
:math:`\kappa < 1/(2\,\mathrm{TOL})` (the SVD rule of :func:`wmr.condition_number` would not call
it singular either).  :func:`kappa_by_lapack` does the same with LAPACK's eigenvalues, whose error
:math:`e + 8\epsilon\lambda_1` is not amplified.

The in-place kernel :func:`~wmr.analysis._closed.kappa_from_gram` (with
:data:`~wmr.analysis._closed.UPPER` and :data:`~wmr.analysis._closed.SCRATCH`) is defined in
:mod:`wmr.analysis._closed`, where the 3x3 condition number of :func:`wmr.condition_number` uses it
too, and is re-exported here.
"""

from __future__ import annotations

import numpy as np

from ...model.tolerance import TOL
from .._closed import ACCURACY, KAPPA_ERROR, SCRATCH, UPPER, kappa_from_gram

__all__ = ["UPPER", "SCRATCH", "kappa_from_gram", "kappa_by_lapack"]

_EPS = np.finfo(float).eps
_MARGIN = 1.5  # on a first-order worst-case error bound (as in kappa_from_gram)


def kappa_by_lapack(G, detG, det_rel, g_error):
    """:func:`~wmr.analysis._closed.kappa_from_gram` with the eigenvalues of ``numpy.linalg.eigvalsh``: ``(kappa, ok)``.

    Parameters
    ----------
    G : numpy.ndarray (6, k)
    detG, det_rel : numpy.ndarray (k,)
    g_error : float

    Returns
    -------
    kappa : numpy.ndarray (k,)
    ok : numpy.ndarray of bool (k,)
    """
    A = np.empty((G.shape[1], 3, 3))
    for m, (j, k) in enumerate(UPPER):
        A[:, j, k] = A[:, k, j] = G[m]
    with np.errstate(all="ignore"):
        lam = np.linalg.eigvalsh(A)
        lam1, lam2 = lam[:, 2], lam[:, 1]
        kappa = lam1 * np.sqrt(lam2 / detG)
        bound = (_MARGIN / 2) * ((g_error + 8 * _EPS * lam1) * (1.0 / lam1 + 1.0 / lam2) + det_rel)
        ok = (bound <= np.maximum(kappa * (KAPPA_ERROR * _EPS), ACCURACY)) & (kappa * (2 * TOL) < 1.0)
        ok &= (lam2 > 0) & np.isfinite(kappa)
    return kappa, ok
