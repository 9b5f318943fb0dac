"""Time chapter 9's seven MuJoCo experiments as the chapter runs them, each over its parameter box, and its eight Drake
runs (issues 21 and 31: all together within 60 s of CPU on the project's quiet machine).

Usage: ``python -m tools.bench.physics [--repeat R] [--drake-only]``.

Each experiment of :mod:`edition.physics` is judged over its box (:func:`edition.physics.run`, every point of
:mod:`edition.physics.box`) ``R`` times (default 1) in this process, after one untimed warm-up import; the table
gives the best wall-clock time and the process CPU time of that run (on a shared machine the CPU time is what the
experiment costs with a core to itself, though a loaded machine's shared caches still slow it), the runs of the box
and the verdict over it.  Then the Drake runs of Section 9.10 (:func:`edition.physics.drake.run_all`: four experiments
at the nominal point, point and hydroelastic contact, the dual wheel at two moduli), each timed once, Drake's import
included in the first.  The load average is printed before and after: times are only as quiet as the machine was.
The last row is the sum; its CPU time is the figure to compare with the 60 s budget.
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

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
        0 when the total CPU time is within the budget, 1 otherwise.
    """
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=1, help="runs per experiment (the best is kept)")
    ap.add_argument("--drake-only", action="store_true", help="time the Drake runs only (not the MuJoCo box)")
    args = ap.parse_args(argv)
    import mujoco

    from edition import physics

    print(
        f"Python {platform.python_version()}, MuJoCo {mujoco.__version__}, {os.cpu_count()} cores, "
        f"{platform.machine()}; load average before: {_load()}"
    )
    rows, wall, cpu = [], 0.0, 0.0
    for f in () if args.drake_only else physics.EXPERIMENTS:
        best = (float("inf"), float("inf"))
        for _ in range(max(1, args.repeat)):
            w0, c0 = time.perf_counter(), time.process_time()
            outcome = physics.run(f)
            t = (time.perf_counter() - w0, time.process_time() - c0)
            best = t if t[1] < best[1] else best
        b = outcome.box
        rows.append((f.__name__, f"{b.verdict} ({b.held} of {b.valid} valid runs of {len(b.runs)})", *best))
        wall, cpu = wall + best[0], cpu + best[1]
    w0, c0 = time.perf_counter(), time.process_time()
    import numpy as np

    from edition.physics import drake  # pydrake itself is imported by the first run

    def both():  # wall and CPU at once: run_all subtracts two readings
        return np.array([time.perf_counter(), time.process_time()])

    for result, (w, c) in drake.run_all(clock=both):
        rows.append((f"Drake {result.key}, {result.contact}", result.verdict, float(w), float(c)))
    wall, cpu = wall + time.perf_counter() - w0, cpu + time.process_time() - c0
    width = max(len(r[0]) for r in rows)
    print(f"\n| {'experiment':<{width}} | wall (s) | cpu (s) | verdict (over the box for MuJoCo; nominal for Drake)")
    print(f"| {'-' * width} | -------- | ------- | --------------------")
    for name, v, w, c in rows:
        print(f"| {name:<{width}} | {w:8.2f} | {c:7.2f} | {v}")
    if args.drake_only:
        print(
            f"| {'the Drake runs':<{width}} | {wall:8.2f} | {cpu:7.2f} | (the budget is for all experiments together)"
        )
    else:
        print(
            f"| {'all':<{width}} | {wall:8.2f} | {cpu:7.2f} | budget {BUDGET:g} s of CPU: "
            f"{'within' if cpu <= BUDGET else 'OVER'}"
        )
    print(f"\nload average after: {_load()}")
    return 0 if args.drake_only or cpu <= BUDGET else 1


if __name__ == "__main__":
    sys.exit(main())
