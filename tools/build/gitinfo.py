"""Every git call of the build, in one place; each answers ``"unknown"`` (or nothing) without git.

Provenance printed in the report (the commit, and the build date taken from the commit so that two
builds of one commit are byte-identical) and the work-tree snapshots that let ``make test`` fail
when a build modifies tracked files.
"""
from __future__ import annotations

import os
import subprocess
from pathlib import Path

__all__ = ["head", "describe", "commit_epoch", "source_date_epoch", "changed_paths"]

#: the sources whose uncommitted changes mark the report's commit as modified
SOURCES = ("wmr", "notebooks", "tools", "pyproject.toml")


def _git(root: Path, *args: str) -> str | None:
    """stdout of ``git -C root args`` or ``None`` (no git, not a repository, error)."""
    try:
        p = subprocess.run(["git", "-C", str(root), *args], capture_output=True, text=True, timeout=30,
                           env={**os.environ, "GIT_OPTIONAL_LOCKS": "0", "LC_ALL": "C"})
    except (OSError, subprocess.SubprocessError):
        return None
    return p.stdout if p.returncode == 0 else None


def head(root: Path) -> str:
    """Full hash of HEAD, or ``"unknown"``."""
    out = _git(root, "rev-parse", "HEAD")
    return out.strip() if out and out.strip() else "unknown"


def describe(root: Path) -> str:
    """HEAD's short hash, ``"+ uncommitted changes"`` when the sources differ from it (figures/ is
    written by the build itself and does not count), or ``"unknown"``."""
    h = head(root)
    if h == "unknown":
        return h
    dirty = _git(root, "status", "--porcelain", "--untracked-files=no", "--", *SOURCES)
    return h[:12] + (" + uncommitted changes" if dirty and dirty.strip() else "")


def commit_epoch(root: Path) -> int | None:
    """Committer time of HEAD (seconds since 1970), ``None`` without git."""
    out = _git(root, "log", "-1", "--format=%ct")
    try:
        return int(out.strip()) if out else None
    except ValueError:
        return None


def source_date_epoch(root: Path) -> int:
    """The build date: ``$SOURCE_DATE_EPOCH`` if set, else HEAD's commit time, else 0.

    Never the wall clock: two builds of one commit must be byte-identical.
    """
    env = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    if env.isdigit():
        return int(env)
    return commit_epoch(root) or 0


def changed_paths(root: Path) -> dict[str, str] | None:
    """``{path: status}`` of every tracked file that differs from HEAD and every untracked file
    that is not ignored (``git status --porcelain``), or ``None`` without git."""
    out = _git(root, "status", "--porcelain=v1", "-z", "--untracked-files=all")
    if out is None:
        return None
    res: dict[str, str] = {}
    items = out.split("\0")
    i = 0
    while i < len(items):
        it = items[i]
        i += 1
        if len(it) < 4:
            continue
        code, path = it[:2], it[3:]
        if code[0] in "RC":       # rename/copy: the source path follows
            i += 1
        res[path] = code
    return res
