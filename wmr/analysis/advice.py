r"""Design advice that is checked: every suggestion is applied to a copy of the robot and re-analysed.

``wmr analyze`` suggests what would make :math:`\mathbf J_{L1}` and :math:`\mathbf J_2` isotropic.  A
suggestion is never printed on faith: the changed robot is built and analysed (:func:`profile`:
Campion's class, the actuated mobility, :math:`L`, :math:`\kappa(\mathbf J_{L1})`,
:math:`\kappa(\mathbf J_2)`), and the advice carries the numbers that result.  A change that would
cost the robot a motion (another class, a lower actuated mobility) is reported as **not advised**,
with the limitation it would bring (:func:`wmr.analysis.limitations.limitations` of the changed
robot).

* :math:`\mathbf J_{L1}`: C moved to the centroid of the mount points (:meth:`wmr.Robot.moved`); the
  characteristic length is recomputed for the moved robot -- it is not the old one
  (:mod:`wmr.analysis.overview`: :math:`L^2 = \sum_i\|\mathbf d_i\|^2/w` depends on where C is).
* :math:`\mathbf J_2`: each unit's own change (:func:`~wmr.analysis.unit_design.isotropic_change`:
  offset = radius, omni rollers), one common radius, and all of them together.  A change is not
  advised either when the changed robot's motors cannot drive every motion it can make.
* Actuation: when the motors cannot drive every motion (actuated mobility below
  :math:`\delta_m`), the fewest units rebuilt another way that fix it
  (:func:`~wmr.analysis.unit_design.other_builds`: a mecanum wheel of the other hand).

:math:`\mathbf J_2^T\mathbf J_2 = \mathrm{blockdiag}(\mathbf L_i^T\mathbf L_i)` does not depend on the
configuration, so :math:`\kappa(\mathbf J_2)` is one number per robot.
"""

from __future__ import annotations

import dataclasses
import itertools
from dataclasses import dataclass

import numpy as np

from ..model import validation
from ..model.backend import NUMERIC
from ..model.tolerance import TOL
from .actuation import actuated_mobility, driven_columns
from .classes import campion_class
from .isotropy import characteristic_length
from .kinematics import inverse
from .limitations import limitations
from .linalg import condition_number
from .mobility import admissible_twists
from .unit_design import isotropic_change, other_builds

__all__ = ["Advice", "profile", "advice", "actuation_advice", "motor_conditioning"]


@dataclass(frozen=True)
class Advice:
    """One suggestion, checked on the changed robot.

    Attributes
    ----------
    matrix : str
        ``"J_L1"``, ``"J2"`` or ``"actuation"`` (what the change is for).
    text : str
        The suggestion with the numbers that result (one sentence).
    advised : bool
        False when the change would cost a motion (another class or a lower actuated mobility) or, on
        J2, would not lower its condition number.
    before : dict
        :func:`profile` of the robot.
    after : dict
        :func:`profile` of the changed robot (empty when nothing can be changed).
    """

    matrix: str
    text: str
    advised: bool
    before: dict
    after: dict


def motor_conditioning(robot, beta) -> float:
    r"""How evenly the motors command the admissible twists: :math:`\kappa` of the map from twist to motor rates.

    With an orthonormal basis :math:`\hat{\mathbf T}` of the admissible twists in dimensionless
    coordinates (:func:`wmr.admissible_twists`, scaled), the motor rates of each basis twist
    (:func:`wmr.inverse`, driven columns) form :math:`\mathbf M`; its condition number is 1 when
    every admissible direction costs the motors the same, ``inf`` when some admissible direction
    needs no motor (actuated mobility below the dimension of the admissible twists).

    Parameters
    ----------
    robot : Robot
    beta : array (w,)

    Returns
    -------
    float

    Examples
    --------
    >>> import wmr
    >>> kiwi = wmr.Robot([wmr.SwedishWheel((0.2 * np.cos(a), 0.2 * np.sin(a)), r=0.05, angle=a, roller=np.pi / 2)
    ...                   for a in np.radians([90, 210, 330])])
    >>> round(motor_conditioning(kiwi, np.zeros(3)) ** 2, 9)       # M^T M = diag(3, 3/2, 3/2) / r^2
    2.0
    """
    robot = validation.numeric_robot(robot)
    beta = robot.effective_beta(beta)
    s = robot.F_column_norms[:3]  # dimensionless twist coordinates
    T = admissible_twists(robot, beta) * s[:, None]  # dimensionless, then orthonormalised
    if T.shape[1] == 0:
        return float("inf")
    Q, _ = np.linalg.qr(T)
    rates = inverse(robot, beta, (Q / s[:, None]).T).value  # (m, n_rates)
    M = rates[:, driven_columns(robot)].T  # (n_driven, m)
    if M.shape[0] < M.shape[1]:
        return float("inf")
    return float(condition_number(M))


