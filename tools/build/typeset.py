"""Tables and figures of the report, each written once and rendered twice (HTML and LaTeX).

The report notebook holds them as raw cells whose metadata ``wmr`` describes them (:func:`table`,
:func:`figure`, :func:`part`); :mod:`tools.build.html` and :mod:`tools.build.pdf` render them with
:func:`render_html` and :func:`render_latex`. Cell text is Markdown with ``$...$`` math, converted
by the exporter's :class:`~tools.build.markup.Batch` (``md``). No index column, cells wrap, a
table spans pages in the PDF (``longtable``) and never runs past the margin.
"""
from __future__ import annotations

import base64
import html
import re
from pathlib import Path
from typing import Callable

__all__ = ["table", "figure", "part", "markdown", "display", "spec", "render_html", "render_latex", "image_for_html"]

Md = Callable[..., str]   # md(text, inline=False) -> placeholder of the converted fragment


def _raw(kind: str, **data):
    import nbformat
    c = nbformat.v4.new_raw_cell("")
    c.metadata["wmr"] = {"kind": kind, **data}
    return c


def spec(cell) -> dict | None:
    """The description of a special cell of the report notebook, or ``None`` for an ordinary cell."""
    return cell.get("metadata", {}).get("wmr") if cell.get("cell_type") == "raw" else None


def table(columns: list[tuple[str, float]], rows: list, *, cls: str = "", caption: str = ""):
    """A table cell.

    Parameters
    ----------
    columns : list of (str, float)
        Header (Markdown) and relative width of each column.
    rows : list
        Each row a list of Markdown cells, or a dict ``{"cells": [...], "span": bool, "end": bool}``:
        with ``span`` the row has fewer cells than the table has columns and its last cell spans
        the rest of the width (a formula under its label); ``end`` closes a group of rows (a rule
        follows; the PDF keeps a group on one page where it can).
    cls : str
        CSS class (HTML).
    caption : str
        Markdown above the table.
    """
    total = sum(w for _, w in columns) or 1.0
    cols = [[h, w / total] for h, w in columns]
    norm = []
    for r in rows:
        r = {"cells": list(r), "span": False, "end": True} if isinstance(r, (list, tuple)) else dict(r)
        r.setdefault("span", False)
        r.setdefault("end", True)
        if not (1 <= len(r["cells"]) <= len(cols) if r["span"] else len(r["cells"]) == len(cols)):
            raise ValueError(f"row has {len(r['cells'])} cells, the table {len(cols)} columns: {r['cells']!r}")
        norm.append(r)
    return _raw("table", columns=cols, rows=norm, cls=cls, caption=caption)


def figure(key: str, label: str, title: str, paper_caption: str, caption: str, images: dict):
    """A figure cell: one image, the paper's caption beside ours. ``images``: format -> path."""
    return _raw("figure", key=key, label=label, title=title, paper_caption=paper_caption, caption=caption,
                images={k: str(v) for k, v in images.items()})


def part(title: str, intro: str = ""):
    """The start of a part of the report (Part I: findings, Part II: derivations)."""
    return _raw("part", title=title, intro=intro)


# ----------------------------------------------------------------------------- HTML
def image_for_html(images: dict) -> tuple[str, bytes] | None:
    """(mime, bytes) of the image to embed: the figure's SVG."""
    svg = images.get("svg")
    if svg and Path(svg).exists():
        return "image/svg+xml", Path(svg).read_bytes()
    return None


