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
the bound is within ``KAPPA_ERROR eps kappa`` or :data:`ACCURACY`, and
:math:`\kappa < 1/(2\,\mathrm{TOL})` (the SVD rule of :func:`wmr.condition_number` would not call
it singular either).  :func:`kappa_by_lapack` does the same with LAPACK's eigenvalues, whose error
:math:`e + 8\epsilon\lambda_1` is not amplified.  Used by :func:`wmr.condition_number` (3x3) and by
:mod:`wmr.analysis.sweep.swerve_kappa`.
"""

from __future__ import annotations

import math

import numpy as np

from ..model.tolerance import TOL

__all__ = ["KAPPA_ERROR", "ACCURACY", "kappa_from_gram", "kappa_by_lapack"]

_EPS = np.finfo(float).eps
#: A 3x3 condition number from the closed form is kept when its computed error bound is at most
#: ``KAPPA_ERROR * eps * kappa`` (about the SVD's own accuracy); others go to the SVD.
KAPPA_ERROR = 16.0
#: the fused kernel of a drivable sweep (:mod:`wmr.analysis.sweep.swerve_kappa`) accepts a relative error bound
#: up to this, or the SVD's own if larger
ACCURACY = 1e-12
#: the entries of a symmetric 3 x 3 matrix, in the order of the rows of ``G``
UPPER = ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))
#: scratch vectors :func:`kappa_from_gram` needs
SCRATCH = 14
_SQRT3 = math.sqrt(3.0)
_MARGIN = 1.5  # on a first-order worst-case error bound


def kappa_from_gram(G, detG, det_rel, g_error, v, out, ok, bad, accuracy=ACCURACY):
    r""":math:`\kappa` from the upper entries of Gram matrices and their determinants, in place, with acceptance.

    Parameters
    ----------
    G : numpy.ndarray (6, k)
        Entries (0,0), (0,1), (0,2), (1,1), (1,2), (2,2) of each :math:`\mathbf G` (:data:`UPPER`).
    detG, det_rel : numpy.ndarray (k,)
        :math:`\det\mathbf G` and a bound of its relative error.
    g_error : float or numpy.ndarray (k,)
        A bound of the absolute rounding error of the entries' eigenvalues (``||dG||_F``).
    v : numpy.ndarray (SCRATCH, k)
        Scratch.
    out : numpy.ndarray (k,)
        Receives :math:`\kappa`.
    ok, bad : numpy.ndarray of bool (k,)
        ``ok`` receives the accepted members; ``bad`` is scratch.
    accuracy : float, optional
        A relative error bound accepted whatever ``KAPPA_ERROR eps kappa`` is (0: that rule alone).

    Returns
    -------
    numpy.ndarray (k,)
        :math:`\lambda_2` (a view of ``v``).
    """
    # the two largest eigenvalues of G (the trigonometric solution of its characteristic cubic)
    g00, g01, g02, g11, g12, g22 = G
    q, b00, b11, b22, p2, t, p, det_b = v[0:8]
    np.add(g00, g11, out=q)
    q += g22
    q /= 3.0
    np.subtract(g00, q, out=b00)
    np.subtract(g11, q, out=b11)
    np.subtract(g22, q, out=b22)
    np.multiply(g01, g01, out=p2)
    np.multiply(g02, g02, out=t)
    p2 += t
    np.multiply(g12, g12, out=t)
    p2 += t
    p2 += p2  # 2 (g01^2 + g02^2 + g12^2)
    np.multiply(b00, b00, out=t)
    p2 += t
    np.multiply(b11, b11, out=t)
    p2 += t
    np.multiply(b22, b22, out=t)
    p2 += t
    p2 /= 6.0  # tr B^2 / 6, B = G - q I
    np.sqrt(p2, out=p)
    np.multiply(b11, b22, out=det_b)  # det B by cofactors along the first row
    np.multiply(g12, g12, out=t)
    det_b -= t
    det_b *= b00
    u = v[8]
    np.multiply(g01, b22, out=t)
    np.multiply(g12, g02, out=u)
    t -= u
    t *= g01
    det_b -= t
    np.multiply(g01, g12, out=t)
    np.multiply(b11, g02, out=u)
    t -= u
    t *= g02
    det_b += t
    den = t
    np.multiply(p, p2, out=den)
    den += den
    np.maximum(den, 1e-300, out=den)
    r = det_b
    r /= den
    np.clip(r, -1.0, 1.0, out=r)  # r = det B / (2 p^3)
    # cos and sin of phi = arccos(r) / 3 in [0, pi/3], through tan(phi / 2)
    th, h, c = v[9], v[10], v[11]
    np.arccos(r, out=th)
    th /= 6.0
    np.tan(th, out=th)
    np.multiply(th, th, out=h)
    h += 1.0
    np.divide(2.0, h, out=h)
    np.subtract(h, 1.0, out=c)  # cos phi
    th *= h  # sin phi
    lam1, lam2 = v[12], v[13]
    np.multiply(p, c, out=lam1)
    lam1 += lam1
    lam1 += q  # q + 2 p cos(phi)
    th *= _SQRT3
    th -= c
    np.multiply(th, p, out=lam2)
    lam2 += q  # q + 2 p cos(phi - 2 pi / 3)
    kappa = out  # lam1 sqrt(lam2 / det G)
    np.divide(lam2, detG, out=kappa)
    np.sqrt(kappa, out=kappa)
    kappa *= lam1
    # the first-order error bound (module notes)
    E = r
    np.multiply(r, r, out=E)
    np.subtract(1.0, E, out=E)
    np.maximum(E, 1e-300, out=E)
    np.sqrt(E, out=E)
    np.divide(g_error, E, out=E)
    p += p
    np.minimum(E, p, out=E)
    E += g_error
    bound = h
    np.divide(1.0, lam1, out=bound)
    np.divide(1.0, lam2, out=u)
    bound += u
    bound *= E
    bound += det_rel
    bound *= _MARGIN / 2
    limit = u
    np.multiply(kappa, KAPPA_ERROR * _EPS, out=limit)
    np.maximum(limit, accuracy, out=limit)
    # a nan kappa (lam2 < 0 or det G < 0) makes the limit nan; lam2 = 0 makes the bound inf; det G = 0
    # makes kappa inf: none passes
    np.less_equal(bound, limit, out=ok)
    np.less(kappa, 0.5 / TOL, out=bad)  # sigma_3 > 2 TOL sigma_1: not singular by the SVD rule either
    ok &= bad
    return lam2


def kappa_by_lapack(G, detG, det_rel, g_error):
    """:func:`kappa_from_gram` with the eigenvalues of ``numpy.linalg.eigvalsh``: ``(kappa, ok)``.

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
