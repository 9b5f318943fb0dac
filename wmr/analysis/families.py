r"""The families of singular configurations a robot has, with one example each.

A configuration is singular when :math:`\operatorname{rank}\mathbf J < 3` (56),
:math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2`: some change of the platform twist cannot be made
by the wheel rates alone.  For a driver this means the wheels must be **re-steered** before the
robot can move that way (a robot without steering cannot move that way at all without
skidding).  :func:`singular_families` finds one example of each family; :mod:`wmr.words.families`
names them in geometric words and says what they mean for driving.
"""

from __future__ import annotations

import numpy as np

from ..model import validation
from ..model.platform import wrap_angle
from ..model.tolerance import TOL
from .isotropy import characteristic_length
from .linalg import rank
from .lines import AT_INFINITY, FINITE, concurrencies, planes_through, wheel_plane_lines
from .mobility import rank_F
from .singularities import classify

__all__ = ["singular_families"]


#: steering angles examined at once by :func:`singular_families` (its candidates in chunks of this / w)
_CHUNK_ANGLES = 2**18


def _families(robot, beta):
    """Short names of the families of singular configurations ``beta (N, w)``, from where their wheel-plane lines meet."""
    if robot.w == 3 and robot.n_rates == 3 and all(u.steered and u.rolls_in_plane for u in robot.wheels):
        return [classify(robot, b).family for b in beta]  # three centred wheels: the paper's families
    lined = [k for k, unit in enumerate(robot.wheels) if unit.rolls_in_plane]  # their planes constrain
    if len(lined) < 2:
        return ["other"] * len(beta)
    P, u = wheel_plane_lines(robot, beta)
    kind, point, _, _ = concurrencies(P[:, lined], u[:, lined])
    pts = robot.mount_points
    scale = float(np.abs(pts).max())
    finite = kind == FINITE
    at_c = finite & (np.hypot(point[:, 0], point[:, 1]) <= TOL * scale)  # hypot: no overflow of the squares
    gap = pts - point[:, None, :]  # (N, w, 2)
    at_p = finite & ~at_c & np.any(np.hypot(gap[..., 0], gap[..., 1]) <= TOL * scale, axis=-1)
    names = np.select(
        [kind == AT_INFINITY, ~finite, at_c, at_p], ["parallel", "other", "through-C", "through-P"], "through-point"
    )
    return names.tolist()


def singular_families(robot, L=None):
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
        ``family`` (a short name; in words: :func:`wmr.words.families.description` and
        :func:`~wmr.words.families.meaning`), ``beta`` (w angles, radians), ``rank_J``, ``rank_F``
        (ints); empty when no candidate is singular (e.g. offset wheels, d > 0: J2 is invertible).

    Examples
    --------
    >>> import wmr
    >>> [f["family"] for f in singular_families(wmr.paper_robot("centred"))]
    ['i', 'v-C', 'v-P', 'v', "i'"]
    >>> singular_families(wmr.paper_robot("offset", d=0.5))
    []
    """
    robot = validation.numeric_robot(robot)
    L = characteristic_length(robot) if L is None else validation.number("L", validation.positive("L", L))
    steered = np.array(robot.steered, dtype=bool)
    pts = robot.mount_points
    size = float(np.abs(pts).max()) or 1.0
    fixed_dirs = [
        [-np.sin(float(u.constant_angle)), np.cos(float(u.constant_angle))]
        for u in robot.wheels
        if u.constant_angle is not None
    ]
    dirs = np.array([[1.0, 0.0], [0.0, 1.0], [0.6, 0.8]] + fixed_dirs)
    finite = np.array([[0.0, 0.0], *pts, [0.37 * size, 0.61 * size]])
    beta_inf = np.arctan2(-dirs[:, :1], dirs[:, 1:]) * np.ones(robot.w)  # j_i || direction, every unit
    beta_fin = planes_through(robot, finite)
    for k in range(len(pts)):  # D = P_k: wheel k's angle is free;
        beta_fin[1 + k, k] = 0.4  # a generic value, not 0
    cands = np.concatenate([beta_inf, beta_fin])
    flip = cands.copy()
    flip[:, np.flatnonzero(steered)[:1]] += np.pi  # one wheel turned by pi: the "'" families
    cands = np.concatenate([cands, flip])
    cands = robot.effective_beta(cands)  # unsteered units at their own angle
    _, first = np.unique(cands, axis=0, return_index=True)
    cands = cands[np.sort(first)]  # each candidate once, in the order above
    out, seen = [], set()
    step = max(1, _CHUNK_ANGLES // robot.w)  # candidates a chunk: bounded memory for robots of many units
    for a in range(0, len(cands), step):
        part = cands[a : a + step]
        rk = rank(robot.J(part, L=L))
        part, rk = part[rk < 3], rk[rk < 3]
        for b, r, f, fam in zip(part, rk, rank_F(robot, part), _families(robot, part)):
            if fam in seen:
                continue
            seen.add(fam)
            out.append(
                {
                    "family": fam,
                    "beta": wrap_angle(b).tolist(),
                    "rank_J": int(r),
                    "rank_F": int(f),
                }
            )
    return out
