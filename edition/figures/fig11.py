r"""Fig. 11: the three configurations with two wheel planes coincident (items (ii)-(iv), the paper's (a)-(c)).

Defaults: (a) :math:`\beta_1=\beta_3=60^\circ`, :math:`\beta_2=140^\circ`; (b)
:math:`\beta_1=\beta_2=-60^\circ`, :math:`\beta_3=20^\circ`; (c) :math:`\beta_2=\beta_3=0^\circ`,
:math:`\beta_1=80^\circ` (the same picture turned by 120 degrees each time, up to a half turn of
wheel 1 in (c)).  For each: :math:`D_{ij}`, :math:`\det\mathbf J` (exact and float), rank F.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..text import residual as residual_text
from .common import ABS_DET_J, DEG, centred_robot, drawing
from .configs import beta_text, singular_config

__all__ = ["NUMBER", "TITLE", "PAPER_CAPTION", "CONFIGS", "Fig11Data", "data", "draw", "caption"]

NUMBER = "11"
TITLE = "Singular configurations with two wheel planes coincident"
PAPER_CAPTION = "Singular configurations with two wheel planes coincident."

#: The panels' steering angles, degrees.
CONFIGS = {"a": (60.0, 140.0, 60.0), "b": (-60.0, -60.0, 20.0), "c": (80.0, 0.0, 0.0)}


@dataclass(frozen=True)
class Fig11Data:
    """The numbers of Fig. 11: the singular configurations of its panels.

    Attributes
    ----------
    configs : dict
        Panel letter -> steering angles (3 floats, degrees).
    panels : dict
        Panel letter -> :class:`~edition.figures.configs.SingularConfig`.
    robot : wmr.Robot
        Drawing only: the robot drawn (:func:`~edition.figures.common.centred_robot`).
    """

    configs: dict
    panels: dict
    robot: object = drawing(default=None)


def data(configs=None):
    """The singular configurations ``configs``, one panel each.

    Parameters
    ----------
    configs : dict, optional
        Panel letter -> 3 steering angles in degrees (default :data:`CONFIGS`).

    Returns
    -------
    Fig11Data
    """
    bot = centred_robot()
    configs = {k: tuple(map(float, v)) for k, v in (configs or CONFIGS).items()}
    panels = {k: singular_config(bot, np.asarray(b) * DEG, exact_deg=b) for k, b in configs.items()}
    for k, cfg in panels.items():
        if not cfg.coincident:
            raise ValueError(f"configs[{k!r}] = {configs[k]} has no two coincident wheel planes")
    return Fig11Data(configs=configs, panels=panels, robot=bot)


def _pair(cfg):
    """The coincident pair (i, j) and the third wheel k."""
    i, j = cfg.coincident[0]
    return i, j, ({1, 2, 3} - {i, j}).pop()


def draw(data, fig=None):
    """Draw Fig. 11 from its data.

    Parameters
    ----------
    data : Fig11Data
        The numbers (:func:`data`).
    fig : matplotlib.figure.Figure, optional
        Draw into this figure (cleared) instead of a new one.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from wmr.plot import annotate as an
    from wmr.plot.style import ROLE, common_view, new_figure, panel_title, style

    from .sketch import LINES_LEGEND, draw_singular

    with style():
        fig, axes = new_figure(1, 3, width=7.4, height=3.5, fig=fig)
        views = []
        for ax, (letter, cfg) in zip(axes, data.panels.items(), strict=True):
            i, j, k = _pair(cfg)
            lab = rf"$D_{{{min(i, k)}{max(i, k)}}} = D_{{{min(j, k)}{max(j, k)}}}$"
            g, ext = draw_singular(ax, data.robot, cfg, dp_label=lab, frame=False, dp_offset=(0, -9))
            views.append(ext)
            b = data.configs[letter]
            panel_title(ax, letter, rf"$\beta_{i} = \beta_{j} = {b[i - 1]:g}^\circ$, $\beta_{k} = {b[k - 1]:g}^\circ$")
        common_view(axes, views, pad=0.08)
        fig.legend(
            handles=an.legend_handles(LINES_LEGEND + [("planes meet", f"marker:D:{ROLE['dp']}")]),
            loc="outside lower center",
            ncols=4,
        )
    return fig


def caption(data):
    """Our caption of Fig. 11 (Markdown with ``$...$``).

    Parameters
    ----------
    data : Fig11Data
        The numbers (:func:`data`).

    Returns
    -------
    str
        Markdown with ``$...$`` math.
    """
    cfgs = data.panels.values()
    ranks = sorted(set(c.rank_F for c in cfgs))
    exact = sorted(set(c.det_J_exact for c in cfgs))
    return (
        "Singular configurations with two wheel planes coincident (items (ii)-(iv)): "
        + "; ".join(rf"({k}) {beta_text(c)}" for k, c in data.configs.items())
        + r". The planes of two wheels lie on one side $P_iP_j$ of the mount triangle and the third plane crosses "
        r"it at $D_{ik} = D_{jk}$. Computed for each: $\det\mathbf{J} = "
        + ", ".join(exact)
        + r"$ exactly ($"
        + residual_text(ABS_DET_J, max(abs(c.det_J) for c in cfgs))
        + r"$ in floating point), "
        r"rank $\mathbf{F} = "
        + ", ".join(map(str, ranks))
        + r"$ (mobility "
        + ", ".join(sorted(set(str(c.mobility) for c in cfgs)))
        + r"): the two coincident wheels have parallel "
        r"axles, which the third axle crosses at two different points (open circles), so there is no IC."
    )
