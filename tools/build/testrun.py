"""The test suite, as ``make test`` runs it: two pytest processes side by side.

The machine has two cores and the suite is mostly serial (notebook kernels, xelatex, a browser,
SymPy), so the test files are split into two partitions of about equal duration (durations of the
last run, from pytest's JUnit report, in ``build/test-runs/times.json``) and run at once. The tests that
build this tree's own report (``REAL_TREE``) stay in one partition, so that they run one after the
other as written. The first partition prints as it runs, the second when it ends; the exit status
is the worse of the two. With explicit test paths or ``-k``/``-x``-style selections, one plain
pytest run is made instead.
"""
from __future__ import annotations

import json
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

from . import procs
from .files import atomic_write
from .log import say
from .paths import Tree

__all__ = ["run_tests", "partition", "REAL_TREE"]

#: test modules that execute this tree's notebooks or build its report (one partition)
REAL_TREE = ("test_notebooks.py", "test_report.py")


def partition(files: list[Path], times: dict[str, float], jobs: int) -> list[list[Path]]:
    """Files into ``jobs`` bins of about equal total time, longest first; ``REAL_TREE`` together.

    Examples
    --------
    >>> fs = [Path(f"tests/test_{c}.py") for c in "abcd"]
    >>> [[p.stem for p in b] for b in partition(fs, {"test_a.py": 5, "test_b.py": 3, "test_c.py": 2}, 2)]
    [['test_a', 'test_d'], ['test_b', 'test_c']]
    """
    units: list[list[Path]] = [[f for f in files if f.name in REAL_TREE]]
    units = [u for u in units if u] + [[f] for f in files if f.name not in REAL_TREE]
    cost = lambda u: sum(times.get(f.name, 1.0) for f in u)
    bins: list[list[Path]] = [[] for _ in range(jobs)]
    load = [0.0] * jobs
    for u in sorted(units, key=lambda u: (-cost(u), u[0].name)):
        k = load.index(min(load))
        bins[k] += u
        load[k] += cost(u)
    return [sorted(b) for b in bins if b]


def _times(t: Tree) -> dict[str, float]:
    try:
        data = json.loads((t.test_runs / "times.json").read_text(encoding="utf-8"))
        return {k: float(v) for k, v in data.items()}
    except (OSError, ValueError, AttributeError):
        return {}


def _record(t: Tree, reports: list[Path]) -> None:
    """Per-file durations from the JUnit reports, for the next split."""
    times = _times(t)
    for rep in reports:
        try:
            root = ET.parse(rep).getroot()
        except (OSError, ET.ParseError):
            continue
        per: dict[str, float] = {}
        for case in root.iter("testcase"):
            name = (case.get("classname") or "").split(".")[-1] + ".py"
            per[name] = per.get(name, 0.0) + float(case.get("time") or 0)
        times.update(per)
    atomic_write(t.test_runs / "times.json", json.dumps(times, indent=1, sort_keys=True) + "\n")


def run_tests(t: Tree, args: list[str], jobs: int = 2) -> int:
    """Run pytest over ``tests/`` in ``jobs`` partitions at once; return the worse exit status."""
    files = sorted((t.root / "tests").rglob("test_*.py"))        # tests/ (library) and tests/edition/
    selective = any(not a.startswith("-") for a in args) or any(a in ("-k", "-x", "--lf", "--sw") for a in args)
    if jobs < 2 or selective or len(files) < 2:
        return procs.call([sys.executable, "-m", "pytest", *args], cwd=t.root, env=t.env())
    bins = partition(files, _times(t), jobs)
    t.test_runs.mkdir(parents=True, exist_ok=True)
    reports = [t.test_runs / f"junit-{k}.xml" for k in range(len(bins))]
    logs = [t.test_runs / f"pytest-{k}.log" for k in range(len(bins))]
    cmds = [[sys.executable, "-m", "pytest", *args, f"--junitxml={reports[k]}",
             "-o", f"cache_dir=.pytest_cache/part-{k}", *[str(f.relative_to(t.root)) for f in b]]
            for k, b in enumerate(bins)]
    say("test", f"pytest in {len(bins)} partitions at once: "
        + "; ".join(" ".join(f.stem.removeprefix("test_") for f in b) for b in bins))
    codes = procs.call_parallel(cmds, cwd=t.root, env=t.env(), logs=logs)
    for k in range(1, len(bins)):
        print(f"\n===== partition {k + 1} of {len(bins)} =====", flush=True)
        print(logs[k].read_text(encoding="utf-8", errors="replace"), flush=True)
    _record(t, reports)
    for p in reports:
        p.unlink(missing_ok=True)
    if all(c == 5 for c in codes):
        return 5
    return max((c for c in codes if c != 5), default=0)
