"""Writing the edition's output files atomically: a killed writer never leaves a truncated file.

Each file is written to a temporary file in the same directory and moved over the target with
:func:`os.replace` (atomic on POSIX and Windows), so a reader sees the old file or the new one,
never a part.  Where the files go is always passed in: the library never resolves repository paths.
"""
from __future__ import annotations

import csv
import io
import os
import tempfile
from pathlib import Path

__all__ = ["atomic_write", "csv_text"]


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
    """
    if isinstance(data, str):
        data = data.encode("utf-8")
    elif not isinstance(data, (bytes, bytearray)):
        raise TypeError(f"data must be bytes or str, got {type(data).__name__}")
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix="." + path.name + ".", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise
    return path


def csv_text(rows, columns):
    r"""Rows as CSV text: a header of ``columns``, then one line per row (a missing field is empty).

    Lines end in ``\n`` on every platform, so the files do not change with the machine that wrote them.

    Parameters
    ----------
    rows : iterable of dict
        Field name -> value (written with ``str``).
    columns : sequence of str
        The fields, in order.

    Returns
    -------
    str

    Examples
    --------
    >>> csv_text([{"id": "20", "verdict": "ok"}], ("id", "verdict", "note"))
    'id,verdict,note\n20,ok,\n'
    """
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=list(columns), lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({k: r.get(k, "") for k in columns})
    return buf.getvalue()
