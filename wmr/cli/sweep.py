"""``wmr sweep ROBOT.toml ANALYSIS``: an analysis over the configurations a robot can drive in, or over all of them.

Example::

    wmr sweep examples/paper_centred.toml kappa_J --angles any --grid 72

By default (``--angles drivable``) the configurations are those a steered robot can drive in: the
steering angles of sampled twists (:class:`wmr.analysis.sweep.Drivable`); ``--sample N`` sets how
many (default 1e6).  ``--angles any`` covers every steering angle, drivable or not: a grid
(``--grid``, the default with ``--angles any``) or ``--sample N`` random configurations, in
``--range``.  The reduction (count, min, max, quantiles, the worst configuration: the minimum for
rank F and the mobilities, the maximum for a condition number) says which set it covers; it is
printed as a short table, or as JSON with ``--json``; a progress bar goes to stderr while the sweep
runs (``--no-progress`` turns it off).  Angles on the command line are in degrees, in the convention
of ``--convention``.

Limits (:mod:`wmr.model.limits`) are checked before the sweep starts: at most 1e9 configurations
(``WMR_MAX_CONFIGURATIONS``) and 1024 MB of working memory (``WMR_MAX_MEMORY_MB``).  Ctrl-C stops the
sweep after the chunk in progress and prints the result over the configurations done so far
(marked INTERRUPTED), with exit status 130; a second Ctrl-C stops at once.
"""

from __future__ import annotations

import argparse
import math
import sys
import time

from ..errors import InputValueError
from ..io.decimals import DEGREES
from ._numbers import json_text

__all__ = ["run"]


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


def _angles(args, robot):
    from ..analysis.sweep import Drivable, Grid, Sample
    from ..model.conventions import angle_from

    mode = args.angles or ("any" if args.grid is not None or args.range is not None else "drivable")
    if mode == "drivable":
        if args.grid is not None or args.range is not None:
            raise InputValueError(
                "--grid and --range cover every steering angle: give --angles any with them "
                "(the drivable configurations are sampled: --sample N)"
            )
        return Drivable(_number(args.sample or "1e6", "sample"), seed=args.seed)
    lo_deg, hi_deg = args.range or (-180.0, 180.0)
    lo = math.radians(lo_deg) + float(angle_from(0.0, args.convention))  # the convention's 0 in wmr's angles
    hi = lo + math.radians(hi_deg - lo_deg)
    if args.sample is not None:
        return Sample(_number(args.sample, "sample"), seed=args.seed, lo=lo, hi=hi)
    steps = [_number(s, "grid") for s in (args.grid or "36").split(",")]
    if len(steps) == 1:  # unsteered units keep their own angle: one value is enough
        steps = [steps[0] if steered else 1 for steered in robot.steered]
    return Grid(tuple(steps), lo=lo, hi=hi)


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
        self.stream.write(
            f"\r[{'#' * fill}{'.' * (self.width - fill)}] {100 * frac:3.0f}%  "
            f"{done:.3g}/{total:.3g}  {el:.0f} s, {left:.0f} s left "
        )
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


def _as_json(res, convention="wmr"):
    from ..analysis.sweep import ANALYSES
    from ..model.conventions import angle_to

    def num(x):
        return x if math.isfinite(x) else ("inf" if x > 0 else "-inf")

    def deg(beta):
        return [math.degrees(a) for a in angle_to(beta, convention)]

    return {
        "analysis": res.analysis,
        "covers": res.covers,
        "complete": res.complete,
        "count": res.count,
        "convention": convention,
        "min": num(res.min),
        "max": num(res.max),
        "argmin_deg": deg(res.argmin),
        "argmax_deg": deg(res.argmax),
        "worst": num(res.worst),
        "worst_is": ANALYSES[res.analysis].worst,
        "worst_index": res.worst_index,
        "worst_deg": deg(res.worst_angles),
        "quantiles": {f"{q:g}": num(v) for q, v in res.quantiles.items()},
        "counts": {str(k): n for k, n in res.counts.items()},
        "infinite": res.infinite,
    }


def run(args: argparse.Namespace) -> int:
    """Run ``wmr sweep``.

    Parameters
    ----------
    args : argparse.Namespace
        The options of ``wmr sweep`` (:func:`wmr.cli.main` parses them).

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
        angles = _angles(args, robot)
        qs = [_level(q) for q in args.quantiles.split(",") if q.strip()]
        show = sys.stderr.isatty() if args.progress is None else args.progress
        if args.dask:
            client, cluster = _client(args.dask)
        res = sweep(
            robot,
            args.analysis,
            angles,
            L=args.length,
            quantiles=qs,
            chunk=args.chunk,
            progress=_Bar(sys.stderr) if show else None,
            client=client,
            interruptible=True,
        )
    finally:
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
    if res.count == 0:
        print("wmr sweep: interrupted (Ctrl-C) before any configuration was evaluated", file=sys.stderr)
        return 130
    if args.json:  # the analyses' values are dimensionless (scale 1); angles in degrees at the scale of a radian
        scales = dict.fromkeys(("argmin_deg", "argmax_deg", "worst_deg"), DEGREES)
        print(json_text(_as_json(res, args.convention), scales=scales))
    else:
        print(res.summary(args.convention))
    if not res.complete:
        print(
            f"wmr sweep: interrupted (Ctrl-C) after {res.count:,} configurations: the result above covers those only",
            file=sys.stderr,
        )
        return 130
    return 0
