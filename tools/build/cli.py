"""Command line of the build: ``python -m tools.build [--root DIR] [--build DIR] [--notebooks DIR] COMMAND``.

Commands: ``execute`` (stale notebooks, then the ledger), ``report [--html-only]``, ``figures``
(``python -m edition.figures figures/``, for ``make figures``), ``test [-- PYTEST ARGS]`` (what
``make test`` runs: execute, pytest in two partitions at once, then fail if the build modified
tracked files), ``snapshot`` and
``check-clean`` (the two halves of that check). Exit status: 0 success, 1 a step failed, 2 the
build left tracked files modified, 128+N stopped by signal N.
"""
from __future__ import annotations

import argparse
import signal
import sys

from . import guard, procs
from .execute import execute
from .files import remove_temp_dirs
from .log import BuildError, Interrupted, say
from .paths import Tree
from .report import report
from .testrun import run_tests
from .worker import skip_slow_imports

__all__ = ["main"]


def _figures(t: Tree) -> None:
    p = procs.call([sys.executable, "-m", "edition.figures", str(t.figures)], cwd=t.root, env=t.env())
    if p != 0:
        raise BuildError(f"python -m edition.figures {t.rel(t.figures)} failed (exit {p})")


def _check_clean(t: Tree) -> int:
    changed = guard.compare(t)
    if changed is None:
        say("git", "no snapshot or no git: not checked")
        return 0
    if changed:
        say("git", "FAILED: the build modified files that git tracks (or left new ones it does not ignore):\n  "
            + "\n  ".join(changed) + "\nA build must leave `git status` as it found it; commit regenerated "
            "files if the change is intended, or make their output deterministic.")
        return 2
    say("git", "the build left git status as it found it")
    return 0


def _test(t: Tree, pytest_args: list[str]) -> int:
    guard.snapshot(t)
    execute(t)
    rc = run_tests(t, pytest_args)
    if rc == 5:
        say("test", "pytest collected no tests: failing")
        rc = 1
    clean = _check_clean(t)
    return rc or clean


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m tools.build", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--root", help="project tree (default: $WMR_ROOT or this repository)")
    ap.add_argument("--build", help="build directory (default: ROOT/build)")
    ap.add_argument("--notebooks", help="notebooks to execute (default: ROOT/notebooks)")
    sub = ap.add_subparsers(dest="cmd", required=True)
    sub.add_parser("execute", help="execute stale notebooks, merge the ledger")
    r = sub.add_parser("report", help="build/report.html and build/report.pdf")
    r.add_argument("--html-only", action="store_true")
    sub.add_parser("figures", help="python -m edition.figures figures/")
    te = sub.add_parser("test", help="execute, pytest, fail if tracked files changed")
    te.add_argument("pytest_args", nargs=argparse.REMAINDER)
    sub.add_parser("snapshot", help="record git status before a build")
    sub.add_parser("check-clean", help="fail if git status changed since the snapshot")
    a = ap.parse_args(argv)
    t = Tree(a.root, a.build, a.notebooks)

    skip_slow_imports()
    procs.die_with_parent(signal.SIGTERM)
    procs.become_subreaper()
    procs.handle_signals()
    try:
        if a.cmd == "execute":
            execute(t)
        elif a.cmd == "report":
            report(t, html_only=a.html_only)
        elif a.cmd == "figures":
            _figures(t)
        elif a.cmd == "test":
            args = a.pytest_args[1:] if a.pytest_args[:1] == ["--"] else a.pytest_args
            return _test(t, args)
        elif a.cmd == "snapshot":
            guard.snapshot(t)
        elif a.cmd == "check-clean":
            return _check_clean(t)
        return 0
    except BuildError as e:
        print(f"\nBUILD FAILED\n{e}", file=sys.stderr, flush=True)
        return 1
    except Interrupted as e:
        print(f"\n[build] stopped by signal {e.signum}: stopping every child process", file=sys.stderr, flush=True)
        return 128 + e.signum
    finally:
        procs.terminate_all()
        with procs.BuildLock(t.lock, wait=False) as lock:    # our temporary files, unless another
            if lock.acquired and t.build.is_dir():           # build of this tree is using its own
                remove_temp_dirs(t.tmp)
