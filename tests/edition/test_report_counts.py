"""Every count the PDF states about the singular families and the independent problems is a cell of the computed
table (issue 30): the text is read from build/report.pdf (pdftotext), the counts from edition.families.count_table
over figures/singularities.csv and from edition.problems.tally over figures/ledger.csv.

Each rule is also run on a small text that breaks it, so that it can fail."""

from __future__ import annotations

import csv
import re
import shutil
import subprocess
import unicodedata

import pytest
from test_report import BUILD, HAVE_TEX, TREE, make

from edition.families import count_table
from edition.problems import tally

HAVE_POPPLER = bool(shutil.which("pdftotext"))

_NUMBER = "none no one two three four five six seven eight nine ten eleven twelve".split()
_N = r"(none|no|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|\d+)"


def number(word: str) -> int:
    w = word.lower()
    if w.isdigit():
        return int(w)
    return 0 if w in ("none", "no") else _NUMBER.index(w) - 1


def prose(text: str) -> str:
    """The PDF text as running prose: hyphenation at line ends undone, whitespace collapsed."""
    text = unicodedata.normalize("NFKC", text)
    text = re.sub(r"(\w)-\n\s*(\w)", r"\1\2", text)
    return re.sub(r"\s+", " ", text)


def family_counts_stated(text: str) -> dict[str, list]:
    """What a text states about the singular families: (covered, missed) pairs, missed counts, family totals."""
    t = prose(text)
    pairs = [(number(a), number(b)) for a, b in re.findall(rf"covers {_N} and misses {_N}\b", t, re.I)]
    missed = [number(a) for a in re.findall(rf"misses {_N}\b(?! *(?:of|and|\w+ing))", t, re.I)]
    missed += [
        number(a) for a in re.findall(rf"\b{_N} (?:of them )?(?:that |which )?the (?:paper|list) misses", t, re.I)
    ]
    totals = [number(a) for a in re.findall(rf"finds {_N} famil", t, re.I)]
    upto = re.findall(r"right up to item \(i\)|including one the paper misses", t, re.I)
    return {"pairs": pairs, "missed": missed, "totals": totals, "unqualified": upto}


def family_count_errors(text: str, table: list[dict]) -> list[str]:
    stated = family_counts_stated(text)
    cells = {(t["covered"], t["missed"]) for t in table}
    bad = [f"covers/misses {p}: not a cell of the table {sorted(cells)}" for p in stated["pairs"] if p not in cells]
    bad += [f"misses {m}: no reading gives it" for m in stated["missed"] if m not in {t["missed"] for t in table}]
    bad += [
        f"{n} families: the catalogue has {table[0]['families']}" for n in stated["totals"] if n != table[0]["families"]
    ]
    bad += [f"a count without its reading: {u!r}" for u in stated["unqualified"]]
    missing = cells - set(stated["pairs"])
    bad += [f"the reading with covered/missed {m} is never stated" for m in sorted(missing)]
    return bad


def problem_count_errors(text: str, t: dict) -> list[str]:
    p = prose(text)
    bad = []
    # case-sensitive: the prose says "independent problems"; a heading "Independent problems" after a folio is no count
    for a in re.findall(rf"\b{_N} independent problems?\b", p):
        if number(a) != t["problems"]:
            bad.append(f"{a} independent problems: computed {t['problems']}")
    for a in re.findall(rf"\b{_N} of substance\b", p, re.I):
        if number(a) != t["wrong"]:
            bad.append(f"{a} of substance: computed {t['wrong']}")
    if not re.search(rf"\b{_N} independent problems?\b", p):
        bad.append("the number of independent problems is never stated")
    return bad


