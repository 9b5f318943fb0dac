"""``wmr analyze ROBOT.toml``: class, mobility, isotropy, dead zone and singular configurations of a robot.

Examples::

    wmr analyze examples/swerve4.toml
    wmr analyze examples/paper_offset.toml --json

A short aligned table for people; ``--json`` prints the same numbers for programs (keys
``delta_m``, ``delta_s``, ``class``, ``rank_F``, ``nullity``, ``kappa_J_L1``, ...; infinities as the
string ``"inf"``; angles in degrees).  The computation is :func:`wmr.analysis.overview.overview`.
"""
from __future__ import annotations

import json
import math
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:                                   # (the command imports the library when it runs)
    import argparse

    from ..analysis.overview import Overview

__all__ = ["HELP", "add_arguments", "run", "as_json", "table"]

HELP = "Campion class, mobility (rank F), isotropy, dead zone and singular configurations of a robot file"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Options of ``wmr analyze``.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The sub-command's parser.

    Returns
    -------
    None
    """
    from ..analysis.overview import GRID_SIZE, TWISTS
    parser.add_argument("robot", help="robot file (TOML)")
    parser.add_argument("--wheel-joints", metavar="NAMES", help="URDF only: the wheel joints, NAME[=RADIUS],...")
    parser.add_argument("--json", action="store_true", help="print JSON instead of a table")
    parser.add_argument("--grid", type=int, default=GRID_SIZE, metavar="N",
                        help=f"about N grid configurations of the steered angles (default {GRID_SIZE})")
    parser.add_argument("--twists", type=int, default=TWISTS, metavar="N",
                        help=f"add the steering angles of N random twists (default {TWISTS})")
    parser.add_argument("--seed", type=int, default=0,
                        help="seed of the random twists and of the generic configuration")


def _num(x):
    return x if math.isfinite(x) else ("inf" if x > 0 else "-inf")


def _g(x):
    return f"{x:.4g}" if math.isfinite(x) else "inf"


def as_json(ov: Overview) -> dict[str, Any]:
    """The JSON object of an overview.

    Parameters
    ----------
    ov : wmr.analysis.overview.Overview

    Returns
    -------
    dict
    """
    c = ov.campion
    return {"name": ov.name, "wheels": list(ov.kinds), "delta_m": c["delta_m"], "delta_s": c["delta_s"],
            "class": c["label"],
            "rank_F": {"generic": ov.rank_F, "min": ov.rank_F_range[0], "max": ov.rank_F_range[1]},
            "nullity": {"generic": ov.nullity, "min": ov.nullity_range[0], "max": ov.nullity_range[1]},
            "configurations": ov.configurations, "L": ov.L, "kappa_J_L1": _num(ov.kappa_JL1),
            "kappa_J2": _num(ov.kappa_J2),
            "kappa_J": {"min": _num(ov.kappa_J_range[0]), "max": _num(ov.kappa_J_range[1])},
            "isotropic": dict(ov.isotropic), "advice": list(ov.advice), "dead_zone": ov.dead_zone,
            "singular": [{"family": f["family"], "description": f["description"],
                          "beta_deg": [round(math.degrees(b), 6) for b in f["beta"]], "rank_J": f["rank_J"],
                          "rank_F": f["rank_F"]} for f in ov.singular]}


def table(ov: Overview) -> str:
    """The overview as a short aligned table (one fact per row).

    Parameters
    ----------
    ov : wmr.analysis.overview.Overview

    Returns
    -------
    str
    """
    counts: dict[str, int] = {}
    for k in ov.kinds:
        counts[k] = counts.get(k, 0) + 1
    c = ov.campion
    rows = [("robot", ov.name), ("wheels", ", ".join(f"{n} {k}" for k, n in counts.items())),
            ("class", f"{c['label']}: delta_m = {c['delta_m']}, delta_s = {c['delta_s']} (Campion et al. 1996)"),
            ("rank F", f"{ov.rank_F} generic, {ov.rank_F_range[0]}..{ov.rank_F_range[1]} over "
                       f"{ov.configurations:,} configurations"),
            ("nullity F", f"{ov.nullity} generic, {ov.nullity_range[0]}..{ov.nullity_range[1]}"),
            ("L", f"{ov.L:.4g} (the characteristic length minimising kappa(J_L1))"),
            ("kappa(J_L1)", _g(ov.kappa_JL1) + (" isotropic" if ov.isotropic["J_L1"] else "")),
            ("kappa(J2)", _g(ov.kappa_J2) + (" isotropic" if ov.isotropic["J2"] else "") + ", at every configuration"),
            ("kappa(J)", f"{_g(ov.kappa_J_range[0])} .. {_g(ov.kappa_J_range[1])} over the configurations")]
    if ov.dead_zone is not None:
        rows.append(("dead zone", f"radius {ov.dead_zone:.4g}: C's circle when the units are steered without driving "
                                  "(drift-free only for offset 0)"))
    if ov.dead_zone is None and ov.dead_zones and all(z is not None for z in ov.dead_zones):
        rows.append(("dead zone", "none: the offsets differ, the locked units cannot be steered together"))
    if any(ov.steered) and not ov.singular:
        rows.append(("singular", "none found: rank J = 3 at every candidate"))
    for n, f in enumerate(ov.singular):
        beta = ", ".join(f"{math.degrees(b):.4g}" for b in f["beta"])
        rows.append(("singular" if n == 0 else "", f"{f['family']}: {f['description']}; e.g. beta = ({beta}) deg, "
                                                   f"rank J = {f['rank_J']}, rank F = {f['rank_F']}"))
    if not ov.advice:
        rows.append(("isotropy", "J_L1 and J2 are isotropic as designed"))
    for n, a in enumerate(ov.advice):
        rows.append(("to isotropy" if n == 0 else "", a))
    width = max(len(k) for k, _ in rows)
    return "\n".join(f"{k:<{width}}  {v}" for k, v in rows)


def run(args: argparse.Namespace) -> int:
    """Run ``wmr analyze``.

    Parameters
    ----------
    args : argparse.Namespace

    Returns
    -------
    int
        0; bad input raises an input error (:mod:`wmr.errors`; :func:`wmr.cli.main` reports it in one line, status 2).
    """
    import wmr

    from ..analysis.overview import overview
    robot = wmr.load(args.robot, wheel_joints=args.wheel_joints)
    ov = overview(robot, grid=args.grid, twists=args.twists, seed=args.seed)
    print(json.dumps(as_json(ov), indent=2) if args.json else table(ov))
    return 0
