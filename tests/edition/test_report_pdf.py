"""The PDF as a reader gets it: generic checks on its text (issue 19).

Not a list of strings that were once wrong: rules that any leftover breaks. The text holds no Python
list, dict or set literal and no other program output; no placeholder line; no claim named by its
slug; every page's running head names the section that page opens with; no page opens with a numbered
display (split from its lead-in); every figure has a number and a caption. The report is the one
``make test`` has just built (``test_report.py`` makes it).
Each rule is also run on a small text that breaks it, so that it can fail.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import unicodedata
from pathlib import Path

import pytest
from test_report import BUILD, HAVE_TEX, TREE, make

from edition.ledger import read as read_ledger

HAVE_POPPLER = bool(shutil.which("pdftotext"))
pytestmark = pytest.mark.skipif(not (HAVE_TEX and HAVE_POPPLER), reason="xelatex, pandoc or poppler missing")

# ----------------------------------------------------------------------------- the rules
_ATOM = r"(?:-?\d+(?:\.\d+)?(?:e-?\d+)?|'[^'\n]*'|\"[^\"\n]*\"|True|False|None|inf|nan)"
#: a Python list or tuple of literals (``[6]``, ``[1, 1, 1]``, ``[0, 1]``), a dict (``{d3x: ...}``,
#: ``{'a': 1}``), a set of names (``{rho}``), a float spelled by Python (``inf``, ``nan``)
PROGRAM_OUTPUT = {
    "list": re.compile(r"\[\s*" + _ATOM + r"(?:\s*,\s*" + _ATOM + r")*\s*,?\s*\]"),
    "dict": re.compile(r"\{\s*['\"]?[A-Za-z_][\w ]*['\"]?\s*:\s*[^{}\n]{0,80}\}"),
    "set": re.compile(r"(?<![=\w]\s)(?<![=\w])\{\s*[A-Za-z_]\w*(?:\s*,\s*[A-Za-z_]\w*)*\s*\}"),
    "python float": re.compile(r"(?<![\w.])(?:inf|nan|NaN)(?![\w.])"),
    "empty result": re.compile(r"=\s*(?:undefined|None)\b|=\s*=(?!=)"),
}
#: what is quoted (the paper's words, its citations "[25]" among them) is not program output
QUOTED = re.compile(r"“[^”]{0,800}”", re.DOTALL)
#: what a build leaves when it says where something is instead of showing it, or a note to itself
PLACEHOLDER = re.compile(
    r"\bshown once\b|\bTODO\b|\bFIXME\b|\bTBD\b|\bplaceholder\b|\bXXX\b|lorem ipsum"
    r"|\(Section [A-Z][a-z]+[,)]|\bThe earlier reading\b",
    re.IGNORECASE,
)


def program_output(text: str) -> list[str]:
    """What in a text looks like printed program output (kind: excerpt)."""
    out, text = [], QUOTED.sub("“”", text)
    for kind, rx in PROGRAM_OUTPUT.items():
        out += [f"{kind}: {m.group(0)[:60]!r}" for m in rx.finditer(text)]
    return out


def slugs_named(text: str, slugs: list[str]) -> list[str]:
    """Claim slugs (``isotropy-d-zero``) used in a text as names, hyphenated or with spaces (``isotropy d zero``).

    A slug of one word, or of two that make an ordinary phrase (``dead-zone``), names nothing by itself; a slug
    of three words or more never reads as prose, and a two-word slug is a name when hyphenated and not part
    of a longer compound."""
    found = []
    for s in slugs:
        words = s.split("-")
        if len(words) >= 3:
            pat = r"\b" + r"[\s-]+".join(map(re.escape, words)) + r"\b"
        elif len(words) == 2:
            pat = r"(?<![\w-])" + re.escape(s) + r"(?![\w-])(?!\s+(?:circle|zone|motion|wheel|wheels|rate))"
        else:
            continue
        found += [m.group(0) for m in re.finditer(pat, text, re.IGNORECASE)]
    return found


def norm(s: str) -> str:
    return re.sub(r"[^0-9a-z]+", "", unicodedata.normalize("NFKC", s).lower().replace("--", "-"))


#: the tag of a numbered display at the right margin: ``(17)``, ``(15a)``, ``((15) corrected)``
DISPLAY_TAG = re.compile(r"\s\((?:\d{1,3}[a-z]?|\(\d{1,3}\) corrected)\)\s*$")


def displays_opening_pages(pages: list[str]) -> list[str]:
    """Pages whose text opens, below the running head, with a numbered display: a formula split by the page
    break from what leads into it.  The opening lines of a display are centred (indented), so the page's
    first lines up to the first one at the margin are looked at; one of them ending in a tag is a display."""
    bad = []
    for n, page in enumerate(pages, 1):
        top = []
        for line in [x for x in page.splitlines()[1:] if x.strip()][:8]:
            if len(line) - len(line.lstrip()) < 12:
                break
            top.append(line)
        bad += [f"p. {n}: {line.strip()[:60]!r}" for line in top[:1] if any(DISPLAY_TAG.search(x) for x in top)]
    return bad


def running_heads(pages: list[str], titles: list[str]) -> list[str]:
    """Pages whose running head does not name the section the page opens with.

    ``pages``: the text of each page (``pdftotext -layout``), the head its first line (left part);
    ``titles``: the section (and part) titles in order. A title is found where a line of a page is the
    title (or, for a title long enough to wrap, the start of it); a page opens with the section of its
    first line when that is a title, else with the last section found before it."""
    bad, current, k = [], None, 0
    for n, page in enumerate(pages, 1):
        lines = [ln.strip() for ln in page.splitlines() if ln.strip()]
        if len(lines) < 2:
            continue
        head = re.split(r"\s{2,}", lines[0])[0]
        body = lines[1:]
        opens = current
        for i, line in enumerate(body):
            if k < len(titles) and _is_title(line, titles[k]):
                if i == 0:
                    opens = titles[k]
                current, k = titles[k], k + 1
        if opens is None:
            continue
        h = norm(head.rstrip(".…"))
        if not h or not norm(opens).startswith(h) or len(h) < min(8, len(norm(opens))):
            bad.append(f"p. {n}: head {head!r}, opens with {opens!r}")
    return bad


def _is_title(line: str, title: str) -> bool:
    a, b = norm(line), norm(title)
    return a == b or (len(b) > 60 and len(a) >= 25 and b.startswith(a))


def tex_titles(tex: str) -> list[str]:
    """Section and part titles of the report's LaTeX, in order, as plain text."""
    out = []
    body = tex.split(r"\begin{document}", 1)[-1]
    for m in re.finditer(r"\\(?:section|wmrpart)\{((?:[^{}]|\{[^{}]*\})*)\}", body):
        t = re.sub(r"\\[a-zA-Z]+\s*|[{}]|\\\(|\\\)", "", m.group(1)).replace("--", "–")
        out.append(t)
    return out


