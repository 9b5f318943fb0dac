r"""Kinetostatic isotropy: condition numbers (30)-(31) and isotropy tests (34)-(50).

The condition number :math:`\kappa = \sigma_l / \sigma_s` (30) of an :math:`m\times n` matrix lies in
:math:`[1, \infty]` (31); a matrix is isotropic when :math:`\kappa = 1`, i.e. when
:math:`\mathbf A^T\mathbf A` (for :math:`m\ge n`) or :math:`\mathbf A\mathbf A^T` (for :math:`m<n`) is a
multiple of the identity.
"""
from __future__ import annotations

import numpy as np

from . import _validate as V
from ._batch import map_matrices
from .mobility import _as_stack, singular_values
from .tolerance import TOL


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
    if A.shape[-2:] == (3, 3):
        return map_matrices(_kappa_3x3, A, chunk=8192)
    return _kappa_from_sv(singular_values(A))


def _kappa_from_sv(s):
    smax, smin = s[..., 0], s[..., -1]
    singular = smin <= TOL * np.maximum(1.0, smax)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(singular, np.inf, smax / np.where(singular, 1.0, smin))


#: Jacobi sweeps of :func:`_kappa_3x3` (3x3 symmetric Jacobi converges quadratically: 4 reach round-off)
_SWEEPS = 4
#: members with kappa above this (or with sigma_2 < sigma_1 / 10) are left to the SVD
_KAPPA_FAST_MAX = 1e4


def _kappa_3x3(A):
    r"""Condition numbers of a stack ``(k, 3, 3)``: the fast path of :func:`condition_number`.

    :math:`\sigma_1 \ge \sigma_2` come from the eigenvalues of :math:`\mathbf G = \mathbf A^T\mathbf A` by
    cyclic Jacobi rotations (vectorised over the stack; orthogonal transformations, so the
    eigenvalues are accurate to round-off relative to :math:`\sigma_1^2` even when two are close),
    and :math:`\sigma_3 = |\det\mathbf A| / (\sigma_1\sigma_2)`.  This is as accurate as the SVD
    when :math:`\sigma_2` is not small compared with :math:`\sigma_1` and :math:`\kappa` is moderate;
    the other members (nearly rank-deficient ones, those near the TOL threshold, any that did
    not converge) are computed by the SVD, so the rank decisions are the SVD's.
    """
    a = [[np.ascontiguousarray(A[:, i, j]) for j in range(3)] for i in range(3)]
    scale = np.abs(a[0][0])
    for row in a:
        for x in row:
            np.maximum(scale, np.abs(x), out=scale)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / scale                              # kappa is scale-free: work with max |a_ij| = 1
        a = [[x * inv for x in row] for row in a]      # (zero matrices give nan: left to the SVD)
    g = {(p, q): a[0][p] * a[0][q] + a[1][p] * a[1][q] + a[2][p] * a[2][q]
         for p in range(3) for q in range(p, 3)}                          # G = A^T A
    d = [g[0, 0], g[1, 1], g[2, 2]]
    off = {(0, 1): g[0, 1], (0, 2): g[0, 2], (1, 2): g[1, 2]}
    for _ in range(_SWEEPS):
        for p, q in ((0, 1), (0, 2), (1, 2)):
            r = 3 - p - q
            apq = off[p, q]
            diff = d[q] - d[p]
            den = np.abs(diff) + np.hypot(diff, 2.0 * apq)
            den[den == 0.0] = 1.0                                         # apq = 0 and diff = 0
            t = 2.0 * apq * np.copysign(1.0, diff) / den                  # tan of the Jacobi angle
            c = 1.0 / np.sqrt(1.0 + t * t)
            s = t * c
            d[p] = d[p] - t * apq
            d[q] = d[q] + t * apq
            off[p, q] = np.zeros_like(apq)
            kp, kq = (min(r, p), max(r, p)), (min(r, q), max(r, q))
            arp, arq = off[kp], off[kq]
            off[kp] = c * arp - s * arq
            off[kq] = s * arp + c * arq
    lam1 = np.maximum(np.maximum(d[0], d[1]), d[2])
    lam3 = np.minimum(np.minimum(d[0], d[1]), d[2])
    lam2 = d[0] + d[1] + d[2] - lam1 - lam3
    rest = np.maximum(np.maximum(np.abs(off[0, 1]), np.abs(off[0, 2])), np.abs(off[1, 2]))
    det = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
           - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
           + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        s1, s2 = np.sqrt(lam1), np.sqrt(np.maximum(lam2, 0.0))
        kappa = s1 * s1 * s2 / np.abs(det)                                 # s1 / s3, s3 = |det| / (s1 s2)
        s1_true = scale * s1
        s3_true = s1_true / kappa
        ok = ((rest <= np.finfo(float).eps * lam1) & (lam2 >= 1e-2 * lam1) & (kappa <= _KAPPA_FAST_MAX)
              & np.isfinite(kappa) & np.isfinite(scale) & (scale > 0)
              & (s3_true > 2 * TOL * np.maximum(1.0, s1_true)))              # clearly not singular
    if not np.all(ok):
        kappa = np.where(ok, kappa, 0.0)
        kappa[~ok] = _kappa_from_sv(np.linalg.svd(A[~ok], compute_uv=False))
    return kappa


def is_isotropic(A):
    """True where the condition number equals 1 within ``TOL`` (batched).

    Parameters
    ----------
    A : array_like (..., m, n)

    Returns
    -------
    numpy.ndarray of bool (...)

    Examples
    --------
    >>> is_isotropic([[[2.0, 0.0], [0.0, 2.0]], [[2.0, 0.0], [0.0, 1.0]]]).tolist()
    [True, False]
    """
    return np.abs(condition_number(A) - 1.0) <= TOL


def characteristic_length(robot):
    r"""The characteristic length :math:`L` that makes :math:`\mathbf J_{L1}` best conditioned when C is the centroid.

    With :math:`\sum_i\mathbf d_i = \mathbf 0`, (34) is :math:`\mathrm{diag}(\sum_i\|\mathbf d_i\|^2/L^2,\ w,\ w)`,
    which is isotropic exactly for :math:`L^2 = \tfrac1w\sum_i\|\mathbf d_i\|^2` (the mean, not
    necessarily equal, squared distance).

    Parameters
    ----------
    robot : Robot
        A numeric robot.

    Returns
    -------
    float

    Raises
    ------
    ValueError
        If every mount point is at C.

    Examples
    --------
    >>> from wmr import Robot, CentredWheel
    >>> bot = Robot([CentredWheel(p, r=0.1) for p in [(2.0, 0.0), (-1.0, 1.0), (-1.0, -1.0)]])
    >>> round(characteristic_length(bot) ** 2, 12)        # 8/3: a scalene triangle is isotropic too
    2.666666666667
    """
    d = robot.mount_points
    L = float(np.sqrt(np.mean(np.sum(d ** 2, axis=1))))
    if L == 0:
        raise ValueError("all mount points coincide with C: no characteristic length exists (got L = 0)")
    return L


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
