"""edition.ledger: verdicts computed from findings, a chapter's rows, assembling the ledger, the text of its rows."""

import csv
import math
from pathlib import Path

import pytest
from prose import ascii_math, row_problems

from edition import ledger as LG
from edition.ledger import Finding

LEDGER = Path(__file__).resolve().parents[2] / "figures" / "ledger.csv"


def ok(id, **kw):
    return Finding(str(id), True, "the printed form is proven (SymPy)", 0.0, **kw)


def refuted(id, **kw):
    args = dict(
        corrected=r"\dot\phi_i = x",
        corrected_holds=True,
        severity="wrong",
        why="it is off by $\\dot\\psi$",
        overturn="reading $\\beta_i$ as absolute",
    )
    args.update(kw)
    return Finding(str(id), False, "printed refuted; corrected proven", 1e-15, **args)  # type: ignore[arg-type]


def full_ledger(notebook="nb"):
    led = LG.Ledger(notebook)
    for e in LG.EQUATIONS:
        led.add(ok(e))
    return led


def test_verdict_is_computed_from_the_finding():
    assert LG.grade(ok(2)) == "ok"
    assert LG.grade(refuted(15)) == "wrong"
    assert LG.grade(refuted(42, severity="typo")) == "typo"
    # a changed transcription that now holds re-grades the row, whatever severity the check names
    assert LG.grade(Finding("42", True, "proven", 0.0, corrected="d^2", corrected_holds=True, severity="typo")) == "ok"


@pytest.mark.parametrize(
    "kw, words",
    [
        (dict(corrected=""), ["(15)", "refuted", "no corrected form"]),
        (dict(corrected_holds=False), ["(15)", "no corrected form was proven"]),
        (dict(severity="maybe"), ["(15)", "severity", "'maybe'"]),
        (dict(why=""), ["(15)", "why"]),
        (dict(overturn=" "), ["(15)", "overturn"]),
    ],
)
def test_refuted_without_proof_fails_loudly(kw, words):
    with pytest.raises(ValueError) as exc:
        LG.grade(refuted(15, **kw))
    assert all(w in str(exc.value) for w in words), str(exc.value)


def test_printed_holds_must_be_a_bool():
    with pytest.raises(TypeError, match="printed_holds"):
        LG.grade(Finding("2", "yes", "x", 0.0))  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="Finding"):
        LG.grade({"id": "2"})


def test_row_has_the_contract_columns_and_the_transcribed_text():
    from edition.transcription import claim, printed

    led = LG.Ledger("01_x")
    row = led.add(refuted(15, severity="wrong"))
    assert tuple(row) == LG.COLUMNS
    assert row["kind"] == "equation" and row["section"] == printed(15).section and row["printed"] == printed(15).latex
    assert row["verdict"] == "wrong" and row["printed_holds"] == "no" and row["anchor"] == "eq-15"
    assert row["residual"] == "< 1e-12" and row["notebook"] == "01_x"
    c = led.add(Finding("drift", True, "proven", 2.5e-7))
    assert c["kind"] == "claim" and c["printed"] == claim("drift").text and c["anchor"] == "claim-drift"
    assert c["residual"] == "2.5e-07" and c["corrected"] == "" and c["why"] == ""


def test_ok_rows_drop_a_stale_correction():
    row = LG.Ledger("nb").add(
        Finding("42", True, "proven", 0.0, corrected="d^2", corrected_holds=True, severity="typo", why="sign")
    )
    assert row["verdict"] == "ok" and row["corrected"] == "" and row["why"] == ""


@pytest.mark.parametrize(
    "finding, words",
    [
        (Finding("2", True, "ok", math.nan), ["residual", "nan"]),
        (Finding("2", True, "ok", -1.0), ["residual", "-1.0"]),
        (Finding("99", True, "ok", 0.0), ["(99)", "not transcribed"]),
        (Finding("no-such-claim", True, "ok", 0.0), ["no-such-claim", "not transcribed"]),
    ],
)
def test_bad_rows_are_rejected_with_the_reason(finding, words):
    with pytest.raises(ValueError) as exc:
        LG.Ledger("nb").add(finding)
    assert all(w in str(exc.value) for w in words), str(exc.value)


