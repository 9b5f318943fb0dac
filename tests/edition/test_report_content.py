"""The report's content on a small fixture project: a ledger whose fields are Markdown with ``$...$``,
tagged notebook cells, figure metadata and a singularity list, and this edition's own findings
chapter (``notebooks/findings.ipynb``, copied), which must state what *these* files say. HTML only
(fast); the LaTeX source is checked without typesetting it.

What is checked: the report drops exercise, solution and ledger cells and program output, shows
each figure once (a chapter's figure cell becomes a link), links every erratum to its derivation,
states counts computed from the data (they differ from the real ledger's), puts the paper's caption
beside ours, lists only the singular configurations the paper misses, and gives the PDF no escaped
raw TeX.
"""

from __future__ import annotations

import base64
import csv
import fcntl
import json
import re
import shutil
import struct
import subprocess
import zlib
from pathlib import Path

import nbformat
import pytest

from edition.ledger import COLUMNS
from tools.build.pdf import to_latex

ROOT = Path(__file__).resolve().parents[2]
REPORT = ("report.html", "report.pdf") if shutil.which("xelatex") and shutil.which("pandoc") else ("report.html",)


def png(rgb=(200, 30, 30)) -> bytes:
    """A valid 2x2 PNG."""

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    raw = b"".join(b"\0" + bytes(rgb) * 2 for _ in range(2))
    return (
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 2, 0, 0, 0))
        + chunk(b"IDAT", zlib.compress(raw))
        + chunk(b"IEND", b"")
    )


FIG_PNG = png()
LEDGER = [
    {
        "id": "2",
        "kind": "equation",
        "section": "3.1",
        "verdict": "ok",
        "printed": r"\dot{\mathbf p}_i = \dot{\mathbf c} + \dot\psi\,\mathbf E\mathbf d_i",
        "corrected": "",
        "why": "",
        "convention": r"$\dot\psi\times\mathbf d_i$ read as $(\dot\psi\mathbf k)\times\mathbf d_i$",
        "check": "printed form proven equal to the derivation (SymPy)",
        "printed_holds": "yes",
        "residual": "< 1e-12",
        "notebook": "01_first",
        "anchor": "eq-2",
        "note": "",
    },
    {
        "id": "3",
        "kind": "equation",
        "section": "3.2",
        "verdict": "typo",
        "printed": r"\det\mathbf J = -\tfrac{\sqrt3}{2}\cos\beta",
        "corrected": r"\det\mathbf J = -r^3\tfrac{\sqrt3}{2}\cos\beta",
        "why": "the factor $r^3$ is missing",
        "convention": "",
        "check": "printed form refuted ($r = 2$); corrected form proven equal to the derivation (SymPy)",
        "printed_holds": "no",
        "residual": "0",
        "notebook": "01_first",
        "anchor": "eq-3",
        "note": "FIXTURE-NOTE",
    },
    {
        "id": "drift",
        "kind": "claim",
        "section": "4.2",
        "verdict": "wrong",
        "printed": "“the WMR drifts when $\\dot\\theta_i = 0$” (FIXTURE-CLAIM)",
        "corrected": r"with locked drives ($\dot\theta_i = 0$) the platform stands still: $\mathbf t = \mathbf 0$",
        "why": "$\\det\\mathbf M \\ne 0$ at 2000 configurations",
        "convention": "",
        "check": "refuted by counterexample",
        "printed_holds": "no",
        "residual": "0",
        "notebook": "01_first",
        "anchor": "claim-drift",
        "note": "",
    },
]
SINGULAR = [
    {
        "family": "(i)",
        "configuration": "$\\beta_1=\\beta_2=\\beta_3$",
        "geometric_meaning": "parallel planes",
        "listed_in_paper": "yes",
        "note": "LISTED-FAMILY",
    },
    {
        "family": "(i')",
        "configuration": "$\\beta_i=\\beta+180^\\circ$",
        "geometric_meaning": "same planes",
        "listed_in_paper": "no",
        "note": "MISSED-FAMILY",
    },
]


def _cell(kind, src, tags=()):
    c = nbformat.v4.new_markdown_cell(src) if kind == "md" else nbformat.v4.new_code_cell(src)
    if tags:
        c.metadata["tags"] = list(tags)
    return c


