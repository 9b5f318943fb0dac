"""The PDF report: the report notebook as LaTeX (pandoc, nbconvert's ``wmr_latex``), typeset by xelatex in ``build/tmp``.

``\\wmrdisplay`` scales a formula wider than the line down to it and logs the factor (:func:`scaled_formulas`): none
runs past the margin, none is shrunk silently. xelatex runs until the contents and cross-references are stable, with
``SOURCE_DATE_EPOCH`` from the commit; :func:`fix_id` makes the trailer ``/ID`` a hash of the document.
"""

from __future__ import annotations

import base64
import hashlib
import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

from . import BuildError, atomic_write, say
from . import typeset as ts
from .markup import TEMPLATES, Batch

__all__ = ["MIN_FORMULA_SCALE", "export_pdf", "fix_id", "scaled_formulas", "to_latex"]

MAX_RUNS = 4
#: a formula wider than the line is shrunk to fit it; below this scale it counts as unreadable
MIN_FORMULA_SCALE = 0.8
#: a numbered environment of its own (``align``, ``align*``, ...), which cannot be boxed
_NUMBERED = re.compile(r"\\begin\{(align|gather|multline|equation|eqnarray)\*?\}")
_SCALED = re.compile(r"WMR-SCALE:([\d.]+)pt:([\d.]+)pt:(\S+)")
_DISPLAY = re.compile(r"(?<!\\)\\\[(.*?)(?<!\\)\\\]", re.DOTALL)
_TAG = re.compile(r"\\tag\*?\{([^{}]*)\}")
_NATURAL_TABLE = re.compile(r"\\begin\{longtable\}\[\]\{@\{\}([lcr]+)@\{\}\}")
_TEXTTT = re.compile(r"\\texttt\{([^{}]*)\}")
_XELATEX = ["xelatex", "-interaction=nonstopmode", "-halt-on-error", "-file-line-error", "report.tex"]
_ERROR = re.compile(r"!|\./report\.tex:\d+:")  # the first line of an error in the log
_OVERFULL = re.compile(r"Overfull \\hbox \((\d+\.\d+)pt too wide\)[^\n]*lines? (\d+)")


def display_math(m: re.Match) -> str:
    """LaTeX for one displayed formula ``\\[body\\]`` (match ``m`` of it): ``\\wmrdisplay{body}{tag}``, or the
    body itself when it is a numbered environment of its own (``align``, ``multline``, ...), which cannot be boxed."""
    body = m.group(1).strip()
    if _NUMBERED.match(body):
        return body
    tags = _TAG.findall(body)
    return r"\wmrdisplay{" + _TAG.sub("", body).strip() + "}{" + (tags[0] if tags else "") + "}"


def wrap_tables(tex: str) -> str:
    """Markdown tables of the chapters (pandoc gives them natural-width ``l`` columns, which run
    past the margin when a cell is long) get wrapping columns of equal width."""

    def one(m):
        n = len(m.group(1))
        col = rf">{{\raggedright\arraybackslash}}p{{\dimexpr(\linewidth-{2 * (n - 1)}\tabcolsep)/{n}\relax}}"
        return r"\begin{longtable}[]{@{}" + col * n + "@{}}"

    return _NATURAL_TABLE.sub(one, tex)


def breakable_code(tex: str) -> str:
    """Code and identifiers in the text (``wmr.analysis.mobility.twist_constraints``, ``listed_in_paper``) may break
    after a dot or an underscore, as a URL would, instead of running past the margin."""
    tex = _TEXTTT.sub(lambda m: r"\texttt{" + m.group(1).replace(".", r".\allowbreak{}") + "}", tex)
    return tex.replace(r"\_", r"\_\allowbreak{}")


def to_latex(nb) -> tuple[str, dict]:
    """The report notebook as a LaTeX document, and the image files it includes (name -> bytes)."""
    import nbformat
    from nbconvert import LatexExporter

    # each converted fragment: pandoc's \[...\] becomes \wmrdisplay, tables wrap, code breaks
    batch = Batch("latex", post=lambda tex: breakable_code(wrap_tables(_DISPLAY.sub(display_math, tex))))
    files: dict[str, bytes] = {}
    prepared = nbformat.v4.new_notebook(metadata=nb.metadata)
    for c in nb.cells:
        s, parts = ts.spec(c), []
        if s is not None:
            parts.append(ts.render_latex(s, batch.add))
        elif c.cell_type == "markdown":
            parts.append(batch.add(c.source))
        for o in c.get("outputs", []) if c.cell_type == "code" else []:
            data = o.get("data", {})
            if "text/markdown" in data:
                parts.append(batch.add(data["text/markdown"]))
            elif "image/png" in data:
                name = f"output-{len(files):04d}.png"
                files[name] = base64.b64decode(data["image/png"])
                parts.append(rf"\wmrimage{{{name}}}")
            elif "image/svg+xml" in data:
                parts.append(r"\emph{(an SVG image of the HTML report, not converted for the PDF)}")
        if parts:
            prepared.cells.append(nbformat.v4.new_raw_cell("\n\n".join(parts)))
    paper = batch.add(nb.metadata["wmr"]["paper"], inline=True)
    batch.convert()
    exp = LatexExporter(template_name="wmr_latex", extra_template_basedirs=[str(TEMPLATES)])
    body, _ = exp.from_notebook_node(prepared, resources={"wmr_paper_latex": paper})
    from edition.page_breaks import keep_displays_with_lead_in  # the edition's rule of the text, not glue

    return keep_displays_with_lead_in(batch.fill(body)), files


