r"""The ledger on disk: the chapters' rows validated and concatenated into one file (:func:`assemble`).

Each executed chapter leaves its rows in one file, ``$WMR_OUT/ledger.csv`` (:meth:`Ledger.write`);
:func:`assemble` reads those files, checks the rows (:func:`problems`) and writes them, equations in
numeric order then claims, to the published ledger (the build's ``figures/ledger.csv``).  The same
from a shell: ``python -m edition.ledger CHAPTERS... DEST``.

Part of the ledger: :mod:`edition.ledger`.
"""

from __future__ import annotations

import csv
import sys
from pathlib import Path

from ..files import atomic_write, csv_text
from .verdict import COLUMNS, EQUATIONS, KINDS, SCOPES, SEVERITIES, VERDICTS, anchor, scope_label

__all__ = ["LedgerError", "read", "fragments", "problems", "assemble", "main"]


class LedgerError(ValueError):
    """The chapters' rows do not make a ledger: the message lists every problem (file, row, column)."""


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


def fragments(sources):
    """The chapters' ledger files named by ``sources``, in order, each once.

    Parameters
    ----------
    sources : path-like or sequence of path-like
        Each a chapter's ``ledger.csv``, a chapter's folder holding one, or a folder of chapter
        folders (the build's ``build/out``: its ``*/ledger.csv``, sorted).

    Returns
    -------
    list of pathlib.Path

    Raises
    ------
    FileNotFoundError
        A source that does not exist.
    """
    if isinstance(sources, (str, Path)):
        sources = [sources]
    out = []
    for src in map(Path, sources):
        if src.is_file():
            found = [src]
        elif (src / "ledger.csv").is_file():
            found = [src / "ledger.csv"]
        elif src.is_dir():
            found = sorted(src.glob("*/ledger.csv"))
        else:
            raise FileNotFoundError(f"ledger source {str(src)!r} does not exist")
        out += [f for f in found if f not in out]
    return out


def problems(rows):
    """What is wrong with a ledger: missing or duplicated rows, bad verdicts, missing corrections.

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
        if r["verdict"] in SEVERITIES and not (r["corrected"].strip() and r["why"].strip() and r["overturn"].strip()):
            out.append(
                f"row {r['id']}: judged {r['verdict']} without a corrected form, a why and what would overturn it"
            )
        if r["scope"] and r["verdict"] not in SCOPES.get(scope_label(r["scope"]), ()):
            out.append(f"row {r['id']}: scope {r['scope'][:40]!r} cannot qualify the verdict {r['verdict']!r}")
        if r["anchor"] != anchor(r["id"]):
            out.append(f"row {r['id']}: anchor {r['anchor']!r}, expected {anchor(r['id'])!r}")
    return out


def assemble(sources, dest):
    """Validate the chapters' rows and write them, in the ledger's order, to ``dest``.

    Parameters
    ----------
    sources : path-like or sequence of path-like
        The chapters' ledger files, or folders holding them (see :func:`fragments`).
    dest : path-like
        The ledger to write (the build's ``figures/ledger.csv``); left untouched when its bytes
        would not change, and when the rows do not make a ledger.

    Returns
    -------
    list of dict
        The rows written: equations in numeric order, then claims.

    Raises
    ------
    LedgerError
        A file whose columns are not :data:`COLUMNS`, or rows with :func:`problems`: every
        problem is listed.
    FileNotFoundError
        A source that does not exist.

    Examples
    --------
    >>> import tempfile
    >>> from edition.ledger import Ledger, Finding, EQUATIONS
    >>> tmp = Path(tempfile.mkdtemp())
    >>> led = Ledger("01_x")
    >>> for e in EQUATIONS:
    ...     _ = led.add(Finding(e, True, "proven", 0.0))
    >>> path = led.write(tmp / "01_x")
    >>> len(assemble([tmp], tmp / "ledger.csv"))
    64
    """
    rows, bad = [], []
    for path in fragments(sources):
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            if tuple(reader.fieldnames or ()) != COLUMNS:
                bad.append(f"{path}: columns {reader.fieldnames} are not the ledger's {list(COLUMNS)}")
                continue
            rows += list(reader)
    rows.sort(key=_sort_key)
    bad += problems(rows)
    if bad:
        raise LedgerError(f"the chapters' rows do not make a ledger ({dest}):\n  " + "\n  ".join(bad))
    dest = Path(dest)
    text = csv_text(rows, COLUMNS)
    if not dest.exists() or dest.read_text(encoding="utf-8") != text:
        atomic_write(dest, text)
    return rows


def main(argv=None):
    """Command line: ``python -m edition.ledger CHAPTERS... DEST``: :func:`assemble`, with a one-line report.

    Parameters
    ----------
    argv : list of str, optional
        One or more sources (see :func:`fragments`), then the destination.

    Returns
    -------
    int
        Exit status: 1 when the rows do not make a ledger, 2 for a usage error.
    """
    argv = sys.argv[1:] if argv is None else list(argv)
    if len(argv) < 2:
        print("usage: python -m edition.ledger CHAPTERS... DEST", file=sys.stderr)
        return 2
    *sources, dest = argv
    try:
        rows = assemble(sources, dest)
    except (LedgerError, FileNotFoundError) as e:
        print(f"ledger problem: {e}", file=sys.stderr)
        return 1
    counts = {v: sum(r["verdict"] == v for r in rows) for v in VERDICTS}
    print(f"ledger: {len(rows)} rows -> {dest} ({', '.join(f'{k} {n}' for k, n in counts.items())})")
    return 0
