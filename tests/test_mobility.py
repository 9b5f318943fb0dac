"""wmr.analysis.mobility: rank, nullity and the mobility of F against independent reasoning per wheel type."""

import importlib

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import wmr
from wmr.model.tolerance import TOL

from conftest import random_twist, robots, same_subspace, seeds, steered_beta, transform_twist, twist_map, with_kind

M = importlib.import_module("wmr.analysis.mobility")  # the module (wmr.mobility is the function)
LA = importlib.import_module("wmr.analysis.linalg")


# --- linear algebra ---------------------------------------------------------------------------
@pytest.mark.parametrize(
    "A, rank",
    [
        ([[1.0, 2.0], [2.0, 4.0]], 1),
        (np.eye(3), 3),
        (np.zeros((2, 3)), 0),
        (np.diag([1.0, 1e-12, 1.0]), 3),  # a small column is not zero next to itself
        ([[1.0, 1.0], [1.0, 1.0 + 1e-12]], 1),  # nearly parallel columns: below TOL * s_max
        ([[1.0, 1.0], [1.0, 1.0 + 1e-6]], 2),
        (np.diag([1.0, 1e-6, 1.0]), 3),
        (1e-12 * np.eye(2), 2),  # relative: the same in every unit
        (np.ones((4, 1)), 1),
        (np.ones((1, 5)), 1),
    ],
)
def test_rank_known_values(A, rank):
    assert int(LA.rank(A)) == rank
    assert int(LA.nullity(A)) == np.shape(A)[1] - rank


def test_rank_with_given_column_sizes():
    """``scale`` says what a column is small next to: with equal sizes, the plain relative SVD rule."""
    A = np.diag([1.0, 1e-12, 1.0])
    assert int(LA.rank(A, scale=[1.0, 1.0, 1.0])) == 2 and int(LA.rank(A, scale=[1.0, 1e-12, 1.0])) == 3
    with pytest.raises(ValueError, match="scale"):
        LA.rank(A, scale=[1.0, 0.0, 1.0])


def _svd_rank(A):
    """The rule written out: columns to unit length, singular values above TOL * s_max."""
    n = np.linalg.norm(A, axis=-2, keepdims=True)
    s = np.linalg.svd(A / np.where(n > 0, n, 1.0), compute_uv=False)
    return np.sum(s > TOL * s[..., :1], axis=-1)


@pytest.mark.parametrize("shape", [(3, 3), (7, 3, 3), (2, 5, 4, 6), (6, 2, 3), (9, 3, 2), (4, 1, 1)])
def test_rank_batched_matches_numpy(shape):
    rng = np.random.default_rng(1)
    A = rng.normal(size=shape)
    # make some members rank deficient
    flat = A.reshape((-1,) + shape[-2:])
    flat[::2, ..., -1] = flat[::2, ..., 0]
    s = np.linalg.svd(A, compute_uv=False)
    want = _svd_rank(A)
    assert LA.rank(A).shape == shape[:-2]
    assert np.array_equal(LA.rank(A), want)
    assert np.allclose(LA.singular_values(A), s)


@given(seeds, st.floats(1e-8, 1e-4), st.floats(1e-3, 1e3))
def test_rank_fast_path_agrees_with_svd_near_threshold(seed, eps, scale):
    """The certified fast path must give exactly the SVD rank, also for nearly singular members."""
    rng = np.random.default_rng(seed)
    U, _ = np.linalg.qr(rng.normal(size=(400, 3, 3)))
    V, _ = np.linalg.qr(rng.normal(size=(400, 3, 3)))
    s = np.stack([np.ones(400), rng.uniform(0, 1, 400), eps * 10 ** rng.uniform(-3, 3, 400)], -1)
    A = scale * (U * s[:, None, :]) @ V
    assert np.array_equal(LA.rank(A), _svd_rank(A))


@given(seeds, st.integers(1, 4), st.integers(1, 6))
def test_null_space(seed, r, n):
    rng = np.random.default_rng(seed)
    A = rng.normal(size=(5, r)) @ rng.normal(size=(r, n))
    N = LA.null_space(A)
    assert N.shape == (n, n - min(r, n))
    assert np.allclose(A @ N, 0.0, atol=1e-10)
    assert np.allclose(N.T @ N, np.eye(N.shape[1]))


