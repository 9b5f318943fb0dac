r"""The ledger of verdicts: one row per equation (2)-(65) and per checked claim of the paper.

A check (:mod:`wmr.paper.checks`) compares a printed statement with what the model proves and
returns a :class:`Finding`: whether the printed form holds, what was proven, the corrected form
when it does not, the largest numerical residual.  :meth:`Ledger.add` turns a finding into a
:class:`Row` and **computes** the verdict from it (:func:`grade`): ``ok`` when the printed form is
proven; ``typo`` or ``wrong`` (the class of error the check names) only when the printed form is
refuted *and* a corrected form is proven, otherwise it fails loudly with the reason.  A changed
transcription therefore re-grades its row, or stops the chapter.

Each notebook writes its rows to ``<figures>/ledger/<notebook>.csv`` (:meth:`Ledger.write`);
``python -m wmr.paper.ledger DIR`` merges the fragments into ``DIR/ledger.csv`` (equations in
numeric order, then claims) and reports what is missing.  Columns (:data:`COLUMNS`):

``id``, ``kind``, ``section``, ``verdict``
    Equation number or claim slug; ``equation`` or ``claim``; the paper's section; the verdict.
``printed``, ``corrected``
    For an equation the LaTeX body of the printed form (no ``$``) and of the proven form (empty
    for ``ok``); for a claim the quoted sentence and what is true, Markdown with ``$...$`` math.
``why``, ``convention``, ``check``, ``note``
    Markdown with ``$...$`` math: why the printed form fails (one line, ``typo``/``wrong`` only),
    the convention under which the verdict holds, what was proven, anything else.
``printed_holds``, ``residual``
    ``yes``/``no``; the largest numerical residual as a bound (:func:`wmr.paper.text.bound`).
``notebook``, ``anchor``
    The notebook that derives the row, and the HTML id it puts before the derivation
    (``eq-59``, ``claim-drift``).

No field may carry ASCII pseudo-math (``psi_dot``, ``!=``, ``<=>``, ``^T``, ``3*1``): math is
written in ``$...$`` (:func:`ascii_math` finds offenders; :meth:`Ledger.add` rejects them).
"""
from __future__ import annotations

import csv
import io
import math
import os
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

from .files import atomic_write
from .text import bound

__all__ = ["COLUMNS", "KINDS", "VERDICTS", "SEVERITIES", "EQUATIONS", "Finding", "Row", "Ledger", "grade",
           "ascii_math", "anchor", "read", "problems", "merge", "main"]

COLUMNS = ("id", "kind", "section", "verdict", "printed", "corrected", "why", "convention", "check",
           "printed_holds", "residual", "notebook", "anchor", "note")
KINDS = ("equation", "claim")
VERDICTS = ("ok", "typo", "wrong")
#: Classes of error a check may name for a refuted printed form: a slip of print (sign, factor,
#: size) that the surrounding argument does not rest on, or a false statement.
SEVERITIES = ("typo", "wrong")
EQUATIONS = tuple(str(n) for n in range(2, 66))

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


@dataclass(frozen=True)
class Finding:
    r"""What a check established about one printed equation or claim.

    Attributes
    ----------
    id : str
        Equation number (``"2"`` .. ``"65"``) or a claim's slug.
    printed_holds : bool
        Whether the printed form (or claim) was proven: computed by the check, never typed.
    check : str
        What was proven, in words (Markdown with ``$...$``).
    residual : float
        Largest numerical residual of the proven form (finite, ``>= 0``).
    corrected : str
        The proven form where the printed one fails: LaTeX body for an equation, Markdown for a claim.
    corrected_holds : bool
        Whether ``corrected`` was proven.
    severity : str
        ``typo`` or ``wrong``: the class of error if the printed form fails (ignored when it holds).
    why : str
        One line: why the printed form fails (Markdown).
    convention : str
        The convention under which the verdict holds (Markdown).
    note : str
        Anything else (Markdown).
    """

    id: str
    printed_holds: bool
    check: str
    residual: float
    corrected: str = ""
    corrected_holds: bool = False
    severity: str = ""
    why: str = ""
    convention: str = ""
    note: str = ""


