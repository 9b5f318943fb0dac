"""Writing the edition's output files atomically: a killed writer never leaves a truncated file.

Each file is written to a temporary file in the same directory and moved over the target with
:func:`os.replace` (atomic on POSIX and Windows), so a reader sees the old file or the new one,
never a part.  Where the files go is always passed in: the library never resolves repository paths.

This module uses the standard library only: the build tool (``tools/build/files.py``) loads it by
path, so the project has one atomic writer without the build importing NumPy or SymPy.
"""

from __future__ import annotations

import contextlib
import csv
import io
import os
import tempfile
from pathlib import Path

__all__ = ["atomic_path", "atomic_write", "csv_text"]


def _file_mode():
    """The mode an ordinary new file gets (``0o666`` less the umask): ``mkstemp``'s ``0o600`` is too private."""
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


@contextlib.contextmanager
def atomic_path(path):
    """A temporary path beside ``path`` that replaces ``path`` atomically when the block succeeds.

    On any exception (or a signal turned into one) the temporary file is removed and ``path`` is
    untouched.  For writers that want a file name (``nbformat.write``, ``zipfile``); the bytes are
    flushed to disk before the replace.

    Parameters
    ----------
    path : str or os.PathLike
        The target; its directory is created if needed.

    Yields
    ------
    pathlib.Path
        The temporary file to write.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix="." + path.name + ".", suffix=".tmp")
    os.close(fd)
    try:
        yield Path(tmp)
        with open(tmp, "rb+") as f:
            os.fsync(f.fileno())
        os.chmod(tmp, _file_mode())
        os.replace(tmp, path)
    finally:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)


def atomic_write(path, data):
    """Write ``data`` (bytes, or str written as UTF-8) to ``path`` atomically; returns the path.

    The directory is created if needed; the file gets ordinary permissions (``0o666`` less the
    umask), not those of a private temporary file.

    Parameters
    ----------
    path : str or os.PathLike
    data : bytes or str

    Returns
    -------
    pathlib.Path

    Examples
    --------
    >>> import tempfile
    >>> d = Path(tempfile.mkdtemp())
    >>> atomic_write(d / "a" / "x.txt", "one").read_text(), sorted(p.name for p in (d / "a").iterdir())
    ('one', ['x.txt'])
    """
    if isinstance(data, str):
        data = data.encode("utf-8")
    elif not isinstance(data, (bytes, bytearray)):
        raise TypeError(f"data must be bytes or str, got {type(data).__name__}")
    with atomic_path(path) as tmp:
        tmp.write_bytes(data)
    return Path(path)


def _cell(value):
    """A CSV field: a float by the rule of written numbers (:func:`wmr.io.decimals.float_text`), else ``str``."""
    if isinstance(value, float) or getattr(getattr(value, "dtype", None), "kind", "") == "f":  # NumPy's too
        from wmr.io.decimals import float_text  # only when a float is written: this module stays light

        return float_text(value)
    return "" if value is None else str(value)


def csv_text(rows, columns):
    r"""Rows as CSV text: a header of ``columns``, then one line per row (a missing field is empty).

    Lines end in ``\n`` on every platform, and a float is written by the rule of
    :mod:`wmr.io.decimals` (12 significant digits, the shortest ``repr`` of the rounded double), so the
    files do not change with the machine that wrote them.  The edition's tables hold text their
    chapters formatted (``"< 1e-12"``, ``"0.0500 m"``); a float that reaches a table is written here.

    Parameters
    ----------
    rows : iterable of dict
        Field name -> value (a float by :func:`wmr.io.decimals.float_text`, anything else with ``str``;
        ``None`` and a missing field are empty).
    columns : sequence of str
        The fields, in order.

    Returns
    -------
    str

    Examples
    --------
    >>> csv_text([{"id": "20", "verdict": "ok"}], ("id", "verdict", "note"))
    'id,verdict,note\n20,ok,\n'
    >>> csv_text([{"x": 0.1 + 0.2, "n": 3}], ("x", "n"))
    'x,n\n0.3,3\n'
    """
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(list(columns))
    for r in rows:
        w.writerow([_cell(r.get(k)) for k in columns])
    return buf.getvalue()
