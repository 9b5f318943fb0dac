"""What a chapter derived for later ones (``figures/<chapter>.derived.json``, :mod:`edition.derivations`): the
committed file is what the chapter's derivation cells compute, the reader rebuilds it without running code and
refuses a tampered file, a build reads its own chapters' files first, and the Makefile runs a chapter after the
chapters it reads.

This test runs a chapter's ``imports`` and ``derivation`` cells itself (the chapters never run another's cells):
a later chapter's cells read the earlier chapter's committed file, so each file is checked given the one before.
"""

from __future__ import annotations

import ast
import json
import re
import subprocess
from pathlib import Path

import pytest
import sympy as sp

from edition import derivations as D

from conftest import ROOT

FILES = sorted((ROOT / "figures").glob("*.derived.json"))
CHAPTERS = [p.name.removesuffix(".derived.json") for p in FILES]


def cells(chapter, *tags):
    """The sources of the chapter's code cells with one of ``tags``, in order."""
    nb = json.loads((ROOT / "notebooks" / f"{chapter}.ipynb").read_text(encoding="utf-8"))
    return [
        "".join(c["source"])
        for c in nb["cells"]
        if c["cell_type"] == "code" and set(tags) & set(c.get("metadata", {}).get("tags", []))
    ]


def run_derivations(chapter):
    """The namespace after the chapter's ``imports`` and ``derivation`` cells, with nothing displayed."""
    namespace: dict = {"__name__": f"derivations_of_{chapter}"}
    for source in cells(chapter, "imports", "derivation"):
        exec(compile(source, f"{chapter}.ipynb", "exec"), namespace)
        namespace.update({f: (lambda *a, **k: None) for f in ("show", "say", "table", "quote")})
    return namespace


def saved_names(chapter):
    """``{name in the file: variable of the chapter}`` of the chapter's call ``ch.save_derived(name=variable, ...)``."""
    calls = [
        node
        for source in cells(chapter, "ledger")
        for node in ast.walk(ast.parse(source))
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "save_derived"
    ]
    assert len(calls) == 1, f"{chapter}: one ch.save_derived(...) in its ledger cell"
    assert all(isinstance(kw.value, ast.Name) for kw in calls[0].keywords), "each object a variable of the chapter"
    return {kw.arg: kw.value.id for kw in calls[0].keywords}  # type: ignore[attr-defined]


def test_the_chapters_that_are_read_publish_their_files():
    read = {
        c for p in (ROOT / "notebooks").glob("*.ipynb") for c in re.findall(r'derived\(\\"(\w+)\\"\)', p.read_text())
    }
    assert {"01_platform_and_wheels", "02_offset_wheels_and_mobility"} <= read <= set(CHAPTERS), (
        "a chapter another one reads publishes figures/<chapter>.derived.json"
    )
    assert "03_kinetostatic_isotropy" in CHAPTERS, "the tests read chapter 3's"


@pytest.mark.parametrize("chapter", CHAPTERS)
def test_the_committed_file_is_what_the_chapter_derives(chapter):
    """Byte for byte: the chapter's derivation cells (given the earlier chapters' committed files), the names its
    ``save_derived`` call lists, written as :func:`edition.derivations.dumps` writes them."""
    namespace = run_derivations(chapter)
    names = saved_names(chapter)
    committed = (ROOT / "figures" / D.filename(chapter)).read_text(encoding="utf-8")
    assert sorted(json.loads(committed)["objects"]) == sorted(names)
    assert D.dumps(chapter, {n: namespace[v] for n, v in names.items()}) == committed, (
        f"figures/{D.filename(chapter)} is not what {chapter} derives: make report publishes it again"
    )
    back = D.read(ROOT / "figures" / D.filename(chapter), chapter)
    assert all(back[n] == namespace[v] and type(back[n]) is type(namespace[v]) for n, v in names.items())


def tampered(text, name, replacement):
    data = json.loads(text)
    data["objects"][name] = replacement
    return json.dumps(data)