#: the paper numbers its figures 1-14: this edition's own must not reuse those numbers (E1, E2, ...)
PAPER_FIGURES = 14


def uncaptioned_figures(tex: str) -> list[str]:
    """Images of the report's LaTeX that have no numbered caption: a figure environment needs a title
    ``Figure <number>.``; a chapter's image, a caption starting ``Figure <number>`` right after it, with a
    number that is not one of the paper's (``Figure 8.1`` would be read as part of the paper's Fig. 8)."""
    bad = []
    for m in re.finditer(r"\\begin\{wmrfigure\}\{([^}]*)\}(.*?)\\end\{wmrfigure\}", tex, re.DOTALL):
        if not re.search(r"\\wmrfigtitle\{\\textbf\{Figure [A-Z]?\d+\.\}", m.group(2)):
            bad.append(m.group(1))
    for m in re.finditer(r"\\wmrimage\{([^}]*)\}", tex):
        after = re.sub(r"\\[a-z]+\{|[{}\s]", " ", tex[m.end() : m.end() + 400]).split()
        number = re.match(r"([A-Z]?)(\d+)", after[1]) if after[:1] == ["Figure"] and len(after) > 1 else None
        if not number:
            bad.append(m.group(1))
        elif not number.group(1) and int(number.group(2)) <= PAPER_FIGURES:
            bad.append(f"{m.group(1)} (Figure {after[1]} clashes with the paper's Figure {number.group(2)})")
    return bad


