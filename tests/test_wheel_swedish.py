"""The Swedish wheel (omni, mecanum), wmr.model.wheels.swedish: no slip from first principles, its one
relation along the roller axis, blocks by hand, its joints and isotropy hint, and its parameter checks."""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st

import wmr
from wmr.analysis.unit_design import ChangeKind, isotropic_change, other_builds

from conftest import angles, coords, hub_velocity, lengths, seeds

PI = np.pi


@given(coords, coords, lengths, angles, st.floats(-1.5, 1.5).filter(lambda g: abs(g) > 0.05), angles, seeds)
def test_swedish_block_is_no_slip(x, y, r, angle, roller, beta, seed):
    unit = wmr.SwedishWheel((x, y), r=r, angle=angle, roller=roller)
    rates = np.random.default_rng(seed).normal(size=2)
    assert np.allclose(
        unit.block(beta) @ rates, hub_velocity("swedish", angle, r, rates, roller), atol=1e-12 * max(1, r)
    )


@given(coords, coords, lengths, angles, st.floats(-1.5, 1.5).filter(lambda g: abs(g) > 0.05), seeds)
def test_swedish_wheel_constraint_is_along_the_roller_axis(x, y, r, angle, roller, seed):
    """Any twist is realised (det L = r^2 sin g), and a^T v_P = -r sin(g) theta_dot is the only relation."""
    bot = wmr.Robot([wmr.SwedishWheel((x, y), r=r, angle=angle, roller=roller)])
    t = np.random.default_rng(seed).normal(size=3)
    sol = wmr.inverse(bot, [0.0], t)
    assert bool(sol.no_slip)
    # one wheel alone: with its motor stopped the robot still spins about the hub and rolls on the roller
    assert not bool(sol.actuated) and not bool(sol.admissible)
    v = np.array([t[1] - t[0] * y, t[2] + t[0] * x])  # hub velocity c_dot + psi_dot k x d, by hand
    a = np.array([np.cos(angle + roller), np.sin(angle + roller)])
    assert np.allclose(a @ v, -r * np.sin(roller) * sol.value[0], rtol=1e-9, atol=1e-12)
    assert np.allclose(hub_velocity("swedish", angle, r, sol.value, roller), v, rtol=1e-9, atol=1e-12)
    assert np.allclose(bot.wheels[0].roller_axis(), a)  # type: ignore[attr-defined]


def test_omni_and_mecanum_blocks_by_hand():
    omni = wmr.SwedishWheel((0.0, 0.0), r=2.0, angle=0.0, roller=PI / 2)
    assert np.allclose(omni.block(0.7), [[0.0, 2.0], [-2.0, 0.0]])  # rolls along j, free along the axle i
    s = np.sqrt(0.5)
    mec = wmr.SwedishWheel((0.0, 0.0), r=1.0, angle=PI / 2, roller=-PI / 4)
    # R(pi/2) [[0, r sin g], [-r, -r cos g]] with g = -pi/4
    assert np.allclose(mec.block(0.0), [[1.0, s], [0.0, -s]])
    exact = wmr.SwedishWheel((0, 0), r=1, angle=sp.pi / 2, roller=sp.pi / 4).block(sp.Symbol("b"))
    assert exact == sp.Matrix([[1, sp.sqrt(2) / 2], [0, sp.sqrt(2) / 2]])
    assert mec.rate_names(3) == ("theta_dot_3", "sigma_dot_3") and len(mec.rate_symbols(3)) == 2


def test_joints_and_isotropy_hint():
    omni = wmr.SwedishWheel((0, 0), r=0.05, angle=0.0, roller=PI / 2)
    mecanum = wmr.SwedishWheel((0, 0), r=0.05, angle=0.0, roller=PI / 4)
    assert [(j.kind, j.driven) for j in omni.joints] == [("drive", True), ("roller", False)]
    change = isotropic_change(mecanum)
    assert isotropic_change(omni) is None and change is not None and change.kind is ChangeKind.OMNI_ROLLERS
    assert change.unit == wmr.SwedishWheel((0, 0), r=0.05, angle=0.0, roller=PI / 2)
    assert [c.unit for c in other_builds(mecanum)] == [wmr.SwedishWheel((0, 0), r=0.05, angle=0.0, roller=-PI / 4)]
    assert other_builds(omni) == ()
    s = np.linalg.svd(mecanum.local_block(), compute_uv=False)
    assert np.allclose(s, 0.05 * np.sqrt([1 + np.cos(PI / 4), 1 - np.cos(PI / 4)]))  # what the hint says


@pytest.mark.parametrize(
    "kwargs, exc, word",
    [
        (dict(roller=0.0), ValueError, "roller"),
        (dict(roller=1e-12), ValueError, "roller"),
        (dict(roller=2.0), ValueError, "roller"),
        (dict(roller=-PI / 2), ValueError, "roller"),
        (dict(roller="45"), TypeError, "roller"),
        (dict(roller=sp.Symbol("g")), TypeError, "roller"),
        (dict(roller=np.nan), ValueError, "roller"),
        (dict(angle=None), TypeError, "angle"),
        (dict(angle=np.inf), ValueError, "angle"),
        (dict(angle=[0.1]), TypeError, "angle"),
        (dict(r=-1.0), ValueError, "r"),
        (dict(position=(1.0,)), ValueError, "position"),
    ],
)
def test_bad_swedish_wheel(kwargs, exc, word):
    args = dict(position=(0.0, 0.0), r=0.1, angle=0.0, roller=PI / 4) | kwargs
    with pytest.raises(exc, match=rf"\b{word}\b"):
        wmr.SwedishWheel(**args)
