"""The HTML report: one self-contained file, nothing fetched from the network.

Markdown goes to pandoc in one call (:class:`~tools.build.markup.Batch`), the page to nbconvert
(template ``wmr_html``, code collapsed); then the contents sidebar is built from the headings, ids
made unique and internal links checked. MathJax is inlined, nothing fetched (:func:`tools.mathjax.inline_html`)."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from .. import mathjax
from . import BuildError, atomic_write, say
from . import typeset as ts
from .markup import TEMPLATES, Batch

__all__ = ["broken_links", "export_html", "keep_punctuation", "mathjax_html", "navigation", "unique_ids"]

_HEADING = re.compile(r'<h([12])((?:\s+[a-z-]+="[^"]*")*)>(.*?)</h\1>', re.DOTALL)
_ID = re.compile(r'(?<![\w-])id="([^"]+)"')
_MATH = r'<span class="math inline">[^<]*</span>'
_MATH_PUNCT = re.compile(rf"[(\[]{_MATH}[,.;:!?)\]]*|{_MATH}[,.;:!?)\]]+")  # a formula with a bracket or punctuation


def mathjax_html() -> str:
    """The report's MathJax: :func:`tools.mathjax.inline_html` of :data:`tools.mathjax.PANDOC_TEX`."""
    try:
        return mathjax.inline_html(mathjax.PANDOC_TEX)
    except mathjax.MathJaxError as e:
        raise BuildError(f"MathJax: {e}") from None


def _prepare(nb, batch: Batch):
    """A copy of the report notebook in which every cell is ready for the template: Markdown and special cells become
    raw HTML, Markdown outputs HTML (placeholders that the pandoc batch fills in the finished page), images stay."""
    from nbformat import v4

    out = v4.new_notebook(metadata=nb.metadata)
    for c in nb.cells:
        s = ts.spec(c)
        if s is not None:
            out.cells.append(v4.new_raw_cell(ts.render_html(s, batch.add)))
        elif c.cell_type == "markdown":
            out.cells.append(v4.new_raw_cell(batch.add(c.source)))
        elif c.cell_type == "code":
            n = v4.new_code_cell(c.source, metadata=c.metadata)
            for o in c.outputs:
                md = o.get("data", {}).get("text/markdown")
                n.outputs.append(o if md is None else v4.new_output("display_data", data={"text/html": batch.add(md)}))
            out.cells.append(n)
    return out


def keep_punctuation(page: str) -> str:
    r"""Bind brackets and punctuation to the inline math they touch (``<span class="nobr">``): else a
    narrow table cell may break between a formula and its comma, or a ``(`` and its formula.

    Examples
    --------
    >>> keep_punctuation('(<span class="math inline">\\(x\\)</span>), and <span class="math inline">y</span> z')
    '<span class="nobr">(<span class="math inline">\\(x\\)</span>),</span> and <span class="math inline">y</span> z'
    """
    return _MATH_PUNCT.sub(r'<span class="nobr">\g<0></span>', page)


def unique_ids(page: str) -> tuple[str, list[str]]:
    """Make every ``id="..."`` unique (the second ``x`` becomes ``x-2``); return the page and the
    ids that were duplicated, sorted (a notebook that names one anchor twice)."""
    seen: dict[str, int] = {}

    def one(m):
        i = m.group(1)
        seen[i] = seen.get(i, 0) + 1
        return m.group(0) if seen[i] == 1 else f'id="{i}-{seen[i]}"'

    return _ID.sub(one, page), sorted(i for i, n in seen.items() if n > 1)


def broken_links(page: str) -> list[str]:
    """Internal links (``href="#x"``) whose target id does not exist."""
    ids = set(_ID.findall(page))
    return sorted({h for h in re.findall(r'href="#([^"]+)"', page) if h not in ids})


def navigation(page: str) -> str:
    """The contents sidebar: the parts, every top-level heading, and under each the second-level
    headings (the sections of a chapter)."""
    top: list[dict[str, Any]] = []
    part: dict[str, Any] | None = None
    h1: dict[str, Any] | None = None
    for m in _HEADING.finditer(page):
        attrs, inner = m.group(2), m.group(3).strip()
        if not (hid := re.search(r'\bid="([^"]+)"', attrs)):
            continue
        link = f'<a href="#{hid.group(1)}">{inner}</a>'
        node: dict[str, Any] = {"link": link, "kids": [], "part": 'class="part"' in attrs}
        if node["part"]:
            top.append(node)
            part, h1 = node, None
        elif m.group(1) == "1":
            (part["kids"] if part else top).append(node)
            h1 = node
        elif h1 is not None:
            h1["kids"].append(node)

    def li(n):
        kids = ul(n["kids"])
        return f'<li class="part"><span>{n["link"]}</span>{kids}</li>' if n["part"] else f"<li>{n['link']}{kids}</li>"

    def ul(nodes):
        return "<ul>" + "".join(map(li, nodes)) + "</ul>" if nodes else ""

    return f'<nav class="toc" aria-label="Contents"><p class="toc-title">Contents</p>{ul(top)}</nav>'


def _exporter():
    """nbconvert's HTMLExporter without its passes over the finished page (bleach sanitising and a
    BeautifulSoup re-parse that only adds alt text): the page is our own, already complete."""
    from nbconvert import HTMLExporter
    from nbconvert.exporters.templateexporter import TemplateExporter
    from nbconvert.filters.widgetsdatatypefilter import WidgetsDataTypeFilter

    class ReportExporter(HTMLExporter):
        def from_notebook_node(self, nb, resources=None, **kw):
            resources = self._init_resources(resources)
            data_types = WidgetsDataTypeFilter(notebook_metadata=self._nb_metadata, parent=self, resources=resources)
            self.register_filter("filter_data_type", data_types)
            return TemplateExporter.from_notebook_node(self, nb, resources, **kw)

    template = dict(template_name="wmr_html", extra_template_basedirs=[str(TEMPLATES)])
    return ReportExporter(**template, exclude_input_prompt=True, exclude_output_prompt=True)


def export_html(nb, out: Path) -> None:
    """Render the report notebook ``nb`` into ``out`` (atomically)."""
    batch = Batch("html")
    prepared = _prepare(nb, batch)
    ref = batch.add(nb.metadata["wmr"]["paper"], inline=True)  # the title block's reference
    batch.convert()
    css = (TEMPLATES / "wmr_html" / "report.css").read_text(encoding="utf-8")
    resources = {"wmr_css": css, "wmr_mathjax_html": mathjax_html(), "wmr_paper_html": ref}
    body, _ = _exporter().from_notebook_node(prepared, resources=resources)
    body, dups = unique_ids(keep_punctuation(batch.fill(body)))
    if dups:
        say("html", f"WARNING: ids defined more than once, renamed: {', '.join(dups)}")
    body = body.replace("<!--WMR-NAV-->", navigation(body), 1)
    if bad := broken_links(body):
        say("html", f"WARNING: links to missing anchors: {', '.join(bad)}")
    atomic_write(out, body)