# ----------------------------------------------------------------------------- the rules can fail
TABLE = [
    {"covered": 7, "missed": 3, "families": 10},
    {"covered": 10, "missed": 0, "families": 10},
    {"covered": 4, "missed": 3, "families": 7},
    {"covered": 7, "missed": 0, "families": 7},
]
GOOD = (
    "finds ten families; it covers seven and misses three when, and covers ten and misses none when it may; "
    "counting only, it covers four and misses three, and covers seven and misses none when it may."
)


def test_the_rules_can_fail():
    assert family_count_errors(GOOD, TABLE) == []
    assert family_count_errors(GOOD + " The list covers seven of them and misses two.", TABLE)
    assert family_count_errors(GOOD.replace("ten families", "eleven families"), TABLE)
    assert family_count_errors(GOOD + " The list is right up to item (i).", TABLE)
    assert family_count_errors(GOOD + " including one the paper misses", TABLE)
    assert family_count_errors("finds ten families; it covers seven and misses three", TABLE)  # readings unstated
    t = {"problems": 13, "wrong": 9}
    assert problem_count_errors("they are 13 independent problems: nine of substance", t) == []
    assert problem_count_errors("they are twelve independent problems: nine of substance", t)
    assert problem_count_errors("13 independent problems: eight of sub-\nstance", t)
    assert problem_count_errors("no count here", t)
    assert problem_count_errors("13 independent problems; nine of substance. 12 Independent problems", t) == []


# ----------------------------------------------------------------------------- the report
@pytest.fixture(scope="module")
def pdf_text():
    if not (HAVE_TEX and HAVE_POPPLER):
        pytest.skip("xelatex, pandoc or poppler missing")
    make(str(BUILD / "report.pdf"))
    return subprocess.run(
        ["pdftotext", str(BUILD / "report.pdf"), "-"], capture_output=True, text=True, check=True
    ).stdout


