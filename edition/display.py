r"""How a chapter shows results: everything a reader sees goes out as Markdown with ``$$...$$`` math.

One path, one size of type: :func:`show` (a formula), :func:`say` (a paragraph), :func:`table`
(a Markdown table), :func:`quote` (what the paper prints, from the transcription), :func:`latex`
and :func:`aligned_sum` (LaTeX of SymPy objects), :func:`image` and :func:`figure` (a picture with
its alt text).  No ``print``, no raw data frames.  IPython is imported only when something is displayed.

Numbers in math go through :func:`tex`: a computed value that is zero up to round-off is written
``0`` (or, with ``bound=True``, as a bound such as :math:`< 10^{-12}`), a small or large one as
:math:`a\times10^{k}` -- never Python's ``2.88e-16``.  :func:`raw_output` finds what must not reach a
reader (raw e-notation, printed Python lists, dicts and sets); the answer-table harness
(:mod:`edition.exercises.table`) applies it to every verdict.
"""

from __future__ import annotations

import re

import numpy as np
import sympy as sp

from .text import RESOLUTION, bound, number
from .transcription import claim, printed

__all__ = [
    "UNDEFINED",
    "latex",
    "show",
    "aligned_sum",
    "say",
    "table",
    "quote",
    "tex",
    "raw_output",
    "image",
    "figure",
    "png",
]

#: raw e-notation as Python prints it (``2.88e-16``, ``1.21e+04``), not inside a word or a LaTeX command
RAW_E = re.compile(r"(?<![A-Za-z_\\])[-+]?\d(?:\.\d+)?e[-+]?\d+")
#: a printed Python container: ``[6]`` (a list of one integer), ``{d3x: 1}`` (a dict), ``{'a', 'b'}`` (a set),
#: ``array(...)``; a bracket after ``_``, ``^``, ``{`` or a word (an index) or before ``(`` (a link) is not one
RAW_CONTAINER = re.compile(
    r"(?<![\w\\^_{])\[-?\d+\](?!\()"  # [6]
    r"|(?<!\\)\{\s*['\"]?[A-Za-z_]\w*['\"]?\s*:\s"  # {d3x: 1}
    r"|(?<!\\)\{\s*'[^']*'\s*,|\barray\("
)  # {'a', 'b'}, array(...)


def _display(*objs):
    from IPython.display import display

    display(*objs)


def _markdown(text):
    from IPython.display import Markdown

    return Markdown(text)


#: how a quantity that does not exist (SymPy's ``nan``, NumPy's NaN from 0/0) is written for the reader
UNDEFINED = "undefined"
UNDEFINED_TEX = rf"\text{{{UNDEFINED}}}"


def latex(obj):
    r"""LaTeX of a SymPy object (matrices with square brackets), or a string unchanged.

    SymPy's ``nan`` (what 0/0 evaluates to) is written as the word it means, *undefined*.

    Parameters
    ----------
    obj : SymPy object or str

    Returns
    -------
    str

    Examples
    --------
    >>> latex(sp.Matrix([[1, 0]])), latex(r"\alpha"), latex(sp.Integer(0) / 0)
    ('\\begin{bmatrix}1 & 0\\end{bmatrix}', '\\alpha', '\\text{undefined}')
    """
    if isinstance(obj, str):
        return obj
    if obj is sp.nan:
        return UNDEFINED_TEX
    return sp.latex(obj, mat_str="bmatrix", mat_delim="")


def show(lhs, expr=None, tag=None, per_line=None):
    r"""Typeset ``lhs = expr`` as display math (Markdown ``$$...$$``).

    Parameters
    ----------
    lhs : str
        LaTeX of the left side, or of the whole formula when ``expr`` is None.
    expr : SymPy object or str, optional
        The right side.
    tag : str, optional
        An equation tag, e.g. ``"59"`` for ``\tag{59}``.
    per_line : int, optional
        Break a SymPy sum into lines of this many terms (``aligned``), in SymPy's printing order:
        a long sum then keeps the size of the text instead of being shrunk to the line.

    Returns
    -------
    None
    """
    if per_line is not None:
        _check_per_line(per_line)
    if expr is None:
        body = lhs
    elif per_line is not None and isinstance(expr, sp.Add):
        body = aligned_sum(lhs, expr, per_line)
    else:
        body = f"{lhs} = {latex(expr)}"
    if tag is not None:
        body += rf" \tag{{{tag}}}"
    _display(_markdown(f"$$\n{body}\n$$"))


