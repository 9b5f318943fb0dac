"""wmr.model.backend: the two backends give the same matrices (SymPy exactly, NumPy batched)."""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given

from wmr.model import backend as B
from wmr.model.backend import NUMERIC, SYMBOLIC

from conftest import seeds

x, y = sp.symbols("x y", real=True)


def _rows(bk, a, b):
    return [[bk.cos(a), -bk.sin(b), 2], [a * b, 0, bk.sin(a) + bk.cos(b)]]


@pytest.mark.parametrize("batch", [(), (5,), (2, 3)])
def test_numeric_matrix_shape_and_broadcast(batch):
    rng = np.random.default_rng(0)
    a, b = rng.normal(size=batch), rng.normal(size=batch)
    M = NUMERIC.matrix(_rows(NUMERIC, a, b))
    assert M.shape == batch + (2, 3)
    assert np.all(M[..., 0, 2] == 2) and np.all(M[..., 1, 1] == 0)
    assert np.allclose(M[..., 1, 0], a * b)


@given(seeds)
def test_symbolic_and_numeric_builders_agree(seed):
    rng = np.random.default_rng(seed)
    a, b = rng.uniform(-3, 3, 7), rng.uniform(-3, 3, 7)
    S = SYMBOLIC.matrix(_rows(SYMBOLIC, x, y))
    assert isinstance(S, sp.MatrixBase) and S.shape == (2, 3)
    f = sp.lambdify((x, y), S, "numpy")
    N = NUMERIC.matrix(_rows(NUMERIC, a, b))
    for k in range(7):
        assert np.allclose(np.array(f(a[k], b[k]), float), N[k], atol=1e-14)


@pytest.mark.parametrize("bk", [NUMERIC, SYMBOLIC], ids=["numpy", "sympy"])
def test_zeros_set_block_transpose_eye(bk):
    M = bk.zeros(3, 4)
    bk.set_block(M, 1, 2, bk.matrix([[1, 2], [3, 4]]))
    want = np.zeros((3, 4))
    want[1:3, 2:4] = [[1, 2], [3, 4]]
    assert np.array_equal(np.array(M, dtype=float), want)
    assert np.array_equal(np.array(bk.transpose(M), dtype=float), want.T)
    assert np.array_equal(np.array(bk.eye(3), dtype=float), np.eye(3))
    H = bk.broadcast_hstack(bk.eye(2), bk.matrix([[5], [6]]))
    assert np.array_equal(np.array(H, dtype=float), [[1, 0, 5], [0, 1, 6]])


def test_numeric_batched_blocks_and_hstack():
    M = NUMERIC.zeros(2, 3, (4,))
    assert M.shape == (4, 2, 3)
    NUMERIC.set_block(M, 0, 1, np.ones((4, 2, 2)))
    assert np.all(M[:, :, 1:] == 1) and np.all(M[:, :, 0] == 0)
    H = NUMERIC.broadcast_hstack(np.eye(2), np.ones((4, 2, 1)))  # constant block broadcast
    assert H.shape == (4, 2, 3)
    assert np.array_equal(NUMERIC.hstack(np.eye(2), np.ones((2, 1))), [[1, 0, 1], [0, 1, 1]])


@pytest.mark.parametrize(
    "values, expected",
    [
        ((1.0, 2), False),
        ((1.0, x), True),
        (([1.0, [2.0, y]],), True),
        ((np.array([1.0, x], dtype=object),), True),
        ((np.array([1.0, 2.0]),), False),
        ((sp.Matrix([1, 2]),), True),
    ],
)
def test_is_symbolic(values, expected):
    assert B.is_symbolic(*values) is expected


def test_choose():
    assert B.choose(1.0, 2.0) is NUMERIC
    assert B.choose(1.0, x) is SYMBOLIC
    assert B.choose(x, backend=NUMERIC) is NUMERIC
    with pytest.raises(TypeError, match="backend.*'numpy'"):
        B.choose(1.0, backend="numpy")  # type: ignore[arg-type]
