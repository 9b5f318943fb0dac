r"""The paper's singular families of three centred wheels, computed: :func:`families` samples each and checks
:math:`\det\mathbf J` on it exactly; :func:`check_paper_items` checks the printed list (i)-(v) literally.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.lines import axles_through, circumcircle, pair_line_angle, planes_through
from wmr.analysis.mobility import rank_F
from wmr.analysis.singularities import classify, det_J, det_J_polynomial, exact_robot, exact_zero, numeric_robot
from wmr.model.platform import wrap_angle
from wmr.model.robots import paper_robot

from ..text import degrees as _deg
from .family import PAPER_PAIR_ITEMS, Family, directions_at_angles

__all__ = ["families", "check_paper_items"]


def families(robot=None, n=72, exact=True):
    r"""The singular families of the paper's robot, each checked exactly and at samples.

    Parameters
    ----------
    robot : Robot, optional
        The paper's three-centred-wheel robot (default ``paper_robot("centred", exact=True)``,
        L = r = 1; the zero set does not depend on L or r).
    n : int
        Samples per free angle.
    exact : bool
        Run the symbolic checks.

    Returns
    -------
    list of Family
        With ``det_J_max`` (max :math:`|\det\mathbf J|` over the samples), ``det_J_exact_zero``,
        ``rank_F`` (the ranks found, with counts) and ``classified_as`` filled in.
    """
    if robot is None:
        robot = paper_robot("centred")
    num = numeric_robot(robot)
    det_J(num, np.zeros(3), L=1.0)  # wmr's own check: J must be square (three centred wheels)
    exact_bot = exact_robot(robot)
    P = num.mount_points
    t = np.linspace(-np.pi, np.pi, n, endpoint=False)
    tau = sp.Symbol("tau", real=True)
    th = sp.Symbol("t", real=True)
    x, y = sp.symbols("x y", real=True)
    Pex = [tuple(u.position) for u in exact_bot.wheels]
    out = []

    # (i) and (i'): all wheel-plane lines parallel
    out.append(
        Family(
            "i",
            "(i)",
            r"$\beta_1=\beta_2=\beta_3=\beta$, $\beta$ free",
            r"all wheel planes parallel ($D_P$ and the IC at infinity): translation",
            "yes",
            "(i)",
            "Fig. 10; the only singular family in which the robot still translates.",
            samples=np.stack([t, t, t], axis=-1),
            exact=lambda: directions_at_angles([tau, tau, tau]),
        )
    )
    rev = []
    for k in range(3):
        b = np.stack([t, t, t], axis=-1)
        b[:, k] += np.pi
        rev.append(b)
    out.append(
        Family(
            "i'",
            r"(i') parallel, one wheel turned by $180^\circ$",
            r"$\beta_j=\beta_k=\beta$, $\beta_i=\beta+180^\circ$ (3 choices of i), $\beta$ free",
            r"the same parallel planes as (i): $\beta$ and $\beta+\pi$ give the same wheel plane",
            "no",
            "(i)",
            r"The printed (i) requires equal angles; a wheel turned half a turn has the same plane "
            r"(its column of $\mathbf J$ only changes sign). Translation is still possible "
            r"($\operatorname{rank}\mathbf F = 5$).",
            samples=np.concatenate(rev),
            exact=lambda: directions_at_angles([tau + sp.pi, tau, tau]),
        )
    )

    # (ii)-(iv): two wheel planes on the line P_i P_j, third free
    for (i, j), item in PAPER_PAIR_ITEMS.items():
        k = ({1, 2, 3} - {i, j}).pop()
        a = pair_line_angle(num, i, j)
        ai = sp.nsimplify(sp.Rational(round(np.degrees(a) * 1e6), 10**6)) * sp.pi / 180
        for prime in (False, True):
            rows = []
            combos = [(0.0, 0.0), (np.pi, np.pi)] if not prime else [(0.0, np.pi), (np.pi, 0.0)]
            for oi, oj in combos:
                b = np.zeros((n, 3))
                b[:, i - 1], b[:, j - 1], b[:, k - 1] = a + oi, a + oj, t
                rows.append(b)
            a1, a2 = _deg(wrap_angle(a)), _deg(wrap_angle(a + np.pi))
            if not prime:
                conf = rf"$\beta_{i}=\beta_{j}={a1}^\circ$ or $\beta_{i}=\beta_{j}={a2}^\circ$, $\beta_{k}$ free"
                fam = f"{item} planes {i}, {j} coincident"
                listed, note = (
                    "yes",
                    (
                        f"Fig. 11; line $P_{i}P_{j}$ carries both planes; axles {i} and {j} parallel, "
                        r"so $\operatorname{rank}\mathbf F = 6$ unless the third plane is parallel too "
                        r"(then it is (i) or (i'))."
                    ),
                )
            else:
                conf = (
                    rf"$\beta_{i}={a1}^\circ,\ \beta_{j}={a2}^\circ$ or "
                    rf"$\beta_{i}={a2}^\circ,\ \beta_{j}={a1}^\circ$, $\beta_{k}$ free"
                )
                fam = f"{item}' planes {i}, {j} coincident, half a turn apart"
                listed = "no"
                note = (
                    f"The printed {item} gives equal angles; one wheel of the pair turned by "
                    r"$180^\circ$ has the same plane, so these are singular too."
                )
            out.append(
                Family(
                    f"pair-{i}{j}" + ("'" if prime else ""),
                    fam,
                    conf,
                    rf"planes of wheels {i} and {j} coincide with the line $P_{i}P_{j}$; $D_P$ is where plane {k} "
                    "crosses it",
                    listed,
                    item,
                    note,
                    samples=np.concatenate(rows),
                    exact=(
                        lambda i=i, j=j, k=k, ai=ai, prime=prime: directions_at_angles(  # type: ignore[misc]
                            [ai if w == i else (ai + (sp.pi if prime else 0) if w == j else th) for w in (1, 2, 3)]
                        )
                    ),
                )
            )

    # (v): concurrent at a finite point D_P
    grid = np.linspace(-2.5, 2.5, 11) * np.abs(P).max()
    D = np.array([(gx, gy) for gx in grid for gy in grid])
    D = D[np.min(np.linalg.norm(D[:, None, :] - P[None], axis=-1), axis=1) > 1e-6]
    base = planes_through(num, D)
    flips = np.array([[a, b_, c] for a in (0, 1) for b_ in (0, 1) for c in (0, 1)]) * np.pi
    samples_v = (base[:, None, :] + flips[None]).reshape(-1, 3)

    def dirs_through(Dx, Dy, turn=(0, 0, 0)):
        # axle i_i = -E (D - P_i) direction: wheel plane along D - P_i, i = (v_y, -v_x)
        out_ = []
        for (px, py), f in zip(Pex, turn, strict=True):
            vx, vy = Dx - px, Dy - py
            sgn = -1 if f else 1
            out_.append((sgn * vy, -sgn * vx))
        return out_

    out.append(
        Family(
            "v",
            "(v) planes concurrent",
            r"$\ell_1,\ell_2,\ell_3$ concurrent at a finite $D_P$ (2 free parameters; "
            r"each $\beta_i$ or $\beta_i+180^\circ$)",
            r"the three wheel-plane lines meet at one point $D_P$; generically the axles meet pairwise at three points",
            "yes",
            "(v)",
            "Fig. 12b. Contains (ii)-(iv) (two planes on a side line) and the rows (v-a), (v-b), (v-c); "
            r"$\operatorname{rank}\mathbf F = 5$ only where $D_P$ is on the circle through the $P_i$ (row (v-c)).",
            samples=samples_v,
            exact=lambda: dirs_through(x, y, (0, 1, 0)),
        )
    )
    bC = planes_through(num, [0.0, 0.0])
    out.append(
        Family(
            "v-C",
            "(v-a) planes through C",
            rf"$\beta=({_deg(bC[0])}^\circ, {_deg(bC[1])}^\circ, {_deg(bC[2])}^\circ)$, each $+180^\circ$ optional",
            r"$D_P=C$: every wheel plane contains the operation point; no twist is admissible",
            "yes",
            "(v)",
            f"Fig. 12a (braking at rest). Isolated points ({len(flips)} of them).",
            samples=bC[None, :] + flips,
            exact=lambda: dirs_through(0, 0),
        )
    )
    rows = []
    for kk in range(3):
        b = np.zeros((4 * n, 3))
        base_k = planes_through(num, P[kk])
        for q, (f1, f2) in enumerate([(0, 0), (0, 1), (1, 0), (1, 1)]):
            blk = b[q * n : (q + 1) * n]
            others = [w for w in range(3) if w != kk]
            blk[:, others[0]] = base_k[others[0]] + f1 * np.pi
            blk[:, others[1]] = base_k[others[1]] + f2 * np.pi
            blk[:, kk] = t
        rows.append(b)
    a13 = _deg(pair_line_angle(num, 1, 3))
    a23 = _deg(pair_line_angle(num, 2, 3))
    out.append(
        Family(
            "v-P",
            "(v-b) planes through a mount point",
            rf"e.g. $\beta_1\equiv{a13}^\circ$, $\beta_2\equiv{a23}^\circ$ (mod $180^\circ$), $\beta_3$ free ($D_P=P_3$); "
            r"likewise at $P_1$, $P_2$",
            r"$D_P=P_k$: the other two planes lie on the sides through $P_k$; wheel $k$ may take any angle",
            "yes",
            "(v)",
            "Read literally, (v) holds: the three planes meet at $P_k$. The report's reading of (v) "
            r"excludes a $D_P$ at a mount point, and under it no printed item covers this family.",
            samples=np.concatenate(rows),
            exact=lambda: [(sp.cos(th), sp.sin(th)) if w == 2 else dirs_through(*Pex[2])[w] for w in range(3)],
        )
    )

    # rotation about a point U on the circumcircle: axles through U and planes through the antipode
    cc, R = circumcircle(num.mount_points)
    U = cc + R * np.stack([np.cos(t + np.pi / n), np.sin(t + np.pi / n)], axis=-1)  # half a step: U != P_k
    bU = axles_through(num, U)
    samples_c = (bU[:, None, :] + flips[None]).reshape(-1, 3)
    (ccx, ccy), Rex = circumcircle(Pex)  # the same formula, exact

    def circle_dirs():
        ux = ccx + Rex * (1 - th**2) / (1 + th**2)
        uy = ccy + Rex * 2 * th / (1 + th**2)
        return [(ux - px, uy - py) for px, py in Pex]  # i_i || U - P_i

    out.append(
        Family(
            "v-circle",
            r"(v-c) rotation about a point of the circle through $P_1, P_2, P_3$",
            r"axles through $U$ on the circle through $P_1, P_2, P_3$ (radius $L$ about $C$), $U$ free",
            r"$U$ and $D_P$ antipodal on the circumcircle: each $P_i$ sees them at a right angle (Thales)",
            "no",
            "(v)",
            r"$\det\mathbf J = 0$ while $\operatorname{rank}\mathbf F = 5$: the robot *can* rotate about "
            r"$U$, contradicting the statement that in (v) it has lost all mobility; every rotation about a point at "
            r"distance $L$ from $C$ passes through a singular $\mathbf J$.",
            samples=samples_c,
            exact=circle_dirs,
        )
    )

    poly, c, s = det_J_polynomial(exact_bot)
    for f in out:
        assert f.samples is not None  # every family above is sampled
        dj = np.abs(det_J(num, f.samples))
        f.det_J_max = float(dj.max())
        ranks = rank_F(num, f.samples)
        vals, counts = np.unique(ranks, return_counts=True)
        order = np.argsort(-counts)
        f.rank_F = ", ".join(f"{int(vals[o])} ({int(counts[o])}/{len(ranks)})" for o in order)
        kinds: dict[str, int] = {}
        assert f.samples is not None
        for b in f.samples[:: max(1, len(f.samples) // 24)]:
            fam = classify(num, b).family
            kinds[fam] = kinds.get(fam, 0) + 1
        f.classified_as = ", ".join(f"{k} ({v})" for k, v in sorted(kinds.items()))
        if exact and f.exact is not None:
            f.det_J_exact_zero = exact_zero(poly, c, s, f.exact())
    return out


def check_paper_items(robot=None, L=None):
    r"""Check the printed list (i)-(v) literally, for every value of the free angle (exact).

    Parameters
    ----------
    robot : Robot, optional
        Default: the paper's robot (exact coordinates).
    L : float, optional
        Characteristic length in :math:`\mathbf J_{L1}` (default: the robot's,
        :func:`wmr.characteristic_length`); it scales :math:`\det\mathbf J` (58) and cannot make it vanish.

    Returns
    -------
    dict item -> bool
        ``"(i)"``: :math:`\beta_1=\beta_2=\beta_3=\tau`; ``"(ii) 60"``, ``"(ii) -120"``:
        :math:`\beta_1=\beta_3=60^\circ` (resp. :math:`-120^\circ`), :math:`\beta_2` free; likewise (iii),
        (iv); ``"(v)"``: planes concurrent at a symbolic point D; each True when :math:`\det\mathbf J`
        vanishes identically.
    """
    if robot is None:
        robot = paper_robot("centred")
    robot = exact_robot(robot)
    poly, c, s = det_J_polynomial(robot, L)
    tau = sp.Symbol("tau", real=True)
    deg = sp.pi / 180
    out = {"(i)": exact_zero(poly, c, s, directions_at_angles([tau, tau, tau]))}
    printed = {"(ii)": ((1, 3), (60, -120)), "(iii)": ((1, 2), (-60, 120)), "(iv)": ((2, 3), (0, 180))}
    for item, ((i, j), vals) in printed.items():
        for v in vals:
            ang = [v * deg if w in (i, j) else tau for w in (1, 2, 3)]
            out[f"{item} {v}"] = exact_zero(poly, c, s, directions_at_angles(ang))
    x, y = sp.symbols("x y", real=True)
    dirs = []
    for u in robot.wheels:
        px, py = (sp.nsimplify(v) for v in u.position)
        dirs.append((y - py, -(x - px)))  # plane through D = (x, y)
    out["(v)"] = exact_zero(poly, c, s, dirs)
    return out