@pytest.mark.parametrize(
    "finding, words",
    [
        (Finding("2", True, "holds for psi_dot != 0", 0.0), ["check", "psi_dot", "!="]),
        (Finding("2", True, "J^T J = 3*1", 0.0), ["check", "^T", "*"]),
        (Finding("2", True, "ok", 0.0, convention="kappa <= 2"), ["convention", "Greek", "<="]),
        (
            Finding(
                "15",
                False,
                "refuted",
                0.0,
                corrected=r"$x$",
                corrected_holds=True,
                severity="typo",
                why="slip",
                overturn="a page",
            ),
            ["corrected", "'$'"],
        ),
    ],
)
def test_the_text_rules_find_pseudo_math_in_a_row(finding, words):
    """The rule the tests apply to the published ledger: each offence is named with its field."""
    row = LG.Ledger("nb").add(finding)
    found = "; ".join(row_problems(row))
    assert all(w in found for w in words), found
    assert row_problems(LG.Ledger("nb").add(ok(2))) == []


def test_math_in_dollars_is_not_ascii_math():
    assert ascii_math(r"holds for $\dot\psi \neq 0$ and $\mathbf J^{\mathrm T}$ with `psi_dot` in code") == []
    assert ascii_math("the numeric check and a nucleus") == []  # words that start like Greek names
    assert ascii_math("beta_1 and kappa") and ascii_math("a <=> b")


def test_duplicate_id_rejected():
    led = LG.Ledger("nb")
    led.add(ok(7))
    with pytest.raises(ValueError, match="'7'.*already"):
        led.add(ok(7))


def test_sentence_is_generated_from_the_row():
    led = LG.Ledger("nb")
    s = led.add(refuted(15, convention=r"$\beta_i$ relative")).sentence()
    assert s.startswith("**Verdict (15): wrong.** It is off by $\\dot\\psi$.")
    assert r"\tag*{(15) corrected}" in s and r"\dot\phi_i = x" in s and "*Convention:* $\\beta_i$ relative." in s
    assert led.add(ok(2)).sentence().startswith("**Verdict (2): ok.** The printed form is proven (SymPy).")


def test_write_read_round_trip(tmp_path):
    led = LG.Ledger("02_y")
    led.add(ok(20, note='a "quoted", comma'))
    led.add(refuted(29))
    path = led.write(tmp_path)
    assert path == tmp_path / "ledger.csv"
    assert not list(tmp_path.glob("*.tmp")) and not list(tmp_path.glob(".*"))
    assert LG.read(path) == [dict(r) for r in led.rows]
    with pytest.raises(TypeError, match="directory"):
        led.write(None)


def test_assemble_orders_the_rows_of_all_chapters(tmp_path):
    a, b = LG.Ledger("a"), LG.Ledger("b")
    for e in LG.EQUATIONS[::2]:
        a.add(ok(e))
    a.add(Finding("drift", True, "ok", 0.0))
    for e in LG.EQUATIONS[1::2]:
        b.add(ok(e))
    b.add(Finding("omnidirectional", True, "ok", 0.0))
    pa, pb = a.write(tmp_path / "out" / "a"), b.write(tmp_path / "out" / "b")
    dest = tmp_path / "ledger.csv"
    rows = LG.assemble(tmp_path / "out", dest)  # a folder of chapter folders (the build's)
    assert LG.read(dest) == rows
    assert [r["id"] for r in rows] == list(LG.EQUATIONS) + ["drift", "omnidirectional"]
    assert [r["notebook"] for r in rows[:3]] == ["a", "b", "a"]
    assert LG.assemble([pb, tmp_path / "out" / "a"], dest) == rows  # files or chapter folders, any order
    assert LG.fragments([pa, tmp_path / "out"]) == [pa, pb]  # each file once


