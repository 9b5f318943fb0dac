"""The ledger of verdicts: one row per equation (2)-(65) and per claim of the paper.

Each notebook collects its rows in a :class:`Ledger` and writes a fragment
``figures/ledger/<notebook>.csv``; ``python -m wmr.paper.ledger`` merges the fragments into
``figures/ledger.csv`` (equations in numeric order, then claims) and reports what is missing.
"""
from __future__ import annotations

import csv
import io
import math
import os
import sys
from pathlib import Path

COLUMNS = ("id", "section", "verdict", "printed", "corrected", "convention",
           "symbolic_check", "max_residual", "notebook", "note")
VERDICTS = ("ok", "typo", "wrong")
EQUATIONS = tuple(str(n) for n in range(2, 66))


def output_dir():
    """Where figures and the ledger go: ``$WMR_FIGURES`` or ``<repository>/figures``.

    Returns
    -------
    pathlib.Path
    """
    env = os.environ.get("WMR_FIGURES")
    if env:
        return Path(env)
    return Path(__file__).resolve().parents[2] / "figures"   # TODO(issue 10): no repository paths in the library


class Row(dict):
    """One ledger row: a dict of :data:`COLUMNS` that a notebook displays as a one-line verdict."""

    def _label(self):
        i = self["id"]
        return f"({i})" if i.isdigit() else i

    def __repr__(self):
        return (f"ledger {self._label()}: {self['verdict']}, check {self['symbolic_check']}, "
                f"max residual {self['max_residual']}")

    def _repr_pretty_(self, p, cycle):
        p.text(repr(self))

    def _repr_markdown_(self):
        return (f"**Ledger {self._label()}: `{self['verdict']}`** (check {self['symbolic_check']}, "
                f"max residual {self['max_residual']})")


class Ledger:
    """Rows of verdicts collected by one notebook.

    Parameters
    ----------
    notebook : str
        The notebook's stem, e.g. ``"01_platform_and_wheels"``.

    Examples
    --------
    >>> led = Ledger("00_example")
    >>> row = led.add("3", "2", "ok", r"\\mathbf E", symbolic_check=True, max_residual=0.0)
    >>> row["symbolic_check"], row["max_residual"]
    ('pass', '0.000e+00')
    """

    def __init__(self, notebook):
        self.notebook = notebook
        self.rows = []

    def add(self, id, section, verdict, printed, corrected="", convention="", symbolic_check=True,
            max_residual=0.0, note=""):
        """Record one verdict.

        Parameters
        ----------
        id : str or int
            Equation number (``"2"`` .. ``"65"``) or a claim's name.
        section : str
            Section of the paper.
        verdict : {"ok", "typo", "wrong"}
        printed : str
            The equation as printed (LaTeX).
        corrected : str, optional
            The true statement (LaTeX); required for ``typo`` and ``wrong``.
        convention : str, optional
            The convention under which the verdict holds.
        symbolic_check : bool, optional
            Outcome of the checks backing the verdict (recorded as ``pass``/``fail``).
        max_residual : float, optional
            Largest numerical residual of the correct form (not NaN).
        note : str, optional

        Returns
        -------
        Row
            The row (a dict with the columns :data:`COLUMNS`), shown in a notebook as one line.

        Raises
        ------
        ValueError
            On a bad verdict, a missing correction, a duplicated id, a NaN residual or a
            ``symbolic_check`` that is a string.
        """
        id = str(id)
        if isinstance(symbolic_check, str):
            raise ValueError(f"symbolic_check must be a bool (the outcome of the check), got {symbolic_check!r}")
        if verdict not in VERDICTS:
            raise ValueError(f"verdict must be one of {VERDICTS}, got {verdict!r}")
        if verdict != "ok" and not str(corrected).strip():
            raise ValueError(f"row {id!r} is judged {verdict!r} but has no corrected form")
        if any(r["id"] == id for r in self.rows):
            raise ValueError(f"row {id!r} is already in the ledger of {self.notebook}")
        res = float(max_residual)
        if math.isnan(res):
            raise ValueError(f"max_residual of row {id!r} is NaN")
        row = Row(id=id, section=section, verdict=verdict, printed=printed, corrected=corrected,
                   convention=convention, symbolic_check="pass" if symbolic_check else "fail",
                   max_residual=f"{res:.3e}", notebook=self.notebook, note=note)
        self.rows.append(row)
        return row

    def table(self):
        """The rows as a pandas DataFrame (for display in the notebook).

        Returns
        -------
        pandas.DataFrame
            One row per verdict, columns :data:`COLUMNS`.
        """
        import pandas as pd
        return pd.DataFrame(self.rows, columns=COLUMNS)

    def write(self, directory=None):
        """Write ``<directory>/ledger/<notebook>.csv`` atomically.

        Parameters
        ----------
        directory : path-like, optional
            Default :func:`output_dir`.

        Returns
        -------
        pathlib.Path
            The fragment written.
        """
        d = Path(directory or output_dir()) / "ledger"
        d.mkdir(parents=True, exist_ok=True)
        path = d / f"{self.notebook}.csv"
        _atomic_write(path, _to_csv(self.rows))
        return path


def _to_csv(rows):
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=COLUMNS, lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({k: r.get(k, "") for k in COLUMNS})
    return buf.getvalue()


def _atomic_write(path, text):
    tmp = path.with_suffix(path.suffix + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


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
    """What is wrong with a merged ledger: missing/duplicated equations, failing checks, missing corrections.

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
    ids = [r["id"] for r in rows]
    missing = [e for e in EQUATIONS if e not in ids]
    if missing:
        out.append("missing equations: " + " ".join(missing))
    dup = sorted({i for i in ids if ids.count(i) > 1}, key=lambda i: (not i.isdigit(), i.zfill(3)))
    if dup:
        out.append("duplicated rows: " + " ".join(dup))
    for r in rows:
        if r["verdict"] not in VERDICTS:
            out.append(f"row {r['id']}: bad verdict {r['verdict']!r}")
        if r["symbolic_check"] != "pass":
            out.append(f"row {r['id']}: failing check")
        if r["verdict"] in ("typo", "wrong") and not r["corrected"].strip():
            out.append(f"row {r['id']}: judged {r['verdict']} without a corrected form")
    return out


def merge(directory=None):
    """Merge the fragments ``<directory>/ledger/*.csv`` into ``<directory>/ledger.csv``.

    Parameters
    ----------
    directory : path-like, optional
        Default :func:`output_dir`.

    Returns
    -------
    path : pathlib.Path
    rows : list of dict
        Equations in numeric order, then claims.
    problems : list of str
        See :func:`problems`.
    """
    d = Path(directory or output_dir())
    d.mkdir(parents=True, exist_ok=True)
    rows = []
    for frag in sorted((d / "ledger").glob("*.csv")):
        rows.extend(read(frag))
    rows.sort(key=_sort_key)
    path = d / "ledger.csv"
    _atomic_write(path, _to_csv(rows))
    return path, rows, problems(rows)


def main(argv=None):
    """Command line: ``python -m wmr.paper.ledger [directory]``; merges and reports.

    Parameters
    ----------
    argv : list of str, optional
        ``[directory]``.

    Returns
    -------
    int
        Exit status: 1 when the merged ledger has problems.
    """
    path, rows, probs = merge(argv[0] if argv else None)
    counts = {v: sum(r["verdict"] == v for r in rows) for v in VERDICTS}
    print(f"ledger: {len(rows)} rows -> {path} ({', '.join(f'{k} {n}' for k, n in counts.items())})")
    for p in probs:
        print(f"ledger problem: {p}", file=sys.stderr)
    return 1 if probs else 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
