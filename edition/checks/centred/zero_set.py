r"""The zero set of :math:`\det\mathbf J` against the paper's list (59): the classes of three wheel-plane lines,
the printed items (i)-(v) checked for completeness, and item (v) at points inside and on the circle of the mount
points.

Chapter 4's checks live in :mod:`edition.checks.centred`; this module holds one group of them.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.linalg import condition_number
from wmr.analysis.mobility import mobility
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL, near_zero

from ... import symbols as S
from ...transcription import printed
from ...verify import SEED, symbolic_equal
from .. import Derivation, claim
from .mobility import L_NUM, R_NUM, u_point

__all__ = ["LINE_CLASSES", "classify_lines", "planes_through", "singular_list", "singular_v"]


#: classes of three wheel-plane lines (see :func:`classify_lines`)
LINE_CLASSES = (
    "(i) all parallel, equal angles",
    "all parallel, some angles differ by 180 degrees",
    "(ii)-(iv) two planes coincident",
    "(v) concurrent at a finite point",
    "not concurrent, not parallel",
)


def classify_lines(beta, points):
    r"""The geometric class of the three wheel-plane lines
    :math:`\{\mathbf x : \mathbf i_k\cdot\mathbf x = \mathbf i_k\cdot\mathbf d_k\}`.

    Independent of :mod:`wmr.analysis.singularities`: plain line geometry.

    Parameters
    ----------
    beta : array (3,)
    points : array (3, 2)

    Returns
    -------
    str
        One of :data:`LINE_CLASSES`.
    """
    i = np.stack([np.cos(beta), np.sin(beta)], axis=-1)
    c = np.sum(i * points, axis=-1)
    if all(abs(np.sin(beta[k] - beta[0])) <= TOL for k in (1, 2)):
        same = all(abs(np.sin((beta[k] - beta[0]) / 2)) <= TOL for k in (1, 2))
        return LINE_CLASSES[0] if same else LINE_CLASSES[1]
    for a, b in ((0, 1), (0, 2), (1, 2)):
        if abs(np.sin(beta[b] - beta[a])) <= TOL and abs(i[a] @ (points[b] - points[a])) <= TOL:
            return LINE_CLASSES[2]
    a, b = max(((0, 1), (0, 2), (1, 2)), key=lambda p: abs(np.sin(beta[p[1]] - beta[p[0]])))
    U = np.linalg.solve(i[[a, b]], c[[a, b]])
    k = 3 - a - b
    return LINE_CLASSES[3] if near_zero(i[k] @ U - c[k], np.linalg.norm(U)) else LINE_CLASSES[4]


def planes_through(robot, U):
    r"""Steering angles that put every wheel plane through the body point U (:math:`\mathbf j_i \parallel U - P_i`).

    Parameters
    ----------
    robot : wmr.Robot
    U : array (..., 2)

    Returns
    -------
    numpy.ndarray (..., w)
    """
    w = np.asarray(U, dtype=float)[..., None, :] - robot.mount_points
    return np.arctan2(-w[..., 0], w[..., 1])


def singular_list(det_J, n=1000, n_family=200, n_item=100, seed=SEED):
    r"""Claim ``singular-list-complete``: every printed item is singular, and the zero set is exactly concurrent or
    parallel wheel planes.

    Each item (i)-(iv) (and (i) turned by :math:`\pi`) is checked exactly for every value of its free
    angle, (v) for planes concurrent at a symbolic point; then the zero set is sampled
    (:math:`\det\mathbf J` is linear in :math:`(\cos\beta_3, \sin\beta_3)`) and every sample classified
    by :func:`classify_lines`, with random configurations as a control.

    Parameters
    ----------
    det_J : sympy.Expr
        :math:`\det\mathbf J` of the paper's placement (symbolic L, r), derived in Chapter 4.
    n : int
        Zero-set samples from random :math:`(\beta_1, \beta_2)`, and random controls.
    n_family, n_item : int
        Samples of the parallel families and of each item (ii)-(iv).
    seed : int

    Returns
    -------
    Derivation
        ``families`` (name -> det J vanishes identically), ``classes`` and ``control`` (class -> count),
        ``missed`` (a configuration the printed (i)-(iv) miss, degrees, with det J and kappa), finding
        ``singular-list-complete``.
    """
    p59 = printed(59)
    det_paper = sp.expand(sp.expand_trig(det_J))
    b1, b2, b3 = S.beta
    b = sp.Symbol("b", real=True)
    fams = {}
    for n2, n3 in ((0, 0), (1, 0), (0, 1), (1, 1)):
        label = ", ".join(sp.latex(b + n * sp.pi) for n in (0, n2, n3))
        fams[rf"$({label})$"] = det_paper.subs({b1: b, b2: b + n2 * sp.pi, b3: b + n3 * sp.pi})
    for item, ((i, k), vals) in p59.extra["singular_sets"].items():
        for vi in vals:
            for vk in vals:
                fams[rf"({item}) $\beta_{i} = {vi}^\circ$, $\beta_{k} = {vk}^\circ$"] = det_paper.subs(
                    {S.beta[i - 1]: sp.rad(vi), S.beta[k - 1]: sp.rad(vk)}
                )
    paper = paper_robot("centred", L=S.L, r=S.r, exact=True)
    dets, rhos = det_paper, []
    for k, q in enumerate(paper.wheels):
        w = u_point - sp.Matrix(q.position)
        rhos.append(sp.sqrt(w[0] ** 2 + w[1] ** 2))
        dets = dets.subs({sp.sin(S.beta[k]): -w[0] / rhos[k], sp.cos(S.beta[k]): w[1] / rhos[k]})
    fams["(v) planes concurrent at $U = (u_x, u_y)$"] = sp.expand(dets * sp.prod(rhos))
    families = {name: symbolic_equal(v, 0) for name, v in fams.items()}
    unit = paper_robot("centred", L=1.0, r=1.0)
    pts = unit.mount_points
    rng = np.random.default_rng(seed)
    b12 = rng.uniform(-np.pi, np.pi, (n, 2))
    a_ = np.linalg.det(unit.J(np.c_[b12, np.zeros(n)], L=1.0))
    c_ = np.linalg.det(unit.J(np.c_[b12, np.full(n, np.pi / 2)], L=1.0))
    zeros = [np.c_[b12, np.arctan2(-a_, c_)]]
    bb = rng.uniform(-np.pi, np.pi, (n_family, 1))
    zeros.append(
        np.c_[bb, bb + np.pi * rng.integers(0, 2, (n_family, 1)), bb + np.pi * rng.integers(0, 2, (n_family, 1))]
    )
    for _item, ((i, k), vals) in p59.extra["singular_sets"].items():
        z = rng.uniform(-np.pi, np.pi, (n_item, 3))
        z[:, i - 1], z[:, k - 1] = np.deg2rad(rng.choice(vals, n_item)), np.deg2rad(rng.choice(vals, n_item))
        zeros.append(z)
    Z = np.vstack(zeros)
    res = float(np.max(np.abs(np.linalg.det(unit.J(Z, L=1.0)))))
    NZ = rng.uniform(-np.pi, np.pi, (n, 3))
    classes = {c: 0 for c in LINE_CLASSES}
    control = {c: 0 for c in LINE_CLASSES}
    for z in Z:
        classes[classify_lines(z, pts)] += 1
    for z in NZ:
        control[classify_lines(z, pts)] += 1
    ex = np.array([0.3, 0.3 + np.pi, 0.3])
    bot = paper_robot("centred", L=L_NUM, r=R_NUM)
    missed = {
        "beta": np.degrees(ex),
        "det": float(np.linalg.det(unit.J(ex, L=1.0))),
        "kappa": float(condition_number(bot.J(ex, L=L_NUM))),
    }
    complete = all(families.values()) and res < 1e-9 and classes[LINE_CLASSES[4]] == 0 and control[LINE_CLASSES[4]] == n
    # as printed, (i) is "all angles equal" and (v) a finite point: the half-turned parallel family is outside both
    items_as_printed = complete and classes[LINE_CLASSES[1]] == 0
    return Derivation(
        families=families,
        classes=classes,
        control=control,
        missed=missed,
        n_zero=len(Z),
        findings=[
            claim(
                "singular-list-complete",
                items_as_printed,
                r"every item vanishes for every value of its free angle, and so does each $\pi$-turned variant of (i) (SymPy); "
                rf"all {len(Z)} samples of the zero set are concurrent or parallel wheel planes, none of {n} random "
                r"configurations is",
                res,
                refuted=r"item (i) as printed, $\beta_1 = \beta_2 = \beta_3$, misses the parallel configurations with a wheel "
                r"turned by $180^\circ$, e.g. "
                rf"$\boldsymbol\beta = ({missed['beta'][0]:.1f}^\circ, {missed['beta'][1]:.1f}^\circ, "
                rf"{missed['beta'][2]:.1f}^\circ)$ where $\kappa(\mathbf J) = \infty$",
                corrected=r"$\det\mathbf J = 0$ if and only if the three wheel-plane lines are concurrent or all parallel; "
                r"item (i) must read $\beta_1 \equiv \beta_2 \equiv \beta_3 \pmod{\pi}$, and (ii)-(iv) are special "
                r"cases of (v)",
                corrected_holds=complete,
                severity="typo",
                overturn=(
                    r"reading parallel wheel planes as meeting at infinity in (v): then item (i) as printed needs no "
                    r"correction and the list misses no family"
                ),
                why=r"item (i) as printed omits the wheels turned by $180^\circ$ (unless parallel planes count as meeting "
                r"at infinity in (v)); with (v) read as admitting a mount point as $D_P$, no other family is missing",
                convention=r"the paper's numbering of (59); 'intersect' read as meeting in one finite point, a mount "
                r"point included (the reading *any point* of the singular configurations)",
            )
        ],
    )


def singular_v(thales, angles_deg=(10, 45, 100, 200, 290), n_inside=50, seed=SEED):
    r"""Claim ``singular-v-immobile``: concurrent wheel planes cost all mobility -- unless :math:`D_P` is on the circle
    through the :math:`P_i`.

    Thales: each axle is perpendicular to :math:`P_iD_P` at :math:`P_i`, so when :math:`D_P` is on the
    circumcircle every axle passes through its antipode V and the rotation about V is admissible.

    Parameters
    ----------
    thales : sequence of 3 sympy.Expr
        :math:`(\mathbf u - \mathbf d_i)\cdot(\mathbf d_i + \mathbf u)` for :math:`\mathbf u` on the circle of
        radius L, one per wheel of the paper's placement, derived in Chapter 4 (each must vanish).
    angles_deg : sequence of float
        Positions of :math:`D_P` on the circle (degrees).
    n_inside : int
        Random :math:`D_P` inside the circle.
    seed : int

    Returns
    -------
    Derivation
        ``on_circle`` (mobilities), ``inside`` (set of mobilities), ``at_C`` (mobility), ``n_inside``,
        finding ``singular-v-immobile``.
    """
    thales = len(thales) == 3 and all(symbolic_equal(e, 0) for e in thales)
    bot = paper_robot("centred", L=L_NUM, r=R_NUM)
    on = planes_through(bot, L_NUM * np.stack([np.cos(np.radians(angles_deg)), np.sin(np.radians(angles_deg))], -1))
    inside = planes_through(bot, np.random.default_rng(seed).uniform(-0.25, 0.25, (n_inside, 2)))
    mob_on, mob_in = mobility(bot, on), mobility(bot, inside)
    det_on = float(np.abs(np.linalg.det(bot.J(on, L=L_NUM))).max())
    at_C = int(mobility(bot, planes_through(bot, np.zeros(2))))
    holds = bool(np.all(mob_on == 0))
    return Derivation(
        on_circle=mob_on.tolist(),
        inside=set(mob_in.tolist()),
        at_C=at_C,
        n_inside=n_inside,
        findings=[
            claim(
                "singular-v-immobile",
                holds,
                r"with $D_P$ on the circle through $P_1, P_2, P_3$, every axle passes through "
                rf"the antipode of $D_P$ (SymPy, Thales); numerically, $D_P$ at {len(angles_deg)} points of the circle gives "
                rf"$\det\mathbf J = 0$ and mobility 1, at {n_inside} random points inside it mobility 0",
                det_on,
                refuted=rf"$D_P$ on the circumcircle: $\det\mathbf J = 0$ yet mobility "
                f"{' or '.join(map(str, sorted(set(mob_on.tolist()))))}",
                corrected="Concurrent wheel planes cost all mobility unless $D_P$ lies on the circle through $P_1, P_2, P_3$: "
                "then the axles meet at the antipode of $D_P$ and the robot can turn about it (mobility 1)",
                corrected_holds=thales and bool(np.all(mob_on == 1)) and set(mob_in.tolist()) == {0} and det_on < 1e-12,
                severity="wrong",
                overturn=(
                    r"reading the paper's next sentence (the axles meet at three different locations) as a condition of "
                    r"(v) rather than a consequence of it: that excludes $D_P$ on the circle through the $P_i$, and (v) "
                    r"then costs all mobility"
                ),
                why="mobility needs concurrent axle lines, and concurrent wheel-plane lines do not exclude them",
                convention="paper placement (mount points on a circle of radius $L$ about C)",
                note=rf"$D_P$ at C (Fig. 12a, braking) indeed gives mobility {at_C}",
            )
        ],
    )
