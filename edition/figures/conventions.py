r"""A drawing of the package's conventions (:mod:`wmr.conventions`), computed from the model.

(a) Fixed frame :math:`\mathcal F`, body frame :math:`\mathcal B` at C, :math:`\psi`,
:math:`\mathbf c`, :math:`\mathbf d_i = \overrightarrow{CP_i}`; (b) an offset wheel:
:math:`\beta_i` from :math:`\mathbf i` to :math:`\mathbf i_i`, :math:`\mathbf j_i`,
:math:`H_i = P_i - d\,\mathbf j_i`; (c) a dual wheel: wheels at :math:`P_i \pm b\,\mathbf i_i`.
The points and unit vectors are those of :meth:`wmr.OffsetWheel.points` and
:meth:`wmr.DualWheel.points`, not drawn by hand.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr.model.robots import paper_robot
from wmr.model.wheels import DualWheel, OffsetWheel

from .common import DEG, L_PAPER, R_CENTRED, drawing, snap

__all__ = ["NUMBER", "TITLE", "PAPER_CAPTION", "ConventionsData", "data", "draw", "caption"]

NUMBER = "E1"  # this edition's own figures: E1, E2 (the paper's are 1-14)
TITLE = "Conventions"
PAPER_CAPTION = ""


@dataclass(frozen=True)
class ConventionsData:
    r"""The numbers of the conventions drawing (body frame, units of L; angles in degrees).

    Attributes
    ----------
    psi : float
        Platform orientation drawn, degrees.
    beta : float
        Steering angle drawn, degrees.
    r : float
        Wheel radius.
    d : float
        Offset of the offset wheel drawn.
    b : float
        Half-track of the dual wheel drawn.
    i : tuple (2,)
        :math:`\mathbf i_i` (11) of the offset wheel at :math:`\beta`.
    j : tuple (2,)
        :math:`\mathbf j_i` of the offset wheel at :math:`\beta`.
    H_minus_P : tuple (2,)
        :math:`H_i - P_i` of the offset wheel.
    dual_wheels : tuple of 2 (2,)
        Wheel centres of the dual wheel (mounted at the origin).
    mount_points : tuple of 3 (2,)
        The paper's :math:`\mathbf d_1, \mathbf d_2, \mathbf d_3`.
    robot : wmr.Robot
        Drawing only: the paper's robot of panel (a).
    units : tuple
        Drawing only: the offset and the dual wheel of panels (b) and (c).
    """

    psi: float
    beta: float
    r: float
    d: float
    b: float
    i: tuple
    j: tuple
    H_minus_P: tuple
    dual_wheels: tuple
    mount_points: tuple
    robot: object = drawing(default=None)
    units: tuple = drawing(default=())


def data(psi=25.0, beta=35.0, r=0.3, b=0.45):
    """The conventions at platform angle ``psi`` and steering angle ``beta``.

    Parameters
    ----------
    psi : float, optional
        Platform orientation (degrees).
    beta : float, optional
        Steering angle of the wheels of panels (b) and (c) (degrees).
    r : float, optional
        Wheel radius (and offset) of those wheels (units of L).
    b : float, optional
        Half-track of the dual wheel (units of L).

    Returns
    -------
    ConventionsData
    """
    bot = paper_robot("centred", L=L_PAPER, r=R_CENTRED)
    ow = OffsetWheel((0.0, 0.0), r=r, d=r)
    dw = DualWheel((0.0, 0.0), r=r, b=b)
    po, pd = ow.points(beta * DEG), dw.points(beta * DEG)
    return ConventionsData(
        psi=psi,
        beta=beta,
        r=r,
        d=r,
        b=b,
        i=tuple(po["i"].tolist()),
        j=tuple(po["j"].tolist()),
        H_minus_P=tuple((po["H"] - po["P"]).tolist()),
        dual_wheels=tuple(map(tuple, pd["wheels"].tolist())),
        mount_points=tuple(map(tuple, bot.mount_points.tolist())),
        robot=bot,
        units=(ow, dw),
    )


def draw(data, fig=None):
    """Draw the conventions from their data.

    Parameters
    ----------
    data : ConventionsData
        The numbers (:func:`data`).
    fig : matplotlib.figure.Figure, optional
        Draw into this figure (cleared) instead of a new one.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from wmr.plot import annotate as an
    from wmr.plot import robot as rd
    from wmr.plot.style import FONT_SMALL, PALETTE, ROLE, fit_view, new_figure, panel_title, style

    bot, (ow, dw) = data.robot, data.units
    psi, beta = data.psi * DEG, data.beta * DEG
    P = np.zeros(2)
    H, i_, j_ = snap(data.H_minus_P), snap(data.i), snap(data.j)
    with style():
        fig, axes = new_figure(1, 3, width=7.4, height=2.3, fig=fig)
        # (a) frames
        ax = axes[0]
        an.draw_frame(
            ax,
            (0, 0),
            0.0,
            0.5,
            labels=(r"$\mathbf{i}_\mathcal{F}$", r"$\mathbf{j}_\mathcal{F}$"),
            color=ROLE["fixed_frame"],
        )
        an.label(ax, (0, 0), r"$\mathcal{F}$", offset=(-4, -4), ha="right", va="top", color=ROLE["fixed_frame"])
        g = rd.draw_robot(
            ax,
            bot,
            np.zeros(3),
            (psi, 1.55, 1.1),
            frame=False,
            label_offsets={"C": (-2, -7), 2: (-12, 6), 1: (-13, 0), 3: (13, 0)},
            arrows="j",
        )
        an.draw_frame(ax, g.C, psi, 0.6, zorder=8)
        ax.plot(*np.stack([g.C, g.C + [0.9, 0.0]]).T, color=PALETTE["grey"], lw=0.6, ls=(0, (2, 2)))
        an.draw_angle(ax, g.C, 0.82, 0.0, psi, r"$\psi$", text_radius=1.2)
        an.draw_arrow(ax, g.C, g.P[1] - g.C, color=PALETTE["blue"], lw=1.1, head=7, zorder=8)
        an.label(
            ax,
            g.C + 0.62 * (g.P[1] - g.C),
            r"$\mathbf{d}_2$",
            offset=(7, -2),
            ha="left",
            va="center",
            color=PALETTE["blue"],
        )
        an.draw_arrow(ax, (0, 0), g.C, color=PALETTE["grey"], lw=0.8, head=6, zorder=3)
        an.label(ax, 0.35 * g.C, r"$\mathbf{c}$", offset=(4, -4), ha="left", va="top", color=PALETTE["grey"])
        fit_view(ax, np.vstack([rd.robot_extent(g, rd.platform_radius(bot)), [[-0.35, -0.35]]]), pad=0.02)
        panel_title(ax, "a", r"frames $\mathcal{F}$ and $\mathcal{B}$")
        # (b) offset wheel, (c) dual wheel
        for ax, unit in ((axes[1], ow), (axes[2], dw)):
            ax.plot(*np.stack([P, P + [0.8, 0.0]]).T, color=PALETTE["grey"], lw=0.6, ls=(0, (2, 2)))
            an.label(
                ax,
                P + [0.8, 0.0],
                r"$\mathbf{i}$",
                offset=(3, 0),
                ha="left",
                va="center",
                color=PALETTE["grey"],
                fontsize=FONT_SMALL,
            )
            rd.draw_unit(ax, unit, beta, light=True, zorder=3, arrows="j")
            an.draw_frame(
                ax, P, beta, 0.62, labels=(r"$\mathbf{i}_i$", r"$\mathbf{j}_i$"), color=PALETTE["blue"], zorder=7
            )
            arc = 0.42 if unit is ow else 0.27  # inside wheel 1 of the dual wheel
            an.draw_angle(
                ax,
                P,
                arc,
                0.0,
                beta,
                r"$\beta_i$",
                text_radius=1.35 if unit is ow else 1.5,
                color=PALETTE["purple"],
                zorder=7,
            )
            an.label(ax, P, "$P_i$", offset=(-7, 4), ha="right", va="bottom")
            fit_view(ax, np.array([[-0.72, -0.78], [0.95, 0.72]]), pad=0.0)
        ax = axes[1]
        an.draw_line(ax, H, i_, kind="axle", min_half=0.5, margin=0.05)
        an.draw_point(ax, H, None, size=3.5, color=PALETTE["dark"], zorder=9)
        an.label(ax, H, "$H_i$", offset=(8, -3), ha="left", va="top")
        an.label(ax, 0.5 * (P + H), "$d$", offset=(-7, -2), ha="right", va="center", color=PALETTE["vermillion"])
        ax.plot(*np.stack([P, H]).T, color=PALETTE["vermillion"], lw=1.6, zorder=8)
        panel_title(ax, "b", r"offset wheel: $H_i = P_i - d\,\mathbf{j}_i$")
        ax = axes[2]
        for k, w_ in enumerate(snap(data.dual_wheels)):
            an.label(
                ax,
                w_ + (1 - 2 * k) * (data.r + 0.1) * j_,  # wheel 1 beyond its front, wheel 2 beyond its back
                f"wheel {k + 1}",
                offset=(0, 0),
                ha="center",
                va="center",
                fontsize=FONT_SMALL,
            )
        panel_title(ax, "c", r"dual wheel: wheels at $P_i \pm b\,\mathbf{i}_i$")
    return fig


