r"""Symbolic answers: the student's SymPy symbols mapped onto the package's, and equivalence that admits "cannot tell".

A student writes ``r, d = sp.symbols("r d")`` or ``phi_dot_i = sp.Symbol("phidot_i")``, while the
package's symbols (:mod:`edition.symbols`) carry assumptions (``r`` is positive) and LaTeX names
(``\dot{\phi}_i``).  SymPy treats ``Symbol("r")`` and ``Symbol("r", positive=True)`` as different
symbols, so an equal answer would compare unequal.  :func:`map_symbols` replaces each of the
student's symbols by the package symbol with the same name, or with the same *spelling key*
(:func:`spelling`: the name's words and indices, without backslashes, braces, underscores and
Greek letters spelled out, in any order: ``phi_dot_i``, ``phidot_i``, ``\dot{\phi}_i`` are one key).

:func:`equivalent` decides equality: exactly (:func:`edition.verify.symbolic_equal`), else by
evaluating the difference at random points (fixed seed); an expression that cannot be evaluated
there gives ``None``: the check says that it cannot tell, never a false "wrong".
"""

from __future__ import annotations

import re

import numpy as np
import sympy as sp

from .answers import AnswerError

__all__ = ["spelling", "map_symbols", "equivalent", "compare"]

_GREEK = {
    "α": "alpha",
    "β": "beta",
    "γ": "gamma",
    "δ": "delta",
    "θ": "theta",
    "ϑ": "theta",
    "φ": "phi",
    "ϕ": "phi",
    "ψ": "psi",
    "ω": "omega",
    "κ": "kappa",
    "ν": "nu",
    "σ": "sigma",
    "ρ": "rho",
}
_MARKUP = re.compile(r"\\(?:mathrm|mathbf|boldsymbol|operatorname|text)|\\var")


def spelling(name):
    r"""The spelling key of a symbol name: its words and indices, sorted, with ``dot`` split off.

    Parameters
    ----------
    name : str

    Returns
    -------
    tuple of str

    Examples
    --------
    >>> spelling(r"\dot{\phi}_i") == spelling("phi_dot_i") == spelling("phidot_i") == spelling("φ̇_i".replace("̇", "dot"))
    True
    >>> spelling(r"\dot{\theta}_{i1}") == spelling("theta_dot_i1"), spelling("beta1") == spelling(r"\beta_1")
    (True, True)
    """
    s = _MARKUP.sub("", name)
    for g, word in _GREEK.items():
        s = s.replace(g, f" {word} ")
    tokens = []
    for t in re.findall(r"[A-Za-z]+|\d+", s):
        while len(t) > 3 and t.endswith("dot"):
            tokens.append("dot")
            t = t[:-3]
        while len(t) > 3 and t.startswith("dot"):
            tokens.append("dot")
            t = t[3:]
        tokens.append(t)
    return tuple(sorted(tokens))


def _targets(onto):
    """name -> symbol and spelling key -> symbol (keys shared by two symbols are left out: ambiguous)."""
    by_name = {s.name: s for s in onto}
    by_key: dict = {}
    for s in onto:
        k = spelling(s.name)
        by_key[k] = None if k in by_key and by_key[k] != s else s
    return by_name, {k: s for k, s in by_key.items() if s is not None}


def map_symbols(expr, onto, what="your answer"):
    r"""``expr`` with each free symbol replaced by the symbol of ``onto`` it names; AnswerError for a stranger.

    Parameters
    ----------
    expr : SymPy expression or Matrix
    onto : iterable of sympy.Symbol
        The symbols the answer may use (the package's).
    what : str, optional
        How the message calls the answer.

    Returns
    -------
    SymPy expression or Matrix

    Examples
    --------
    >>> from edition import symbols as S
    >>> r, thd = sp.symbols("r thetadot_i")          # no assumptions, the student's own spelling
    >>> map_symbols(r * thd, [S.r, S.theta_dot_i]) == S.r * S.theta_dot_i
    True
    """
    onto = list(onto)
    by_name, by_key = _targets(onto)
    subs, strangers = {}, []
    for s in sorted(expr.free_symbols, key=lambda s: s.name):
        target = by_name.get(s.name) or by_key.get(spelling(s.name))
        if target is None:
            strangers.append(s)
        elif target is not s:
            subs[s] = target
    if strangers:
        allowed = ", ".join(f"${sp.latex(s)}$" for s in sorted(onto, key=lambda s: s.name))
        bad = ", ".join(f"${sp.latex(s)}$" for s in strangers)
        raise AnswerError(
            f"{what[0].upper()}{what[1:]} uses {bad}, which this exercise does not have; it may use {allowed}."
        )
    return expr.xreplace(subs) if subs else expr


