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
    A[::3, 2] = A[::3, 0] - 2 * A[::3, 1]  # exact linear dependence (up to rounding)
    A[1::3, :, 1] = 0.0  # a zero column: det exactly 0
    got = LA.det(A)
    assert np.all(got[1::3] == 0.0)
    assert np.allclose(got, np.linalg.det(A), rtol=1e-11, atol=1e-13)
    bot = wmr.paper_robot("centred", L=0.3, r=0.05)
    beta = np.random.default_rng(1).uniform(-np.pi, np.pi, (5000, 3))
    beta[:100] = 0.7  # all wheels parallel: singular
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
        A[::4, -1, :] = 0.0  # rank-deficient members (a zero row)
    else:
        A[::4, ..., -1] = 0.0  # rank-deficient members (a zero column)
    A[1::4] *= 10.0 ** rng.uniform(-12, 12, (750, 1, 1))  # all scales, absolute part of the rule
    if p > 1:
        A[2::4, :, 0] = A[2::4, :, 1] * (1 + TOL * rng.uniform(0.5, 3, (750, 1)))  # nearly dependent
    assert np.array_equal(LA.rank(A), R.rank(A))
    ok = _closed.certified_full_rank(A.reshape((-1,) + shape))
    assert ok.any() and not ok.all()  # both paths ran
    assert np.all(R.rank(A)[ok] == p)  # a certificate is never wrong


# ------------------------------------------------------------------------------ kappa 3x3
@pytest.mark.parametrize("scale", [1e-40, 1e-3, 1.0, 1e5])
@pytest.mark.parametrize(
    "kind",
    [
        "random",
        "graded",
        "near-isotropic",
        "isotropic",
        "double-smallest",
        "double-largest",
        "rank-2",
        "near-threshold",
    ],
)
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
    assert accepted.mean() > 0.98  # the SVD is the exception
    want = R.condition_number(R.J(bot, beta, 0.3))
    got = LA.condition_number(J)
    fin = np.isfinite(want)
    assert np.array_equal(np.isinf(got), ~fin)
    assert np.all(np.abs(got[fin] / want[fin] - 1) <= 32 * EPS * want[fin])
    assert np.array_equal(wmr.is_isotropic(J), np.abs(want - 1) <= TOL)


# ------------------------------------------------------------------------------ kinematics
def _mixed_robot():
    return wmr.Robot(
        [
            wmr.OffsetWheel((0.4, 0.1), r=0.05, d=0.02),
            wmr.CentredWheel((-0.3, 0.25), r=0.06),
            wmr.DualWheel((-0.1, -0.35), r=0.04, b=0.03),
            wmr.CentredWheel((0.2, -0.2), r=0.05),
        ]
    )


ROBOTS = {
    "centred": lambda: wmr.paper_robot("centred", L=0.3, r=0.05),
    "offset": lambda: wmr.paper_robot("offset", L=0.3, r=0.05, d=0.02),
    "dual": lambda: wmr.paper_robot("dual", L=0.3, r=0.05, b=0.04),
    "mixed": _mixed_robot,
}