def scaled_formulas(log: str) -> list[tuple[float, str]]:
    """(scale, page) of every formula ``\\wmrdisplay`` had to shrink, from the xelatex log."""
    return [(float(avail) / float(wd), page) for wd, avail, page in _SCALED.findall(log)]


def fix_id(pdf: bytes) -> bytes:
    """Replace the trailer's ``/ID [<a><b>]`` by a hash of the rest of the file (same length, so
    the cross-reference offsets stay valid): identical documents get identical files."""
    m = list(re.finditer(rb"/ID\s*\[\s*<([0-9A-Fa-f]+)>\s*<([0-9A-Fa-f]+)>\s*\]", pdf))
    if not m:
        return pdf
    h = hashlib.sha256(pdf[: m[-1].start()] + pdf[m[-1].end() :]).hexdigest().upper()
    out = pdf
    for x in reversed(m):
        a, b = x.group(1), x.group(2)
        new = x.group(0).replace(a, h[: len(a)].encode()).replace(b, h[: len(b)].encode())
        out = out[: x.start()] + new + out[x.end() :]
    return out


def _run_xelatex(d: Path, epoch: int) -> str:
    env = dict(os.environ, SOURCE_DATE_EPOCH=str(epoch), FORCE_SOURCE_DATE="1", TZ="UTC")
    prev = None
    for run in range(1, MAX_RUNS + 1):
        p = subprocess.run(_XELATEX, cwd=d, env=env, capture_output=True, text=True, timeout=900, check=False)
        log_file = d / "report.log"
        log = log_file.read_text(encoding="utf-8", errors="replace") if log_file.exists() else p.stdout
        if p.returncode != 0 or not (d / "report.pdf").exists():
            lines = log.splitlines()
            at = next((i for i, line in enumerate(lines) if _ERROR.match(line)), None)
            where = "\n".join(lines[at : at + 12]) if at is not None else log[-3000:]
            raise BuildError(f"xelatex failed (run {run}; the source is build/report.tex):\n{where}")
        state = b"".join(f.read_bytes() for f in (d / "report.aux", d / "report.toc", d / "report.out") if f.exists())
        if state == prev:
            return log
        prev = state
    return log


def export_pdf(nb, out: Path) -> list[str]:
    """Typeset the report notebook into ``out`` (atomically), beside it ``report.tex`` (the source the
    xelatex log refers to) and ``report.log``; return warnings for the reader of the build log
    (missing glyphs, shrunk formulas, lines past the margin). xelatex runs in a temporary directory
    under ``<build>/tmp``, removed however the step ends (what a killed build left is removed first)."""
    if not shutil.which("xelatex"):
        raise BuildError(
            "xelatex not found: run `make report` (it installs the TeX toolchain) or "
            "apt-get install texlive-xetex texlive-latex-extra texlive-fonts-recommended lmodern pandoc"
        )
    out = Path(out)
    tex, files = to_latex(nb)
    atomic_write(out.with_suffix(".tex"), tex)
    tmp = out.parent / "tmp" / "pdf"
    shutil.rmtree(tmp, ignore_errors=True)  # one PDF step at a time per tree (build/.lock)
    tmp.mkdir(parents=True)
    with tempfile.TemporaryDirectory(dir=tmp) as name:
        d = Path(name)
        for fname, data in {"report.tex": tex.encode("utf-8"), **files}.items():
            (d / fname).write_bytes(data)
        log = _run_xelatex(d, int(nb.metadata["wmr"]["epoch"]))
        atomic_write(out, fix_id((d / "report.pdf").read_bytes()))
    atomic_write(out.with_suffix(".log"), log)
    missing = sorted(set(re.findall(r"Missing character: There is no (\S+)", log)))
    small = [f"{s:.2f} (p. {p})" for s, p in scaled_formulas(log) if s < MIN_FORMULA_SCALE]
    wide = [f"{float(w):.0f}pt (report.tex line {line})" for w, line in _OVERFULL.findall(log) if float(w) > 2]
    warnings = [f"characters missing from the fonts: {' '.join(missing)}"] if missing else []
    warnings += [f"formulas shrunk below {MIN_FORMULA_SCALE:.0%} to fit the line: {', '.join(small)}"] if small else []
    warnings += [f"{len(wide)} lines wider than the text: {', '.join(wide[:8])}"] if wide else []
    for w in warnings:
        say("pdf", "WARNING: " + w)
    return warnings
