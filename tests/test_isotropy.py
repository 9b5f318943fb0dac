"""wmr.analysis.isotropy: condition numbers (30)-(31), isotropy of J_L1 (34)-(38) and of the offset robot's J."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import wmr
from wmr.analysis import isotropy as I
from wmr.analysis import linalg as LA
from wmr.model.tolerance import TOL

from conftest import robots, seeds


@pytest.mark.parametrize(
    "A, kappa",
    [
        (np.diag([2.0, 1.0]), 2.0),
        (np.diag([3.0, -3.0, 3.0]), 1.0),
        ([[1.0, 0.0, 0.0], [0.0, 4.0, 0.0]], 4.0),  # m < n
        (np.ones((4, 1)), 1.0),
        ([[1.0, 2.0], [2.0, 4.0]], np.inf),  # singular
        (np.zeros((3, 3)), np.inf),
        (np.diag([1.0, 1e-11]), np.inf),  # below TOL * sigma_max
        (np.diag([1.0, 1e-8]), 1e8),
    ],
)
def test_condition_number_known_values(A, kappa):
    assert np.isclose(float(LA.condition_number(A)), kappa, rtol=1e-12) or (
        np.isinf(kappa) and np.isinf(LA.condition_number(A))
    )


@pytest.mark.parametrize("shape", [(3, 3), (5, 3, 3), (2, 4, 6, 3), (7, 3, 6)])
def test_condition_number_batched(shape):
    A = np.random.default_rng(0).normal(size=shape)
    k = LA.condition_number(A)
    s = np.linalg.svd(A, compute_uv=False)
    assert k.shape == shape[:-2]
    assert np.allclose(k, s[..., 0] / s[..., -1], rtol=1e-12)
    assert np.all(k >= 1.0)  # (31)


def _kappa_svd(A):
    s = np.linalg.svd(A, compute_uv=False)
    singular = s[..., -1] <= TOL * s[..., 0]  # relative: the same in every unit
    with np.errstate(divide="ignore"):
        return np.where(singular, np.inf, s[..., 0] / s[..., -1])


@pytest.mark.parametrize("scale", [1e-160, 1e-9, 1e-3, 1.0, 1e4, 1e160])
@pytest.mark.parametrize("kind", ["random", "graded", "rank2", "rank1", "isotropic", "near-threshold"])
def test_3x3_fast_path_matches_svd(scale, kind):
    """The 3x3 kernel (Jacobi on the Gram matrix) gives the SVD's kappa to ~eps * kappa, same infs."""
    rng = np.random.default_rng(sum(map(ord, kind)))
    n = 500
    U, _ = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    V, _ = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    s = {
        "random": rng.uniform(0.1, 1.0, (n, 3)),
        "graded": np.stack([np.ones(n), 10 ** rng.uniform(-3, 0, n), 10 ** rng.uniform(-12, 0, n)], -1),
        "rank2": np.stack([np.ones(n), rng.uniform(0, 1, n), np.zeros(n)], -1),
        "rank1": np.stack([np.ones(n), np.zeros(n), np.zeros(n)], -1),
        "isotropic": np.ones((n, 3)),
        "near-threshold": np.stack([np.ones(n), np.ones(n), TOL * rng.uniform(0.5, 2.0, n)], -1),
    }[kind]
    A = scale * (U * s[:, None, :]) @ V
    got, want = LA.condition_number(A), _kappa_svd(A)
    assert np.array_equal(np.isinf(got), np.isinf(want))
    fin = np.isfinite(want)
    assert np.all(np.abs(got[fin] / want[fin] - 1) <= 20 * np.finfo(float).eps * want[fin])


def test_3x3_fast_path_on_the_paper_robot():
    bot = wmr.paper_robot("centred", L=0.3, r=0.05)
    beta = np.random.default_rng(11).uniform(-np.pi, np.pi, (20000, 3))
    J = bot.J(beta, L=0.3)
    got, want = LA.condition_number(J), _kappa_svd(J)
    fin = np.isfinite(want)
    assert np.array_equal(np.isinf(got), np.isinf(want))
    assert np.all(np.abs(got[fin] / want[fin] - 1) <= 20 * np.finfo(float).eps * want[fin])
    # the batch size does not change the result (chunking and threads)
    assert np.array_equal(LA.condition_number(J[:7]), got[:7])


