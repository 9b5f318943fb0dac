"""The transcription (edition/printed.toml): complete, read without side effects, faithful to the extraction.

The table is data: these tests check what a reviewer of one text file cannot see at a glance --
that every equation is there once, that every SymPy form reads against the paper's symbols (a
misspelt name is an error, never a new symbol), that what it says the extraction shows is in the
extraction verbatim, that its prose follows the text rules, and that the published ledger quotes it.
"""

from __future__ import annotations

import csv
import os
import re
from pathlib import Path

import pytest
import sympy as sp
from prose import ascii_math

from edition import symbols as S
from edition.ledger import EQUATIONS
from edition.transcription import TABLE, TranscriptionError, claim, load, printed, table

ROOT = Path(__file__).resolve().parents[2]
#: the paper's text extraction (not in the repository): $WMR_PAPER_TEXT, else the shared copy of this machine
PAPER = Path(os.environ.get("WMR_PAPER_TEXT", "/work/shared/paper/leow-low-loh-2002-wmr-kinematics.md"))


def test_every_equation_once_in_order_with_its_section():
    eqs = table().equations
    assert tuple(eqs) == EQUATIONS
    for id, p in eqs.items():
        assert p.id == id and re.fullmatch(r"[3-5](\.\d){1,2}", p.section), (id, p.section)
        assert p.latex and "$" not in p.latex and p.extracted, id
    assert [printed(n).section for n in (2, 6, 20, 28, 30, 51, 52, 54, 60, 61)] == [
        "3.1",
        "3.2",
        "4.1",
        "4.2",
        "4.3",
        "5.1",
        "5.2",
        "5.3",
        "5.4.1",
        "5.4.2",
    ]


def test_the_sympy_forms_use_the_papers_symbols():
    """Every free symbol of a printed form is a symbol of edition.symbols (no stray name crept in)."""
    known = set()
    for v in vars(S).values():
        for x in v if isinstance(v, tuple) else (v,):
            if isinstance(x, (sp.Basic, sp.MatrixBase)):
                known |= {x} if isinstance(x, (sp.Symbol, sp.MatrixSymbol)) else set(x.free_symbols)
    for id, p in table().equations.items():
        forms = [p.expr, *[v for v in p.extra.values() if isinstance(v, (sp.Basic, sp.MatrixBase, tuple))]]
        free = set()
        for f in forms:
            for x in f if isinstance(f, tuple) else (f,):
                if isinstance(x, (sp.Basic, sp.MatrixBase)):
                    free |= {a for a in sp.sympify(x).atoms(sp.Symbol, sp.MatrixSymbol)}
        assert free <= known, (id, free - known)
    assert printed(26).expr is None and printed(29).expr is None  # statements checked through their consequences


def test_identities_are_never_decided_when_read():
    eq11 = printed(11).expr
    assert isinstance(eq11, sp.Equality) and eq11.lhs == S.R_bwi
    assert isinstance(printed(46).expr, sp.Equality)  # Eq(d, r) stays a statement
    names = table().names
    assert isinstance(names["Eq"](S.d, S.d), sp.Equality)  # even a trivially true one
    assert isinstance(names["Eq"](sp.Matrix([1]), sp.Matrix([2])), sp.Equality)  # and a false one


def test_the_rotation_of_11_is_written_once():
    text = TABLE.read_text(encoding="utf-8")
    assert text.count("cos(angle)") == 2 and text.count("-sin(angle)") == 1  # in [notation] R only
    R = table().names["R"]
    assert printed(11).expr.rhs == R(S.beta_i)
    assert printed(10).expr.rhs == R(S.beta_i) * sp.Matrix([-S.d * S.phi_dot_i, -S.r * S.theta_dot_i])
    assert printed(41).expr.rhs.args[0] == R(S.beta_i)


def test_the_extraction_is_quoted_verbatim():
    """What the table says the extraction shows is in the extraction, character for character."""
    if not PAPER.is_file():
        pytest.skip(f"the paper's text extraction is not on this machine ({PAPER}; set WMR_PAPER_TEXT)")
    text = PAPER.read_text(encoding="utf-8")
    missing = [(id, f[:60]) for id, p in table().equations.items() for f in p.extracted if f not in text]
    missing += [(slug, f[:60]) for slug, c in table().claims.items() for f in c.extracted if f not in text]
    assert not missing
    for id, p in table().equations.items():  # and one of its fragments is the display numbered id
        after = [f + text[text.index(f) + len(f) :][:40] for f in p.extracted]
        assert any(rf"\tag{{{id}}}" in a or f"({id})" in a for a in after), id