def test_assemble_reports_every_problem_and_writes_nothing(tmp_path):
    a, b = LG.Ledger("a"), LG.Ledger("b")
    for e in ("10", "2"):
        a.add(ok(e))
    b.add(ok(3))
    b.add(ok(10))
    a.write(tmp_path / "out" / "a")
    b.write(tmp_path / "out" / "b")
    (tmp_path / "out" / "c").mkdir()
    (tmp_path / "out" / "c" / "ledger.csv").write_text("id,verdict\n2,ok\n", encoding="utf-8")
    dest = tmp_path / "ledger.csv"
    with pytest.raises(LG.LedgerError) as exc:
        LG.assemble(tmp_path / "out", dest)
    text = str(exc.value)
    assert "missing equations: 1 4 5" in text and "duplicated rows: 10" in text
    assert "c/ledger.csv: columns ['id', 'verdict']" in text
    assert not dest.exists()
    with pytest.raises(FileNotFoundError, match="no-such"):
        LG.assemble(tmp_path / "no-such", dest)


def test_problems_on_hand_edited_rows():
    rows = [dict(r) for r in full_ledger().rows]
    rows[0]["verdict"] = "fine"
    rows[1]["verdict"] = "typo"
    rows[2]["anchor"] = "eq-x"
    del rows[3]["kind"]
    probs = "\n".join(LG.problems(rows))
    ids = [r["id"] for r in full_ledger().rows]
    assert f"row {ids[0]}: bad verdict 'fine'" in probs
    assert (
        f"row {ids[1]}: verdict 'typo' but printed_holds 'yes'" in probs
        and f"row {ids[1]}: judged typo without" in probs
    )
    assert f"row {ids[2]}: anchor 'eq-x'" in probs and f"row {ids[3]}: lacks the columns ['kind']" in probs


def test_main_exit_status(tmp_path, capsys):
    full_ledger().write(tmp_path / "out" / "full")
    args = [str(tmp_path / "out"), str(tmp_path / "ledger.csv")]
    assert LG.main(args) == 0
    assert f"ledger: {len(LG.EQUATIONS)} rows" in capsys.readouterr().out
    bad = LG.Ledger("bad")
    bad.add(ok(2))
    bad.write(tmp_path / "out" / "bad")
    assert LG.main(args) == 1
    assert "duplicated rows: 2" in capsys.readouterr().err


def test_main_needs_the_chapters_and_the_destination(tmp_path, capsys):
    assert LG.main([]) == 2 and LG.main([str(tmp_path)]) == 2
    assert "usage" in capsys.readouterr().err
    full_ledger().write(tmp_path / "out" / "01")
    dest = tmp_path / "ledger.csv"
    assert LG.main([str(tmp_path / "out"), str(dest)]) == 0 and dest.exists()
    before = dest.stat().st_mtime_ns
    # the same bytes: the file is left untouched
    assert LG.main([str(tmp_path / "out"), str(dest)]) == 0 and dest.stat().st_mtime_ns == before
    assert LG.main([str(tmp_path / "out" / "01" / "ledger.csv"), str(dest)]) == 0  # a chapter's file


def test_committed_ledger_is_complete_and_clean():
    """figures/ledger.csv (written by the build) has every equation, the contract's columns, computed verdicts."""
    with open(LEDGER, newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert list(rows[0]) == list(LG.COLUMNS)
    assert LG.problems(rows) == []
    for r in rows:
        if r["kind"] == "claim":
            assert "$" in r["printed"] and (r["verdict"] == "ok" or "$" in r["corrected"]), r["id"]


def test_committed_ledger_follows_the_text_rules():
    """No ASCII pseudo-math in the prose of the published ledger; no ``$`` in its LaTeX bodies."""
    with open(LEDGER, newline="", encoding="utf-8") as f:
        bad = {r["id"]: row_problems(r) for r in csv.DictReader(f)}
    assert not {k: v for k, v in bad.items() if v}


def test_a_scope_qualifies_only_the_verdicts_it_may():
    ok = Finding("2", True, "proven", 0.0, scope="special case: tested at mobility 1")
    row = LG.Ledger("nb").add(ok)
    assert LG.grade(ok) == "ok" and row["scope"].startswith("special case")
    assert "ok (special case)" in row.sentence() and "Tested at mobility 1." in row.sentence()
    with pytest.raises(ValueError, match="cannot qualify"):
        LG.grade(Finding("2", True, "proven", 0.0, scope="terminology: a word"))
    for bad in ("maybe: x", "special case", "special case:  "):
        with pytest.raises(ValueError, match="label"):
            LG.grade(Finding("2", True, "proven", 0.0, scope=bad))
    assert LG.scope_label("presupposition fails: x") == "presupposition fails"