# --- the structured rank of F -------------------------------------------------------------------
@given(robots(), seeds)
def test_rank_F_equals_svd_rank_random(bot, seed):
    beta = np.random.default_rng(seed).uniform(-np.pi, np.pi, (20, bot.w))
    assert np.array_equal(M.rank_F(bot, beta), LA.rank(bot.F(beta)))


@given(robots(spread=True, w_min=3), seeds)
def test_rank_F_equals_svd_rank_at_special_configurations(bot, seed):
    rng = np.random.default_rng(seed)
    twists = np.vstack([rng.normal(size=(3, 3)), [[0.0, 1.0, 0.5], [2.0, 0.0, 0.0], [0.0, 0.0, 0.0]]])
    betas = np.stack([steered_beta(bot, t, seed) for t in twists] + [np.full(bot.w, 0.4), np.zeros(bot.w)])
    assert np.array_equal(M.rank_F(bot, betas), LA.rank(bot.F(betas)))


@pytest.mark.parametrize(
    "units",
    [
        [
            wmr.OffsetWheel((1, 0), r=0.1, d=0.0),
            wmr.OffsetWheel((-1, 0), r=0.1, d=0.0),
            wmr.OffsetWheel((0, 1), r=0.1, d=0.0),
        ],  # d = 0: rank L_i = 1
        [wmr.OffsetWheel((1, 0), r=0.1, d=0.0), wmr.CentredWheel((-1, 0), r=0.1)],
        [wmr.CentredWheel((0, 0), r=0.1)],  # one wheel
        [wmr.DualWheel((0, 0), r=0.1, b=0.1), wmr.DualWheel((0, 0), r=0.1, b=0.2)],  # coincident mounts
    ],
    ids=["offset-d0", "offset-d0+centred", "single", "coincident-duals"],
)
def test_rank_F_equals_svd_rank_degenerate_units(units):
    bot = wmr.Robot(units)
    rng = np.random.default_rng(3)
    betas = np.vstack(
        [rng.uniform(-np.pi, np.pi, (50, bot.w)), np.zeros((1, bot.w)), steered_beta(bot, np.array([1.0, 0.2, -0.3]))]
    )
    assert np.array_equal(M.rank_F(bot, betas), LA.rank(bot.F(betas)))


# --- mobility per wheel type ---------------------------------------------------------------------
@given(robots(kinds=("offset",)), seeds)
def test_offset_wheels_full_mobility(bot, seed):
    """d > 0: each unit's block R diag(-d, -r) is invertible, so rank F = 2w and nu = 3 for any beta."""
    beta = np.random.default_rng(seed).uniform(-np.pi, np.pi, (10, bot.w))
    assert np.all(M.mobility(bot, beta) == 3)
    assert M.admissible_twists(bot, beta[0]).shape == (3, 3)


@given(robots(kinds=("centred",), spread=True, w_min=3), seeds)
def test_centred_steered_for_a_twist_has_mobility_one(bot, seed):
    """Axles of non-collinear wheels all through the IC (or all parallel): exactly one motion."""
    rng = np.random.default_rng(seed)
    for t in list(rng.normal(size=(3, 3))) + [np.array([0.0, 1.0, -2.0]), np.array([1.0, 0.0, 0.0])]:
        beta = wmr.steering_angles(bot, t)
        assert int(M.mobility(bot, beta)) == 1
        basis = M.admissible_twists(bot, beta)
        assert same_subspace(basis, t[:, None])


@given(robots(kinds=("centred",), spread=True, w_min=3), seeds)
def test_centred_generic_angles_have_mobility_zero(bot, seed):
    beta = np.random.default_rng(seed).uniform(-np.pi, np.pi, (20, bot.w))
    assert np.all(M.mobility(bot, beta) == 0)


