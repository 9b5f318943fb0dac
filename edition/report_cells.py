r"""What the build does to the report's cells that is a rule of the text, not glue (``tools/build`` calls it).

- :func:`drop_empty_headings`: no heading with nothing under it (what is left of an exercise section);
- :func:`figure_sentences`: the figures a chapter draws, named in one sentence per place the report shows them;
- :func:`stamp`: the commit and its year put where the findings chapter marked them (:data:`STAMPS`).
"""

from __future__ import annotations

import re

__all__ = ["STAMPS", "drop_empty_headings", "figure_sentences", "stamp"]

#: what the findings chapter writes where only the build knows the value (:data:`edition.findings.COMMIT`, ``YEAR``)
STAMPS = ("@COMMIT@", "@YEAR@")

_HEADING = re.compile(r"^(#{1,6})\s+\S")


def _level(cell):
    """The level of the heading a Markdown cell opens with (1-6), 0 when it does not open with one."""
    m = _HEADING.match(cell.source.lstrip()) if cell.cell_type == "markdown" else None
    return len(m.group(1)) if m else 0


def drop_empty_headings(cells, new_markdown_cell):
    r"""The cells without a heading that has nothing under it before the next heading of its level or above (or
    the end): what is left when the cells under a heading were dropped.  A code cell without outputs is nothing
    to a reader of the PDF.

    Parameters
    ----------
    cells : list of nbformat cells
    new_markdown_cell : callable
        ``nbformat.v4.new_markdown_cell`` (a cell whose trailing heading is cut is a new cell).

    Returns
    -------
    list

    Examples
    --------
    >>> from nbformat import v4
    >>> md = v4.new_markdown_cell
    >>> [c.source for c in drop_empty_headings([md("## A"), md("text"), md("## Exercises"), v4.new_code_cell("x")], md)]
    ['## A', 'text', 'x']
    >>> [c.source for c in drop_empty_headings([md("## A"), md("### B"), md("text")], md)]
    ['## A', '### B', 'text']
    >>> [c.source for c in drop_empty_headings([md("## Summary\n\ntext\n\n## Exercises"), md("## Next"), md("x")], md)]
    ['## Summary\n\ntext', '## Next', 'x']
    """
    keep = []
    for i, c in enumerate(cells):
        nxt = next((d for d in cells[i + 1 :] if not (d.cell_type == "code" and not d.get("outputs"))), None)
        if c.cell_type == "markdown":
            lines = c.source.rstrip().splitlines()
            while lines and _HEADING.match(lines[-1]) and (nxt is None or 0 < _level(nxt) <= len(lines[-1].split()[0])):
                lines.pop()  # a heading at the end of the cell with nothing under it
                while lines and not lines[-1].strip():
                    lines.pop()
            if not lines:
                continue
            if len(lines) < len(c.source.rstrip().splitlines()):
                c = new_markdown_cell("\n".join(lines))
        keep.append(c)
    return keep


def figure_sentences(figures, front_matter):
    """The figures a chapter draws, as one Markdown sentence per place the report prints them.

    Parameters
    ----------
    figures : list of dict
        The figures' metadata (``key``, ``label``, ``title``, ``paper_caption``), in the chapter's order.
    front_matter : dict
        Key -> where the report prints a figure outside Part I's figures.

    Returns
    -------
    str

    Examples
    --------
    >>> figs = [{"key": k, "label": f"Figure {n}", "title": "", "paper_caption": "c"} for k, n in (("a", 10), ("b", 11))]
    >>> print(figure_sentences(figs, {}).replace(", printed", ",\\nprinted"))
    *This computation draws [Figure 10](#figure-a) and [Figure 11](#figure-b),
    printed in the figures of Part I, each with the paper's caption beside the computed one.*
    """
    groups: dict = {}
    for f in figures:
        where = front_matter.get(f["key"], "the figures of Part I")
        groups.setdefault((where, bool(f["paper_caption"])), []).append(
            f"[{f['label'] or f['title']}](#figure-{f['key']})"
        )
    sentences = []
    for (where, paper), links in groups.items():
        both = (
            (", each" if len(links) > 1 else ",") + " with the paper's caption beside the computed one" if paper else ""
        )
        listed = ", ".join(links[:-1]) + " and " + links[-1] if len(links) > 1 else links[0]
        sentences.append(f"This computation draws {listed}, printed in {where}{both}.")
    return "*" + " ".join(sentences) + "*"


def stamp(cells, commit, year):
    """The cells with the commit and its year put where the findings chapter marked them (the BibTeX entry): the
    chapter is executed again only when its inputs change, the commit changes with every build.

    Examples
    --------
    >>> from nbformat import v4
    >>> stamp([v4.new_markdown_cell("commit = {@COMMIT@}, year = {@YEAR@}")], "0a7f9ffb1647", "2026")[0].source
    'commit = {0a7f9ffb1647}, year = {2026}'
    """
    for c in cells:
        if c.cell_type == "markdown":
            c.source = c.source.replace(STAMPS[0], commit).replace(STAMPS[1], year)
    return cells
