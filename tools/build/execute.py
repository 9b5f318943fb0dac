"""Execute one notebook in a fresh kernel (nbclient), cached by content hash; publish what the chapters wrote.

``execute NOTEBOOK OUT [--reads DIR]`` (Make runs one per chapter, two at a time): the notebook runs in its own folder
with ``WMR_OUT=<build>/out/<chapter>`` (where a chapter writes figures and ledger rows, nothing tracked); its executed
copy is ``OUT``. Its key hashes the notebook, every file of ``wmr/`` and ``edition/``, the files under ``DIR`` or the
file ``DIR`` (the findings chapter reads ``figures/``, a chapter the derived objects of an earlier one), Python and
this file; the stamp ``OUT.stamp`` records the key and the hash of
every output. While both hold nothing is written (Make sees nothing new); a changed input, a damaged output or a garbage
stamp runs it again, and the report is removed first. :func:`publish` copies what the chapters wrote into ``figures/``,
a file only when its bytes differ: the build is the only writer there, ``git status`` stays clean."""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import sys
import time
from pathlib import Path

from . import BuildError, atomic_write, say

__all__ = ["CELL_TIMEOUT", "ROOT", "execute", "kernel_env", "key", "outputs", "publish", "up_to_date", "write_stamp"]

#: the project tree whose ``wmr/`` and ``edition/`` the notebooks import (``$WMR_ROOT``, set by the Makefile)
ROOT = Path(os.environ.get("WMR_ROOT") or Path(__file__).resolve().parents[2])
CELL_TIMEOUT = 600  # seconds per cell


def _files(d: Path) -> list[Path]:
    if not d.is_dir():
        return [d] if d.is_file() else []
    files = (p for p in d.rglob("*") if p.is_file())
    return sorted(p for p in files if "__pycache__" not in p.parts and not p.name.startswith("."))


def key(nb: Path, root: Path = ROOT, reads: tuple[Path, ...] = ()) -> str:
    """What an executed notebook depends on: its bytes, ``root/wmr/``, ``root/edition/``, ``reads`` (folders
    or files), Python, this file."""
    h = hashlib.sha256(nb.read_bytes())
    for d in (root / "wmr", root / "edition", *reads):
        for p in _files(d):
            h.update(str(p.relative_to(d.parent)).encode() + b"\0" + p.read_bytes() + b"\0")
    h.update(sys.version.encode() + Path(__file__).read_bytes())
    return h.hexdigest()


def outputs(out: Path) -> list[Path]:
    """The executed copy and the files its chapter wrote (``<build>/out/<chapter>/``)."""
    return [out, *_files(out.parent.parent / "out" / out.stem)]


def _hashes(out: Path) -> dict[str, str | None]:
    """``{path relative to the build directory: SHA-256}`` of the outputs (a copied build stays valid)."""
    sha = {p: hashlib.sha256(p.read_bytes()).hexdigest() if p.is_file() else None for p in outputs(out)}
    return {p.relative_to(out.parent.parent).as_posix(): h for p, h in sha.items()}


def up_to_date(stamp: Path, k: str, out: Path) -> bool:
    """True when ``stamp`` records key ``k`` and the current hash of each output of ``out``."""
    try:
        data = json.loads(stamp.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    return isinstance(data, dict) and data.get("key") == k and data.get("outputs") == _hashes(out)


def write_stamp(out: Path, k: str) -> None:
    """Write ``OUT.stamp``: key ``k`` and the hash of each output of ``out`` (what :func:`up_to_date` reads)."""
    atomic_write(out.with_suffix(".stamp"), json.dumps({"key": k, "outputs": _hashes(out)}, indent=1) + "\n")


def kernel_env(root: Path, chapter_out: Path) -> dict[str, str]:
    """The kernel's environment: the venv's Python first on ``PATH``, the project importable,
    ``WMR_OUT``, no plot windows, one BLAS thread (two notebooks share two cores), a fixed hash seed."""
    env = dict(os.environ, WMR_OUT=str(chapter_out), MPLBACKEND="Agg", PYTHONHASHSEED="0")
    env.update(JUPYTER_PREFER_ENV_PATH="1", PYDEVD_DISABLE_FILE_VALIDATION="1")
    env["PATH"] = str(Path(sys.executable).parent) + os.pathsep + env.get("PATH", "")
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(root), env.get("PYTHONPATH")]))
    for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        env.setdefault(var, "1")
    return env


def execute(nb: Path, out: Path, reads: tuple[Path, ...] = (), root: Path = ROOT) -> bool:
    """Execute ``nb`` into ``out`` unless its stamp is current; True when it ran (``root``: the
    project whose ``wmr/`` and ``edition/`` it imports).

    Raises
    ------
    BuildError
        A cell raised: the message holds the notebook's name, the cell's source and the traceback;
        the executed copy, the stamp and the report are left removed.
    """
    nb, out = Path(nb).resolve(), Path(out).resolve()
    stamp, k = out.with_suffix(".stamp"), key(nb, Path(root), tuple(Path(r).resolve() for r in reads))
    if up_to_date(stamp, k, out):
        return False
    build, chapter_out = out.parent.parent, out.parent.parent / "out" / out.stem
    for p in (stamp, out, *(build / f"report.{ext}" for ext in ("ipynb", "html", "pdf"))):
        p.unlink(missing_ok=True)
    shutil.rmtree(chapter_out, ignore_errors=True)
    t0 = time.perf_counter()
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError
    from traitlets.config import Config

    book = nbformat.read(nb, as_version=4)
    if any(c.cell_type == "code" and c.source.strip() for c in book.cells):  # else: no kernel to start
        resources = {"metadata": {"path": str(nb.parent)}}
        config = Config({"KernelManager": {"transport_encryption": "auto"}})  # CurveZMQ, as the kernel offers
        client = NotebookClient(
            book, timeout=CELL_TIMEOUT, kernel_name="python3", record_timing=False, resources=resources, config=config
        )
        try:
            client.execute(env=kernel_env(Path(root), chapter_out))
        except CellExecutionError as e:
            text = re.sub(r"\x1b\[[0-9;]*[A-Za-z]", "", str(e))  # the traceback, without terminal colours
            raise BuildError(f"=== notebook {nb.name} failed ===\n{text}") from None
        except Exception as e:  # the kernel died or was stopped (a signal: nbclient shut it down)
            raise BuildError(f"=== notebook {nb.name}: execution stopped ({type(e).__name__}) ===") from None
    atomic_write(out, nbformat.writes(book))
    write_stamp(out, k)
    say("execute", nb.name, t0)
    return True


def publish(figures: Path, executed: list[Path]) -> list[Path]:
    """Copy the files each chapter wrote, but its ledger rows, into ``figures/`` when their bytes differ.

    Returns
    -------
    list of Path
        The files of ``figures/`` that were written.

    Raises
    ------
    BuildError
        Two chapters write a file of one name.
    """
    owner: dict[str, str] = {}
    changed = []
    for out in executed:
        for f in outputs(Path(out))[1:]:
            if f.name == "ledger.csv":
                continue
            if f.name in owner:
                raise BuildError(f"{out.stem} and {owner[f.name]} both write {f.name}")
            owner[f.name] = out.stem
            dest = Path(figures) / f.name
            if not dest.is_file() or dest.read_bytes() != f.read_bytes():
                atomic_write(dest, f.read_bytes())
                changed.append(dest)
    say("publish", f"{len(owner)} files of the chapters in figures/, {len(changed)} changed")
    return changed
