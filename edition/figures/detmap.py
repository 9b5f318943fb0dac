r"""A map of det J and kappa(J) over :math:`(\beta_2,\beta_3)` for fixed :math:`\beta_1` (batched).

For each :math:`\beta_1` (a column of panels) an ``n`` x ``n`` grid of cell centres is evaluated
in one batch.  Solid black: the singular curves (zero contour of :math:`\det\mathbf J`); dashed:
configurations with concurrent axles (zero contour of :math:`\det\mathbf A`, the twist-constraint
matrix of :func:`wmr.analysis.mobility.twist_constraints`: rank F = 5, the robot can move);
markers: where both hold (:func:`wmr.analysis.singularities.singular_motions`).

Files: SVG and PDF, like every figure.  The colour maps are drawn unresampled
(``interpolation="none"``): each file embeds the grid's cells once, as a small image of snapped values,
and the viewer scales it, so the file does not depend on how a renderer anti-aliases.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr.analysis import lines as ln
from wmr.analysis import singularities as sg
from wmr.analysis.linalg import condition_number
from wmr.analysis.mobility import rank_F, twist_constraints
from wmr.analysis.steering import steering_angles
from wmr.model.platform import wrap_angle

from ..text import degrees
from ..text import residual as residual_text
from .common import ABS_DET_J, DEG, L_PAPER, centred_robot, drawing, residual, snap

__all__ = [
    "NUMBER",
    "TITLE",
    "PAPER_CAPTION",
    "MOBILE_TWISTS",
    "MOBILE_SEED",
    "DetSlice",
    "DetMapData",
    "refine_kappa_min",
    "data",
    "draw",
    "caption",
]

NUMBER = "E2"  # this edition's own figures: E1, E2 (the paper's are 1-14)
TITLE = "Singular configurations and conditioning of J"
PAPER_CAPTION = ""
#: Largest :math:`\log_{10}\kappa` shown (the colour scale is clipped there).
LOG_KAPPA_MAX = 2.0
KAPPA_ERROR = r"|\kappa(\mathbf{J}) - 1|"


@dataclass(frozen=True)
class DetSlice:
    r"""One slice :math:`\beta_1 = ` const.

    Attributes
    ----------
    beta1 : float
        Degrees.
    det_min : float
        Smallest :math:`\det\mathbf J/r^3` (58) on the grid.
    det_max : float
        Largest :math:`\det\mathbf J/r^3` on the grid.
    kappa_min : float
        Smallest :math:`\kappa(\mathbf J)` on the grid.
    kappa_min_refined : float
        The same minimum refined around the best grid point (:func:`refine_kappa_min`): the grid
        minimum rounds the true one up.
    singular_fraction : float
        Fraction of grid points where :math:`\mathbf J` is rank deficient (:math:`\kappa = \infty`).
    singular_motions : tuple of (beta2, beta3, family)
        Where :math:`\det\mathbf J = 0` and rank F = 5 (degrees; family from
        :func:`wmr.analysis.singularities.classify`).
    singular_motion_det_max : float
        Largest :math:`|\det\mathbf J|` there.
    singular_motion_ranks : tuple of int
        The ranks of F there.
    det : numpy.ndarray (n, n)
        Drawing only: :math:`\det\mathbf J/r^3`, rows :math:`\beta_3`, columns :math:`\beta_2`.
    log_kappa : numpy.ndarray (n, n)
        Drawing only: :math:`\log_{10}\kappa(\mathbf J)`, clipped to [0, 16].
    det_A : numpy.ndarray (n, n)
        Drawing only: the determinant of the twist-constraint matrix.
    """

    beta1: float
    det_min: float
    det_max: float
    kappa_min: float
    kappa_min_refined: float
    singular_fraction: float
    singular_motions: tuple
    singular_motion_det_max: float = residual()
    singular_motion_ranks: tuple = ()
    det: np.ndarray = drawing(default=None)  # (n, n) det J / r^3, rows beta3, columns beta2
    log_kappa: np.ndarray = drawing(default=None)  # (n, n) log10 kappa, clipped to [0, 16]
    det_A: np.ndarray = drawing(default=None)  # (n, n) det of the twist-constraint matrix


@dataclass(frozen=True)
class DetMapData:
    r"""The numbers of the det J map.

    Attributes
    ----------
    n : int
        Grid points per axis.
    slices : tuple of DetSlice
    a13 : float
        Angle (degrees) that puts plane 1 on :math:`P_1P_3`.
    a23 : float
        Angle (degrees) that puts plane 2 on :math:`P_2P_3`.
    vortex_beta_deg : tuple (3,)
        Every wheel turned :math:`45^\circ` from its radial line :math:`CP_i`.
    kappa_vortex : float
        :math:`\kappa(\mathbf J)` (30) there.
    kappa_vortex_minus : float
        The same at :math:`-45^\circ`.
    vortex_error : float
        :math:`\max|\kappa - 1|` of the two.
    vortex_rank_F : int
        rank F at the isotropic configuration (6: the robot cannot move there).
    mobile_twists : int
        Number of random twists (fixed seed) at whose steering angles :math:`\kappa(\mathbf J)` is evaluated.
    kappa_mobile_min : float
        Smallest :math:`\kappa(\mathbf J)` at those configurations, where the robot can move (:math:`\ge\sqrt2`).
    grid : numpy.ndarray (n,)
        Drawing only: the cell centres (degrees).
    lim : float
        Drawing only: the colour range of :math:`\det\mathbf J/r^3`.
    """

    n: int
    slices: tuple
    a13: float
    a23: float
    vortex_beta_deg: tuple
    kappa_vortex: float
    kappa_vortex_minus: float
    vortex_error: float = residual()
    vortex_rank_F: int = 0
    mobile_twists: int = 0
    kappa_mobile_min: float = 0.0
    grid: np.ndarray = drawing(default=None)  # (n,) degrees, cell centres
    lim: float = drawing(default=1.0)  # colour range of det J / r^3


def _slice(bot, beta1, g):
    B2, B3 = np.meshgrid(g, g, indexing="xy")
    beta = np.stack([np.full_like(B2, beta1), B2, B3], axis=-1) * DEG
    J = bot.J(beta, L=L_PAPER)
    D = np.linalg.det(J) / float(np.prod([u.r for u in bot.wheels]))
    kap = condition_number(J)
    A, _ = twist_constraints(bot, beta)
    mb, fams = sg.singular_motions(bot, beta1 * DEG)
    mdeg = np.degrees(mb)
    finite = kap[np.isfinite(kap)]
    k = np.argmin(snap(np.where(np.isfinite(kap), kap, np.inf)))  # snapped: ties (symmetry) go to the first
    return DetSlice(
        beta1=float(beta1),
        det_min=float(D.min()),
        det_max=float(D.max()),
        kappa_min=float(finite.min()),
        kappa_min_refined=refine_kappa_min(bot, beta1, B2.flat[k], B3.flat[k], g[1] - g[0]),
        singular_fraction=float(np.mean(~np.isfinite(kap))),
        singular_motions=tuple((float(a), float(b), f) for (_, a, b), f in zip(mdeg, fams, strict=True)),
        singular_motion_det_max=float(np.abs(sg.det_J(bot, mb)).max()),
        singular_motion_ranks=tuple(sorted(set(int(v) for v in rank_F(bot, mb)))),
        det=snap(D),
        log_kappa=snap(np.log10(np.clip(np.where(np.isfinite(kap), kap, 1e16), 1, 1e16))),
        det_A=snap(np.linalg.det(A)),
    )


def refine_kappa_min(bot, beta1, beta2, beta3, step, rounds=4, m=41):
    r"""Refine a grid minimum of :math:`\kappa(\mathbf J)` over :math:`(\beta_2, \beta_3)` at fixed :math:`\beta_1`.

    Each round evaluates an ``m`` x ``m`` grid (one batch) spanning one cell of the previous grid
    around its best point, so the cell shrinks by a factor ``(m - 1) / 2`` per round.

    Parameters
    ----------
    bot : wmr.Robot
        The robot (three steered wheels).
    beta1, beta2, beta3 : float
        Degrees: the slice and the best grid point.
    step : float
        Degrees: the spacing of the grid the point comes from.
    rounds, m : int, optional

    Returns
    -------
    float
        The refined minimum (never above :math:`\kappa` at the starting point).

    Examples
    --------
    >>> bot = centred_robot()
    >>> k = refine_kappa_min(bot, 60.0, -69.75, 170.55, 0.9)   # the best point of the 400 x 400 grid: 1.30209
    >>> round(k, 5)
    1.30189
    """
    best = (float(beta2), float(beta3))
    kmin = np.inf
    for _ in range(rounds):
        t = np.linspace(-step, step, m)
        B2, B3 = np.meshgrid(best[0] + t, best[1] + t, indexing="xy")
        beta = np.stack([np.full_like(B2, beta1), B2, B3], axis=-1) * DEG
        kap = condition_number(bot.J(beta, L=L_PAPER))
        k = int(np.argmin(snap(kap)))
        if kap.flat[k] < kmin:
            kmin, best = float(kap.flat[k]), (float(B2.flat[k]), float(B3.flat[k]))
        step *= 2.0 / (m - 1)
    return kmin


#: Random twists (fixed seed) at whose steering angles kappa(J) is sampled where the robot can move.
MOBILE_TWISTS = 2000
MOBILE_SEED = 2002


def _kappa_mobile_min(bot, n=MOBILE_TWISTS, seed=MOBILE_SEED):
    """Smallest kappa(J) at the steering angles of ``n`` random twists and of a spin about C."""
    twists = np.random.default_rng(seed).normal(size=(n, 3))
    twists = np.vstack([twists, [1.0, 0.0, 0.0]])
    return float(condition_number(bot.J(steering_angles(bot, twists), L=L_PAPER)).min())


def data(beta1s=(60.0, 20.0), n=400):
    r"""Evaluate :math:`\det\mathbf J` (58) and :math:`\kappa(\mathbf J)` (30) on slices ``beta1s`` (degrees), ``n`` x
    ``n`` each.

    Parameters
    ----------
    beta1s : sequence of float, optional
        The values of :math:`\beta_1` (degrees), one slice each.
    n : int, optional
        Grid points per axis (:math:`\beta_2`, :math:`\beta_3` over a full turn, at cell centres).

    Returns
    -------
    DetMapData
    """
    bot = centred_robot()
    g = -180.0 + (np.arange(n) + 0.5) * 360.0 / n  # cell centres: no sample sits exactly on a zero
    slices = tuple(_slice(bot, float(b1), g) for b1 in beta1s)
    alpha = np.arctan2(bot.mount_points[:, 1], bot.mount_points[:, 0])  # polar angles of the P_i
    kv = {sgn: float(condition_number(bot.J(alpha + sgn * 45 * DEG, L=L_PAPER))) for sgn in (1, -1)}
    return DetMapData(
        n=n,
        slices=slices,
        a13=float(np.degrees(ln.pair_line_angle(bot, 1, 3))),
        a23=float(np.degrees(ln.pair_line_angle(bot, 2, 3))),
        vortex_beta_deg=tuple(np.degrees(wrap_angle(alpha + 45 * DEG)).tolist()),
        kappa_vortex=kv[1],
        kappa_vortex_minus=kv[-1],
        vortex_error=max(abs(k - 1) for k in kv.values()),
        vortex_rank_F=int(rank_F(bot, alpha + 45 * DEG)),
        mobile_twists=MOBILE_TWISTS,
        kappa_mobile_min=_kappa_mobile_min(bot),
        grid=g,
        lim=float(np.round(max(max(abs(s.det_min), abs(s.det_max)) for s in slices), 3)),
    )


#: Marker and colour of the families in :attr:`DetSlice.singular_motions`.
_FAMILY_STYLE = {"i": ("o", "vermillion"), "i'": ("s", "vermillion"), "v-circle": ("^", "yellow")}


def draw(data, fig=None):
    """Draw the map from its data.

    Parameters
    ----------
    data : DetMapData
        The numbers (:func:`data`).
    fig : matplotlib.figure.Figure, optional
        Draw into this figure (cleared) instead of a new one.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib import colormaps
    from matplotlib.lines import Line2D

    from wmr.plot.style import FONT_SMALL, PALETTE, new_figure, style

    g, ns = data.grid, len(data.slices)
    with style():
        fig, axes = new_figure(2, ns, width=7.2, height=6.6, fig=fig, drawing=False)
        axes = np.reshape(axes, (2, ns))
        for col, sl in enumerate(data.slices):
            maps = (
                (sl.det, dict(cmap=colormaps["PuOr"].resampled(64), vmin=-data.lim, vmax=data.lim)),
                (sl.log_kappa, dict(cmap=colormaps["cividis"].resampled(64), vmin=0, vmax=LOG_KAPPA_MAX)),
            )
            for row, (Z, kw) in enumerate(maps):
                ax = axes[row, col]
                m = ax.imshow(
                    Z, extent=(-180, 180, -180, 180), origin="lower", interpolation="none", aspect="equal", **kw
                )
                ax.contour(g, g, sl.det, levels=[0.0], colors=[PALETTE["black"]], linewidths=1.2)
                ax.contour(
                    g, g, sl.det_A, levels=[0.0], colors=[PALETTE["sky"]], linewidths=1.0, linestyles=[(0, (4, 2))]
                )
                for a, b, f in sl.singular_motions:
                    mk, c = _FAMILY_STYLE.get(f, ("x", "black"))
                    ax.plot(
                        *snap([a, b]),
                        marker=mk,
                        color=PALETTE[c],
                        markersize=6,
                        markeredgecolor=PALETTE["black"],
                        markeredgewidth=0.7,
                        linestyle="none",
                        zorder=5,
                        clip_on=False,
                    )
                ax.set_xlim(-180, 180)
                ax.set_ylim(-180, 180)
                ax.set_xticks(np.arange(-180, 181, 90))
                ax.set_yticks(np.arange(-180, 181, 90))
                ax.tick_params(labelsize=FONT_SMALL)
                ax.set_xlabel(r"$\beta_2$ (deg)")
                if col == 0:
                    ax.set_ylabel(r"$\beta_3$ (deg)")
                what = r"$\det\mathbf{J}/r^3$" if row == 0 else r"$\log_{10}\kappa(\mathbf{J})$"
                ax.set_title(f"({'abcd'[row * ns + col]}) {what}, $\\beta_1 = {sl.beta1:g}^\\circ$", loc="left")
                if col == ns - 1:
                    fig.colorbar(
                        m, ax=axes[row, :].tolist(), shrink=0.9, label=what, extend="neither" if row == 0 else "max"
                    )
        handles = [
            Line2D([], [], color=PALETTE["black"], lw=1.2, label=r"$\det\mathbf{J} = 0$"),
            Line2D(
                [], [], color=PALETTE["sky"], lw=1.0, ls=(0, (4, 2)), label=r"axles concurrent (rank $\mathbf{F}=5$)"
            ),
        ]
        for f, lab in (("i", "(i)"), ("i'", "(i')"), ("v-circle", "IC on the circle through the $P_i$")):
            mk, c = _FAMILY_STYLE[f]
            handles.append(
                Line2D(
                    [],
                    [],
                    marker=mk,
                    color=PALETTE[c],
                    markeredgecolor=PALETTE["black"],
                    markeredgewidth=0.7,
                    linestyle="none",
                    markersize=6,
                    label=lab,
                )
            )
        fig.legend(handles=handles, loc="outside lower center", ncols=3)
    return fig


