"""``make test`` must fail when a build modifies tracked files (or leaves new, unignored ones).

:func:`snapshot` records, before the build, every path that ``git status`` reports and the hash
of each; :func:`compare` lists what the build changed since. Changes that were already there
(someone's uncommitted edits) do not count; on a clean checkout (CI) this is exactly "the build
leaves ``git status`` clean".
"""
from __future__ import annotations

import json
from pathlib import Path

from . import gitinfo
from .files import atomic_write, sha256_file
from .paths import Tree

__all__ = ["snapshot", "compare", "state"]


def state(t: Tree) -> dict[str, str] | None:
    """``{path: status + hash}`` of every changed or untracked path, ``None`` without git."""
    changed = gitinfo.changed_paths(t.root)
    if changed is None:
        return None
    return {p: f"{code} {sha256_file(t.root / p) or 'deleted'}" for p, code in changed.items()}


def snapshot(t: Tree) -> bool:
    """Record the state before a build in ``build/git-before.json``; False without git."""
    s = state(t)
    if s is None:
        return False
    atomic_write(t.git_snapshot, json.dumps(s, indent=1, sort_keys=True) + "\n")
    return True


def compare(t: Tree) -> list[str] | None:
    """The paths whose state changed since :func:`snapshot` (``None``: no snapshot or no git)."""
    try:
        before = json.loads(Path(t.git_snapshot).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    after = state(t)
    if after is None:
        return None
    return sorted(p for p in set(before) | set(after) if before.get(p) != after.get(p))
