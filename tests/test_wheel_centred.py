"""The centred steered wheel, wmr.model.wheels.centred: its block (51) from first principles, steering as an
independent input, the swerve module it is, and its parameter checks."""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given

import wmr

from conftest import angles, coords, lengths, seeds, unit_mount_velocity, wheel_centre_velocity


@given(coords, coords, lengths, angles, seeds)
def test_block_is_no_slip(x, y, r, beta, seed):
    unit = wmr.CentredWheel((x, y), r=r)
    rates = np.random.default_rng(seed).normal(size=1)
    want, _ = unit_mount_velocity(unit, beta, rates)
    assert np.allclose(unit.block(beta) @ rates, want, atol=1e-12)


def test_steering_is_an_independent_input():
    unit = wmr.CentredWheel((0, 0), r=1.0)
    assert unit.beta_rate(0.3, [2.0]) == 0
    assert unit.beta_rate(0.3, [2.0], steer=0.25) == 0.25
    assert unit.steering_row() is None and unit.rolls_in_plane and unit.steered


def test_known_values_51():
    """At beta = 0 the axle is along x and the wheel rolls along -y for theta_dot > 0 (h_dot = -r theta_dot j)."""
    u = wmr.CentredWheel((0, 0), r=2.0)
    assert np.allclose(u.block(0.0) @ [1.0], [0.0, -2.0])
    b = sp.Symbol("b")
    assert wmr.CentredWheel((0, 0), r=2).block(b) == sp.Matrix([[2 * sp.sin(b)], [-2 * sp.cos(b)]])  # R(b) [0, -r]^T


def test_wheel_centre_velocity_helper_is_rolling():
    """The first-principles helper itself: rolling at theta_dot moves the centre along -j at r theta_dot, whatever
    the spin about k."""
    assert np.allclose(wheel_centre_velocity(2.0, 5.0, 0.0, 0.5), [0.0, -1.0])


def test_a_swerve_module():
    bot = wmr.Robot([wmr.CentredWheel(p, r=0.05) for p in [(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3)]])
    assert wmr.swerve.swerve_robot(bot) is bot
    with pytest.raises(ValueError, match=r"centred wheels only .*'dual'"):
        wmr.swerve.swerve_robot(wmr.paper_robot("dual"))


BAD = [
    (dict(r=0.0), ValueError, "r", "0"),
    (dict(r=-1.0), ValueError, "r", "-1"),
    (dict(r=np.nan), ValueError, "r", "nan"),
    (dict(r=np.inf), ValueError, "r", "inf"),
    (dict(r="1"), TypeError, "r", "'1'"),
    (dict(position=(0, 0, 0)), ValueError, "position", "(0, 0, 0)"),
    (dict(position=(np.nan, 0)), ValueError, "position", "nan"),
    (dict(position=5.0), TypeError, "position", "5.0"),
    (dict(r=-sp.Symbol("r", positive=True)), ValueError, "r", "-r"),
    (dict(r=1e308), ValueError, "CentredWheel", "overflow"),
]


@pytest.mark.parametrize("kwargs, exc, name, shown", BAD)
def test_bad_parameters_raise_with_name_and_value(kwargs, exc, name, shown):
    args = dict(position=(0.0, 0.0), r=1.0) | kwargs
    with pytest.raises(exc) as info:
        wmr.CentredWheel(**args)
    assert name in str(info.value) and shown in str(info.value), str(info.value)
    with pytest.raises(ValueError, match="beta.*nan"):
        wmr.CentredWheel((0, 0), r=1.0).block(np.nan)
