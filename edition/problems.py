r"""Independent problems: the ledger rows that fail, merged where two rows are one error, by computation.

A ledger row is one printed statement; two rows can be one error.  Two failing rows (verdict ``typo`` or
``wrong``) are merged when the data show it, by one of two tests, each computed here and never typed:

``integral``
    The printed form of one equation is the time integral of the printed form of the other: differentiating
    it (every angle a function of time, :data:`RATES`) gives the other exactly (SymPy, on the transcription
    ``edition/printed.toml``).  (16), the integral of (15), is wrong for the same reason as (15).
``counterexample``
    The two rows are refuted by the same counterexample: the ``refuted (...)`` parts of their ``check`` fields
    are the same text (the checks build it from one computation).  (38) and the claim of the equilateral
    placement are one error.

:func:`problems` returns the connected components of that relation: one :class:`Problem` per independent
error, with the rows it merges and why.  Part I of the report shows the merge and states the count from here.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import sympy as sp

from . import symbols as S

__all__ = ["RATES", "Problem", "links", "problems", "tally"]

#: each angle of the transcription and its rate: what "differentiate in time" replaces
RATES = {
    S.beta_i: S.beta_dot_i,
    S.phi_i: S.phi_dot_i,
    S.psi: S.psi_dot,
    S.theta_i: S.theta_dot_i,
    S.theta_i1: S.theta_dot_i1,
    S.theta_i2: S.theta_dot_i2,
}

_REFUTED = re.compile(r"refuted \((?P<how>.*)\); (?:corrected form proven|what is true, proven)", re.S)


@dataclass(frozen=True)
class Problem:
    """One independent error of the paper: the ledger rows that state it, and why they were merged.

    Attributes
    ----------
    rows : tuple of str
        Ledger ids, equations first in numeric order, then claims in ledger order.
    verdict : str
        ``wrong`` if any of its rows is wrong, else ``typo``.
    merged : tuple of (str, str, str)
        ``(id, id, test)`` for each link found, ``test`` one of ``integral``, ``counterexample``.
    """

    rows: tuple
    verdict: str
    merged: tuple = ()


def _time_derivative(expr):
    t = sp.Symbol("t", real=True)
    funcs = {s: sp.Function(s.name)(t) for s in RATES if expr.has(s)}
    d = sp.diff(expr.subs(funcs), t)
    return d.subs({sp.Derivative(f, t): RATES[s] for s, f in funcs.items()}).subs({f: s for s, f in funcs.items()})


def _integral_of(a, b, transcription):
    """Whether the printed equation ``b`` differentiates in time into the printed equation ``a``."""
    A, B = transcription.equations.get(a), transcription.equations.get(b)
    if A is None or B is None or not isinstance(A.expr, sp.Equality) or not isinstance(B.expr, sp.Equality):
        return False
    if not any(B.expr.has(s) for s in RATES):
        return False
    lhs, rhs = _time_derivative(B.expr.lhs), _time_derivative(B.expr.rhs)
    return _same(lhs, A.expr.lhs) and _same(rhs, A.expr.rhs)


def _same(x, y):
    if isinstance(x, sp.MatrixBase) != isinstance(y, sp.MatrixBase):
        return False
    try:
        d = sp.simplify(x - y)
    except (TypeError, ValueError, sp.ShapeError):
        return False
    return d.is_zero_matrix if isinstance(d, sp.MatrixBase) else d == 0


def _counterexample(row):
    m = _REFUTED.search(row["check"])
    return m["how"].strip() if m else ""


def links(ledger, transcription=None):
    """The pairs of failing rows that are one error, and the test that shows it.

    Parameters
    ----------
    ledger : list of dict
        Rows of ``figures/ledger.csv``.
    transcription : Transcription, optional
        Default :func:`edition.transcription.table`.

    Returns
    -------
    list of (str, str, str)
        ``(id, id, test)``.
    """
    from .transcription import table

    tr = table() if transcription is None else transcription
    failing = [r for r in ledger if r["verdict"] != "ok"]
    out = []
    for i, a in enumerate(failing):
        for b in failing[i + 1 :]:
            if a["kind"] == b["kind"] == "equation" and (
                _integral_of(a["id"], b["id"], tr) or _integral_of(b["id"], a["id"], tr)
            ):
                out.append((a["id"], b["id"], "integral"))
            elif (how := _counterexample(a)) and how == _counterexample(b):
                out.append((a["id"], b["id"], "counterexample"))
    return out


def problems(ledger, transcription=None):
    """The independent problems: the failing rows merged by :func:`links` (connected components).

    Parameters
    ----------
    ledger : list of dict
    transcription : Transcription, optional

    Returns
    -------
    list of Problem
        In ledger order of their first row.
    """
    failing = [r for r in ledger if r["verdict"] != "ok"]
    found = links(ledger, transcription)
    parent = {r["id"]: r["id"] for r in failing}

    def root(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for a, b, _ in found:
        parent[root(b)] = root(a)
    groups: dict[str, list] = {}
    for r in failing:
        groups.setdefault(root(r["id"]), []).append(r)
    out = []
    for rows in groups.values():
        ids = tuple(r["id"] for r in rows)
        verdict = "wrong" if any(r["verdict"] == "wrong" for r in rows) else "typo"
        out.append(Problem(ids, verdict, tuple(link for link in found if link[0] in ids)))
    return out


def tally(ledger, transcription=None):
    """The counts Part I states: failing rows, and independent problems by verdict.

    Returns
    -------
    dict
        ``rows`` (failing rows), ``problems``, ``wrong``, ``typo`` (independent problems), ``merged``
        (rows merged into another).
    """
    ps = problems(ledger, transcription)
    rows = sum(len(p.rows) for p in ps)
    return {
        "rows": rows,
        "problems": len(ps),
        "wrong": sum(p.verdict == "wrong" for p in ps),
        "typo": sum(p.verdict == "typo" for p in ps),
        "merged": rows - len(ps),
    }
