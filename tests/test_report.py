"""End-to-end: build/report.html is self-contained (nothing fetched from the network), typesets
its math offline, and contains every figure and every ledger row; build/report.pdf has pages
and the figure titles."""
from __future__ import annotations

import csv
import os
import json
import re
import shutil
import subprocess
import sys
import tempfile
import time
import unicodedata
from html.parser import HTMLParser
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
import build  # noqa: E402

TREE = build.Tree(os.environ.get("WMR_ROOT") or ROOT)  # WMR_ROOT: test another tree
HAVE_TEX = bool(shutil.which("xelatex") and shutil.which("pandoc"))
REMOTE = re.compile(r"^\s*(https?:)?//", re.I)


@pytest.fixture(scope="module")
def built():
    """Build the report once for this module (cached: near-instant when nothing changed).
    A failing PDF does not hide the HTML checks: the HTML is written first and checked alone."""
    t0 = time.time()
    err = None
    try:
        build.report(TREE, html_only=not HAVE_TEX)
    except build.BuildError as e:
        err = str(e)
    html_path, pdf_path = TREE.build / "report.html", TREE.build / "report.pdf"
    return html_path, pdf_path, err, t0


@pytest.fixture(scope="module")
def report(built):
    html_path, pdf_path, err, _ = built
    if err:
        pytest.fail(err, pytrace=False)
    return html_path, pdf_path


@pytest.fixture(scope="module")
def html_text(built):
    html_path, _, err, t0 = built
    if not html_path.exists() or (err and html_path.stat().st_mtime < t0):
        pytest.fail(f"build/report.html was not built: {err}", pytrace=False)
    return html_path.read_text(encoding="utf-8")


def captions() -> dict:
    return build.read_captions(TREE)


def ledger_rows() -> list[dict]:
    return build.read_csv(TREE.figures / "ledger.csv") or []