def _check_per_line(per_line):
    if isinstance(per_line, bool) or not isinstance(per_line, int):
        raise TypeError(f"per_line must be an int, got {per_line!r}")
    if per_line < 1:
        raise ValueError(f"per_line must be at least 1, got {per_line}")


def aligned_sum(lhs, expr, per_line):
    r"""LaTeX of ``lhs = expr`` with the terms of the sum ``expr`` in lines of ``per_line`` (``aligned``).

    Parameters
    ----------
    lhs : str
        LaTeX of the left side.
    expr : sympy.Add
        The right side; its terms are taken in SymPy's printing order.
    per_line : int
        Terms per line, at least 1.

    Returns
    -------
    str
        A LaTeX body (no ``$``).

    Examples
    --------
    >>> x, y, z = sp.symbols("x y z")
    >>> aligned_sum("s", x - y + z, 2)
    '\\begin{aligned}s = {}& x - y\\\\ &+ z\\end{aligned}'
    """
    _check_per_line(per_line)
    parts = []
    for k, term in enumerate(expr.as_ordered_terms()):
        neg = term.could_extract_minus_sign()
        text = latex(-term if neg else term)
        parts.append(("- " if neg else ("+ " if k else "")) + text)
    lines = [" ".join(parts[i : i + per_line]) for i in range(0, len(parts), per_line)]
    return r"\begin{aligned}" + lhs + " = {}& " + r"\\ &".join(lines) + r"\end{aligned}"


def say(text):
    """Display a Markdown paragraph (for results: no ``print``).

    Parameters
    ----------
    text : str
        Markdown with ``$...$`` math.

    Returns
    -------
    None
    """
    _display(_markdown(text))


def _cell(v, in_array=False):
    if isinstance(v, (bool, np.bool_)):
        return "yes" if v else "no"
    if isinstance(v, (float, np.floating)):
        x = float(v)
        if np.isnan(x):  # a quantity that does not exist here (0/0)
            return UNDEFINED
        if 0 < abs(x) < RESOLUTION:  # round-off: no digits that differ between machines
            return "$0$" if in_array else f"$< 10^{{{int(np.log10(RESOLUTION))}}}$"
        return f"${number(x)}$"
    if isinstance(v, (list, tuple, set, frozenset, np.ndarray)):
        items = sorted(v) if isinstance(v, (set, frozenset)) else list(np.ravel(v) if isinstance(v, np.ndarray) else v)
        cells = [_cell(x, in_array=True) for x in items]
        return UNDEFINED if cells and all(c == UNDEFINED for c in cells) else ", ".join(cells)
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    return str(v).replace("|", r"\|").replace("\n", " ")


def table(rows, columns=None):
    r"""A Markdown table (no index column): the one way a chapter shows tabular results.

    Parameters
    ----------
    rows : list of dict or list of sequence
        One entry per row.  Booleans print as yes/no, NaN as "undefined", floats with 3 significant digits in
        math (round-off below :data:`edition.text.RESOLUTION` as a bound, or 0 inside a
        vector), lists as comma-separated values.
    columns : sequence of str, optional
        Headers; for dict rows also the keys, in order (default: the first row's keys).

    Returns
    -------
    None

    """
    rows = list(rows)
    if rows and isinstance(rows[0], dict):
        columns = list(columns or rows[0].keys())
        body = [[r.get(c, "") for c in columns] for r in rows]
    else:
        if columns is None:
            raise ValueError("columns must be given for rows that are not dicts")
        body = [list(r) for r in rows]
    head = "| " + " | ".join(columns) + " |\n|" + "---|" * len(columns) + "\n"
    text = head + "".join("| " + " | ".join(_cell(v) for v in r) + " |\n" for r in body)
    _display(_markdown(text))


def quote(id):
    r"""Display what the paper says: equation ``id`` as printed (with ``\tag``), or the claim ``id``.

    Parameters
    ----------
    id : int or str
        An equation number, or a claim's slug.

    Returns
    -------
    None
        (Read the transcription itself with :func:`edition.printed` or :func:`edition.claim`.)
    """
    if str(id).isdigit():
        p = printed(id)
        text = f"*As printed (Section {p.section}):*\n\n$$\n{p.latex} \\tag{{{p.id}}}\n$$"
        if p.doubt:
            text += f"\n\n*Transcription:* {p.doubt}"
        _display(_markdown(text))
        return None
    c = claim(id)
    _display(_markdown(f"> {c.text} ({_where(c.section)})"))
    return None


