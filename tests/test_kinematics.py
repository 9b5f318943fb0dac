"""wmr.analysis.kinematics: forward and inverse kinematics, round trips, first principles, body-frame independence."""

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

import wmr

from conftest import (
    check_round_trip,
    rigid_velocity,
    robots,
    rolling_dir,
    seeds,
    steered_beta,
    transform_twist,
    unit_mount_velocity,
)


@given(robots(w_min=2), seeds)
def test_forward_inverse_round_trip(bot, seed):
    """forward(inverse(t)) = t when centred/dual wheels are steered for t (offset wheels: any beta)."""
    assume(int(wmr.rank(bot.J1())) == 3)  # two distinct mount points at least
    rng = np.random.default_rng(seed)
    for t in [rng.normal(size=3), np.array([0.0, rng.normal(), rng.normal()]), np.array([1.3, 0.0, 0.0])]:
        check_round_trip(bot, t, seed)


@given(robots(), seeds)
def test_inverse_rates_satisfy_no_slip_first_principles(bot, seed):
    """Each unit's rates from inverse() move its mount point with the platform's velocity there."""
    rng = np.random.default_rng(seed)
    t = rng.normal(size=3)
    beta = steered_beta(bot, t, seed)
    bdot = rng.normal(size=bot.w)
    sol = wmr.inverse(bot, beta, t, beta_dot=bdot)
    assert bool(sol.no_slip) and np.allclose(sol.residual, 0.0, atol=1e-9)
    vP = rigid_velocity(t[0], t[1:], bot.mount_points)
    for i, (u, sl) in enumerate(zip(bot.wheels, bot.rate_slices)):
        v, phi_dot = unit_mount_velocity(u, beta[i], sol.value[sl])
        assert np.allclose(v, vP[i], atol=1e-9)
        if u.kind == "dual":  # the wheel-rate difference turns the unit at psi_dot + beta_dot
            assert np.isclose(phi_dot, t[0] + bdot[i])
            assert np.isclose(u.beta_rate(t[0], sol.value[sl]), bdot[i])


def test_known_values_spin_about_C(paper_centred):
    """Spin about C at psi_dot: wheel i rolls at |d_i| psi_dot / r, axle pointing at C."""
    t = np.array([2.0, 0.0, 0.0])
    beta = wmr.steering_angles(paper_centred, t)
    sol = wmr.inverse(paper_centred, beta, t)
    assert np.allclose(sol.value, 0.3 * 2.0 / 0.05)
    for i, d in enumerate(paper_centred.mount_points):  # rolling direction = -p_dot/|p_dot|
        assert np.allclose(rolling_dir(beta[i]), -rigid_velocity(2.0, [0, 0], d) / (0.3 * 2.0))


def test_offset_robot_known_values():
    """Offset wheels: theta_dot_i = -j_i . p_dot_i / r, phi_dot_i = -i_i . p_dot_i / d (from (9))."""
    bot = wmr.paper_robot("offset", L=0.5, r=0.1, d=0.04)
    beta = np.array([0.2, -1.0, 2.5])
    t = np.array([0.3, -0.4, 0.9])
    sol = wmr.inverse(bot, beta, t)
    vP = rigid_velocity(t[0], t[1:], bot.mount_points)
    i_dir = np.stack([np.cos(beta), np.sin(beta)], -1)
    j_dir = rolling_dir(beta)
    assert np.allclose(sol.value[0::2], -np.sum(i_dir * vP, -1) / 0.04)
    assert np.allclose(sol.value[1::2], -np.sum(j_dir * vP, -1) / 0.1)
    assert bool(sol.admissible)
    fwd = wmr.forward(bot, beta, sol.value)
    assert np.allclose(fwd.value, t)


@given(robots(kinds=("centred",), w_min=3, spread=True), seeds)
def test_inadmissible_motion_is_flagged(bot, seed):
    rng = np.random.default_rng(seed)
    beta = rng.uniform(-np.pi, np.pi, bot.w)  # generic: only t = 0 admissible
    t = rng.normal(size=3)
    inv = wmr.inverse(bot, beta, t)
    assert not bool(inv.admissible)
    assert np.allclose(inv.residual, bot.J1() @ t - bot.J2(beta) @ inv.value)
    # incompatible joint rates: forward returns the least-squares twist and flags the slip
    rates = rng.normal(size=bot.n_rates)
    fw = wmr.forward(bot, beta, rates)
    assert not bool(fw.admissible)
    J1, J2 = bot.J1(), bot.J2(beta)
    assert np.allclose(fw.residual, J1 @ fw.value - J2 @ rates)
    assert np.allclose(J1.T @ fw.residual, 0.0, atol=1e-10)  # normal equations of least squares


