"""wmr.paper.ledger: recording verdicts, writing fragments, merging and reporting problems."""
import math

import pytest

from wmr.paper import ledger as LG


def full_ledger(notebook="nb", skip=()):
    led = LG.Ledger(notebook)
    for e in LG.EQUATIONS:
        if e not in skip:
            led.add(e, "s", "ok", f"eq {e}")
    return led


def test_add_records_a_row():
    led = LG.Ledger("01_x")
    row = led.add(59, "4", "typo", r"\det J = ...", corrected=r"r^3 \det J", convention="paper numbering",
                  symbolic_check=True, max_residual=1.5e-16, note="r = 1 in print")
    assert row["id"] == "59" and row["symbolic_check"] == "pass" and row["max_residual"] == "1.500e-16"
    assert row["notebook"] == "01_x" and set(row) == set(LG.COLUMNS)
    assert led.add("claim-x", "5", "wrong", "p", corrected="c", symbolic_check=False)["symbolic_check"] == "fail"
    table = led.table()
    assert list(table.columns) == list(LG.COLUMNS) and len(table) == 2


@pytest.mark.parametrize("kwargs, words", [
    (dict(verdict="maybe"), ["verdict", "'maybe'"]),
    (dict(verdict="typo"), ["'5'", "corrected"]),
    (dict(verdict="wrong", corrected="   "), ["'5'", "corrected"]),
    (dict(max_residual=math.nan), ["max_residual", "NaN"]),
    (dict(symbolic_check="fail"), ["symbolic_check", "'fail'"]),
])
def test_add_rejects_bad_rows(kwargs, words):
    args = dict(id="5", section="2", verdict="ok", printed="x")
    args.update(kwargs)
    with pytest.raises(ValueError) as exc:
        LG.Ledger("nb").add(**args)
    assert all(w in str(exc.value) for w in words), str(exc.value)


def test_duplicate_id_rejected():
    led = LG.Ledger("nb")
    led.add("7", "2", "ok", "x")
    with pytest.raises(ValueError, match="'7'.*already"):
        led.add(7, "2", "ok", "y")


def test_write_read_round_trip(tmp_path):
    led = LG.Ledger("02_y")
    led.add("20", "3", "ok", "a, with comma", note='quote " inside')
    led.add("29", "3", "wrong", "b", corrected="c\nsecond line")
    path = led.write(tmp_path)
    assert path == tmp_path / "ledger" / "02_y.csv"
    assert not list((tmp_path / "ledger").glob("*.tmp"))
    assert LG.read(path) == led.rows


def test_output_dir_env(monkeypatch, tmp_path):
    monkeypatch.setenv("WMR_FIGURES", str(tmp_path))
    assert LG.output_dir() == tmp_path
    path = full_ledger("only").write()
    assert path.parent == tmp_path / "ledger"
    monkeypatch.delenv("WMR_FIGURES")
    assert LG.output_dir().name == "figures"


def test_merge_orders_and_reports(tmp_path):
    a, b = LG.Ledger("a"), LG.Ledger("b")
    for e in ("10", "2", "claim-z"):
        a.add(e, "s", "ok", "p")
    b.add("3", "s", "ok", "p", symbolic_check=False)
    b.add("claim-a", "s", "ok", "p")
    b.add("10", "s", "ok", "again")
    a.write(tmp_path)
    b.write(tmp_path)
    path, rows, probs = LG.merge(tmp_path)
    assert path == tmp_path / "ledger.csv" and LG.read(path) == rows
    assert [r["id"] for r in rows] == ["2", "3", "10", "10", "claim-a", "claim-z"]
    text = "\n".join(probs)
    assert "missing equations: 4 5" in text and "duplicated rows: 10" in text and "row 3: failing check" in text


def test_problems_on_hand_edited_rows():
    rows = [dict(r, verdict="typo", corrected="") if r["id"] == "8" else r for r in full_ledger().rows]
    rows[0]["verdict"] = "fine"
    probs = LG.problems(rows)
    assert any("row 8: judged typo without a corrected form" in p for p in probs)
    assert any("row 2: bad verdict 'fine'" in p for p in probs)


def test_main_exit_status(tmp_path, capsys):
    full_ledger().write(tmp_path)
    assert LG.main([str(tmp_path)]) == 0
    assert "ledger: 64 rows" in capsys.readouterr().out
    LG.Ledger("extra").write(tmp_path)
    bad = LG.Ledger("bad")
    bad.add("claim", "s", "ok", "p", symbolic_check=False)
    bad.write(tmp_path)
    assert LG.main([str(tmp_path)]) == 1
    assert "failing check" in capsys.readouterr().err


def test_merge_creates_missing_directory(tmp_path):
    path, rows, probs = LG.merge(tmp_path / "new")
    assert path.exists() and rows == [] and probs == ["missing equations: " + " ".join(LG.EQUATIONS)]
