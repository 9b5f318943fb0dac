"""The committed notebooks are what JupyterLab would save, and running one writes nothing tracked.

JupyterLab marks a notebook modified when opening it changes the model: a kernel whose
``language_info`` differs from the saved one, a missing cell id.  Autosave then writes that change
into the repository.  These tests keep the committed files equal to what JupyterLab's save writes.
"""

from __future__ import annotations

import subprocess

import nbformat
import pytest

from conftest import ROOT

NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
KERNELSPEC = {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"}


def language_info():
    """What the project's kernel (ipykernel) reports, and JupyterLab writes into the notebook."""
    from ipykernel.ipkernel import IPythonKernel

    return dict(IPythonKernel.language_info)


def jupyterlab_save(nb) -> str:
    """The text JupyterLab's contents manager writes for ``nb`` (nbformat, no conversion, final newline)."""
    text = nbformat.writes(nb, version=nbformat.NO_CONVERT)
    return text if text.endswith("\n") else text + "\n"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_opening_and_saving_changes_nothing(path):
    raw = path.read_text(encoding="utf-8")
    nb = nbformat.reads(raw, as_version=nbformat.NO_CONVERT)
    assert jupyterlab_save(nb) == raw, f"{path.name}: JupyterLab would rewrite it on its first save"
    assert (nb.nbformat, nb.nbformat_minor) >= (4, 5), "cell ids need nbformat 4.5"
    ids = [c.get("id") for c in nb.cells]
    assert all(ids) and len(set(ids)) == len(ids), f"{path.name}: every cell needs a unique, saved id"
    assert nb.metadata.get("kernelspec") == KERNELSPEC
    saved, kernel = dict(nb.metadata.get("language_info", {})), language_info()
    # the micro version is the reference interpreter's (where this would differ, so does the kernel)
    same_minor = saved.pop("version", "").split(".")[:2] == kernel.pop("version").split(".")[:2]
    assert saved == kernel and same_minor, f"{path.name}: the kernel would rewrite language_info on opening"
    for c in nb.cells:
        if c.cell_type == "code":
            assert c.outputs == [] and c.execution_count is None, f"{path.name}: committed with outputs"


def test_a_chapter_run_outside_the_build_writes_nothing_tracked(monkeypatch):
    """Run as JupyterLab would (nbclient, in notebooks/, no build environment): git status is unchanged."""
    from nbclient import NotebookClient

    def status():
        return subprocess.run(
            ["git", "status", "--porcelain", "--untracked-files=all"],
            cwd=ROOT,
            capture_output=True,
            text=True,
            check=True,
        ).stdout

    before = status()
    path = ROOT / "notebooks" / "05_steering_and_instant_centre.ipynb"  # writes Fig. 13 and ledger rows
    nb = nbformat.read(path, as_version=4)
    monkeypatch.delenv("WMR_OUT", raising=False)  # the kernel inherits this environment
    monkeypatch.setenv("MPLBACKEND", "Agg")
    NotebookClient(nb, timeout=300, kernel_name="python3").execute(cwd=str(path.parent))
    assert status() == before, "a chapter run outside the build changed the tracked tree"
    scratch = ROOT / "build" / "scratch" / path.stem
    assert (scratch / "fig13.svg").is_file() and (scratch / "ledger.csv").is_file()
    said = "".join(o.get("data", {}).get("text/markdown", "") for c in nb.cells for o in c.get("outputs", []))
    assert str(scratch) in said, "the chapter must say where it writes"
