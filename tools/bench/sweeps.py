"""The sweep rows of tools/bench/batched.py: :func:`wmr.sweep` in process, on Dask, and the drivable sweep of issue 24.

Every in-process sweep runs in a fresh interpreter (:func:`sweep_child`), so that its peak resident
memory is its own; inside it the sweep is timed around the call (no interpreter start, no command
line), after one small warm-up sweep, as the best of ``repeat`` runs, with the process CPU time of
all threads and the 1-minute load average of each run.  The drivable row is issue 24's requirement:
``kappa_J`` of ``examples/swerve4.toml`` over its drivable configurations (the coordinated steering
angles of sampled twists) at 5 million configurations per second or more, in process, on the
project's 2-core machine; the cpu rate (configurations per second of CPU time, all threads together)
is what the sweep costs when it has the cores to itself.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import wmr

#: issue 24: configurations per second of a default (drivable) sweep of the swerve's kappa(J), in process
GOAL = 5e6
SWERVE = Path(__file__).resolve().parents[2] / "examples" / "swerve4.toml"

_CHILD = """
import json, os, sys, time
import numpy as np
import wmr
from wmr.analysis.sweep import {source}
bot = {make}
wmr.sweep(bot, {analysis!r}, {source}(1 << 18, seed=2), chunk={chunk})  # warm-up: imports, pool, kernels
runs = []
for _ in range({repeat}):
    load = os.getloadavg()[0]
    t0, c0 = time.perf_counter(), time.process_time()
    res = wmr.sweep(bot, {analysis!r}, {source}({n}, seed=1), chunk={chunk})
    runs.append((time.perf_counter() - t0, time.process_time() - c0, load))
hwm = [l for l in open('/proc/self/status') if l.startswith('VmHWM')][0].split()[1]
ref = float(res.worst)
if {analysis!r} == 'kappa_J':  # the reported worst value against a plain SVD of J at the reported configuration
    s = np.linalg.svd(bot.J(res.worst_angles, L=wmr.characteristic_length(bot)), compute_uv=False)
    ref = float('inf') if s[-1] <= wmr.TOL * s[0] else float(s[0] / s[-1])
