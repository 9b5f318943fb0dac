r"""``make course``: the student package, a wheel with no solution in it, checked in a fresh venv.

``python -m tools.course OUT`` (the Makefile: ``build/course``) writes ``OUT/wmr_course-<version>-py3-none-any.whl``:

* ``wmr_course/notebooks/``: every lesson as nbgrader releases it (:mod:`tools.assignments`, then
  ``nbgrader generate_assignment``): the worked solutions replaced by ``# YOUR CODE HERE``, the hidden tests
  removed, the questions in words left as ``YOUR ANSWER HERE`` without their rubric; a lesson without exercises,
  its cells as they are;
* ``edition/``: the checks the notebooks call, with ``edition/_derived/``, the derived objects a lesson wrote
  for a later one (the published ``figures/*.derived.json``, what :func:`edition.derivations.derived` reads);
* ``python -m wmr_course DIR`` copies the notebooks into ``DIR`` (never over an existing file).

The wheel is written byte for byte the same from the same tree (sorted members, fixed dates).  A pass is
recorded in ``OUT/stamp`` with :func:`key`; while it holds, nothing runs.  With ``--check``
(``make course`` passes it) a fresh venv outside the repository gets the ``wmr`` wheel (``python -m build``), the
course wheel and a Jupyter kernel, offline from the release's wheelhouse, and runs every notebook to the end
with its answers blank; ``OUT/check.json`` records what ran.  A solution found in the wheel fails the build.
"""

from __future__ import annotations