def _exact(point):
    """A mount point (units of L) as exact LaTeX, e.g. ``L\\left(\\frac{1}{2}, \\frac{\\sqrt{3}}{2}\\right)``."""
    import sympy as sp

    xy = [sp.latex(sp.nsimplify(v / L_PAPER, [sp.sqrt(3)], tolerance=1e-12)) for v in point]
    return rf"L\left({xy[0]}, {xy[1]}\right)"


def caption(data):
    """Our caption of the conventions drawing (Markdown with ``$...$``).

    Parameters
    ----------
    data : ConventionsData
        The numbers (:func:`data`).

    Returns
    -------
    str
        Markdown with ``$...$`` math.
    """
    return (
        r"Conventions of the package. (a) Fixed frame $\mathcal{F}$ and body frame $\mathcal{B}$ "
        r"($\mathbf{i}$, $\mathbf{j}$) at the operation point $C$, turned by $\psi$ (counter-clockwise positive, "
        rf"here {data.psi:g}$^\circ$); $\mathbf{{c}}$ locates $C$ in $\mathcal{{F}}$ and "
        r"$\mathbf{d}_i = \overrightarrow{CP_i}$ is resolved in $\mathcal{B}$; the numbering inferred from (59) (the "
        r"paper does not state it; the only one of 24 for which (59) holds) "
        + ", ".join(rf"$\mathbf{{d}}_{k + 1} = {_exact(p)}$" for k, p in enumerate(data.mount_points))
        + ". "
        rf"(b) Offset wheel: the intermediate body turns by $\beta_i$ (here {data.beta:g}$^\circ$) from "
        r"$\mathbf{i}$ to the axle $\mathbf{i}_i$; $\mathbf{j}_i$ is the rolling direction (arrows on the wheels) "
        r"and the wheel centre is $H_i = P_i - d\,\mathbf{j}_i$ (a centred wheel has $d = 0$). (c) Dual wheel: "
        r"wheel 1 at $P_i + b\,\mathbf{i}_i$, wheel 2 at $P_i - b\,\mathbf{i}_i$. No slip: "
        r"$\dot{\mathbf{h}}_i = -r\dot\theta_i\mathbf{j}_i$."
    )
