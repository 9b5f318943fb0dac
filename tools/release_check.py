"""The release installs and tests itself: build the sdist and the wheel, install the wheel into a fresh
virtual environment outside the repository, and run the library's tests and the command line there.

    python -m tools.release_check            # what `make release` (and so `make test`) runs
    python -m tools.release_check --force    # even when nothing changed since the last pass
    python -m tools.release_check --python python3.13 --keep

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
import email.parser
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time
import zipfile
from collections.abc import Iterable, Sequence
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "build" / "release"
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
    "tools/release_check.py",
)
#: extras installed in the fresh venv: the library's tests, and what they test beyond numpy and sympy (Dask
#: sweeps, wmr.sim in MuJoCo, the URDF, ROS 2 and WPILib bridges), so that none of them is skipped
EXTRAS = "test,dask,sim,urdf,ros,wpilib"
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
    r"|byte-compiling is disabled"
)  # PYTHONDONTWRITEBYTECODE
#: top-level names the shipped tests must not import
REPO_ONLY_MODULES = ("edition", "tools")


class ReleaseError(RuntimeError):
    """The release is not what it should be; the message says what."""


def say(msg: str) -> None:
    print(f"[release] {msg}", flush=True)


# ---------------------------------------------------------------------------------------- inputs
def _files(root: Path, names: Iterable[str]) -> list[Path]:
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
    for f in _files(root, INPUTS):
        h.update(f.relative_to(root).as_posix().encode() + b"\0" + f.read_bytes() + b"\0")
    h.update(_python_version(python).encode())
    return h.hexdigest()


def _python_version(python: str) -> str:
    code = "import sys, platform; print(platform.python_implementation(), sys.version.split()[0], platform.machine())"
    out = subprocess.run([python, "-c", code], capture_output=True, text=True, check=True)
    return out.stdout.strip()


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


# ---------------------------------------------------------------------------------- the artefacts
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


# ------------------------------------------------------------------------------- the fresh venv
def constraints(lock: str) -> str:
    """The pins of ``environment.lock`` (``name==version ; marker``) without hashes, for ``pip -c``.

    Examples
    --------
    >>> lock = ("numpy==2.4.6 \\\\\\n    --hash=sha256:ab \\\\\\n    # via x\\n"
    ...         "sphinx==9 ; python_version < '3.12' \\\\\\n")
    >>> print(constraints(lock), end="")
    numpy==2.4.6
    sphinx==9 ; python_version < '3.12'
    """
    pins = []
    for line in lock.splitlines():
        line = line.strip().removesuffix("\\").strip()
        if line and not line.startswith(("#", "--")) and "==" in line:
            pins.append(line)
    return "\n".join(pins) + "\n"


def _run(cmd: Sequence[str | Path], cwd: Path, env: dict[str, str], what: str, timeout: float = 1800) -> str:
    proc = subprocess.run(
        [str(c) for c in cmd], cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout, check=False
    )
    if proc.returncode != 0:
        raise ReleaseError(
            f"{what} failed (exit {proc.returncode}): {' '.join(map(str, cmd))}\n{(proc.stdout + proc.stderr)[-4000:]}"
        )
    return proc.stdout


def clean_env(tmp: Path) -> dict[str, str]:
    """The environment of the fresh venv's processes: nothing that points back into the repository."""
    env = {
        k: v
        for k, v in os.environ.items()
        if not k.startswith(("PYTHON", "VIRTUAL_ENV", "WMR_", "PIP_REQUIRE", "CONDA"))
    }
    env.update(
        HOME=env.get("HOME", str(tmp)),
        PYTHONNOUSERSITE="1",
        MPLBACKEND="Agg",
        PYTHONDONTWRITEBYTECODE="1",
        PIP_DISABLE_PIP_VERSION_CHECK="1",
    )
    return env


