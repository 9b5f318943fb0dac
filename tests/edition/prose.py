r"""The text rule of the edition's prose: math in ``$...$``, never ASCII pseudo-math.

Used by the tests over the published ledger (``figures/ledger.csv``) and the transcription
(``edition/printed.toml``): a rule of the text, checked where the text is, not at run time.
"""

from __future__ import annotations

import re

#: (pattern, what it is): ASCII pseudo-math a reader should never see outside ``$...$``
ASCII = [
    (re.compile(r"\b[A-Za-z]+_dot\b"), "a variable named *_dot"),
    (re.compile(r"!="), "!="),
    (re.compile(r"<=>|<==>|==>|=>|->"), "an ASCII arrow"),
    (re.compile(r"<=|>="), "<= or >="),
    (re.compile(r"\^T\b"), "^T"),
    (re.compile(r"\b\d+\s*\*\s*(?:\d|1\b)"), "a * product"),
    (re.compile(r"\b(?:sqrt|atan2|arccos|acos)\("), "a function call"),
    (
        re.compile(r"\b(?:alpha|beta|theta|phi|psi|kappa|sigma|lambda|nu|Upsilon)(?:_\w+)?\b"),
        "a Greek letter spelled out",
    ),
]
#: the ledger's fields written as Markdown (an equation's ``printed``/``corrected`` are LaTeX bodies)
MARKDOWN_FIELDS = ("why", "convention", "check", "note")


def outside_math(text):
    """The parts of a Markdown string outside ``$...$``, ``$$...$$`` and `code` spans."""
    return re.sub(r"\$\$.*?\$\$|\$[^$]*\$|`[^`]*`", " ", text, flags=re.S)


def ascii_math(text):
    """ASCII pseudo-math in the prose of a Markdown string: one description per offending fragment."""
    prose = outside_math(str(text))
    return [f"{what}: {m.group(0)!r}" for pattern, what in ASCII for m in pattern.finditer(prose)]


def row_problems(row):
    """What breaks the text rules in one ledger row (a dict of the ledger's columns)."""
    out = []
    fields = list(MARKDOWN_FIELDS) + (["printed", "corrected"] if row["kind"] == "claim" else [])
    for f in fields:
        out += [f"{f}: {p}" for p in ascii_math(row[f])]
    if row["kind"] == "equation":
        out += [f"{f} is a LaTeX body and must not contain '$'" for f in ("printed", "corrected") if "$" in row[f]]
    return out
