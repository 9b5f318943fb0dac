"""The fixed conventional wheel, wmr.model.wheels.fixed: no slip from first principles at its own angle (the
configuration entry ignored), its actuation (driven, or an idler) and its parameter checks."""

import numpy as np
import pytest
from hypothesis import given

import wmr

from conftest import angles, axle, coords, hub_velocity, lengths, rolling_dir, seeds

PI = np.pi


@given(coords, coords, lengths, angles, angles, seeds)
def test_fixed_wheel_block_is_no_slip_and_ignores_beta(x, y, r, angle, beta, seed):
    unit = wmr.FixedWheel((x, y), r=r, angle=angle)
    rate = np.random.default_rng(seed).normal(size=1)
    want = hub_velocity("fixed", angle, r, rate)
    assert np.allclose(unit.block(beta) @ rate, want, atol=1e-12 * max(1.0, r))
    assert np.allclose(unit.block(beta), wmr.CentredWheel((x, y), r=r).block(angle), rtol=0, atol=1e-15 * max(1, r))
    pts = unit.points(np.full(3, beta))
    assert np.allclose(pts["i"], axle(angle)) and np.allclose(pts["j"], rolling_dir(angle))
    assert np.allclose(pts["H"], (x, y))


def test_driven_by_default_an_idler_when_passive():
    wheel = wmr.FixedWheel((0.0, 0.2), r=0.05, angle=PI / 2)
    idler = wmr.FixedWheel((0.0, 0.2), r=0.05, angle=PI / 2, driven={"drive": False})
    assert [(j.name, j.driven) for j in wheel.joints] == [("drive", True)] and idler.driven == (False,)
    assert not wheel.steered and wheel.rolls_in_plane and wheel.constant_angle == PI / 2
    assert wmr.io.loads(wmr.dump(wmr.Robot([idler]))).wheels[0].driven == (False,)


@pytest.mark.parametrize(
    "kwargs, exc",
    [
        (dict(angle="0"), TypeError),
        (dict(angle=10**400), ValueError),
        (dict(angle=True), TypeError),
        (dict(r=0), ValueError),
    ],
)
def test_bad_fixed_wheel(kwargs, exc):
    args = dict(position=(0.0, 0.0), r=0.1, angle=0.0) | kwargs
    with pytest.raises(exc, match=rf"\b{next(iter(kwargs))}\b"):
        wmr.FixedWheel(**args)


def test_a_constant_angle_stays_exact_or_becomes_a_float():
    import sympy as sp

    from wmr.model.wheels.unsteered import constant

    assert constant("angle", sp.pi / 2) == sp.pi / 2 and constant("angle", 1) == 1.0
    assert type(constant("angle", 1)) is float
