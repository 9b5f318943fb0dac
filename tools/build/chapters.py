"""The executed chapters as a reader sees them in the report (new cell objects).

Exercise cells (:data:`tools.assignments.ROLE_TAGS`) and ``ledger`` cells are dropped. In a derivation chapter a
``figure`` cell, or an output marked ``wmr_figure``, becomes a link to the figure, shown once in Part I; code stays
(collapsed in the HTML, absent from the PDF); of the outputs only Markdown, LaTeX and images reach the reader (no
printed text, HTML tables, errors or widget state). The findings chapter (Part I, ``notebooks/findings.ipynb``) is
prose: its Markdown and its outputs, not its code; an output marked ``wmr_figure`` is the figure itself, a Markdown cell
tagged ``part`` starts a part of the report, the cell tagged ``title`` gives the title block (:func:`title`)."""

from __future__ import annotations

import re
from typing import Any

from nbformat import from_dict, v4

from ..assignments import ROLE_TAGS
from . import typeset as ts

__all__ = ["DROP_TAGS", "FIGURE_METADATA", "KEEP_MIMES", "chapter_cells", "findings_cells", "title"]

DROP_TAGS = frozenset({*ROLE_TAGS, "ledger", "remove-cell", "remove_cell"})  # the exercises' cells, and more
#: output types a reader sees, in order of preference (one per output)
KEEP_MIMES = ("text/markdown", "text/latex", "image/svg+xml", "image/png")
#: output metadata key with which a notebook marks the display of one of the figures
FIGURE_METADATA = "wmr_figure"
#: figures the report shows outside its figures section: key -> where (the conventions drawing)
FRONT_MATTER_FIGURES = {"conventions": "How to read this edition"}
_MATH_ONLY = re.compile(r"^\s*(\$\$|\$|\\\[)(.*?)(\$\$|\$|\\\])\s*$", re.DOTALL)


def _display(data: dict, metadata: dict | None = None) -> dict:
    return {"output_type": "display_data", "metadata": metadata or {}, "data": data}


def _output(o) -> dict | None:
    r"""One output as the reader sees it (Markdown or an image), or ``None``; a LaTeX output becomes
    Markdown, a formula of its own (SymPy's ``$\displaystyle ...$``) displayed.

    Examples
    --------
    >>> _output({"output_type": "execute_result", "data": {"text/latex": r"$\displaystyle x^2$"}})["data"]
    {'text/markdown': '$$\nx^2\n$$'}
    """
    if o.get("output_type") not in ("display_data", "execute_result"):
        return None  # stream, error: program output, not for the reader
    data, meta = o.get("data", {}), o.get("metadata", {})
    mime = next((m for m in KEEP_MIMES if m in data), None)
    if mime == "text/latex":
        m = _MATH_ONLY.match(data[mime])
        if m and {m.group(1), m.group(3)} in ({"$"}, {"$$"}, {"\\[", "\\]"}) and "$" not in m.group(2):
            body = re.sub(r"^\\displaystyle\s*", "", m.group(2).strip())
            return _display({"text/markdown": f"$$\n{body}\n$$"})
        mime, data = "text/markdown", {"text/markdown": data[mime]}
    return None if mime is None else _display({mime: data[mime]}, {mime: meta[mime]} if mime in meta else {})


def _figure_link(keys: list[str], figures: dict[str, dict[str, Any]]) -> str:
    """The line that replaces the figure cells of a chapter: one sentence per place the report shows them."""
    if not keys:
        return "*The figure this computation draws is printed with the [figures](#figures) of Part I.*"
    from edition.report_cells import figure_sentences  # the edition's text rule; not a light import

    return figure_sentences([figures[k] for k in keys], FRONT_MATTER_FIGURES)


def chapter_cells(nb, figures: dict[str, dict[str, Any]]) -> list:
    """The cells of one executed derivation chapter, as the report shows them (consecutive figure cells: one line)."""
    out: list = []
    for c in nb.cells:
        tags = set(c.get("metadata", {}).get("tags", []))
        if tags & DROP_TAGS:
            continue
        if "figure" in tags:
            keys = [k for k in figures if re.search(r"[\"']" + re.escape(k) + r"[\"']", c.source)]
            if out and (joined := out[-1].metadata.get("wmr_figure_keys")):  # consecutive figure cells: one line
                keys, _ = joined + keys, out.pop()
            out.append(v4.new_markdown_cell(_figure_link(keys, figures), metadata={"wmr_figure_keys": keys}))
        elif c.cell_type == "markdown":
            out.append(v4.new_markdown_cell(c.source))
        elif c.cell_type == "code":
            n = v4.new_code_cell(c.source)
            for raw in c.get("outputs", []):
                o, key = _output(raw), raw.get("metadata", {}).get(FIGURE_METADATA)
                if o and key in figures:
                    o = _display({"text/markdown": _figure_link([key], figures)})
                if o:
                    n.outputs.append(from_dict(o))
            if tags:
                n.metadata["tags"] = sorted(tags)
            out.append(n)
    return out


def findings_cells(nb, figures: dict[str, dict[str, Any]]) -> list:
    """The cells of the executed findings chapter: its prose, its computed outputs, its figures, its parts."""
    out = []
    for c in nb.cells:
        tags = set(c.get("metadata", {}).get("tags", []))
        if tags & (DROP_TAGS | {"title"}):
            continue
        if c.cell_type == "markdown" and "part" in tags:
            head, _, intro = c.source.strip().partition("\n")
            out.append(ts.part(head.lstrip("# ").strip(), intro.strip()))
        elif c.cell_type == "markdown":
            out.append(v4.new_markdown_cell(c.source))
        for raw in c.get("outputs", []) if c.cell_type == "code" else []:
            key = raw.get("metadata", {}).get(FIGURE_METADATA)
            if key in figures:
                out.append(ts.figure(figures[key]))
            elif (o := _output(raw)) and "text/markdown" in o["data"]:
                out.append(v4.new_markdown_cell("".join(o["data"]["text/markdown"])))
            elif o:
                out.append(v4.new_code_cell("", outputs=[from_dict(o)]))
    return out


def title(nb) -> dict[str, str]:
    """The title block from the findings chapter's cell tagged ``title`` (its Markdown, or the Markdown it
    displays): the heading, the line under it, the edition's line (version, licences), its authors; and the paper's full
    reference, the entry by Leow under its heading ``# References``."""
    c: Any = next((c for c in nb.cells if "title" in c.get("metadata", {}).get("tags", [])), {"source": ""})
    shown = "".join(o.get("data", {}).get("text/markdown", "") for o in c.get("outputs", []))
    head = shown if c.get("cell_type") == "code" else c["source"]
    lines = [line.strip().strip("*") for line in head.strip().splitlines() if line.strip()] + ["", "", "", ""]
    refs = next((c.source for c in nb.cells if c.cell_type == "markdown" and c.source.startswith("# References")), "")
    paper = re.search(r"^(?:1\.|-)\s+(Y\. P\. Leow.+?)(?:\n\d+\.|\n-|\n\n|\Z)", refs, re.MULTILINE | re.DOTALL)
    ref = " ".join(paper.group(1).split()) if paper else ""
    return dict(title=lines[0].lstrip("# ").strip(), subtitle=lines[1], edition=lines[2], authors=lines[3], paper=ref)