def profile(robot) -> dict:
    r"""What advice is judged by: class, actuated mobility, L, :math:`\kappa(\mathbf J_{L1})`, kappa(J2).

    Parameters
    ----------
    robot : Robot
        A numeric robot.

    Returns
    -------
    dict
        ``class`` (Campion's label), ``actuated_mobility`` (at the class's generic configuration),
        ``L`` (:func:`wmr.characteristic_length`), ``kappa_JL1`` (at that L), ``kappa_J2`` (floats).

    Examples
    --------
    >>> import wmr
    >>> p = profile(wmr.paper_robot("offset", L=0.3, r=0.05, d=0.05))
    >>> p["class"], p["actuated_mobility"], round(p["L"], 12), round(p["kappa_JL1"], 12), round(p["kappa_J2"], 12)
    ('(3,0)', 3, 0.3, 1.0, 1.0)
    """
    robot = validation.numeric_robot(robot)
    c = campion_class(robot)
    L = float(characteristic_length(robot))
    return {
        "class": c.label,
        "actuated_mobility": int(actuated_mobility(robot, np.asarray(c.beta))),
        "L": L,
        "kappa_JL1": float(condition_number(robot.J1(L=L))),
        "kappa_J2": float(condition_number(robot.J2(np.zeros(robot.w)))),
    }


def _g(x):
    return f"{x:.4g}" if np.isfinite(x) else "inf"


def _delta_m(label):
    return int(label.strip("()").split(",")[0])


def _lost(robot, changed, before, after):
    """Why a change is not advised (empty when it costs no motion and its motors drive every motion)."""
    if (
        after["class"] == before["class"]
        and after["actuated_mobility"] >= before["actuated_mobility"]
        and after["actuated_mobility"] == _delta_m(after["class"])
    ):
        return ""
    new = [s for s in limitations(changed) if s not in limitations(robot)] or limitations(changed)
    why = (
        f"class {after['class']} (now {before['class']}), actuated mobility {after['actuated_mobility']} "
        f"(now {before['actuated_mobility']})"
    )
    return f"; not advised: {why}" + (f" -- {new[0]}" if new else "")


def _rebuilt(robot, units):
    wheels = list(robot.wheels)
    for k, u in units.items():
        wheels[k] = u
    return type(robot)(wheels, name=robot.name)


def actuation_advice(robot, before=None) -> list[Advice]:
    """When the motors cannot drive every motion: units rebuilt another way that fix it (checked).

    Tries every set of at most four of the units that have another build
    (:func:`~wmr.analysis.unit_design.other_builds`), keeps those that give an actuated mobility
    equal to the degree of mobility, and advises the one whose motors command the admissible
    twists most evenly (:func:`~wmr.analysis.advice.motor_conditioning`; fewer changes first on
    a tie); nothing when none does or nothing is lost.

    Parameters
    ----------
    robot : Robot
    before : dict, optional
        Its :func:`profile`.

    Returns
    -------
    list of Advice
    """
    robot = validation.numeric_robot(robot)
    before = profile(robot) if before is None else before
    dm = _delta_m(before["class"])
    if before["actuated_mobility"] >= dm:
        return []
    beta = np.asarray(campion_class(robot).beta)
    options = [(k, c.words, c.unit) for k, unit in enumerate(robot.wheels) for c in other_builds(unit)]
    best = None
    for size in range(1, min(4, len(options)) + 1):
        for pick in itertools.combinations(options, size):
            if len({k for k, _, _ in pick}) < size:
                continue
            changed = _rebuilt(robot, {k: u for k, _, u in pick})
            if int(actuated_mobility(changed, beta)) < dm:
                continue
            key = (round(motor_conditioning(changed, beta), 9), size)
            if best is None or key < best[0]:
                best = (key, pick, changed)
    if best is None:
        return []
    (kappa, _), pick, changed = best
    after = profile(changed)
    if after["class"] != before["class"] or after["actuated_mobility"] < dm:
        return []
    what = "; ".join(f"wheel {k + 1} {words}" for k, words, _ in pick)
    return [
        Advice(
            "actuation",
            f"actuation: build {what}: then actuated mobility {after['actuated_mobility']} "
            f"(now {before['actuated_mobility']}), the motors' map to the twist has condition number "
            f"{kappa:.4g}, kappa(J2) = {_g(after['kappa_J2'])}",
            True,
            before,
            after,
        )
    ]


def _change(robot, before, units, what):
    """Advice on J2 for the robot with ``units`` (index -> new unit) changed."""
    changed = _rebuilt(robot, units)
    after = profile(changed)
    lost = _lost(robot, changed, before, after)
    gain = after["kappa_J2"] < before["kappa_J2"] * (1 - TOL)
    text = (
        f"J2: {what}: then kappa(J2) = {_g(after['kappa_J2'])} (now {_g(before['kappa_J2'])})"
        f"{lost or ('' if gain else ': no gain by itself')}"
    )
    return Advice("J2", text, gain and not lost, before, after)


