"""edition.problems: failing ledger rows merged into independent problems only where a computation shows one error."""

from __future__ import annotations

import csv
from pathlib import Path
from types import SimpleNamespace

import sympy as sp

from edition import problems as PR
from edition import symbols as S

ROOT = Path(__file__).resolve().parents[2]


def ledger():
    with open(ROOT / "figures" / "ledger.csv", newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def test_the_published_ledger_merges_16_into_15_and_the_placement_claim_into_38():
    rows = ledger()
    assert PR.links(rows) == [("15", "16", "integral"), ("38", "isotropy-placement", "counterexample")]
    t = PR.tally(rows)
    failing = [r for r in rows if r["verdict"] != "ok"]
    assert t["rows"] == len(failing) and t["problems"] == len(failing) - 2 and t["merged"] == 2
    assert t["wrong"] + t["typo"] == t["problems"]
    merged = {p.rows for p in PR.problems(rows) if len(p.rows) > 1}
    assert merged == {("15", "16"), ("38", "isotropy-placement")}


def _row(id, verdict, check, kind="equation"):
    return {"id": id, "kind": kind, "verdict": verdict, "check": check}


def _eq(expr):
    return SimpleNamespace(expr=expr)


def test_an_integral_is_merged_only_when_it_differentiates_into_the_other():
    rate = sp.Eq(S.beta_dot_i, S.r * S.theta_dot_i1)
    angle = sp.Eq(S.beta_i, S.r * S.theta_i1)
    other = sp.Eq(S.beta_i, 2 * S.r * S.theta_i1)  # not the integral of `rate`
    rows = [
        _row("a", "wrong", "printed form refuted (x); corrected form proven: y"),
        _row("b", "wrong", "printed form refuted (z); corrected form proven: y"),
    ]
    assert PR.links(rows, SimpleNamespace(equations={"a": _eq(rate), "b": _eq(angle)})) == [("a", "b", "integral")]
    assert PR.links(rows, SimpleNamespace(equations={"a": _eq(rate), "b": _eq(other)})) == []
    # a row that holds is never part of a problem
    rows[1]["verdict"] = "ok"
    assert PR.links(rows, SimpleNamespace(equations={"a": _eq(rate), "b": _eq(angle)})) == []


def test_a_shared_counterexample_merges_and_a_different_one_does_not():
    tr = SimpleNamespace(equations={})
    a = _row("a", "wrong", "printed form refuted ($P = (1, 2)$); corrected form proven: y")
    b = _row("c", "wrong", "claim refuted ($P = (1, 2)$); what is true, proven: z", kind="claim")
    c = _row("d", "typo", "claim refuted ($P = (1, 3)$); what is true, proven: z", kind="claim")
    assert PR.links([a, b, c], tr) == [("a", "c", "counterexample")]
    assert [p.rows for p in PR.problems([a, b, c], tr)] == [("a", "c"), ("d",)]
    assert PR.tally([a, b, c], tr) == {"rows": 3, "problems": 2, "wrong": 1, "typo": 1, "merged": 1}
