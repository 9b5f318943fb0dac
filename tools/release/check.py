"""The release installs and tests itself: build the sdist and the wheel, install the wheel into a fresh
virtual environment outside the repository, and run the library's tests and the command line there.

    python -m tools.release            # what `make release` (and so `make test`) runs
    python -m tools.release --force    # even when nothing changed since the last pass
    python -m tools.release --python python3.13 --keep

Steps, each of which fails the check with a message saying what is wrong:

1. ``python -m build --no-isolation``: the sdist, then the wheel built *from the sdist* (so the sdist is
   complete enough to build), with the environment's setuptools, which must satisfy
   ``[build-system] requires``.
2. The sdist holds the metadata files, the library's tests with what they need (``tests/conftest.py``,
   ``tests/fuzz_api.py``, ``examples/``) and nothing of the repository's edition, notebooks, build or
   ``tests/edition/``; no shipped test imports ``edition`` or ``tools``. The wheel holds ``wmr/``
   (with ``py.typed``) and its metadata: name, version (``wmr/_version.py``), ``License-Expression: MIT``,
   the licence file, the ``wmr`` command.
3. A fresh venv in a temporary folder (no system site-packages) gets the wheel with the extras the
   library's tests use (:data:`EXTRAS`), offline, from a wheelhouse in
   ``build/release/wheelhouse/<key>/``: filled once from the package index with the versions pinned in
   ``environment.lock``, keyed by the lock, the wheel's requirements and the interpreter.
4. In that venv, from the unpacked sdist with its ``wmr/`` removed (so only the installed wheel can
   be imported): ``pip check``, ``pip show``, ``wmr --version``, the README's Python examples, the
   ``wmr`` commands on the example robots (and a bad file: one line, exit status 2), the library's
   tests, none of which may be skipped for want of a module.

A pass is recorded in ``build/release/stamp`` with the hash of everything that goes into the sdist,
the lock and this script; the next run with the same hash stops at once. ``build/release/`` keeps the
sdist, the wheel and ``report.txt`` (``pip show``, versions, test summary).
"""

from __future__ import annotations

import argparse
import ast
import hashlib
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time
from collections.abc import Iterable
from pathlib import Path

from .artifacts import build, inspect
from .common import OUT, ROOT, ReleaseError, python_version, run, say
from .venv import EXTRAS, clean_env, in_venv, wheelhouse

#: what goes into the sdist besides wmr/ (MANIFEST.in): the inputs of the check, with this script
INPUTS = (
    "pyproject.toml",
    "MANIFEST.in",
    "README.md",
    "LICENSE",
    "CITATION.cff",
    "CHANGELOG.md",
    "environment.lock",
    "wmr",
    "tests",
    "examples",
    "tools/release",
)


def files(root: Path, names: Iterable[str]) -> list[Path]:
    """The files under ``names`` (files or folders of ``root``), sorted; no byte code, nothing of tests/edition/."""
    out: list[Path] = []
    for name in names:
        p = root / name
        if p.is_file():
            out.append(p)
        elif p.is_dir():
            out += [
                f
                for f in p.rglob("*")
                if f.is_file()
                and "__pycache__" not in f.parts
                and not f.name.endswith((".pyc", ".pyo"))
                and not f.is_relative_to(root / "tests" / "edition")
            ]
    return sorted(out)


def inputs_hash(root: Path = ROOT, python: str = sys.executable) -> str:
    """sha256 over the paths and bytes of :data:`INPUTS` and the target interpreter's version."""
    h = hashlib.sha256()
    for f in files(root, INPUTS):
        h.update(f.relative_to(root).as_posix().encode() + b"\0" + f.read_bytes() + b"\0")
    h.update(python_version(python).encode())
    return h.hexdigest()


