r"""Drawing re-steering studies (matplotlib, imported here only: ``import wmr`` and ``import wmr.swerve`` do not).

The data come from :func:`wmr.swerve.transient.resteer_study`; this module only draws them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..errors import InputTypeError
from .transient import TransientStudy

if TYPE_CHECKING:  # matplotlib is imported when a figure is drawn
    from matplotlib.figure import Figure

__all__ = ["transient_figure"]


def transient_figure(study: TransientStudy, fig: Figure | None = None) -> Figure:
    r"""Three panels for a :class:`~wmr.swerve.transient.TransientStudy`: paths, slip, path error.

    (a) the path of C for each strategy and the reference (dashed); (b) the slip
    :math:`\sigma = \|\mathbf J_1\mathbf t - \mathbf J_2\dot{\boldsymbol\theta}\|` (m/s) over time;
    (c) the path error (m) over time.

    Parameters
    ----------
    study : TransientStudy
    fig : matplotlib.figure.Figure, optional
        Draw into this (cleared) figure instead of a new one.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from ..plot.style import PALETTE, ROLE, new_figure, panel_title, style
    from .transient import TransientStudy

    if not isinstance(study, TransientStudy):
        raise InputTypeError(f"study must be a TransientStudy (wmr.swerve.resteer_study), got {type(study).__name__}")
    colours = list(ROLE["path"]) + [PALETTE["blue"], PALETTE["grey"]]
    with style():
        fig, (ax_p, ax_s, ax_e) = new_figure(1, 3, width=10.0, height=3.3, fig=fig, drawing=False)
        ref = study.runs[0].reference
        ax_p.plot(ref[:, 1], ref[:, 2], color=PALETTE["black"], ls="--", lw=1.0, label="commanded")
        for i, run in enumerate(study.runs):
            c = colours[i % len(colours)]
            ls = ":" if run.label.endswith("cos") else "-"
            lw = 2.8 if i == 0 else 1.2  # the first run wide: others may run on it
            ax_p.plot(run.pose[:, 1], run.pose[:, 2], color=c, ls=ls, lw=lw, label=run.label)
            ax_s.plot(run.t[1:], run.slip, color=c, ls=ls, lw=lw, label=run.label)
            ax_e.plot(run.t, run.path_error, color=c, ls=ls, lw=lw, label=run.label)
        ax_p.set_aspect("equal", adjustable="datalim")
        ax_p.set_xlabel("X (m)")
        ax_p.set_ylabel("Y (m)")
        panel_title(ax_p, "a", "path of C")
        ax_s.set_xlabel("t (s)")
        ax_s.set_ylabel("slip (m/s)")
        panel_title(ax_s, "b", "slip of the wheels")
        ax_e.set_xlabel("t (s)")
        ax_e.set_ylabel("path error (m)")
        panel_title(ax_e, "c", "path error")
        for ax in (ax_s, ax_e):
            ax.set_ylim(bottom=0.0)
            ax.grid(True, lw=0.3, color=PALETTE["light"])
        ax_p.legend(loc="best")
        fig.suptitle(f"{study.profile.name}: steering rate {np.degrees(study.steer_rate):.0f} deg/s", fontsize=10.0)
    return fig
