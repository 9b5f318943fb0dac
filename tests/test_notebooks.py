"""Every notebook executes cleanly (through tools/build.py, so cached when `make test`
already ran it), and a failing notebook fails the build loudly and leaves nothing behind."""
from __future__ import annotations

import csv
import os
import sys
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
import build  # noqa: E402

TREE = build.Tree(os.environ.get("WMR_ROOT") or ROOT)  # WMR_ROOT: test another tree
NOTEBOOKS = TREE.notebook_files()
LEDGER_COLUMNS = ["id", "kind", "section", "verdict", "printed", "corrected", "why", "convention", "check",
                  "printed_holds", "residual", "notebook", "anchor", "note"]   # CONTRACTS.md


@pytest.mark.parametrize(
    "nb", NOTEBOOKS or [pytest.param(None, marks=pytest.mark.skip(reason="no notebooks/*.ipynb yet"))],
    ids=[p.name for p in NOTEBOOKS] or ["none"])
def test_notebook_executes(nb):
    try:
        build.execute(TREE, only=[nb.name], merge=False)
    except build.BuildError as e:
        pytest.fail(str(e), pytrace=False)
    out = TREE.nb_out / nb.name
    assert out.exists(), f"{out} missing after execution"
    executed = nbformat.read(out, as_version=4)
    errors = [(i, o) for i, c in enumerate(executed.cells) if c.cell_type == "code"
              for o in c.get("outputs", []) if o.get("output_type") == "error"]
    assert not errors, f"{nb.name}: error output in cell {errors[0][0]}: {errors[0][1].get('ename')}"
    src = nbformat.read(nb, as_version=4)
    n_code = sum(c.cell_type == "code" and c.source.strip() != "" for c in src.cells)
    n_run = sum(c.cell_type == "code" and c.get("execution_count") is not None for c in executed.cells)
    assert n_run >= n_code, f"{nb.name}: only {n_run} of {n_code} code cells ran"


def test_ledger_merged():
    if not NOTEBOOKS:
        pytest.skip("no notebooks yet")
    try:
        build.execute(TREE)  # all cached by now; runs the merge if its inputs changed
    except build.BuildError as e:
        pytest.fail(str(e), pytrace=False)
    ledger = TREE.figures / "ledger.csv"
    assert ledger.exists(), "python -m wmr.paper.ledger did not write figures/ledger.csv"
    with open(ledger, newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert rows, "figures/ledger.csv has no rows"
    assert list(rows[0].keys()) == LEDGER_COLUMNS


def _write_nb(path: Path, sources: list[str]) -> None:
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(s) for s in sources]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    path.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, path)


def test_failing_notebook_fails_build_and_leaves_nothing(tmp_path, capsys):
    tree = build.Tree(tmp_path)
    nb = tmp_path / "notebooks" / "99_broken.ipynb"
    # first a good version, so that a valid output + stamp exist ...
    _write_nb(nb, ["x = 41", "x + 1"])
    assert build.execute(tree, merge=False) == ["99_broken.ipynb"]
    out, stamp = tree.nb_out / "99_broken.ipynb", tree.nb_out / "99_broken.stamp"
    assert out.exists() and stamp.exists()
    # ... then break it: the build must fail and the stale output/stamp must go
    _write_nb(nb, ["x = 41", "def f(y):\n    raise ValueError(f'deliberate failure {y}')\nf(x + 1)"])
    with pytest.raises(build.BuildError) as ei:
        build.execute(tree, merge=False)
    msg = str(ei.value)
    assert "99_broken.ipynb" in msg                       # which notebook
    assert "raise ValueError(f'deliberate failure {y}')" in msg  # the failing cell's source
    assert "ValueError: deliberate failure 42" in msg      # the traceback
    assert "\x1b[" not in msg                              # readable, no ANSI colours
    assert not out.exists(), "stale executed notebook left behind"
    assert not stamp.exists(), "stale stamp left behind"
    assert not list(tree.nb_out.glob("*.tmp")) and not list(tree.nb_out.glob(".*.tmp"))
    # the CLI prints the same and exits non-zero
    assert build.main(["--root", str(tmp_path), "execute"]) == 1
    err = capsys.readouterr().err
    assert "BUILD FAILED" in err and "deliberate failure 42" in err


def test_cache_reexecutes_only_changed_notebook(tmp_path):
    tree = build.Tree(tmp_path)
    a, b = tmp_path / "notebooks" / "01_a.ipynb", tmp_path / "notebooks" / "02_b.ipynb"
    _write_nb(a, ["import os\nos.getcwd()", "import sys\nsys.executable"])
    _write_nb(b, ["1 + 1"])
    assert build.execute(tree, merge=False) == ["01_a.ipynb", "02_b.ipynb"]
    # cwd of the kernel is the root of the tree
    out = nbformat.read(tree.nb_out / "01_a.ipynb", as_version=4)
    assert str(tmp_path) in out.cells[0].outputs[0]["data"]["text/plain"]
    # ... and the kernel is the venv's Python (the one running the build)
    kernel_py = Path(out.cells[1].outputs[0]["data"]["text/plain"].strip("'\""))
    assert kernel_py.parent == Path(sys.executable).parent
    assert build.execute(tree, merge=False) == []          # nothing changed: nothing runs
    _write_nb(b, ["2 + 2"])
    assert build.execute(tree, merge=False) == ["02_b.ipynb"]
    (tmp_path / "wmr").mkdir()
    (tmp_path / "wmr" / "__init__.py").write_text("# package changed\n")
    assert build.execute(tree, merge=False) == ["01_a.ipynb", "02_b.ipynb"]  # wmr change: all stale