def grade(finding):
    """The verdict of a finding: ``ok`` if the printed form holds, else its severity, if the correction is proven.

    Parameters
    ----------
    finding : Finding

    Returns
    -------
    str
        One of :data:`VERDICTS`.

    Raises
    ------
    ValueError
        When the printed form fails but no corrected form was proven, or the severity or the
        one-line *why* is missing: the message names the row and says what the check found.

    Examples
    --------
    >>> grade(Finding("42", False, "signs refuted", 0.0, corrected="d^2", corrected_holds=True,
    ...               severity="typo", why="sign slip"))
    'typo'
    >>> grade(Finding("42", True, "proven", 0.0, corrected="d^2", corrected_holds=True, severity="typo"))
    'ok'
    """
    if not isinstance(finding, Finding):
        raise TypeError(f"finding must be a Finding, got {type(finding).__name__}")
    if not isinstance(finding.printed_holds, bool):
        raise TypeError(f"printed_holds of row {finding.id!r} must be a bool (the outcome of the check), "
                        f"got {finding.printed_holds!r}")
    if finding.printed_holds:
        return "ok"
    label = _label(finding.id)
    if not str(finding.corrected).strip() or finding.corrected_holds is not True:
        raise ValueError(f"{label}: the printed form is refuted ({finding.check}) but no corrected form was proven")
    if finding.severity not in SEVERITIES:
        raise ValueError(f"{label}: the printed form is refuted; severity must be one of {SEVERITIES}, "
                         f"got {finding.severity!r}")
    if not str(finding.why).strip():
        raise ValueError(f"{label}: the printed form is refuted but 'why' is empty")
    return finding.severity


def _sentence(text):
    text = str(text).strip().rstrip(".")
    return (text[:1].upper() + text[1:] + ".") if text else ""


def _residual_latex(text):
    m = re.fullmatch(r"<\s*1e(-?\d+)", text.strip())
    if m:
        return f"< 10^{{{int(m.group(1))}}}"
    return "= " + bound(float(text), latex=True)


def _label(id):
    return f"({id})" if str(id).isdigit() else f"claim {id!r}"


class Row(dict):
    """One ledger row: a dict of :data:`COLUMNS`, shown in a notebook as the verdict sentence."""

    def _label(self):
        return f"({self['id']})" if self["kind"] == "equation" else f"`{self['id']}`"

    def sentence(self):
        r"""The verdict as a Markdown paragraph, generated from the row (the chapters show this, nothing typed).

        Returns
        -------
        str
        """
        parts = [f"**Verdict {self._label()}: {self['verdict']}.**"]
        if self["verdict"] != "ok":
            parts.append(_sentence(self["why"]))
        parts.append(_sentence(self["check"]))
        if self["convention"]:
            parts.append(f"*Convention:* {self['convention'].rstrip('.')}.")
        parts.append(f"*Largest numerical residual* ${_residual_latex(self['residual'])}$.")
        text = " ".join(parts)
        if self["verdict"] != "ok":
            if self["kind"] == "equation":
                text += (f"\n\n*Corrected:*\n\n$$\n{self['corrected']}\n\\tag*{{({self['id']}) corrected}}\n$$")
            else:
                text += f"\n\n*What is true:* {self['corrected']}"
        if self["note"]:
            text += f"\n\n*Note:* {_sentence(self['note'])}"
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

        The section and the printed text come from the transcription: :func:`wmr.paper.printed`
        for an equation, :func:`wmr.paper.claim` for a claim.

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
        from . import claim, printed
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
        row = Row(id=id, kind=kind, section=section, verdict=verdict, printed=text, corrected=corrected,
                  why="" if verdict == "ok" else str(finding.why).strip(), convention=str(finding.convention).strip(),
                  check=str(finding.check).strip(), printed_holds="yes" if finding.printed_holds else "no",
                  residual=bound(res), notebook=self.notebook, anchor=anchor(id), note=str(finding.note).strip())
        bad = _row_problems(row)
        if bad:
            raise ValueError(f"row {id!r}: " + "; ".join(bad))
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
        """Write ``<directory>/ledger/<notebook>.csv`` atomically.

        Parameters
        ----------
        directory : path-like
            The project's figures directory (see :func:`wmr.paper.notebook.project`).

        Returns
        -------
        pathlib.Path
            The fragment written.
        """
        if directory is None:
            raise TypeError("directory must be a path (the project's figures directory), got None")
        path = Path(directory) / "ledger" / f"{self.notebook}.csv"
        return atomic_write(path, _to_csv(self.rows))


