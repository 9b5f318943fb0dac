r"""Fig. 10: the singular configuration :math:`\beta_1=\beta_2=\beta_3` (item (i), IC at infinity).

With the computed :math:`\det\mathbf J` (exact and float), rank F and the admissible twist.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr.analysis.mobility import admissible_twists
from wmr.model.platform import E

from ..text import residual as residual_text
from .common import ABS_DET_J, DEG, L_PAPER, centred_robot, drawing, snap
from .configs import SingularConfig, singular_config

__all__ = ["NUMBER", "TITLE", "PAPER_CAPTION", "Fig10Data", "data", "draw", "caption"]

NUMBER = "10"
TITLE = "Singular configuration with IC at infinity"
PAPER_CAPTION = r"Singular configuration with IC at infinity ($\beta_1 = \beta_2 = \beta_3$)."


@dataclass(frozen=True)
class Fig10Data:
    r"""The numbers of Fig. 10.

    Attributes
    ----------
    beta : float
        The common steering angle, degrees.
    config : SingularConfig
    admissible : tuple (3,)
        Unit twist :math:`(\dot\psi, \dot{\mathbf c})` spanning the admissible twists
        (:func:`wmr.admissible_twists`), signed so that its largest component is positive.
    line_gap : float
        The smallest distance, in units of :math:`L`, between two of the three parallel axle lines
        or two of the three parallel wheel-plane lines: zero when one line hides another.
    robot : wmr.Robot
        Drawing only: the robot drawn (:func:`~edition.figures.common.centred_robot`).
    """

    beta: float
    config: SingularConfig
    admissible: tuple
    line_gap: float
    robot: object = drawing(default=None)


def data(beta=15.0):
    r"""The configuration :math:`\beta_i = ` ``beta`` for every wheel: item (i) of the list after (59).

    Parameters
    ----------
    beta : float, optional
        The common steering angle (degrees).  The default, :math:`15^\circ`, keeps the three axle lines
        and the three wheel-plane lines apart (:attr:`Fig10Data.line_gap`); at multiples of
        :math:`30^\circ` two of them coincide and the drawing shows two lines for three wheels.

    Returns
    -------
    Fig10Data
    """
    bot = centred_robot()
    bdeg = [beta] * 3
    b = np.asarray(bdeg) * DEG
    A = admissible_twists(bot, b)
    if A.shape[1] != 1:
        raise ValueError(f"expected one admissible direction at beta = {beta!r} deg, found {A.shape[1]}")
    t = A[:, 0] / np.linalg.norm(A[:, 0])
    t = t if t[np.argmax(snap(np.abs(t)))] > 0 else -t  # snapped: equal components tie to the first
    i = np.array([np.cos(b[0]), np.sin(b[0])])  # axle direction, the same for every wheel
    offsets = (bot.mount_points @ (E() @ i), bot.mount_points @ i)  # where each axle / plane line lies
    gap = min(float(np.diff(np.sort(o)).min()) for o in offsets) / L_PAPER
    return Fig10Data(
        beta=beta, config=singular_config(bot, b, exact_deg=bdeg), admissible=tuple(t.tolist()), line_gap=gap, robot=bot
    )


def draw(data, fig=None):
    """Draw Fig. 10 from its data.

    Parameters
    ----------
    data : Fig10Data
        The numbers (:func:`data`).
    fig : matplotlib.figure.Figure, optional
        Draw into this figure (cleared) instead of a new one.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from wmr.plot import annotate as an
    from wmr.plot.style import PALETTE, fit_view, new_figure, style

    from .sketch import LINES_LEGEND, draw_singular

    cfg = data.config
    with style():
        fig, (ax,) = new_figure(1, 1, width=5.0, height=4.6, fig=fig)
        g, ext = draw_singular(ax, data.robot, cfg)
        v = snap(data.admissible[1:]) / np.linalg.norm(data.admissible[1:])
        v = v if v[1] >= 0 else -v
        for sgn in (1, -1):
            an.draw_arrow(ax, g.C + sgn * 0.06 * v, sgn * 0.5 * v, color=PALETTE["green"], lw=2.0, head=11, zorder=9)
        an.label(
            ax, g.C + 0.5 * v, r"$\dot{\mathbf{c}}$", offset=(-7, 0), ha="right", va="center", color=PALETTE["green"]
        )
        fit_view(ax, ext, pad=0.06)
        fig.legend(
            handles=an.legend_handles(LINES_LEGEND[:2] + [("admissible motion", f"path:{PALETTE['green']}")]),
            loc="outside upper center",
            ncols=3,
        )
        an.scale_bar(ax, L_PAPER, "$L$", loc=(0.03, 0.03))
    return fig


def caption(data):
    """Our caption of Fig. 10 (Markdown with ``$...$``).

    Parameters
    ----------
    data : Fig10Data
        The numbers (:func:`data`).

    Returns
    -------
    str
        Markdown with ``$...$`` math.
    """
    cfg = data.config
    return (
        rf"Singular configuration with the IC at infinity, $\beta_1 = \beta_2 = \beta_3 = {data.beta:g}^\circ$ "
        rf"(item (i)). Computed: $\det\mathbf{{J}} = {cfg.det_J_exact}$ exactly "
        rf"(${residual_text(ABS_DET_J, abs(cfg.det_J))}$ in floating point), rank $\mathbf{{F}} = "
        rf"{cfg.rank_F}$ (mobility {cfg.mobility}): the wheel planes (dash-dotted) and the axles (dashed) are "
        r"parallel, and the only admissible motion is the translation along the wheel planes (green)."
    )
