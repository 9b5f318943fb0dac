"""Every notebook executes cleanly through the build (cached: `make test` has just run them), and
the ledger is merged. The cache itself (what re-executes when) is tested in ``test_build.py``."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[2]
TREE = Path(os.environ.get("WMR_ROOT") or ROOT)  # WMR_ROOT: test another tree
NOTEBOOKS = sorted((TREE / "notebooks").glob("*.ipynb"))
BUILD = Path(os.environ.get("WMR_BUILD") or TREE / "build")


@pytest.fixture(scope="module")
def executed():
    """``make notebooks``: every chapter, then the findings chapter (each only when its key changed)."""
    p = subprocess.run(
        ["make", "-s", "--no-print-directory", "-C", str(ROOT), f"WMR_ROOT={TREE}", f"WMR_BUILD={BUILD}", "notebooks"],
        capture_output=True,
        text=True,
        check=False,
    )
    if p.returncode != 0:
        pytest.fail(p.stdout + p.stderr, pytrace=False)
    return BUILD / "notebooks"


@pytest.mark.parametrize("nb", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_notebook_executes(nb, executed):
    out = nbformat.read(executed / nb.name, as_version=4)
    errors = [
        (i, o)
        for i, c in enumerate(out.cells)
        if c.cell_type == "code"
        for o in c.get("outputs", [])
        if o.get("output_type") == "error"
    ]
    assert not errors, f"{nb.name}: error output in cell {errors[0][0]}: {errors[0][1].get('ename')}"
    src = nbformat.read(nb, as_version=4)
    assert [c.source for c in out.cells] == [c.source for c in src.cells], f"{nb.name}: executed copy is stale"
    n_code = sum(c.cell_type == "code" and c.source.strip() != "" for c in src.cells)
    n_run = sum(c.cell_type == "code" and c.get("execution_count") is not None for c in out.cells)
    assert n_run >= n_code, f"{nb.name}: only {n_run} of {n_code} code cells ran"


def test_ledger_merged(executed):
    from edition.ledger import VERDICTS, problems, read

    rows = read(TREE / "figures" / "ledger.csv")
    assert rows, "python -m edition.ledger did not write figures/ledger.csv, or it has no rows"
    assert {r["verdict"] for r in rows} <= set(VERDICTS)
    assert problems(rows) == []