def _row_problems(row):
    out = []
    fields = list(_MARKDOWN_FIELDS) + (["printed", "corrected"] if row["kind"] == "claim" else [])
    for f in fields:
        out += [f"{f}: {p}" for p in ascii_math(row[f])]
    if row["kind"] == "equation":
        out += [f"{f} is a LaTeX body and must not contain '$'" for f in ("printed", "corrected") if "$" in row[f]]
    return out


def _to_csv(rows):
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=COLUMNS, lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({k: r.get(k, "") for k in COLUMNS})
    return buf.getvalue()


def _sort_key(row):
    i = row["id"]
    return (0, int(i), "") if i.isdigit() else (1, 0, i)


def read(path):
    """Rows of a ledger CSV.

    Parameters
    ----------
    path : path-like

    Returns
    -------
    list of dict
    """
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def problems(rows):
    """What is wrong with a merged ledger: missing or duplicated rows, bad verdicts, missing corrections.

    Parameters
    ----------
    rows : list of dict
        Ledger rows (as from :func:`read`).

    Returns
    -------
    list of str
        One message per problem; empty when the ledger is complete.
    """
    out = []
    ids = [r.get("id", "") for r in rows]
    missing = [e for e in EQUATIONS if e not in ids]
    if missing:
        out.append("missing equations: " + " ".join(missing))
    dup = sorted({i for i in ids if ids.count(i) > 1}, key=lambda i: (not i.isdigit(), i.zfill(3)))
    if dup:
        out.append("duplicated rows: " + " ".join(dup))
    for r in rows:
        lacking = [c for c in COLUMNS if c not in r]
        if lacking:
            out.append(f"row {r.get('id')}: lacks the columns {lacking}")
            continue
        if r["verdict"] not in VERDICTS:
            out.append(f"row {r['id']}: bad verdict {r['verdict']!r}")
        if r["kind"] not in KINDS:
            out.append(f"row {r['id']}: bad kind {r['kind']!r}")
        if (r["verdict"] == "ok") != (r["printed_holds"] == "yes"):
            out.append(f"row {r['id']}: verdict {r['verdict']!r} but printed_holds {r['printed_holds']!r}")
        if r["verdict"] in SEVERITIES and not (r["corrected"].strip() and r["why"].strip()):
            out.append(f"row {r['id']}: judged {r['verdict']} without a corrected form and a why")
        if r["anchor"] != anchor(r["id"]):
            out.append(f"row {r['id']}: anchor {r['anchor']!r}, expected {anchor(r['id'])!r}")
    return out


def merge(directory):
    """Merge the fragments ``<directory>/ledger/*.csv`` into ``<directory>/ledger.csv``.

    Parameters
    ----------
    directory : path-like
        The project's figures directory.

    Returns
    -------
    path : pathlib.Path
    rows : list of dict
        Equations in numeric order, then claims.
    problems : list of str
        See :func:`problems`.
    """
    d = Path(directory)
    rows = []
    for frag in sorted((d / "ledger").glob("*.csv")):
        rows.extend(read(frag))
    rows.sort(key=_sort_key)
    path = atomic_write(d / "ledger.csv", _to_csv(rows))
    return path, rows, problems(rows)


def main(argv=None):
    """Command line: ``python -m wmr.paper.ledger [DIR]``; merges ``DIR/ledger/*.csv`` and reports.

    ``DIR`` defaults to the figures directory of the project (``$WMR_PROJECT/figures``, else
    ``./figures``; see :func:`wmr.paper.notebook.project`).

    Parameters
    ----------
    argv : list of str, optional
        ``[DIR]``.

    Returns
    -------
    int
        Exit status: 1 when the merged ledger has problems.
    """
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv:
        directory = Path(argv[0])
    else:
        from .notebook import project
        directory = project(os.getcwd()).figures
    path, rows, probs = merge(directory)
    counts = {v: sum(r.get("verdict") == v for r in rows) for v in VERDICTS}
    print(f"ledger: {len(rows)} rows -> {path} ({', '.join(f'{k} {n}' for k, n in counts.items())})")
    for p in probs:
        print(f"ledger problem: {p}", file=sys.stderr)
    return 1 if probs else 0


if __name__ == "__main__":
    raise SystemExit(main())
