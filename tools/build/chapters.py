"""The derivation chapters (Part II): the executed notebooks as a reader should see them.

Cell tags (set by the notebooks, see ``CONTRACTS.md``) say what to drop: ``exercise``,
``solution`` and ``ledger`` cells are not in the report; a ``figure`` cell becomes a one-line
reference to the figure, which the report shows once, in its figures section; a ``widget`` cell
keeps its saved static output. Code stays (collapsed in the HTML, absent from the PDF); of the
outputs only Markdown, LaTeX and images reach the reader: no printed text, no HTML tables, no
error output, no widget state.
"""
from __future__ import annotations

import re
from pathlib import Path

from .inputs import FigureMeta

__all__ = ["DROP_TAGS", "KEEP_MIMES", "chapter_cells"]

DROP_TAGS = frozenset({"exercise", "solution", "ledger", "remove-cell", "remove_cell"})
FIGURE_TAG = "figure"
#: output types a reader sees, in order of preference (one per output)
KEEP_MIMES = ("text/markdown", "text/latex", "image/svg+xml", "image/png")


def _output(o) -> dict | None:
    if o.get("output_type") not in ("display_data", "execute_result"):
        return None                          # stream, error: program output, not for the reader
    data = o.get("data", {})
    for mime in KEEP_MIMES:
        if mime in data:
            return {"output_type": "display_data", "data": {mime: data[mime]},
                    "metadata": {mime: o.get("metadata", {}).get(mime, {})} if mime in o.get("metadata", {}) else {}}
    return None


#: figures the report shows outside its figures section: key -> where (the conventions drawing)
FRONT_MATTER_FIGURES = {"conventions": "How to read this edition"}


def _figure_reference(source: str, figures: list[FigureMeta]) -> str:
    """The line that replaces a figure cell: a link to where the report shows the figure."""
    found = [f for f in figures if re.search(r"[\"']%s[\"']" % re.escape(f.key), source)]
    if not found:
        return "*The figure computed here is shown once, in the [figures](#figures) of Part I.*"
    out = []
    for f in found:
        where = FRONT_MATTER_FIGURES.get(f.key, "the figures of Part I")
        both = ", with the paper's caption beside the computed one" if f.paper_caption else ""
        out.append(f"[{f.label or f.title}](#figure-{f.key}): shown once, in {where}{both}.")
    return "*" + " ".join(out) + "*"


#: output metadata key with which a notebook marks the display of one of the paper's figures
FIGURE_METADATA = "wmr_figure"


def chapter_cells(nb, figures: list[FigureMeta]) -> list:
    """The cells of one executed notebook, as the report shows them (new cell objects).

    An output marked as one of the figures (output metadata ``wmr_figure``) is replaced by a link to
    the figure as well (a figure cell that was not tagged).
    """
    import nbformat
    shown = {f.key: f for f in figures}
    out = []
    for c in nb.cells:
        tags = set(c.get("metadata", {}).get("tags", []))
        if tags & DROP_TAGS:
            continue
        if FIGURE_TAG in tags:
            out.append(nbformat.v4.new_markdown_cell(_figure_reference(c.source, figures)))
            continue
        if c.cell_type == "markdown":
            out.append(nbformat.v4.new_markdown_cell(c.source))
        elif c.cell_type == "code":
            n = nbformat.v4.new_code_cell(c.source)
            for raw in c.get("outputs", []):
                o = _output(raw)
                key = raw.get("metadata", {}).get(FIGURE_METADATA)
                if o and key in shown:
                    f = shown[key]
                    o = {"output_type": "display_data", "metadata": {},
                         "data": {"text/markdown": _figure_reference(f'"{f.key}"', [f])}}
                if o:
                    n.outputs.append(nbformat.from_dict(o))
            if tags:
                n.metadata["tags"] = sorted(tags)
            out.append(n)
    return out


def chapter_title(nb, path: Path) -> str:
    """The chapter's first heading (``# 4. WMR with centred wheels ...``), else its file name."""
    for c in nb.cells:
        if c.cell_type == "markdown":
            m = re.match(r"\s*#\s+(.+)", c.source)
            if m:
                return m.group(1).strip()
    return path.stem.replace("_", " ")