def version_of(root: Path = ROOT) -> tuple[str, str]:
    """(``__version__``, ``DISTRIBUTION``) as ``wmr/_version.py`` writes them (read, not imported)."""
    tree = ast.parse((root / "wmr" / "_version.py").read_text(encoding="utf-8"))
    found: dict[str, str] = {}
    for node in tree.body:
        if isinstance(node, ast.Assign) and isinstance(node.value, ast.Constant):
            for t in node.targets:
                if isinstance(t, ast.Name) and isinstance(node.value.value, str):
                    found[t.id] = node.value.value
    return found["__version__"], found["DISTRIBUTION"]


def check(python: str, keep: bool) -> dict[str, str]:
    """Build, inspect, install into a fresh venv and check there; the facts for ``report.txt``."""
    version, dist = version_of()
    sdist, wheel = build(OUT / "dist")
    say(f"built {sdist.name} and {wheel.name}")
    inspect(sdist, wheel, version, dist)
    tmp = Path(tempfile.mkdtemp(prefix="wmr-release-"))
    if tmp.is_relative_to(ROOT):
        raise ReleaseError(f"the temporary folder {tmp} is inside the repository")
    try:
        env = clean_env(tmp)
        vdir = tmp / "venv"
        run([python, "-m", "venv", vdir], tmp, env, "python -m venv")
        vpy = vdir / "bin" / "python"
        house = wheelhouse(vpy, wheel, env, tmp)
        t0 = time.monotonic()
        run(
            [vpy, "-m", "pip", "install", "--quiet", "--no-index", "--find-links", house, f"{wheel}[{EXTRAS}]"],
            tmp,
            env,
            "pip install (offline)",
        )
        say(f"installed {wheel.name}[{EXTRAS}] into a fresh venv in {tmp} ({time.monotonic() - t0:.0f} s, offline)")
        with tarfile.open(sdist) as tar:
            tar.extractall(tmp, filter="data")
        src = tmp / sdist.name.removesuffix(".tar.gz")
        shutil.rmtree(src / "wmr")  # only the installed wheel can be imported
        facts = in_venv(vdir, src, env, version, dist)
        facts["python"] = python_version(str(vpy))
        facts["artefacts"] = f"{sdist.relative_to(ROOT)}, {wheel.relative_to(ROOT)}"
        return facts
    finally:
        if keep:
            say(f"kept {tmp}")
        else:
            shutil.rmtree(tmp, ignore_errors=True)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(
        description=(__doc__ or "").split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--force", action="store_true", help="check even when nothing changed since the last pass")
    ap.add_argument("--python", default=sys.executable, help="interpreter of the fresh venv (default: this one)")
    ap.add_argument("--keep", action="store_true", help="keep the temporary folder with the venv and the sdist")
    args = ap.parse_args(argv)
    python = shutil.which(args.python) or args.python
    digest = inputs_hash(ROOT, python)
    # this interpreter: build/release/stamp and report.txt; another one: stamp-<its version>, report-<its version>.txt
    suffix = "" if args.python == sys.executable else "-" + re.sub(r"\W+", "-", python_version(python).lower())
    stamp, report_file = OUT / f"stamp{suffix}", OUT / f"report{suffix}.txt"
    if not args.force and stamp.exists() and stamp.read_text(encoding="utf-8").strip() == digest:
        say(f"unchanged since the last pass ({digest[:12]}): nothing to do ({report_file.relative_to(ROOT)})")
        return 0
    t0 = time.monotonic()
    try:
        facts = check(python, args.keep)
    except (ReleaseError, subprocess.TimeoutExpired) as exc:
        print(f"[release] FAILED: {exc}", file=sys.stderr)
        stamp.unlink(missing_ok=True)
        return 1
    report = "\n\n".join(f"{k}:\n{v}" for k, v in facts.items()) + "\n"
    report_file.write_text(report, encoding="utf-8")
    print(report, end="")
    stamp.write_text(digest + "\n", encoding="utf-8")
    say(f"passed in {time.monotonic() - t0:.0f} s ({report_file.relative_to(ROOT)})")
    return 0
