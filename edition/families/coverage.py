r"""The accounting of the report (issue 19): the singular families modulo a half turn, and which printed item
covers each, computed from the configurations themselves under a stated reading (:data:`READINGS`);
:func:`table` and :func:`write_csv` give them as the rows of ``singularities.csv``.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.lines import planes_through
from wmr.analysis.mobility import rank_F
from wmr.analysis.singularities import det_J, det_J_polynomial, exact_robot, exact_zero, numeric_robot
from wmr.model.platform import wrap_angle
from wmr.model.robots import paper_robot

from ..files import atomic_write, csv_text
from ..text import degrees as _deg
from .catalogue import families
from .family import COLUMNS, PAPER_PAIR_ITEMS, Family

__all__ = ["READINGS", "ITEMS", "covering_items", "accounting", "table", "write_csv"]


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


def _free_parameters(family):
    """How many free symbols the exact parameterisation of ``family`` has (``-1`` without one)."""
    if family.exact is None:
        return -1
    free = set()
    for pair in family.exact():
        for c in pair:
            free |= sp.sympify(c).free_symbols
    return len(free)


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
            exact=f.exact,
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
        f.covered_any_point = "yes" if cover["any point"] else "no"
        f.free_parameters = _free_parameters(f)
    return merged


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
