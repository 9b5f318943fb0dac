"""The edition's comparison helpers (edition.verify): exact equality and the largest numerical residual."""

import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st

from edition import verify

x = sp.Symbol("x", real=True)
p = sp.Symbol("p", positive=True)


def test_symbolic_equal():
    assert verify.symbolic_equal(sp.sin(x) ** 2 + sp.cos(x) ** 2, 1)
    assert verify.symbolic_equal(sp.Matrix([sp.sin(2 * x)]), sp.Matrix([2 * sp.sin(x) * sp.cos(x)]))
    assert verify.symbolic_equal(sp.Eq(sp.cos(x) ** 2, 1 - sp.sin(x) ** 2))
    assert not verify.symbolic_equal(sp.sin(x), sp.cos(x))
    with pytest.raises(ValueError, match="shapes"):
        verify.symbolic_equal(sp.Matrix([1, 2]), sp.Matrix([1, 2, 3]))


def test_symbolic_equal_reduces_modulo_pythagoras_and_only_proves():
    """Polynomials in the sines and cosines of several angles: the reduction modulo sin^2 + cos^2 = 1 proves the
    identities (fast, no trigsimp) and never a near miss: a zero remainder is a proof, a nonzero one is not."""
    a, b, r = sp.symbols("a b r", real=True)
    s, c = sp.sin, sp.cos
    rows = sp.Matrix([[c(a), s(a)], [-s(a) * c(b), c(a) * c(b)], [s(a) * s(b), -c(a) * s(b)]])
    gram = sp.expand(r**2 * rows.T * rows)  # its columns are orthonormal: r^2 times the identity
    assert verify.symbolic_equal(gram, r**2 * sp.eye(2))
    assert verify.symbolic_equal(s(a) ** 4 - c(a) ** 4, (s(a) ** 2 - c(a) ** 2) / (s(b) ** 2 + c(b) ** 2))
    assert not verify.symbolic_equal(gram, r**2 * sp.eye(2) + sp.Matrix([[0, s(a) * c(b) ** 2], [0, 0]]))
    assert not verify.symbolic_equal(s(a) ** 4 - c(a) ** 4, s(a) ** 2 - c(b) ** 2)


@given(st.integers(1, 50))
def test_max_residual(n):
    assert verify.max_residual(sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1, n=n) < 1e-14
    assert verify.max_residual(sp.sin(x), sp.cos(x), n=n) > 0
    r1 = verify.max_residual(sp.sin(x) - x / 2, n=n)
    assert r1 == verify.max_residual(sp.sin(x) - x / 2, n=n)  # fixed seed: deterministic
    assert verify.max_residual(p - 2, ranges={p: (2.0, 2.0)}, n=n) == 0.0
