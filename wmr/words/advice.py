r"""Design advice in plain sentences: the words of :mod:`wmr.analysis.advice`' records (``wmr analyze``).

Examples
--------
>>> import wmr
>>> tips, _ = wmr.analysis.advice.advice(wmr.paper_robot("offset", r=0.1, d=0.03))
>>> print(sentence(tips[0]))
J2: set offset = radius on wheel 1, 2, 3 (d = r, the paper's (46)): then kappa(J2) = 1 (now 3.333)
"""

from __future__ import annotations

import math

import numpy as np

from ..analysis.advice import Advice, Suggestion, Verdict
from ..analysis.unit_design import Change, ChangeKind
from . import limitations

__all__ = ["change", "sentence"]

_CHANGES = {
    ChangeKind.OFFSET_EQUALS_RADIUS: "set offset = radius on wheel {wheels} (d = r, the paper's (46))",
    ChangeKind.OMNI_ROLLERS: "use omni wheels (rollers at 90 deg) on wheel {wheels}: a Swedish wheel's block "
    "r[[0, sin g], [-1, -cos g]] has singular values r sqrt(1 +- cos g)",
}


def change(c: Change) -> str:
    """A unit's change in words: an isotropic change about ``{wheels}`` (a format field for the wheel numbers),
    another build the words after "build wheel k".

    Parameters
    ----------
    c : wmr.analysis.unit_design.Change

    Returns
    -------
    str
    """
    if c.kind is ChangeKind.OTHER_HAND:
        return f"of the other hand (rollers at {np.degrees(float(c.unit.roller)):.0f} deg)"  # type: ignore[attr-defined]
    return _CHANGES[c.kind]


def _g(x):
    return f"{x:.4g}" if math.isfinite(x) else "inf"


def sentence(a: Advice) -> str:
    """A piece of advice in one sentence, with the numbers of the changed robot.

    Parameters
    ----------
    a : wmr.analysis.advice.Advice

    Returns
    -------
    str
    """
    b, f, S = a.before, a.after, Suggestion
    wheels = ", ".join(str(k + 1) for k in a.units)
    if a.suggestion is S.MOVE_C:
        x, y = a.point or (0.0, 0.0)
        return (
            f"J_L1: move C to the centroid of the mount points, ({x:.4g}, {y:.4g}) in this frame (subtract it from "
            f"every position); then L = {f['L']:.4g} gives kappa(J_L1) = {_g(f['kappa_JL1'])} (now "
            f"{_g(b['kappa_JL1'])} at L = {b['L']:.4g})"
        )
    if a.suggestion is S.REBUILD:
        what = "; ".join(f"wheel {k + 1} {change(c)}" for k, c in zip(a.units, a.changes))
        return (
            f"actuation: build {what}: then actuated mobility {f['actuated_mobility']} (now "
            f"{b['actuated_mobility']}), the motors' map to the twist has condition number {a.motor_kappa:.4g}, "
            f"kappa(J2) = {_g(f['kappa_J2'])}"
        )
    if a.suggestion is S.SINGULAR:
        return (
            f"J2: singular at every configuration ({', '.join(sorted(set(a.kinds)))} units: wheel {wheels} drive "
            "their mount point through one direction only); no choice of lengths makes it isotropic"
        )
    if a.suggestion is S.EQUAL_VALUES:
        blocks = "; ".join(f"wheel {k}: {', '.join(f'{x:.4g}' for x in s)}" for k, s in enumerate(a.singular_values, 1))
        return f"J2: kappa(J2) = {_g(b['kappa_J2'])}: make the singular values of every unit's block equal ({blocks})"
    if a.suggestion is S.CHANGE_UNITS:
        what = change(a.changes[0]).format(wheels=wheels)
    elif a.suggestion is S.SAME_RADIUS:
        what = f"give every wheel the radius {a.radii[-1]:.4g} (now {', '.join(f'{r:.4g}' for r in a.radii)})"
    else:
        what = "both changes together"
    why = {Verdict.ADVISED: "", Verdict.NO_GAIN: ": no gain by itself"}.get(a.verdict)
    if why is None:
        why = (
            f"; not advised: class {f['class']} (now {b['class']}), actuated mobility {f['actuated_mobility']} "
            f"(now {b['actuated_mobility']})" + ("" if a.lost is None else f" -- {limitations.sentence(a.lost)}")
        )
    return f"J2: {what}: then kappa(J2) = {_g(f['kappa_J2'])} (now {_g(b['kappa_J2'])}){why}"