def wheelhouse(vpy: Path, wheel: Path, env: dict[str, str], cwd: Path) -> Path:
    """The folder of wheels the fresh venv installs from offline; filled once per key."""
    lock = (ROOT / "environment.lock").read_text(encoding="utf-8")
    with zipfile.ZipFile(wheel) as zf:
        meta = next(zf.read(n) for n in zf.namelist() if n.endswith(".dist-info/METADATA"))
    reqs = "\n".join(sorted(ln for ln in meta.decode().splitlines() if ln.startswith("Requires-Dist")))
    key = hashlib.sha256("\0".join([lock, reqs, EXTRAS, _python_version(str(vpy))]).encode()).hexdigest()[:16]
    house = OUT / "wheelhouse" / key
    if (house / ".complete").exists():
        return house
    say(f"wheelhouse {house.relative_to(ROOT)}: downloading the pinned dependencies once")
    tmp = house.with_name(house.name + f".tmp{os.getpid()}")
    shutil.rmtree(tmp, ignore_errors=True)
    tmp.mkdir(parents=True)
    (tmp / "constraints.txt").write_text(constraints(lock), encoding="utf-8")
    _run(
        [
            vpy,
            "-m",
            "pip",
            "download",
            "--quiet",
            "--only-binary=:all:",
            "--dest",
            tmp,
            "--constraint",
            tmp / "constraints.txt",
            f"{wheel}[{EXTRAS}]",
        ],
        cwd,
        env,
        "pip download",
    )
    (tmp / wheel.name).unlink(missing_ok=True)  # the wheel itself comes from build/release
    (tmp / ".complete").write_text("", encoding="utf-8")
    shutil.rmtree(house, ignore_errors=True)
    os.replace(tmp, house)
    return house


def python_blocks(markdown: str) -> list[str]:
    """The fenced ```python blocks of a Markdown text, in order.

    Examples
    --------
    >>> python_blocks("a\\n```python\\nx = 1\\n```\\n```console\\n$ wmr\\n```\\n```python\\nprint(x)\\n```\\n")
    ['x = 1\\n', 'print(x)\\n']
    """
    return [m.group(1) for m in re.finditer(r"^```python\n(.*?)^```\s*$", markdown, flags=re.MULTILINE | re.DOTALL)]


def missing_modules(pytest_output: str) -> list[str]:
    """The skip reasons of a ``pytest -rs`` run that say a module could not be imported.

    Examples
    --------
    >>> missing_modules("SKIPPED [1] tests/test_a.py:3: could not import 'yaml': No module named 'yaml'\\n"
    ...                 "SKIPPED [2] tests/test_b.py:9: chromium not installed\\n")
    ["tests/test_a.py:3: could not import 'yaml'"]
    """
    return [
        m.group(1)
        for m in re.finditer(r"^SKIPPED \[\d+\] (\S+: could not import '[^']+')", pytest_output, re.MULTILINE)
    ]