print(json.dumps(dict(runs=runs, rss=int(hwm) / 1024, count=res.count, worst=float(res.worst), ref=ref)))
"""


@dataclass
class Row:
    """One timed sweep: the best (smallest wall-clock) of the runs, and what the child measured."""

    name: str
    sec: float  # wall-clock seconds of the best run
    cpu: float  # its process CPU seconds (all threads)
    load: float  # the 1-minute load average when it started
    count: int
    rss: float | None  # peak resident memory of the child (MB)
    ok: bool = True  # the worst value equals a plain SVD at its configuration

    @property
    def rate(self):
        """Configurations per second of wall-clock time."""
        return self.count / self.sec

    @property
    def cpu_rate(self):
        """Configurations per second of CPU time (all threads together)."""
        return self.count / self.cpu


def load():
    """The load average, in words."""
    try:
        return "load average " + " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:
        return "load average unknown"


def sweep_child(name, analysis, n, chunk, threads=None, robot="paper_centred", source="Sample", repeat=1):
    """Run ``repeat`` in-process sweeps in a fresh interpreter: the :class:`Row` of the fastest.

    ``robot`` is ``"paper_centred"`` (the paper's three centred wheels) or ``"swerve4"`` (examples/swerve4.toml);
    ``source`` is ``"Sample"`` (random angles) or ``"Drivable"`` (the steering angles of sampled twists);
    ``threads`` sets ``WMR_THREADS`` (None: every core).
    """
    # VmHWM, not ru_maxrss: Linux carries the parent's peak over fork + exec into ru_maxrss
    make = "wmr.paper_robot('centred')" if robot == "paper_centred" else f"wmr.load({str(SWERVE)!r})"
    code = _CHILD.format(source=source, make=make, analysis=analysis, chunk=chunk, n=n, repeat=repeat)
    env = dict(os.environ, **({} if threads is None else {"WMR_THREADS": str(threads)}))
    out = json.loads(
        subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True, env=env).stdout
    )
    sec, cpu, at = min(out["runs"])
    worst, ref = out["worst"], out["ref"]
    ok = out["count"] == n and (worst == ref or abs(worst / ref - 1) <= 1e-12 + 64 * 2.2e-16 * ref)
    return Row(name, sec, cpu, at, out["count"], out["rss"], ok)


def sweep_rows(n, dask):
    """The paper's centred robot over random angles: rank F and kappa(J), in process (all cores, one) and on Dask."""
    from wmr.analysis.sweep import CHUNK, Sample

    rows = []
    for analysis in ("rank_F", "kappa_J"):
        for threads in (None, 1):
            where = "in process" if threads is None else "in process, 1 thread"
            rows.append(sweep_child(f"sweep {analysis}, {where}", analysis, n, CHUNK, threads))
        if dask:
            from dask.distributed import Client, LocalCluster

            bot = wmr.paper_robot("centred")
            with (
                LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cl,
                Client(cl) as client,
            ):
                wmr.sweep(bot, analysis, Sample(4 * CHUNK, seed=2), client=client)  # warm the workers
                at = os.getloadavg()[0]
                t0 = time.perf_counter()
                res = wmr.sweep(bot, analysis, Sample(n, seed=1), client=client)
                sec = time.perf_counter() - t0
                rows.append(Row(f"sweep {analysis}, dask 2 workers", sec, float("nan"), at, res.count, None))
    return rows


def drivable_rows(n, repeat=3):
    """Issue 24: kappa(J) of the four-module swerve over drivable configurations (goal :data:`GOAL`), and references."""
    from wmr.analysis.sweep import CHUNK

    cores = os.cpu_count() or 1
    rows = [
        sweep_child(
            f"drivable, all {cores} cores", "kappa_J", n, CHUNK, None, robot="swerve4", source="Drivable", repeat=repeat
        ),
        sweep_child("drivable, 1 thread", "kappa_J", n, CHUNK, 1, robot="swerve4", source="Drivable", repeat=repeat),
        sweep_child(  # (a tenth of the configurations: the general kernels are 20 times slower)
            "random angles (general kernels)", "kappa_J", max(1, n // 10), CHUNK, None, robot="swerve4", source="Sample"
        ),
    ]
    return rows


def print_sweep_rows(rows):
    """The rows of :func:`sweep_rows`, one line each."""
    base: dict = {}
    for r in rows:
        an = r.name.split(",")[0]
        extra = f"peak RSS {r.rss:.0f} MB" if r.rss is not None else f"speed-up {base[an] / r.sec:.2f}x vs in process"
        base.setdefault(an, r.sec)
        print(f"{r.name:36s} {r.sec:8.2f} s  {r.rate / 1e6:6.2f} M configurations/s  load {r.load:.2f}  {extra}")
    return sum(not r.ok for r in rows)


def print_drivable_rows(rows, n, repeat):
    """The drivable rows against :data:`GOAL`: wall and CPU time, both rates, the load average, the verdict."""
    print(
        f"\nissue 24: the default (drivable) sweep, kappa(J) of examples/swerve4.toml over {n:,} drivable "
        f"configurations,\nin process (wmr.sweep timed around the call, best of {repeat}); "
        f"goal >= {GOAL / 1e6:.0f} M configurations/s wall on {os.cpu_count()} cores"
    )
    head = (
        f"{'swerve4 kappa_J':34s} {'wall s':>7s} {'cpu s':>7s} {'M/s wall':>9s} {'M/cpu-s':>8s} "
        f"{'load':>5s} {'RSS MB':>7s}  check  goal"
    )
    print(head)
    print("-" * len(head))
    for i, r in enumerate(rows):
        goal = ("met" if r.rate >= GOAL else f"MISSED (at load {r.load:.1f})") if i == 0 else "(reference)"
        print(
            f"{r.name:34s} {r.sec:7.3f} {r.cpu:7.3f} {r.rate / 1e6:9.2f} {r.cpu_rate / 1e6:8.2f} "
            f"{r.load:5.2f} {r.rss:7.0f}  {'ok' if r.ok else 'FAIL':5s}  {goal}"
        )
    return sum(not r.ok for r in rows)
