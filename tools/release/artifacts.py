"""The release's artefacts: build the sdist and the wheel, and check what each holds."""

from __future__ import annotations

import ast
import email.parser
import re
import shutil
import subprocess
import sys
import tarfile
import zipfile
from collections.abc import Sequence
from pathlib import Path

from .common import ROOT, ReleaseError, say

__all__ = [
    "SDIST_FILES",
    "SDIST_FORBIDDEN",
    "REPO_ONLY_MODULES",
    "build",
    "check_sdist",
    "repo_only_imports",
    "check_wheel",
    "inspect",
]

#: in the sdist: the metadata files (besides wmr/, tests/*.py and examples/)
SDIST_FILES = (
    "PKG-INFO",
    "pyproject.toml",
    "MANIFEST.in",
    "README.md",
    "LICENSE",
    "CITATION.cff",
    "CHANGELOG.md",
    "wmr/py.typed",
    "wmr/_version.py",
    "tests/conftest.py",
    "tests/fuzz_api.py",
)

#: never in the sdist: the repository's own parts
SDIST_FORBIDDEN = (
    "edition/",
    "notebooks/",
    "tools/",
    "figures/",
    "docs/",
    "tests/edition/",
    "build/",
    ".venv/",
    ".ci/",
    "environment.lock",
    "Makefile",
)

#: what setuptools says on every build that is not a problem of the release
BENIGN = (
    r"no previously-included files matching '\*\.py\[cod\]' found"  # MANIFEST.in's global-exclude
    r"|byte-compiling is disabled"  # PYTHONDONTWRITEBYTECODE
    r"|^(copying|adding|creating) \S*/deprecated\.py\b|^adding '\S*/deprecated\.py'"  # a file list: wmr/deprecated.py
)

#: top-level names the shipped tests must not import
REPO_ONLY_MODULES = ("edition", "tools")


def build(outdir: Path) -> tuple[Path, Path]:
    """``python -m build --no-isolation``: the sdist, and the wheel built from it. Returns both paths."""
    shutil.rmtree(outdir, ignore_errors=True)
    outdir.mkdir(parents=True)
    log = outdir.parent / "build.log"
    with open(log, "w", encoding="utf-8") as fh:
        code = subprocess.run(
            [sys.executable, "-m", "build", "--no-isolation", "--outdir", str(outdir), str(ROOT)],
            cwd=ROOT,
            stdout=fh,
            stderr=subprocess.STDOUT,
            check=False,
        ).returncode
    text = log.read_text(encoding="utf-8", errors="replace")
    if code != 0:
        raise ReleaseError(f"python -m build failed (exit {code}); its log, {log}:\n{text[-3000:]}")
    warnings = [
        ln
        for ln in text.splitlines()
        if re.search(r"warning|deprecat", ln, re.IGNORECASE) and not re.search(BENIGN, ln)
    ]
    if warnings:
        raise ReleaseError("python -m build warned:\n  " + "\n  ".join(warnings[:20]))
    sdists, wheels = sorted(outdir.glob("*.tar.gz")), sorted(outdir.glob("*.whl"))
    if len(sdists) != 1 or len(wheels) != 1:
        raise ReleaseError(f"expected one sdist and one wheel in {outdir}, found {sdists + wheels}")
    return sdists[0], wheels[0]


def check_sdist(names: Sequence[str], tree: Path = ROOT) -> list[str]:
    """Problems of an sdist whose members (without the leading ``name-version/``) are ``names``.

    Every ``tests/*.py`` file and every file under ``examples/`` of ``tree`` must be in it, with
    :data:`SDIST_FILES`; nothing under :data:`SDIST_FORBIDDEN`.

    Examples
    --------
    >>> import tempfile; t = Path(tempfile.mkdtemp()); (t / "tests").mkdir(); (t / "examples").mkdir()
    >>> _ = (t / "tests" / "test_a.py").write_text("import wmr")
    >>> check_sdist([*SDIST_FILES, "tests/test_a.py", "edition/x.py"], t)
    ['not in the sdist: nothing under edition/ (found edition/x.py)']
    >>> check_sdist(SDIST_FILES, t)
    ['missing from the sdist: tests/test_a.py']
    """
    have = set(names)
    want = list(SDIST_FILES)
    want += [p.relative_to(tree).as_posix() for p in sorted((tree / "tests").glob("*.py"))]
    want += [p.relative_to(tree).as_posix() for p in sorted((tree / "examples").rglob("*")) if p.is_file()]
    problems = [f"missing from the sdist: {w}" for w in dict.fromkeys(want) if w not in have]
    compiled = sorted(n for n in have if n.endswith((".pyc", ".pyo")) or "__pycache__/" in n)
    if compiled:
        problems.append(f"compiled files in the sdist: {', '.join(compiled[:3])}")
    for bad in SDIST_FORBIDDEN:
        hits = sorted(n for n in have if n == bad or n.startswith(bad))
        if hits:
            problems.append(f"not in the sdist: nothing under {bad} (found {', '.join(hits[:3])})")
    return problems


