"""The PDF report: the report notebook as LaTeX, typeset by xelatex in a temporary directory.

All Markdown is converted by one pandoc call (:class:`~tools.build.markup.Batch`); nbconvert's
LaTeX exporter fills the ``wmr_latex`` template. Display math is set by ``\\wmrdisplay``, which
scales a formula wider than the line down to it and writes the factor to the log (see
:func:`scaled_formulas`): no formula runs past the margin and none is shrunk silently. xelatex runs
until the table of contents and the cross-references are stable (at most four times), with
``SOURCE_DATE_EPOCH`` from the commit so that two builds of one commit are byte-identical
(:func:`fix_id` makes the trailer ``/ID`` a hash of the document). The LaTeX directory lives
under ``build/tmp`` and is removed however the build ends.
"""
from __future__ import annotations

import base64
import hashlib
import os
import re
import shutil
from pathlib import Path

from . import procs
from . import typeset as ts
from .files import atomic_write, temp_dir
from .log import BuildError, say
from .markup import Batch, math_body, text_of
from .paths import TEMPLATES, Tree

__all__ = ["export_pdf", "to_latex", "display_math", "wrap_tables", "breakable_code", "scaled_formulas", "fix_id", "UNICODE",
           "MIN_FORMULA_SCALE"]

MAX_RUNS = 4
#: a formula wider than the line is shrunk to fit it; below this scale it counts as unreadable
MIN_FORMULA_SCALE = 0.8
#: characters of the text that Latin Modern lacks, set from the math fonts instead
UNICODE = {
    "→": r"\ensuremath{\rightarrow}", "←": r"\ensuremath{\leftarrow}", "↔": r"\ensuremath{\leftrightarrow}",
    "⇒": r"\ensuremath{\Rightarrow}", "⇔": r"\ensuremath{\Leftrightarrow}", "≤": r"\ensuremath{\le}",
    "≥": r"\ensuremath{\ge}", "≠": r"\ensuremath{\ne}", "≈": r"\ensuremath{\approx}", "≡": r"\ensuremath{\equiv}",
    "−": r"\ensuremath{-}", "∞": r"\ensuremath{\infty}", "±": r"\ensuremath{\pm}", "∈": r"\ensuremath{\in}",
    "∑": r"\ensuremath{\sum}", "√": r"\ensuremath{\surd}", "∂": r"\ensuremath{\partial}", "⊥": r"\ensuremath{\perp}",
    "‖": r"\ensuremath{\|}", "·": r"\ensuremath{\cdot}", "∘": r"\ensuremath{\circ}",
    "α": r"\ensuremath{\alpha}", "β": r"\ensuremath{\beta}", "γ": r"\ensuremath{\gamma}", "δ": r"\ensuremath{\delta}",
    "ε": r"\ensuremath{\varepsilon}", "θ": r"\ensuremath{\theta}", "κ": r"\ensuremath{\kappa}", "λ": r"\ensuremath{\lambda}",
    "μ": r"\ensuremath{\mu}", "ν": r"\ensuremath{\nu}", "π": r"\ensuremath{\pi}", "σ": r"\ensuremath{\sigma}",
    "φ": r"\ensuremath{\varphi}", "ϕ": r"\ensuremath{\phi}", "ψ": r"\ensuremath{\psi}", "ω": r"\ensuremath{\omega}",
    "Δ": r"\ensuremath{\Delta}", "Σ": r"\ensuremath{\Sigma}", "Φ": r"\ensuremath{\Phi}", "Ψ": r"\ensuremath{\Psi}",
    "Ω": r"\ensuremath{\Omega}", "✓": r"\ensuremath{\checkmark}", "✗": r"\ensuremath{\times}",
}
_ENVS = ("align", "align*", "gather", "gather*", "multline", "multline*", "equation", "equation*", "eqnarray", "eqnarray*")
_DISPLAY = re.compile(r"(?<!\\)\\\[(.*?)(?<!\\)\\\]", re.S)
_TAG = re.compile(r"\\tag\*?\{([^{}]*)\}")


