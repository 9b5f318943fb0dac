"""Markdown to HTML and to LaTeX, through one reader: pandoc's GitHub-flavoured Markdown with
``$...$`` math and typographic quotes and dashes (``gfm+tex_math_dollars+smart``: "drifts" is set
with opening and closing quotes, ``--`` as an en dash), the closest to what Jupyter shows.

Every Markdown fragment of the report (cells, Markdown outputs, table cells, captions) is
converted in **one** pandoc call per format (:class:`Batch`), so the HTML and the PDF read the
same text the same way, heading ids are unique across the whole report, and a build starts two
pandoc processes, not hundreds. The text is taken as it is: ledger fields and notebooks write
their math as ``$...$`` at the source, nothing here guesses which words are TeX.
"""
from __future__ import annotations

import re
import shutil

from . import procs
from .log import BuildError

__all__ = ["READER", "Batch", "math_body", "text_of", "table_math_pipes", "tex_anchor_tokens", "tex_anchor_targets"]

READER = "gfm+tex_math_dollars+smart"
_SEP = "WMRFRAGMENT{:05d}"
_SEP_RE = {"html": re.compile(r"\n*<p>WMRFRAGMENT(\d{5})</p>\n*"),
           "latex": re.compile(r"\n*^WMRFRAGMENT(\d{5})$\n*", re.M)}
_ANCHOR = re.compile(r'<a\s+(?:id|name)="([^"]+)"\s*>\s*</a>')
_TOKEN = re.compile(r"WMRANCHOR([0-9a-f]+)Z")


_TABLE_ROW = re.compile(r"^\s*\|.*\|\s*$", re.M)
_INLINE_MATH = re.compile(r"(?<!\\)\$(?!\$)(.+?)(?<!\\)\$")


def table_math_pipes(md: str) -> str:
    r"""On a row of a Markdown table, a ``|`` inside ``$...$`` belongs to the formula (an absolute
    value, a norm); GitHub-flavoured Markdown would split the cell there, so it is written
    ``\vert{}`` (``\Vert{}`` for ``\|``): the empty group ends the command without a space, so
    that a closing ``$`` still follows a non-space and pandoc still reads the formula as math.

    Examples
    --------
    >>> print(table_math_pipes(r"| a | $\min|CC_f|$ |"))
    | a | $\min\vert{}CC_f\vert{}$ |
    >>> table_math_pipes("not a table: $|x|$")
    'not a table: $|x|$'
    """
    def row(m):
        return _INLINE_MATH.sub(lambda k: "$" + k.group(1).replace("\\|", "\\Vert{}").replace("|", "\\vert{}") + "$",
                                m.group(0))
    return _TABLE_ROW.sub(row, md)


def tex_anchor_tokens(md: str) -> str:
    """``<a id="eq-59"></a>`` (raw HTML, which the LaTeX writer drops) -> a plain-text token
    that survives pandoc and becomes ``\\hypertarget`` in :func:`tex_anchor_targets`."""
    return _ANCHOR.sub(lambda m: "WMRANCHOR" + m.group(1).encode().hex() + "Z", md)


def tex_anchor_targets(tex: str) -> str:
    return _TOKEN.sub(lambda m: r"\hypertarget{" + bytes.fromhex(m.group(1)).decode() + "}{}", tex)


class Batch:
    """Markdown fragments collected, then converted by one pandoc call.

    ``add(md)`` returns a placeholder string; ``convert()`` runs pandoc; ``fill(text)`` replaces
    every placeholder in ``text`` by its converted fragment.

    Parameters
    ----------
    to : {"html", "latex"}
    """

    def __init__(self, to: str):
        if to not in _SEP_RE:
            raise ValueError(f"to must be 'html' or 'latex', got {to!r}")
        self.to = to
        self._src: list[str] = []
        self._out: list[str] | None = None

    def add(self, md: str, inline: bool = False) -> str:
        """Queue ``md``; return the placeholder that :meth:`fill` replaces. ``inline``: drop the
        paragraph around a one-paragraph result (for table cells and captions)."""
        md = table_math_pipes(md)
        if self.to == "latex":
            md = tex_anchor_tokens(md)
        self._src.append(md)
        return f"\x00WMR{len(self._src) - 1}{'i' if inline else 'b'}\x00"

    def convert(self) -> None:
        if not self._src:
            self._out = []
            return
        if not shutil.which("pandoc"):
            raise BuildError("pandoc not found: run `make report` (it installs it) or apt-get install pandoc")
        src = "".join(f"{_SEP.format(i)}\n\n{s.strip()}\n\n" for i, s in enumerate(self._src))
        args = ["pandoc", "-f", READER, "-t", "html5" if self.to == "html" else "latex", "--wrap=none"]
        if self.to == "html":
            args.append("--mathjax")
        p = procs.run(args, input=src, timeout=600)
        if p.returncode != 0:
            raise BuildError(f"pandoc failed (exit {p.returncode}): {p.stderr[-3000:]}")
        parts = _SEP_RE[self.to].split("\n" + p.stdout)
        # parts = [before, idx0, text0, idx1, text1, ...]
        out = [""] * len(self._src)
        for i in range(1, len(parts) - 1, 2):
            out[int(parts[i])] = parts[i + 1].strip("\n")
        if len(parts) != 2 * len(self._src) + 1:
            raise BuildError(f"pandoc output could not be split back into {len(self._src)} fragments")
        if self.to == "latex":
            out = [tex_anchor_targets(o) for o in out]
        self._out = out

    def fill(self, text: str) -> str:
        if self._out is None:
            raise RuntimeError("convert() first")

        def one(m):
            s = self._out[int(m.group(1))]
            if m.group(2) == "i":
                s = _unwrap(s, self.to)
            return s
        return re.sub(r"\x00WMR(\d+)([ib])\x00", one, text)


def _unwrap(s: str, to: str) -> str:
    if to == "html":
        m = re.fullmatch(r"<p>(.*)</p>", s.strip(), re.S)
        return m.group(1) if m and "<p>" not in m.group(1) else s
    return s.strip()


def text_of(value) -> str:
    """A notebook's multi-line string field (a str, or a list of lines) as one string."""
    return value if isinstance(value, str) else "".join(value)


_MATH_ONLY = re.compile(r"^\s*(\$\$|\$|\\\[)(.*?)(\$\$|\$|\\\])\s*$", re.S)


def math_body(latex_output: str) -> str | None:
    """The body of a ``text/latex`` output that is one formula (SymPy's ``$\\displaystyle ...$``,
    ``$$...$$`` or ``\\[...\\]``), without delimiters and ``\\displaystyle``; ``None`` otherwise."""
    m = _MATH_ONLY.match(latex_output)
    if not m or {m.group(1), m.group(3)} not in ({"$"}, {"$$"}, {"\\[", "\\]"}):
        return None
    body = m.group(2).strip()
    if "$" in body:
        return None
    return re.sub(r"^\\displaystyle\s*", "", body)
