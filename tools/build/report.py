"""The report step: execute what is stale, assemble ``build/report.ipynb``, export HTML and PDF.

Up to date (nothing runs, well under a second) only when the report stamp records today's inputs
(the executed notebooks, ``figures/``, the build tool, the commit and the build date) and the
hashes of ``report.html`` and ``report.pdf`` as they are on disk. Otherwise the old report is
removed first, so that a failure never leaves a report that looks current; each output is
written atomically; the stamp is written last.
"""
from __future__ import annotations

import hashlib
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from . import gitinfo, procs
from .assemble import report_notebook
from .execute import execute, invalidate_report
from .files import atomic_write, hash_files, remove_temp_dirs
from .inputs import read_inputs
from .log import BuildError, say
from .paths import TOOL_SOURCES, Tree
from .stamps import Stamp

__all__ = ["report", "report_key", "report_outputs"]


def report_outputs(t: Tree, html_only: bool = False) -> list[Path]:
    return [t.report_html] if html_only else [t.report_html, t.report_pdf]


def report_key(t: Tree, commit: str, epoch: int) -> str:
    """What the report depends on beyond the executed notebooks' stamps (which cover the
    notebooks and ``wmr/``): the executed copies, ``figures/``, this tool, commit and date."""
    files = [t.executed_notebook(nb) for nb in t.notebook_files()]
    files += t.figure_files() + [t.ledger]
    files += sorted(p for p in TOOL_SOURCES.rglob("*") if p.is_file() and "__pycache__" not in p.parts)
    h = hash_files(files, t.root)
    h.update(f"\0{commit}\0{epoch}\0{sys.version}".encode())
    return h.hexdigest()


def report(t: Tree | None = None, html_only: bool = False) -> tuple[Path, Path | None]:
    """Build ``build/report.html`` and (unless ``html_only``) ``build/report.pdf``.

    Raises
    ------
    BuildError
        A notebook or an export failed; no report is left in ``build/``.
    """
    t = t or Tree()
    with procs.BuildLock(t.lock):
        t0 = time.perf_counter()
        remove_temp_dirs(t.tmp)
        execute(t)
        commit, epoch = gitinfo.describe(t.root), gitinfo.source_date_epoch(t.root)
        key = report_key(t, commit, epoch)
        stamp = Stamp(t.report_stamp)
        outputs = report_outputs(t, html_only)
        if stamp.valid(key, outputs) or (html_only and stamp.valid(key, report_outputs(t))):
            say("report", "up to date (inputs and outputs unchanged)", t0)
            return t.report_html, None if html_only else t.report_pdf
        invalidate_report(t)
        try:
            _build(t, commit, epoch, html_only)
        except BaseException:
            invalidate_report(t)            # no half-built report may look current
            raise
        stamp.write(key, outputs)
        say("report", f"done: {', '.join(t.rel(p) for p in outputs)}", t0)
        return t.report_html, None if html_only else t.report_pdf


def _build(t: Tree, commit: str, epoch: int, html_only: bool) -> None:
    import nbformat
    from .html import export_html
    from .pdf import export_pdf

    t1 = time.perf_counter()
    nb = report_notebook(read_inputs(t), commit, epoch)
    atomic_write(t.report_notebook, nbformat.writes(nb))
    say("report", f"assembled {t.rel(t.report_notebook)} ({len(nb.cells)} cells)", t1)

    def html():
        t2 = time.perf_counter()
        export_html(nb, t.report_html)
        say("report", f"HTML {t.report_html.stat().st_size / 1e6:.2f} MB", t2)

    def pdf():
        t2 = time.perf_counter()
        export_pdf(nb, t, t.report_pdf, epoch)
        say("report", f"PDF {t.report_pdf.stat().st_size / 1e6:.2f} MB", t2)

    jobs = [html] if html_only else [pdf, html]
    with ThreadPoolExecutor(max_workers=len(jobs)) as pool:
        futs = [pool.submit(j) for j in jobs]
        errors = [f.exception() for f in futs]
    for e in errors:
        if e is not None:
            raise e if isinstance(e, BuildError) else BuildError(f"export failed: {e!r}") from e
