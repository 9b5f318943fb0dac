"""``wmr analyze ROBOT.toml``: class, actuation, limitations, mobility, isotropy, singular configurations of a robot.

Example::

    wmr analyze examples/swerve4.toml --convention wpilib

A short aligned table for people, with notes under it that say what its rows mean (``--brief``
leaves them out; ``wmr explain TERM`` says more); ``--json`` prints the same numbers for programs
(keys ``delta_m``, ``delta_s``, ``class``, ``actuated_mobility``, ``limitations``, ``rank_F``,
``nullity``, ``kappa_J_L1``, ...; infinities as the string ``"inf"``; angles in degrees, in the
convention chosen).  The computation is :func:`wmr.analysis.overview.overview`.
"""

from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING, Any

import numpy as np

from ..words import advice as advice_words
from ..words import families as words
from ..words import limitations as limitation_words

if TYPE_CHECKING:  # (the command imports the library when it runs)
    from ..analysis.overview import Overview

__all__ = ["run"]

#: the glossary terms the table uses, in its order
TERMS = ("class", "actuated-mobility", "rank-F", "nullity", "L", "J_L1", "J2", "J", "singular", "isotropic")


def run(args: argparse.Namespace) -> int:
    """Run ``wmr analyze``.

    Parameters
    ----------
    args : argparse.Namespace
        The options of ``wmr analyze`` (:func:`wmr.cli.main` parses them).

    Returns
    -------
    int
        0; bad input raises an input error (:mod:`wmr.errors`; :func:`wmr.cli.main` reports it in one line, status 2).
    """
    import wmr

    from ..analysis.overview import overview
    from ..io.decimals import length_scale

    robot = wmr.load(args.robot, wheel_joints=args.wheel_joints)
    ov = overview(robot, grid=args.grid, twists=args.twists, seed=args.seed)
    if args.json:
        from ._numbers import json_text

        print(json_text(as_json(ov, args.convention), scales={"L": length_scale(robot)}))
    else:
        print(table(ov, args.convention, args.brief))
    return 0


def _num(x):
    return x if math.isfinite(x) else ("inf" if x > 0 else "-inf")


def _g(x):
    return f"{x:.4g}" if math.isfinite(x) else "inf"


def _angles(beta, convention):
    from ..model.conventions import angle_to

    return [round(math.degrees(b), 6) + 0.0 for b in angle_to(np.asarray(beta, dtype=float), convention)]


def as_json(ov: Overview, convention: str = "wmr") -> dict[str, Any]:
    """The JSON object of an overview, the singular configurations' angles in degrees in ``convention``."""
    kappa_J = {**{k: _num(v) for k, v in ov.kappa_J.items()}, "drivable_configurations": ov.drivable}
    angles = [_angles(f["beta"], convention) for f in ov.singular]  # the numbers first, then the words
    c = ov.campion
    return {
        "name": ov.name,
        "wheels": list(ov.kinds),
        "delta_m": c["delta_m"],
        "delta_s": c["delta_s"],
        "class": c["label"],
        "class_name": c["name"],
        "actuated_mobility": ov.actuated_mobility,
        "uncontrolled": [limitation_words.where(m) for m in ov.uncontrolled],
        "limitations": [limitation_words.sentence(x) for x in ov.limitations],
        "rank_F": {"generic": ov.rank_F, "min": ov.rank_F_range[0], "max": ov.rank_F_range[1]},
        "nullity": {"generic": ov.nullity, "min": ov.nullity_range[0], "max": ov.nullity_range[1]},
        "configurations": ov.configurations,
        "L": ov.L,
        "kappa_J_L1": _num(ov.kappa_JL1),
        "kappa_J2": _num(ov.kappa_J2),
        "kappa_J": kappa_J,
        "isotropic": dict(ov.isotropic),
        "advice": [advice_words.sentence(a) for a in ov.advice],
        "advised": list(ov.advised),
        "dead_zone": ov.dead_zone,
        "convention": convention,
        "singular": [
            {
                "family": f["family"],
                "description": words.description(f["family"]),
                "meaning": words.meaning(f["family"]),
                "angles_deg": beta,
                "rank_J": f["rank_J"],
                "rank_F": f["rank_F"],
            }
            for f, beta in zip(ov.singular, angles)
        ],
    }


