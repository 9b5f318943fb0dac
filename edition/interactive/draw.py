r"""The figures of a state: one :class:`matplotlib.figure.Figure` each, and a PNG of a figure.

Part of the interactive chapter: :mod:`edition.interactive`.
"""

from __future__ import annotations

import io

import numpy as np

from wmr.analysis.lines import AT_INFINITY, FINITE

from ..text import number

__all__ = ["draw_steering", "draw_mounts", "png", "DPI", "LEGEND_PT", "TITLE_PT"]

#: the pictures are small in inches and rendered at 120 dpi, so that their text (legend 9 pt, title 10.5 pt,
#: labels 9 pt) stays at least 14 px high when JupyterLab shrinks the picture to a narrow notebook (820 px window)
DPI = 120
LEGEND_PT = 9.0
TITLE_PT = 10.5


def _deg(x):
    return f"{np.degrees(x):.0f}^\\circ"


def draw_steering(state, fig=None):
    """The robot at ``state``: wheels, axle lines (blue), wheel-plane lines (vermillion), the centre U and :math:`D_P`.

    Parameters
    ----------
    state : SteeringState
    fig : matplotlib.figure.Figure, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.lines import Line2D

    from wmr.plot.annotate import draw_line, draw_point, label
    from wmr.plot.robot import draw_robot, platform_radius, robot_geometry
    from wmr.plot.style import DASHES, ROLE, fit_view, new_figure, style

    with style():
        fig, (ax,) = new_figure(1, 1, width=4.2, height=4.0, fig=fig)
        g = robot_geometry(state.robot, state.beta)
        R = platform_radius(state.robot)
        view = 2.6 * R
        U = state.axles.point if state.axles.kind == FINITE and np.linalg.norm(state.axles.point) < view else None
        D = state.planes.point if state.planes.kind == FINITE and np.linalg.norm(state.planes.point) < view else None
        for k in range(3):
            pts = [p for p in (U,) if p is not None]
            draw_line(ax, g.P[k], g.i[k], pts, kind="axle", margin=0.35 * R, min_half=1.2 * R)
            pts = [p for p in (D,) if p is not None]
            draw_line(ax, g.P[k], g.j[k], pts, kind="plane", margin=0.35 * R, min_half=1.2 * R)
        draw_robot(ax, state.robot, state.beta, arrows="j")
        if U is not None and state.mobility > 0:
            draw_point(ax, U, None, color=ROLE["ic"], size=6, zorder=9)
            label(ax, U, "$U$", offset=(6, 6), color=ROLE["ic"])
        if D is not None:
            draw_point(ax, D, None, marker="s", color=ROLE["dp"], size=5, zorder=9)
            label(ax, D, "$D_P$", offset=(6, -10), color=ROLE["dp"])
        if state.motion is not None and state.axles.kind == AT_INFINITY:
            v = state.motion[1:] / max(np.linalg.norm(state.motion[1:]), 1e-12)
            ax.annotate(
                "",
                xy=tuple(0.9 * R * v),
                xytext=(0, 0),
                arrowprops=dict(arrowstyle="-|>", color=ROLE["ic"], lw=1.6),
                zorder=9,
            )
        fit_view(ax, np.array([[-view, -view], [view, view]]) * 0.62, pad=0.02)
        handles = [
            Line2D([], [], color=DASHES["axle"][0], ls=DASHES["axle"][1], lw=1.2, label="axle lines"),
            Line2D([], [], color=DASHES["plane"][0], ls=DASHES["plane"][1], lw=1.2, label="wheel-plane lines"),
            Line2D([], [], color=ROLE["ic"], marker="o", ls="none", label="$U$: centre of rotation"),
            Line2D([], [], color=ROLE["dp"], marker="s", ls="none", label="$D_P$: planes meet"),
        ]
        ax.legend(
            handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.02), ncols=2, fontsize=LEGEND_PT, frameon=False
        )
        verdict = "can move" if state.mobility > 0 else "cannot move"
        ax.set_title(rf"$\beta = ({', '.join(_deg(b) for b in state.beta)})$: the robot {verdict}", fontsize=TITLE_PT)
    return fig


def draw_mounts(state, fig=None):
    r"""Three mount points, their centroid, the circle of radius L about C and the triangle.

    Parameters
    ----------
    state : MountState
    fig : matplotlib.figure.Figure, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, Polygon

    from wmr.plot.annotate import draw_point, label
    from wmr.plot.style import PALETTE, fit_view, new_figure, style

    with style():
        fig, (ax,) = new_figure(1, 1, width=4.0, height=3.9, fig=fig)
        p = state.points
        ax.add_patch(Polygon(p, closed=True, facecolor=PALETTE["light"], edgecolor=PALETTE["grey"], lw=0.9))
        ax.add_patch(Circle((0, 0), state.L, facecolor="none", edgecolor=PALETTE["blue"], lw=0.9, ls=(0, (5, 3))))
        ax.add_patch(Circle((0, 0), state.L_rms, facecolor="none", edgecolor=PALETTE["green"], lw=0.8, ls=(0, (1, 2))))
        draw_point(ax, (0, 0), None, size=5)
        label(ax, (0, 0), "$C$", offset=(-6, 6), ha="right", va="bottom")
        draw_point(ax, state.centroid, None, marker="x", color=PALETTE["vermillion"], size=7, zorder=8)
        label(ax, state.centroid, r"$\bar P$", offset=(6, -6), ha="left", va="top", color=PALETTE["vermillion"])
        handles = [
            Line2D([], [], color=PALETTE["blue"], ls=(0, (5, 3)), label=f"radius $L = {state.L:.3g}$"),
            Line2D([], [], color=PALETTE["green"], ls=(0, (1, 2)), label=f"RMS distance ${state.L_rms:.3g}$"),
            Line2D([], [], color=PALETTE["vermillion"], marker="x", ls="none", label=r"centroid $\bar P$"),
        ]
        ax.legend(
            handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.02), ncols=2, fontsize=LEGEND_PT, frameon=False
        )
        for k, q in enumerate(p, 1):
            draw_point(ax, q, None, size=5, color=PALETTE["dark"])
            label(ax, q, f"$P_{k}$", offset=(6, 6))
        m = max(float(np.abs(p).max()), state.L, state.L_rms) * 1.25
        fit_view(ax, np.array([[-m, -m], [m, m]]), pad=0.02)
        ax.set_title(
            rf"$\kappa(\mathbf{{J}}_{{L1}}) = {number(state.kappa, 4)}$ at $L = {state.L:.3g}$", fontsize=TITLE_PT
        )
    return fig


def png(fig, dpi=DPI):
    """The figure as PNG bytes (Agg), without registering it anywhere.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    dpi : int

    Returns
    -------
    bytes
    """
    from wmr.plot.style import style

    buf = io.BytesIO()
    with style():
        fig.savefig(buf, format="png", dpi=dpi)
    return buf.getvalue()
