r"""Design advice that is checked: every suggestion is applied to a copy of the robot and re-analysed.

``wmr analyze`` suggests what would make :math:`\mathbf J_{L1}` and :math:`\mathbf J_2` isotropic.  A
suggestion is never printed on faith: the changed robot is built and analysed (:func:`profile`:
Campion's class, the actuated mobility, :math:`L`, :math:`\kappa(\mathbf J_{L1})`,
:math:`\kappa(\mathbf J_2)`), and the advice carries the numbers that result (an :class:`Advice`;
in words: :mod:`wmr.words.advice`).  A change that would cost the robot a motion (another class, a
lower actuated mobility) is **not advised**, with the limitation it would bring
(:func:`wmr.analysis.limitations.limitations` of the changed robot).

* :math:`\mathbf J_{L1}`: C moved to the centroid of the mount points (:meth:`wmr.Robot.moved`), with
  :math:`L^2 = \sum_i\|\mathbf d_i\|^2/w` recomputed for the moved robot.
* :math:`\mathbf J_2`: each unit's own change (:func:`~wmr.analysis.unit_design.isotropic_change`:
  offset = radius, omni rollers), one common radius, and all of them together.
* Actuation: when the motors cannot drive every motion (actuated mobility below
  :math:`\delta_m`), the fewest units rebuilt another way that fix it
  (:func:`~wmr.analysis.unit_design.other_builds`: a mecanum wheel of the other hand).

:math:`\mathbf J_2^T\mathbf J_2 = \mathrm{blockdiag}(\mathbf L_i^T\mathbf L_i)` does not depend on the
configuration, so :math:`\kappa(\mathbf J_2)` is one number per robot.
"""

from __future__ import annotations

import dataclasses
import enum
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
from .limitations import Limitation, limitations
from .linalg import condition_number
from .mobility import admissible_twists
from .unit_design import Change, isotropic_change, other_builds

__all__ = ["Suggestion", "Verdict", "Advice", "advice"]


class Suggestion(enum.Enum):
    """What an :class:`Advice` suggests."""

    MOVE_C = "move C"  #: J_L1: C moved to the centroid of the mount points (``point``, in the robot's frame)
    REBUILD = "rebuild"  #: actuation: ``units`` built another way (``changes``)
    CHANGE_UNITS = "change units"  #: J2: ``units`` given their own isotropic change (``changes``, of one kind)
    SAME_RADIUS = "same radius"  #: J2: every wheel given the largest of its ``radii``
    BOTH = "both"  #: J2: the same radius and every unit's own change together
    SINGULAR = "singular"  #: J2 singular everywhere (``units``: their block drives one direction only)
    EQUAL_VALUES = "equal singular values"  #: J2: no known change; each unit's ``singular_values`` to be equal


class Verdict(enum.Enum):
    """Whether an :class:`Advice` is advised, and why not."""

    ADVISED = "advised"
    COSTS_MOTION = "costs a motion"  #: another class, a lower actuated mobility or an undriven motion (``lost``)
    NO_GAIN = "no gain"  #: the condition number is not lowered


@dataclass(frozen=True)
class Advice:
    """One suggestion, checked on the changed robot.

    Attributes
    ----------
    matrix : str
        ``"J_L1"``, ``"J2"`` or ``"actuation"`` (what the change is for).
    suggestion : Suggestion
        What is changed.
    verdict : Verdict
    before : dict
        :func:`profile` of the robot.
    after : dict
        :func:`profile` of the changed robot (empty when nothing can be changed).
    units : tuple of int
        The units changed or concerned (indices in ``robot.wheels``).
    changes : tuple of Change
        Their changes (``REBUILD``, ``CHANGE_UNITS``).
    kinds : tuple of str
        ``SINGULAR``: the kinds of ``units``.
    point : tuple of float or None
        ``MOVE_C``: the new C, in the robot's frame (round-off of a zero coordinate written 0).
    radii : tuple of float
        ``SAME_RADIUS``, ``BOTH``: the wheels' radii, ascending.
    singular_values : tuple of tuple of float
        ``SINGULAR``, ``EQUAL_VALUES``: those of each unit's block of J2.
    motor_kappa : float or None
        ``REBUILD``: the changed robot's :func:`motor_conditioning`.
    lost : Limitation or None
        ``COSTS_MOTION``: the first limitation the change brings.
    """

    matrix: str
    suggestion: Suggestion
    verdict: Verdict
    before: dict
    after: dict
    units: tuple[int, ...] = ()
    changes: tuple[Change, ...] = ()
    kinds: tuple[str, ...] = ()
    point: tuple[float, ...] | None = None
    radii: tuple[float, ...] = ()
    singular_values: tuple[tuple[float, ...], ...] = ()
    motor_kappa: float | None = None
    lost: Limitation | None = None

    @property
    def advised(self) -> bool:
        """Whether the change is advised (its ``verdict`` is ``ADVISED``).

        Returns
        -------
        bool
        """
        return self.verdict is Verdict.ADVISED


