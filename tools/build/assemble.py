"""Assemble the report notebook ``build/report.ipynb`` from the executed chapters and the data.

Order: abstract and how to read (front matter); Part I, the findings (errata, claims that fail,
missed singular configurations, verdicts by section, the figures, conclusions, references);
Part II, the derivation chapters. The exporters (:mod:`tools.build.html`, :mod:`tools.build.pdf`)
render the same notebook; cell ids are deterministic.
"""
from __future__ import annotations

from . import closing, findings, frontmatter
from . import typeset as ts
from .chapters import chapter_cells
from .inputs import Inputs

__all__ = ["report_notebook"]


def report_notebook(inp: Inputs, commit: str, epoch: int):
    """The report as one notebook (``nbformat`` node)."""
    import nbformat

    nb = nbformat.v4.new_notebook()
    nb.metadata["wmr"] = frontmatter.title_metadata(commit, epoch)
    nb.metadata["title"] = frontmatter.TITLE
    cells = nb.cells
    cells.append(ts.markdown(frontmatter.abstract(inp)))
    cells += frontmatter.how_to_read(inp)

    cells.append(ts.part("Part I. Findings"))
    cells += findings.errata(inp)
    cells += findings.failed_claims(inp)
    cells += findings.singularities(inp)
    if inp.ledger is not None:
        cells += findings.by_section(inp)
    cells += findings.figures(inp)
    cells += closing.conclusions(inp)
    cells += closing.references()

    cells.append(ts.part("Part II. Derivations",
                         "The chapters below are the notebooks of this edition, executed for this report; "
                         "the code is collapsed in the HTML version and left out of the PDF, exercises are "
                         "left out of both. Each equation carries the paper's number."))
    for path, src in zip(inp.chapters, inp.sources):
        if not path.exists():
            cells.append(ts.markdown(f"# {src.stem.replace('_', ' ')}\n\n*Not executed: `{src.name}`.*"))
            continue
        chap = nbformat.read(path, as_version=4)
        if len(cells) and "language_info" in chap.metadata and "language_info" not in nb.metadata:
            nb.metadata["language_info"] = chap.metadata["language_info"]
        cells += chapter_cells(chap, inp.figures)

    for j, c in enumerate(cells):
        c["id"] = f"r{j:04d}"
    nb.nbformat, nb.nbformat_minor = 4, 5
    return nb
