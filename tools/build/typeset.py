"""The two cells Markdown cannot say: a figure (one image, the paper's caption beside ours) and the
start of a part of the report, held in the report notebook as raw cells described by their metadata
``wmr`` and rendered once to HTML (:func:`render_html`) and once to LaTeX (:func:`render_latex`).
Captions are Markdown, converted by the exporter's :class:`~tools.build.markup.Batch` (``md``); a
figure's metadata is ``figures/<key>.json``, written by ``edition.figures`` (:func:`read_figures`)."""

from __future__ import annotations

import base64
import html
import json
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

from . import BuildError

__all__ = ["figure", "part", "read_figures", "render_html", "render_latex", "spec"]

Md = Callable[..., str]  # md(text, inline=False) -> placeholder of the converted fragment
_GRAPHICS = r"\includegraphics[width=\linewidth,height=0.5\textheight,keepaspectratio]"


def read_figures(figdir: Path) -> dict[str, dict[str, Any]]:
    """``{key: metadata}`` of every ``figures/<key>.json`` that describes a figure, with ``label``
    (``Figure 7``, or empty for this edition's own) and ``images`` (format -> path of the files that exist)."""
    out = {}
    for p in sorted(Path(figdir).glob("*.json")):
        m = json.loads(p.read_text(encoding="utf-8"))
        if isinstance(m, dict) and "title" in m:
            label = f"Figure {m['number']}" if m.get("number") else ""
            captions = {c: m.get(c) or "" for c in ("paper_caption", "caption")}
            images = {f: str(p.with_suffix("." + f)) for f in ("svg", "pdf") if p.with_suffix("." + f).exists()}
            out[p.stem] = {"key": p.stem, "label": label, "title": m["title"], **captions, "images": images}
    return out


def _raw(kind: str, **data):
    import nbformat

    return nbformat.v4.new_raw_cell("", metadata={"wmr": {"kind": kind, **data}})


def figure(meta: dict[str, Any]):
    """A figure cell from the figure's metadata (:func:`read_figures`)."""
    return _raw("figure", **{k: meta[k] for k in ("key", "label", "title", "paper_caption", "caption", "images")})


def part(title: str, intro: str = ""):
    """The start of a part of the report (Part I: findings, Part II: derivations)."""
    return _raw("part", title=title, intro=intro)


def spec(cell) -> dict | None:
    """The description of a special cell of the report notebook, or ``None`` for an ordinary cell."""
    return cell.get("metadata", {}).get("wmr") if cell.get("cell_type") == "raw" else None


def render_html(s: dict, md: Md) -> str:
    """The HTML of a special cell: the figure's SVG inlined (nothing fetched), its captions side by side."""
    if s["kind"] == "part":
        slug = re.sub(r"[^a-z0-9]+", "-", s["title"].lower()).strip("-")
        heading = f'<h1 class="part" id="{slug}">{html.escape(s["title"])}</h1>'
        return heading + (md(s["intro"]) if s["intro"] else "")
    alt = html.escape(f"{s['label']}: {s['title']}" if s["label"] else s["title"], quote=True)
    if svg := s["images"].get("svg"):
        pic = f'<img src="data:image/svg+xml;base64,{base64.b64encode(Path(svg).read_bytes()).decode()}" alt="{alt}">'
    else:
        pic = f'<p class="missing">missing image figures/{html.escape(s["key"])}.svg</p>'
    title = md(s["title"], inline=True)
    head = f"<b>{html.escape(s['label'])}.</b> {title}" if s["label"] else f"<b>{title}.</b>"
    if s["paper_caption"]:
        paper = f'<div class="cap"><p class="cap-h">In the paper</p>{md(s["paper_caption"])}</div>'
        ours = f'<div class="cap"><p class="cap-h">Computed in this edition</p>{md(s["caption"])}</div>'
        caps = f'<div class="captions">{paper}{ours}</div>'
    else:
        caps = f'<div class="captions one"><div class="cap">{md(s["caption"])}</div></div>'
    figure = f'<figure class="wmr-figure" id="figure-{html.escape(s["key"])}">{pic}'
    return figure + f'<figcaption><p class="fig-title">{head}</p>{caps}</figcaption></figure>'


def _minipage(width: str, body: str, head: str = "") -> str:
    """``body`` in a top-aligned minipage ``width`` of the line wide, under the caption heading ``head``."""
    heading = rf"\wmrcaphead{{{head}}}" if head else ""
    return rf"\begin{{minipage}}[t]{{{width}\linewidth}}{heading}{body}\end{{minipage}}"


def render_latex(s: dict, md: Md) -> str:
    """The LaTeX of a special cell: the figure's PDF, its captions in two minipages."""
    if s["kind"] == "part":
        return rf"\wmrpart{{{s['title']}}}" + ("\n\n" + md(s["intro"]) if s["intro"] else "")
    pdf = s["images"].get("pdf")
    if pdf and any(c in pdf for c in "%#{}\\ "):
        raise BuildError(f"image path not usable in LaTeX: {pdf!r}")
    pic = _GRAPHICS + "{" + Path(pdf).as_posix() + "}" if pdf else r"\fbox{missing image}"
    title = md(s["title"], inline=True)
    head = rf"\textbf{{{s['label']}.}} {title}" if s["label"] else r"\textbf{" + title + ".}"
    if s["paper_caption"]:
        paper = _minipage("0.485", md(s["paper_caption"]), "In the paper")
        caps = paper + r"\hfill" + _minipage("0.485", md(s["caption"]), "Computed in this edition")
    else:
        caps = _minipage("", md(s["caption"]))
    begin = rf"\begin{{wmrfigure}}{{figure-{s['key']}}}"
    return "\n".join([begin, pic, r"\wmrfigtitle{" + head + "}", caps, r"\end{wmrfigure}"])
