"""End-to-end: the report of this tree, as a reader gets it (issue 9).

The report is the one ``make test`` has just built (the fixtures run ``make``: cached, nothing is
rebuilt); that two builds are byte-identical is checked on a small tree (``test_report_content.py``).
Checks: nothing fetched from the network, math typeset offline in a browser, at most 4 MB, unique
ids, working links, each figure once, code collapsed, a contents sidebar with sub-levels, one font
family; an A4 PDF with nothing past the margins, no raw TeX or ASCII math in its text, no formula
shrunk below a readable size, the build date from the commit; a second ``make report`` rebuilds nothing.
"""

from __future__ import annotations

import base64
import gzip
import json
import os
import re
import shutil
import subprocess
import tempfile
import time
import unicodedata
from html.parser import HTMLParser
from pathlib import Path

import nbformat
import pytest

from edition.ledger import read as read_ledger
from tools.build import html as html_export
from tools.build.pdf import MIN_FORMULA_SCALE, scaled_formulas
from tools.build.typeset import read_figures

ROOT = Path(__file__).resolve().parents[2]

TREE = Path(os.environ.get("WMR_ROOT") or ROOT)  # WMR_ROOT: test another tree
BUILD = Path(os.environ.get("WMR_BUILD") or TREE / "build")
CHAPTERS = [
    p
    for p in sorted((TREE / "notebooks").glob("*.ipynb"))
    if p.name not in ("findings.ipynb", "10_robot_classes.ipynb")
]  # the Makefile's REPORTED
HAVE_TEX = bool(shutil.which("xelatex") and shutil.which("pandoc"))
HAVE_POPPLER = bool(shutil.which("pdftotext") and shutil.which("pdfinfo"))
REMOTE = re.compile(r"^\s*(https?:)?//", re.IGNORECASE)
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")
MAX_HTML_BYTES = 4_000_000


def make(*targets: str, build: Path = BUILD) -> str:
    """Run the build (cached: ``make test`` has just built the report); fail the test with its log."""
    p = subprocess.run(
        [
            "make",
            "-s",
            "--no-print-directory",
            "-j2",
            "-C",
            str(ROOT),
            f"WMR_ROOT={TREE}",
            f"WMR_BUILD={build}",
            *targets,
        ],
        capture_output=True,
        text=True,
        check=False,
    )
    if p.returncode != 0:
        pytest.fail(p.stdout + p.stderr, pytrace=False)
    return p.stdout


def commit_epoch() -> int:
    """The commit's date, asked of git here (not read back from the build): the report's date."""
    env = os.environ.get("SOURCE_DATE_EPOCH", "")
    if env.isdigit():
        return int(env)
    p = subprocess.run(
        ["git", "-C", str(TREE), "log", "-1", "--format=%ct"], capture_output=True, text=True, check=False
    )
    return int(p.stdout.strip()) if p.returncode == 0 else 0


@pytest.fixture(scope="module")
def html_text():
    make(str(BUILD / "report.html"), *([str(BUILD / "report.pdf")] if HAVE_TEX else []))
    return (BUILD / "report.html").read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def pdf_path(html_text):
    if not HAVE_TEX:
        pytest.skip("xelatex/pandoc not installed: run `make report` (it installs them)")
    return BUILD / "report.pdf"


