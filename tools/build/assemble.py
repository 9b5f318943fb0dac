"""Assemble the report notebook ``build/report.ipynb`` from the executed chapters.

``assemble REPORT COMMIT FIGURES FINDINGS CHAPTER...``: the title block (from the findings chapter;
the commit and its date from ``COMMIT``, written by the Makefile), the findings chapter (abstract, how
to read, Part I), the derivation chapters (Part II). Cell ids are deterministic and the date is the
commit's: two builds of one commit are byte-identical."""

from __future__ import annotations

import datetime as dt
from pathlib import Path

from .chapters import chapter_cells, findings_cells, title
from .typeset import read_figures

__all__ = ["commit_info", "report_notebook"]


def commit_info(path: Path) -> tuple[str, int]:
    """``("0a7f9ffb1647 + uncommitted changes", epoch)`` from the Makefile's ``build/commit``
    (``HASH EPOCH [+]``); ``("unknown", 0)`` outside git."""
    parts = (Path(path).read_text(encoding="utf-8").split() if Path(path).exists() else []) + ["unknown", "0"]
    dirty = " + uncommitted changes" if "+" in parts[2:] else ""
    commit = parts[0] if parts[0] == "unknown" else parts[0][:12] + dirty
    return commit, int(parts[1]) if parts[1].isdigit() else 0


def report_notebook(commit_file: Path, figures_dir: Path, findings: Path, chapters: list[Path]):
    """The report as one notebook (``nbformat`` node)."""
    import nbformat

    figures = read_figures(figures_dir)
    commit, epoch = commit_info(commit_file)
    part1 = nbformat.read(findings, as_version=4)
    nb = nbformat.v4.new_notebook()
    date = dt.datetime.fromtimestamp(epoch, dt.UTC).strftime("%Y-%m-%d") if epoch else "unknown"
    nb.metadata["wmr"] = {**title(part1), "commit": commit, "epoch": epoch, "date": date}
    nb.metadata["title"] = nb.metadata["wmr"]["title"]
    from edition.report_cells import drop_empty_headings, stamp  # rules of the text (the edition's, not glue)

    nb.cells = stamp(findings_cells(part1, figures), commit, date[:4] if epoch else "unknown")
    for path in chapters:
        chapter = nbformat.read(path, as_version=4)
        if "language_info" in chapter.metadata:
            nb.metadata.setdefault("language_info", chapter.metadata["language_info"])
        nb.cells += drop_empty_headings(chapter_cells(chapter, figures), nbformat.v4.new_markdown_cell)
    for j, c in enumerate(nb.cells):
        c["id"] = f"r{j:04d}"
    nb.nbformat, nb.nbformat_minor = 4, 5
    return nb
