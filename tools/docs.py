"""``make docs``: the API reference and the user guide, in build/docs/html (Sphinx, warnings are errors).

    python -m tools.docs            # build (skipped when nothing that goes into the docs changed)
    python -m tools.docs --force

1. docs/ is copied into build/docs/src, so that autosummary's stub pages never land in the tree;
2. MathJax from its official release (:mod:`tools.mathjax`, checked against the npm registry's sha512
   integrity) goes into its ``_static/mathjax/``: the pages load math from their own folder;
3. ``sphinx-build -W --keep-going -E`` writes build/docs/html (a warning fails the build);
4. the pages are checked: no script, style sheet or image from the network, every local link resolves,
   MathJax is the release's file; the number of pages is reported.

A pass is recorded with the hash of its inputs (docs/, wmr/, README.md, CHANGELOG.md, CITATION.cff,
examples/, environment.lock, this script and tools/mathjax.py) in build/docs/stamp.
"""

from __future__ import annotations

import argparse
import hashlib
import html.parser
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path
from urllib.parse import unquote, urlsplit

from tools import mathjax

ROOT = Path(__file__).resolve().parents[1]

OUT = ROOT / "build" / "docs"
SRC, HTML = OUT / "src", OUT / "html"
INPUTS = (
    "docs",
    "wmr",
    "README.md",
    "CHANGELOG.md",
    "CITATION.cff",
    "examples",
    "environment.lock",
    "tools/docs.py",
    "tools/mathjax.py",
)
#: the MathJax bundle the pages load (tex-svg-full: every TeX extension, glyphs as SVG paths, no fonts)
BUNDLE = "tex-svg-full.js"


class DocsError(RuntimeError):
    """The docs did not build, or what they hold is wrong; the message says what."""


def inputs_hash() -> str:
    h = hashlib.sha256()
    for name in INPUTS:
        p = ROOT / name
        files = [p] if p.is_file() else sorted(f for f in p.rglob("*") if f.is_file() and "__pycache__" not in f.parts)
        for f in files:
            h.update(f.relative_to(ROOT).as_posix().encode() + b"\0" + f.read_bytes() + b"\0")
    return h.hexdigest()


class _Refs(html.parser.HTMLParser):
    """The URLs a page loads (script src, link href, img src) and links to (a href)."""

    def __init__(self) -> None:
        super().__init__()
        self.loads: list[str] = []
        self.links: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = dict(attrs)
        if tag in ("script", "img", "iframe") and a.get("src"):
            self.loads.append(a["src"] or "")
        elif tag == "link" and a.get("href"):
            self.loads.append(a["href"] or "")
        elif tag == "a" and a.get("href"):
            self.links.append(a["href"] or "")


def check_pages(html_dir: Path) -> list[str]:
    """Problems of the built pages: anything loaded from the network, local links that resolve to no file,
    reST markup shown as text.

    Examples
    --------
    >>> import tempfile; d = Path(tempfile.mkdtemp())
    >>> _ = (d / "a.html").write_text('<script src="https://cdn.example/m.js"></script><a href="b.html#x">b</a>')
    >>> check_pages(d)
    ['a.html loads https://cdn.example/m.js from the network', 'a.html links to b.html#x: no such file']
    """
    problems = []
    for page in sorted(html_dir.rglob("*.html")):
        text = page.read_text(encoding="utf-8")
        refs = _Refs()
        refs.feed(text)
        rel = page.relative_to(html_dir).as_posix()
        prose = re.sub(r"<(pre|script)\b.*?</\1>", "", text, flags=re.DOTALL)
        if "``" in prose:  # reST markup that was not converted (code inside bold, ...)
            at = prose.index("``")
            problems.append(f"{rel} shows raw markup: ...{prose[max(0, at - 60) : at + 40]}...")
        for url in refs.loads:
            if urlsplit(url).scheme or url.startswith("//"):
                problems.append(f"{rel} loads {url} from the network")
        for url in refs.loads + refs.links:
            parts = urlsplit(url)
            if parts.scheme or url.startswith(("//", "#", "mailto:")) or not parts.path:
                continue
            if not (page.parent / unquote(parts.path)).exists():
                problems.append(f"{rel} links to {url}: no such file")
    return problems


def build() -> int:
    """Build the docs; return the number of pages (html files other than Sphinx's index and search)."""
    shutil.rmtree(SRC, ignore_errors=True)
    shutil.copytree(ROOT / "docs", SRC, ignore=shutil.ignore_patterns("__pycache__", "_build"))
    js = mathjax.bundle(BUNDLE)
    static = SRC / "_static" / "mathjax"
    static.mkdir(parents=True)
    shutil.copy(js, static / BUNDLE)
    shutil.rmtree(HTML, ignore_errors=True)
    env = dict(os.environ, WMR_REPOSITORY=str(ROOT), MPLBACKEND="Agg")
    log = OUT / "sphinx.log"
    cmd = [
        sys.executable,
        "-m",
        "sphinx",
        "-b",
        "html",
        "-W",
        "--keep-going",
        "-E",
        "-q",
        "-j",
        "1",
        "-d",
        str(OUT / "doctrees"),
        str(SRC),
        str(HTML),
    ]
    with open(log, "w", encoding="utf-8") as fh:
        code = subprocess.run(cmd, cwd=ROOT, env=env, stdout=fh, stderr=subprocess.STDOUT, check=False).returncode
    text = log.read_text(encoding="utf-8", errors="replace")
    if code != 0:
        raise DocsError(f"sphinx-build failed (exit {code}; warnings are errors); {log}:\n{text[-8000:]}")
    problems = check_pages(HTML)
    served = HTML / "_static" / "mathjax" / BUNDLE
    if not served.exists() or served.read_bytes() != js.read_bytes():
        problems.append(f"{served} is not MathJax {mathjax.VERSION}'s es5/{BUNDLE}")
    if problems:
        raise DocsError("the built pages are wrong:\n  " + "\n  ".join(problems[:30]))
    special = {"genindex.html", "search.html", "py-modindex.html"}
    return sum(1 for p in HTML.rglob("*.html") if p.name not in special and "_modules" not in p.parts)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    ap.add_argument("--force", action="store_true", help="build even when nothing changed since the last pass")
    args = ap.parse_args(argv)
    digest = inputs_hash()
    stamp = OUT / "stamp"
    if (
        not args.force
        and stamp.exists()
        and stamp.read_text(encoding="utf-8").strip() == digest
        and (HTML / "index.html").exists()
    ):
        print(f"[docs] unchanged since the last build ({digest[:12]}): {HTML.relative_to(ROOT)}/index.html")
        return 0
    stamp.unlink(missing_ok=True)
    t0 = time.monotonic()
    try:
        pages = build()
    except (DocsError, mathjax.MathJaxError) as exc:
        print(f"[docs] FAILED: {exc}", file=sys.stderr)
        return 1
    stamp.write_text(digest + "\n", encoding="utf-8")
    print(
        f"[docs] {pages} pages (and {len(list((HTML / '_modules').rglob('*.html')))} of highlighted source) "
        f"in {time.monotonic() - t0:.0f} s, no warnings: {HTML.relative_to(ROOT)}/index.html"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
