"""The dual-wheel unit, wmr.model.wheels.dual: its block (17) and the corrected (15) from first principles, the
two wheels' places, and its steering row: inverse kinematics turns it at the wanted rate."""

import numpy as np
import pytest
from hypothesis import given

import wmr
from wmr.analysis import reference

from conftest import angles, axle, coords, lengths, rolling_dir, seeds, unit_mount_velocity


@given(coords, coords, lengths, lengths, angles, seeds)
def test_block_is_no_slip_and_steering_is_corrected_15(x, y, r, b, beta, seed):
    """Both wheels roll without slip; the absolute heading rate is set by their difference (corrected (15))."""
    unit = wmr.DualWheel((x, y), r=r, b=b)
    rates = np.random.default_rng(seed).normal(size=2)
    want, phi_dot = unit_mount_velocity(unit, beta, rates)
    assert np.allclose(unit.block(beta) @ rates, want, atol=1e-12)
    psi_dot = np.random.default_rng(seed + 1).normal()
    assert np.isclose(unit.beta_rate(psi_dot, rates), phi_dot - psi_dot)
    row = unit.steering_row()
    assert row is not None and np.isclose(row @ rates, phi_dot)  # c theta_dot = psi_dot + beta_dot


def test_equal_rates_drive_like_a_centred_wheel():
    du, cu = wmr.DualWheel((0, 0), r=2.0, b=0.4), wmr.CentredWheel((0, 0), r=2.0)
    assert np.allclose(du.block(0.3) @ [0.7, 0.7], cu.block(0.3) @ [0.7])  # (17)-(18)
    assert np.isclose(du.beta_rate(0.0, np.array([1.0, 0.0])), -2.0 / (2 * 0.4))


def test_the_two_wheels_are_either_side_of_the_steering_axis():
    beta = np.array([0.0, 0.4, -2.0])
    pts = wmr.DualWheel((1.0, 2.0), r=0.3, b=0.5).points(beta)
    assert np.allclose(pts["i"], axle(beta)) and np.allclose(pts["j"], rolling_dir(beta))
    assert np.allclose(pts["wheels"][..., 0, :], pts["P"] + 0.5 * axle(beta))
    assert np.allclose(pts["wheels"][..., 1, :], pts["P"] - 0.5 * axle(beta))


def test_inverse_kinematics_steers_it_as_wanted():
    """The wheel-rate difference the block leaves free is set by beta_dot; the hub's velocity is unchanged."""
    bot = wmr.paper_robot("dual", L=0.4, r=0.05, b=0.03)
    twist, beta_dot = np.array([0.2, 0.5, -0.1]), np.array([0.4, -0.3, 0.0])
    beta = wmr.steering_angles(bot, twist)
    still = wmr.inverse(bot, beta, twist)
    turning = wmr.inverse(bot, beta, twist, beta_dot=beta_dot)
    assert bool(still.admissible) and bool(turning.admissible)
    got = [u.beta_rate(twist[0], turning.value[sl]) for u, sl in zip(bot.wheels, bot.rate_slices)]
    assert np.allclose(got, beta_dot) and np.allclose(
        [u.beta_rate(twist[0], still.value[sl]) for u, sl in zip(bot.wheels, bot.rate_slices)], 0, atol=1e-12
    )
    assert np.allclose(bot.J2(beta) @ turning.value, bot.J2(beta) @ still.value)
    assert np.allclose(reference.inverse(bot, beta, twist, beta_dot)[0], turning.value)


def test_its_swivel_is_passive():
    unit = wmr.DualWheel((0, 0), r=0.1, b=0.05)
    assert [(j.kind, j.driven) for j in unit.joints] == [("swivel", False), ("drive", True), ("drive", True)]
    assert unit.steered and unit.rolls_in_plane


@pytest.mark.parametrize(
    "b, exc, shown",
    [(0.0, ValueError, "0"), (-2, ValueError, "-2"), (np.inf, ValueError, "inf"), (None, TypeError, "None")],
)
def test_bad_half_separation(b, exc, shown):
    with pytest.raises(exc) as info:
        wmr.DualWheel((0, 0), r=1.0, b=b)
    assert "b" in str(info.value) and shown in str(info.value)
