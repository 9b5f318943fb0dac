"""Rendering a figure to bytes and writing its files: deterministic, atomic, with no per-build data.

A figure is rendered once per format in memory (:func:`render`) and each file is then written
atomically (:func:`edition.files.atomic_write`).  The files are the same on every machine and
every run: matplotlib settings from :data:`wmr.plot.style.RC` (fixed SVG hash salt, text as
paths), metadata without dates, no git commit or path inside (the report names the commit), and
numbers in the JSON without round-off digits (:func:`edition.figures.common.numbers`).
"""

from __future__ import annotations

import io
import json

from ..files import atomic_write
from .common import numbers

__all__ = ["FORMATS", "formats", "render", "record", "write"]

#: Formats written for a figure unless its module says otherwise (``FORMATS`` in the module).
FORMATS = ("svg", "pdf")


def formats(module):
    """The formats written for a figure module (its ``FORMATS``, else :data:`FORMATS`).

    Parameters
    ----------
    module : module
        A figure module (:data:`edition.figures.FIGURES`).

    Returns
    -------
    tuple of str
    """
    return tuple(getattr(module, "FORMATS", FORMATS))


def _metadata(fmt, title, creator):
    if fmt == "svg":
        return {"Title": title, "Creator": creator, "Date": None}
    if fmt == "pdf":
        return {"Title": title, "Creator": creator, "CreationDate": None, "ModDate": None}
    return {"Title": title, "Software": creator}


def _palette_png(blob, metadata):
    """The PNG as 256 colours (median cut, no dithering), about a third of the size, same look.

    The drawings have few colours (a palette of ten, 64-level colour maps, anti-aliased edges), so
    the palette is not visible; Pillow's median cut and zlib are deterministic.
    """
    from PIL import Image, PngImagePlugin

    im = Image.open(io.BytesIO(blob)).convert("RGB")
    pal = im.quantize(256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    info = PngImagePlugin.PngInfo()
    for k, v in metadata.items():
        info.add_text(k, v)
    buf = io.BytesIO()
    pal.save(buf, format="PNG", optimize=True, pnginfo=info, dpi=im.info.get("dpi", (200, 200)))
    return buf.getvalue()


def render(fig, fmts, *, title="", creator="wmr"):
    """Render ``fig`` to each format in ``fmts``; returns ``{fmt: bytes}``.

    The layout is computed once, before any format is rendered, and then frozen: every format, and
    every choice of formats, shows the same layout.  A PNG (for display in a notebook) is reduced to
    a 256-colour palette.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    fmts : sequence of str
        ``"png"``, ``"svg"``, ``"pdf"``.
    title, creator : str
        Metadata (no dates, no commit).

    Returns
    -------
    dict
    """
    from wmr.plot.style import style

    out = {}
    with style():
        if fig.get_layout_engine() is not None:
            fig.draw_without_rendering()
            fig.set_layout_engine("none")
        for fmt in fmts:
            buf = io.BytesIO()
            fig.savefig(buf, format=fmt, metadata=_metadata(fmt, title, creator))
            out[fmt] = _palette_png(buf.getvalue(), _metadata(fmt, title, creator)) if fmt == "png" else buf.getvalue()
    return out


def record(key, module, data):
    """The JSON record of a figure: key, number, title, the paper's caption, our caption, the numbers, the formats.

    Parameters
    ----------
    key : str
        The figure's key.
    module : module
        Its figure module.
    data : data class
        Its numbers (``module.data(...)``).

    Returns
    -------
    dict
        Ready for :func:`json.dumps` (the numbers through :func:`edition.figures.common.numbers`).
    """
    return {
        "key": key,
        "number": module.NUMBER,
        "title": module.TITLE,
        "paper_caption": module.PAPER_CAPTION,
        "caption": module.caption(data),
        "numbers": numbers(data),
        "formats": list(formats(module)),
    }


def write(outdir, key, files, rec):
    """Write ``outdir/<key>.<fmt>`` for each rendered file and ``outdir/<key>.json``, atomically.

    Parameters
    ----------
    outdir : str or os.PathLike
        Created if needed.
    key : str
        The figure's key (the files' stem).
    files : dict
        ``{fmt: bytes}`` from :func:`render`.
    rec : dict
        The record (:func:`record`).

    Returns
    -------
    list of pathlib.Path
    """
    from pathlib import Path

    outdir = Path(outdir)
    paths = [atomic_write(outdir / f"{key}.{fmt}", blob) for fmt, blob in files.items()]
    paths.append(atomic_write(outdir / f"{key}.json", json.dumps(rec, indent=2, ensure_ascii=False) + "\n"))
    return paths
