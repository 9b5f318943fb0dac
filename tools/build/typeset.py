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

Md = Callable[..., str]   # md(text, inline=False) -> placeholder of the converted fragment


def read_figures(figdir: Path) -> dict[str, dict[str, Any]]:
    """``{key: metadata}`` of every ``figures/<key>.json`` that describes a figure, with ``label``
    (``Figure 7``, or empty for this edition's own) and ``images`` (format -> path of the files that exist)."""
    out = {}
    for p in sorted(Path(figdir).glob("*.json")):
        m = json.loads(p.read_text(encoding="utf-8"))
        if isinstance(m, dict) and "title" in m:
            number = str(m.get("number") or "")
            out[p.stem] = {"key": p.stem, "label": f"Figure {number}" if number else "", "title": m["title"],
                           "paper_caption": m.get("paper_caption") or "", "caption": m.get("caption") or "",
                           "images": {f: str(p.with_suffix("." + f)) for f in ("svg", "pdf") if p.with_suffix("." + f).exists()}}
    return out


def _raw(kind: str, **data):
    import nbformat
    c = nbformat.v4.new_raw_cell("")
    c.metadata["wmr"] = {"kind": kind, **data}
    return c


def figure(meta: dict[str, Any]):
    """A figure cell from the figure's metadata (:func:`read_figures`)."""
    return _raw("figure", **{k: meta[k] for k in ("key", "label", "title", "paper_caption", "caption", "images")})


def part(title: str, intro: str = ""):
    """The start of a part of the report (Part I: findings, Part II: derivations)."""
    return _raw("part", title=title, intro=intro)


def spec(cell) -> dict | None:
    """The description of a special cell of the report notebook, or ``None`` for an ordinary cell."""
    return cell.get("metadata", {}).get("wmr") if cell.get("cell_type") == "raw" else None


def _slug(s: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", s.lower()).strip("-")


def render_html(s: dict, md: Md) -> str:
    """The HTML of a special cell: the figure's SVG inlined (nothing fetched), its captions side by side."""
    if s["kind"] == "part":
        return f'<h1 class="part" id="{_slug(s["title"])}">{html.escape(s["title"])}</h1>' + (md(s["intro"]) if s["intro"] else "")
    svg = s["images"].get("svg")
    alt = html.escape(f"{s['label']}: {s['title']}" if s["label"] else s["title"], quote=True)
    pic = (f'<img src="data:image/svg+xml;base64,{base64.b64encode(Path(svg).read_bytes()).decode()}" alt="{alt}">'
           if svg else f'<p class="missing">missing image figures/{html.escape(s["key"])}.svg</p>')
    head = (f"<b>{html.escape(s['label'])}.</b> " + md(s["title"], inline=True) if s["label"]
            else "<b>" + md(s["title"], inline=True) + ".</b>")
    if s["paper_caption"]:
        caps = (f'<div class="captions"><div class="cap"><p class="cap-h">In the paper</p>{md(s["paper_caption"])}</div>'
                f'<div class="cap"><p class="cap-h">Computed in this edition</p>{md(s["caption"])}</div></div>')
    else:
        caps = f'<div class="captions one"><div class="cap">{md(s["caption"])}</div></div>'
    return (f'<figure class="wmr-figure" id="figure-{html.escape(s["key"])}">{pic}'
            f'<figcaption><p class="fig-title">{head}</p>{caps}</figcaption></figure>')


def _tex_path(p: str) -> str:
    if any(c in p for c in "%#{}\\ "):
        raise BuildError(f"image path not usable in LaTeX: {p!r}")
    return Path(p).as_posix()


def render_latex(s: dict, md: Md) -> str:
    """The LaTeX of a special cell: the figure's PDF, its captions in two minipages."""
    if s["kind"] == "part":
        return rf"\wmrpart{{{s['title']}}}" + ("\n\n" + md(s["intro"]) if s["intro"] else "")
    pdf = s["images"].get("pdf")
    pic = (rf"\includegraphics[width=\linewidth,height=0.5\textheight,keepaspectratio]{{{_tex_path(pdf)}}}"
           if pdf else r"\fbox{missing image}")
    head = (rf"\textbf{{{s['label']}.}} " + md(s["title"], inline=True) if s["label"]
            else r"\textbf{" + md(s["title"], inline=True) + ".}")
    if s["paper_caption"]:
        caps = (r"\begin{minipage}[t]{0.485\linewidth}\wmrcaphead{In the paper}" + md(s["paper_caption"])
                + r"\end{minipage}\hfill\begin{minipage}[t]{0.485\linewidth}\wmrcaphead{Computed in this edition}"
                + md(s["caption"]) + r"\end{minipage}")
    else:
        caps = r"\begin{minipage}[t]{\linewidth}" + md(s["caption"]) + r"\end{minipage}"
    return (rf"\begin{{wmrfigure}}{{figure-{s['key']}}}" + "\n" + pic + "\n"
            + r"\wmrfigtitle{" + head + "}\n" + caps + "\n" + r"\end{wmrfigure}")
