r"""Chapter 4 exercises (centred wheels and singularities): fair checks (:func:`~.framework.exercise`).

Both checks decide by plane geometry with the tolerance the question states (angles to 0.01 degree):
a wheel-plane line is :math:`\{\mathbf x : \mathbf i_k\cdot\mathbf x = \mathbf i_k\cdot\mathbf d_k\}`, an axle line
:math:`\{\mathbf x : \mathbf j_k\cdot\mathbf x = \mathbf j_k\cdot\mathbf d_k\}`; :math:`\det\mathbf J = 0` iff the
wheel-plane lines are concurrent or all parallel, and the robot can move iff the axle lines are (Chapter 4).
"""

from __future__ import annotations

import numpy as np

from wmr.model.robot import Robot
from wmr.model.wheels import CentredWheel

from ..text import number
from . import answers
from .feedback import right, wrong
from .framework import exercise
from .tolerance import angle_gap, within

__all__ = [
    "TOL_4_1",
    "TOL_4_2",
    "DIRECTION_4_1",
    "POINTS_4_2",
    "robot_4_2",
    "unlisted_singularity",
    "mobile_and_singular",
]

#: angles to 0.01 degree (absolute, radians)
TOL_4_1 = within("to 0.01 degree", abs=np.radians(0.01))
TOL_4_2 = TOL_4_1
#: exercise 4.1: the body direction (degrees from the x-axis) along which the robot must translate
DIRECTION_4_1 = 30.0
#: exercise 4.2: the mount points (m) of a robot that is not the paper's
POINTS_4_2 = ((0.5, 0.0), (-0.2, 0.4), (-0.3, -0.3))


def robot_4_2():
    """The robot of exercise 4.2: three centred wheels (r = 0.05 m) at :data:`POINTS_4_2`.

    Returns
    -------
    wmr.Robot
    """
    return Robot([CentredWheel(p, r=0.05) for p in POINTS_4_2])


def _degrees(x):
    return f"{number(np.degrees(x), 4)}^\\circ"


def _stated_item(beta):
    """The printed item (i)-(iv) that states ``beta`` literally (equalities to the tolerance), or ""."""
    from ..transcription import printed

    tol = TOL_4_1.abs * 1.0000001

    def same(a, b):
        return angle_gap([a], [b], period=2 * np.pi) <= tol

    if same(beta[0], beta[1]) and same(beta[0], beta[2]):
        return "(i)"
    for item, ((i, k), values) in printed(59).extra["singular_sets"].items():
        if same(beta[i - 1], beta[k - 1]) and any(same(beta[i - 1], np.radians(v)) for v in values):
            return f"({item})"
    return ""


@exercise("4.1", answer="three steering angles in degrees", tolerance=TOL_4_1, units={"beta_deg": "deg"})
def unlisted_singularity(beta_deg):
    r"""Exercise 4.1: angles at which the paper's robot translates along :data:`DIRECTION_4_1`, :math:`\mathbf J` is
    singular, and no printed item (i)-(v) states them literally.

    Parameters
    ----------
    beta_deg : array_like (3,)
        Steering angles in degrees.

    Returns
    -------
    Result
    """
    beta = answers.angles(beta_deg, 3, "deg")
    want = np.radians(DIRECTION_4_1)
    rolling = beta + np.pi / 2  # the angle of j_k
    off = [k + 1 for k in range(3) if angle_gap([rolling[k]], [want]) > TOL_4_1.abs * 1.0000001]
    if off:
        which = ", ".join(str(k) for k in off)
        return wrong(
            f"Wheel{'s' if len(off) > 1 else ''} {which} "
            f"roll{'' if len(off) > 1 else 's'} along another direction than "
            f"${DIRECTION_4_1:g}^\\circ$ (the rolling direction $\\mathbf j_k$ is at $\\beta_k + 90^\\circ$): "
            "the robot cannot translate along it."
        )
    item = _stated_item(beta)
    if item:
        return wrong(
            f"The robot translates along ${DIRECTION_4_1:g}^\\circ$ and $\\mathbf J$ is singular (the wheel "
            f"planes are parallel), but item {item} states these angles literally. Find angles no item "
            "states."
        )
    return right(
        f"All wheels roll along ${DIRECTION_4_1:g}^\\circ$, so the wheel-plane lines are parallel and "
        r"$\det\mathbf J = 0$; no item (i)-(iv) states these angles, and parallel lines do not meet in one "
        "point as (v) requires: the printed list misses a wheel turned by $180^\\circ$."
    )


def _meet(normals, points):
    """Least-squares common point of the lines n_k . x = n_k . p_k, and the largest miss (m)."""
    c = np.einsum("kj,kj->k", normals, points)
    x = np.linalg.lstsq(normals, c, rcond=None)[0]
    return x, float(np.max(np.abs(normals @ x - c)))