def caption(data):
    """Our caption of the map (Markdown with ``$...$``).

    Parameters
    ----------
    data : DetMapData
        The numbers (:func:`data`).

    Returns
    -------
    str
        Markdown with ``$...$`` math.
    """
    b1 = [s.beta1 for s in data.slices]
    det_max = max(s.singular_motion_det_max for s in data.slices)
    kmin = min(s.kappa_min_refined for s in data.slices)
    vortex = ", ".join(degrees(np.radians(b)) for b in data.vortex_beta_deg)
    return (
        rf"$\det\mathbf{{J}}/r^3$ (top) and $\log_{{10}}\kappa(\mathbf{{J}})$ (bottom, clipped at "
        rf"{LOG_KAPPA_MAX:g}) of the WMR with three centred wheels over $(\beta_2, \beta_3)$ for "
        rf"$\beta_1 = {b1[0]:g}^\circ$ (left) and ${b1[1]:g}^\circ$ (right), each on a {data.n}$\times${data.n} "
        r"grid evaluated in one batch. Black: the singular curves $\det\mathbf{J} = 0$. For $\beta_1 = "
        rf"{b1[0]:g}^\circ$ plane 1 lies on the side $P_1P_3$, and the singular set is the straight lines $\beta_3 "
        rf"\equiv {degrees(np.radians(data.a13))}^\circ$ (item (ii) and its half-turn variant) and $\beta_2 \equiv "
        rf"{degrees(np.radians(data.a23))}^\circ$ (mod $180^\circ$; planes 1 and 2 through $P_3$, $\beta_3$ free); "
        r"for a generic $\beta_1$ it is a curve. Dashed: configurations with concurrent axles, the "
        r"only ones in which the robot can move (rank $\mathbf{F} = 5$). Markers: where the robot can move "
        r"although "
        rf"$\mathbf{{J}}$ is singular (computed ${residual_text(ABS_DET_J, det_max)}$, rank "
        r"$\mathbf{F} = 5$): all planes parallel, (i): all $\beta_i$ equal, and (i'): one wheel turned by $180^\circ$ "
        r"from the others; and rotations about a point of the circle through the "
        rf"$P_i$. On these slices the smallest $\kappa(\mathbf{{J}})$ is {kmin:.4f} (the grid minimum, "
        r"refined): although $\mathbf{J}_{L1}$ and $\mathbf{J}_2$ are isotropic, $\mathbf{J}$ is isotropic only at "
        r"special configurations, e.g. with every wheel turned by the same $45^\circ$ from its radial line $CP_i$ "
        rf"(computed ${residual_text(KAPPA_ERROR, data.vortex_error)}$ at $\beta = ({vortex})^\circ$), where rank "
        rf"$\mathbf{{F}} = {data.vortex_rank_F}$ and the robot cannot move. Where it can move (dashed), "
        rf"$\kappa(\mathbf{{J}}) \geq \sqrt2$: the smallest value at the steering angles of {data.mobile_twists} "
        rf"random twists and of a spin about $C$ is {data.kappa_mobile_min:.4f}."
    )