@given(seeds, st.floats(1e-3, 1e3))
def test_condition_number_scale_invariant(seed, c):
    A = np.random.default_rng(seed).normal(size=(10, 3, 3))
    assert np.allclose(LA.condition_number(c * A), LA.condition_number(A), rtol=1e-9)


@given(seeds)
def test_orthogonal_is_isotropic(seed):
    Q, _ = np.linalg.qr(np.random.default_rng(seed).normal(size=(4, 3, 3)))
    assert np.all(I.is_isotropic(2.5 * Q))
    assert not np.any(I.is_isotropic(Q @ np.diag([1.0, 1.0, 1.0 + 1e-6])))


@given(robots(w_min=3, w_max=6, spread=True))
def test_JL1_isotropic_with_centroid_at_C(bot):
    """sum d_i = 0 and L^2 = mean |d_i|^2  =>  J_L1^T J_L1 = w I (34): isotropic for any polygon."""
    centred = bot.moved(tuple(bot.mount_points.mean(axis=0)), 0.0)
    L = I.characteristic_length(centred)
    assert np.isclose(L**2, np.mean(np.sum(centred.mount_points**2, axis=1)))
    JL1 = centred.J1(L)
    assert np.allclose(JL1.T @ JL1, centred.w * np.eye(3), atol=1e-12)
    assert bool(I.is_isotropic(JL1))
    # a different length, or C away from the centroid, breaks isotropy
    assert not bool(I.is_isotropic(centred.J1(1.5 * L)))
    assert not bool(I.is_isotropic(centred.moved((0.3 * L, 0.0), 0.0).J1(L)))


def test_non_equilateral_triangle_is_isotropic():
    # (38) asks for |d_i| = L; a scalene triangle with its centroid at C is isotropic too
    bot = wmr.Robot([wmr.CentredWheel(p, r=0.1) for p in [(2.0, 0.0), (-1.0, 1.0), (-1.0, -1.0)]])
    L = I.characteristic_length(bot)
    assert np.isclose(L**2, 8 / 3)
    assert np.isclose(float(LA.condition_number(bot.J1(L))), 1.0)


@given(st.floats(0.05, 2.0), st.floats(0.2, 3.0), seeds)
def test_offset_robot_with_d_equal_r_is_isotropic_for_all_beta(r, Lm, seed):
    """Offset wheels with d = r on an equilateral triangle: J J^T = 3 r^2 I for every beta."""
    bot = wmr.paper_robot("offset", L=Lm, r=r, d=r)
    beta = np.random.default_rng(seed).uniform(-np.pi, np.pi, (20, 3))
    J = bot.J(beta, L=I.characteristic_length(bot))
    assert np.allclose(J @ np.swapaxes(J, -1, -2), 3 * r**2 * np.eye(3), atol=1e-12)
    assert np.all(I.is_isotropic(J))


def test_centred_robot_J_is_not_isotropic():
    bot = wmr.paper_robot("centred", L=0.3, r=0.05)
    beta = np.random.default_rng(3).uniform(-np.pi, np.pi, (200, 3))
    k = LA.condition_number(bot.J(beta, L=0.3))
    assert not np.any(I.is_isotropic(bot.J(beta, L=0.3)))
    assert np.ptp(k[np.isfinite(k)]) > 1.0  # depends on beta


def test_characteristic_length_rejects_degenerate():
    bot = wmr.Robot([wmr.CentredWheel((0, 0), r=0.1)])
    with pytest.raises(ValueError, match="L = 0"):
        I.characteristic_length(bot)


def test_is_isotropic_uses_TOL():
    assert bool(I.is_isotropic(np.diag([1.0, 1.0 + TOL / 10])))
    assert not bool(I.is_isotropic(np.diag([1.0, 1.0 + 100 * TOL])))


@pytest.mark.parametrize("A, value", [([1.0, 2.0], "(2,)"), ([[np.nan, 1.0]], "nan"), ("x", "'x'")])
def test_bad_input(A, value):
    for f in (LA.condition_number, I.is_isotropic):
        with pytest.raises(TypeError if isinstance(A, str) else ValueError) as exc:
            f(A)
        assert "A" in str(exc.value) and value in str(exc.value), str(exc.value)
