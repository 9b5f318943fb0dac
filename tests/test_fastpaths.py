"""Every fast path against the dense reference (wmr.analysis.reference), on random, singular and
nearly singular members; the closed forms against 40-digit arithmetic where the SVD is not exact enough."""
import mpmath
import numpy as np
import pytest

import wmr
from wmr.analysis import _closed
from wmr.analysis import linalg as LA
from wmr.analysis import reference as R
from wmr.model.tolerance import TOL

EPS = np.finfo(float).eps


def _with_singular_values(s, seed):
    """Matrices U diag(s) V^T with random orthogonal U, V (one per row of s)."""
    rng = np.random.default_rng(seed)
    n = len(s)
    U, _ = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    V, _ = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    return (U * np.asarray(s)[:, None, :]) @ V


def _singular_values(kind, n, rng):
    one = np.ones(n)
    return {
        "random": rng.uniform(0.1, 1.0, (n, 3)),
        "graded": np.stack([one, 10 ** rng.uniform(-3, 0, n), 10 ** rng.uniform(-12, 0, n)], -1),
        "near-isotropic": 1 + 10 ** rng.uniform(-16, -6, (n, 3)),
        "isotropic": np.ones((n, 3)),
        "double-smallest": np.stack([one, np.full(n, 1e-2), 1e-2 * (1 + 10 ** rng.uniform(-16, -4, n))], -1),
        "double-largest": np.stack([one, 1 + 10 ** rng.uniform(-16, -4, n), 10 ** rng.uniform(-4, 0, n)], -1),
        "rank-2": np.stack([one, rng.uniform(0, 1, n), np.zeros(n)], -1),
        "near-threshold": np.stack([one, one, TOL * rng.uniform(0.5, 4.0, n)], -1),
    }[kind]


def _kappa_exact(A):
    """sigma_max / sigma_min in 40-digit arithmetic."""
    with mpmath.workdps(40):
        out = []
        for M in A:
            s = mpmath.svd_r(mpmath.matrix(M.tolist()), compute_uv=False)
            out.append(float(max(s) / min(s)) if min(s) > 0 else np.inf)
    return np.array(out)


# -------------------------------------------------------------------------------------- det
@pytest.mark.parametrize("n", [1, 2, 3, 4])
@pytest.mark.parametrize("batch", [(), (7,), (3, 5)])
def test_det_equals_lu(n, batch):
    A = np.random.default_rng(n).normal(size=batch + (n, n))
    got = LA.det(A)
    assert got.shape == batch
    assert np.allclose(got, np.linalg.det(A), rtol=1e-12, atol=1e-14)


def test_det_singular_members_and_the_paper_robot():
    A = np.random.default_rng(0).normal(size=(1000, 3, 3))
    A[::3, 2] = A[::3, 0] - 2 * A[::3, 1]                       # exact linear dependence (up to rounding)
    A[1::3, :, 1] = 0.0                                          # a zero column: det exactly 0
    got = LA.det(A)
    assert np.all(got[1::3] == 0.0)
    assert np.allclose(got, np.linalg.det(A), rtol=1e-11, atol=1e-13)
    bot = wmr.paper_robot("centred", L=0.3, r=0.05)
    beta = np.random.default_rng(1).uniform(-np.pi, np.pi, (5000, 3))
    beta[:100] = 0.7                                             # all wheels parallel: singular
    J = bot.J(beta, L=0.3)
    got, want = LA.det(J), R.det(R.J(bot, beta, 0.3))
    assert np.allclose(got, want, rtol=1e-12, atol=1e-18) and np.all(np.abs(got[:100]) < 1e-17)


def test_det_rejects_non_square():
    with pytest.raises(ValueError, match="square"):
        LA.det(np.ones((4, 2, 3)))


# ------------------------------------------------------------------------------ rank (certified)
@pytest.mark.parametrize("shape", [(3, 3), (6, 3), (3, 6), (2, 5), (4, 1)])
def test_certified_rank_equals_svd_rank(shape):
    rng = np.random.default_rng(sum(shape))
    A = rng.normal(size=(3000,) + shape)
    p = min(shape)
    if shape[0] < shape[1]:
        A[::4, -1, :] = 0.0                                      # rank-deficient members (a zero row)
    else:
        A[::4, ..., -1] = 0.0                                    # rank-deficient members (a zero column)
    A[1::4] *= 10.0 ** rng.uniform(-12, 12, (750, 1, 1))         # all scales, absolute part of the rule
    if p > 1:
        A[2::4, :, 0] = A[2::4, :, 1] * (1 + TOL * rng.uniform(0.5, 3, (750, 1)))   # nearly dependent
    assert np.array_equal(LA.rank(A), R.rank(A))
    ok = _closed.certified_full_rank(A.reshape((-1,) + shape))
    assert ok.any() and not ok.all()                             # both paths ran
    assert np.all(R.rank(A)[ok] == p)                            # a certificate is never wrong


# ------------------------------------------------------------------------------ kappa 3x3
@pytest.mark.parametrize("scale", [1e-40, 1e-3, 1.0, 1e5])
@pytest.mark.parametrize("kind", ["random", "graded", "near-isotropic", "isotropic", "double-smallest",
                                  "double-largest", "rank-2", "near-threshold"])
def test_kappa_3x3_agrees_with_svd(kind, scale):
    """Same infs as the SVD rule; finite values within the sum of both methods' errors."""
    rng = np.random.default_rng(len(kind))
    A = scale * _with_singular_values(_singular_values(kind, 2000, rng), len(kind))
    got, want = LA.condition_number(A), R.condition_number(A)
    assert np.array_equal(np.isinf(got), np.isinf(want))
    fin = np.isfinite(want)
    # the closed form is kept within 16 eps kappa of the truth; LAPACK's own error is a few eps kappa,
    # up to ~50 eps near isotropy (measured against 40 digits in the next test)
    assert np.all(np.abs(got[fin] / want[fin] - 1) <= 64 * EPS * want[fin])


@pytest.mark.parametrize("kind", ["random", "graded", "near-isotropic", "double-smallest", "double-largest"])
def test_kappa_3x3_closed_form_error_bound_holds(kind):
    """Where the closed form is accepted, its error against 40-digit arithmetic is within its bound."""
    rng = np.random.default_rng(100 + len(kind))
    A = _with_singular_values(_singular_values(kind, 400, rng), 100 + len(kind))
    kappa, accepted = _closed.condition_number_3x3(A)
    exact = _kappa_exact(A)
    err = np.abs(kappa[accepted] / exact[accepted] - 1)
    assert np.all(err <= _closed.KAPPA_ERROR * EPS * exact[accepted])


def test_kappa_3x3_takes_the_closed_form_on_the_paper_robot():
    bot = wmr.paper_robot("centred", L=0.3, r=0.05)
    beta = np.random.default_rng(2).uniform(-np.pi, np.pi, (20000, 3))
    J = bot.J(beta, L=0.3)
    kappa, accepted = _closed.condition_number_3x3(J)
    assert accepted.mean() > 0.98                                # the SVD is the exception
    want = R.condition_number(R.J(bot, beta, 0.3))
    got = LA.condition_number(J)
    fin = np.isfinite(want)
    assert np.array_equal(np.isinf(got), ~fin)
    assert np.all(np.abs(got[fin] / want[fin] - 1) <= 32 * EPS * want[fin])
    assert np.array_equal(wmr.is_isotropic(J), np.abs(want - 1) <= TOL)
