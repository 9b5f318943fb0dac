r"""A robot at a glance: class, mobility, isotropy, drift and singularities (what ``wmr analyze`` reports).

Everything is computed from the batched kernels (:func:`wmr.sweep` over a set of configurations,
:func:`wmr.rank_F`, :func:`wmr.condition_number`, :meth:`wmr.Robot.J`); nothing is specific to the
paper's robots.

The configurations examined (:func:`configurations`) are a regular grid over the steering
angles of the steered units together with the configurations that admit a motion
(:func:`wmr.steering_angles` of a sample of twists: translations, spins about C, about each mount
point and about random points).  The rank of F drops exactly at configurations of the second
kind, which a grid or a random sample would almost surely miss, so the minimum of rank F is
found; its maximum is the generic value.

Characteristic length.  With :math:`a = \sum_i\|\mathbf d_i\|^2`, :math:`\mathbf b = \sum_i\mathbf E\mathbf d_i`,
(34) reads
:math:`\mathbf J_{L1}^T\mathbf J_{L1} = \begin{bmatrix}a/L^2 & \mathbf b^T/L\\ \mathbf b/L & w\mathbf 1\end{bmatrix}`,
whose eigenvalues are :math:`w` and :math:`\mu_\pm` with :math:`\mu_+ + \mu_- = a/L^2 + w`,
:math:`\mu_+\mu_- = (a/L^2)(w - \|\mathbf b\|^2/a)`; :math:`\kappa^2 = \mu_+/\mu_-` is smallest at
:math:`a/L^2 = w`, i.e. at :func:`wmr.characteristic_length` :math:`L^2 = a/w` wherever C is, where
:math:`\kappa(\mathbf J_{L1}) = \sqrt{(w + c)/(w - c)}`, :math:`c = \|\sum_i\mathbf d_i\|\sqrt{w/a}`:
isotropic exactly when C is the centroid of the mount points.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..model import validation as V
from ..model.backend import NUMERIC
from ..model.platform import wrap_angle
from ..model.robot import Robot
from ..model.tolerance import TOL
from ..model.types import FloatArray
from .classes import campion_class
from .isotropy import characteristic_length
from .linalg import condition_number, rank
from .lines import AT_INFINITY, FINITE, lines_concurrency, planes_through, wheel_plane_lines
from .mobility import rank_F
from .singularities import classify
from .steering import steering_angles
from .sweep import Grid, Sample, sweep

__all__ = ["FAMILIES", "Overview", "configurations", "dead_zone_radius", "singular_families", "overview"]

#: about this many grid configurations are examined (the grid has at least 4 values per steered angle)
GRID_SIZE = 20000
#: random twists whose steering angles are added to the grid
TWISTS = 2000


def configurations(robot: Robot, grid: int = GRID_SIZE, twists: int = TWISTS, seed: int = 0) -> FloatArray:
    """The configurations :func:`overview` examines: a grid over the steered angles and motion configurations.

    Parameters
    ----------
    robot : Robot
        A numeric robot.
    grid : int, optional
        About how many grid configurations (each steered angle takes
        ``max(4, floor(grid ** (1 / s)))`` values in :math:`[-\\pi, \\pi)` for ``s`` steered units;
        when that would make more than ``4 * grid`` configurations, ``grid`` random ones instead).
    twists : int, optional
        How many random twists' steering angles (:func:`wmr.steering_angles`) to add, besides
        the translations along the body axes and the spins about C and about each mount point.
    seed : int, optional
        Seed of the random twists.

    Returns
    -------
    numpy.ndarray (N, w)
        Angles of fixed and Swedish units are 0 (ignored by the model).

    Examples
    --------
    >>> import wmr
    >>> configurations(wmr.paper_robot("centred"), grid=64, twists=10).shape
    (81, 3)
    """
    robot = V.numeric_robot(robot)
    grid = V.integer("grid", grid, minimum=1)
    twists = V.integer("twists", twists, minimum=0)
    seed = V.integer("seed", seed, minimum=0)
    w, steered = robot.w, np.array(robot.steered, dtype=bool)
    s = int(steered.sum())
    parts: list[FloatArray] = []
    if s:
        steps = max(4, int(np.floor(grid ** (1.0 / s) + 1e-9)))
        if steps ** s <= 4 * grid:
            g = Grid(steps)
            sub = g.configurations(s, 0, g.size(s))
        else:                                        # many steered units: a seeded sample of the same size
            sub = Sample(grid, seed=seed).configurations(s, 0, grid)
        full = np.zeros((sub.shape[0], w))
        full[:, steered] = sub
        parts.append(full)
    size = float(np.abs(robot.mount_points).max()) or 1.0
    rng = np.random.default_rng(seed)
    special = [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 1.0], [1.0, 0.0, 0.0]]
    special += [[1.0, d[1], -d[0]] for d in robot.mount_points]           # spin about P_i: c_dot = -psi E d_i
    tw = np.concatenate([np.array(special), np.c_[rng.uniform(-1, 1, (twists, 1)) / size,
                                                  rng.uniform(-1, 1, (twists, 2))]])
    parts.append(steering_angles(robot, tw))
    return np.concatenate(parts)


def dead_zone_radius(robot: Robot) -> float | None:
    r"""Radius of the dead zone of a robot on offset wheels: C's circle when the units are steered without driving.

    With every unit an offset wheel of the same offset d, steering all units together with the
    drives locked moves C on a circle of radius d about the fixed centroid of the contact points
    (the paper's dead zone, checked by simulation in ``edition.checks.assembly.dead_zone``).
    Only d = 0 is drift-free, and then :math:`\kappa(\mathbf J_2) = \infty`.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    float or None
        d; None when some unit has no dead zone (it is not an offset wheel:
        :meth:`~wmr.model.wheels.WheelUnit.dead_zone`) or the offsets differ (the locked units then
        cannot be steered together).

    Examples
    --------
    >>> import wmr
    >>> dead_zone_radius(wmr.paper_robot("offset", r=0.1, d=0.03))
    0.03
    >>> dead_zone_radius(wmr.paper_robot("centred")) is None
    True
    """
    robot = V.numeric_robot(robot)
    zones = [u.dead_zone() for u in robot.wheels]
    if any(z is None for z in zones):
        return None
    d = np.array(zones, dtype=float)
    return float(d[0]) if np.all(np.abs(d - d[0]) <= TOL * d.max()) else None


#: plain words for the families of :func:`wmr.analysis.singularities.classify` and of :func:`_family`
FAMILIES = {
    "i": "all wheel planes parallel, equal angles",
    "i'": "all wheel planes parallel, a wheel turned by 180 deg",
    "pair": "the planes of two wheels on the line through their mount points",
    "v-C": "wheel planes concurrent at C",
    "v-P": "wheel planes concurrent at a mount point",
    "v-circle": "wheel planes concurrent and axles concurrent (rotation about a point of the circle through the P_i)",
    "v": "wheel planes concurrent at another point",
    "parallel": "all wheel planes parallel",
    "through-C": "wheel planes concurrent at C",
    "through-P": "wheel planes concurrent at a mount point",
    "through-point": "wheel planes concurrent at another point",
    "other": "rank J < 3",
}


def _family(robot, beta):
    """Short name of the family of a singular configuration, from where its wheel-plane lines meet."""
    if robot.w == 3 and robot.n_rates == 3 and all(u.steered and u.rolls_in_plane for u in robot.wheels):
        return classify(robot, beta).family                     # three centred wheels: the paper's families
    P, u = wheel_plane_lines(robot, beta)
    lined = [k for k, unit in enumerate(robot.wheels) if unit.rolls_in_plane]     # their planes constrain
    if len(lined) < 2:
        return "other"
    meet = lines_concurrency(P[lined], u[lined])
    if meet.kind == AT_INFINITY:
        return "parallel"
    if meet.kind != FINITE or meet.point is None:
        return "other"
    scale = float(np.abs(robot.mount_points).max())
    if np.linalg.norm(meet.point) <= TOL * scale:
        return "through-C"
    if np.any(np.linalg.norm(robot.mount_points - meet.point, axis=1) <= TOL * scale):
        return "through-P"
    return "through-point"


def _describe(family):
    if family.startswith("pair-"):
        i, j = family[5], family[6]
        turned = ", one turned by 180 deg" if family.endswith("'") else ""
        return f"the planes of wheels {i} and {j} on the line P{i}P{j}{turned}"
    return FAMILIES.get(family, family)


def singular_families(robot: Robot, L: float | None = None) -> list[dict[str, Any]]:
    r"""Families of singular configurations, :math:`\operatorname{rank}\mathbf J < 3` (56), with one example each.

    :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` loses rank where the wheel rates no longer
    control every twist: for centred and dual units, where the wheel-plane lines are concurrent
    or all parallel (:mod:`wmr.analysis.singularities`).  Candidates: the wheel planes of the
    steered units through C, through each mount point, through a point off the robot and parallel
    to a few directions (those of the fixed wheels included); those of rank J < 3 are kept, one per
    family (named by :func:`wmr.analysis.singularities.classify` for three centred wheels).

    Parameters
    ----------
    robot : Robot
    L : float, optional
        Characteristic length of :math:`\mathbf J_{L1}` (default :func:`wmr.characteristic_length`).

    Returns
    -------
    list of dict
        ``family`` (a short name), ``description`` (plain words), ``beta`` (w angles, radians), ``rank_J``,
        ``rank_F`` (ints); empty when
        no candidate is singular (e.g. offset wheels, d > 0: J2 is invertible).

    Examples
    --------
    >>> import wmr
    >>> [f["family"] for f in singular_families(wmr.paper_robot("centred"))]
    ['i', 'v-C', 'v-P', 'v', "i'"]
    >>> singular_families(wmr.paper_robot("offset", d=0.5))
    []
    """
    robot = V.numeric_robot(robot)
    L = characteristic_length(robot) if L is None else V.number("L", V.positive("L", L))
    steered = np.array(robot.steered, dtype=bool)
    pts = robot.mount_points
    size = float(np.abs(pts).max()) or 1.0
    fixed_dirs = [[-np.sin(float(u.constant_angle)), np.cos(float(u.constant_angle))] for u in robot.wheels
                  if u.constant_angle is not None]
    dirs = np.array([[1.0, 0.0], [0.0, 1.0], [0.6, 0.8]] + fixed_dirs)
    finite = np.array([[0.0, 0.0], *pts, [0.37 * size, 0.61 * size]])
    beta_inf = np.arctan2(-dirs[:, :1], dirs[:, 1:]) * np.ones(robot.w)      # j_i || direction, every unit
    beta_fin = planes_through(robot, finite)
    for k in range(len(pts)):                                                 # D = P_k: wheel k's angle is free;
        beta_fin[1 + k, k] = 0.4                                              # a generic value, not 0
    cands = np.concatenate([beta_inf, beta_fin])
    flip = cands.copy()
    flip[:, np.flatnonzero(steered)[:1]] += np.pi                             # one wheel turned by pi: the "'" families
    cands = np.concatenate([cands, flip])
    cands = robot.effective_beta(cands)                                      # unsteered units at their own angle
    rk = rank(robot.J(cands, L=L))
    rf = rank_F(robot, cands)
    out, seen = [], set()
    for b, r, f in zip(cands, rk, rf):
        if r >= 3:
            continue
        fam = _family(robot, b)
        if fam in seen:
            continue
        seen.add(fam)
        out.append({"family": fam, "description": _describe(fam), "beta": wrap_angle(b).tolist(), "rank_J": int(r),
                    "rank_F": int(f)})
    return out


@dataclass(frozen=True)
class Overview:
    r"""What :func:`overview` finds (all numbers plain Python).

    Attributes
    ----------
    name : str
    kinds : tuple of str
        The units' types, wheel 1 first.
    campion : dict
        ``delta_m``, ``delta_s``, ``label`` (Campion, Bastin & d'Andrea-Novel 1996), from
        :func:`wmr.campion_class`.
    rank_F : int
        At a generic configuration (random angles).
    nullity : int
        :math:`3 + n - \operatorname{rank}\mathbf F` (27) there: the mobility.
    rank_F_range : tuple of int
        (min, max) of rank F over :func:`configurations`.
    nullity_range : tuple of int
        (min, max) of the nullity.
    configurations : int
        How many configurations were examined.
    L : float
        :func:`wmr.characteristic_length`: the L that minimises :math:`\kappa(\mathbf J_{L1})`.
    kappa_JL1 : float
        :math:`\kappa(\mathbf J_{L1})` (32) at that L.
    kappa_J2 : float
        :math:`\kappa(\mathbf J_2)`, the same at every configuration
        (:math:`\mathbf J_2^T\mathbf J_2 = \mathrm{blockdiag}(\mathbf L_i^T\mathbf L_i)`); ``inf`` when singular.
    kappa_J_range : tuple of float
        (min, max) of :math:`\kappa(\mathbf J)` (56) over the configurations.
    isotropic : dict
        ``J_L1``, ``J2`` (bool): isotropic as designed.
    advice : list of str
        What to change to make :math:`\mathbf J_{L1}` and :math:`\mathbf J_2` isotropic (empty if they are).
    dead_zone : float or None
        :func:`dead_zone_radius`.
    singular : list of dict
        :func:`singular_families`.
    steered : tuple of bool
        :attr:`wmr.Robot.steered`: which units have a steering joint.
    dead_zones : tuple of float or None
        Each unit's :meth:`~wmr.model.wheels.WheelUnit.dead_zone`.
    """

    name: str
    kinds: tuple
    campion: dict
    rank_F: int
    nullity: int
    rank_F_range: tuple
    nullity_range: tuple
    configurations: int
    L: float
    kappa_JL1: float
    kappa_J2: float
    kappa_J_range: tuple
    isotropic: dict
    advice: list = field(default_factory=list)
    dead_zone: float | None = None
    singular: list = field(default_factory=list)
    steered: tuple = ()
    dead_zones: tuple = ()


def _campion(robot):
    c = campion_class(robot)
    return {"delta_m": int(c.delta_m), "delta_s": int(c.delta_s), "label": str(c.label)}


def _advice(robot, L):
    """Sentences saying how to make J_L1 and J2 isotropic; and whether each already is."""
    out = []
    pts = robot.mount_points
    centroid = pts.mean(axis=0)
    size = float(np.abs(pts).max())
    jl1 = bool(np.all(np.abs(centroid) <= TOL * size))
    if not jl1:
        out.append(f"J_L1: put C at the centroid of the mount points, ({centroid[0]:.4g}, {centroid[1]:.4g}) in "
                   f"this frame (subtract it from every position); then kappa(J_L1) = 1 at L = {L:.4g}")
    sv = [np.linalg.svd(np.asarray(u.block_terms(NUMERIC)[0], dtype=float), compute_uv=False) for u in robot.wheels]
    top = max(float(s.max()) for s in sv)
    rank_deficient = [k for k, s in enumerate(sv, 1) if s.min() <= TOL * top]
    j2 = not rank_deficient and all(np.all(np.abs(s - top) <= TOL * top) for s in sv)
    if rank_deficient:
        kinds = sorted({robot.wheels[k - 1].kind for k in rank_deficient})
        out.append(f"J2: singular at every configuration ({', '.join(kinds)} units: wheel "
                   f"{', '.join(map(str, rank_deficient))} drive their mount point through one direction only); "
                   "no choice of lengths makes it isotropic")
    elif not j2:
        hints: dict[str, list[str]] = {}                    # each unit's own advice, wheels grouped by it
        for k, u in enumerate(robot.wheels, 1):
            if u.isotropy_advice() is not None:
                hints.setdefault(u.isotropy_advice(), []).append(str(k))
        out += ["J2: " + hint.format(wheels=", ".join(ks)) for hint, ks in hints.items()]
        radii = sorted({float(u.r) for u in robot.wheels})
        if len(radii) > 1:
            out.append(f"J2: give every wheel the same radius (now {', '.join(f'{r:.4g}' for r in radii)})")
        if not hints and len(radii) == 1:
            out.append("J2: make the singular values of every unit's block equal ("
                       + "; ".join(f"wheel {k}: {', '.join(f'{x:.4g}' for x in s)}" for k, s in enumerate(sv, 1)) + ")")
    return out, {"J_L1": jl1, "J2": bool(j2)}


def overview(robot: Robot, grid: int = GRID_SIZE, twists: int = TWISTS, seed: int = 0) -> Overview:
    """Class, mobility, isotropy, dead zone and singular families of a robot (see module notes).

    Parameters
    ----------
    robot : Robot
        A numeric robot.
    grid, twists, seed : int, optional
        The configurations examined (:func:`configurations`).

    Returns
    -------
    Overview

    Examples
    --------
    >>> import wmr
    >>> o = overview(wmr.paper_robot("centred", L=0.3, r=0.05), grid=1000, twists=100)
    >>> o.rank_F, o.nullity, o.rank_F_range, o.nullity_range
    (6, 0, (5, 6), (0, 1))
    >>> round(o.kappa_JL1, 12), o.kappa_J2, o.isotropic
    (1.0, 1.0, {'J_L1': True, 'J2': True})
    """
    robot = V.numeric_robot(robot)
    beta = configurations(robot, grid, twists, seed)
    generic = np.random.default_rng(seed).uniform(-np.pi, np.pi, robot.w)
    rf = int(rank_F(robot, generic))
    n = 3 + robot.n_rates
    ranks = sweep(robot, "rank_F", beta, quantiles=())
    L = characteristic_length(robot)
    kj = sweep(robot, "kappa_J", beta, L=L, quantiles=())
    advice, iso = _advice(robot, L)
    return Overview(
        name=robot.name, kinds=tuple(u.kind for u in robot.wheels), campion=_campion(robot), rank_F=rf, nullity=n - rf,
        rank_F_range=(int(ranks.min), int(ranks.max)), nullity_range=(n - int(ranks.max), n - int(ranks.min)),
        configurations=int(beta.shape[0]), L=float(L), kappa_JL1=float(condition_number(robot.J1(L=L))),
        kappa_J2=float(condition_number(robot.J2(np.zeros(robot.w)))), kappa_J_range=(float(kj.min), float(kj.max)),
        isotropic=iso, advice=advice, dead_zone=dead_zone_radius(robot), singular=singular_families(robot, L),
        steered=robot.steered, dead_zones=tuple(u.dead_zone() for u in robot.wheels))
