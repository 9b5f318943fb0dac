r"""A notebook's rows (:class:`Row`, :class:`Ledger`) and the fragment it writes.

Part of the ledger: :mod:`edition.ledger`.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

from ..files import atomic_write, csv_text
from ..text import bound
from ..transcription import claim, printed
from .verdict import COLUMNS, VERDICTS, anchor, grade, scope_label

__all__ = ["Row", "Ledger"]


def _sentence(text):
    text = str(text).strip().rstrip(".")
    return (text[:1].upper() + text[1:] + ".") if text else ""


def _residual_latex(text):
    m = re.fullmatch(r"<\s*1e(-?\d+)", text.strip())
    if m:
        return f"< 10^{{{int(m.group(1))}}}"
    return "= " + bound(float(text), latex=True)


class Row(dict):
    """One ledger row: a dict of :data:`COLUMNS`, shown in a notebook as the verdict sentence."""

    def _label(self):
        return f"({self['id']})" if self["kind"] == "equation" else f"on {claim(self['id']).title}"

    def sentence(self):
        r"""The verdict as a Markdown paragraph, generated from the row (the chapters show this, nothing typed).

        Returns
        -------
        str
        """
        scope = scope_label(self.get("scope", ""))
        parts = [f"**Verdict {self._label()}: {self['verdict']}{f' ({scope})' if scope else ''}.**"]
        if self["verdict"] != "ok":
            parts.append(_sentence(self["why"]))
        parts.append(_sentence(self["check"]))
        if self["convention"]:
            parts.append(f"*Convention:* {self['convention'].rstrip('.')}.")
        parts.append(f"*Largest numerical residual* ${_residual_latex(self['residual'])}$.")
        text = " ".join(parts)
        if self["verdict"] != "ok":
            if self["kind"] == "equation":
                text += f"\n\n*Corrected:*\n\n$$\n{self['corrected']}\n\\tag*{{({self['id']}) corrected}}\n$$"
            else:
                text += f"\n\n*What is true:* {self['corrected']}"
        if self["note"]:
            text += f"\n\n*Note:* {_sentence(self['note'])}"
        if scope:
            text += f"\n\n*Scope ({scope}):* {_sentence(self['scope'].split(':', 1)[1].strip())}"
        return text

    def _repr_markdown_(self):
        return self.sentence()

    def __repr__(self):
        return f"ledger {self._label()}: {self['verdict']} (printed holds: {self['printed_holds']})"

    def _repr_pretty_(self, p, cycle):
        p.text(repr(self))


class Ledger:
    r"""Rows of verdicts collected by one notebook.

    Parameters
    ----------
    notebook : str
        The notebook's stem, e.g. ``"01_platform_and_wheels"``.

    Examples
    --------
    >>> led = Ledger("00_example")
    >>> row = led.add(Finding("3", True, "the columns of $\\mathbf E$ are $\\mathbf k\\times\\mathbf e_j$", 0.0))
    >>> row["verdict"], row["kind"], row["anchor"], row["residual"]
    ('ok', 'equation', 'eq-3', '< 1e-12')
    """

    def __init__(self, notebook):
        if not isinstance(notebook, str) or not notebook.strip():
            raise ValueError(f"notebook must be a non-empty name, got {notebook!r}")
        self.notebook = notebook
        self.rows = []

    def add(self, finding):
        r"""Grade a finding and record it as a row.

        The section and the printed text come from the transcription: :func:`edition.printed`
        for an equation, :func:`edition.claim` for a claim.  The text rules of a row (math in
        ``$...$``, never ASCII pseudo-math) are checked by the tests over the published ledger,
        not here.

        Parameters
        ----------
        finding : Finding

        Returns
        -------
        Row
            The row (a dict of :data:`COLUMNS`), shown in a notebook as its verdict sentence.

        Raises
        ------
        ValueError
            A duplicated id, an unknown equation or claim, a residual that is NaN, infinite or
            negative, ASCII pseudo-math in a text field, LaTeX with ``$`` in an equation's
            printed or corrected form, or a refuted printed form without a proven correction
            (:func:`grade`).
        """

        verdict = grade(finding)
        id = str(finding.id)
        if any(r["id"] == id for r in self.rows):
            raise ValueError(f"row {id!r} is already in the ledger of {self.notebook}")
        res = float(finding.residual)
        if not math.isfinite(res) or res < 0:
            raise ValueError(f"residual of row {id!r} must be finite and >= 0, got {finding.residual!r}")
        if id.isdigit():
            src = printed(id)
            kind, section, text = "equation", src.section, src.latex
        else:
            src = claim(id)
            kind, section, text = "claim", src.section, src.text
        corrected = "" if verdict == "ok" else str(finding.corrected).strip()
        row = Row(
            id=id,
            kind=kind,
            section=section,
            verdict=verdict,
            printed=text,
            corrected=corrected,
            why="" if verdict == "ok" else str(finding.why).strip(),
            convention=str(finding.convention).strip(),
            check=str(finding.check).strip(),
            printed_holds="yes" if finding.printed_holds else "no",
            residual=bound(res),
            notebook=self.notebook,
            anchor=anchor(id),
            note=str(finding.note).strip(),
            scope=str(finding.scope).strip(),
            overturn="" if verdict == "ok" else str(finding.overturn).strip(),
        )
        self.rows.append(row)
        return row

    def counts(self):
        """Rows per verdict.

        Returns
        -------
        dict
            ``{verdict: count}`` for every verdict of :data:`VERDICTS`.
        """
        return {v: sum(r["verdict"] == v for r in self.rows) for v in VERDICTS}

    def write(self, directory):
        """Write this chapter's rows to ``<directory>/ledger.csv`` atomically.

        Parameters
        ----------
        directory : path-like
            Where the chapter writes (:attr:`edition.notebook.Project.out`).

        Returns
        -------
        pathlib.Path
            The file written.
        """
        if directory is None:
            raise TypeError("directory must be a path (where the chapter writes), got None")
        path = Path(directory) / "ledger.csv"
        return atomic_write(path, csv_text(self.rows, COLUMNS))
