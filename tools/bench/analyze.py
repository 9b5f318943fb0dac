"""Benchmark of ``wmr analyze`` against the number of wheel units (4 to 1,000): wall time and peak memory.

Usage: ``make bench`` (after the kernel rows) or ``python -m tools.bench.analyze [--sizes 4,100,1000] [--repeat R]``.

Three families of robots are written as robot files (TOML) in a temporary folder, for each size n:

* ``fixed row``: n fixed wheels in a row along x, all rolling along x (a differential drive
  of n wheels: every wheel plane parallel, the singular family "parallel");
* ``centred ring``: n centred steered wheels on a circle (a swerve drive of n modules: the
  grid over the steered angles becomes a seeded sample, singular families through C, through a
  mount point and through another point);
* ``mixed ring``: offset, centred, dual, Swedish and fixed units in turn on a circle.

Each file is analysed by a fresh ``python -m wmr analyze FILE`` (so the time includes the start of
Python and the import of wmr, as a user sees it) with ``WMR_MAX_WHEELS`` raised to the largest
size; the row gives the best wall time of ``--repeat`` runs and the largest peak resident memory
(``ru_maxrss`` of the child, from ``os.wait4``).  The goals of issue 28: at most 0.5 s for 4 units,
2 s for 100 and 20 s for 1,000, each in at most 500 MB.  The load average is printed before and
after: timings on a shared machine are only as quiet as it was.
"""

from __future__ import annotations

import argparse
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

#: (size, seconds): the goals of issue 28 (a size between two goals is held to the larger one)
GOALS = ((4, 0.5), (100, 2.0), (1000, 20.0))
#: peak resident memory goal (MB)
MEMORY_MB = 500

_MIXED = (
    ('type = "offset"', "radius = 0.05", "offset = 0.03"),
    ('type = "centred"', "radius = 0.05"),
    ('type = "dual"', "radius = 0.05", "half_separation = 0.04"),
    ('type = "swedish"', "radius = 0.05", "angle_deg = 90.0", "roller_deg = 45.0"),
    ('type = "fixed"', "radius = 0.05", "angle_deg = 90.0"),
)


def robot_file(family: str, n: int) -> str:
    """The TOML text of a robot of ``family`` with ``n`` units."""
    lines = [f'name = "{family}, {n} units"']
    for i in range(n):
        if family == "fixed row":
            x, y = 0.1 * i - 0.05 * (n - 1), 0.3
            keys: tuple[str, ...] = ('type = "fixed"', "radius = 0.05", "angle_deg = 0.0")
        else:
            a = 2 * math.pi * i / n
            x, y = 0.5 * math.cos(a), 0.5 * math.sin(a)
            keys = ('type = "centred"', "radius = 0.05") if family == "centred ring" else _MIXED[i % len(_MIXED)]
        lines += ["[[wheel]]", keys[0], f"position = [{x:.6f}, {y:.6f}]", *keys[1:]]
    return "\n".join(lines) + "\n"


def run(path: Path, env: dict) -> tuple[float, float, int]:
    """One ``wmr analyze``: wall seconds, peak resident MB, exit status."""
    t0 = time.perf_counter()
    p = subprocess.Popen([sys.executable, "-m", "wmr", "analyze", str(path)], env=env, stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    return time.perf_counter() - t0, usage.ru_maxrss / 1024, p.returncode


def goal(n: int) -> float:
    """The time goal for ``n`` units."""
    return next((sec for size, sec in GOALS if n <= size), GOALS[-1][1])


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="4,10,30,100,300,1000", help="numbers of units, comma-separated")
    parser.add_argument("--repeat", type=int, default=3, help="runs per robot (the best time is kept)")
    args = parser.parse_args(argv)
    sizes = [int(s) for s in args.sizes.split(",")]
    env = dict(os.environ, WMR_MAX_WHEELS=str(max(sizes)))
    print(f"load average before: {os.getloadavg()[0]:.2f}   ({os.cpu_count()} CPUs, Python {sys.version.split()[0]})")
    print()
    print("| robot | units | wall (s) | goal (s) | peak memory (MB) | goal met |")
    print("| --- | ---: | ---: | ---: | ---: | --- |")
    missed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for family in ("fixed row", "centred ring", "mixed ring"):
            for n in sizes:
                path = Path(tmp) / f"{family.replace(' ', '_')}_{n}.toml"
                path.write_text(robot_file(family, n), encoding="utf-8")
                runs = [run(path, env) for _ in range(args.repeat)]
                if any(code != 0 for _, _, code in runs):
                    print(f"| {family} | {n} | failed (exit {runs[0][2]}) | | | no |")
                    missed += 1
                    continue
                sec, mb = min(r[0] for r in runs), max(r[1] for r in runs)
                ok = sec <= goal(n) and mb <= MEMORY_MB
                missed += not ok
                print(f"| {family} | {n:,} | {sec:.2f} | {goal(n):g} | {mb:.0f} | {'yes' if ok else 'NO'} |")
    print()
    print(f"load average after: {os.getloadavg()[0]:.2f}")
    return 1 if missed else 0


if __name__ == "__main__":
    raise SystemExit(main())