def repo_only_imports(source: str) -> list[str]:
    """Top-level modules of :data:`REPO_ONLY_MODULES` that a test module's source imports.

    Examples
    --------
    >>> repo_only_imports("import wmr\\nfrom edition import verify\\ndef f():\\n    import tools.build")
    ['edition', 'tools']
    """
    found: set[str] = set()
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            mods = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            mods = [node.module]
        else:
            continue
        found |= {m.split(".")[0] for m in mods if m.split(".")[0] in REPO_ONLY_MODULES}
    return sorted(found)


def check_wheel(names: Sequence[str], metadata: str, entry_points: str, version: str, dist: str) -> list[str]:
    """Problems of a wheel: its members ``names``, its METADATA text and entry_points.txt."""
    problems: list[str] = []
    info = f"{dist.replace('-', '_')}-{version}.dist-info/"
    stray = sorted(n for n in names if not n.startswith(("wmr/", info)))
    if stray:
        problems.append(f"the wheel holds more than wmr/ and its metadata: {', '.join(stray[:5])}")
    for need in ("wmr/__init__.py", "wmr/py.typed", "wmr/_version.py", f"{info}licenses/LICENSE"):
        if need not in names:
            problems.append(f"missing from the wheel: {need}")
    meta = email.parser.Parser().parsestr(metadata)
    expect = {"Name": dist, "Version": version, "License-Expression": "MIT"}
    for key, value in expect.items():
        if meta.get(key) != value:
            problems.append(f"wheel METADATA {key}: {meta.get(key)!r}, expected {value!r}")
    if meta.get("License"):
        problems.append("wheel METADATA has the deprecated License field besides License-Expression")
    requires = {
        re.split(r"[ ;<>=!~\[]", r, maxsplit=1)[0].lower()
        for r in meta.get_all("Requires-Dist") or []
        if "extra ==" not in r
    }
    if requires != {"numpy", "sympy"}:
        problems.append(f"wheel METADATA Requires-Dist (not extras): {sorted(requires)}, expected numpy and sympy")
    if not re.search(r"^wmr\s*=\s*wmr\.cli:main\s*$", entry_points, re.MULTILINE):
        problems.append("the wheel declares no console script 'wmr = wmr.cli:main'")
    return problems


def inspect(sdist: Path, wheel: Path, version: str, dist: str) -> None:
    """Check the sdist and the wheel (:func:`check_sdist`, :func:`repo_only_imports`, :func:`check_wheel`)."""
    with tarfile.open(sdist) as tar:
        members = [m.name.split("/", 1)[1] for m in tar.getmembers() if "/" in m.name and m.isfile()]
        top = sdist.name.removesuffix(".tar.gz")
        shipped_tests = {n: tar.extractfile(f"{top}/{n}") for n in members if re.fullmatch(r"tests/[^/]+\.py", n)}
        sources = {n: f.read().decode() for n, f in shipped_tests.items() if f is not None}
    problems = check_sdist(members)
    for name, src in sorted(sources.items()):
        bad = repo_only_imports(src)
        if bad:
            problems.append(
                f"{name} (shipped in the sdist) imports {', '.join(bad)}: a test that needs the "
                f"repository belongs in tests/edition/"
            )
    with zipfile.ZipFile(wheel) as zf:
        names = zf.namelist()
        info = f"{dist.replace('-', '_')}-{version}.dist-info/"
        try:
            metadata = zf.read(info + "METADATA").decode()
            entry_points = zf.read(info + "entry_points.txt").decode()
        except KeyError as exc:
            raise ReleaseError(f"{wheel.name}: {exc}") from None
    problems += check_wheel(names, metadata, entry_points, version, dist)
    if problems:
        raise ReleaseError("the release artefacts are wrong:\n  " + "\n  ".join(problems))
    say(
        f"sdist: {len(members)} files, {len(sources)} of them tests/*.py; wheel: {len(names)} files; "
        f"metadata: {dist} {version}, License-Expression MIT"
    )
