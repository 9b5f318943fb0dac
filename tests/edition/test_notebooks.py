"""Every notebook executes cleanly through the build (cached: `make test` has just run them); the
cache re-executes exactly what changed (a failing notebook: ``test_build.py``)."""
from __future__ import annotations

import os
import sys
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
from tools import build  # noqa: E402
from tools.build import inputs  # noqa: E402
from tools.build.execute import stale_notebooks  # noqa: E402

TREE = build.Tree(os.environ.get("WMR_ROOT") or ROOT)  # WMR_ROOT: test another tree
NOTEBOOKS = TREE.notebook_files()


@pytest.mark.parametrize(
    "nb", NOTEBOOKS or [pytest.param(None, marks=pytest.mark.skip(reason="no notebooks/*.ipynb yet"))],
    ids=[p.name for p in NOTEBOOKS] or ["none"])
def test_notebook_executes(nb):
    try:
        build.execute(TREE, only=[nb.name], merge=False)
    except build.BuildError as e:
        pytest.fail(str(e), pytrace=False)
    out = TREE.executed_notebook(nb)
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
        build.execute(TREE)  # all cached by now; merges the ledger if its inputs changed
    except build.BuildError as e:
        pytest.fail(str(e), pytrace=False)
    rows = inputs.read_ledger(TREE.ledger)
    assert rows, "python -m edition.ledger did not write figures/ledger.csv, or it has no rows"
    assert {r.verdict for r in rows} <= set(inputs.VERDICTS)


def write_nb(path: Path, sources: list[str], markdown: str | None = None) -> Path:
    nb = nbformat.v4.new_notebook()
    if markdown:
        nb.cells.append(nbformat.v4.new_markdown_cell(markdown))
    nb.cells += [nbformat.v4.new_code_cell(s) for s in sources]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    path.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, path)
    return path


def test_cache_reexecutes_only_changed_notebook(tmp_path):
    tree = build.Tree(tmp_path)
    a, b = tmp_path / "notebooks" / "01_a.ipynb", tmp_path / "notebooks" / "02_b.ipynb"
    write_nb(a, ["import os\nos.getcwd()", "import sys\nsys.executable", "os.environ['WMR_OUT']"])
    write_nb(b, [], markdown="Markdown only: executed without a kernel.")
    assert build.execute(tree, merge=False) == ["01_a.ipynb", "02_b.ipynb"]
    out = nbformat.read(tree.executed_notebook(a), as_version=4)
    # the contract: the notebook's own directory is the working directory, WMR_OUT its folder under build/
    assert out.cells[0].outputs[0]["data"]["text/plain"].strip("'\"") == str(tmp_path / "notebooks")
    assert out.cells[2].outputs[0]["data"]["text/plain"].strip("'\"") == str(tree.chapter_out(a))
    kernel_py = Path(out.cells[1].outputs[0]["data"]["text/plain"].strip("'\""))
    assert kernel_py.parent == Path(sys.executable).parent         # the venv's Python
    assert build.execute(tree, merge=False) == []                  # nothing changed: nothing runs
    os.utime(b)                                                    # a new mtime, same bytes
    assert build.execute(tree, merge=False) == []
    write_nb(b, [], markdown="Edited.")
    assert [p.name for p in stale_notebooks(tree)] == ["02_b.ipynb"]
    assert build.execute(tree, merge=False) == ["02_b.ipynb"]
    (tmp_path / "wmr").mkdir()
    (tmp_path / "wmr" / "__init__.py").write_text("# package changed\n")
    assert [p.name for p in stale_notebooks(tree)] == ["01_a.ipynb", "02_b.ipynb"]  # wmr change: all stale
