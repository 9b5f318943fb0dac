"""Stamps: what a build step consumed (one key) and what it produced (a hash per output).

A step is up to date only when its stamp parses, its key equals the key of today's inputs, and
every output it recorded still exists with the recorded SHA-256. A truncated output, a deleted
output or a garbage stamp therefore means "run the step again", never "up to date".
"""
from __future__ import annotations

import json
from pathlib import Path

from .files import atomic_write, sha256_file

__all__ = ["Stamp"]


class Stamp:
    """The stamp file ``path`` of one build step.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> out = d / "out.txt"; _ = out.write_text("result")
    >>> s = Stamp(d / "step.stamp")
    >>> s.valid("key1", [out])
    False
    >>> s.write("key1", [out]); s.valid("key1", [out]), s.valid("key2", [out])
    (True, False)
    >>> _ = out.write_text("resu"); s.valid("key1", [out])      # truncated output
    False
    """

    def __init__(self, path: Path):
        self.path = Path(path)

    def read(self) -> dict | None:
        """The stamp's content, or ``None`` if it is missing or not a stamp."""
        try:
            data = json.loads(self.path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None
        if not (isinstance(data, dict) and isinstance(data.get("key"), str)
                and isinstance(data.get("outputs"), dict)):
            return None
        return data

    def valid(self, key: str, outputs) -> bool:
        """True when the stamp records ``key`` and each of ``outputs`` with its current hash."""
        data = self.read()
        if data is None or data["key"] != key:
            return False
        rec = data["outputs"]
        outputs = [Path(p) for p in outputs]
        if set(rec) != {self._name(p) for p in outputs}:
            return False
        return all(rec[self._name(p)] == sha256_file(p) for p in outputs)

    def output_hashes(self) -> dict:
        """``{output name: sha256}`` as recorded (empty when the stamp is invalid)."""
        data = self.read()
        return dict(data["outputs"]) if data else {}

    def info(self) -> dict:
        """Extra facts the step recorded (e.g. how long it took), even when the stamp is stale."""
        data = self.read()
        return dict(data.get("info") or {}) if data else {}

    def write(self, key: str, outputs, info: dict | None = None) -> None:
        """Record ``key`` and the current hash of each of ``outputs`` (which must exist), and
        ``info`` (facts about the run that do not decide whether it is up to date)."""
        rec = {}
        for p in outputs:
            h = sha256_file(Path(p))
            if h is None:
                raise FileNotFoundError(f"cannot stamp missing output {p}")
            rec[self._name(Path(p))] = h
        data = {"key": key, "outputs": rec, **({"info": info} if info else {})}
        atomic_write(self.path, json.dumps(data, indent=1, sort_keys=True) + "\n")

    def clear(self) -> None:
        self.path.unlink(missing_ok=True)

    def _name(self, p: Path) -> str:
        return p.name if p.parent == self.path.parent else str(p)
