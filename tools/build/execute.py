"""Execute the notebooks (cached by content hash, two at a time) and merge the ledger.

A notebook is re-executed when its bytes, any ``wmr/**/*.py``, the Python version or this
executor change, or when its executed copy no longer has the hash its stamp recorded (a truncated
copy heals itself). Each runs in a fresh kernel (:mod:`tools.build.worker`) with ``WMR_PROJECT``
set to the project root and its own directory as working directory. The notebooks write
``figures/``; the stamp ``build/figures.stamp`` records what they wrote, so a damaged figure file
re-executes them. ``python -m wmr.paper.ledger figures/`` then merges the ledger fragments.
"""
from __future__ import annotations

import hashlib
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from . import procs
from .files import hash_files, remove_temp_dirs
from .log import BuildError, say, strip_ansi
from .paths import TOOL_ROOT, Tree
from .stamps import Stamp

__all__ = ["execute", "stale_notebooks", "wmr_hash", "notebook_key", "merge_ledger", "invalidate_report", "WORKERS"]

WORKERS = 2
_EXECUTOR = [Path(__file__).resolve().parent / "worker.py"]   # a change re-executes everything


def wmr_hash(t: Tree) -> str:
    return hash_files(t.wmr_files(), t.root).hexdigest()


def notebook_key(t: Tree, nb: Path, whash: str | None = None) -> str:
    """What an executed notebook depends on: its bytes, the package, Python, the executor."""
    h = hashlib.sha256(nb.read_bytes())
    h.update((whash if whash is not None else wmr_hash(t)).encode())
    h.update(sys.version.encode())
    hash_files(_EXECUTOR, TOOL_ROOT, h)
    return h.hexdigest()


def stale_notebooks(t: Tree, nbs: list[Path] | None = None) -> list[Path]:
    """The notebooks whose executed copy is missing, damaged or older than their inputs."""
    wh = wmr_hash(t)
    nbs = t.notebook_files() if nbs is None else nbs
    return [nb for nb in nbs
            if not Stamp(t.notebook_stamp(nb)).valid(notebook_key(t, nb, wh), [t.executed_notebook(nb)])]


#: the figures stamp records the files under figures/ after each execution (no inputs of its own)
_FIGURES_KEY = "files under figures/ as the last notebook execution left them"


def invalidate_report(t: Tree) -> None:
    """Remove the report and its stamp: once its inputs change it must not look current."""
    for p in (t.report_stamp, t.report_html, t.report_pdf, t.report_notebook):
        p.unlink(missing_ok=True)


def _execute_one(t: Tree, nb: Path, key: str) -> str | None:
    """Execute ``nb`` in a fresh worker process; ``None`` on success, else the error text."""
    out, stamp = t.executed_notebook(nb), Stamp(t.notebook_stamp(nb))
    stamp.clear()                         # nothing stale may look valid while we run
    out.unlink(missing_ok=True)
    t0 = time.perf_counter()
    p = procs.run([sys.executable, "-m", "tools.build.worker", str(nb), str(out), str(nb.parent)],
                  cwd=nb.parent, env=t.env(), pdeathsig=False)
    if p.returncode != 0 or not out.exists():
        out.unlink(missing_ok=True)
        say("execute", f"FAILED {nb.name}", t0)
        err = "\n".join(l for l in p.stderr.splitlines() if not l.startswith("[IPKernelApp] WARNING"))
        return strip_ansi(err.strip() or p.stdout.strip() or f"exit code {p.returncode}")
    stamp.write(key, [out], info={"seconds": round(time.perf_counter() - t0, 1)})
    say("execute", nb.name, t0)
    return None