def motor_conditioning(robot, beta) -> float:
    r"""How evenly the motors command the admissible twists: :math:`\kappa` of the map from twist to motor rates.

    :math:`\mathbf M` (n_driven, m) holds the driven joints' rates (:func:`wmr.inverse`) of an orthonormal
    basis of the admissible twists in dimensionless coordinates; ``inf`` when some admissible direction
    needs no motor.
    """
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

    A dict: ``class`` (Campion's label), ``actuated_mobility`` (at the class's generic configuration),
    ``L`` (:func:`wmr.characteristic_length`), ``kappa_JL1`` (at that L), ``kappa_J2``.
    """
    L = float(characteristic_length(robot))
    kappa_JL1 = float(condition_number(robot.J1(L=L)))
    c = campion_class(robot)
    return {
        "class": c.label,
        "actuated_mobility": int(actuated_mobility(robot, np.asarray(c.beta))),
        "L": L,
        "kappa_JL1": kappa_JL1,
        "kappa_J2": float(condition_number(robot.J2(np.zeros(robot.w)))),
    }


def _delta_m(label):
    return int(label.strip("()").split(",")[0])


def _same(a: Limitation, b: Limitation) -> bool:
    """The same limitation: its kind and numbers, its motions along the same lines (up to round-off)."""
    if dataclasses.replace(a, motions=()) != dataclasses.replace(b, motions=()) or len(a.motions) != len(b.motions):
        return False
    pairs = [(np.asarray(m.twist), np.asarray(n.twist)) for m, n in zip(a.motions, b.motions)]
    return all(abs(s @ t) >= (1 - 1e-9) * np.linalg.norm(s) * np.linalg.norm(t) for s, t in pairs)


def _lost(robot, changed, before, after) -> tuple[bool, Limitation | None]:
    """Whether a change costs a motion or leaves one undriven, and the first limitation it brings."""
    if (
        after["class"] == before["class"]
        and after["actuated_mobility"] >= before["actuated_mobility"]
        and after["actuated_mobility"] == _delta_m(after["class"])
    ):
        return False, None
    now, then = limitations(changed), limitations(robot)
    new = [x for x in now if not any(_same(x, y) for y in then)] or now
    return True, (new[0] if new else None)


def _rebuilt(robot, units):
    wheels = list(robot.wheels)
    for k, u in units.items():
        wheels[k] = u
    return type(robot)(wheels, name=robot.name)


def actuation_advice(robot, before=None) -> list[Advice]:
    """When the motors cannot drive every motion: at most one ``REBUILD``, units rebuilt another way (checked).

    Of the sets of at most four units with another build that give an actuated mobility equal to the
    degree of mobility, the one with the smallest :func:`motor_conditioning` (fewer changes on a tie).
    """
    before = profile(robot) if before is None else before
    dm = _delta_m(before["class"])
    if before["actuated_mobility"] >= dm:
        return []
    beta = np.asarray(campion_class(robot).beta)
    options = [(k, c) for k, unit in enumerate(robot.wheels) for c in other_builds(unit)]
    best = None
    for size in range(1, min(4, len(options)) + 1):
        for pick in itertools.combinations(options, size):
            if len({k for k, _ in pick}) < size:
                continue
            changed = _rebuilt(robot, {k: c.unit for k, c in pick})
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
    units, changes = tuple(k for k, _ in pick), tuple(c for _, c in pick)
    return [Advice("actuation", Suggestion.REBUILD, Verdict.ADVISED, before, after, units, changes, motor_kappa=kappa)]


def _change(robot, before, new, suggestion, **data):
    """Advice on J2 for the robot with ``new`` units (index -> unit)."""
    changed = _rebuilt(robot, new)
    after = profile(changed)
    costs, lost = _lost(robot, changed, before, after)
    gain = after["kappa_J2"] < before["kappa_J2"] * (1 - TOL)
    verdict = Verdict.COSTS_MOTION if costs else Verdict.ADVISED if gain else Verdict.NO_GAIN
    return Advice("J2", suggestion, verdict, before, after, lost=lost, **data)


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
    >>> tips[0].suggestion.name, tips[0].advised, tips[0].point, round(tips[0].after["L"], 3), iso["J_L1"]
    ('MOVE_C', True, (1.35, 0.0), 1.557, False)
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
        verdict = Verdict.ADVISED if after["kappa_JL1"] < before["kappa_JL1"] else Verdict.NO_GAIN
        out.append(Advice("J_L1", Suggestion.MOVE_C, verdict, before, after, point=(float(shown[0]), float(shown[1]))))
    sv = [np.linalg.svd(np.asarray(u.block_terms(NUMERIC)[0], dtype=float), compute_uv=False) for u in robot.wheels]
    values = tuple(tuple(float(x) for x in s) for s in sv)
    top = max(float(s.max()) for s in sv)
    deficient = tuple(k for k, s in enumerate(sv) if s.min() <= TOL * top)
    j2 = not deficient and all(np.all(np.abs(s - top) <= TOL * top) for s in sv)
    if deficient:
        kinds = tuple(robot.wheels[k].kind for k in deficient)
        out.append(
            Advice(
                "J2", Suggestion.SINGULAR, Verdict.ADVISED, before, {}, deficient, kinds=kinds, singular_values=values
            )
        )
    elif not j2:
        changes = {k: c for k, u in enumerate(robot.wheels) if (c := isotropic_change(u)) is not None}
        for kind in dict.fromkeys(c.kind for c in changes.values()):  # each unit's own change, grouped by its kind
            group = {k: c for k, c in changes.items() if c.kind is kind}
            new, changed = {k: c.unit for k, c in group.items()}, tuple(group.values())
            out.append(_change(robot, before, new, Suggestion.CHANGE_UNITS, units=tuple(group), changes=changed))
        radii = tuple(sorted({float(u.r) for u in robot.wheels}))
        if len(radii) > 1:
            same = {k: dataclasses.replace(u, r=radii[-1]) for k, u in enumerate(robot.wheels)}
            out.append(_change(robot, before, same, Suggestion.SAME_RADIUS, radii=radii))
            if changes:
                both = {k: (c.unit if (c := isotropic_change(u)) else u) for k, u in same.items()}
                out.append(_change(robot, before, both, Suggestion.BOTH, radii=radii))
        if not changes and len(radii) == 1:
            out.append(Advice("J2", Suggestion.EQUAL_VALUES, Verdict.ADVISED, before, {}, singular_values=values))
    return out, {"J_L1": jl1, "J2": bool(j2)}