# ----------------------------------------------------------------------------- offline HTML
class _Refs(HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.refs: list[tuple[str, str]] = []
        self.styles: list[str] = []
        self.scripts: list[tuple[dict, str]] = []
        self.ids: list[str] = []
        self._in: tuple[str, dict] | None = None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if a.get("id"):
            self.ids.append(a["id"])
        if tag == "script":
            if a.get("src"):
                self.refs.append(("script src", a["src"]))
            self._in = ("script", a)
        elif tag == "link" and a.get("href"):
            self.refs.append((f"link rel={a.get('rel')}", a["href"]))
        elif tag in ("img", "iframe", "embed", "source", "audio", "video") and a.get("src"):
            self.refs.append((f"{tag} src", a["src"]))
        elif tag == "object" and a.get("data"):
            self.refs.append(("object data", a["data"]))
        elif tag == "style":
            self._in = ("style", a)
        if a.get("style"):
            self.styles.append(a["style"])

    def handle_endtag(self, tag):
        if tag in ("script", "style"):
            self._in = None

    def handle_data(self, data):
        if self._in and self._in[0] == "style":
            self.styles.append(data)
        elif self._in and self._in[0] == "script":
            self.scripts.append((self._in[1], data))


def parse(page: str) -> _Refs:
    p = _Refs()
    p.feed(page)
    return p


def remote_references(page: str) -> list[str]:
    """Every reference a browser would fetch from the network on opening the page."""
    p = parse(page)
    bad = [f"{what}: {url[:120]}" for what, url in p.refs if REMOTE.match(url)]
    for css in p.styles:
        for m in re.finditer(r"@import\s+(?:url\()?\s*['\"]?([^'\")\s;]+)", css, re.IGNORECASE):
            if not m.group(1).startswith("data:"):
                bad.append(f"@import {m.group(1)[:120]}")
        for m in re.finditer(r"url\(\s*['\"]?([^'\")]+)", css, re.IGNORECASE):
            if REMOTE.match(m.group(1)):
                bad.append(f"css url({m.group(1)[:120]})")
        for m in re.finditer(r"@font-face\s*{([^}]*)}", css, re.IGNORECASE):
            for u in re.findall(r"url\(\s*['\"]?([^'\")]+)", m.group(1)):
                if not u.startswith("data:"):
                    bad.append(f"@font-face url({u[:120]})")
    return bad


def test_remote_reference_detector_can_fail():
    page = (
        '<html><head><script src="https://cdn.example/mathjax.js"></script>'
        '<link rel="stylesheet" href="//fonts.example/css">'
        '<style>@import url("https://x/y.css"); @font-face { font-family: F; src: url(/f.woff2) }'
        " body { background: url(http://x/bg.png) }</style></head><body>"
        '<img src="data:image/png;base64,AAAA"><script>var a = "https://not-a-fetch";</script></body></html>'
    )
    bad = remote_references(page)
    assert len(bad) == 6, bad
    assert not any("not-a-fetch" in b or "data:" in b for b in bad)


def test_html_fetches_nothing(html_text):
    assert remote_references(html_text) == []


def test_html_inlines_the_pinned_mathjax(html_text):
    p = parse(html_text)
    packed = [d for a, d in p.scripts if a.get("id") == "wmr-mathjax-gz"]
    assert len(packed) == 1, "the compressed MathJax bundle is not in the page"
    js = gzip.decompress(base64.b64decode(packed[0].strip()))
    assert b"MathJax" in js and len(js) > 1_000_000
    (config,) = [d for a, d in p.scripts if "window.MathJax = " in d]
    config = json.loads(config.split("window.MathJax = ", 1)[1].strip().rstrip(";"))
    assert config["options"]["enableMenu"] is False and config["loader"]["load"] == []  # nothing loaded lazily
    assert {"autoload", "require"} <= set(config["tex"]["packages"]["[-]"])


def test_html_size(html_text):
    size = len(html_text.encode("utf-8"))
    assert size <= MAX_HTML_BYTES, f"build/report.html is {size / 1e6:.2f} MB (limit {MAX_HTML_BYTES / 1e6:.0f} MB)"


def test_html_keeps_punctuation_with_its_formula(html_text):
    # a comma after inline math must not start a line of a narrow table cell, nor "(" end one before it
    bound = r'(?<!<span class="nobr">)(?<!<span class="nobr">\()(?<!<span class="nobr">\[)'
    loose = re.findall(
        bound + r'<span class="math inline">[^<]*</span>[,.;:)]'
        r'|(?<!<span class="nobr">)\(<span class="math inline">',
        html_text,
    )
    assert not loose, f"{len(loose)} formulas whose punctuation may wrap to the next line: {loose[:3]}"


def test_html_ids_unique_and_links_resolve(html_text):
    ids = parse(html_text).ids
    dups = sorted({i for i in ids if ids.count(i) > 1})
    assert not dups, f"ids defined more than once: {dups[:10]}"
    assert html_export.broken_links(html_text) == []


def test_every_ledger_row_links_to_its_derivation(html_text):
    rows = read_ledger(TREE / "figures" / "ledger.csv")
    ids = set(parse(html_text).ids)
    missing = [r["id"] for r in rows if not r["anchor"] or r["anchor"] not in ids]
    assert not missing, f"ledger rows without an anchor in the chapters: {missing[:10]}"
    part1 = html_text.split('id="part-i-findings"', 1)[1].split('id="part-ii-derivations"', 1)[0]
    for r in rows:
        if r["verdict"] != "ok":
            assert f'href="#{r["anchor"]}"' in part1, f"the findings do not link {r['id']} to its derivation"


def test_each_figure_embedded_once(html_text):
    figs = read_figures(TREE / "figures")
    assert figs, "no figures/<key>.json"
    srcs = re.findall(r'<img src="(data:[^"]+)"', html_text)
    dup = len(srcs) - len(set(srcs))
    assert dup == 0, f"{dup} images embedded more than once"
    for key in figs:
        block = re.findall(
            r'<figure class="wmr-figure" id="figure-' + re.escape(key) + r'">(.*?)</figure>', html_text, re.DOTALL
        )
        assert len(block) == 1, f"figure {key} shown {len(block)} times in the figures section"
        assert "data:image/svg+xml" in block[0], f"{key}: not shown from its SVG"


def test_paper_figures_only_in_the_figures_section(html_text):
    """A chapter's figure cell is replaced by a reference: no chapter output repeats a figure."""
    shown = [
        o["data"]["image/png"].replace("\n", "")
        for nb in CHAPTERS
        for c in nbformat.read(BUILD / "notebooks" / nb.name, as_version=4).cells
        if c.cell_type == "code"
        for o in c.outputs
        if o.get("metadata", {}).get("wmr_figure") and "image/png" in o.get("data", {})
    ]
    assert len(shown) >= len(read_figures(TREE / "figures")) - 1, "the chapters no longer mark their figures"
    assert not [s for s in shown if s in html_text], "the chapters still show the paper's figures"


def test_code_collapsed_and_no_program_output(html_text):
    main = html_text.split("<main>", 1)[1]
    outside = re.sub(r'<details class="code">.*?</details>', "", main, flags=re.DOTALL)
    assert html_text.count('<details class="code">') >= len(CHAPTERS)
    outputs = re.findall(r'<div class="output[^"]*">(.*?)</div>', outside, re.DOTALL)
    printed = [o[:80] for o in outputs if "<pre" in o]
    assert not printed, f"printed program output in the report: {printed[:5]}"
    assert not re.search(r"Out\[\d+\]|In&nbsp;\[|Traceback \(most recent call last\)", outside)


def test_markdown_tables_are_tables(html_text):
    """A Markdown table that the reader could not parse would show as rows of pipes."""
    main = re.sub(r'<details class="code">.*?</details>', "", html_text.split("<main>", 1)[1], flags=re.DOTALL)
    text = re.sub(r"<[^>]+>", " ", main)
    leaked = re.findall(r"\|\s*-{3,}\s*\|", text)
    assert not leaked, f"{len(leaked)} Markdown tables shown as text"


def test_contents_sidebar_stays_with_sub_levels(html_text):
    nav = re.search(r'<nav class="toc".*?</nav>', html_text, re.DOTALL)
    assert nav, "no contents sidebar"
    assert nav.group(0).count("<ul>") >= 1 + len(CHAPTERS), "the contents have no sub-levels"
    assert re.search(r"nav\.toc\s*{[^}]*position:\s*fixed", html_text), "the contents scroll away with the page"
    for hid in re.findall(r'<h1[^>]* id="([^"]+)"', html_text):
        assert f'href="#{hid}"' in nav.group(0), f"section {hid} missing from the contents"


def test_one_font_family(html_text):
    css = "\n".join(parse(html_text).styles)
    families = {f.strip() for f in re.findall(r"font-family:\s*([^;}]+)", css)}
    text = {f for f in families if "monospace" not in f and f != "inherit"}
    assert len(text) == 1, f"more than one font family for text: {text}"
    sizes = re.findall(r"mjx-container[^{]*{[^}]*font-size:\s*([^;}\s]+)", css)
    assert set(sizes) <= {"100%"}, f"math scaled apart from the text: {sizes}"


def test_build_date_is_the_commit_date(html_text):
    epoch = commit_epoch()
    date = time.strftime("%Y-%m-%d", time.gmtime(epoch)) if epoch else "unknown"
    assert f"committed {date}" in html_text


def test_abstract_counts_come_from_the_ledger(html_text):
    rows = read_ledger(TREE / "figures" / "ledger.csv")
    eqs = [r for r in rows if r["kind"] == "equation"]
    ok = sum(r["verdict"] == "ok" for r in eqs)
    abstract = html_text.split('id="abstract"', 1)[1].split("<h1", 1)[0]
    numbered = max(int(r["id"]) for r in eqs)
    judged = f"all {numbered}" if len(eqs) == numbered else f"{len(eqs)} of the"
    assert re.search(rf"The paper numbers (\d+) equations; this edition judges {judged}", abstract), abstract[:300]
    assert f"Of those judged, {ok} hold as printed" in abstract


@pytest.mark.skipif(not CHROMIUM, reason="chromium not installed: offline typesetting not checked in a browser")
def test_html_typesets_offline_in_browser(html_text):
    """Open the page in headless Chromium with the network disabled; math is typeset, none in error."""
    with tempfile.TemporaryDirectory() as prof:
        p = subprocess.run(
            [
                str(CHROMIUM),
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--disable-quic",
                "--no-first-run",
                "--disable-background-networking",
                "--disable-component-update",
                "--disable-sync",
                f"--user-data-dir={prof}",
                "--proxy-server=http://127.0.0.1:9",
                "--proxy-bypass-list=<-loopback>",
                "--virtual-time-budget=30000",
                "--dump-dom",
                (BUILD / "report.html").as_uri(),
            ],
            capture_output=True,
            text=True,
            timeout=240,
            check=False,
        )
    dom = p.stdout
    assert "<body" in dom, p.stderr[-2000:]
    dom = re.sub(r"<script.*?</script>|<style.*?</style>", "", dom, flags=re.DOTALL)
    n = dom.count("<mjx-container")
    assert n > 100, f"MathJax typeset only {n} formulas"
    errors = re.findall(r'data-mjx-error="([^"]*)"', dom) + re.findall(r"<mjx-merror", dom)
    assert not errors, f"{len(errors)} TeX errors: {errors[:5]}"
    body = re.sub(
        r"<mjx-container.*?</mjx-container>|<code.*?</code>|<pre.*?</pre>|<details.*?</details>",
        "",
        dom,
        flags=re.DOTALL,
    )
    text = re.sub(r"<[^>]+>", " ", body)
    leftovers = re.findall(r"\\\(|\\\[|\\[A-Za-z]+|\$", text)
    assert not leftovers, f"untypeset TeX left in the page: {leftovers[:5]}"


# ----------------------------------------------------------------------------- PDF
def _pdftext(pdf: Path, *args) -> str:
    return subprocess.run(["pdftotext", *args, str(pdf), "-"], capture_output=True, text=True, check=True).stdout


def test_pdf_is_a4_and_dated_from_the_commit(pdf_path):
    if not HAVE_POPPLER:
        pytest.skip("poppler-utils not installed")
    info = subprocess.run(["pdfinfo", str(pdf_path)], capture_output=True, text=True, check=True).stdout
    size = re.search(r"Page size:\s+([\d.]+) x ([\d.]+) pts", info)
    created = re.search(r"CreationDate:\s+(.*)", info)
    assert size and created, info
    w, h = map(float, size.groups())
    assert abs(w - 595.28) < 1 and abs(h - 841.89) < 1, f"not A4: {w} x {h} pt"
    epoch = commit_epoch()
    assert time.strftime("%Y", time.gmtime(epoch)) in created.group(1)


def test_pdf_words_inside_the_margins(pdf_path):
    if not HAVE_POPPLER:
        pytest.skip("poppler-utils not installed")
    page_w, margin = 595.28, 2.4 / 2.54 * 72  # the template's A4 with 2.4 cm margins
    bbox = _pdftext(pdf_path, "-bbox")
    out = []
    for page, body in enumerate(re.findall(r"<page[^>]*>(.*?)</page>", bbox, re.DOTALL), 1):
        words = r'<word xMin="([\d.]+)" yMin="[\d.]+" xMax="([\d.]+)" yMax="[\d.]+">([^<]*)</word>'
        for x0, x1, word in re.findall(words, body):
            if float(x1) > page_w - margin + 3 or float(x0) < margin - 3:
                out.append(f"p. {page}: {word!r} at x = {float(x0):.0f}..{float(x1):.0f}")
    assert not out, f"{len(out)} words past the margins: {out[:10]}"


def test_pdf_formulas_readable(pdf_path):
    log = (BUILD / "report.log").read_text(encoding="utf-8", errors="replace")
    small = [(round(s, 2), p) for s, p in scaled_formulas(log) if s < MIN_FORMULA_SCALE]
    assert not small, f"formulas shrunk below {MIN_FORMULA_SCALE:.0%} to fit the line (scale, page): {small}"
    missing = sorted(set(re.findall(r"Missing character: There is no (\S+)", log)))
    assert not missing, f"characters missing from the PDF's fonts: {missing}"
    from tools.build.pdf import _OVERFULL

    wide = [(w, line) for w, line in _OVERFULL.findall(log) if float(w) > 2]  # the build's own warning, as a test
    assert not wide, f"lines wider than the text (width in pt, report.tex line): {wide}"


def test_pdf_text_has_no_raw_tex_or_ascii_math(pdf_path):
    if not HAVE_POPPLER:
        pytest.skip("poppler-utils not installed")
    text = unicodedata.normalize("NFKC", _pdftext(pdf_path, "-layout"))
    raw = re.findall(r"\\[A-Za-z]+|\$", text)  # any TeX command or dollar left untypeset
    assert not raw, f"raw TeX in the PDF text: {raw[:10]}"
    ascii_math = re.findall(r"\w+_dot\b|!=|<=>|\^T\b|\b\d\*\d\b|\bkappa\b", text)
    assert not ascii_math, f"ASCII pseudo-math in the PDF text: {ascii_math[:10]}"


def test_a_second_report_rebuilds_nothing(pdf_path, html_text):
    outputs = [BUILD / f"report.{ext}" for ext in ("ipynb", "html", "pdf")] + sorted((BUILD / "notebooks").glob("*"))
    before = [p.stat().st_mtime_ns for p in outputs]
    log = make("report")
    assert [p.stat().st_mtime_ns for p in outputs] == before and "[execute]" not in log, log