def _csv(name):
    with open(TREE / "figures" / name, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def test_every_family_count_in_the_pdf_is_a_cell_of_the_computed_table(pdf_text):
    table = count_table(_csv("singularities.csv"))
    bad = family_count_errors(pdf_text, table)
    assert not bad, f"{len(bad)} family counts that disagree with the computed table: {bad[:12]}"


def test_every_problem_count_in_the_pdf_is_the_computed_one(pdf_text):
    bad = problem_count_errors(pdf_text, tally(_csv("ledger.csv")))
    assert not bad, f"{len(bad)} counts of independent problems that disagree with edition.problems: {bad[:12]}"


def test_every_scoped_verdict_carries_its_label_in_the_pdf(pdf_text):
    text = prose(pdf_text)
    rows = [r for r in _csv("ledger.csv") if r.get("scope")]
    assert {r["scope"].split(":")[0] for r in rows} >= {"presupposition fails", "terminology", "special case"}
    bad = [r["id"] for r in rows if f"{r['verdict']} ({r['scope'].split(':')[0]})" not in text]
    assert not bad, f"verdicts shown without the label of their scope: {bad}"


# ----------------------------------------------------------------------------- physics counts, cards, claim names
def physics_count_errors(text: str, t: dict) -> list[str]:
    """The physics counts a text states (the paper's claims and this edition's predictions apart) against ``t``
    (:func:`edition.physics.tally`)."""
    p = prose(text)
    bad = []
    for tested, held in re.findall(rf"Of the {_N} claims of the paper tested there, {_N} holds?", p):
        if (number(tested), number(held)) != (t["paper"]["tested"], t["paper"]["hold"]):
            bad.append(f"paper: {tested} tested, {held} hold; computed {t['paper']}")
    for tested, held in re.findall(
        rf"of the {_N} predictions? of this edition's own tested there[^,]*, {_N} holds?", p
    ):
        if (number(tested), number(held)) != (t["edition"]["tested"], t["edition"]["hold"]):
            bad.append(f"edition: {tested} tested, {held} hold; computed {t['edition']}")
    for held, tested in re.findall(rf"\b{_N} of {_N} of the paper's claims hold", p):
        if (number(tested), number(held)) != (t["paper"]["tested"], t["paper"]["hold"]):
            bad.append(f"chapter 9: {held} of {tested} of the paper's claims; computed {t['paper']}")
    if not re.search(rf"Of the {_N} claims of the paper tested there", p):
        bad.append("the physics counts are never stated")
    return bad


def card_errors(text: str, problems: int, experiments: list[str]) -> list[str]:
    """Cards missing from a text: one per independent problem and one per physics experiment, each with its
    four fields."""
    p = prose(text)
    bad = [f"no card for problem {k}" for k in range(1, problems + 1) if f"Problem {k}:" not in p]
    bad += [
        f"no card for the physics experiment {e}" for e in experiments if f"Physics: {e.replace('-', ' ')}," not in p
    ]
    for field in ("Claim:", "Readings:", "Depends on:", "Would overturn it:"):
        if p.count(field) < problems + len(experiments):
            bad.append(f"{p.count(field)} cards have the field {field!r}, {problems + len(experiments)} expected")
    return bad


def truncated_names(text: str) -> list[str]:
    """Claims named by a quotation cut short: an opening quote whose text ends in an ellipsis."""
    return re.findall(r"“[^”]{0,80}(?:…|\.\.\.)”", prose(text))


def test_the_physics_and_card_rules_can_fail():
    t = {"paper": {"tested": 5, "hold": 4}, "edition": {"tested": 2, "hold": 1}}
    good = (
        "Of the five claims of the paper tested there, four hold and one does not; of the two predictions of this "
        "edition's own tested there (counted apart), one holds. 4 of 5 of the paper's claims hold in MuJoCo."
    )
    assert physics_count_errors(good, t) == []
    assert physics_count_errors(good.replace("five claims", "six claims"), t)
    assert physics_count_errors(good.replace("one holds", "two hold"), t)
    assert physics_count_errors(good.replace("4 of 5", "5 of 7"), t)
    cards = "Problem 1: x Claim: Readings: Depends on: Would overturn it: Physics: dead zone, y Claim: Readings: "
    assert card_errors(cards + "Depends on: Would overturn it:", 1, ["dead-zone"]) == []
    assert card_errors(cards, 1, ["dead-zone"])
    assert card_errors(cards + "Depends on: Would overturn it:", 2, ["dead-zone"])
    assert truncated_names("the claim “Equations (28) and (29) reveal a drift …” fails")
    assert not truncated_names("the claim drift when steering without driving fails; “a whole quotation.”")


def test_physics_counts_in_the_pdf_are_the_computed_ones(pdf_text):
    from edition import physics

    bad = physics_count_errors(pdf_text, physics.tally(_csv("physics.csv")))
    assert not bad, f"physics counts that disagree with figures/physics.csv: {bad}"


def test_every_finding_has_its_card_in_the_pdf(pdf_text):
    bad = card_errors(pdf_text, tally(_csv("ledger.csv"))["problems"], [r["experiment"] for r in _csv("physics.csv")])
    assert not bad, bad


def test_no_claim_is_named_by_a_truncated_quotation(pdf_text):
    cut = truncated_names(pdf_text)
    assert not cut, f"claims named by quotations cut short: {cut[:5]}"


# ----------------------------------------------------------------------------- the verdict counts
def verdict_counts(rows: list[dict]) -> dict[str, dict[str, int]]:
    """Equations and claims of a ledger, counted by verdict (and in all)."""
    out = {}
    for kind in ("equation", "claim"):
        group = [r for r in rows if r["kind"] == kind]
        out[kind] = {v: sum(r["verdict"] == v for r in group) for v in ("ok", "typo", "wrong")} | {"all": len(group)}
    return out


def verdict_count_errors(text: str, c: dict) -> list[str]:
    """Every sentence of a text that counts verdicts, against ``c`` (:func:`verdict_counts`); each must be found."""
    p = prose(text)
    e, k = c["equation"], c["claim"]
    rules = [  # (pattern, what its numbers must be)
        (
            rf"Of those judged, {_N} holds? as printed, {_N} carr(?:y|ies) a typo and {_N} (?:is|are) wrong",
            (e["ok"], e["typo"], e["wrong"]),
        ),
        (
            rf"Of the {_N} claims? of its text that this edition checks by computation, {_N} holds?, {_N} holds? once "
            rf"corrected and {_N} fails?",
            (k["all"], k["ok"], k["typo"], k["wrong"]),
        ),
        (
            rf"{_N} equations? of the paper do(?:es)? not hold as printed \({_N} typo, {_N} wrong\)",
            (e["typo"] + e["wrong"], e["typo"], e["wrong"]),
        ),
        (rf"Of the {_N} such claims this edition checks by computation, {_N} (?:is|are) false", (k["all"], k["wrong"])),
        (
            rf"{_N} of the {_N} numbered equations judged holds? as printed, and {_N} more",
            (e["ok"], e["all"], e["typo"]),
        ),
        (rf"Of the claims of its text, {_N} holds?", (k["ok"],)),
        (rf"{_N} equations? (?:is|are) wrong", (e["wrong"],)),
        (rf"{_N} claims? of the text fails?", (k["wrong"],)),
        (rf"{_N} claims? holds? once", (k["typo"],)),
        (
            r"(\d+) numbered equations, derived and judged \((\d+) ok, (\d+) typo, (\d+) wrong",
            (e["all"], e["ok"], e["typo"], e["wrong"]),
        ),
    ]
    bad = []
    for pattern, expected in rules:
        found = re.findall(pattern, p, re.I)
        if not found:
            bad.append(f"never stated: {pattern[:50]!r}")
        for m in found:
            got = tuple(number(x) for x in ((m,) if isinstance(m, str) else m))
            if got != expected:
                bad.append(f"{pattern[:40]!r}: stated {got}, computed {expected}")
    for n, ok, typo, wrong in re.findall(r"\b(\d+): (\d+) ok, (\d+) typo, (\d+) wrong", p):  # the table of counts
        if (int(n), int(ok), int(typo), int(wrong)) not in {
            tuple(x[v] for v in ("all", "ok", "typo", "wrong")) for x in (e, k)
        }:
            bad.append(f"table cell {n}: {ok} ok, {typo} typo, {wrong} wrong: not a computed count")
    return bad


def test_the_verdict_count_rule_can_fail():
    c = {"equation": {"ok": 2, "typo": 1, "wrong": 1, "all": 4}, "claim": {"ok": 1, "typo": 0, "wrong": 1, "all": 2}}
    good = (
        "Of those judged, two hold as printed, one carries a typo and one is wrong. Of the two claims of its text "
        "that this edition checks by computation, one holds, no holds once corrected and one fails. Two equations of "
        "the paper do not hold as printed (one typo, one wrong). Of the two such claims this edition checks by "
        "computation, one is false. Two of the four numbered equations judged hold as printed, and one more. Of the "
        "claims of its text, one holds. One equation is wrong. One claim of the text fails. No claims hold once. "
        "4 numbered equations, derived and judged (2 ok, 1 typo, 1 wrong; 4: 2 ok, 1 typo, 1 wrong"
    )
    assert verdict_count_errors(good, c) == []
    assert verdict_count_errors(good.replace("One equation is wrong", "Two equations are wrong"), c)
    assert verdict_count_errors(good.replace("4: 2 ok", "4: 3 ok"), c)
    assert verdict_count_errors(good.replace("Of the claims of its text, one holds.", ""), c)


def test_every_verdict_count_in_the_pdf_is_the_ledgers(pdf_text):
    bad = verdict_count_errors(pdf_text, verdict_counts(_csv("ledger.csv")))
    assert not bad, f"{len(bad)} verdict counts that disagree with figures/ledger.csv: {bad[:10]}"
