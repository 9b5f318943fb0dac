"""The HTML report: one self-contained file, nothing fetched from the network.

Markdown goes to pandoc in one call (:class:`~tools.build.markup.Batch`), the page to nbconvert
(template ``wmr_html``, code collapsed); then the contents sidebar is built from the headings, ids
made unique and internal links checked. MathJax is the official release's bundle (:mod:`tools.mathjax`:
the npm tarball checked against its sha512), inlined gzip-compressed (the page stays under 4 MB)."""
from __future__ import annotations

import base64
import functools
import gzip
import re
from pathlib import Path
from typing import Any

from . import BuildError, say
from . import typeset as ts
from .markup import TEMPLATES, Batch

__all__ = ["broken_links", "export_html", "keep_punctuation", "mathjax_gz", "navigation", "unique_ids"]


@functools.lru_cache(maxsize=1)
def mathjax_gz() -> str:
    """MathJax 3 ``tex-svg-full.js`` (every TeX extension, SVG glyphs: no font files) of the official
    release (:func:`tools.mathjax.bundle`), gzip (fixed mtime, so the bytes never change) and base64."""
    from tools import mathjax
    try:
        js = mathjax.bundle("tex-svg-full.js").read_bytes()
    except mathjax.MathJaxError as e:
        raise BuildError(f"MathJax: {e}") from None
    return base64.b64encode(gzip.compress(js, compresslevel=9, mtime=0)).decode()


def _prepare(nb, batch: Batch):
    """A copy of the report notebook in which every cell is ready for the template: Markdown and
    special cells become raw HTML, Markdown outputs HTML (placeholders that the pandoc batch fills
    in the finished page), images stay."""
    import nbformat
    out = nbformat.v4.new_notebook(metadata=nb.metadata)
    for c in nb.cells:
        s = ts.spec(c)
        if s is not None:
            out.cells.append(nbformat.v4.new_raw_cell(ts.render_html(s, batch.add)))
        elif c.cell_type == "markdown":
            out.cells.append(nbformat.v4.new_raw_cell(batch.add(c.source)))
        elif c.cell_type == "code":
            n = nbformat.v4.new_code_cell(c.source, metadata=c.metadata)
            for o in c.outputs:
                md = o.get("data", {}).get("text/markdown")
                n.outputs.append(o if md is None else nbformat.v4.new_output("display_data", data={"text/html": batch.add(md)}))
            out.cells.append(n)
    return out


_HEADING = re.compile(r'<h([12])((?:\s+[a-z-]+="[^"]*")*)>(.*?)</h\1>', re.DOTALL)


_MATH_PUNCT = re.compile(r'([(\[]?)(<span class="math inline">[^<]*</span>)([,.;:!?)\]]*)')


def keep_punctuation(page: str) -> str:
    r"""Bind brackets and punctuation to the inline math they touch (``<span class="nobr">``): else a
    narrow table cell may break between a formula and its comma, or a ``(`` and its formula.

    Examples
    --------
    >>> keep_punctuation('(<span class="math inline">\\(x\\)</span>), and <span class="math inline">y</span> z')
    '<span class="nobr">(<span class="math inline">\\(x\\)</span>),</span> and <span class="math inline">y</span> z'
    """
    def one(m):
        return f'<span class="nobr">{m.group(0)}</span>' if m.group(1) or m.group(3) else m.group(0)
    return _MATH_PUNCT.sub(one, page)


def unique_ids(page: str) -> tuple[str, list[str]]:
    """Make every ``id="..."`` unique (the second ``x`` becomes ``x-2``); return the page and the
    ids that were duplicated (a notebook that names one anchor twice)."""
    seen: dict[str, int] = {}
    dups: list[str] = []

    def one(m):
        i = m.group(1)
        seen[i] = seen.get(i, 0) + 1
        if seen[i] == 1:
            return m.group(0)
        dups.append(i)
        return f'id="{i}-{seen[i]}"'
    return re.sub(r'(?<![\w-])id="([^"]+)"', one, page), dups


def broken_links(page: str) -> list[str]:
    """Internal links (``href="#x"``) whose target id does not exist."""
    ids = set(re.findall(r'(?<![\w-])id="([^"]+)"', page))
    return sorted({h for h in re.findall(r'href="#([^"]+)"', page) if h not in ids})


def navigation(page: str) -> str:
    """The contents sidebar: the parts, every top-level heading, and under each the second-level
    headings (the sections of a chapter)."""
    top: list[dict[str, Any]] = []
    part: dict[str, Any] | None = None
    h1: dict[str, Any] | None = None
    for m in _HEADING.finditer(page):
        attrs, inner = m.group(2), m.group(3).strip()
        hid = re.search(r'\bid="([^"]+)"', attrs)
        if not hid:
            continue
        node: dict[str, Any] = {"link": f'<a href="#{hid.group(1)}">{inner}</a>', "kids": [], "part": 'class="part"' in attrs}
        if node["part"]:
            top.append(node)
            part, h1 = node, None
        elif m.group(1) == "1":
            (part["kids"] if part else top).append(node)
            h1 = node
        elif h1 is not None:
            h1["kids"].append(node)

    def ul(nodes):
        return "<ul>" + "".join(f'<li class="part"><span>{n["link"]}</span>{ul(n["kids"])}</li>' if n["part"]
                                else f'<li>{n["link"]}{ul(n["kids"])}</li>' for n in nodes) + "</ul>" if nodes else ""
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
            self.register_filter("filter_data_type", WidgetsDataTypeFilter(
                notebook_metadata=self._nb_metadata, parent=self, resources=resources))
            return TemplateExporter.from_notebook_node(self, nb, resources, **kw)

    return ReportExporter(template_name="wmr_html", extra_template_basedirs=[str(TEMPLATES)],
                          exclude_input_prompt=True, exclude_output_prompt=True)


def export_html(nb, out: Path) -> None:
    """Render the report notebook ``nb`` into ``out`` (atomically)."""
    from edition.files import atomic_write
    batch = Batch("html")
    prepared = _prepare(nb, batch)
    ref = batch.add(nb.metadata["wmr"]["paper"], inline=True)   # the title block's reference
    batch.convert()
    body, _ = _exporter().from_notebook_node(prepared, resources={
        "wmr_css": (TEMPLATES / "wmr_html" / "report.css").read_text(encoding="utf-8"), "wmr_mathjax_gz": mathjax_gz(),
        "wmr_paper_html": ref})
    body, dups = unique_ids(keep_punctuation(batch.fill(body)))
    if dups:
        say("html", f"WARNING: ids defined more than once, renamed: {', '.join(sorted(set(dups)))}")
    body = body.replace("<!--WMR-NAV-->", navigation(body), 1)
    bad = broken_links(body)
    if bad:
        say("html", f"WARNING: links to missing anchors: {', '.join(bad)}")
    atomic_write(out, body)
