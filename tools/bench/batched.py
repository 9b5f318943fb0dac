"""Benchmark of wmr's batched kernels against plain-NumPy floors, a peer library and targets.

Usage: ``make bench`` or ``python -m tools.bench.batched [--n N] [--repeat R] [--sweep N] [--no-dask]``.

Each row times one kernel on N configurations (default 10**6, fixed seed) as the best of R
wall-clock runs, and compares it with

* a **target** (issue 13: rank F and det J at most 0.1 s, kappa(J) at most 0.15 s), or
* a **floor**: the same arithmetic written as plain NumPy over the whole batch, with what is
  constant per robot computed once (e.g. :math:`\\mathbf J_1^+`); goal: ``wmr`` within 2x of it, or
* a **peer**: WPILib's ``SwerveDrive4Kinematics.toSwerveModuleStates`` (robotpy-wpimath) called
  once per twist, and ``SwerveDrive4Odometry.update`` once per sample (:func:`wmr.wheel_odometry`
  takes the whole run at once), timed in the same run; goal: ``wmr`` at least 5x faster per item.

The ratio column is wmr / (target or floor) -- smaller is better -- and peer / wmr for the peer
(larger is better); both use wall-clock times.  The cpu column is the smallest process CPU time
of the runs (all threads together): on a loaded machine it is what the kernel costs when it has
the cores to itself.  The check column compares a slice of every result with the dense reference
definitions of :mod:`wmr.analysis.reference` (full matrices, SVD, pseudo-inverse), with the floor
and with WPILib, so a fast kernel that returned wrong numbers would say FAIL here.  The sweep rows
time :func:`wmr.sweep` in process (in a fresh child process, which also gives the peak resident
memory) and on a local Dask cluster of 2 single-thread workers; the last rows time the default sweep
of issue 24, kappa(J) of the four-module swerve over its drivable configurations (goal: 5 M
configurations per second in process), with its CPU time, configurations per CPU-second and the load
average of each run, beside the same over random angles (tools/bench/sweeps.py).  The load average is
printed before and after: timings on a shared machine are only as quiet as it was.

The parts: tools/bench/floors.py (the kernel rows: floors, peers, checks), tools/bench/sweeps.py
(the sweep rows), this file (the command line and the table).
"""

from __future__ import annotations

import argparse
import os
import platform
import sys

import numpy as np

import wmr
from tools.bench.floors import SEED, best_of, kernel_rows
from tools.bench.sweeps import drivable_rows, load, print_drivable_rows, print_sweep_rows, sweep_rows


def print_kernel_rows(n, k, args):
    """Time and check the kernel rows (tools/bench/floors.py); the number of failed checks."""
    rows, twist = kernel_rows(n, args.repeat, k, int(args.peer_n))
    head = (
        f"{'kernel':34s} {'wmr s':>8s} {'cpu s':>7s}  {'compared with':28s} {'its s':>8s} {'ratio':>7s}  "
        f"{'goal':>7s}  check"
    )
    print(head)
    print("-" * len(head))
    fails = 0
    for name, fn, (kind, ref), check in rows:
        cpu: list[float] = []
        sec, out = best_of(fn, args.repeat, cpu)
        ok = bool(check(out))
        if kind == "target":  # the targets are for 10**6 configurations
            other = ref * n / 1e6
            what, ratio, goal, met = "target (issue 13)", sec / other, "<= 1", sec <= other
        elif kind == "floor":
            other, _ = best_of(ref, args.repeat)
            what, ratio, goal = "plain NumPy floor", sec / other, "<= 2"
            met = ratio <= 2
        else:
            m = min(int(args.peer_n), n)
            peer_sec, _ = best_of(lambda ref=ref, m=m: ref(twist[:m]), max(1, args.repeat // 2))
            per_wmr, per_peer = sec / n, peer_sec / m
            what = getattr(ref, "label", "WPILib, one call per twist")
            print(
                f"{name:34s} {per_wmr * 1e6:6.3f}us {cpu[0] / n * 1e6:5.3f}us  {what:28s} "
                f"{per_peer * 1e6:6.3f}us {per_peer / per_wmr:6.1f}x  {'>= 5x':>7s}  "
                f"{'ok' if ok else 'FAIL'}{'' if per_peer / per_wmr >= 5 else ' (goal missed)'}"
            )
            fails += not ok
            continue
        fails += not ok
        print(
            f"{name:34s} {sec:8.4f} {cpu[0]:7.4f}  {what:28s} {other:8.4f} {ratio:7.2f}  {goal:>7s}  "
            f"{'ok' if ok else 'FAIL'}{'' if met else ' (goal missed)'}"
        )
    return fails


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=float, default=1e6, help="configurations per kernel (default 1e6)")
    p.add_argument("--repeat", type=int, default=5, help="runs per kernel; the best counts (default 5)")
    p.add_argument("--peer-n", type=float, default=2e5, help="twists for the per-twist WPILib loop (default 2e5)")
    p.add_argument("--sweep", type=float, default=1e7, help="configurations per sweep row (0: no sweep rows)")
    p.add_argument("--no-dask", action="store_true", help="skip the Dask rows")
    p.add_argument("--sweep-repeat", type=int, default=3, help="runs per drivable sweep row; the best counts")
    p.add_argument(
        "--only-drivable", action="store_true", help="only the drivable sweep rows of issue 24 (no kernel rows)"
    )
    args = p.parse_args(argv)
    n, k = int(args.n), min(int(args.n), 20000)
    print(
        f"wmr {wmr.__version__}, numpy {np.__version__}, Python {platform.python_version()}, "
        f"{os.cpu_count()} cores, WMR_THREADS={os.environ.get('WMR_THREADS', '(all)')}, N = {n:,}, "
        f"best of {args.repeat}, seed {SEED}"
    )
    print(f"before: {load()}")
    fails = 0
    if not args.only_drivable:
        fails += print_kernel_rows(n, k, args)
    if args.sweep > 0:
        ns = int(args.sweep)
        if not args.only_drivable:
            print(f"\nsweeps of {ns:,} random configurations of the paper's centred robot ({load()})")
            fails += print_sweep_rows(sweep_rows(ns, dask=not args.no_dask))
        fails += print_drivable_rows(drivable_rows(ns, args.sweep_repeat), ns, args.sweep_repeat)
    print(f"after: {load()}")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