# ----------------------------------------------------------------------------- the rules can fail
def test_the_rules_can_fail():
    assert len(program_output("dims [6] and [1, 1, 1]; {d3x: 2}; L in {rho}; u_c: inf, inf; = undefined")) >= 6
    assert not program_output(
        "the rank is 6 (see [the errata](#errata)), det J = 0 at beta = (10, 20, 30) deg,\n"
        "“computed using Maple [25], the”  license = {MIT},"
    )
    assert PLACEHOLDER.search("Figure 7: shown once, in Part I.") and PLACEHOLDER.search("(Section Abstract, 7)")
    assert slugs_named(
        "the claim isotropy d zero fails; singular-v-immobile too", ["isotropy-d-zero", "singular-v-immobile"]
    )
    assert not slugs_named("the dead-zone circle and the dead zone", ["dead-zone"])
    pages = ["Errata    head\nErrata\ntext", "Errata    head\ntext\nClaims\nmore", "Errata    head\nmore"]
    assert running_heads(pages, ["Errata", "Claims"]) == ["p. 3: head 'Errata', opens with 'Claims'"]
    pages = [
        "1. Head    edition\n" + " " * 30 + "h = -r theta j" + " " * 20 + "(17)\nVerdict (17): ok.",
        "1. Head    edition\nAs printed (Section 3.2):\n" + " " * 30 + "h = -r theta j" + " " * 20 + "(17)",
        "Title page\n" + " " * 20 + "An executable edition of Leow, Low & Loh (2002)",
    ]
    assert displays_opening_pages(pages) == ["p. 1: 'h = -r theta j                    (17)'"]
    tex = (
        r"\begin{wmrfigure}{figure-x}\wmrfigtitle{\textbf{Conventions.}}\end{wmrfigure} \wmrimage{a.png} text"
        r" \wmrimage{b.png} \emph{Figure 8.1. A plot.} \wmrimage{c.png} \emph{Figure D1. A plot.}"
    )
    assert uncaptioned_figures(tex) == ["figure-x", "a.png", "b.png (Figure 8.1. clashes with the paper's Figure 8)"]


# ----------------------------------------------------------------------------- the report
@pytest.fixture(scope="module")
def pdf_pages():
    make(str(BUILD / "report.pdf"))
    text = subprocess.run(
        ["pdftotext", "-layout", str(BUILD / "report.pdf"), "-"], capture_output=True, text=True, check=True
    ).stdout
    return [unicodedata.normalize("NFKC", p) for p in text.split("\f")]


def _where(pages, hits_of):
    return [f"p. {n}: {h}" for n, p in enumerate(pages, 1) for h in hits_of(p)]


def test_pdf_has_no_program_output(pdf_pages):
    bad = _where(pdf_pages, program_output)
    assert not bad, f"{len(bad)} bits of program output in the PDF: {bad[:12]}"


def test_pdf_has_no_placeholder_line(pdf_pages):
    bad = _where(pdf_pages, lambda p: [m.group(0) for m in PLACEHOLDER.finditer(p)])
    assert not bad, f"{len(bad)} placeholder lines in the PDF: {bad[:12]}"


def test_pdf_names_no_claim_by_its_slug(pdf_pages):
    slugs = [r["id"] for r in read_ledger(TREE / "figures" / "ledger.csv") if r["kind"] == "claim"]
    bad = _where(pdf_pages, lambda p: slugs_named(p, slugs))
    assert not bad, f"{len(bad)} claims named by their slug: {bad[:12]}"


def test_pdf_running_heads_name_the_section_each_page_opens_with(pdf_pages):
    titles = tex_titles((BUILD / "report.tex").read_text(encoding="utf-8"))
    assert len(titles) > 10
    bad = running_heads(pdf_pages, titles)
    assert not bad, f"{len(bad)} pages with a wrong running head: {bad[:12]}"
    found = [t for t in titles if any(_is_title(line, t) for p in pdf_pages for line in p.splitlines())]
    assert len(found) == len(titles), f"section titles not found in the PDF text: {sorted(set(titles) - set(found))}"


def test_pdf_no_page_opens_with_a_numbered_display(pdf_pages):
    bad = displays_opening_pages(pdf_pages)
    assert not bad, f"{len(bad)} pages open with a display, away from what leads into it: {bad[:12]}"


def test_pdf_every_figure_is_numbered_and_captioned(pdf_pages):
    bad = uncaptioned_figures((BUILD / "report.tex").read_text(encoding="utf-8"))
    assert not bad, f"{len(bad)} figures without a number and a caption: {bad[:12]}"
    assert not [p for p in Path(BUILD).glob("report.tex") if "(an SVG image of the HTML report" in p.read_text()]