def _configurations(bot, n, seed):
    """Random angles, plus singular ones: all wheels parallel, and axles through one point."""
    rng = np.random.default_rng(seed)
    beta = rng.uniform(-np.pi, np.pi, (n, bot.w))
    beta[: n // 4] = rng.uniform(-np.pi, np.pi, (n // 4, 1))  # parallel wheels
    twist = rng.normal(size=(n, 3))
    beta[n // 4 : n // 2] = wmr.steering_angles(bot, twist[n // 4 : n // 2])  # axles through the IC
    beta[n // 2 : n // 2 + 50] += 1e-9 * rng.normal(size=(50, bot.w))  # nearly so
    return beta, twist


@pytest.mark.parametrize("kind", sorted(ROBOTS))
def test_forward_equals_pseudo_inverse(kind):
    bot = ROBOTS[kind]()
    beta, _ = _configurations(bot, 20000, 1)  # more than one chunk of the batched kernel
    rates = np.random.default_rng(2).normal(size=(20000, bot.n_rates))
    rates[:100] = 0.0
    sol = wmr.forward(bot, beta, rates)
    t, res, adm = R.forward(bot, beta, rates)
    assert np.allclose(sol.value, t, rtol=1e-12, atol=1e-13)
    assert np.allclose(sol.residual, res, rtol=1e-12, atol=1e-13)
    assert np.array_equal(sol.admissible, adm) and adm[:100].all()


@pytest.mark.parametrize("kind", sorted(ROBOTS))
def test_inverse_equals_pseudo_inverse(kind):
    bot = ROBOTS[kind]()
    beta, twist = _configurations(bot, 20000, 3)
    bdot = np.random.default_rng(4).normal(size=(20000, bot.w))
    for bd in (None, bdot):
        sol = wmr.inverse(bot, beta, twist, beta_dot=bd)
        th, res, adm = R.inverse(bot, beta, twist, beta_dot=bd)
        assert np.allclose(sol.value, th, rtol=1e-11, atol=1e-11)
        assert np.allclose(sol.residual, res, rtol=1e-12, atol=1e-12)
        assert np.array_equal(sol.admissible, adm)
    # steered for the twist: admissible exactly where the reference says so (all, for steerable units)
    assert sol.admissible[5000:10000].all() or kind == "mixed"


@pytest.mark.parametrize("bshape, tshape", [((), ()), ((5,), ()), ((), (5,)), ((2, 1), (1, 3)), ((0,), ())])
def test_kinematics_broadcasting(bshape, tshape):
    bot = _mixed_robot()
    rng = np.random.default_rng(5)
    beta = rng.uniform(-3, 3, bshape + (bot.w,))
    twist, rates = rng.normal(size=tshape + (3,)), rng.normal(size=tshape + (bot.n_rates,))
    batch = np.broadcast_shapes(bshape, tshape)
    inv, fwd = wmr.inverse(bot, beta, twist), wmr.forward(bot, beta, rates)
    assert inv.value.shape == batch + (bot.n_rates,) and inv.residual.shape == batch + (2 * bot.w,)
    assert fwd.value.shape == batch + (3,) and fwd.admissible.shape == batch
    b = np.broadcast_to(beta, batch + (bot.w,))
    assert np.allclose(inv.value, R.inverse(bot, b, np.broadcast_to(twist, batch + (3,)))[0], atol=1e-11)


def test_threads_do_not_change_results(monkeypatch):
    bot = _mixed_robot()
    beta, twist = _configurations(bot, 30000, 6)
    many = wmr.inverse(bot, beta, twist), wmr.condition_number(wmr.paper_robot("centred").J(beta[:, :3]))
    monkeypatch.setenv("WMR_THREADS", "1")
    one = wmr.inverse(bot, beta, twist), wmr.condition_number(wmr.paper_robot("centred").J(beta[:, :3]))
    assert np.array_equal(many[0].value, one[0].value) and np.array_equal(many[0].residual, one[0].residual)
    assert np.array_equal(many[1], one[1])


# ------------------------------------------------------------------------------ steering
@pytest.mark.parametrize("kind", sorted(ROBOTS))
def test_steering_angles_point_the_wheels_along_the_velocity(kind):
    bot = ROBOTS[kind]()
    rng = np.random.default_rng(7)
    twist = rng.normal(size=(5000, 3))
    twist[:10] = 0.0  # still: keep the current angles
    twist[10:20, 1:] = 0.0  # spin about C
    current = rng.uniform(-np.pi, np.pi, (5000, bot.w))
    beta = wmr.steering_angles(bot, twist, current=current)
    d = bot.mount_points
    p = np.stack([twist[:, 1:2] - twist[:, :1] * d[:, 1], twist[:, 2:3] + twist[:, :1] * d[:, 0]], -1)
    speed = np.linalg.norm(p, axis=-1)
    steer = np.array([u.kind in ("centred", "dual") for u in bot.wheels])
    moving = speed > 1e-6
    j = np.stack([-np.sin(beta), np.cos(beta)], -1)  # rolling direction R(beta) [0, 1]
    cosang = -np.sum(j * p, -1) / np.where(moving, speed, 1.0)  # j = -p / |p|
    assert np.all(np.abs(cosang[moving & steer] - 1) < 1e-12)
    assert np.array_equal(beta[~moving | ~steer], current[~moving | ~steer])
    assert np.all(np.abs(beta[moving & steer]) <= np.pi)
    # still within TOL of the terms' size (relative: a slow translation is a translation in any unit)
    t = np.array([[0.0, 1e-10, 0.0], [0.0, 2e-9, 0.0]])
    assert np.allclose(np.abs(wmr.steering_angles(wmr.paper_robot("centred"), t)), np.pi / 2)
    at_c = wmr.Robot([wmr.CentredWheel((0.0, 0.0), r=0.1), wmr.CentredWheel((1.0, 0.0), r=0.1)])
    t = np.array([[1.0, 1e-12, 0.0], [1.0, 1e-8, 0.0]])  # wheel 1 at the spin centre, or near it
    got = wmr.steering_angles(at_c, t, current=[[0.7, 0.7], [0.7, 0.7]])
    assert got[0, 0] == 0.7 and abs(abs(got[1, 0]) - np.pi / 2) < 1e-12


# ------------------------------------------------------------------------------ Robot.J2 / F / J
@pytest.mark.parametrize("kind", sorted(ROBOTS))
def test_robot_matrices_equal_the_dense_definitions(kind):
    """J2, F and J (entry-major, from trig_combination) against blockdiag(R(beta_i) L_i) formed in full."""
    bot = ROBOTS[kind]()
    beta, _ = _configurations(bot, 20000, 8)
    beta[0], beta[1], beta[2] = 0.0, np.pi, -np.pi / 2  # exact special angles
    beta = beta.reshape(40, 500, bot.w)  # two batch axes
    for L in (1.0, 0.37):
        assert np.allclose(bot.J(beta, L=L), R.J(bot, beta, L), rtol=0, atol=4e-16)
    assert np.allclose(bot.J2(beta), R.J2(bot, beta), rtol=0, atol=4e-16)
    F = bot.F(beta)
    assert F.shape == (40, 500, 2 * bot.w, 3 + bot.n_rates)
    assert np.allclose(F, R.F(bot, beta), rtol=0, atol=4e-16)
    assert np.array_equal(F[7, 11], bot.F(beta[7, 11]))  # one configuration = any batch
    assert np.array_equal(np.ascontiguousarray(F), F)  # the layout changes no value


# ----------------------------------------------------------------------------- motion_kappa
@pytest.mark.parametrize("kind", ["centred", "dual"])
def test_motion_kappa_equals_the_svd_of_the_dense_J(kind):
    """kappa(J) along the admissible motions (3x3 closed form or SVD of the fast J) against the dense definitions."""
    from wmr.analysis.motion_kappa import motion_kappa

    bot = wmr.paper_robot(kind, L=0.3, r=0.05)
    L = wmr.characteristic_length(bot)
    twist = np.random.default_rng(3).normal(size=(20_000, 3))
    twist[:50, 0] = 0.0  # translations: singular J for centred wheels
    got = motion_kappa(bot, twist, L)
    want = R.condition_number(R.J(bot, wmr.steering_angles(bot, twist), L))
    fin = np.isfinite(want)
    assert np.array_equal(np.isinf(got), ~fin)
    assert np.all(np.abs(got[fin] / want[fin] - 1) <= 1e-12 + 64 * EPS * want[fin])
