"""wmr.analysis.integration: integrated motions that can be predicted without the package."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import wmr

from conftest import check_offset_steer_only, rolling_dir


@pytest.mark.parametrize("kind", ["centred", "dual"])
def test_spin_about_C_keeps_C_fixed(kind):
    """Wheels steered for a rotation about C, driven at the matching rates: C stays put, no slip."""
    bot = wmr.paper_robot(kind, L=0.4, r=0.1, b=0.05)
    t = np.array([0.8, 0.0, 0.0])
    beta = wmr.steering_angles(bot, t)
    rates = wmr.inverse(bot, beta, t).value
    tr = wmr.integrate(bot, rates, beta, t_end=2.0, dt=0.05, pose0=(0.1, 1.0, -2.0))
    assert np.allclose(tr.pose[:, 1:], [1.0, -2.0], atol=1e-12)
    assert np.allclose(tr.pose[:, 0], 0.1 + 0.8 * tr.t, atol=1e-12)
    assert np.allclose(tr.slip, 0.0, atol=1e-12)
    assert np.allclose(tr.beta, beta, atol=1e-12)  # steering stays put on the platform
    assert np.allclose(tr.twist, t, atol=1e-12)
    # every wheel contact point moves on a circle about C of radius |d_i|
    for i in range(bot.w):
        P = tr.unit_points(i, "P")
        assert np.allclose(np.linalg.norm(P - [1.0, -2.0], axis=-1), 0.4, atol=1e-12)


@settings(max_examples=8)
@given(st.floats(0.05, 0.5), st.floats(-2.0, 2.0), st.floats(-1.0, 1.0), st.floats(-1.0, 1.0))
def test_offset_steer_without_driving_moves_C_on_circle(d, omega, cx, cy):
    """C anywhere (not only at the centroid): all arms parallel, theta_dot = 0, C on a circle of radius d."""
    pts = [(x - cx, y - cy) for x, y in wmr.equilateral_mounts(0.5)]
    bot = wmr.Robot([wmr.OffsetWheel(p, r=0.1, d=d) for p in pts])
    check_offset_steer_only(bot, omega=omega, t_end=1.0, dt=0.05)


@pytest.mark.parametrize("t_end, dt, n", [(1.0, 0.1, 10), (1.0, 0.3, 4), (0.5, 2.0, 1), (np.pi, 0.01, 315)])
def test_time_grid_ends_at_t_end(t_end, dt, n):
    bot = wmr.paper_robot("centred")
    tr = wmr.integrate(bot, np.zeros(3), np.zeros(3), t_end, dt)
    assert len(tr.t) == n + 1 and tr.t[-1] == pytest.approx(t_end, abs=1e-12)
    assert np.all(np.diff(tr.t) <= dt + 1e-15)


def test_offset_steer_only_centre_is_contact_centroid():
    """C at the centroid of the P_i: the circle's centre is the centroid of the wheel centres."""
    bot = wmr.paper_robot("offset", L=0.5, r=0.1, d=0.08)
    rates = np.tile([1.0, 0.0], 3)
    tr = wmr.integrate(bot, rates, np.full(3, 0.3), t_end=np.pi, dt=0.01)
    Cf = np.mean([tr.unit_points(i, "H")[0] for i in range(3)], axis=0)
    assert np.allclose(np.linalg.norm(tr.pose[:, 1:] - Cf, axis=-1), 0.08, atol=1e-9)
    # after phi turns by pi, C is diametrically opposite
    assert np.allclose(tr.pose[-1, 1:] - Cf, -(tr.pose[0, 1:] - Cf), atol=1e-6)


