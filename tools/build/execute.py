"""Execute the notebooks (cached by content hash, two at a time), then publish what they wrote.

A notebook is re-executed when its bytes, any ``wmr/**/*.py``, the Python version or this
executor change, or when its executed copy or a file it wrote no longer has the hash its stamp
recorded (a truncated or deleted output heals itself). Each runs in a fresh kernel
(:mod:`tools.build.worker`) with its own directory as working directory and ``WMR_OUT`` set to
``build/out/<notebook>``: a chapter writes nothing tracked. :func:`publish` then copies the
chapters' figures and tables into ``figures/`` (only files whose bytes changed) and
``python -m edition.ledger build/out figures/ledger.csv`` concatenates their ledger rows.
"""
from __future__ import annotations

import hashlib
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from . import procs
from .files import atomic_write, hash_files, remove_temp_dirs
from .log import BuildError, say, strip_ansi
from .paths import TOOL_ROOT, Tree
from .stamps import Stamp

__all__ = ["execute", "stale_notebooks", "wmr_hash", "notebook_key", "publish", "merge_ledger", "invalidate_report",
           "WORKERS"]

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
    return [nb for nb in nbs if not Stamp(t.notebook_stamp(nb)).valid(notebook_key(t, nb, wh), _outputs(t, nb))]


def _outputs(t: Tree, nb: Path) -> list[Path]:
    """What executing ``nb`` produces: its executed copy and the files it wrote."""
    return [t.executed_notebook(nb), *t.chapter_files(nb)]


def invalidate_report(t: Tree) -> None:
    """Remove the report and its stamp: once its inputs change it must not look current."""
    for p in (t.report_stamp, t.report_html, t.report_pdf, t.report_notebook):
        p.unlink(missing_ok=True)


def _execute_one(t: Tree, nb: Path, key: str) -> str | None:
    """Execute ``nb`` in a fresh worker process; ``None`` on success, else the error text."""
    out, stamp = t.executed_notebook(nb), Stamp(t.notebook_stamp(nb))
    stamp.clear()                         # nothing stale may look valid while we run
    out.unlink(missing_ok=True)
    for f in t.chapter_files(nb):         # what it wrote last time
        f.unlink()
    t0 = time.perf_counter()
    p = procs.run([sys.executable, "-m", "tools.build.worker", str(nb), str(out), str(nb.parent)],
                  cwd=nb.parent, env=t.env(out=t.chapter_out(nb)), pdeathsig=False)
    if p.returncode != 0 or not out.exists():
        out.unlink(missing_ok=True)
        say("execute", f"FAILED {nb.name}", t0)
        err = "\n".join(l for l in p.stderr.splitlines() if not l.startswith("[IPKernelApp] WARNING"))
        return strip_ansi(err.strip() or p.stdout.strip() or f"exit code {p.returncode}")
    stamp.write(key, _outputs(t, nb), info={"seconds": round(time.perf_counter() - t0, 1)})
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
        Run ``python -m edition.ledger`` afterwards (when its inputs changed).
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
        if failures:
            invalidate_report(t)
            msg = "\n\n".join(f"=== notebook {t.rel(t.notebooks)}/{n} failed ===\n{e}" for n, e in failures.items())
            raise BuildError(msg)
        say("execute", f"{len(todo)} executed, {len(nbs) - len(todo)} cached", t0)
        if merge and only is None:
            publish(t, every)
            merge_ledger(t, force=bool(todo))
        return sorted(nb.name for nb in todo)


def publish(t: Tree, nbs: list[Path]) -> list[Path]:
    """Copy what the chapters wrote (all but their ledger rows) into ``figures/``: the build's only writer there.

    A file is written only when its bytes differ from the tracked one, so an unchanged figure keeps
    its timestamp and ``git status`` stays clean.  Two chapters may not write the same file.

    Returns
    -------
    list of Path
        The files of ``figures/`` that changed.
    """
    owner: dict[str, Path] = {}
    changed = []
    for nb in nbs:
        for f in t.chapter_files(nb):
            if f.name == "ledger.csv":
                continue
            if f.name in owner:
                raise BuildError(f"{nb.name} and {owner[f.name].name} both write {f.name}")
            owner[f.name] = nb
            dest = t.figures / f.name
            blob = f.read_bytes()
            if not dest.exists() or dest.read_bytes() != blob:
                atomic_write(dest, blob)
                changed.append(dest)
    stray = sorted(p.name for p in t.figure_files() if p.name not in owner and p != t.ledger)
    if stray:
        say("publish", f"files in {t.rel(t.figures)}/ that no chapter writes (left alone): {' '.join(stray)}")
    say("publish", f"{len(owner)} files of the chapters in {t.rel(t.figures)}/, {len(changed)} changed")
    return changed


def _module_present(t: Tree, mod: str) -> bool:
    return (t.edition / (mod + ".py")).exists() or (t.edition / mod / "__init__.py").exists()


def merge_ledger(t: Tree, force: bool = False) -> None:
    """``python -m edition.ledger build/out figures/ledger.csv``: the chapters' rows in one ledger."""
    t0 = time.perf_counter()
    if not _module_present(t, "ledger"):
        say("ledger", "skipped: edition/ledger.py not found")
        return
    frags = sorted(t.out.glob("*/ledger.csv"))
    key = hash_files(frags, t.root, hashlib.sha256(wmr_hash(t).encode())).hexdigest()
    stamp = Stamp(t.ledger_stamp)
    if not force and stamp.valid(key, [t.ledger]):
        say("ledger", f"{t.rel(t.ledger)} up to date (cached)")
        return
    stamp.clear()
    p = procs.run([sys.executable, "-m", "edition.ledger", str(t.out), str(t.ledger)], cwd=t.root, env=t.env())
    if p.returncode != 0:
        raise BuildError(f"python -m edition.ledger failed (exit {p.returncode}):\n{p.stdout}\n{p.stderr}")
    stamp.write(key, [t.ledger])
    last = (p.stdout.strip().splitlines() or [""])[-1]
    say("ledger", f"python -m edition.ledger: {last or t.rel(t.ledger)} ({len(frags)} fragments)", t0)