@pytest.mark.parametrize(
    "replacement, why",
    [
        ("__import__('os').system('touch {marker}')", "not a SymPy class"),
        ("Symbol('x').__class__", "not SymPy's srepr"),
        ("MutableDenseMatrix([[\"__import__('os').system('touch {marker}')\"]])", "not SymPy's srepr"),
        ("Add('x + 1', Integer(1))", "SymPy would parse it"),
        ("Function('f')(Symbol('x'), evaluate=sp)", "only True, False or an integer"),
        ("open('{marker}', 'w')", "not a SymPy class"),
        ("Integer(1) if True else Integer(2)", "not SymPy's srepr"),
        ("Integer(1", "never closed"),
        ("Integer(10000000000000000000000000)", "an integer of 26 digits"),
        ("Pow(Integer(10), Integer(1000000))", "the power 1000000"),
        ("factorial(Integer(1000000))", "not a SymPy class"),
    ],
)
def test_the_reader_refuses_a_tampered_file(tmp_path, replacement, why):
    """Code where an object's srepr should be is refused, and nothing of it runs."""
    marker = tmp_path / "ran"
    path = ROOT / "figures" / D.filename("01_platform_and_wheels")
    bad = tmp_path / path.name
    bad.write_text(tampered(path.read_text(encoding="utf-8"), "E", replacement.format(marker=marker)))
    with pytest.raises(ValueError, match=rf"{bad.name}: E: .*{why}"):
        D.read(bad, "01_platform_and_wheels")
    assert not marker.exists()


def test_the_reader_refuses_a_file_too_large_or_not_a_file(tmp_path):
    big = tmp_path / "big.derived.json"
    big.write_text(" " * (D.MAX_BYTES + 1))
    for path in (big, tmp_path):
        with pytest.raises(ValueError, match="not a regular file of at most"):
            D.read(path)


def test_the_reader_refuses_another_chapter_or_format(tmp_path):
    text = (ROOT / "figures" / D.filename("01_platform_and_wheels")).read_text(encoding="utf-8")
    with pytest.raises(ValueError, match="not of '02_offset_wheels_and_mobility'"):
        D.loads(text, "02_offset_wheels_and_mobility")
    with pytest.raises(ValueError, match="not a file of derived objects"):
        D.loads(text.replace(D.FORMAT, "pickle"))
    with pytest.raises(ValueError, match="not JSON"):
        D.loads(text[:-10])
    with pytest.raises(ValueError, match="not a name"):
        D.loads(tampered(text, "__class__.x", "Integer(1)"))


def test_what_does_not_read_back_exactly_is_not_written():
    with pytest.raises(ValueError, match="x: Dummy does not read back exactly"):
        D.dumps("ch", {"x": sp.Dummy("x")})
    with pytest.raises(ValueError, match="does not read back exactly"):
        D.dumps("ch", {"f": sp.sin})
    text = D.dumps("ch", {"q": [sp.Rational(1, 3), (2, -1.5)], "s": {sp.Symbol("a", positive=True): sp.pi * sp.I}})
    assert D.loads(text, "ch") == {
        "q": [sp.Rational(1, 3), (2, -1.5)],
        "s": {sp.Symbol("a", positive=True): sp.pi * sp.I},
    }
    t = sp.Symbol("t", real=True)
    assert D.loads(D.dumps("ch", {"d": sp.Function("psi")(t).diff(t)}))["d"] == sp.Function("psi")(t).diff(t)


def test_a_build_reads_what_its_own_chapter_wrote_first(tmp_path, monkeypatch):
    """With ``$WMR_OUT = <build>/out/<chapter>``, the file in ``<build>/out/<earlier chapter>/``; else ``figures/``."""
    chapter = "01_platform_and_wheels"
    own = D.write(tmp_path / "out" / chapter, chapter, {"E": sp.eye(2)})
    monkeypatch.setenv("WMR_OUT", str(tmp_path / "out" / "02_offset_wheels_and_mobility"))
    assert D.source(chapter) == own and D.derived.__wrapped__(chapter)["E"] == sp.eye(2)
    assert D.source("03_kinetostatic_isotropy") == ROOT / "figures" / D.filename("03_kinetostatic_isotropy")
    monkeypatch.delenv("WMR_OUT")
    assert D.source(chapter) == ROOT / "figures" / D.filename(chapter)
    with pytest.raises(FileNotFoundError, match="no 99_none.derived.json"):
        D.source("99_none")


def test_the_makefile_runs_a_chapter_after_the_chapters_it_reads(tmp_path):
    """``make -n``: chapters 1, 2, 3 in that order, each key holding the file of the chapter before it."""
    target = tmp_path / "notebooks" / "03_kinetostatic_isotropy.ipynb"
    p = subprocess.run(
        ["make", "-n", "--no-print-directory", "-C", str(ROOT), f"WMR_BUILD={tmp_path}", str(target)],
        capture_output=True,
        text=True,
        check=True,
    )
    runs = [line.split(" execute ", 1)[1].split() for line in p.stdout.splitlines() if " execute " in line]
    assert [Path(r[0]).stem for r in runs] == CHAPTERS
    assert runs[0][2:] == []
    for (prev, *_), (_, _, *reads) in zip(runs, runs[1:]):
        chapter = Path(prev).stem
        assert reads == ["--reads", str(tmp_path / "out" / chapter / D.filename(chapter))]
