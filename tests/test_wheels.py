"""wmr.model.wheels: each unit's block of J2 against the no-slip condition at the contact point (3D)."""
import numpy as np
import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st

import wmr
from wmr.model.backend import SYMBOLIC

from conftest import (
    angles,
    axle,
    coords,
    lengths,
    make_unit,
    rolling_dir,
    seeds,
    unit_mount_velocity,
    wheel_centre_velocity,
)

UNITS = [
    wmr.OffsetWheel((0.3, -0.2), r=0.1, d=0.05),
    wmr.OffsetWheel((0.3, -0.2), r=0.1, d=0.0),
    wmr.CentredWheel((-1.0, 0.5), r=0.2),
    wmr.DualWheel((0.0, 1.0), r=0.15, b=0.07),
]
IDS = ["offset", "offset-d0", "centred", "dual"]


@pytest.mark.parametrize("unit", UNITS, ids=IDS)
@pytest.mark.parametrize("batch", [(), (6,), (2, 3)])
def test_block_shapes(unit, batch):
    beta = np.random.default_rng(0).uniform(-3, 3, batch)
    Bk = unit.block(beta)
    assert Bk.shape == batch + (2, unit.n_rates)
    assert len(unit.rate_names(1)) == len(unit.rate_symbols(1)) == unit.n_rates
    pts = unit.points(beta)
    assert pts["P"].shape == pts["H"].shape == pts["i"].shape == batch + (2,)
    assert pts["wheels"].shape == batch + ({"dual": 2}.get(unit.kind, 1), 2)


@pytest.mark.parametrize("unit", UNITS, ids=IDS)
@given(seed=seeds)
def test_block_symbolic_matches_numeric(unit, seed):
    b = sp.Symbol("beta", real=True)
    S = unit.block(b)
    assert isinstance(S, sp.MatrixBase) and S.shape == (2, unit.n_rates)
    f = sp.lambdify(b, S, "numpy")
    betas = np.random.default_rng(seed).uniform(-np.pi, np.pi, 5)
    N = unit.block(betas)
    for k in range(5):
        assert np.allclose(np.array(f(betas[k]), float), N[k], atol=1e-14)


@given(st.sampled_from(["offset", "centred", "dual"]), coords, coords, lengths, lengths, lengths, angles, seeds)
def test_block_is_no_slip_first_principles(kind, x, y, r, d, b, beta, seed):
    """B_i(beta) theta_dot_i is the velocity of P_i implied by no slip at every contact point."""
    unit = make_unit(kind, (x, y), r, d=d, b=b)
    rates = np.random.default_rng(seed).normal(size=unit.n_rates)
    want, phi_dot = unit_mount_velocity(unit, beta, rates)
    assert np.allclose(unit.block(beta) @ rates, want, atol=1e-12)
    psi_dot = np.random.default_rng(seed + 1).normal()
    if kind == "offset":      # (7): beta_dot = phi_dot - psi_dot
        assert np.isclose(unit.beta_rate(psi_dot, rates), phi_dot - psi_dot)
    elif kind == "dual":      # corrected (15): the absolute heading rate is set by the wheel rates
        assert np.isclose(unit.beta_rate(psi_dot, rates), phi_dot - psi_dot)
    else:                     # centred: steering is an independent input
        assert unit.beta_rate(psi_dot, rates) == 0
        assert unit.beta_rate(psi_dot, rates, steer=0.25) == 0.25


def test_known_values_paper_conventions():
    # centred wheel at beta = 0: axle along x, rolls along -y for theta_dot > 0 (h_dot = -r theta_dot j)
    u = wmr.CentredWheel((0, 0), r=2.0)
    assert np.allclose(u.block(0.0) @ [1.0], [0.0, -2.0])
    # offset wheel: (9) p_dot = -r theta_dot j - d phi_dot i
    o = wmr.OffsetWheel((0, 0), r=2.0, d=0.5)
    beta = 0.3
    want = -2.0 * 0.7 * rolling_dir(beta) - 0.5 * 1.1 * axle(beta)
    assert np.allclose(o.block(beta) @ [1.1, 0.7], want)
    # dual: equal wheel rates drive like a centred wheel of the same radius (17)-(18)
    du = wmr.DualWheel((0, 0), r=2.0, b=0.4)
    assert np.allclose(du.block(beta) @ [0.7, 0.7], u.block(beta) @ [0.7])
    assert np.isclose(du.beta_rate(0.0, np.array([1.0, 0.0])), -2.0 / (2 * 0.4))


