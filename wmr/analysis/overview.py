r"""A robot at a glance: class, actuation, mobility, isotropy, drift, singularities and limitations (``wmr analyze``).

The configurations examined (:func:`configurations`) are a regular grid over the steering
angles of the steered units together with the configurations that admit a motion
(:func:`wmr.steering_angles` of a sample of twists: translations, spins about C, about each mount
point and about random points).  The rank of F drops exactly at configurations of the second
kind, which a grid or a random sample would almost surely miss, so the minimum of rank F is
found; its maximum is the generic value.  :math:`\kappa(\mathbf J)` is reported over the drivable
configurations only (:class:`~wmr.analysis.sweep.Drivable`): a robot never drives in the others.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..model import validation
from ..model.limits import check
from ..model.robot import Robot
from ..model.types import FloatArray
from .advice import advice, profile
from .classes import campion_class
from .families import singular_families
from .kinematics import inverse
from .limitations import LimitationKind, limitations
from .linalg import condition_number
from .mobility import rank_F
from .steering import steering_angles
from .sweep import Drivable, Grid, Sample, sweep
from .unit_design import dead_zone, dead_zone_radius

__all__ = ["Overview", "overview"]

#: about this many grid configurations are examined (the grid has at least 4 values per steered angle)
GRID_SIZE = 20000
#: ... but at most this many angles in all (a robot of more than 100 steered units: fewer configurations)
GRID_ANGLES = 2_000_000
#: random twists whose steering angles are added to the grid
TWISTS = 2000


def special_twists(robot):
    """The motions (4 + w, 3) where rank drops are expected: translations along x, y, the diagonal; spins about C, each P_i."""
    special = [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 1.0], [1.0, 0.0, 0.0]]
    special += [[1.0, d[1], -d[0]] for d in robot.mount_points]  # spin about P_i: c_dot = -psi E d_i
    return np.array(special)


def configurations(robot: Robot, grid: int | None = None, twists: int = TWISTS, seed: int = 0) -> FloatArray:
    """The configurations (N, w) :func:`overview` examines: a grid over the steered angles and motion configurations.

    Each of the ``s`` steered angles takes ``max(4, floor(grid ** (1 / s)))`` values in [-pi, pi) (``grid``
    random configurations instead when that would make more than ``4 * grid``); then the steering angles
    of :func:`special_twists` and of ``twists`` random twists.  Fixed and Swedish units' angles are 0.
    """
    special = special_twists(validation.numeric_robot(robot))
    w, steered = robot.w, np.array(robot.steered, dtype=bool)
    s = int(steered.sum())
    grid = (
        min(GRID_SIZE, max(1, GRID_ANGLES // max(s, 1)))
        if grid is None
        else validation.integer("grid", grid, minimum=1)
    )
    twists = validation.integer("twists", twists, minimum=0)
    seed = validation.integer("seed", seed, minimum=0)
    steps = max(4, int(np.floor(grid ** (1.0 / s) + 1e-9))) if s else 0
    on_grid = s > 0 and steps**s <= 4 * grid
    most = (steps**s if on_grid else grid if s else 0) + twists + w + 4  # held in memory at once, with their analyses
    check("configurations", most, "the overview (grid and twists)")
    check("memory_mb", most * 8 * (3 * w + 3 * robot.n_rates + 16) / 2**20, "the overview (grid and twists)")
    parts: list[FloatArray] = []
    if s:
        if on_grid:
            g = Grid(steps)
            sub = g.configurations(s, 0, g.size(s))
        else:  # many steered units: a seeded sample of the same size
            sub = Sample(grid, seed=seed).configurations(s, 0, grid)
        full = np.zeros((sub.shape[0], w))
        full[:, steered] = sub
        parts.append(full)
    size = float(np.abs(robot.mount_points).max()) or 1.0
    rng = np.random.default_rng(seed)
    tw = np.concatenate([special, np.c_[rng.uniform(-1, 1, (twists, 1)) / size, rng.uniform(-1, 1, (twists, 2))]])
    parts.append(steering_angles(robot, tw))
    return np.concatenate(parts)


@dataclass(frozen=True)
class Overview:
    r"""What :func:`overview` finds (all numbers plain Python).

    Attributes
    ----------
    name : str
    kinds : tuple of str
        The units' types, wheel 1 first.
    campion : dict
        ``delta_m``, ``delta_s``, ``label``, ``name`` (Campion, Bastin & d'Andrea-Novel 1996), from
        :func:`wmr.campion_class`.
    actuated_mobility : int
        The dimension of the admissible twists the motors command at the class's generic
        configuration (:func:`wmr.analysis.actuation.actuated_mobility`); at most ``delta_m``.
    uncontrolled : list of Motion
        The motions the robot makes with every motor stopped there (empty when the motors command
        every admissible twist).
    limitations : list of Limitation
        :func:`wmr.analysis.limitations.limitations`: what the robot cannot do.
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
        :func:`wmr.characteristic_length`: the L that minimises :math:`\kappa(\mathbf J_{L1})` for this C.
    kappa_JL1 : float
        :math:`\kappa(\mathbf J_{L1})` (32) at that L.
    kappa_J2 : float
        :math:`\kappa(\mathbf J_2)`, the same at every configuration
        (:math:`\mathbf J_2^T\mathbf J_2 = \mathrm{blockdiag}(\mathbf L_i^T\mathbf L_i)`); ``inf`` when singular.
    kappa_J : dict
        :math:`\kappa(\mathbf J)` (56) over the drivable configurations: those of sampled twists
        (:class:`~wmr.analysis.sweep.Drivable`; their ``median`` and ``p95``) and of the special motions
        the robot can make (:func:`special_twists`; ``min`` and ``max`` cover both, e.g. ``inf`` for a
        straight drive with every wheel parallel).
    isotropic : dict
        ``J_L1``, ``J2`` (bool): isotropic as designed.
    advice : list of Advice
        What to change to make :math:`\mathbf J_{L1}` and :math:`\mathbf J_2` isotropic, each checked on
        the changed robot (:mod:`wmr.analysis.advice`); empty if they are.
    advised : list of bool
        For each advice, :attr:`~wmr.analysis.advice.Advice.advised`.
    dead_zone : float or None
        :func:`~wmr.analysis.unit_design.dead_zone_radius`.
    singular : list of dict
        :func:`singular_families`.
    steered : tuple of bool
        :attr:`wmr.Robot.steered`: which units have a steering joint.
    dead_zones : tuple of float or None
        Each unit's :func:`~wmr.analysis.unit_design.dead_zone`.
    drivable : int
        How many drivable configurations ``kappa_J`` covers (sampled, and special motions).
    """

    name: str
    kinds: tuple
    campion: dict
    actuated_mobility: int
    uncontrolled: list
    limitations: list
    rank_F: int
    nullity: int
    rank_F_range: tuple
    nullity_range: tuple
    configurations: int
    L: float
    kappa_JL1: float
    kappa_J2: float
    kappa_J: dict
    isotropic: dict
    advice: list = field(default_factory=list)
    advised: list = field(default_factory=list)
    dead_zone: float | None = None
    singular: list = field(default_factory=list)
    steered: tuple = ()
    dead_zones: tuple = ()
    drivable: int = 0


def overview(robot: Robot, grid: int | None = None, twists: int = TWISTS, seed: int = 0) -> Overview:
    r"""Class, actuation, mobility, isotropy, dead zone, singular families and limitations of a robot (module notes).

    Parameters
    ----------
    robot : Robot
        A numeric robot.
    grid, twists, seed : int, optional
        The configurations examined (:func:`configurations`); ``twists`` drivable configurations
        (at least 100) are also the set of :math:`\kappa(\mathbf J)`.

    Returns
    -------
    Overview

    Examples
    --------
    >>> import wmr
    >>> o = overview(wmr.paper_robot("centred", L=0.3, r=0.05), grid=1000, twists=100)
    >>> o.rank_F, o.nullity, o.rank_F_range, o.nullity_range, o.actuated_mobility
    (6, 0, (5, 6), (0, 1), 1)
    >>> round(o.kappa_JL1, 12), o.kappa_J2, o.isotropic
    (1.0, 1.0, {'J_L1': True, 'J2': True})
    """
    robot = validation.numeric_robot(robot)
    beta = configurations(robot, grid, twists, seed)
    generic = np.random.default_rng(seed).uniform(-np.pi, np.pi, robot.w)
    rf = int(rank_F(robot, generic))
    n = 3 + robot.n_rates
    before = profile(robot)
    ranks = sweep(robot, "rank_F", beta, quantiles=())
    L = before["L"]
    drive = Drivable(max(100, twists), seed=seed)
    kj = sweep(robot, "kappa_J", drive, L=L, quantiles=(0.5, 0.95))
    special = special_twists(robot)  # and the special motions the robot can make
    sb = steering_angles(robot, special)
    sb = sb[inverse(robot, sb, special).no_slip]
    ks = condition_number(robot.J(sb, L=L)) if sb.size else np.zeros(0)
    tips, iso = advice(robot, before)
    c = campion_class(robot)
    lims = limitations(robot, c)
    return Overview(
        name=robot.name,
        kinds=tuple(u.kind for u in robot.wheels),
        campion={"delta_m": int(c.delta_m), "delta_s": int(c.delta_s), "label": str(c.label), "name": str(c.name)},
        actuated_mobility=before["actuated_mobility"],
        uncontrolled=[x.motions[0] for x in lims if x.kind is LimitationKind.UNCONTROLLED],
        limitations=lims,
        rank_F=rf,
        nullity=n - rf,
        rank_F_range=(int(ranks.min), int(ranks.max)),
        nullity_range=(n - int(ranks.max), n - int(ranks.min)),
        configurations=int(beta.shape[0]),
        L=float(L),
        kappa_JL1=before["kappa_JL1"],
        kappa_J2=before["kappa_J2"],
        kappa_J={
            "min": float(min(kj.min, ks.min(initial=np.inf))),
            "median": float(kj.quantiles[0.5]),
            "p95": float(kj.quantiles[0.95]),
            "max": float(max(kj.max, ks.max(initial=0.0))),
        },
        isotropic=iso,
        advice=tips,
        advised=[t.advised for t in tips],
        dead_zone=dead_zone_radius(robot),
        singular=singular_families(robot, L),
        steered=robot.steered,
        dead_zones=tuple(dead_zone(u) for u in robot.wheels),
        drivable=int(kj.count + sb.shape[0]),
    )