def advice(robot, before=None) -> tuple[list[Advice], dict]:
    r"""Checked advice on :math:`\mathbf J_{L1}` and :math:`\mathbf J_2` (module notes), and whether each is isotropic.

    Parameters
    ----------
    robot : Robot
        A numeric robot.
    before : dict, optional
        Its :func:`profile`, when already computed.

    Returns
    -------
    advice : list of Advice
        Empty when both matrices are isotropic.
    isotropic : dict
        ``{"J_L1": bool, "J2": bool}``.

    Examples
    --------
    >>> import wmr
    >>> car = wmr.Robot([wmr.FixedWheel((0.0, 0.775), r=0.33, angle=np.pi / 2),
    ...                  wmr.FixedWheel((0.0, -0.775), r=0.33, angle=np.pi / 2),
    ...                  wmr.CentredWheel((2.7, 0.775), r=0.33), wmr.CentredWheel((2.7, -0.775), r=0.33)])
    >>> tips, iso = advice(car)
    >>> print(tips[0].text.replace("; ", ";\n"))
    J_L1: move C to the centroid of the mount points, (1.35, 0) in this frame (subtract it from every position);
    then L = 1.557 gives kappa(J_L1) = 1 (now 2.191 at L = 2.06)
    """
    robot = validation.numeric_robot(robot)
    before = profile(robot) if before is None else before
    out = actuation_advice(robot, before)
    pts = robot.mount_points
    centroid = pts.mean(axis=0)
    zero = np.abs(centroid) <= TOL * float(np.abs(pts).max())
    jl1 = bool(np.all(zero))
    if not jl1:
        moved = robot.moved(origin=centroid)
        shown = np.where(zero, 0.0, centroid) + 0.0  # round-off of a zero coordinate shown as 0
        after = profile(moved)
        ok = after["kappa_JL1"] < before["kappa_JL1"]
        out.append(
            Advice(
                "J_L1",
                f"J_L1: move C to the centroid of the mount points, ({shown[0]:.4g}, "
                f"{shown[1]:.4g}) in this frame (subtract it from every position); then L = "
                f"{after['L']:.4g} gives kappa(J_L1) = {_g(after['kappa_JL1'])} (now "
                f"{_g(before['kappa_JL1'])} at L = {before['L']:.4g})",
                ok,
                before,
                after,
            )
        )
    sv = [np.linalg.svd(np.asarray(u.block_terms(NUMERIC)[0], dtype=float), compute_uv=False) for u in robot.wheels]
    top = max(float(s.max()) for s in sv)
    deficient = [k for k, s in enumerate(sv, 1) if s.min() <= TOL * top]
    j2 = not deficient and all(np.all(np.abs(s - top) <= TOL * top) for s in sv)
    if deficient:
        kinds = sorted({robot.wheels[k - 1].kind for k in deficient})
        out.append(
            Advice(
                "J2",
                f"J2: singular at every configuration ({', '.join(kinds)} units: wheel "
                f"{', '.join(map(str, deficient))} drive their mount point through one direction only); "
                "no choice of lengths makes it isotropic",
                True,
                before,
                {},
            )
        )
    elif not j2:
        changes = {k: c for k, u in enumerate(robot.wheels) if (c := isotropic_change(u)) is not None}
        groups: dict[str, list[int]] = {}  # each unit's own change, wheels grouped by its words
        for k, c in changes.items():
            groups.setdefault(c.words, []).append(k)
        for hint, ks in groups.items():
            what = hint.format(wheels=", ".join(str(k + 1) for k in ks))
            out.append(_change(robot, before, {k: changes[k].unit for k in ks}, what))
        radii = sorted({float(u.r) for u in robot.wheels})
        if len(radii) > 1:
            same = {k: dataclasses.replace(u, r=radii[-1]) for k, u in enumerate(robot.wheels)}
            out.append(
                _change(
                    robot,
                    before,
                    same,
                    f"give every wheel the radius {radii[-1]:.4g} (now {', '.join(f'{r:.4g}' for r in radii)})",
                )
            )
            if groups:
                both = {k: (c.unit if (c := isotropic_change(u)) else u) for k, u in same.items()}
                out.append(_change(robot, before, both, "both changes together"))
        if not groups and len(radii) == 1:
            out.append(
                Advice(
                    "J2",
                    f"J2: kappa(J2) = {_g(before['kappa_J2'])}: make the singular values of every "
                    "unit's block equal ("
                    + "; ".join(f"wheel {k}: {', '.join(f'{x:.4g}' for x in s)}" for k, s in enumerate(sv, 1))
                    + ")",
                    True,
                    before,
                    {},
                )
            )
    return out, {"J_L1": jl1, "J2": bool(j2)}
