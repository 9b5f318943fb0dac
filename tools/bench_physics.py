"""Time chapter 9's seven MuJoCo experiments (issue 21: all seven together in under 60 s on the project's machine).

Usage: ``python tools/bench_physics.py [--repeat R]``.

Each experiment of :mod:`edition.physics` is run ``R`` times (default 1) in this process, after one
untimed warm-up import; the table gives the best wall-clock time and the process CPU time of that
run (on a shared machine the CPU time is what the experiment costs with a core to itself).  The
load average is printed before and after: wall
times are only as quiet as the machine was.  The last row is the sum, the figure to compare with
the 60 s budget.
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

BUDGET = 60.0


def _load():
    try:
        return " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:  # pragma: no cover - not on Linux
        return "n/a"


def main(argv=None):
    """Run the benchmark and print its table.

    Parameters
    ----------
    argv : list of str, optional

    Returns
    -------
    int
        0 when the total wall time is within the budget, 1 otherwise.
    """
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=1, help="runs per experiment (the best is kept)")
    args = ap.parse_args(argv)
    import mujoco

    from edition import physics

    print(
        f"Python {platform.python_version()}, MuJoCo {mujoco.__version__}, {os.cpu_count()} cores, "
        f"{platform.machine()}; load average before: {_load()}"
    )
    rows, wall, cpu = [], 0.0, 0.0
    for f in physics.EXPERIMENTS:
        best = (float("inf"), float("inf"))
        for _ in range(max(1, args.repeat)):
            w0, c0 = time.perf_counter(), time.process_time()
            outcome = f()
            t = (time.perf_counter() - w0, time.process_time() - c0)
            best = t if t[0] < best[0] else best
        rows.append((f.__name__, outcome.verdict, *best))
        wall, cpu = wall + best[0], cpu + best[1]
    width = max(len(r[0]) for r in rows)
    print(f"\n| {'experiment':<{width}} | wall (s) | cpu (s) | verdict")
    print(f"| {'-' * width} | -------- | ------- | -------")
    for name, v, w, c in rows:
        print(f"| {name:<{width}} | {w:8.2f} | {c:7.2f} | {v}")
    print(
        f"| {'all seven':<{width}} | {wall:8.2f} | {cpu:7.2f} | budget {BUDGET:g} s: "
        f"{'within' if wall <= BUDGET else 'OVER'}"
    )
    print(f"\nload average after: {_load()}")
    return 0 if wall <= BUDGET else 1


if __name__ == "__main__":
    sys.exit(main())