@given(robots(kinds=("centred", "dual"), spread=True, w_min=3), seeds)
def test_dual_adds_one_per_unit_and_same_twists(bot, seed):
    """nullity(F_dual) = nullity(F_centred) + w; both admit the same platform twists."""
    cen, dual = with_kind(bot, "centred"), with_kind(bot, "dual")
    rng = np.random.default_rng(seed)
    betas = [rng.uniform(-np.pi, np.pi, bot.w), steered_beta(cen, rng.normal(size=3), seed), np.full(bot.w, -0.7)]
    for beta in betas:
        assert int(LA.nullity(dual.F(beta))) == int(LA.nullity(cen.F(beta))) + bot.w
        assert int(M.mobility(dual, beta)) == int(M.mobility(cen, beta)) + bot.w
        assert same_subspace(M.admissible_twists(dual, beta), M.admissible_twists(cen, beta))


@given(robots(), seeds)
def test_admissible_twists_are_realisable(bot, seed):
    beta = steered_beta(bot, random_twist(seed), seed)
    basis = M.admissible_twists(bot, beta)
    A, base = M.twist_constraints(bot, beta)
    assert np.allclose(A @ basis, 0.0, atol=1e-10)
    for t in basis.T:
        assert bool(wmr.inverse(bot, beta, t).no_slip)
    # mobility = dim of admissible twists + dim of joint-rate motions with the platform still
    null = LA.null_space(bot.F(beta))
    assert int(M.mobility(bot, beta)) == null.shape[1]
    assert np.linalg.matrix_rank(null[:3], tol=1e-8) == basis.shape[1]
    # a twist outside the admissible set leaves a residual
    if basis.shape[1] < 3:
        t = np.linalg.svd(basis.T)[2][-1]  # orthogonal to all admissible twists
        assert not bool(wmr.inverse(bot, beta, t).admissible)


# --- independence of the body frame --------------------------------------------------------------
@given(robots(), seeds, st.tuples(st.floats(-2, 2), st.floats(-2, 2)), st.floats(-np.pi, np.pi))
def test_mobility_and_admissibility_do_not_depend_on_body_frame(bot, seed, origin, angle):
    rng = np.random.default_rng(seed)
    moved = bot.moved(origin, angle)
    beta = np.vstack([rng.uniform(-np.pi, np.pi, (5, bot.w)), steered_beta(bot, rng.normal(size=3), seed)])
    assert np.array_equal(M.mobility(moved, beta - angle), M.mobility(bot, beta))
    T = twist_map(origin, angle)
    for b in beta:
        assert same_subspace(M.admissible_twists(moved, b - angle), T @ M.admissible_twists(bot, b))
    t = rng.normal(size=3)
    b = beta[-1]
    assert bool(wmr.inverse(bot, b, t).admissible) == bool(
        wmr.inverse(moved, b - angle, transform_twist(t, origin, angle)).admissible
    )


@pytest.mark.parametrize("batch", [(), (3,), (2, 4)])
def test_batched_shapes(batch):
    bot = wmr.paper_robot("dual", r=0.1)
    beta = np.random.default_rng(0).uniform(-3, 3, batch + (3,))
    assert M.mobility(bot, beta).shape == batch
    assert M.rank_F(bot, beta).shape == batch
    A, base = M.twist_constraints(bot, beta)
    assert A.shape == batch + (3, 3) and base == 3


BAD = [
    (lambda: LA.rank([1.0, 2.0]), "A", "(2,)"),
    (lambda: LA.rank([[1.0, np.nan]]), "A", "nan"),
    (lambda: LA.rank([[1.0, 2.0], [3.0]]), "A", "[[1.0, 2.0], [3.0]]"),
    (lambda: LA.nullity("abc"), "A", "'abc'"),
    (lambda: LA.null_space(np.zeros((2, 2, 2))), "A", "(2, 2, 2)"),
    (lambda: M.mobility(wmr.paper_robot(), [0.0, 0.0]), "beta", "(2,)"),
    (lambda: M.rank_F(wmr.paper_robot(), [0.0, 0.0, np.inf]), "beta", "inf"),
    (lambda: M.admissible_twists(wmr.paper_robot(), np.zeros((2, 3))), "beta", "(2, 3)"),
]


@pytest.mark.parametrize("call, name, value", BAD)
def test_bad_input(call, name, value):
    with pytest.raises(TypeError if value == "'abc'" else ValueError) as exc:  # a string: the wrong kind
        call()
    assert name in str(exc.value) and value in str(exc.value), str(exc.value)
