r"""The nbgrader round trip of one chapter, cached like an executed notebook: ``build/assignments/grades/<chapter>.json``.

``python -m tools.grades CHAPTER OUT`` (the Makefile runs one per lesson, two at a time, and
``make test`` runs them before pytest): in a temporary nbgrader course, the chapter's source notebook
(:func:`tools.assignments.assignment`), ``nbgrader generate_assignment``, then ``nbgrader autograde`` of two
submissions: ``solved`` (the source notebook, worked solutions in place) and ``blank`` (the released notebook, the
solutions replaced by ``# YOUR CODE HERE``).  ``OUT`` records, per exercise (nbgrader's graded cell), the points
it is worth and the score of each submission, as nbgrader's gradebook holds them::

    {"chapter": "04_isotropy", "exercises": [{"grade_id": "04_isotropy-check_4_1", "check": "check_4_1",
     "max": 2.0, "solved": 2.0, "blank": 0.0}, ...], "total": {"max": ..., "solved": ..., "blank": ...}}

``written`` lists the questions answered in words (manually graded Markdown cells): the solved submission (the
model answer) waits for a grader, the blank one (``YOUR ANSWER HERE`` untouched) is scored 0 by nbgrader itself.
``total`` is nbgrader's own score of each submission (not a sum taken here): its maximum counts the written
questions, its score only what nbgrader could grade.  A chapter without gradable
exercises gets ``"exercises": []`` and no ``total`` (nbgrader is not started).
``tests/edition/test_assignments.py`` reads these files and asserts full marks for the solved submission and
zero for the blank one, exercise by exercise.

The cache is the build's (:mod:`tools.build.execute`): :func:`key` is :func:`tools.build.execute.key` of the
chapter with, as what it reads, the published ``figures/*.derived.json`` (a chapter reads what earlier ones derived,
:func:`edition.derivations.derived`), this file, ``tools/assignments.py`` and ``environment.lock`` (nbgrader's
version); ``OUT.stamp`` records the key and the hash of ``OUT``.  While both hold nothing runs and nothing is
written.
"""

from __future__ import annotations

import argparse
import json
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from tools.build import BuildError, say
from tools.build import execute as X

__all__ = ["READS", "grade", "key", "main", "run_nbgrader"]

#: what the round trip reads besides the chapter, ``wmr/``, ``edition/`` and the derived objects the chapters
#: published (``figures/*.derived.json``), relative to the project's root
READS = ("tools/grades.py", "tools/assignments.py", "environment.lock")
TIMEOUT = 1800  # seconds per nbgrader call


def key(chapter: Path, root: Path = X.ROOT) -> str:
    """The cache key of a chapter's grades: :func:`tools.build.execute.key` with :data:`READS` of ``root`` and its
    ``figures/*.derived.json``."""
    root = Path(root).resolve()
    derived = sorted((root / "figures").glob("*.derived.json"))
    return X.key(Path(chapter).resolve(), root, (*(root / r for r in READS), *derived))


def run_nbgrader(course: Path, env: dict[str, str], *args: str) -> None:
    """Run ``nbgrader ARGS`` in ``course``; when this step is stopped, nbgrader gets SIGTERM (it stops its kernel)."""
    cmd = [sys.executable, "-m", "nbgrader", *args, "--log-level=WARN"]
    with subprocess.Popen(cmd, cwd=course, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True) as p:
        try:
            log = p.communicate(timeout=TIMEOUT)[0]
        except BaseException:
            p.terminate()
            try:
                p.wait(10)
            except subprocess.TimeoutExpired:
                p.kill()
            raise
    if p.returncode != 0:
        raise BuildError(f"nbgrader {' '.join(args)} failed (exit status {p.returncode}):\n{log[-6000:]}")