def render_html(s: dict, md: Md) -> str:
    kind = s["kind"]
    if kind == "table":
        n = len(s["columns"])
        cols = "".join(f'<col style="width:{100 * w:.1f}%">' for _, w in s["columns"])
        head = "".join(f"<th>{md(h, inline=True)}</th>" for h, _ in s["columns"])
        body = []
        for r in s["rows"]:
            cls = ' class="end"' if r["end"] else ""
            if r["span"]:
                *lead, last = r["cells"]
                body.append(f"<tr{cls}>" + "".join(f'<td class="label">{md(c, inline=True)}</td>' for c in lead)
                            + f'<td colspan="{n - len(lead)}" class="span">{md(last)}</td></tr>')
            else:
                body.append(f"<tr{cls}>" + "".join(f"<td>{md(c, inline=True)}</td>" for c in r["cells"]) + "</tr>")
        cap = f'<div class="table-caption">{md(s["caption"])}</div>' if s.get("caption") else ""
        return (f'{cap}<div class="table-wrap"><table class="wmr-table {html.escape(s.get("cls", ""))}">'
                f"<colgroup>{cols}</colgroup><thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table></div>")
    if kind == "figure":
        img = image_for_html(s["images"])
        alt = html.escape(f"{s['label']}: {s['title']}" if s["label"] else s["title"], quote=True)
        pic = (f'<img src="data:{img[0]};base64,{base64.b64encode(img[1]).decode()}" alt="{alt}">' if img
               else f'<p class="missing">missing image figures/{html.escape(s["key"])}.svg</p>')
        head = (f"<b>{html.escape(s['label'])}.</b> " + md(s["title"], inline=True) if s["label"]
                else "<b>" + md(s["title"], inline=True) + ".</b>")
        if s["paper_caption"]:
            caps = (f'<div class="captions"><div class="cap"><p class="cap-h">In the paper</p>{md(s["paper_caption"])}</div>'
                    f'<div class="cap"><p class="cap-h">Computed in this edition</p>{md(s["caption"])}</div></div>')
        else:
            caps = f'<div class="captions one"><div class="cap">{md(s["caption"])}</div></div>'
        return (f'<figure class="wmr-figure" id="figure-{html.escape(s["key"])}">{pic}'
                f'<figcaption><p class="fig-title">{head}</p>{caps}</figcaption></figure>')
    if kind == "part":
        return (f'<h1 class="part" id="{_slug(s["title"])}">{html.escape(s["title"])}</h1>'
                + (md(s["intro"]) if s.get("intro") else ""))
    raise ValueError(f"unknown special cell kind {kind!r}")


def _slug(s: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", s.lower()).strip("-")


# ----------------------------------------------------------------------------- LaTeX
def render_latex(s: dict, md: Md) -> str:
    kind = s["kind"]
    if kind == "table":
        n = len(s["columns"])
        width = lambda w: rf"p{{\dimexpr(\linewidth-{2 * (n - 1)}\tabcolsep)*{round(1000 * w)}/1000\relax}}"
        spec_ = "@{}" + "".join(r">{\raggedright\arraybackslash}" + width(w) for _, w in s["columns"]) + "@{}"
        head = " & ".join(r"\textbf{" + md(h, inline=True) + "}" for h, _ in s["columns"]) + r" \\"
        out = [r"\begin{wmrtable}", rf"\begin{{longtable}}{{{spec_}}}", r"\toprule", head, r"\midrule",
               r"\endhead", r"\bottomrule", r"\endlastfoot"]
        rows = s["rows"]
        for i, r in enumerate(rows):
            if r["span"]:
                *lead, last = r["cells"]
                rest = sum(w for _, w in s["columns"][len(lead):])
                k = n - len(lead)
                width = rf"\dimexpr(\linewidth-{2 * (n - 1)}\tabcolsep)*{round(1000 * rest)}/1000+{2 * (k - 1)}\tabcolsep\relax"
                edge = "" if lead else "@{}"
                line = "".join(md(c, inline=True) + " & " for c in lead) + \
                    rf"\multicolumn{{{k}}}{{{edge}>{{\raggedright\arraybackslash}}p{{{width}}}@{{}}}}{{{md(last)}}}"
            else:
                line = " & ".join(md(c, inline=True) for c in r["cells"])
            last = i == len(rows) - 1
            out.append(line + (r" \\" if r["end"] else r" \\*") + (r" \midrule\relax" if r["end"] and not last else ""))
        out += [r"\end{longtable}", r"\end{wmrtable}"]
        cap = (md(s["caption"]) + "\n\n") if s.get("caption") else ""
        return cap + "\n".join(out)
    if kind == "figure":
        pdf = s["images"].get("pdf") or s["images"].get("png")
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
    if kind == "part":
        return rf"\wmrpart{{{s['title']}}}" + ("\n\n" + md(s["intro"]) if s.get("intro") else "")
    raise ValueError(f"unknown special cell kind {kind!r}")


def _tex_path(p: str) -> str:
    p = Path(p).as_posix()
    if any(c in p for c in "%#{}\\ "):
        raise ValueError(f"image path not usable in LaTeX: {p!r}")
    return p


def markdown(src: str):
    """An ordinary Markdown cell of the report notebook."""
    import nbformat
    return nbformat.v4.new_markdown_cell(src)


def display(body: str) -> str:
    """A LaTeX body (a ledger's ``printed``/``corrected``) as Markdown display math."""
    lines = [l for l in body.strip().splitlines() if l.strip()]   # a blank line would end the math
    return "$$\n" + "\n".join(lines) + "\n$$" if lines else ""