def display_math(body: str) -> str:
    """LaTeX for one displayed formula: ``\\wmrdisplay{body}{tag}``, or the body itself when it is
    a numbered environment of its own (``align``, ``multline``, ...), which cannot be boxed."""
    body = body.strip()
    if re.match(r"\\begin\{(%s)\}" % "|".join(re.escape(e) for e in _ENVS), body):
        return body
    tags = _TAG.findall(body)
    return r"\wmrdisplay{" + _TAG.sub("", body).strip() + "}{" + (tags[0] if tags else "") + "}"


def _displays(tex: str) -> str:
    """Every ``\\[...\\]`` that pandoc wrote becomes :func:`display_math`."""
    return _DISPLAY.sub(lambda m: display_math(m.group(1)), tex)


_NATURAL_TABLE = re.compile(r"\\begin\{longtable\}\[\]\{@\{\}([lcr]+)@\{\}\}")
_TEXTTT = re.compile(r"\\texttt\{([^{}]*)\}")


def wrap_tables(tex: str) -> str:
    """Markdown tables of the chapters (pandoc gives them natural-width ``l`` columns, which run
    past the margin when a cell is long) get wrapping columns of equal width."""
    def one(m):
        n = len(m.group(1))
        col = rf">{{\raggedright\arraybackslash}}p{{\dimexpr(\linewidth-{2 * (n - 1)}\tabcolsep)/{n}\relax}}"
        return r"\begin{longtable}[]{@{}" + col * n + "@{}}"
    return _NATURAL_TABLE.sub(one, tex)


def breakable_code(tex: str) -> str:
    """Code and identifiers in the text (``wmr.analysis.mobility.twist_constraints``,
    ``listed_in_paper``) may break after a dot or an underscore, as a URL would, instead of
    running past the margin."""
    tex = _TEXTTT.sub(lambda m: r"\texttt{" + m.group(1).replace(".", r".\allowbreak{}") + "}", tex)
    return tex.replace(r"\_", r"\_\allowbreak{}")


def to_latex(nb) -> tuple[str, dict]:
    """The report notebook as a LaTeX document, and the image files it includes (name -> bytes)."""
    import nbformat
    from nbconvert import LatexExporter
    batch = Batch("latex")
    files: dict[str, bytes] = {}
    prepared = nbformat.v4.new_notebook(metadata=nb.metadata)
    for c in nb.cells:
        s = ts.spec(c)
        if s is not None:
            src = ts.render_latex(s, batch.add)
        elif c.cell_type == "markdown":
            src = batch.add(c.source)
        elif c.cell_type == "code":
            parts = []
            for o in c.outputs:
                data = o.get("data", {})
                if "text/markdown" in data:
                    parts.append(batch.add(text_of(data["text/markdown"])))
                elif "text/latex" in data:
                    tex = text_of(data["text/latex"])
                    body = math_body(tex)
                    parts.append(display_math(body) if body is not None else batch.add(tex))
                elif "image/png" in data:
                    name = f"output-{len(files):04d}.png"
                    files[name] = base64.b64decode(text_of(data["image/png"]))
                    parts.append(rf"\wmrimage{{{name}}}")
                elif "image/svg+xml" in data:
                    parts.append(r"\emph{(an SVG image of the HTML report, not converted for the PDF)}")
            src = "\n\n".join(parts)
        else:
            continue
        prepared.cells.append(nbformat.v4.new_raw_cell(src))
    paper = batch.add(nb.metadata["wmr"]["paper"], inline=True)
    batch.convert()
    for c in prepared.cells:
        c.source = breakable_code(wrap_tables(_displays(batch.fill(c.source))))
    unicode = "\n".join(rf"\newunicodechar{{{k}}}{{{v}}}" for k, v in UNICODE.items())
    exp = LatexExporter(template_name="wmr_latex", extra_template_basedirs=[str(TEMPLATES)])
    body, _ = exp.from_notebook_node(prepared, resources={"wmr_paper_latex": batch.fill(paper),
                                                           "wmr_unicode": unicode})
    return body, files


