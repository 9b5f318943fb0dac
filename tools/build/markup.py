"""Markdown to HTML and to LaTeX through one reader, pandoc's ``gfm+tex_math_dollars+smart``
(GitHub-flavoured Markdown, ``$...$`` math, typographic quotes and dashes: the closest to Jupyter).

Every Markdown fragment of the report is converted in **one** pandoc call per format (:class:`Batch`):
the HTML and the PDF read the text the same way, heading ids are unique across the report, and a
build starts two pandoc processes, not hundreds. Math is written ``$...$`` at the source; nothing here
guesses which words are TeX."""
from __future__ import annotations

import re
import shutil
import subprocess
from collections.abc import Callable
from pathlib import Path

from . import BuildError

__all__ = ["READER", "TEMPLATES", "Batch", "table_math_pipes", "tex_anchor_targets", "tex_anchor_tokens"]

#: nbconvert templates of the report (HTML page, LaTeX document)
TEMPLATES = Path(__file__).resolve().parent / "templates"
READER = "gfm+tex_math_dollars+smart"
_SEP = "WMRFRAGMENT{:05d}"
_SEP_RE = {"html": re.compile(r"\n*<p>WMRFRAGMENT(\d{5})</p>\n*"),
           "latex": re.compile(r"\n*^WMRFRAGMENT(\d{5})$\n*", re.MULTILINE)}
_ANCHOR = re.compile(r'<a\s+(?:id|name)="([^"]+)"\s*>\s*</a>')
_TOKEN = re.compile(r"WMRANCHOR([0-9a-f]+)Z")
_TABLE_ROW = re.compile(r"^\s*\|.*\|\s*$", re.MULTILINE)
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
    post : callable, optional
        Applied to each converted fragment (the PDF's rewriting of displays, tables and code).
    """

    def __init__(self, to: str, post: Callable[[str], str] | None = None):
        if to not in _SEP_RE:
            raise ValueError(f"to must be 'html' or 'latex', got {to!r}")
        self.to, self.post = to, post
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
        if not shutil.which("pandoc"):
            raise BuildError("pandoc not found: run `make report` (it installs it) or apt-get install pandoc")
        src = "".join(f"{_SEP.format(i)}\n\n{s.strip()}\n\n" for i, s in enumerate(self._src))
        args = ["pandoc", "-f", READER, "-t", "html5" if self.to == "html" else "latex", "--wrap=none"]
        if self.to == "html":
            args.append("--mathjax")
        p = subprocess.run(args, input=src, capture_output=True, text=True, timeout=600, check=False)
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
        self._out = [self.post(o) for o in out] if self.post else out

    def fill(self, text: str) -> str:
        if (out := self._out) is None:
            raise RuntimeError("convert() first")

        def one(m):                      # inline: without the paragraph around a one-paragraph result
            s = out[int(m.group(1))]
            if m.group(2) == "b":
                return s
            p = re.fullmatch(r"<p>(.*)</p>", s.strip(), re.DOTALL) if self.to == "html" else None
            return s.strip() if self.to == "latex" else p.group(1) if p and "<p>" not in p.group(1) else s
        return re.sub(r"\x00WMR(\d+)([ib])\x00", one, text)