def _where(section):
    """Where in the paper: ``"4.2"`` -> ``"Section 4.2"``, ``"3.2, 6"`` -> ``"Sections 3.2 and 6"``,
    ``"Abstract, 7"`` -> ``"Abstract and Section 7"``."""
    parts = [p.strip() for p in str(section).split(",") if p.strip()]
    numbered = [p for p in parts if p[:1].isdigit()]
    named = [p for p in parts if not p[:1].isdigit()]
    if numbered:
        named.append(
            ("Section " if len(numbered) == 1 else "Sections ")
            + (numbered[0] if len(numbered) == 1 else ", ".join(numbered[:-1]) + " and " + numbered[-1])
        )
    return " and ".join(named)


# ------------------------------------------------------------------------------------- numbers for readers
def tex(value, digits=3, scale=1.0, as_bound=False, resolution=RESOLUTION):
    r"""LaTeX of a computed number for ``$...$``: round-off as ``0`` (or a bound), else ``digits`` digits.

    Parameters
    ----------
    value : float
    digits : int, optional
        Significant digits of a value that is not round-off.
    scale : float, optional
        The size of the quantities it was computed from: :math:`|x| <` ``resolution * scale`` is round-off.
    as_bound : bool, optional
        Write round-off as :math:`< 10^{-12}` (relative to ``scale``) instead of ``0``.
    resolution : float, optional

    Returns
    -------
    str

    Examples
    --------
    >>> tex(2.88e-16), tex(2.88e-16, as_bound=True), tex(-0.0), tex(4.93e-7), tex(12098.4), tex(0.50332)
    ('0', '< 10^{-12}', '0', '4.93\\times10^{-7}', '1.21\\times10^{4}', '0.503')
    """
    x, s = float(value), abs(float(scale))
    if not np.isfinite(s) or s <= 0:
        raise ValueError(f"scale must be a positive finite number, got {scale!r}")
    if np.isfinite(x) and abs(x) < resolution * s:
        return bound(abs(x) / s, resolution, latex=True) if as_bound else "0"
    return number(x, digits)


def raw_output(text):
    r"""The fragments of ``text`` a reader must not see: raw e-notation and printed Python containers.

    Parameters
    ----------
    text : str

    Returns
    -------
    list of str
        Empty when the text is clean.

    Examples
    --------
    >>> raw_output("$|det J| = 2.88e-16$ and rank [6]"), raw_output(r"$4.9\\times10^{-11}$, see [Figure 7](#f7)")
    (['2.88e-16', '[6]'], [])
    """
    return [m.group(0) for m in RAW_E.finditer(text)] + [m.group(0) for m in RAW_CONTAINER.finditer(text)]


# ------------------------------------------------------------------------------------- pictures
def png(fig, dpi=150):
    """The figure as PNG bytes, drawn with the package's style (:func:`wmr.plot.style.style`).

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    dpi : int, optional

    Returns
    -------
    bytes
    """
    import io

    from wmr.plot.style import style

    buf = io.BytesIO()
    with style():
        fig.savefig(buf, format="png", dpi=dpi)
    return buf.getvalue()


def image(data, alt, width=None, metadata=None):
    """Display PNG bytes with alt text: an ``<img alt=...>`` for JupyterLab and HTML, the PNG for PDF.

    JupyterLab's PNG renderer drops alt text, so the output carries ``text/html`` (an image with ``alt``,
    preferred by JupyterLab and nbconvert's HTML), ``image/png`` (used by LaTeX/PDF) and ``text/plain``
    (the alt text, for a reader without images).

    Parameters
    ----------
    data : bytes
        A PNG.
    alt : str
        What the picture shows, in words (plain text; no Markdown or LaTeX).
    width : int, optional
        Display width in pixels (the picture shrinks to fit a narrower notebook).
    metadata : dict, optional
        Output metadata (e.g. ``{"wmr_figure": key}``, which the report build reads).

    Returns
    -------
    None
    """
    from IPython.display import display

    from wmr.plot.design import picture_bundle

    bundle = picture_bundle(data, alt, width)
    meta = dict(metadata or {})
    if width:
        meta["image/png"] = {"width": int(width)}
    display(bundle, raw=True, metadata=meta)


def figure(fig, caption, alt, width=None, dpi=150):
    """Display a matplotlib figure with its alt text and, below it, its caption (Markdown).

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    caption : str
        Markdown.
    alt : str
        What the figure shows, in words (see :func:`image`).
    width : int, optional
        Display width in pixels (default 110 per inch of the figure).
    dpi : int, optional

    Returns
    -------
    None
    """
    image(png(fig, dpi), alt, width or round(fig.get_figwidth() * 110))
    _display(_markdown(caption))