def execute(t: Tree | None = None, workers: int = WORKERS, merge: bool = True,
            only: list[str] | None = None) -> list[str]:
    """Execute every stale notebook (``workers`` at a time), then merge the ledger.

    Parameters
    ----------
    t : Tree, optional
    workers : int
    merge : bool
        Run ``python -m wmr.paper.ledger`` afterwards (when its inputs changed).
    only : list of str, optional
        Restrict to these notebook file names.

    Returns
    -------
    list of str
        The names of the notebooks executed.

    Raises
    ------
    BuildError
        When a notebook fails (its executed copy and stamp are removed, and so is the report).
    """
    t = t or Tree()
    with procs.BuildLock(t.lock):
        t0 = time.perf_counter()
        remove_temp_dirs(t.tmp)
        every = t.notebook_files()
        nbs = [nb for nb in every if only is None or nb.name in only]
        if not nbs:
            say("execute", f"no notebooks in {t.notebooks}")
        t.executed.mkdir(parents=True, exist_ok=True)
        todo = stale_notebooks(t, nbs)
        fstamp = Stamp(t.figures_stamp)
        if only is None and nbs and not todo and not fstamp.valid(_FIGURES_KEY, t.figure_files()):
            say("execute", f"{t.rel(t.figures)}/ is not what the notebooks wrote: re-executing them")
            todo = list(nbs)
        for nb in nbs:
            if nb not in todo:
                say("execute", f"{nb.name} up to date (cached)")
        if todo:
            invalidate_report(t)
        wh = wmr_hash(t)
        failures: dict[str, str] = {}
        if todo:
            # longest first (as long as the last run took; unknown first): the last to finish
            # is then a short one, and the two workers end together
            last = {nb: Stamp(t.notebook_stamp(nb)).info().get("seconds", float("inf")) for nb in todo}
            todo = sorted(todo, key=lambda nb: -last[nb])
            with ThreadPoolExecutor(max_workers=max(1, workers)) as pool:
                futs = {nb.name: pool.submit(_execute_one, t, nb, notebook_key(t, nb, wh)) for nb in todo}
                for name, f in futs.items():
                    err = f.result()
                    if err:
                        failures[name] = err
            fstamp.write(_FIGURES_KEY, t.figure_files())     # what the notebooks left in figures/
        if failures:
            invalidate_report(t)
            msg = "\n\n".join(f"=== notebook {t.rel(t.notebooks)}/{n} failed ===\n{e}" for n, e in failures.items())
            raise BuildError(msg)
        say("execute", f"{len(todo)} executed, {len(nbs) - len(todo)} cached", t0)
        if merge:
            merge_ledger(t, force=bool(todo))
        return sorted(nb.name for nb in todo)


def _module_present(t: Tree, mod: str) -> bool:
    return (t.wmr / (mod + ".py")).exists() or (t.wmr / mod / "__init__.py").exists()


def merge_ledger(t: Tree, force: bool = False) -> None:
    """``python -m wmr.paper.ledger figures/``: merge ``figures/ledger/*.csv`` into ``figures/ledger.csv``."""
    t0 = time.perf_counter()
    if not _module_present(t, "paper/ledger"):
        say("ledger", "skipped: wmr/paper/ledger.py not found")
        return
    frags = sorted(t.ledger_fragments.glob("*.csv"))
    key = hash_files(frags, t.root, hashlib.sha256(wmr_hash(t).encode())).hexdigest()
    stamp = Stamp(t.ledger_stamp)
    if not force and stamp.valid(key, [t.ledger]):
        say("ledger", f"{t.rel(t.ledger)} up to date (cached)")
        return
    stamp.clear()
    p = procs.run([sys.executable, "-m", "wmr.paper.ledger", str(t.figures)], cwd=t.root, env=t.env())
    if p.returncode != 0:
        raise BuildError(f"python -m wmr.paper.ledger failed (exit {p.returncode}):\n{p.stdout}\n{p.stderr}")
    stamp.write(key, [t.ledger])
    last = (p.stdout.strip().splitlines() or [""])[-1]
    say("ledger", f"python -m wmr.paper.ledger: {last or t.rel(t.ledger)} ({len(frags)} fragments)", t0)