def equivalent(answer, truth, n=24, seed=20020101):
    """Whether ``answer`` equals ``truth``: True, False, or None when it cannot be decided.

    Exact simplification first; then the difference at ``n`` random points (positive symbols in
    [0.2, 2], others in [-pi, pi]): equal at every point to round-off means equal (two different
    analytic expressions agree at random points with probability zero).

    Parameters
    ----------
    answer, truth : SymPy expression or Matrix of the same shape
        In the same symbols (:func:`map_symbols` first).
    n : int, optional
    seed : int, optional

    Returns
    -------
    bool or None
    """
    from ..verify import symbolic_equal

    A, B = (
        sp.Matrix([answer]) if not isinstance(answer, sp.MatrixBase) else sp.Matrix(answer),
        sp.Matrix([truth]) if not isinstance(truth, sp.MatrixBase) else sp.Matrix(truth),
    )
    if A.shape != B.shape:
        return False
    try:
        if symbolic_equal(A, B):
            return True
    except (TypeError, ValueError, NotImplementedError, RecursionError):
        pass
    syms = sorted((A.free_symbols | B.free_symbols), key=lambda s: s.name)
    rng = np.random.default_rng(seed)
    vals = [rng.uniform(0.2, 2.0, n) if s.is_positive else rng.uniform(-np.pi, np.pi, n) for s in syms]
    try:
        fa, fb = (sp.lambdify(syms, list(M), modules="numpy") for M in (A, B))
        with np.errstate(all="ignore"):
            a = np.array([np.broadcast_to(np.asarray(x, dtype=complex), (n,)) for x in fa(*vals)])
            b = np.array([np.broadcast_to(np.asarray(x, dtype=complex), (n,)) for x in fb(*vals)])
    except (TypeError, ValueError, NameError, ZeroDivisionError, AttributeError):
        return None
    ok = np.isfinite(a) & np.isfinite(b)
    if ok.sum() < n // 2:
        return None
    gap = np.abs(a - b)[ok]
    return bool(np.all(gap <= 1e-9 * (1 + np.abs(b[ok]))))


def compare(answer, truth, onto, what):
    """Read a student's symbolic answer, map its symbols onto ``onto`` and compare it with ``truth``.

    Parameters
    ----------
    answer : SymPy expression or Matrix (or a number / nested list)
        The student's answer, in their own symbols.
    truth : SymPy expression or Matrix
        The derived answer, in the package's symbols.
    onto : iterable of sympy.Symbol
        The symbols the answer may use.
    what : str
        What the answer should be, in words (for a malformed answer's one line).

    Returns
    -------
    mapped : SymPy expression or Matrix
        The answer in the package's symbols.
    same : bool or None
        :func:`equivalent`: None when it cannot be decided.

    Raises
    ------
    AnswerError
        Not a SymPy object, a shape other than ``truth``'s, or a symbol the exercise does not have.
    """
    from .answers import describe, sympy_object

    obj = sympy_object(answer, what)
    if isinstance(truth, sp.MatrixBase):
        if not isinstance(obj, sp.MatrixBase) or obj.shape != truth.shape:
            raise AnswerError(f"Expected {what} (a matrix of shape {truth.shape}); got {describe(answer)}.")
    elif isinstance(obj, sp.MatrixBase):
        raise AnswerError(f"Expected {what} (one expression); got {describe(answer)}.")
    mapped = map_symbols(obj, onto)
    return mapped, equivalent(mapped, truth)