def _gap_to_lines_through(beta, points, X, along):
    r"""Largest angle (radians, modulo pi) by which the lines of ``beta`` miss being lines through ``X``.

    ``along="plane"``: the wheel-plane line (direction :math:`\mathbf j_k`); ``"axle"``: the axle line
    (:math:`\mathbf i_k`).  A wheel whose mount point is ``X`` itself is through it at any angle.
    """
    w = X - points
    far = np.linalg.norm(w, axis=1) > 1e-9 * max(1.0, float(np.abs(points).max()))
    want = np.arctan2(-w[:, 0], w[:, 1]) if along == "plane" else np.arctan2(w[:, 1], w[:, 0])
    return max([angle_gap([beta[k]], [want[k]]) for k in range(len(beta)) if far[k]], default=0.0)


def _circumcentre(P):
    """Centre of the circle through the three points ``P`` (3, 2)."""
    A = 2 * (P[1:] - P[0])
    b = np.sum(P[1:] ** 2, axis=1) - np.sum(P[0] ** 2)
    return np.linalg.solve(A, b)


def _nearest_turning_point(beta, P):
    r"""How far (radians, the largest over the wheels) the axle lines of ``beta`` are from the nearest configuration
    that is singular and mobile, and its turning point.

    Three centred wheels are singular and mobile exactly when their axles meet at a point :math:`V` of the circle
    through the mount points (the wheel-plane lines, perpendicular to the axles at :math:`P_k`, then meet at the
    antipode :math:`D_P`, by Thales). The answer passes when some such :math:`V` has every axle within the stated
    tolerance: a rounded right answer passes wherever on the circle it lies, which a fit of one point through the
    rounded lines does not guarantee (a wheel near :math:`V` swings its axle far for a small move of :math:`V`).
    """
    c = _circumcentre(P)
    R = float(np.linalg.norm(P[0] - c))
    lo, hi, best = 0.0, 2 * np.pi, (np.inf, c)
    for _ in range(6):  # a grid over the circle, then finer grids around the best point
        t = np.linspace(lo, hi, 721)
        V = c + R * np.stack([np.cos(t), np.sin(t)], -1)  # (n, 2)
        w = V[:, None, :] - P[None]  # (n, 3, 2)
        want = np.arctan2(w[..., 1], w[..., 0])
        d = np.abs(np.mod(beta - want + np.pi / 2, np.pi) - np.pi / 2)
        d[np.linalg.norm(w, axis=-1) < 1e-9 * R] = 0.0  # a wheel at V turns on the spot
        g = d.max(axis=1)
        k = int(np.argmin(g))
        if g[k] < best[0]:
            best = (float(g[k]), V[k])
        step = t[1] - t[0]
        lo, hi = t[k] - 2 * step, t[k] + 2 * step
    return best


@exercise("4.2", answer="three steering angles in degrees", tolerance=TOL_4_2, units={"beta_deg": "deg"})
def mobile_and_singular(beta_deg):
    r"""Exercise 4.2: angles at which :math:`\mathbf J` of :func:`robot_4_2` is singular although the robot can turn
    about a point (rank F = 5, not a translation).

    Parameters
    ----------
    beta_deg : array_like (3,)
        Steering angles in degrees.

    Returns
    -------
    Result
    """
    beta = answers.angles(beta_deg, 3, "deg")
    P = np.array(POINTS_4_2)
    axle = np.stack([np.cos(beta), np.sin(beta)], -1)  # i_k: normal of the wheel-plane line
    if all(angle_gap([beta[k]], [beta[0]]) <= 2 * TOL_4_2.abs for k in (1, 2)):
        return wrong(
            r"All wheel planes are parallel: $\mathbf J$ is singular and the robot can translate, but it "
            "cannot turn about a point at these angles. Find angles at which it turns."
        )
    tol = TOL_4_2.abs * 1.0000001
    gap, V = _nearest_turning_point(beta, P)
    if gap <= tol:  # exact angles within the tolerance turn about V on the circle
        D = 2 * _circumcentre(P) - V  # ... and their wheel-plane lines meet at its antipode
        return right(
            f"The wheel-plane lines meet at $D_P = ({number(D[0])}, {number(D[1])})$, so "
            f"$\\det\\mathbf J = 0$, and the axles meet at $({number(V[0])}, {number(V[1])})$: the robot can "
            r"turn about that point (rank $\mathbf F = 5$)."
        )
    D, miss = _meet(axle, P)  # where the wheel-plane lines (nearly) meet
    if _gap_to_lines_through(beta, P, D, "plane") > tol:
        return wrong(
            r"$\det\mathbf J \neq 0$: the three wheel-plane lines do not meet in one point (they miss by "
            f"${number(miss)}$ m), so $\\mathbf J$ is not singular here."
        )
    return wrong(
        f"$\\mathbf J$ is singular (the wheel-plane lines meet at $({number(D[0])}, {number(D[1])})$), "
        r"but the axles do not meet in one point: rank $\mathbf F = 6$, the robot cannot move."
    )
