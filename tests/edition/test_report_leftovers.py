"""Leftovers of the report, caught by class (issue 30, item 7): no empty heading, no reference to material the
report omits, figure numbers in the order the report shows them, every marker of a figure legend defined.

Each rule is also run on a small text that breaks it, so that it can fail. The report is the one ``make test``
has just built (``test_report.py`` makes it)."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import unicodedata

import pytest
from test_report import BUILD, HAVE_TEX, TREE, make

from edition.families import ITEMS

HAVE_POPPLER = bool(shutil.which("pdftotext"))

# ----------------------------------------------------------------------------- the rules
_LEVELS = {"part": 0, "chapter": 0, "section": 1, "subsection": 2, "subsubsection": 3, "paragraph": 4}
_HEAD = re.compile(r"\\(part|chapter|section|subsection|subsubsection|paragraph)\*?\{((?:[^{}]|\{[^{}]*\})*)\}")
_NOISE = re.compile(r"\\(?:label|hypertarget|addcontentsline|markboth|markright)\{[^{}]*\}|[{}%\s]|\\par\b|\\clearpage")


def empty_headings(tex: str) -> list[str]:
    """Headings of a LaTeX text with nothing under them before the next heading of their level or above."""
    body = tex.split(r"\begin{document}", 1)[-1].split(r"\end{document}", 1)[0]
    heads = list(_HEAD.finditer(body))
    bad = []
    for k, h in enumerate(heads):
        following = heads[k + 1] if k + 1 < len(heads) else None
        between = _NOISE.sub("", body[h.end() : following.start() if following else len(body)])
        if not between and (following is None or _LEVELS[following.group(1)] <= _LEVELS[h.group(1)]):
            bad.append(h.group(2)[:60])
    return bad


OMITTED = re.compile(r"\bExercises?\s+\d+\.\d+\b|\bthe exercises? (?:below|above|at the end)\b", re.IGNORECASE)


def omitted_references(text: str) -> list[str]:
    """References to exercises, all of which the report leaves out."""
    return [m.group(0) for m in OMITTED.finditer(text)]


_CAPTION = re.compile(r"(?:\\textbf\{|\\emph\{|\\textit\{|\*)Figure (E?)(\d+)\.")


def figure_order(tex: str) -> list[str]:
    """Figure captions whose number does not follow the one before (the paper's and the edition's separately)."""
    seen: dict[str, list[int]] = {"": [], "E": []}
    bad = []
    for m in _CAPTION.finditer(tex):
        series, n = m.group(1), int(m.group(2))
        if n in seen[series]:
            continue
        if seen[series] and n < seen[series][-1]:
            bad.append(f"Figure {series}{n} after Figure {series}{seen[series][-1]}")
        seen[series].append(n)
    return bad


_MARKER = re.compile(r"\((?:[ivx]+'+|[ivx]+-[a-z]+)\)")


def undefined_markers(legend_text: str, caption: str) -> list[str]:
    """Item markers in a legend, like (i') or (v-b), that are neither the paper's items nor defined in the caption
    ("(i'): ..." or "(i') ...")."""
    out = []
    for m in sorted(set(_MARKER.findall(legend_text))):
        if m in ITEMS:
            continue
        if not re.search(re.escape(m) + r"\s*(?::|=|is\b|are\b)", caption):
            out.append(m)
    return out


def test_the_rules_can_fail():
    tex = (
        r"\begin{document}\section{A}text\subsection{B}more\section{Exercises}\label{x}"
        r"\section{C}\subsection{D}words\end{document}"
    )
    assert empty_headings(tex) == ["Exercises"]
    assert empty_headings(r"\begin{document}\section{A}\subsection{B}text\end{document}") == []
    assert empty_headings(r"\begin{document}\section{A}text\section{End}\end{document}") == ["End"]
    assert omitted_references("which Exercise 5.3 asks for; (Exercise 9.1)") == ["Exercise 5.3", "Exercise 9.1"]
    assert not omitted_references("exercises are left out of both")
    assert figure_order(r"\emph{Figure E10. x} \emph{Figure E3. y} \textbf{Figure 7.} \textbf{Figure 8.}") == [
        "Figure E3 after Figure E10"
    ]
    assert figure_order(r"\textbf{Figure E1.} \emph{Figure E2. a} \emph{Figure E3. b}") == []
    assert undefined_markers("(i) (i') (deg)", "all planes parallel ((i), (i'))") == ["(i')"]
    assert undefined_markers("(i) (i')", "(i'): one wheel turned by 180 degrees") == []


# ----------------------------------------------------------------------------- the report
@pytest.fixture(scope="module")
def built():
    if not (HAVE_TEX and HAVE_POPPLER):
        pytest.skip("xelatex, pandoc or poppler missing")
    make(str(BUILD / "report.pdf"))
    text = subprocess.run(
        ["pdftotext", str(BUILD / "report.pdf"), "-"], capture_output=True, text=True, check=True
    ).stdout
    return {"tex": (BUILD / "report.tex").read_text(encoding="utf-8"), "pdf": unicodedata.normalize("NFKC", text)}


def test_no_empty_heading(built):
    bad = empty_headings(built["tex"])
    assert not bad, f"headings with nothing under them: {bad}"


def test_no_reference_to_omitted_material(built):
    bad = omitted_references(re.sub(r"\s+", " ", built["pdf"]))
    assert not bad, f"references to exercises, which the report leaves out: {bad}"


def test_figure_numbers_in_order(built):
    bad = figure_order(built["tex"])
    assert not bad, f"figures out of order: {bad}"


def test_every_legend_marker_is_defined():
    bad = []
    for meta in sorted((TREE / "figures").glob("*.json")):
        m = json.loads(meta.read_text(encoding="utf-8"))
        svg = meta.with_suffix(".svg")
        if "caption" in m and svg.exists():
            bad += [f"{meta.stem}: {x}" for x in undefined_markers(svg.read_text(encoding="utf-8"), m["caption"])]
    assert not bad, f"legend markers defined nowhere in the caption: {bad}"