@given(robots(w_min=2), seeds, st.tuples(st.floats(-2, 2), st.floats(-2, 2)), st.floats(-np.pi, np.pi))
def test_forward_twist_transforms_as_a_twist(bot, seed, origin, angle):
    assume(int(wmr.rank(bot.J1())) == 3)
    rng = np.random.default_rng(seed)
    beta, rates = rng.uniform(-np.pi, np.pi, (4, bot.w)), rng.normal(size=(4, bot.n_rates))
    moved = bot.moved(origin, angle)
    a, b = wmr.forward(bot, beta, rates), wmr.forward(moved, beta - angle, rates)
    assert np.allclose(b.value, transform_twist(a.value, origin, angle), atol=1e-9)
    assert np.array_equal(a.admissible, b.admissible)
    t = rng.normal(size=3)
    inv_a = wmr.inverse(bot, beta, t)
    inv_b = wmr.inverse(moved, beta - angle, transform_twist(t, origin, angle))
    assert np.allclose(inv_a.value, inv_b.value, atol=1e-9)  # joint rates do not depend on B


@pytest.mark.parametrize(
    "bshape, xshape, out",
    [
        ((3,), (3,), ()),
        ((5, 3), (3,), (5,)),
        ((3,), (5, 3), (5,)),
        ((4, 1, 3), (5, 3), (4, 5)),
    ],
)
def test_batched_shapes(bshape, xshape, out):
    bot = wmr.paper_robot("dual", r=0.1, b=0.2)
    rng = np.random.default_rng(0)
    beta, t = rng.uniform(-3, 3, bshape), rng.normal(size=xshape)
    inv = wmr.inverse(bot, beta, t)
    assert inv.value.shape == out + (bot.n_rates,) and inv.residual.shape == out + (6,)
    assert inv.admissible.shape == out
    fw = wmr.forward(bot, beta, inv.value)
    assert fw.value.shape == out + (3,) and fw.admissible.shape == out


def test_batched_equals_loop():
    bot = wmr.Robot(
        [wmr.OffsetWheel((1, 0), r=0.1, d=0.05), wmr.CentredWheel((-1, 1), r=0.2), wmr.DualWheel((0, -1), r=0.1, b=0.1)]
    )
    rng = np.random.default_rng(5)
    beta, t = rng.uniform(-3, 3, (6, 3)), rng.normal(size=(6, 3))
    inv = wmr.inverse(bot, beta, t)
    for k in range(6):
        one = wmr.inverse(bot, beta[k], t[k])
        assert np.allclose(one.value, inv.value[k]) and one.admissible == inv.admissible[k]


BOT = wmr.paper_robot("centred")
BAD = [
    (lambda: wmr.forward(BOT, [0.0, 0.0, 0.0], [1.0, 2.0]), "rates", "(2,)"),
    (lambda: wmr.forward(BOT, [0.0, 0.0], [1.0, 2.0, 3.0]), "beta", "(2,)"),
    (lambda: wmr.forward(BOT, [0.0, 0.0, 0.0], [1.0, np.nan, 3.0]), "rates", "nan"),
    (lambda: wmr.inverse(BOT, [0.0, 0.0, 0.0], [1.0, 2.0]), "twist", "(2,)"),
    (lambda: wmr.inverse(BOT, [0.0, np.inf, 0.0], [1.0, 2.0, 0.0]), "beta", "inf"),
    (lambda: wmr.inverse(BOT, [0.0, 0.0, 0.0], [1.0, 2.0, 0.0], beta_dot=[1.0]), "beta_dot", "(1,)"),
    (lambda: wmr.forward(wmr.Robot([wmr.CentredWheel((1, 1), r=1)]), [0.0], [1.0]), "mount points", "[[1.0, 1.0]]"),
]


@pytest.mark.parametrize("call, name, value", BAD)
def test_bad_input(call, name, value):
    with pytest.raises(ValueError) as exc:
        call()
    assert name in str(exc.value) and value in str(exc.value), str(exc.value)
