r"""The ledger on disk: read a fragment, check rows, merge the fragments (``python -m wmr.paper.ledger``).

Part of the ledger: :mod:`wmr.paper.ledger`.
"""
from __future__ import annotations

import csv
import os
import sys
from pathlib import Path

from ..files import atomic_write, csv_text
from .markup import anchor
from .verdict import COLUMNS, EQUATIONS, KINDS, SEVERITIES, VERDICTS

__all__ = ["read", "problems", "merge", "main"]


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
    path = atomic_write(d / "ledger.csv", csv_text(rows, COLUMNS))
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
        from ..notebook import project
        directory = project(os.getcwd()).figures
    path, rows, probs = merge(directory)
    counts = {v: sum(r.get("verdict") == v for r in rows) for v in VERDICTS}
    print(f"ledger: {len(rows)} rows -> {path} ({', '.join(f'{k} {n}' for k, n in counts.items())})")
    for p in probs:
        print(f"ledger problem: {p}", file=sys.stderr)
    return 1 if probs else 0