@pytest.mark.parametrize("kind", ["offset", "dual"])
def test_points_geometry(kind):
    beta = np.array([0.0, 0.4, -2.0])
    u = make_unit(kind, (1.0, 2.0), 0.3, d=0.25, b=0.5)
    pts = u.points(beta)
    assert np.allclose(pts["i"], axle(beta)) and np.allclose(pts["j"], rolling_dir(beta))
    if kind == "offset":
        assert np.allclose(pts["H"], pts["P"] - 0.25 * rolling_dir(beta))   # H = P - d j
    else:
        assert np.allclose(pts["wheels"][..., 0, :], pts["P"] + 0.5 * axle(beta))
        assert np.allclose(pts["wheels"][..., 1, :], pts["P"] - 0.5 * axle(beta))


def test_offset_with_zero_offset_is_centred_plus_free_steering():
    o, c = wmr.OffsetWheel((1, 1), r=0.3, d=0.0), wmr.CentredWheel((1, 1), r=0.3)
    beta = 0.8
    assert np.allclose(o.block(beta)[:, 1:], c.block(beta))
    assert np.allclose(o.block(beta)[:, 0], 0.0)


def test_symbolic_unit_parameters():
    r, d = sp.symbols("r d", positive=True)
    u = wmr.OffsetWheel((sp.Symbol("x"), 0), r=r, d=d)
    assert u.is_symbolic
    assert u.block(0, backend=SYMBOLIC) == sp.Matrix([[-d, 0], [0, -r]])
    assert not wmr.CentredWheel((1, 0), r=1).is_symbolic


def test_wheel_centre_velocity_helper_is_rolling():
    # sanity check of the first-principles helper itself: a wheel rolling about its axle at
    # theta_dot moves along -j at speed r theta_dot, whatever its spin about k
    v = wheel_centre_velocity(2.0, 5.0, 0.0, 0.5)
    assert np.allclose(v, [0.0, -1.0])


BAD = [
    (lambda: wmr.CentredWheel((0, 0), r=0.0), "r", "0"),
    (lambda: wmr.CentredWheel((0, 0), r=-1.0), "r", "-1"),
    (lambda: wmr.CentredWheel((0, 0), r=np.nan), "r", "nan"),
    (lambda: wmr.CentredWheel((0, 0), r=np.inf), "r", "inf"),
    (lambda: wmr.CentredWheel((0, 0), r="1"), "r", "'1'"),
    (lambda: wmr.OffsetWheel((0, 0), r=1.0, d=-0.1), "d", "-0.1"),
    (lambda: wmr.OffsetWheel((0, 0), r=1.0, d=np.nan), "d", "nan"),
    (lambda: wmr.DualWheel((0, 0), r=1.0, b=0.0), "b", "0"),
    (lambda: wmr.DualWheel((0, 0), r=1.0, b=-2), "b", "-2"),
    (lambda: wmr.CentredWheel((0, 0, 0), r=1.0), "position", "(0, 0, 0)"),
    (lambda: wmr.CentredWheel((np.nan, 0), r=1.0), "position", "nan"),
    (lambda: wmr.CentredWheel(5.0, r=1.0), "position", "5.0"),
    (lambda: wmr.CentredWheel((0, 0), r=-sp.Symbol("r", positive=True)), "r", "-r"),
    (lambda: wmr.CentredWheel((0, 0), r=1.0).block(np.nan), "beta", "nan"),
]


@pytest.mark.parametrize("make, name, value", BAD)
def test_bad_parameters_raise_with_name_and_value(make, name, value):
    wrong_kind = {("r", "'1'"), ("position", "5.0")}
    with pytest.raises(TypeError if (name, value) in wrong_kind else ValueError) as exc:
        make()
    msg = str(exc.value)
    assert name in msg and value in msg, msg
