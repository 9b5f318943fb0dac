r"""Comparing a derived result with the printed one: exactly (SymPy) and numerically (NumPy).

:func:`symbolic_equal` decides exact equality by reducing the difference to zero with a short,
targeted chain of simplifications (no blanket ``simplify`` on large expressions): expansion, the exact
reduction modulo :math:`\sin^2 + \cos^2 = 1`, then ``trigsimp``;
:func:`max_residual` evaluates the difference at random points drawn with a fixed seed.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

#: seed of every random check (determinism)
SEED = 20020101


def _as_matrix(x):
    if isinstance(x, sp.MatrixBase):
        return sp.Matrix(x)
    if isinstance(x, sp.Equality):
        return sp.Matrix([x.lhs - x.rhs])
    return sp.Matrix([sp.sympify(x)])


def _pythagorean_remainder(e):
    r"""``e`` reduced modulo :math:`\sin^2 a + \cos^2 a = 1` for each angle ``a`` it holds, or None.

    With :math:`s_a = \sin a`, :math:`c_a = \cos a` as independent variables, the numerator of ``e`` is a
    polynomial; the relations :math:`s_a^2 + c_a^2 - 1` of distinct angles have coprime leading terms, so they
    are a Gröbner basis and the remainder is 0 exactly when the numerator lies in the ideal they generate.
    A zero remainder therefore proves ``e = 0`` for every angle (sound); a nonzero one proves nothing (two
    angles may be related, e.g. :math:`a` and :math:`2a`), and the caller goes on with ``trigsimp``.
    None when ``e`` is not polynomial in sines and cosines.
    """
    args = sorted({t.args[0] for t in e.atoms(sp.sin, sp.cos)}, key=sp.default_sort_key)
    if not args:
        return None
    subs: dict = {}
    relations, gens = [], []
    for a in args:
        s, c = sp.Dummy("s"), sp.Dummy("c")
        subs |= {sp.sin(a): s, sp.cos(a): c}
        relations.append(s**2 + c**2 - 1)
        gens += [s, c]
    p = sp.numer(sp.together(e.xreplace(subs)))
    if p.has(sp.sin, sp.cos, sp.tan) or not p.is_polynomial(*gens):
        return None
    return sp.reduced(sp.expand(p), relations, *gens)[1]


def _is_zero(e):
    if e == 0:
        return True
    for step in (sp.expand, lambda z: sp.expand(sp.expand_trig(z))):
        e = step(e)
        if e == 0:
            return True
    if _pythagorean_remainder(e) == 0:  # exact and cheap where it applies; trigsimp below is neither cheap nor complete
        return True
    for step in (sp.trigsimp, lambda z: sp.simplify(sp.expand_trig(z))):
        e = step(e)
        if e == 0:
            return True
    return False


def symbolic_equal(a, b=0):
    """True when ``a - b`` simplifies to zero (expressions or matrices of equal shape).

    Parameters
    ----------
    a : SymPy expression, Matrix or Equality
        An equality ``lhs = rhs`` is compared as ``lhs - rhs``.
    b : SymPy expression or Matrix, optional
        Default 0.

    Returns
    -------
    bool

    Examples
    --------
    >>> x = sp.Symbol("x", real=True)
    >>> symbolic_equal(sp.sin(x)**2 + sp.cos(x)**2, 1)
    True
    """
    A, B = _as_matrix(a), _as_matrix(b) if not (isinstance(b, int) and b == 0) else None
    if B is not None and A.shape != B.shape:
        raise ValueError(f"cannot compare shapes {A.shape} and {B.shape}")
    D = A if B is None else A - B
    return all(_is_zero(e) for e in D)


def max_residual(a, b=0, symbols=None, n=200, seed=SEED, ranges=None):
    r"""Largest absolute entry of ``a - b`` at ``n`` random values of the free symbols.

    Parameters
    ----------
    a, b : SymPy expression or Matrix
    symbols : sequence of Symbol, optional
        Variables to sample (default: all free symbols, sorted by name).
    n : int
        Number of random points.
    seed : int
        Seed (default :data:`SEED`).
    ranges : dict Symbol -> (lo, hi), optional
        Explicit sampling ranges.  By default symbols declared positive are sampled in
        [0.2, 2], others in [-pi, pi].

    Returns
    -------
    float
    """
    A, B = _as_matrix(a), (_as_matrix(b) if not (isinstance(b, int) and b == 0) else None)
    D = A if B is None else A - B
    syms = list(symbols) if symbols is not None else sorted(D.free_symbols, key=lambda s: s.name)
    if not syms:
        return float(np.max(np.abs(np.array(D.evalf(), dtype=complex)))) if D.shape[0] else 0.0
    rng = np.random.default_rng(seed)
    ranges = dict(ranges or {})
    vals = []
    for s in syms:
        lo, hi = ranges.get(s, (0.2, 2.0) if s.is_positive else (-np.pi, np.pi))
        vals.append(rng.uniform(lo, hi, n))
    # entry by entry, so that constant entries (lambdify returns a scalar) broadcast to (n,)
    worst = 0.0
    for e in D:
        val = np.broadcast_to(np.asarray(sp.lambdify(syms, e, modules="numpy")(*vals), dtype=complex), (n,))
        worst = max(worst, float(np.max(np.abs(val))))
    return worst
