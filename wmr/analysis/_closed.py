r"""Closed forms for stacks of small matrices (at most three rows or columns), chunked on all cores.

The batched LAPACK routines spend about a microsecond per 3x3 matrix in call overhead; these
kernels evaluate the closed forms element-wise over a chunk of :data:`~wmr.analysis._batch.CHUNK`
matrices at a time (entry ``(i, j)`` of every matrix of the chunk is one strided vector).  Where a
closed form cannot vouch for its result (a nearly rank-deficient member, a condition number
whose computed error bound is too large) it says so, and :mod:`wmr.analysis.linalg` sends that
member to the SVD: every decision stays the SVD's.
"""

from __future__ import annotations

import numpy as np

from ..model.tolerance import TOL
from ._batch import for_chunks
from .gram_kappa import ACCURACY, KAPPA_ERROR, SCRATCH, UPPER, kappa_from_gram

__all__ = ["det", "certified_full_rank", "condition_number_3x3", "KAPPA_ERROR", "ACCURACY"]

_EPS = np.finfo(float).eps
_SAFE = (1e-100, 1e100)  # range of ||A||_F^2 where no product below over- or underflows


def _entries(A, a, b, scale=None):
    """Entries of matrices ``a .. b-1`` of a flat stack ``(N, m, n)``: ``e[i][j]`` has shape (b - a,).

    Every later operation reads contiguous memory: an entry-major stack (as :meth:`wmr.Robot.J`
    returns) is used as it is, any other layout is copied entry-major first.  With ``scale`` (n,),
    column j is divided by ``scale[j]`` on the way (no pass over the whole stack).
    """
    m, n = A.shape[1:]
    X = A[a:b].reshape(b - a, m * n).T
    if scale is not None:  # a new array (X may be a view of A)
        X = (X.reshape(m, n, b - a) / np.asarray(scale, dtype=float)[None, :, None]).reshape(m * n, b - a)
    elif X.strides[1] != X.itemsize:  # not entry-major (see wmr.model.trig): copy once
        X = np.ascontiguousarray(X)
    return [[X[i * n + j] for j in range(n)] for i in range(m)]


def _det_entries(e):
    p = len(e)
    if p == 1:
        return e[0][0].copy()
    if p == 2:
        return e[0][0] * e[1][1] - e[0][1] * e[1][0]
    (a0, a1, a2), (a3, a4, a5), (a6, a7, a8) = e
    # cofactor expansion along the first row
    return a0 * (a4 * a8 - a5 * a7) + a1 * (a5 * a6 - a3 * a8) + a2 * (a3 * a7 - a4 * a6)


def det(A):
    r"""Determinants (N,) of a flat stack ``A (N, p, p)``, ``1 <= p <= 3`` (cofactor expansion)."""
    out = np.empty(A.shape[0])

    def chunk(a, b):
        out[a:b] = _det_entries(_entries(A, a, b))

    for_chunks(chunk, A.shape[0])
    return out


def _dot(xs, ys):
    """sum_k xs[k] * ys[k] for lists of equal-length vectors."""
    out = xs[0] * ys[0]
    for x, y in zip(xs[1:], ys[1:]):
        out += x * y
    return out


def _gram_entries(e, rows):
    """Upper triangle of the Gram matrix of the rows (``rows=True``: A A^T) or of the columns."""
    vecs = e if rows else [list(col) for col in zip(*e)]
    p = len(vecs)
    return [[None if j < i else _dot(vecs[i], vecs[j]) for j in range(p)] for i in range(p)]


def certified_full_rank(A, scale=None):
    r"""Members (N,) of a flat stack ``A (N, m, n)``, ``p = min(m, n) <= 3``, whose rank is surely ``p``.

    With ``scale`` (n,), the test is made on the matrices with column j divided by ``scale[j]``.

    With :math:`f = \|\mathbf A\|_F^2 \ge \sigma_{max}^2` and :math:`D = \prod_k\sigma_k` (for a
    square matrix :math:`|\det\mathbf A|`, otherwise :math:`\sqrt{\det\mathbf G}` with the
    :math:`p\times p` Gram matrix :math:`\mathbf G`), the smallest singular value satisfies
    :math:`\sigma_{min} \ge D / f^{(p-1)/2}`.  A member is certified when this lower bound, less a
    generous bound on the rounding error of the determinant, exceeds
    :math:`2\,\mathrm{TOL}\sqrt f`: then the SVD rule of :func:`wmr.analysis.linalg.rank`
    gives rank ``p`` as well (its own rounding is far below the factor 2), so the certificate
    changes no result.  The others are left to the SVD.
    """
    N, m, n = A.shape
    p = min(m, n)
    out = np.empty(N, dtype=bool)

    def chunk(a, b):
        e = _entries(A, a, b, scale)
        with np.errstate(over="ignore", invalid="ignore", under="ignore"):
            f = _dot([x for row in e for x in row], [x for row in e for x in row])
            if m == n:
                D = np.abs(_det_entries(e))
                err = (10 * p + 100) * _EPS * f ** (p / 2)  # >> rounding of det A
                ok = (D - err) > 2 * TOL * np.sqrt(f) * f ** ((p - 1) / 2)
            else:
                g = _gram_entries(e, rows=m < n)
                G = [[g[min(i, j)][max(i, j)] for j in range(p)] for i in range(p)]
                err = (10 * (m + n) + 100) * _EPS * f**p  # >> rounding of G and det G
                ok = (_det_entries(G) - err) > (2 * TOL) ** 2 * f * f ** (p - 1)
            out[a:b] = ok & np.isfinite(f) & (f > 0)

    for_chunks(chunk, N)
    return out