def test_the_doubts_name_what_the_extraction_shows():
    """A doubt says what the extraction shows; the three readings the extraction cannot settle say so."""
    for id, what in (("13", r"\dot{\mathbf{j}}_{i}"), ("15", r"\frac{r}{2h}"), ("21", r"\dot{\phi}_2 & \dot{\phi}_2")):
        p = printed(id)
        assert any(what in f for f in p.extracted), id
        assert "cannot be told from the extraction" in p.doubt, id


def test_the_prose_of_the_transcription_follows_the_text_rules():
    bad = {f"claim {c.slug}": ascii_math(c.text) for c in table().claims.values()}
    bad |= {f"({p.id}) doubt": ascii_math(p.doubt) for p in table().equations.values()}
    assert not {k: v for k, v in bad.items() if v}
    for c in table().claims.values():
        assert "$" in c.text and c.extracted, c.slug


def test_the_published_ledger_quotes_the_table():
    with open(ROOT / "figures" / "ledger.csv", newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        src = printed(r["id"]) if r["kind"] == "equation" else claim(r["id"])
        assert r["section"] == src.section, r["id"]
        assert r["printed"] == (src.latex if r["kind"] == "equation" else src.text), r["id"]
    assert {r["id"] for r in rows if r["kind"] == "claim"} == set(table().claims)


GOOD = """\
[notation]
twice = "lambda x: 2*x"
[equation.8]
section = "3.2"
latex = '\\phi_i = \\psi + \\beta_i'
sympy = "Eq(phi_i, twice(psi) + beta_i)"
extracted = "x"
[claim.c]
title = "the claim"
section = "1"
text = "a claim"
"""


@pytest.mark.parametrize(
    "edit, words",
    [
        (("twice(psi)", "twice(psii)"), ["equation.8.sympy", "psii", "NameError"]),  # a misspelt symbol
        (("sympy =", "sympi ="), ["equation.8", "unknown keys ['sympi']"]),
        (("latex = ", "lates = "), ["equation.8", "unknown keys"]),
        (('section = "3.2"\n', ""), ["equation.8", "'section' is missing"]),
        (("twice = ", "beta = "), ["notation.beta", "defined already"]),  # a notation hiding a symbol
        (("Eq(phi_i, twice(psi) + beta_i)", "Eq(phi_i,"), ["equation.8.sympy", "cannot read"]),
        (("[claim.c]", '[claim.c]\nsource = "x"'), ["claim.c", "unknown keys ['source']"]),
        (('title = "the claim"\n', ""), ["claim.c", "'title' is missing"]),  # named by its slug
        (('extracted = "x"', 'extracted = ["x", 3]'), ["equation.8.extracted"]),
        (("[equation.8]", "[equations.8]"), ["top level", "equations"]),
    ],
)
def test_a_bad_table_is_an_error_naming_the_entry(tmp_path, edit, words):
    path = tmp_path / "t.toml"
    path.write_text(GOOD, encoding="utf-8")
    t = load(path)
    assert t.equations["8"].expr == sp.Eq(S.phi_i, 2 * S.psi + S.beta_i) and t.claims["c"].text == "a claim"
    path.write_text(GOOD.replace(*edit), encoding="utf-8")
    with pytest.raises(TranscriptionError) as exc:
        load(path)
    assert all(w in str(exc.value) for w in words) and str(path) in str(exc.value), str(exc.value)


def test_unknown_ids_are_errors():
    with pytest.raises(ValueError, match=r"\(66\) is not transcribed"):
        printed(66)
    with pytest.raises(ValueError, match="'drift2' is not transcribed"):
        claim("drift2")


def test_reading_the_table_has_no_side_effect():
    """Importing the edition does not read the table; reading it twice gives equal records."""
    import subprocess
    import sys

    code = "import edition, edition.transcription as T, edition.checks; print(T.table.cache_info().currsize)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    assert out.stdout.strip() == "0"
    assert load().equations["59"].latex == printed(59).latex
