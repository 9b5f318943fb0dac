"""Writing files atomically, hashing them, and temporary directories that do not outlive a build.

:func:`atomic_write` is the build's one way of writing a file: the bytes go to a temporary file
beside the target, are flushed to disk, and replace the target in one ``os.replace``; a crash or a
signal leaves either the old file or the new one, never a truncated one.  It and :func:`atomic_path`
are the library's own (``edition/files.py``, standard library only), loaded here by path so that
the build does not import the package it builds (nor NumPy and SymPy) to write a stamp.
"""
from __future__ import annotations

import contextlib
import hashlib
import importlib.util
import os
import shutil
import tempfile
from pathlib import Path

__all__ = ["atomic_write", "atomic_path", "sha256_file", "hash_files", "temp_dir", "remove_temp_dirs"]


def _library_files():
    """``edition/files.py`` of this source tree, loaded as a module of its own (no ``wmr`` import)."""
    path = Path(__file__).resolve().parents[2] / "edition" / "files.py"
    spec = importlib.util.spec_from_file_location("_edition_files", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


_files = _library_files()
atomic_path = _files.atomic_path
atomic_write = _files.atomic_write


def sha256_file(path: Path) -> str | None:
    """Hex SHA-256 of the file's bytes, ``None`` if it cannot be read."""
    h = hashlib.sha256()
    try:
        with open(path, "rb") as f:
            for block in iter(lambda: f.read(1 << 20), b""):
                h.update(block)
    except OSError:
        return None
    return h.hexdigest()


def hash_files(files, base: Path, h=None):
    """Update (or start) a SHA-256 with the relative name and bytes of each file, in order.

    A missing file hashes as its name followed by a marker, so that deleting a file changes the hash.
    """
    h = h or hashlib.sha256()
    for p in files:
        p = Path(p)
        try:
            rel = p.relative_to(base).as_posix()
        except ValueError:
            rel = p.as_posix()
        h.update(rel.encode() + b"\0")
        try:
            h.update(p.read_bytes())
        except OSError:
            h.update(b"\0<missing>")
        h.update(b"\0")
    return h


_live: set[Path] = set()


@contextlib.contextmanager
def temp_dir(parent: Path, prefix: str):
    """A fresh directory under ``parent`` (the build's ``tmp/``), removed on exit, on an
    exception and on a signal (:class:`tools.build.log.Interrupted`); :func:`remove_temp_dirs`
    removes what a killed build (SIGKILL) left."""
    parent = Path(parent)
    parent.mkdir(parents=True, exist_ok=True)
    d = Path(tempfile.mkdtemp(dir=parent, prefix=prefix))
    _live.add(d)
    try:
        yield d
    finally:
        _live.discard(d)
        shutil.rmtree(d, ignore_errors=True)


def remove_temp_dirs(parent: Path) -> int:
    """Remove every directory under ``parent`` not in use by this process; return how many.

    Called under the build lock, so nothing else uses them: they are what an earlier build,
    killed with SIGKILL, could not clean up.
    """
    parent = Path(parent)
    n = 0
    if parent.is_dir():
        for d in parent.iterdir():
            if d not in _live:
                if d.is_dir():
                    shutil.rmtree(d, ignore_errors=True)
                else:
                    d.unlink(missing_ok=True)
                n += 1
    return n