# ----------------------------------------------------------------------------- offline HTML
class _Refs(HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.refs: list[tuple[str, str]] = []   # (what, url)
        self.styles: list[str] = []
        self.inline_scripts: list[str] = []
        self._in: str | None = None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "script":
            if a.get("src"):
                self.refs.append(("script src", a["src"]))
            self._in = "script"
        elif tag == "link" and a.get("href"):
            self.refs.append((f"link rel={a.get('rel')}", a["href"]))
        elif tag in ("img", "iframe", "embed", "source", "audio", "video") and a.get("src"):
            self.refs.append((f"{tag} src", a["src"]))
        elif tag == "object" and a.get("data"):
            self.refs.append(("object data", a["data"]))
        elif tag == "style":
            self._in = "style"
        if a.get("style"):
            self.styles.append(a["style"])

    def handle_endtag(self, tag):
        if tag in ("script", "style"):
            self._in = None

    def handle_data(self, data):
        if self._in == "style":
            self.styles.append(data)
        elif self._in == "script":
            self.inline_scripts.append(data)


def remote_references(html_text: str) -> list[str]:
    """Every reference a browser would fetch from the network on opening the page."""
    p = _Refs()
    p.feed(html_text)
    bad = [f"{what}: {url[:120]}" for what, url in p.refs if REMOTE.match(url)]
    for css in p.styles:
        for m in re.finditer(r"@import\s+(?:url\()?\s*['\"]?([^'\")\s;]+)", css, re.I):
            if not m.group(1).startswith("data:"):
                bad.append(f"@import {m.group(1)[:120]}")
        for m in re.finditer(r"url\(\s*['\"]?([^'\")]+)", css, re.I):
            if REMOTE.match(m.group(1)):
                bad.append(f"css url({m.group(1)[:120]})")
        for m in re.finditer(r"@font-face\s*{([^}]*)}", css, re.I):
            for u in re.findall(r"url\(\s*['\"]?([^'\")]+)", m.group(1)):
                if not u.startswith("data:"):
                    bad.append(f"@font-face url({u[:120]})")
    return bad


def test_remote_reference_detector_can_fail():
    page = ('<html><head><script src="https://cdn.example/mathjax.js"></script>'
            '<link rel="stylesheet" href="//fonts.example/css">'
            '<style>@import url("https://x/y.css"); @font-face { font-family: F; src: url(/f.woff2) }'
            ' body { background: url(http://x/bg.png) }</style></head><body>'
            '<img src="data:image/png;base64,AAAA"><script>var a = "https://not-a-fetch";</script></body></html>')
    bad = remote_references(page)
    assert len(bad) == 6, bad  # script, link, @import (+ its url), background url, @font-face
    assert not any("not-a-fetch" in b or "data:" in b for b in bad)


def test_html_fetches_nothing(html_text):
    assert remote_references(html_text) == []


def test_html_math_is_inlined_mathjax(html_text):
    p = _Refs()
    p.feed(html_text)
    assert any("MathJax" in s and len(s) > 500_000 for s in p.inline_scripts), \
        "the MathJax bundle is not inlined in build/report.html"
    assert "enableMenu: false" in html_text  # no menu: nothing lazily loaded


def test_html_has_every_figure(html_text):
    caps = captions()
    if not caps:
        pytest.skip("figures/captions.json missing (python -m wmr.paper.figures not run / not written yet)")
    for key, c in caps.items():
        m = re.search(r'<figure class="wmr-fig" id="%s">(.*?)</figure>' % re.escape(key), html_text, re.S)
        assert m, f"figure {key} missing from the HTML report"
        assert 'src="data:image/' in m.group(1), f"figure {key} is not embedded as a data URI"
        assert build.html_text(c["title"]) in m.group(1), f"caption title of {key} missing"


def test_html_has_ledger_table(html_text):
    rows = ledger_rows()
    if not rows:
        pytest.skip("figures/ledger.csv missing (python -m wmr.paper.ledger not run / not written yet)")
    body = html_text.split('id="Ledger"', 1)
    assert len(body) == 2, "no Ledger section in the HTML report"
    table = body[1].split("</table>", 1)[0]
    missing = [r["id"] for r in rows if f"<td>{build.html.escape(r['id'])}</td>" not in table]
    assert not missing, f"ledger ids missing from the HTML ledger table: {missing[:10]}"
    for r in rows:
        if r.get("verdict") in build.NOT_OK:
            assert re.search(r"E\d+\. %s " % re.escape(build.html.escape(r["id"])), html_text), \
                f"erratum for {r['id']} missing"


def test_html_code_is_collapsed(html_text):
    n_code = 0
    for nb in TREE.notebook_files():
        import nbformat
        n_code += sum(c.cell_type == "code" for c in nbformat.read(nb, as_version=4).cells)
    if not n_code:
        pytest.skip("no notebooks yet")
    assert html_text.count('<details class="wmr-code">') >= 1
    assert "jp-InputPrompt" not in html_text or "In&nbsp;[" not in html_text


CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")


@pytest.mark.skipif(not CHROMIUM, reason="chromium not installed (apt-get install chromium): "
                                         "offline typesetting not checked in a browser")
def test_html_typesets_offline_in_browser(html_text):
    """Open the page in headless Chromium with the network disabled; every $...$ must become
    a MathJax container and none may be a TeX error."""
    with tempfile.TemporaryDirectory() as prof:
        p = subprocess.run(
            [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             f"--user-data-dir={prof}", "--proxy-server=http://127.0.0.1:9", "--proxy-bypass-list=<-loopback>",
             "--virtual-time-budget=20000", "--dump-dom", (TREE.build / "report.html").as_uri()],
            capture_output=True, text=True, timeout=180)
    dom = p.stdout
    assert "<body" in dom, p.stderr[-2000:]
    dom = re.sub(r"<script.*?</script>|<style.*?</style>", "", dom, flags=re.S)  # the bundle names its own tags
    n = dom.count("<mjx-container")
    assert n > 0, "MathJax typeset nothing"
    errors = re.findall(r'data-mjx-error="([^"]*)"', dom) + re.findall(r"<mjx-merror", dom)
    assert not errors, f"{len(errors)} TeX errors: {errors[:5]}"
    body = re.sub(r"<mjx-container.*?</mjx-container>|<code.*?</code>|<pre.*?</pre>", "", dom, flags=re.S)
    text = re.sub(r"<[^>]+>", " ", body)
    leftovers = re.findall(r"\$[^$\n]{0,40}\\[a-zA-Z]+[^$\n]{0,40}\$", text)
    assert not leftovers, f"untypeset TeX left in the page: {leftovers[:5]}"


# ----------------------------------------------------------------------------- PDF
def _pdf_text(pdf: Path) -> str:
    if shutil.which("pdftotext"):
        txt = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True, check=True).stdout
    else:
        from pypdf import PdfReader
        txt = "\n".join(pg.extract_text() or "" for pg in PdfReader(str(pdf)).pages)
    return _norm(txt)


def _norm(s: str) -> str:
    s = unicodedata.normalize("NFKC", s)
    s = re.sub(r"-\s*\n\s*", "", s)      # hyphenation at line ends
    return " ".join(s.split()).lower()


def _pages(pdf: Path) -> int:
    from pypdf import PdfReader
    return len(PdfReader(str(pdf)).pages)


@pytest.mark.skipif(not HAVE_TEX, reason="xelatex/pandoc not installed (not a Debian machine?): "
                                         "run `make report` or apt-get install texlive-xetex pandoc ...")
def test_pdf_pages_and_captions(report):
    pdf = report[1]
    assert pdf.exists() and pdf.read_bytes()[:5] == b"%PDF-"
    caps = captions()
    n_chapters = len(TREE.notebook_files())
    want = 3 + len(caps) // 2 + n_chapters  # title + contents + summary, figures, chapters
    assert _pages(pdf) >= want, f"{pdf} has {_pages(pdf)} pages, expected at least {want}"
    text = _pdf_text(pdf)
    assert "summary of findings" in text and "contents" in text
    for key, c in caps.items():
        # compare the longest math-free run of words of the title
        run = max((_norm(s) for s in re.split(r"\$[^$]*\$", c["title"])), key=len).strip(" .,;:")
        assert run in text, f"title of {key} ({c['title']!r}) not found in the PDF text"


def test_second_report_is_instant(report):
    if not HAVE_TEX:
        pytest.skip("no TeX: the report stamp is only written for a full (HTML + PDF) build")
    t0 = time.perf_counter()
    build.report(TREE)
    assert time.perf_counter() - t0 < 1.0, "an up-to-date report took over a second"
