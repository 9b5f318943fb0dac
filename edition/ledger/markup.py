r"""The text of a row: math in ``$...$``, never ASCII pseudo-math (:func:`ascii_math`), and anchors.

Part of the ledger: :mod:`edition.ledger`.
"""
from __future__ import annotations

import re

__all__ = ["ascii_math", "anchor"]


#: Text fields written as Markdown (math in ``$...$``); ``printed``/``corrected`` of equations are LaTeX.
_MARKDOWN_FIELDS = ("why", "convention", "check", "note")
_ASCII = [
    (re.compile(r"\b[A-Za-z]+_dot\b"), "a variable named *_dot"),
    (re.compile(r"!="), "!="),
    (re.compile(r"<=>|<==>|==>|=>|->"), "an ASCII arrow"),
    (re.compile(r"<=|>="), "<= or >="),
    (re.compile(r"\^T\b"), "^T"),
    (re.compile(r"\b\d+\s*\*\s*(?:\d|1\b)"), "a * product"),
    (re.compile(r"\b(?:sqrt|atan2|arccos|acos)\("), "a function call"),
    (re.compile(r"\b(?:alpha|beta|theta|phi|psi|kappa|sigma|lambda|nu|Upsilon)(?:_\w+)?\b"), "a Greek letter spelled out"),
]


def _outside_math(text):
    """The parts of a Markdown string outside ``$...$``, ``$$...$$`` and `code` spans."""
    return re.sub(r"\$\$.*?\$\$|\$[^$]*\$|`[^`]*`", " ", text, flags=re.S)


def ascii_math(text):
    r"""ASCII pseudo-math in the prose of a Markdown string (outside ``$...$`` and `code`).

    Parameters
    ----------
    text : str

    Returns
    -------
    list of str
        One description per offending fragment (empty when the text is clean).

    Examples
    --------
    >>> ascii_math(r"holds for $\dot\psi \neq 0$")
    []
    >>> ascii_math("holds for psi_dot != 0")
    ["a variable named *_dot: 'psi_dot'", "!=: '!='", "a Greek letter spelled out: 'psi_dot'"]
    """
    prose = _outside_math(str(text))
    out = []
    for pattern, what in _ASCII:
        out += [f"{what}: {m.group(0)!r}" for m in pattern.finditer(prose)]
    return out


def anchor(id):
    """The HTML id a notebook puts before the derivation of row ``id``: ``eq-59`` or ``claim-drift``.

    Parameters
    ----------
    id : str or int

    Returns
    -------
    str

    Examples
    --------
    >>> anchor(59), anchor("drift")
    ('eq-59', 'claim-drift')
    """
    id = str(id)
    return f"eq-{id}" if id.isdigit() else f"claim-{id}"


def _row_problems(row):
    out = []
    fields = list(_MARKDOWN_FIELDS) + (["printed", "corrected"] if row["kind"] == "claim" else [])
    for f in fields:
        out += [f"{f}: {p}" for p in ascii_math(row[f])]
    if row["kind"] == "equation":
        out += [f"{f} is a LaTeX body and must not contain '$'" for f in ("printed", "corrected") if "$" in row[f]]
    return out
