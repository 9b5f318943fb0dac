"""Where the CPU of a test run goes: a pytest plugin that measures each test file, and the table of the results.

``pytest -p tools.pytest_cpu`` (``tools/bench/tests.sh`` passes it through ``make test``) records, in each process
that runs tests (each pytest-xdist worker, or pytest alone), the CPU seconds -- user + sys of the process and of the
child processes it waited for -- from the start of each test to its end (fixture set-up and teardown included,
so a module's fixtures count for the module), and the seconds the process spent before its first test (interpreter,
imports, collection).  Each process writes ``build/cpu/<worker>.tsv`` (per file) and ``<worker>.tests`` (per test);
``python -m tools.pytest_cpu [DIR] [--tests N]`` sums them per file and prints a Markdown table, largest first
(with ``--tests``: the N tests that cost most).
"""

from __future__ import annotations

import os
import resource
import sys
from collections import defaultdict
from pathlib import Path

import pytest

__all__ = ["cpu_seconds", "main", "table"]

_FILES: defaultdict[str, float] = defaultdict(float)
_TESTS: dict[str, float] = {}
_COLLECTED: list[float] = []


def cpu_seconds() -> float:
    """User + sys seconds of this process and of its children that have ended."""
    me, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return me.ru_utime + me.ru_stime + kids.ru_utime + kids.ru_stime


def pytest_collection_finish(session):
    _COLLECTED.append(cpu_seconds())


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    c0 = cpu_seconds()
    yield
    _TESTS[item.nodeid] = cpu_seconds() - c0
    _FILES[item.nodeid.split("::", 1)[0]] += _TESTS[item.nodeid]


def pytest_sessionfinish(session):
    if not _FILES:
        return
    worker = os.environ.get("PYTEST_XDIST_WORKER", "main")
    out = Path(session.config.rootpath) / "build" / "cpu" / f"{worker}.tsv"
    out.parent.mkdir(parents=True, exist_ok=True)
    rows = [("(start-up and collection)", _COLLECTED[0] if _COLLECTED else 0.0), *sorted(_FILES.items())]
    out.write_text("".join(f"{name}\t{s:.3f}\n" for name, s in rows), encoding="utf-8")
    out.with_suffix(".tests").write_text("".join(f"{n}\t{s:.3f}\n" for n, s in _TESTS.items()), encoding="utf-8")


def table(folder: Path, tests: int = 0) -> str:
    """The Markdown table of the CPU seconds per test file, summed over the processes' files in ``folder``
    (``tests`` > 0: of the ``tests`` tests that cost most)."""
    total: defaultdict[str, float] = defaultdict(float)
    for f in sorted(Path(folder).glob("*.tests" if tests else "*.tsv")):
        for line in f.read_text(encoding="utf-8").splitlines():
            name, s = line.rsplit("\t", 1)
            total[name] += float(s)
    lines = ["| tests | CPU (s) |", "| --- | --- |"]
    lines += [f"| {name} | {s:.1f} |" for name, s in sorted(total.items(), key=lambda kv: -kv[1])[: tests or None]]
    if tests:
        return "\n".join(lines)
    return "\n".join([*lines, f"| all ({len(total)} rows) | {sum(total.values()):.1f} |"])


def main(argv: list[str] | None = None) -> int:
    """``python -m tools.pytest_cpu [DIR] [--tests N]`` (default ``build/cpu``): print the table."""
    args = list(sys.argv[1:] if argv is None else argv)
    n = int(args.pop(args.index("--tests") + 1)) if "--tests" in args else 0
    args = [a for a in args if a != "--tests"]
    print(table(Path(args[0] if args else "build/cpu"), n))
    return 0


if __name__ == "__main__":
    sys.exit(main())
