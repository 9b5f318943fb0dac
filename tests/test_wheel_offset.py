"""The offset (castor) wheel, wmr.model.wheels.offset: its block (20) and steering (7) from first principles,
its geometry, its actuation (active by default, a castor when passive), its robot-file key and design hints."""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given

import wmr
from wmr.analysis.unit_design import ChangeKind, dead_zone, isotropic_change
from wmr.io.wheel_tables import file_keys
from wmr.model.backend import SYMBOLIC
from wmr.plot.parts import unit_parts
from wmr.words.advice import change

from conftest import angles, axle, coords, lengths, rolling_dir, seeds, unit_mount_velocity


@given(coords, coords, lengths, lengths, angles, seeds)
def test_block_is_no_slip_and_steering_is_7(x, y, r, d, beta, seed):
    """B(beta) theta_dot is the velocity of P that no slip at the contact implies; beta_dot = phi_dot - psi_dot (7)."""
    unit = wmr.OffsetWheel((x, y), r=r, d=d)
    rates = np.random.default_rng(seed).normal(size=2)
    want, phi_dot = unit_mount_velocity(unit, beta, rates)
    assert np.allclose(unit.block(beta) @ rates, want, atol=1e-12)
    psi_dot = np.random.default_rng(seed + 1).normal()
    assert np.isclose(unit.beta_rate(psi_dot, rates), phi_dot - psi_dot)


def test_known_values_9():
    o = wmr.OffsetWheel((0, 0), r=2.0, d=0.5)
    beta = 0.3
    want = -2.0 * 0.7 * rolling_dir(beta) - 0.5 * 1.1 * axle(beta)  # (9): p_dot = -r theta_dot j - d phi_dot i
    assert np.allclose(o.block(beta) @ [1.1, 0.7], want)


def test_wheel_centre_is_behind_the_steering_axis():
    beta = np.array([0.0, 0.4, -2.0])
    pts = wmr.OffsetWheel((1.0, 2.0), r=0.3, d=0.25).points(beta)
    assert np.allclose(pts["i"], axle(beta)) and np.allclose(pts["j"], rolling_dir(beta))
    assert np.allclose(pts["H"], pts["P"] - 0.25 * rolling_dir(beta))  # H = P - d j
    assert np.allclose(pts["wheels"][..., 0, :], pts["H"])


def test_zero_offset_is_a_centred_wheel_plus_free_steering():
    o, c = wmr.OffsetWheel((1, 1), r=0.3, d=0.0), wmr.CentredWheel((1, 1), r=0.3)
    assert np.allclose(o.block(0.8)[:, 1:], c.block(0.8)) and np.allclose(o.block(0.8)[:, 0], 0.0)


def test_symbolic_parameters():
    r, d = sp.symbols("r d", positive=True)
    u = wmr.OffsetWheel((sp.Symbol("x"), 0), r=r, d=d)
    assert u.is_symbolic and u.free_symbols == {r, d, sp.Symbol("x")}
    assert u.block(0, backend=SYMBOLIC) == sp.Matrix([[-d, 0], [0, -r]])
    with pytest.raises(ValueError, match="free symbols"):
        u.numeric()


def test_active_by_default_a_castor_when_passive():
    """The paper's offset wheels are active (steering and driving motors); a castor is the same unit, passive."""
    active = wmr.OffsetWheel((0, 0), r=0.1, d=0.05)
    castor = wmr.OffsetWheel((0, 0), r=0.1, d=0.05, driven={"steer": False, "drive": False})
    assert [(j.name, j.kind, j.driven) for j in active.joints] == [("steer", "steer", True), ("drive", "drive", True)]
    assert [j.driven for j in castor.joints] == [False, False]
    assert np.array_equal(castor.block(0.3), active.block(0.3))  # the kinematics do not change
    text = wmr.dump(wmr.Robot([castor]))
    assert "offset = 0.05" in text and "driven = {steer = false, drive = false}" in text
    assert wmr.io.loads(text).wheels[0] == castor


def test_dead_zone_and_isotropy_hints():
    """Steered with the drives locked, offset wheels carry C on a circle of radius d; d = r makes L_i isotropic (46)."""
    assert (
        dead_zone(wmr.OffsetWheel((0, 0), r=0.1, d=0.03)) == 0.03 and dead_zone(wmr.CentredWheel((0, 0), r=0.1)) is None
    )
    assert isotropic_change(wmr.OffsetWheel((0, 0), r=0.1, d=0.1)) is None
    change = isotropic_change(wmr.OffsetWheel((0, 0), r=0.1, d=0.03))
    assert change is not None and change.unit == wmr.OffsetWheel((0, 0), r=0.1, d=0.1)
    assert change.kind is ChangeKind.OFFSET_EQUALS_RADIUS


def test_the_moved_methods_warn_and_answer_as_their_replacements():
    """wmr.deprecated: each method that left the wheel kinds warns, naming its replacement, and answers as it does."""
    castor, mecanum = wmr.OffsetWheel((0, 0), r=0.1, d=0.03), wmr.SwedishWheel((0, 0), r=0.1, angle=0.0, roller=0.7)
    with pytest.warns(DeprecationWarning, match=r"dead_zone\(\) is deprecated: use wmr.analysis.unit_design"):
        assert castor.dead_zone() == dead_zone(castor)  # type: ignore[attr-defined]
    with pytest.warns(DeprecationWarning, match="isotropic_change"):
        assert castor.isotropic_variant() == isotropic_change(castor).unit  # type: ignore[attr-defined, union-attr]
    with pytest.warns(DeprecationWarning, match="isotropic_change"):
        assert castor.isotropy_advice() == change(isotropic_change(castor))  # type: ignore[attr-defined, arg-type]
    with pytest.warns(DeprecationWarning, match="other_builds"):
        assert mecanum.other_builds()[0][1].roller == -0.7  # type: ignore[attr-defined]
    with pytest.warns(DeprecationWarning, match="wmr.plot.parts.unit_parts"):
        assert repr(castor.parts(0.2)) == repr(unit_parts(castor, 0.2))  # type: ignore[attr-defined]
    with pytest.warns(DeprecationWarning, match="wmr.io.wheel_tables.file_keys"):
        assert wmr.OffsetWheel.file_keys() == file_keys(wmr.OffsetWheel)  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    "kwargs, exc, shown",
    [
        (dict(d=-0.1), ValueError, "-0.1"),
        (dict(d=np.nan), ValueError, "nan"),
        (dict(d="0.1"), TypeError, "'0.1'"),
        (dict(r=0.0), ValueError, "0"),
    ],
)
def test_bad_parameters(kwargs, exc, shown):
    args = dict(position=(0.0, 0.0), r=1.0, d=0.5) | kwargs
    with pytest.raises(exc) as info:
        wmr.OffsetWheel(**args)
    assert next(iter(kwargs)) in str(info.value) and shown in str(info.value)