def in_venv(vdir: Path, src: Path, env: dict[str, str], version: str, dist: str) -> dict[str, str]:
    """Check the installed wheel from the unpacked sdist ``src`` (its ``wmr/`` removed); return facts."""
    vpy, wmr_cmd = vdir / "bin" / "python", vdir / "bin" / "wmr"
    facts: dict[str, str] = {}
    _run([vpy, "-m", "pip", "check"], src, env, "pip check")
    facts["pip show"] = _run([vpy, "-m", "pip", "show", dist], src, env, "pip show").strip()
    probe = (
        "import wmr, importlib.metadata as m, sysconfig; "
        f"print(wmr.__file__); print(m.version({dist!r})); print(sysconfig.get_path('purelib'))"
    )
    where = _run([vpy, "-P", "-c", probe], src, env, "import wmr").split("\n")
    if not Path(where[0]).is_relative_to(Path(where[2])):
        raise ReleaseError(f"import wmr found {where[0]}, not the installed wheel in {where[2]}")
    if where[1] != version:
        raise ReleaseError(f"installed metadata says {dist} {where[1]}, wmr/_version.py says {version}")
    out = _run([wmr_cmd, "--version"], src, env, "wmr --version").strip()
    if not out.startswith(f"wmr {version} ({dist}, {Path(where[0]).parent}"):
        raise ReleaseError(f"wmr --version printed {out!r}")
    facts["wmr --version"] = out
    # the README's examples, in one namespace, as a user would paste them
    code = "\n".join(python_blocks((src / "README.md").read_text(encoding="utf-8")))
    if not code:
        raise ReleaseError("the README has no ```python example")
    facts["README example"] = _run([vpy, "-P", "-c", code], src, env, "the README's Python examples").strip()
    # the command line on the shipped example robots
    analyzed = json.loads(_run([wmr_cmd, "analyze", "examples/swerve4.toml", "--json"], src, env, "wmr analyze"))
    if (analyzed["delta_m"], analyzed["delta_s"]) != (1, 2):
        raise ReleaseError(
            f"wmr analyze examples/swerve4.toml: class ({analyzed['delta_m']},{analyzed['delta_s']}), "
            "expected (1,2) (tests/test_cli_robot.py has the same robot)"
        )
    _run(
        [wmr_cmd, "ik", "examples/swerve4.toml", "--vx", "1", "--vy", "0.5", "--omega", "0.8", "--json"],
        src,
        env,
        "wmr ik",
    )
    _run(
        [wmr_cmd, "fk", "examples/paper_centred.toml", "--angles", "0", "0", "0", "--rates", "1", "1", "1", "--json"],
        src,
        env,
        "wmr fk",
    )
    _run([wmr_cmd, "sweep", "examples/paper_centred.toml", "kappa_J", "--grid", "12", "--json"], src, env, "wmr sweep")
    bad = subprocess.run(
        [str(wmr_cmd), "analyze", "no-such-robot.toml"], cwd=src, env=env, capture_output=True, text=True, check=False
    )
    if bad.returncode != 2 or len(bad.stderr.strip().splitlines()) != 1 or "no-such-robot.toml" not in bad.stderr:
        raise ReleaseError(
            f"wmr analyze on a missing file: exit {bad.returncode}, stderr {bad.stderr!r} "
            "(expected exit 2 and one line naming the file)"
        )
    ros2 = _run([wmr_cmd, "convert", "examples/urdf/diffbot.urdf", "--to", "ros2"], src, env, "wmr convert")
    if "diff_drive_controller" not in ros2:
        raise ReleaseError(f"wmr convert examples/urdf/diffbot.urdf --to ros2: no diff_drive_controller in\n{ros2}")
    facts["wmr commands"] = (
        "analyze, ik, fk, sweep, convert (URDF -> ROS 2) on examples/; a missing file: exit 2, one line"
    )
    # the library's tests, as shipped
    log = vdir.parent / "pytest.log"
    t0 = time.monotonic()
    with open(log, "w", encoding="utf-8") as fh:
        proc = subprocess.run(
            [str(vpy), "-P", "-m", "pytest", "-q", "-rs", "-p", "no:cacheprovider", "tests"],
            cwd=src,
            env=env,
            stdout=fh,
            stderr=subprocess.STDOUT,
            check=False,
        )
    text = log.read_text(encoding="utf-8", errors="replace")
    summary = next((ln.strip("= ") for ln in reversed(text.splitlines()) if re.search(r"\d+ (passed|failed)", ln)), "")
    if proc.returncode != 0 or "passed" not in summary:
        raise ReleaseError(f"the library's tests failed in the fresh venv (exit {proc.returncode}):\n{text[-6000:]}")
    unimported = missing_modules(text)
    if unimported:
        raise ReleaseError(
            "library tests were skipped in the fresh venv for want of a module (an extra missing "
            f"from EXTRAS, or from pyproject's extras): {'; '.join(unimported)}"
        )
    facts["library tests"] = f"{summary} ({time.monotonic() - t0:.0f} s)"
    return facts


def check(python: str, keep: bool) -> dict[str, str]:
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
        _run([python, "-m", "venv", vdir], tmp, env, "python -m venv")
        vpy = vdir / "bin" / "python"
        house = wheelhouse(vpy, wheel, env, tmp)
        t0 = time.monotonic()
        _run(
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
        facts["python"] = _python_version(str(vpy))
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
    suffix = "" if args.python == sys.executable else "-" + re.sub(r"\W+", "-", _python_version(python).lower())
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


if __name__ == "__main__":
    sys.exit(main())
