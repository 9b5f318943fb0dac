"""Time ``nbgrader autograde`` of one student's full submission, chapter by chapter (issue 32: at most 15 s each).

Usage: ``python -m tools.bench.autograde [--repeat R] [CHAPTER...]`` (default: every lesson with exercises).

For each chapter, in a temporary nbgrader course: the source notebook (:func:`tools.assignments.main`),
``nbgrader generate_assignment``, then one student's submission -- the source notebook itself, every answer
filled in with the worked solution -- autograded ``R`` times (default 1; each run starts from a fresh copy of
the course, so nbgrader never finds an earlier grade).  The table gives the best wall-clock time of the
``nbgrader autograde --student student1`` call (what an instructor waits for, per student) and that run's CPU
time of nbgrader and its kernel together.  The load average is printed before and after: wall times are only
as quiet as the machine was.
"""

from __future__ import annotations

import argparse
import os
import platform
import resource
import shutil
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

BUDGET = 15.0  # seconds per student and chapter


def _load() -> str:
    try:
        return " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:  # pragma: no cover - not on Linux
        return "n/a"


def _children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def autograde_seconds(chapter: Path, root: Path) -> tuple[float, float] | None:
    """Wall and CPU seconds of autograding one full submission of ``chapter``; None without exercises."""
    from tools import assignments
    from tools.build import execute
    from tools.grades import run_nbgrader

    with tempfile.TemporaryDirectory(prefix=f"bench-autograde-{chapter.stem}-") as tmp:
        course = Path(tmp) / "course"
        if assignments.main(["--no-feedback", str(course), str(chapter)]) != 0:
            raise SystemExit(f"{chapter.name}: its exercise cells do not make an assignment")
        source = course / "source" / chapter.stem / chapter.name
        if not source.is_file():
            return None
        env = execute.kernel_env(root, course / "out")
        del env["WMR_OUT"]  # as an instructor runs it: the submission is not the build's, its notebook writes nothing
        run_nbgrader(course, env, "generate_assignment", chapter.stem)
        submitted = course / "submitted" / "student1" / chapter.stem
        submitted.mkdir(parents=True)
        shutil.copy(source, submitted / chapter.name)
        cpu0, t0 = _children_cpu(), time.perf_counter()
        run_nbgrader(course, env, "autograde", chapter.stem, "--student", "student1")
        return time.perf_counter() - t0, _children_cpu() - cpu0


def main(argv: list[str] | None = None) -> int:
    """Run the benchmark and print its table.

    Parameters
    ----------
    argv : list of str, optional

    Returns
    -------
    int
        0 when every chapter is within :data:`BUDGET` (wall time), 1 otherwise.
    """
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=1, help="autograde runs per chapter (the best is kept)")
    ap.add_argument("chapters", nargs="*", type=Path, help="notebooks (default: notebooks/[0-9][0-9]_*.ipynb)")
    args = ap.parse_args(argv)
    root = Path(__file__).resolve().parents[2]
    chapters = args.chapters or sorted((root / "notebooks").glob("[0-9][0-9]_*.ipynb"))
    import nbgrader  # type: ignore[import-untyped]

    print(
        f"Python {platform.python_version()}, nbgrader {nbgrader.__version__}, {os.cpu_count()} cores; "
        f"load average before: {_load()}"
    )
    print(f"{'chapter':28s} {'autograde s':>12s} {'cpu s':>7s}  within {BUDGET:g} s")
    worst = 0.0
    for chapter in chapters:
        runs = [autograde_seconds(Path(chapter).resolve(), root) for _ in range(max(1, args.repeat))]
        timed = [r for r in runs if r is not None]
        if not timed:
            print(f"{Path(chapter).stem:28s} {'(no exercises)':>12s}")
            continue
        wall, cpu = min(timed)
        worst = max(worst, wall)
        print(f"{Path(chapter).stem:28s} {wall:12.1f} {cpu:7.1f}  {'yes' if wall <= BUDGET else 'NO'}")
    print(f"load average after: {_load()}")
    return 0 if worst <= BUDGET else 1


if __name__ == "__main__":
    sys.exit(main())
