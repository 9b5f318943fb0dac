r"""The paper's singular configurations of three centred wheels (section 5.3, items (i)-(v)), as computed families.

Each :class:`Family` states a set of configurations in the paper's words (LaTeX), the verdict on
whether the paper lists it, and carries computed evidence: :math:`|\det\mathbf J|` at sampled
members, an exact check that :math:`\det\mathbf J` vanishes identically on the family
(:func:`wmr.analysis.singularities.exact_zero`), the ranks of :math:`\mathbf F` found there and the
family :func:`wmr.analysis.singularities.classify` assigns.  :func:`check_paper_items` checks the
printed list literally.  The general analysis lives in :mod:`wmr.analysis.singularities`; only the
paper's catalogue is here.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from wmr.analysis.lines import axles_through, circumcircle, pair_line_angle, planes_through
from wmr.analysis.mobility import rank_F
from wmr.analysis.singularities import classify, det_J, det_J_polynomial, exact_robot, exact_zero, numeric_robot
from wmr.model.platform import wrap_angle
from wmr.model.robots import paper_robot

from .files import atomic_write, csv_text
from .text import bound
from .text import degrees as _deg

__all__ = [
    "PAPER_PAIR_ITEMS",
    "COLUMNS",
    "Family",
    "families",
    "paper_item",
    "check_paper_items",
    "table",
    "write_csv",
    "READINGS",
    "ITEMS",
    "covering_items",
    "accounting",
]

#: The paper's items of section 5.3 for its wheel numbering (wheels 1-based): planes of wheels i and j on
#: the line P_i P_j.
PAPER_PAIR_ITEMS = {(1, 3): "(ii)", (1, 2): "(iii)", (2, 3): "(iv)"}


def paper_item(family):
    """The paper's item (i)-(v) that states a family of :func:`~wmr.analysis.singularities.classify` literally.

    Parameters
    ----------
    family : str
        A family key (``"i"``, ``"pair-13"``, ``"v-C"``, ...).

    Returns
    -------
    str
        ``"(i)"`` .. ``"(v)"``, or ``""`` when the paper's list does not state it (``"i'"``, the
        half-turn pairs, ``"regular"``).

    Examples
    --------
    >>> paper_item("pair-13"), paper_item("pair-13'"), paper_item("v-circle")
    ('(ii)', '', '(v)')
    """
    if family == "i":
        return "(i)"
    if family.startswith("pair-") and not family.endswith("'"):
        i, j = int(family[5]), int(family[6])
        return PAPER_PAIR_ITEMS.get((i, j), "")
    if family == "v" or family.startswith("v-"):
        return "(v)"
    return ""


@dataclass
class Family:
    """One family of singular configurations, with computed evidence (a row of ``singularities.csv``).

    Attributes
    ----------
    key : str
        Short id of the family.
    family : str
        Its name in the table.
    configuration : str
        The steering angles that make it (Markdown).
    geometric_meaning : str
        What the wheel-plane lines do there.
    listed_in_paper : str
        Whether the paper's list (i)-(v) after (59) contains it.
    paper_item : str
        The paper's item, e.g. ``"(ii)"`` (:func:`paper_item`), or ``""``.
    note : str
    samples : numpy.ndarray (n, 3)
        Representative configurations (radians).
    exact : callable or None
        Returns the list of (cos, sin) pairs (unnormalised directions of :math:`\\mathbf i_i`, SymPy)
        parameterising the family by free symbols, used for the exact check.
    det_J_max : float
        Computed: the largest :math:`|\\det\\mathbf J|` (58) over ``samples``.
    det_J_exact_zero : bool or None
        Computed: :math:`\\det\\mathbf J` vanishes identically on the family (None: not checked).
    rank_F : str
        Computed: the ranks of :math:`\\mathbf F` (24) seen on ``samples``.
    classified_as : str
        Computed: what :func:`wmr.analysis.singularities.classify` calls the samples.
    """

    key: str
    family: str
    configuration: str
    geometric_meaning: str
    listed_in_paper: str
    paper_item: str
    note: str
    samples: np.ndarray | None = None
    exact: Callable[[], Any] | None = None
    # computed
    det_J_max: float = float("nan")
    det_J_exact_zero: bool | None = None
    rank_F: str = ""
    classified_as: str = ""

    def row(self):
        """The family as a row of ``singularities.csv``.

        Returns
        -------
        dict
            Columns :data:`COLUMNS`; numbers as text.
        """
        return {
            "family": self.family,
            "configuration": self.configuration,
            "geometric_meaning": self.geometric_meaning,
            "det_J": bound(self.det_J_max),
            "det_J_exact": (
                "0 identically"
                if self.det_J_exact_zero
                else ("NOT zero" if self.det_J_exact_zero is False else "not checked")
            ),
            "rank_F": self.rank_F,
            "samples": 0 if self.samples is None else len(self.samples),
            "listed_in_paper": self.listed_in_paper,
            "paper_item": self.paper_item,
            "note": self.note,
        }


COLUMNS = (
    "family",
    "configuration",
    "geometric_meaning",
    "det_J",
    "det_J_exact",
    "rank_F",
    "samples",
    "listed_in_paper",
    "paper_item",
    "note",
)


def _exact_dirs_angles(angles):
    """(cos, sin) of exact angles (SymPy) as unnormalised axle directions."""
    return [(sp.cos(a), sp.sin(a)) for a in angles]


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
            exact=lambda: _exact_dirs_angles([tau, tau, tau]),
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
            exact=lambda: _exact_dirs_angles([tau + sp.pi, tau, tau]),
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
                        lambda i=i, j=j, k=k, ai=ai, prime=prime: _exact_dirs_angles(  # type: ignore[misc]
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
    out = {"(i)": exact_zero(poly, c, s, _exact_dirs_angles([tau, tau, tau]))}
    printed = {"(ii)": ((1, 3), (60, -120)), "(iii)": ((1, 2), (-60, 120)), "(iv)": ((2, 3), (0, 180))}
    for item, ((i, j), vals) in printed.items():
        for v in vals:
            ang = [v * deg if w in (i, j) else tau for w in (1, 2, 3)]
            out[f"{item} {v}"] = exact_zero(poly, c, s, _exact_dirs_angles(ang))
    x, y = sp.symbols("x y", real=True)
    dirs = []
    for u in robot.wheels:
        px, py = (sp.nsimplify(v) for v in u.position)
        dirs.append((y - py, -(x - px)))  # plane through D = (x, y)
    out["(v)"] = exact_zero(poly, c, s, dirs)
    return out


def table(robot=None, n=72, exact=True):
    """The families as rows of ``singularities.csv``: those of :func:`accounting`, counted modulo a half turn.

    ``listed_in_paper`` and ``paper_item`` say which printed items cover a family under the reading the report
    counts with (:data:`READINGS` ``"half-turn"``), computed from its configurations; ``note`` says what the
    other stated reading changes.

    Parameters
    ----------
    robot, n, exact
        As for :func:`families`.

    Returns
    -------
    list of dict
        One row per family (columns :data:`COLUMNS`, numbers as text).
    """
    rows = []
    for f in accounting(robot, n=n, exact=exact):
        row = f.row()
        if f.note == f.paper_item:
            row["note"] = "the same under either reading"
        elif f.note:
            row["note"] = (
                f'covered by {f.note} when $D_P$ may be a mount point (the reading "any point"), by '
                f"{f.paper_item or 'no printed item'} when not"
            )
        else:
            row["note"] = "covered by no printed item under either reading"
        rows.append(row)
    return rows


def write_csv(path, robot=None, n=72, exact=True):
    """Write ``singularities.csv`` (columns :data:`COLUMNS`) atomically.

    Parameters
    ----------
    path : str or os.PathLike
        Where to write (the caller knows the project; the library does not).
    robot, n, exact
        As for :func:`families`.

    Returns
    -------
    list of dict
        The rows written (:func:`table`).
    """
    rows = table(robot, n=n, exact=exact)
    atomic_write(path, csv_text(rows, COLUMNS))
    return rows


# --------------------------------------------------------------------------------------------------
# The accounting of the report (issue 19): the families modulo a half turn, and which printed item
# covers each, computed from the configurations themselves under a stated reading.

#: The readings under which the report compares the zero set with the printed list (i)-(v).  ``"half-turn"``
#: is the reading the report counts with; ``"any point"`` differs from it only in item (v).
READINGS = {
    "half-turn": (
        r"a steering angle matters modulo $180^\circ$ ($\beta_i$ and $\beta_i + 180^\circ$ give the same "
        r"wheel-plane line, and $\det\mathbf J$ only changes sign); (i) is all three lines parallel; "
        r"(ii)-(iv) the two named planes on the side $P_iP_j$, the third wheel free; (v) the three lines "
        r"through one finite point $D_P$ that is not a mount point"
    ),
    "any point": r"(v) also with $D_P$ at a mount point, the rest as in the reading above",
}

#: The printed items in the order of the paper.
ITEMS = ("(i)", "(ii)", "(iii)", "(iv)", "(v)")


def covering_items(robot, beta, reading="half-turn"):
    r"""Which printed items (i)-(v) of section 5.3 hold at each configuration, read as :data:`READINGS` says.

    Decided from the wheel-plane lines :math:`\ell_i` (through :math:`P_i` along :math:`\mathbf j_i`), with
    the one tolerance :data:`wmr.TOL` relative to the size of the robot.

    Parameters
    ----------
    robot : Robot
        Three centred wheels in the paper's numbering (:data:`PAPER_PAIR_ITEMS`).
    beta : array (n, 3)
        Configurations (radians).
    reading : {"half-turn", "any point"}

    Returns
    -------
    dict item -> numpy.ndarray (n,) of bool
        For each item of :data:`ITEMS`, where it holds.
    """
    from wmr.analysis.lines import wheel_plane_lines
    from wmr.model.tolerance import TOL

    if reading not in READINGS:
        raise ValueError(f"reading must be one of {sorted(READINGS)}, got {reading!r}")
    num = numeric_robot(robot)
    P, j = wheel_plane_lines(num, np.asarray(beta, dtype=float).reshape(-1, 3))  # (n, 3, 2) each
    scale = float(np.abs(num.mount_points).max())

    def cross(a, b):
        return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]

    pairs = ((0, 1), (0, 2), (1, 2))
    sines = np.stack([cross(j[:, a], j[:, b]) for a, b in pairs], axis=-1)  # (n, 3)
    out = {"(i)": np.all(np.abs(sines) <= TOL, axis=-1)}
    for (i, k), item in PAPER_PAIR_ITEMS.items():
        side = P[:, k - 1] - P[:, i - 1]
        tol = TOL * np.linalg.norm(side, axis=-1)
        out[item] = (np.abs(cross(j[:, i - 1], side)) <= tol) & (np.abs(cross(j[:, k - 1], side)) <= tol)
    best = np.argmax(np.abs(sines), axis=-1)  # two lines that cross
    a, b = np.array(pairs)[best].T
    rows = np.arange(len(j))
    Pa, ja, Pb, jb = P[rows, a], j[rows, a], P[rows, b], j[rows, b]
    den = cross(jb, ja)
    finite = np.abs(den) > TOL
    s = np.where(finite, cross(jb, Pb - Pa) / np.where(finite, den, 1.0), 0.0)
    D = Pa + s[:, None] * ja  # (n, 2)
    size = np.maximum(scale, np.abs(D).max(axis=-1))
    through = np.all(np.abs(cross(j, D[:, None, :] - P)) <= TOL * size[:, None], axis=-1)
    at_mount = np.min(np.linalg.norm(D[:, None, :] - P, axis=-1), axis=-1) <= TOL * size
    out["(v)"] = finite & through & (~at_mount if reading == "half-turn" else True)
    return out


def _mount_point_family(num, exact_bot, k, n):
    """(v-b) at the mount point P_k: the planes of the other two wheels through P_k, wheel k free."""
    t = np.linspace(-np.pi, np.pi, n, endpoint=False)
    th = sp.Symbol("t", real=True)
    Pex = [tuple(u.position) for u in exact_bot.wheels]
    base = planes_through(num, num.mount_points[k - 1])
    others = [w for w in (1, 2, 3) if w != k]
    blocks = []
    for f1, f2 in ((0, 0), (0, 1), (1, 0), (1, 1)):
        b = np.zeros((n, 3))
        b[:, others[0] - 1] = base[others[0] - 1] + f1 * np.pi
        b[:, others[1] - 1] = base[others[1] - 1] + f2 * np.pi
        b[:, k - 1] = t
        blocks.append(b)
    angles = ", ".join(rf"\beta_{w}\equiv{_deg(wrap_angle(base[w - 1]))}^\circ" for w in others)

    def dirs():
        kx, ky = Pex[k - 1]
        return [(sp.cos(th), sp.sin(th)) if w == k else (ky - Pex[w - 1][1], -(kx - Pex[w - 1][0])) for w in (1, 2, 3)]

    return Family(
        f"v-P{k}",
        rf"(v-b) planes through $P_{k}$",
        rf"${angles}$ (mod $180^\circ$), $\beta_{k}$ free",
        rf"$D_P = P_{k}$: the planes of wheels {others[0]} and {others[1]} lie on the sides through "
        rf"$P_{k}$; the plane of wheel {k} contains $P_{k}$ whatever $\beta_{k}$",
        "",
        "",
        "",
        samples=np.concatenate(blocks),
        exact=dirs,
    )


def accounting(robot=None, n=72, exact=True):
    r"""The singular families modulo a half turn, each with the printed items that cover it (computed).

    The families of :func:`families` with a wheel turned by :math:`180^\circ` are merged into the family
    they repeat (same wheel-plane lines); (v-b) is derived at each mount point separately
    (:math:`D_P = P_k`, the plane of wheel k through its own mount point whatever :math:`\beta_k`).  A family is
    *covered* by an item when the item holds at every sample of it (:func:`covering_items`), and *missed*
    under a reading when no item covers it.

    Parameters
    ----------
    robot, n, exact
        As for :func:`families`.

    Returns
    -------
    list of Family
        Computed fields as in :func:`families`; ``listed_in_paper`` is ``"yes"`` or ``"no"`` under the
        reading ``"half-turn"``, ``paper_item`` the covering items under it, and ``note`` those under
        ``"any point"``.
    """
    if robot is None:
        robot = paper_robot("centred")
    num = numeric_robot(robot)
    exact_bot = exact_robot(robot)
    fams = {f.key: f for f in families(robot, n=n, exact=exact)}
    merged = []
    for key in ("i", "pair-13", "pair-12", "pair-23"):
        f, g = fams[key], fams[key + "'"]
        both = Family(
            f.key,
            f.family.split(" ")[0],
            f.configuration + r" (mod $180^\circ$)",
            f.geometric_meaning,
            "",
            "",
            "",
            samples=np.concatenate([f.samples, g.samples]),
        )
        both.det_J_max = max(f.det_J_max, g.det_J_max)
        both.det_J_exact_zero = (
            None
            if f.det_J_exact_zero is None or g.det_J_exact_zero is None
            else f.det_J_exact_zero and g.det_J_exact_zero
        )
        both.rank_F = f.rank_F if f.rank_F == g.rank_F else f"{f.rank_F}; turned: {g.rank_F}"
        merged.append(both)
    merged += [fams["v"], fams["v-C"]]
    poly, c, s = det_J_polynomial(exact_bot)
    for k in (1, 2, 3):
        f = _mount_point_family(num, exact_bot, k, n)
        f.det_J_max = float(np.abs(det_J(num, f.samples)).max())
        vals, counts = np.unique(rank_F(num, f.samples), return_counts=True)
        f.rank_F = ", ".join(
            f"{int(v)} ({int(m)}/{len(f.samples)})"
            for v, m in sorted(zip(vals, counts, strict=True), key=lambda vm: -vm[1])
        )
        if exact:
            f.det_J_exact_zero = exact_zero(poly, c, s, f.exact())
        merged.append(f)
    merged.append(fams["v-circle"])
    for f in merged:
        cover = {}
        for reading in READINGS:
            holds = covering_items(num, f.samples, reading)
            cover[reading] = [item for item in ITEMS if holds[item].all()]
        f.paper_item = ", ".join(cover["half-turn"])
        f.listed_in_paper = "yes" if cover["half-turn"] else "no"
        f.note = ", ".join(cover["any point"])
    return merged
