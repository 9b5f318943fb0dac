"""The before/after table of issue 24: the twelve engineers' robots through two versions of the `wmr` command line.

For each robot of ``examples/engineers/``, each version is run as a user runs it (``analyze --json``,
``sweep --json ROBOT kappa_J --sample 1e5`` and the same of ``mobility``: the default set of
configurations of each version, 100,000 of them) and the table
shows what it printed: Campion's class, the actuated mobility, the limitations, kappa(J) over the
configurations its default sweep covers (median and 95th percentile) and the least mobility there.
A version that does not print a quantity shows a dash.

    usage: python -m tools.bench.design --before "CMD" --after "CMD" (its table is a section of tools/BENCH.md)

CMD is a command that runs ``wmr``, e.g. ``"env PYTHONPATH=/tmp/main /work/main/.venv/bin/python -m wmr"``
(the library of another commit with this project's venv) or ``"$PWD/.venv/bin/wmr"``; it runs in ``/``.
"""

from __future__ import annotations

import argparse
import json
import math
import shlex
import subprocess
import sys
import time
from pathlib import Path

SAMPLE = "1e5"  # (the default grid of 36 angles per steered unit has 36^6 = 2.2e9 for six units)
ROBOTS = Path(__file__).resolve().parents[2] / "examples" / "engineers"


def _run(cmd: str, *argv: str) -> dict:
    out = subprocess.run(
        [*shlex.split(cmd), *argv], capture_output=True, text=True, check=True, cwd="/"
    ).stdout  # (python -m puts the working directory first on sys.path)
    return json.loads(out)


def _num(x) -> str:
    if isinstance(x, str):
        return x
    return "inf" if math.isinf(x) else f"{x:.3g}"


def _version(cmd: str, robot: Path) -> dict:
    a = _run(cmd, "analyze", "--json", str(robot))
    k = _run(cmd, "sweep", "--json", str(robot), "kappa_J", "--sample", SAMPLE)
    m = _run(cmd, "sweep", "--json", str(robot), "mobility", "--sample", SAMPLE)
    q = k["quantiles"]
    over = k.get("covers", "").split(":")[0] or "random configurations"
    return {
        "class": a["class"],
        "actuated": str(a.get("actuated_mobility", "-")),
        "limitations": "; ".join(a.get("limitations", [])) or ("none" if "limitations" in a else "-"),
        "kappa": f"{_num(q['0.5'])} / {_num(q['0.95'])}",
        "count": f"{k['count']:,} {over}",
        "mobility": _num(m["min"]),
    }


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--before", required=True, help="command running the old wmr")
    p.add_argument("--after", required=True, help="command running the new wmr")
    args = p.parse_args(argv)
    t0 = time.time()
    print(
        "| robot | class before / after | actuated mobility before / after | kappa(J) median / p95 before "
        "| over | after | over | least mobility of the default sweep before / after | limitations before "
        "| limitations after |"
    )
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for robot in sorted(ROBOTS.glob("*.toml")):
        b, a = _version(args.before, robot), _version(args.after, robot)
        print(
            f"| {robot.stem} | {b['class']} / {a['class']} | {b['actuated']} / {a['actuated']} | {b['kappa']} "
            f"| {b['count']} | {a['kappa']} | {a['count']} | {b['mobility']} / {a['mobility']} "
            f"| {b['limitations']} | {a['limitations']} |"
        )
        print(f"  ({robot.stem}: {time.time() - t0:.0f} s)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
