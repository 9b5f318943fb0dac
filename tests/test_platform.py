"""wmr.model.platform: E, rotations and platform point velocities, checked against 3D cross products."""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st

from wmr.model import platform as P
from wmr.model.backend import NUMERIC, SYMBOLIC

from conftest import K, angles, coords, rigid_velocity, seeds, vec3

a_sym = sp.Symbol("a", real=True)


def test_E_is_k_cross():
    E = P.E()
    for v in np.eye(2):
        assert np.allclose(E @ v, np.cross(K, vec3(v))[:2])
    assert np.array_equal(E @ E, -np.eye(2))
    assert P.E(SYMBOLIC) == sp.Matrix([[0, -1], [1, 0]])


@pytest.mark.parametrize("batch", [(), (7,), (2, 3)])
def test_rotation_shapes_and_orthogonality(batch):
    a = np.random.default_rng(1).uniform(-4, 4, batch)
    R = P.rotation(a)
    assert R.shape == batch + (2, 2)
    assert np.allclose(R @ np.swapaxes(R, -1, -2), np.eye(2))
    assert np.allclose(np.linalg.det(R), 1.0)
    # first column is the rotated e1 = (cos a, sin a): counter-clockwise positive
    assert np.allclose(R[..., :, 0], np.stack([np.cos(a), np.sin(a)], -1))


@given(angles, angles)
def test_rotation_composes(a, b):
    assert np.allclose(P.rotation(a) @ P.rotation(b), P.rotation(a + b))


@given(seeds)
def test_rotation_symbolic_matches_numeric(seed):
    a = np.random.default_rng(seed).uniform(-np.pi, np.pi, 5)
    f = sp.lambdify(a_sym, P.rotation(a_sym, SYMBOLIC), "numpy")
    for ak, Rk in zip(a, P.rotation(a)):
        assert np.allclose(np.array(f(ak), float), Rk, atol=1e-14)
    assert P.rotation(sp.pi / 2, SYMBOLIC) == P.E(SYMBOLIC)


@given(coords, coords, seeds)
def test_point_velocity_first_principles(dx, dy, seed):
    t = np.random.default_rng(seed).normal(size=3)
    want = rigid_velocity(t[0], t[1:], [dx, dy])  # c_dot + (psi_dot k) x d
    assert np.allclose(P.point_velocity(t, [dx, dy]), want, atol=1e-12)
    assert np.allclose(P.point_row((dx, dy)) @ t, want, atol=1e-12)


@given(coords, coords, st.floats(0.1, 5.0), seeds)
def test_point_row_with_characteristic_length(dx, dy, L, seed):
    t = np.random.default_rng(seed).normal(size=3)
    tL = np.array([L * t[0], t[1], t[2]])  # (33)
    assert np.allclose(P.point_row((dx, dy), L) @ tL, P.point_row((dx, dy)) @ t, atol=1e-12)


def test_point_row_symbolic():
    dx, dy, L = sp.symbols("d_x d_y L", positive=True)
    M = P.point_row((dx, dy), L)
    assert isinstance(M, sp.MatrixBase)
    assert M == sp.Matrix([[-dy / L, 1, 0], [dx / L, 0, 1]])
    assert P.point_row((dx, dy), 1) == sp.Matrix([[-dy, 1, 0], [dx, 0, 1]])  # exact, no 1.0


@pytest.mark.parametrize(
    "tshape, dshape, out",
    [
        ((3,), (2,), (2,)),
        ((5, 3), (2,), (5, 2)),
        ((3,), (4, 2), (4, 2)),
        ((5, 1, 3), (4, 2), (5, 4, 2)),
    ],
)
def test_point_velocity_broadcasts(tshape, dshape, out):
    rng = np.random.default_rng(0)
    t, d = rng.normal(size=tshape), rng.normal(size=dshape)
    v = P.point_velocity(t, d)
    assert v.shape == out
    assert np.allclose(v, rigid_velocity(t[..., 0], t[..., 1:], d))


@pytest.mark.parametrize(
    "twist, d, name",
    [
        ([1.0, 2.0], [0.0, 0.0], "twist"),
        ([1.0, 2.0, 3.0], [0.0, 0.0, 0.0], "d"),
        ([1.0, np.nan, 3.0], [0.0, 0.0], "twist"),
        ([1.0, 2.0, 3.0], [np.inf, 0.0], "d"),
    ],
)
def test_point_velocity_bad_input(twist, d, name):
    with pytest.raises(ValueError, match=name):
        P.point_velocity(twist, d)


@pytest.mark.parametrize("angle", [np.nan, np.inf, [0.0, np.nan]])
def test_rotation_rejects_non_finite(angle):
    with pytest.raises(ValueError, match="angle"):
        P.rotation(angle, NUMERIC)