def table(ov: Overview, convention: str = "wmr", brief: bool = False) -> str:
    """The overview as a short aligned table (one fact per row) and, unless ``brief``, the notes under it:
    one line per glossary term the table uses (:mod:`wmr.words.glossary`)."""
    from ..words.glossary import lookup

    kj = {k: _g(v) for k, v in ov.kappa_J.items()}  # the numbers first, then the words
    angles = [", ".join(f"{a:.4g}" for a in _angles(f["beta"], convention)) for f in ov.singular]
    counts: dict[str, int] = {}
    for k in ov.kinds:
        counts[k] = counts.get(k, 0) + 1
    c = ov.campion
    if ov.actuated_mobility < c["delta_m"]:
        actuated = f"{ov.actuated_mobility} of delta_m = {c['delta_m']}: the motors cannot move it " + " or ".join(
            limitation_words.where(m) for m in ov.uncontrolled
        )
    else:
        actuated = f"{ov.actuated_mobility}: the motors command every motion it can make"
    rows = [
        ("robot", ov.name),
        ("wheels", ", ".join(f"{n} {k}" for k, n in counts.items())),
        (
            "class",
            f"{c['label']}: delta_m = {c['delta_m']}, delta_s = {c['delta_s']}, {c['name']} (Campion et al. 1996)",
        ),
        ("actuated", actuated),
    ]
    rows += [("limitation" if n == 0 else "", limitation_words.sentence(x)) for n, x in enumerate(ov.limitations)]
    rows += [
        (
            "rank F",
            f"{ov.rank_F} generic, {ov.rank_F_range[0]}..{ov.rank_F_range[1]} over "
            f"{ov.configurations:,} configurations",
        ),
        ("nullity F", f"{ov.nullity} generic, {ov.nullity_range[0]}..{ov.nullity_range[1]}"),
        ("L", f"{ov.L:.4g} (the characteristic length minimising kappa(J_L1) with C where it is)"),
        ("kappa(J_L1)", _g(ov.kappa_JL1) + (" isotropic" if ov.isotropic["J_L1"] else "")),
        ("kappa(J2)", _g(ov.kappa_J2) + (" isotropic" if ov.isotropic["J2"] else "") + ", at every configuration"),
        (
            "kappa(J)",
            f"{kj['min']} .. {kj['max']}, median {kj['median']}, 95% below "
            f"{kj['p95']}, over {ov.drivable:,} drivable configurations",
        ),
    ]
    if ov.dead_zone is not None:
        rows.append(
            (
                "dead zone",
                f"radius {ov.dead_zone:.4g}: C's circle when the units are steered without driving "
                "(drift-free only for offset 0)",
            )
        )
    if ov.dead_zone is None and ov.dead_zones and all(z is not None for z in ov.dead_zones):
        rows.append(("dead zone", "none: the offsets differ, the locked units cannot be steered together"))
    if any(ov.steered) and not ov.singular:
        rows.append(("singular", "none found: rank J = 3 at every candidate"))
    unit = "axle angles" if convention == "wmr" else f"{convention} module angles"
    for n, (f, beta) in enumerate(zip(ov.singular, angles)):
        rows.append(
            (
                "singular" if n == 0 else "",
                f"{f['family']}: {words.description(f['family'])}; e.g. ({beta}) deg {unit}, rank J = {f['rank_J']}",
            )
        )
        rows.append(("", f"  means: {words.meaning(f['family'])}"))
    if not ov.advice:
        rows.append(("isotropy", "J_L1 and J2 are isotropic as designed"))
    for n, a in enumerate(ov.advice):
        rows.append(("advice" if n == 0 else "", advice_words.sentence(a)))
    width = max(len(k) for k, _ in rows)
    lines = [f"{k:<{width}}  {v}" for k, v in rows]
    if not brief:
        lines += ["", "What the rows mean (wmr explain TERM for more):"]
        lines += [f"  {lookup(t).term:<18} {lookup(t).short}" for t in TERMS if t != "singular" or ov.singular]
    return "\n".join(lines)
