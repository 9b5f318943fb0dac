"""Every path of the build, in one place.

A :class:`Tree` is a project root (``notebooks/``, ``wmr/``, ``figures/``) and a build directory
(default ``<root>/build``). Nothing else in :mod:`tools.build` spells a path.
"""
from __future__ import annotations

import os
import sys
from dataclasses import dataclass
from pathlib import Path

__all__ = ["Tree", "TOOL_ROOT", "TEMPLATES"]

#: the repository that holds this build tool (``tools/build/`` is two levels below it)
TOOL_ROOT = Path(__file__).resolve().parents[2]
#: nbconvert templates of the report (HTML page, LaTeX document)
TEMPLATES = Path(__file__).resolve().parent / "templates"
#: sources of the build tool itself: a change to any of them invalidates the report
TOOL_SOURCES = Path(__file__).resolve().parent


def _listing(directory: Path, pattern: str, keep) -> list[Path]:
    """The files of ``directory`` that match ``pattern`` (``**/`` for every level) and ``keep``,
    in name order; none when the directory does not exist."""
    if not directory.is_dir():
        return []
    return sorted(p for p in directory.glob(pattern) if p.is_file() and keep(p))


@dataclass(frozen=True)
class Tree:
    """The paths of one project tree.

    Parameters
    ----------
    root : path-like, optional
        Project root; default ``$WMR_ROOT`` or the repository of this tool.
    build : path-like, optional
        Build directory; default ``$WMR_BUILD`` or ``<root>/build``.
    notebooks : path-like, optional
        The notebooks to execute; default ``<root>/notebooks``. Another set (the student
        edition) with its own build directory gets the same cached execution.
    """

    root: Path
    build: Path
    notebooks: Path

    def __init__(self, root=None, build=None, notebooks=None):
        r = Path(root or os.environ.get("WMR_ROOT") or TOOL_ROOT).resolve()
        b = Path(build or os.environ.get("WMR_BUILD") or r / "build").resolve()
        object.__setattr__(self, "root", r)
        object.__setattr__(self, "build", b)
        object.__setattr__(self, "notebooks", Path(notebooks or r / "notebooks").resolve())

    # --- sources

    @property
    def wmr(self) -> Path:
        return self.root / "wmr"

    @property
    def edition(self) -> Path:
        return self.root / "edition"

    def notebook_files(self) -> list[Path]:
        """``notebooks/*.ipynb`` in name order (hidden files and checkpoints excluded)."""
        return _listing(self.notebooks, "*.ipynb", lambda p: not p.name.startswith("."))

    def wmr_files(self) -> list[Path]:
        """Every ``wmr/**/*.py`` and ``edition/**/*.py``: a change to any of them makes every notebook stale."""
        return [p for d in (self.wmr, self.edition) for p in _listing(d, "**/*.py", lambda p: "__pycache__" not in p.parts)]

    # --- generated, tracked (published by the build from what the chapters wrote; must not change when re-built)
    @property
    def figures(self) -> Path:
        return self.root / "figures"

    @property
    def ledger(self) -> Path:
        return self.figures / "ledger.csv"

    @property
    def singularities(self) -> Path:
        return self.figures / "singularities.csv"

    def figure_files(self) -> list[Path]:
        """Files under ``figures/`` (what the build published)."""
        return _listing(self.figures, "*", lambda p: not p.name.startswith("."))

    # --- what each executed chapter wrote (``$WMR_OUT``): published into figures/ by the build
    @property
    def out(self) -> Path:
        return self.build / "out"

    def chapter_out(self, nb: Path) -> Path:
        return self.out / nb.stem

    def chapter_files(self, nb: Path) -> list[Path]:
        """The files chapter ``nb`` wrote (figures, tables and its ``ledger.csv``)."""
        return _listing(self.chapter_out(nb), "*", lambda p: not p.name.startswith("."))

    # --- build outputs (untracked)
    @property
    def executed(self) -> Path:
        """Executed notebooks."""
        return self.build / "notebooks"

    def executed_notebook(self, nb: Path) -> Path:
        return self.executed / nb.name

    def notebook_stamp(self, nb: Path) -> Path:
        return self.executed / (nb.stem + ".stamp")

    @property
    def ledger_stamp(self) -> Path:
        return self.build / "ledger.stamp"

    @property
    def report_notebook(self) -> Path:
        return self.build / "report.ipynb"

    @property
    def report_html(self) -> Path:
        return self.build / "report.html"

    @property
    def report_pdf(self) -> Path:
        return self.build / "report.pdf"

    @property
    def report_tex(self) -> Path:
        """The LaTeX source of the PDF (kept to read the xelatex log against)."""
        return self.build / "report.tex"

    @property
    def report_log(self) -> Path:
        return self.build / "report.log"

    @property
    def report_stamp(self) -> Path:
        return self.build / "report.stamp"

    @property
    def lock(self) -> Path:
        """Held while a build runs in this tree (a second build waits)."""
        return self.build / ".lock"

    @property
    def tmp(self) -> Path:
        """Temporary directories of the build (LaTeX runs); emptied when a build ends."""
        return self.build / "tmp"

    @property
    def test_runs(self) -> Path:
        """Logs, JUnit reports and recorded durations of the test partitions (``make test``)."""
        return self.build / "test-runs"

    @property
    def git_snapshot(self) -> Path:
        """State of the work tree before ``make test`` (see :mod:`tools.build.guard`)."""
        return self.build / "git-before.json"

    # --- environment of notebook kernels and of ``python -m wmr...``
    def env(self, out: Path | None = None) -> dict:
        """Environment for notebook kernels: the running (venv) Python first on ``PATH``, the
        project root on ``PYTHONPATH`` (its ``wmr`` first) and the build tool importable,
        ``WMR_OUT`` (where a chapter writes: ``out``), one BLAS thread per process, a fixed hash seed."""
        env = dict(os.environ)
        env["PATH"] = str(Path(sys.executable).parent) + os.pathsep + env.get("PATH", "")
        pp = [str(self.root), str(TOOL_ROOT)] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else [])
        env["PYTHONPATH"] = os.pathsep.join(dict.fromkeys(pp))
        env.pop("WMR_OUT", None)
        if out is not None:
            env["WMR_OUT"] = str(out)
        env["PYDEVD_DISABLE_FILE_VALIDATION"] = "1"
        env["MPLBACKEND"] = "Agg"
        # notebooks run side by side on few cores: one BLAS thread each (no oversubscription,
        # and floating-point reductions in a fixed order)
        for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
            env.setdefault(var, "1")
        env["PYTHONHASHSEED"] = "0"
        # the venv's own "python3" kernelspec before any user-level one that names another Python
        env["JUPYTER_PREFER_ENV_PATH"] = "1"
        # kernel connection files under build/tmp, removed with it (even after a SIGKILL)
        env["JUPYTER_RUNTIME_DIR"] = str(self.tmp / "jupyter-runtime")
        return env

    def rel(self, p: Path) -> str:
        """``p`` relative to the root when inside it (for messages and stamps)."""
        try:
            return p.resolve().relative_to(self.root).as_posix()
        except ValueError:
            return p.as_posix()