def scaled_formulas(log: str) -> list[tuple[float, str]]:
    """(scale, page) of every formula ``\\wmrdisplay`` had to shrink, from the xelatex log."""
    out = []
    for wd, avail, page in re.findall(r"WMR-SCALE:([\d.]+)pt:([\d.]+)pt:(\S+)", log):
        out.append((float(avail) / float(wd), page))
    return out


def fix_id(pdf: bytes) -> bytes:
    """Replace the trailer's ``/ID [<a><b>]`` by a hash of the rest of the file (same length, so
    the cross-reference offsets stay valid): identical documents get identical files."""
    m = list(re.finditer(rb"/ID\s*\[\s*<([0-9A-Fa-f]+)>\s*<([0-9A-Fa-f]+)>\s*\]", pdf))
    if not m:
        return pdf
    h = hashlib.sha256(pdf[:m[-1].start()] + pdf[m[-1].end():]).hexdigest().upper()
    out = pdf
    for x in reversed(m):
        a, b = x.group(1), x.group(2)
        new = x.group(0).replace(a, h[:len(a)].encode()).replace(b, h[:len(b)].encode())
        out = out[:x.start()] + new + out[x.end():]
    return out


def _run_xelatex(d: Path, epoch: int) -> str:
    env = dict(os.environ, SOURCE_DATE_EPOCH=str(epoch), FORCE_SOURCE_DATE="1", TZ="UTC")
    prev = None
    for run in range(1, MAX_RUNS + 1):
        p = procs.run(["xelatex", "-interaction=nonstopmode", "-halt-on-error", "-file-line-error", "report.tex"],
                      cwd=d, env=env, timeout=900)
        log = (d / "report.log").read_text(encoding="utf-8", errors="replace") if (d / "report.log").exists() else p.stdout
        if p.returncode != 0 or not (d / "report.pdf").exists():
            lines = log.splitlines()
            at = next((i for i, l in enumerate(lines) if l.startswith("!") or re.match(r"\./report\.tex:\d+:", l)), None)
            where = "\n".join(lines[at:at + 12]) if at is not None else log[-3000:]
            raise BuildError(f"xelatex failed (run {run}; the source is build/report.tex):\n{where}")
        state = b"".join((d / f"report.{ext}").read_bytes() for ext in ("aux", "toc", "out") if (d / f"report.{ext}").exists())
        if state == prev:
            return log
        prev = state
    return log


def export_pdf(nb, t: Tree, out: Path, epoch: int) -> list[str]:
    """Typeset the report notebook into ``out`` (atomically); return warnings for the reader of
    the build log (missing glyphs, shrunk formulas, lines past the margin)."""
    if not shutil.which("xelatex"):
        raise BuildError("xelatex not found: run `make report` (it installs the TeX toolchain) or "
                         "apt-get install texlive-xetex texlive-latex-extra texlive-fonts-recommended lmodern pandoc")
    tex, files = to_latex(nb)
    atomic_write(t.report_tex, tex)              # to read the log's line numbers against
    with temp_dir(t.tmp, "pdf-") as d:
        (d / "report.tex").write_text(tex, encoding="utf-8")
        for name, data in files.items():
            (d / name).write_bytes(data)
        log = _run_xelatex(d, epoch)
        atomic_write(out, fix_id((d / "report.pdf").read_bytes()))
    atomic_write(t.report_log, log)
    warnings = []
    missing = sorted(set(re.findall(r"Missing character: There is no (\S+)", log)))
    if missing:
        warnings.append(f"characters missing from the fonts: {' '.join(missing)}")
    small = [f"{s:.2f} (p. {p})" for s, p in scaled_formulas(log) if s < MIN_FORMULA_SCALE]
    if small:
        warnings.append(f"formulas shrunk below {MIN_FORMULA_SCALE:.0%} to fit the line: {', '.join(small)}")
    over = re.findall(r"Overfull \\hbox \((\d+\.\d+)pt too wide\)[^\n]*lines? (\d+)", log)
    wide = [f"{float(w):.0f}pt (report.tex line {l})" for w, l in over if float(w) > 2]
    if wide:
        warnings.append(f"{len(wide)} lines wider than the text: {', '.join(wide[:8])}")
    for w in warnings:
        say("pdf", "WARNING: " + w)
    return warnings