import argparse
import base64
import hashlib
import json
import re
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: the chapters a student works through (the report's findings chapter is not one)
LESSONS = tuple(sorted(p for p in (ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb")))
#: what the package and its check read (paths relative to the root, as git lists them): the stamp's key
READS = (
    "edition",
    "figures/*.derived.json",
    "notebooks",
    "wmr",
    "pyproject.toml",
    "environment.lock",
    "tools/course.py",
    "tools/assignments.py",
    "tools/grades.py",
)
#: what the course wheel needs besides ``wmr-kinematics`` (the notebooks' own imports)
REQUIRES = ("sympy", "matplotlib", "ipython", "ipywidgets", "nbformat", "pillow")
_DATE = (1980, 1, 1, 0, 0, 0)  # every member's timestamp: the wheel does not depend on when it was built


def _version() -> str:
    text = (ROOT / "wmr" / "_version.py").read_text(encoding="utf-8")
    return re.search(r"__version__\s*=\s*\"([^\"]+)\"", text).group(1)  # type: ignore[union-attr]


def solution_texts(lessons=LESSONS) -> list[str]:
    """Every worked solution and rubric of the lessons, whitespace collapsed: what the package must not hold."""
    import nbformat

    out = []
    for p in lessons:
        for c in nbformat.read(p, as_version=4).cells:
            if {"solution", "rubric"} & set(c.get("metadata", {}).get("tags", [])):
                out += [" ".join(line.split()) for line in c.source.splitlines() if len(line.split()) >= 4]
    return out


def leaks(members: dict[str, bytes], solutions: list[str]) -> list[str]:
    """``name: what`` for each member that holds solution text or nbgrader's solution and hidden-test markers.

    >>> leaks({"a.py": b"x = 1  # YOUR CODE HERE"}, ["x = 2.0 + y  # worked"])
    []
    >>> leaks({"a.py": b"### BEGIN SOLUTION"}, [])
    ['a.py: ### BEGIN SOLUTION']
    """
    found = []
    for name, data in members.items():
        raw = data.decode("utf-8", errors="replace")
        if name.endswith(".ipynb"):  # the cells' text, not its JSON escapes
            raw = "\n".join("".join(c["source"]) for c in json.loads(raw)["cells"])
        text = " ".join(raw.split())
        for marker in ("### BEGIN SOLUTION", "### BEGIN HIDDEN TESTS", "Model answer", "Rubric ("):
            if marker in text:
                found.append(f"{name}: {marker}")
        found += [f"{name}: {s[:60]!r}" for s in solutions if s in text]
    return found


def released(out: Path) -> dict[str, bytes]:
    """The lessons as nbgrader releases them (``name.ipynb`` -> bytes), in a temporary nbgrader course."""
    from tools import assignments as A
    from tools.build import execute as X
    from tools.grades import run_nbgrader

    notebooks: dict[str, bytes] = {}
    with tempfile.TemporaryDirectory(prefix="course-") as tmp:
        course = Path(tmp)
        if A.main(["--no-feedback", str(course), *map(str, LESSONS)]) != 0:
            raise SystemExit("the lessons' exercise cells do not make assignments")
        env = X.kernel_env(ROOT, course / "out")
        for p in LESSONS:
            if (course / "source" / p.stem / p.name).is_file():
                run_nbgrader(course, env, "generate_assignment", p.stem)
                notebooks[p.name] = (course / "release" / p.stem / p.name).read_bytes()
            else:  # no exercise to release: the lesson as it is, outputs cleared
                notebooks[p.name] = _cleared(p)
    return notebooks


def _cleared(path: Path) -> bytes:
    import nbformat

    nb = nbformat.read(path, as_version=4)
    for c in nb.cells:
        if c.cell_type == "code":
            c.outputs, c.execution_count = [], None
    return (nbformat.writes(nb) + "\n").encode("utf-8")


MAIN = '''"""``python -m wmr_course DIR``: copy the course's notebooks into DIR (an existing file is never overwritten)."""

import shutil
import sys
from importlib.resources import files
from pathlib import Path


def main(argv=None):
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: python -m wmr_course DIR", file=sys.stderr)
        return 2
    out = Path(args[0])
    out.mkdir(parents=True, exist_ok=True)
    for nb in sorted(files("wmr_course").joinpath("notebooks").iterdir(), key=lambda p: p.name):
        target = out / nb.name
        if target.exists():
            print(f"kept {target} (it exists)")
            continue
        with nb.open("rb") as src, open(target, "wb") as dst:
            shutil.copyfileobj(src, dst)
        print(f"wrote {target}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
'''


def members(version: str) -> dict[str, bytes]:
    """The wheel's files (name -> bytes), its metadata included."""
    files: dict[str, bytes] = {}
    for p in sorted((ROOT / "edition").rglob("*")):
        if p.is_file() and "__pycache__" not in p.parts and p.suffix in (".py", ".toml"):
            files[p.relative_to(ROOT).as_posix()] = p.read_bytes()
    for p in sorted((ROOT / "figures").glob("*.derived.json")):
        files[f"edition/_derived/{p.name}"] = p.read_bytes()
    for name, data in released(ROOT).items():
        files[f"wmr_course/notebooks/{name}"] = data
    files["wmr_course/__init__.py"] = b'"""The lessons of wmr-kinematics as a course: `python -m wmr_course DIR`."""\n'
    files["wmr_course/__main__.py"] = MAIN.encode("utf-8")
    info = f"wmr_course-{version}.dist-info"
    requires = "".join(f"Requires-Dist: {r}\n" for r in (f"wmr-kinematics[sim]=={version}", *REQUIRES))
    files[f"{info}/METADATA"] = (
        f"Metadata-Version: 2.1\nName: wmr-course\nVersion: {version}\n"
        "Summary: The lessons of wmr-kinematics, released for students (no solutions)\n"
        f"License-Expression: MIT\nRequires-Python: >=3.11\n{requires}"
    ).encode("utf-8")
    files[f"{info}/WHEEL"] = b"Wheel-Version: 1.0\nGenerator: tools.course\nRoot-Is-Purelib: true\nTag: py3-none-any\n"
    files[f"{info}/top_level.txt"] = b"edition\nwmr_course\n"
    record = [
        f"{n},sha256={base64.urlsafe_b64encode(hashlib.sha256(d).digest()).rstrip(b'=').decode()},{len(d)}"
        for n, d in sorted(files.items())
    ]
    files[f"{info}/RECORD"] = ("\n".join([*record, f"{info}/RECORD,,"]) + "\n").encode("utf-8")
    return files


def write_wheel(path: Path, files: dict[str, bytes]) -> None:
    """Write ``files`` as a zip with sorted members and fixed dates, atomically."""
    tmp = path.with_suffix(".tmp")
    with zipfile.ZipFile(tmp, "w", compression=zipfile.ZIP_DEFLATED) as zf:
        for name in sorted(files):
            zi = zipfile.ZipInfo(name, date_time=_DATE)
            zi.external_attr = 0o644 << 16
            zi.compress_type = zipfile.ZIP_DEFLATED
            zf.writestr(zi, files[name])
    tmp.replace(path)


def check(wheel: Path, out: Path) -> dict:
    """Install ``wheel`` with the ``wmr`` wheel into a fresh venv and run every notebook with its answers blank."""
    from tools.release.artifacts import build
    from tools.release.venv import clean_env, wheelhouse

    with tempfile.TemporaryDirectory(prefix="course-venv-") as tmp:
        t = Path(tmp)
        env = clean_env(t)
        _, wmr_wheel = build(t / "dist")
        subprocess.run([sys.executable, "-m", "venv", str(t / "venv")], check=True)
        vpy = t / "venv" / "bin" / "python"
        house = wheelhouse(vpy, wmr_wheel, env, t)
        extra = t / "kernel"
        pins = (ROOT / "environment.lock").read_text(encoding="utf-8")
        from tools.release.venv import constraints

        (t / "constraints.txt").write_text(constraints(pins), encoding="utf-8")
        need = ["ipykernel", "nbclient", *REQUIRES]
        subprocess.run(
            [vpy, "-m", "pip", "download", "-q", "-d", str(extra), "-c", str(t / "constraints.txt"), *need],
            env=env,
            check=True,
        )
        subprocess.run(
            [
                vpy,
                "-m",
                "pip",
                "install",
                "-q",
                "--no-index",
                "--find-links",
                str(house),
                "--find-links",
                str(extra),
                f"{wmr_wheel}[sim]",
                str(wheel),
                "ipykernel",
                "nbclient",
            ],
            env=env,
            check=True,
        )
        work = t / "student"
        subprocess.run([vpy, "-m", "wmr_course", str(work)], cwd=t, env=env, check=True, capture_output=True)
        runner = (
            "import sys, nbformat, nbclient\n"
            "nb = nbformat.read(sys.argv[1], as_version=4)\n"
            "nbclient.NotebookClient(nb, timeout=600, kernel_name='python3',"
            " resources={'metadata': {'path': sys.argv[2]}}).execute()\n"
            "blank = sum('No answer yet' in str(o) for c in nb.cells if c.cell_type == 'code' for o in c.outputs)\n"
            "print(blank)\n"
        )
        ran = {}
        for nb in sorted(work.glob("*.ipynb")):
            p = subprocess.run(
                [vpy, "-c", runner, str(nb), str(work)], cwd=work, env=env, capture_output=True, text=True, check=False
            )
            ran[nb.name] = (
                {"runs_to_the_end": True, "unanswered_shown": int(p.stdout.split()[-1])}
                if p.returncode == 0
                else {"runs_to_the_end": False, "error": (p.stderr.strip().splitlines() or ["?"])[-1]}
            )
    return {"wheel": wheel.name, "notebooks": ran}


def key(root: Path = ROOT) -> str:
    """sha256 of every file git tracks under :data:`READS` (path and bytes): a new key rebuilds the course."""
    names = subprocess.run(["git", "ls-files", "-z", *READS], cwd=root, capture_output=True, check=True).stdout.split(
        b"\0"
    )
    h = hashlib.sha256()
    for name in sorted(n for n in names if n):
        p = root / name.decode()
        if p.is_file():
            h.update(name + b"\0" + hashlib.sha256(p.read_bytes()).digest())
    return h.hexdigest()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m tools.course", description=__doc__.split("\n\n")[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("--check", action="store_true", help="install it in a fresh venv and run every notebook")
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)
    stamp, k = a.out / "stamp", key() + (":checked" if a.check else "")
    if stamp.is_file() and stamp.read_text(encoding="utf-8").strip() == k:
        return 0  # nothing it reads has changed since it passed
    stamp.unlink(missing_ok=True)
    version = _version()
    files = members(version)
    found = leaks(files, solution_texts())
    if found:
        print("[course] solutions in the student package:\n  " + "\n  ".join(found[:20]), file=sys.stderr)
        return 1
    wheel = a.out / f"wmr_course-{version}-py3-none-any.whl"
    write_wheel(wheel, files)
    print(f"[course] {wheel} ({len(files)} files, no solution)")
    if a.check:
        result = check(wheel, a.out)
        (a.out / "check.json").write_text(json.dumps(result, indent=1) + "\n", encoding="utf-8")
        bad = {n: v for n, v in result["notebooks"].items() if not v["runs_to_the_end"]}
        print(
            f"[course] fresh venv: {len(result['notebooks']) - len(bad)} of {len(result['notebooks'])} notebooks "
            "run to the end with blank answers" + (f"; failed: {bad}" if bad else "")
        )
        if bad:
            return 1
    stamp.write_text(k + "\n", encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