def test_straight_line_and_world_frame():
    bot = wmr.paper_robot("centred", L=0.3, r=0.05)
    t = np.array([0.0, 0.0, 1.0])  # along body +y
    beta = wmr.steering_angles(bot, t)
    rates = wmr.inverse(bot, beta, t).value
    tr = wmr.integrate(bot, rates, beta, t_end=1.0, dt=0.1, pose0=(np.pi / 2, 0.0, 0.0))
    # body +y is world -x when psi = pi/2
    assert np.allclose(tr.pose[-1], [np.pi / 2, -1.0, 0.0], atol=1e-12)
    w = tr.world([0.3, 0.0])
    assert w.shape == (len(tr.t), 2) and np.allclose(w[0], [0.0, 0.3])
    assert tr.world(np.zeros((5, 2))).shape == (len(tr.t), 5, 2)


def test_callable_inputs_and_determinism():
    bot = wmr.paper_robot("centred", L=0.3, r=0.05)

    def rates(t, state):
        return np.array([1.0 + t, 2.0, -1.0])

    def steer(t, state):
        pose, beta = state
        return 0.1 * np.ones(3)

    a = wmr.integrate(bot, rates, np.zeros(3), 1.0, 0.05, steer=steer)
    b = wmr.integrate(bot, rates, np.zeros(3), 1.0, 0.05, steer=steer)
    assert np.array_equal(a.pose, b.pose) and np.array_equal(a.slip, b.slip)
    assert a.t.shape == (21,) and a.pose.shape == (21, 3) and a.beta.shape == (21, 3)
    assert np.allclose(a.beta[-1], 0.1, atol=1e-12)  # centred wheels follow the steering input
    assert np.all(a.slip[1:] > 0)  # incompatible rates are reported


def test_dual_unit_turns_by_wheel_difference():
    """Corrected (15): on a platform that does not turn, beta_dot = -(r/2b)(theta_1 - theta_2)."""
    bot = wmr.Robot([wmr.DualWheel(p, r=0.1, b=0.05) for p in wmr.equilateral_mounts(0.5)])
    t = np.array([0.0, 0.0, 0.0])
    rates = wmr.inverse(bot, np.zeros(3), t, beta_dot=np.full(3, 0.5)).value
    tr = wmr.integrate(bot, rates, np.zeros(3), t_end=1.0, dt=0.05)
    assert np.allclose(tr.beta[-1], 0.5, atol=1e-12)
    assert np.allclose(tr.pose, 0.0, atol=1e-12) and np.allclose(tr.slip, 0.0, atol=1e-12)
    assert np.allclose(rolling_dir(tr.beta[-1]), rolling_dir(0.5))


BOT = wmr.paper_robot("centred")
BAD = [
    (lambda: wmr.integrate(BOT, [1.0, 1.0], np.zeros(3), 1.0, 0.1), "rates", "(2,)"),
    (lambda: wmr.integrate(BOT, np.ones(3), np.zeros(2), 1.0, 0.1), "beta0", "(2,)"),
    (lambda: wmr.integrate(BOT, np.ones(3), np.zeros(3), 1.0, 0.0), "dt", "0"),
    (lambda: wmr.integrate(BOT, np.ones(3), np.zeros(3), np.nan, 0.1), "t_end", "nan"),
    (lambda: wmr.integrate(BOT, np.ones(3), np.zeros(3), 1.0, -0.1), "dt", "-0.1"),
    (lambda: wmr.integrate(BOT, np.ones(3), np.zeros(3), 1.0, 0.1, steer=[1.0]), "steer", "(1,)"),
    (lambda: wmr.integrate(BOT, np.ones(3), np.zeros(3), 1.0, 0.1, pose0=(0.0, np.inf, 0.0)), "pose0", "inf"),
    (lambda: wmr.integrate(BOT, lambda t, s: np.ones(2), np.zeros(3), 1.0, 0.1), "rates(t)", "(2,)"),
]


@pytest.mark.parametrize("call, name, value", BAD)
def test_bad_input(call, name, value):
    with pytest.raises(ValueError) as exc:
        call()
    assert name in str(exc.value) and value in str(exc.value), str(exc.value)
