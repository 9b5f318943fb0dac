r"""The ledger on disk: read a fragment, check rows, merge the fragments (``python -m edition.ledger``).

Part of the ledger: :mod:`edition.ledger`.
"""
from __future__ import annotations

import csv
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


def merge(chapters, dest):
    """Concatenate the chapters' rows ``<chapters>/*/ledger.csv`` into ``dest``, in the ledger's order.

    Parameters
    ----------
    chapters : path-like
        The folder holding one folder per executed chapter (the build's ``build/out``).
    dest : path-like
        The ledger to write (the build's ``figures/ledger.csv``); left untouched when its bytes
        would not change.

    Returns
    -------
    path : pathlib.Path
    rows : list of dict
        Equations in numeric order, then claims.
    problems : list of str
        See :func:`problems`.
    """
    rows = []
    for frag in sorted(Path(chapters).glob("*/ledger.csv")):
        rows.extend(read(frag))
    rows.sort(key=_sort_key)
    dest = Path(dest)
    text = csv_text(rows, COLUMNS)
    if not dest.exists() or dest.read_text(encoding="utf-8") != text:
        atomic_write(dest, text)
    return dest, rows, problems(rows)


def main(argv=None):
    """Command line: ``python -m edition.ledger CHAPTERS DEST``; merges ``CHAPTERS/*/ledger.csv`` and reports.

    Parameters
    ----------
    argv : list of str, optional
        ``[CHAPTERS, DEST]``.

    Returns
    -------
    int
        Exit status: 1 when the merged ledger has problems, 2 for a usage error.
    """
    argv = sys.argv[1:] if argv is None else list(argv)
    if len(argv) != 2:
        print("usage: python -m edition.ledger CHAPTERS DEST", file=sys.stderr)
        return 2
    path, rows, probs = merge(*argv)
    counts = {v: sum(r.get("verdict") == v for r in rows) for v in VERDICTS}
    print(f"ledger: {len(rows)} rows -> {path} ({', '.join(f'{k} {n}' for k, n in counts.items())})")
    for p in probs:
        print(f"ledger problem: {p}", file=sys.stderr)
    return 1 if probs else 0