@pytest.fixture(scope="module")
def project(tmp_path_factory, worker_id):
    """The fixture project, built once per run: pytest-xdist's workers share it (a lock, then a marker)."""
    if worker_id == "master":
        return build_project(tmp_path_factory.mktemp("project"))
    shared = tmp_path_factory.getbasetemp().parent / "report-content-project"
    with open(shared.with_suffix(".lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # the other worker waits for the build
        if not (shared / "built").exists():
            shutil.rmtree(shared, ignore_errors=True)
            shared.mkdir()
            build_project(shared)
            (shared / "built").touch()
    return shared


def build_project(root: Path) -> Path:
    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nb.cells = [
        _cell(
            "md",
            '# 1. First chapter\n\nProse with $x^2$.\n\n<a id="eq-2"></a>\n\n'
            "## 1.1 Equation (2)\n\n$$\\dot{\\mathbf p}_i \\tag{2}$$",
        ),
        _cell("code", "from IPython.display import Image, Markdown, Math, display\nimport base64"),
        _cell(
            "code", f"key = 'fig07'\nImage(data=base64.b64decode({base64.b64encode(FIG_PNG).decode()!r}))", ["figure"]
        ),
        _cell("md", '<a id="eq-3"></a>\n\n## 1.2 Equation (3)\n\nDerivation of (3).'),
        _cell("code", "print('PRINTED-OUTPUT')\ndisplay(Markdown('Shown: $\\\\kappa = 1$ (MARKDOWN-OUTPUT)'))"),
        _cell("code", "Math(r'\\mathbf J = \\mathbf 1 \\quad (LATEX-OUTPUT)')"),
        _cell(
            "code",
            "class T:\n    def _repr_html_(self):\n"
            "        return '<table><tr><td>HTML-TABLE-OUTPUT</td></tr></table>'\nT()",
        ),
        _cell("md", "**Exercise.** EXERCISE-TEXT", ["exercise"]),
        _cell("code", "answer_1 = 'ANSWER-TEXT'", ["answer"]),
        _cell("code", "'SOLUTION-TEXT'", ["solution"]),
        _cell("code", "'CHECK-TEXT'", ["check"]),
        _cell("code", "display(Markdown('LEDGER-CELL-OUTPUT'))", ["ledger"]),
        _cell("code", "display(Markdown('WIDGET-STATIC-STATE'))", ["widget"]),
        _cell("md", '<a id="claim-drift"></a>\n\n## 1.3 The drift claim'),
    ]
    (root / "notebooks").mkdir()
    nbformat.write(nb, root / "notebooks" / "01_first.ipynb")
    shutil.copy(ROOT / "notebooks" / "findings.ipynb", root / "notebooks")
    fig = root / "figures"
    fig.mkdir()
    with open(fig / "ledger.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS, lineterminator="\n")
        w.writeheader()
        w.writerows(LEDGER)
    with open(fig / "singularities.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=list(SINGULAR[0]), lineterminator="\n")
        w.writeheader()
        w.writerows(SINGULAR)
    svg = '<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"><rect width="10" height="10"/></svg>'
    for key, number, paper_cap in (("fig07", "7", "PAPER-CAPTION-7"), ("conventions", "", "")):
        (fig / f"{key}.svg").write_text(svg.replace('10"/>', f'10" id="{key}"/>'))
        shutil.copy(ROOT / "figures" / "conventions.pdf", fig / f"{key}.pdf")  # any vector figure will do
        (fig / f"{key}.json").write_text(
            json.dumps(
                {
                    "key": key,
                    "number": number,
                    "title": f"Title of {key}",
                    "paper_caption": paper_cap,
                    "caption": f"OUR-CAPTION-{key} with $L = 1$",
                    "numbers": {},
                }
            )
        )
    make(root, root / "build", *REPORT)
    return root


def make(root: Path, build: Path, *files: str) -> str:
    """``make`` the given files of the report of ``root``, in the build directory ``build``."""
    p = subprocess.run(
        [
            "make",
            "-s",
            "--no-print-directory",
            "-j2",
            "-C",
            str(ROOT),
            f"WMR_ROOT={root}",
            f"WMR_BUILD={build}",
            *(str(build / f) for f in files),
        ],
        capture_output=True,
        text=True,
        check=False,
    )
    assert p.returncode == 0, p.stdout + p.stderr
    return p.stdout


@pytest.fixture(scope="module")
def page(project):
    return (project / "build" / "report.html").read_text(encoding="utf-8")


def test_tagged_cells_and_program_output_are_dropped(page):
    for gone in ("EXERCISE-TEXT", "ANSWER-TEXT", "SOLUTION-TEXT", "CHECK-TEXT", "LEDGER-CELL-OUTPUT"):  # not even code
        assert gone not in page
    no_code = re.sub(r'<details class="code">.*?</details>', "", page, flags=re.DOTALL)
    for gone in ("PRINTED-OUTPUT", "HTML-TABLE-OUTPUT"):  # the code stays, collapsed
        assert gone not in no_code
    for kept in ("MARKDOWN-OUTPUT", "LATEX-OUTPUT", "WIDGET-STATIC-STATE", "Prose with"):
        assert kept in page


def test_figure_cell_becomes_a_link_and_the_figure_is_shown_once(page):
    assert base64.b64encode(FIG_PNG).decode() not in page, "the chapter still embeds its figure"
    assert 'href="#figure-fig07"' in page and "printed in the figures of Part I, with the paper" in page
    block = re.findall(r'<figure class="wmr-figure" id="figure-fig07">(.*?)</figure>', page, re.DOTALL)
    assert len(block) == 1
    assert "PAPER-CAPTION-7" in block[0] and "OUR-CAPTION-fig07" in block[0], "the paper's caption beside ours"
    assert page.count('id="figure-conventions"') == 1  # the conventions drawing, in the front matter
    assert page.index('id="figure-conventions"') < page.index('id="errata"')


def test_errata_and_claims_link_to_their_derivations(page):
    errata = page.split('id="errata"', 1)[1].split('id="claims-that-fail"', 1)[0]
    assert 'href="#eq-3"' in errata and "the factor" in errata and "r^3" in errata and "FIXTURE-NOTE" not in errata
    assert 'href="#eq-2"' not in errata, "an ok equation listed among the errata"
    claims = page.split('id="claims-that-fail"', 1)[1].split("<h1", 1)[0]
    # Part I prints the ledger's row as the chapter recorded it (what is true: the fixture's own words)
    assert 'href="#claim-drift"' in claims and "FIXTURE-CLAIM" in claims and "with locked drives" in claims
    for anchor in ("eq-2", "eq-3", "claim-drift"):
        assert page.count(f'id="{anchor}"') == 1


def text(html: str) -> str:
    return re.sub(r"\s+", " ", re.sub(r"<[^>]+>", "", html)).replace("’", "'")


def test_counts_come_from_the_data(page):
    abstract = text(page.split('id="abstract"', 1)[1].split("<h1", 1)[0])
    # the number of equations the paper numbers comes from the transcription (printed.toml), the verdicts from
    # this ledger; the locked-drive claim is judged by edition.findings, the singular families by edition.families
    assert (
        "The paper numbers 65 equations; this edition judges 2 of the 65 ((1) and (4)–(65) are not judged" in abstract
    )
    assert "Of those judged, 1 holds as printed, one carries a typo and none are wrong" in abstract
    assert (
        "Of the one claim of its text that this edition checks by computation, none hold, none hold once "
        "corrected and one fails"
    ) in abstract
    assert "finds ten families of singular configurations" in abstract and "misses three" in abstract
    assert "Figure 7 of the paper is recomputed from the model, and this edition adds one figure of its own" in abstract
    part1 = text(page.split('id="part-i-findings"', 1)[1].split('id="part-ii-derivations"', 1)[0])
    assert "One equation of the paper does not hold as printed (one typo, none wrong)" in part1
    assert "What holds. 1 of the 2 numbered equations judged holds as printed, and one more holds" in part1
    assert "§3 1 1 0 0 0 0 §4 0 0 0 0 0 1 all 1 1 0 0 0 1" in part1  # verdicts by section, and the totals


def test_singular_families_are_counted_under_the_stated_reading(page):
    """The full table, derived (not the chapter's CSV), the reading stated, the count computed from the table."""
    sect = text(page.split('id="singular-configurations"', 1)[1].split("<h1", 1)[0])
    assert "MISSED-FAMILY" not in sect and "under each reading of item (v)" in sect and "modulo" in sect
    rows = sect.split("Printed item", 1)[1].split("What the wheel planes do", 1)[0]
    assert rows.count("identically") == 10 and rows.count("none; (v)") == 3, rows  # missed under half-turn only
    assert "covers seven and misses three when" in sect and "covers ten and misses none when it may" in sect


def test_title_block_comes_from_the_findings_chapter(page):
    head = page.split("<main>", 1)[1].split("</header>", 1)[0]
    assert "Kinematic modeling, mobility analysis and design of wheeled mobile robots" in head
    assert "Advanced Robotics" in head and "2002" in head and "Built from commit <code>unknown</code>" in head
    assert re.search(r"wmr(-kinematics)? \d+\.\d+\.\d+; code: MIT; text and figures: CC BY 4\.0", head), "no licences"
    assert "The wmr-kinematics contributors" in head, "no authors"


def test_latex_has_no_escaped_raw_tex_and_links(project):
    tex, _ = to_latex(nbformat.read(project / "build" / "report.ipynb", as_version=4))
    assert r"\textbackslash" not in tex, "raw TeX in the text would be printed as text in the PDF"
    assert r"\hypertarget{eq-3}{}" in tex and r"\hyperlink{eq-3}" in tex
    assert r"\wmrdisplay{\dot{\mathbf p}_i}{2}" in tex, "the paper's equation number becomes a tag"
    assert "PRINTED-OUTPUT" not in tex and "print(" not in tex, "code or program output in the PDF"


def test_two_builds_are_byte_identical(project, tmp_path):
    """A second build of the same tree in a copy of build/: the executed notebooks are reused (their
    stamps hold), the report notebook, the HTML and the PDF are made again, and come out the same."""
    copy = tmp_path / "second" / "build"
    shutil.copytree(project / "build", copy, ignore=shutil.ignore_patterns("report.*", "tmp"))
    log = make(project, copy, *REPORT)
    assert "[execute]" not in log and "[assemble]" in log, log
    for name in REPORT:
        same = (project / "build" / name).read_bytes() == (copy / name).read_bytes()
        assert same, f"two builds gave different {name}"
