"""``wmr sweep ROBOT.toml ANALYSIS``: an analysis over a grid or a random sample of steering angles.

Examples::

    wmr sweep examples/paper_centred.toml kappa_J --grid 72
    wmr sweep examples/swerve.toml rank_F --sample 1e8 --seed 1 --json
    wmr sweep examples/swerve.toml mobility --grid 36 --dask local:2

The reduction (count, min, max, quantiles, the worst configuration) is printed as a short table,
or as JSON with ``--json``; a progress bar goes to stderr while the sweep runs (``--no-progress``
turns it off).  Angles on the command line are in degrees.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time

from ..errors import InputValueError

HELP = "evaluate rank F, mobility, det J or a condition number over a grid or a sample of steering angles"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Options of ``wmr sweep``.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The sub-command's parser.

    Returns
    -------
    None
    """
    from ..analysis.sweep import ANALYSES, CHUNK, QUANTILES
    parser.add_argument("robot", help="robot file (TOML)")
    parser.add_argument("analysis", choices=sorted(ANALYSES), help="what to evaluate at each configuration")
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--grid", metavar="STEPS", help="regular grid: STEPS values per angle (default 36), "
                       "or one count per wheel separated by commas")
    which.add_argument("--sample", metavar="N", help="N random configurations (e.g. 1e6)")
    parser.add_argument("--seed", type=int, default=0, help="seed of --sample (default 0)")
    parser.add_argument("--range", nargs=2, type=float, metavar=("LO", "HI"), default=(-180.0, 180.0),
                        help="range of every steering angle in degrees (default -180 180)")
    parser.add_argument("--length", type=float, default=None, metavar="L",
                        help="characteristic length of J_L1 (default: the robot's characteristic length)")
    parser.add_argument("--quantiles", default=",".join(f"{q:g}" for q in QUANTILES),
                        help="quantile levels, comma-separated")
    parser.add_argument("--chunk", type=int, default=CHUNK, help=f"configurations per chunk (default {CHUNK})")
    parser.add_argument("--dask", metavar="SCHEDULER", default=None,
                        help="run the chunks on Dask: a scheduler address, or local:N for N local workers")
    parser.add_argument("--json", action="store_true", help="print JSON instead of a table")
    parser.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                        help="show a progress bar on stderr (default: when stderr is a terminal)")


def _number(text, name):
    try:
        value = float(text)
    except ValueError:
        raise InputValueError(f"--{name} must be a number, got {text!r}") from None
    if not value.is_integer() or value < 1:
        raise InputValueError(f"--{name} must be a positive whole number, got {text!r}")
    return int(value)


def _level(text):
    try:
        return float(text)
    except ValueError:
        raise InputValueError(f"--quantiles must be numbers in [0, 1] separated by commas, got {text!r}") from None


def _angles(args, w):
    from ..analysis.sweep import Grid, Sample
    lo, hi = (math.radians(a) for a in args.range)
    if args.sample is not None:
        return Sample(_number(args.sample, "sample"), seed=args.seed, lo=lo, hi=hi)
    steps = (args.grid or "36").split(",")
    steps = [_number(s, "grid") for s in steps]
    return Grid(steps[0] if len(steps) == 1 else tuple(steps), lo=lo, hi=hi)


class _Bar:
    """A one-line progress bar on a stream: ``[#####.....]  52%  5.2e+07/1e+08  12 s, 11 s left``."""

    def __init__(self, stream, width=30):
        self.stream, self.width, self.t0, self.last = stream, width, time.perf_counter(), -1.0

    def __call__(self, done, total):
        now = time.perf_counter()
        if done < total and now - self.last < 0.2:
            return
        self.last = now
        frac = done / total
        fill = int(round(frac * self.width))
        el = now - self.t0
        left = el * (1 - frac) / frac if frac > 0 else math.nan
        self.stream.write(f"\r[{'#' * fill}{'.' * (self.width - fill)}] {100 * frac:3.0f}%  "
                          f"{done:.3g}/{total:.3g}  {el:.0f} s, {left:.0f} s left ")
        if done >= total:
            self.stream.write("\n")
        self.stream.flush()


def _client(spec):
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        from .._version import DISTRIBUTION
        raise InputValueError(f"--dask needs dask and distributed: pip install '{DISTRIBUTION}[dask]'") from None
    if spec.startswith("local"):
        n = _number(spec.partition(":")[2] or "2", "dask local:N")
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=":0")
        return Client(cluster), cluster
    return Client(spec), None


def _as_json(res):
    def num(x):
        return x if math.isfinite(x) else ("inf" if x > 0 else "-inf")
    return {"analysis": res.analysis, "count": res.count, "min": num(res.min), "max": num(res.max),
            "argmin_deg": [math.degrees(a) for a in res.argmin],
            "argmax_deg": [math.degrees(a) for a in res.argmax],
            "worst": num(res.worst), "worst_index": res.worst_index,
            "worst_deg": [math.degrees(a) for a in res.worst_angles],
            "quantiles": {f"{q:g}": num(v) for q, v in res.quantiles.items()},
            "counts": {str(k): n for k, n in res.counts.items()}, "infinite": res.infinite}


def run(args: argparse.Namespace) -> int:
    """Run ``wmr sweep``.

    Parameters
    ----------
    args : argparse.Namespace

    Returns
    -------
    int
        0; bad input raises an input error (:mod:`wmr.errors`; :func:`wmr.cli.main` reports it in one line, status 2).
    """
    import wmr

    from ..analysis.sweep import sweep
    client = cluster = None
    try:
        robot = wmr.load(args.robot)
        angles = _angles(args, robot.w)
        qs = [_level(q) for q in args.quantiles.split(",") if q.strip()]
        show = sys.stderr.isatty() if args.progress is None else args.progress
        if args.dask:
            client, cluster = _client(args.dask)
        res = sweep(robot, args.analysis, angles, L=args.length, quantiles=qs, chunk=args.chunk,
                    progress=_Bar(sys.stderr) if show else None, client=client)
    finally:
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
    print(json.dumps(_as_json(res), indent=2) if args.json else res.summary())
    return 0