def condition_number_3x3(A):
    r"""Condition numbers of a flat stack of 3x3 matrices from the eigenvalues of :math:`\mathbf A^T\mathbf A`.

    The eigenvalues :math:`\lambda_1\ge\lambda_2\ge\lambda_3` of :math:`\mathbf G = \mathbf A^T\mathbf A`
    are the squared singular values, and they solve a cubic.  With :math:`q = \operatorname{tr}\mathbf G/3`,
    :math:`\mathbf B = \mathbf G - q\mathbf I`, :math:`p = \sqrt{\operatorname{tr}\mathbf B^2/6}` and
    :math:`r = \det\mathbf B/(2p^3)\in[-1, 1]`, the trigonometric solution is

    .. math:: \lambda_k = q + 2p\cos\Big(\phi + \frac{2\pi j_k}{3}\Big),\qquad
              \phi = \tfrac13\arccos r,\quad j_1 = 0,\ j_3 = 1,\ \lambda_2 = 3q - \lambda_1 - \lambda_3 .

    :math:`\lambda_1` and :math:`\lambda_2` come from it; the smallest one, which the formula
    gives only to an absolute accuracy :math:`\sim\epsilon q`, comes from the determinant instead,
    :math:`\lambda_3 = (\det\mathbf A)^2/(\lambda_1\lambda_2)`, so that

    .. math:: \kappa = \sqrt{\lambda_1/\lambda_3} = \frac{\lambda_1\sqrt{\lambda_2}}{|\det\mathbf A|}.

    Its relative error is bounded, to first order, by
    :math:`e = \tfrac12 E(1/\lambda_1 + 1/\lambda_2) + \epsilon\,\operatorname{per}|\mathbf A|/|\det\mathbf A|`
    with :math:`E = \epsilon q + \min(2p,\ \epsilon q/\sqrt{1 - r^2})` (the rounding of
    :math:`\mathbf G`, amplified where two eigenvalues nearly coincide) and the permanent of
    :math:`|\mathbf A|` (the rounding of the determinant).  The eigenvalues, the bound and the first two
    tests are those of :func:`~wmr.analysis.gram_kappa.kappa_from_gram` (the kernel of the drivable sweep too: the formula is
    written once), with :math:`\det\mathbf G = (\det\mathbf A)^2`.  A member is **accepted** when
    :math:`1.5e \le` :data:`KAPPA_ERROR` :math:`\epsilon\kappa` (the margin covers the bound's
    first-order neglect; measured errors stay below half of ``e``), when
    :math:`\sigma_3 = \sigma_1/\kappa > 2\,\mathrm{TOL}\,\sigma_1` (so the SVD rule
    would not call it singular either) and when :math:`\|\mathbf A\|_F^2` lies where nothing
    over- or underflows.  Returns ``kappa (N,)`` (anything where not accepted) and ``accepted (N,)``.
    """
    N = A.shape[0]
    kappa = np.empty(N)
    accepted = np.empty(N, dtype=bool)

    def chunk(a, b):
        e = _entries(A, a, b)
        with np.errstate(all="ignore"):
            kappa[a:b], accepted[a:b] = _kappa_entries(e)

    for_chunks(chunk, N)
    return kappa, accepted


def _kappa_entries(e):
    (a0, a1, a2), (a3, a4, a5), (a6, a7, a8) = e
    g = _gram_entries(e, rows=False)  # G = A^T A, upper triangle
    G = np.stack([g[j][k] for j, k in UPPER])
    f = G[0] + G[3] + G[5]  # ||A||_F^2 = tr G
    # det A by cofactors, and the permanent of |A| from the same products (its rounding bound)
    x48, x57, x56, x38, x37, x46 = a4 * a8, a5 * a7, a5 * a6, a3 * a8, a3 * a7, a4 * a6
    absD = np.abs(a0 * (x48 - x57) + a1 * (x56 - x38) + a2 * (x37 - x46))
    per = (
        np.abs(a0) * (np.abs(x48) + np.abs(x57))
        + np.abs(a1) * (np.abs(x56) + np.abs(x38))
        + np.abs(a2) * (np.abs(x37) + np.abs(x46))
    )
    k = absD.size
    kappa, ok, bad = np.empty(k), np.empty(k, dtype=bool), np.empty(k, dtype=bool)
    # lam3 = det G / (lam1 lam2), det G = (det A)^2 with twice det A's relative error; G's entries to eps tr G / 3
    lam2 = kappa_from_gram(
        G, absD * absD, 2 * _EPS * per / absD, _EPS * f / 3, np.empty((SCRATCH, k)), kappa, ok, bad, 0.0
    )
    ok &= (f > _SAFE[0]) & (f < _SAFE[1]) & (lam2 > 0) & np.isfinite(kappa)
    return kappa, ok
