"""The edition's test results reused while nothing changed: ``build/tests-edition.stamp``.

``make test`` runs the library's tests (``tests/``) every time.  The edition's tests (``tests/edition/``:
the build on small trees, the report, the figures redrawn one ulp off, the physics in MuJoCo, the
lessons' grades) test what the repository builds from its own files, and they are most of the CPU of a
warm run.  When they passed on exactly this tree, with the same interpreter, system tools and pytest
arguments, ``make test`` says so and does not run them again -- as Bazel reuses the result of a test
whose inputs did not change, and as ``make release`` reuses its fresh-venv run.  ``make test FRESH=1``
runs them anyway; a fresh clone (CI) has no stamp and runs everything.

:func:`key` is a sha256 over

- the path and bytes of every file git sees: tracked files as they are in the work tree (edits
  included, a deleted one by its name) and untracked files that are not ignored
  (``git ls-files --cached --others --exclude-standard``);
- the Python version and platform, and the versions of the report's system tools (xelatex, pandoc,
  chromium);
- the pytest arguments.

What git ignores (``build/``, ``.venv/``) is made from these: the build's outputs by the build's own
cached steps, the environment from ``environment.lock``, which is hashed.  The stamp is written only after
a run of the whole suite in which pytest passed and the build left git status as it found it.

    python -m tools.testcache key [PYTEST_ARGS ...]   print the key (nothing outside a git checkout)
    python -m tools.testcache check KEY               exit 0, and say so, when the stamp holds KEY
    python -m tools.testcache stamp KEY               record a pass at KEY
"""

from __future__ import annotations

import hashlib
import json
import platform
import subprocess
import sys
import time
from pathlib import Path

__all__ = ["STAMP", "TOOLS", "key", "main"]

ROOT = Path(__file__).resolve().parents[1]
STAMP = ROOT / "build" / "tests-edition.stamp"
#: the system tools the edition's tests run, by the command that prints their version
TOOLS = (("xelatex", "--version"), ("pandoc", "--version"), ("chromium", "--version"))


def _version(cmd: tuple[str, ...]) -> str:
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=60, check=False).stdout
    except OSError:
        return f"{cmd[0]}: absent"
    return out.strip().splitlines()[0] if out.strip() else f"{cmd[0]}: no version"


def key(args: list[str], root: Path = ROOT) -> str:
    """The key of a test run with pytest arguments ``args`` on the tree at ``root`` (see the module)."""
    listed = subprocess.run(
        ["git", "-C", str(root), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
        capture_output=True,
        check=True,
    ).stdout
    h = hashlib.sha256()
    for name in sorted(set(listed.decode().split("\0")) - {""}):
        path = root / name
        h.update(name.encode() + b"\0" + (path.read_bytes() if path.is_file() else b"(absent)") + b"\0")
    for line in (sys.version, platform.platform(), *(_version(t) for t in TOOLS), *args):
        h.update(line.encode() + b"\0")
    return h.hexdigest()


def main(argv: list[str] | None = None) -> int:
    """The command line (see the module); ``check`` exits 1 when the stamp does not hold the key."""
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] not in ("key", "check", "stamp") or (argv[0] != "key" and len(argv) != 2):
        print("usage: python -m tools.testcache key [PYTEST_ARGS ...] | check KEY | stamp KEY", file=sys.stderr)
        return 2
    if argv[0] == "key":
        try:
            print(key(argv[1:]))
        except (OSError, subprocess.CalledProcessError):  # no git, or not a git checkout: no key, no reuse
            print("[test] not a git checkout: tests/edition/ runs every time", file=sys.stderr)
        return 0
    if argv[0] == "stamp":
        STAMP.parent.mkdir(parents=True, exist_ok=True)
        when = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
        STAMP.write_text(json.dumps({"key": argv[1], "passed": when}) + "\n", encoding="utf-8")
        return 0
    try:
        held = json.loads(STAMP.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return 1
    if not isinstance(held, dict) or held.get("key") != argv[1]:
        return 1
    print(
        f"[test] tests/edition/ passed on exactly this tree at {held.get('passed')} (key {argv[1][:12]}, "
        f"{STAMP.relative_to(ROOT)}): not run again; `make test FRESH=1` runs them"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