def _round_trip(chapter: Path, course: Path, root: Path) -> dict:
    """Generate, submit (solved and blank) and autograde ``chapter`` in the course folder ``course``."""
    import contextlib
    import io

    from tools import assignments as A

    name, log = chapter.stem, io.StringIO()
    with contextlib.redirect_stdout(log), contextlib.redirect_stderr(log):
        if A.main(["--no-feedback", str(course), str(chapter)]) != 0:
            raise BuildError(f"{chapter.name}: its exercise cells do not make an assignment:\n{log.getvalue()}")
    if not (course / "source" / name / chapter.name).is_file():
        return {"chapter": name, "exercises": []}
    env = X.kernel_env(root, course / "out")
    run_nbgrader(course, env, "generate_assignment", name)
    released = _run_all(course / "release" / name / chapter.name, env)
    for student, src in (("solved", course / "source"), ("blank", course / "release")):
        (course / "submitted" / student / name).mkdir(parents=True)
        shutil.copy(src / name / chapter.name, course / "submitted" / student / name / chapter.name)
    run_nbgrader(course, env, "autograde", name)
    from nbgrader.api import Gradebook  # type: ignore[import-untyped]

    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        scores: dict[str, dict[str, tuple[float, float]]] = {}
        manual: dict[str, dict[str, tuple[float | None, float, bool]]] = {}
        total: dict[str, float] = {}
        for student in ("solved", "blank"):
            sub = gb.find_submission(name, student)
            (nb,) = sub.notebooks
            auto = [g for g in nb.grades if g.max_score and g.cell_type == "code"]
            scores[student] = {g.name: (g.score, g.max_score) for g in auto}
            manual[student] = {
                g.name: (g.score, g.max_score, bool(g.needs_manual_grade))
                for g in nb.grades
                if g.max_score and g.cell_type == "markdown"
            }
            total |= {"max": sub.max_score, student: sub.score}
    order = {f"{name}-{c}": i for i, c in enumerate(_checks(chapter))}  # the chapter's order
    exercises = [
        {
            "grade_id": gid,
            "check": gid.removeprefix(f"{name}-"),
            "max": m,
            "solved": s,
            "blank": scores["blank"].get(gid, (None, None))[0],
        }
        for gid, (s, m) in sorted(scores["solved"].items(), key=lambda kv: order.get(kv[0], len(order)))
    ]
    written = [
        {
            "grade_id": gid,
            "max": m,
            "solved_needs_manual_grade": needs,
            "blank": manual["blank"][gid][0],
            "blank_needs_manual_grade": manual["blank"][gid][2],
        }
        for gid, (_, m, needs) in manual["solved"].items()
    ]
    return {
        "chapter": name,
        "exercises": exercises,
        "written": written,
        "total": total,
        "released_runs_to_the_end": released,
    }


def _run_all(notebook: Path, env: dict[str, str]) -> bool | str:
    """Run All on a released notebook, as a student would before answering: True when every cell runs, else the
    error of the first cell that raises (its last line)."""
    with tempfile.TemporaryDirectory(prefix="run-all-") as tmp:
        cmd = [
            sys.executable,
            "-m",
            "jupyter",
            "nbconvert",
            "--to",
            "notebook",
            "--execute",
            str(notebook),
            "--output-dir",
            tmp,
            "--ExecutePreprocessor.timeout=600",
            "--log-level=ERROR",
        ]
        p = subprocess.run(cmd, cwd=notebook.parent, env=env, capture_output=True, text=True, timeout=TIMEOUT)
    if p.returncode == 0:
        return True
    lines = [line for line in p.stderr.splitlines() if line.strip()]
    return lines[-1] if lines else f"exit status {p.returncode}"


def grade(chapter: Path, out: Path, root: Path = X.ROOT) -> bool:
    """Write the grades of ``chapter`` to ``out`` unless its stamp is current; True when nbgrader ran.

    Raises
    ------
    BuildError
        nbgrader failed (its output's tail) or the chapter's exercise cells break the convention;
        ``out`` and its stamp are left removed.
    """
    chapter, out = Path(chapter).resolve(), Path(out).resolve()
    k = key(chapter, root)
    if X.up_to_date(out.with_suffix(".stamp"), k, out):
        return False
    from edition.files import atomic_write

    for p in (out, out.with_suffix(".stamp")):
        p.unlink(missing_ok=True)
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix=f"grades-{chapter.stem}-") as tmp:
        grades = _round_trip(chapter, Path(tmp) / "course", Path(root))
    atomic_write(out, json.dumps(grades, indent=1) + "\n")
    X.write_stamp(out, k)
    say("grades", f"{chapter.name}: {len(grades['exercises'])} exercises graded", t0)
    return True


def _checks(chapter: Path) -> list[str]:
    """The names of the checks the chapter's cells tagged ``check`` call, in order."""
    import nbformat

    from tools.assignments import check_call

    cells = nbformat.read(chapter, as_version=4).cells
    return [check_call(c.source, chapter.name) for c in cells if "check" in c.get("metadata", {}).get("tags", [])]


def _stop(signum, frame):
    raise KeyboardInterrupt(signum)


def main(argv: list[str] | None = None) -> int:
    """``python -m tools.grades CHAPTER OUT``; exit status 0, 1 with ``BUILD FAILED`` and the reason, 128 + N
    when stopped by signal N (the temporary course and nbgrader's processes go)."""
    ap = argparse.ArgumentParser(prog="python -m tools.grades", description=__doc__.split("\n\n")[0])
    ap.add_argument("chapter", type=Path)
    ap.add_argument("out", type=Path)
    a = ap.parse_args(argv)
    sys.modules.setdefault("rfc3987_syntax", None)  # type: ignore[arg-type]  # jsonschema's IRI grammar: unused
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, _stop)
    try:
        grade(a.chapter, a.out)
        return 0
    except BuildError as e:
        print(f"\nBUILD FAILED\n{e}", file=sys.stderr, flush=True)
        return 1
    except KeyboardInterrupt as e:
        signum = e.args[0] if e.args and isinstance(e.args[0], int) else signal.SIGINT
        print(f"\n[grades] {a.chapter.name} stopped by signal {signum}", file=sys.stderr, flush=True)
        return 128 + signum


if __name__ == "__main__":
    sys.exit(main())
