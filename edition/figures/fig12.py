r"""Fig. 12: all three wheel planes through one point (item (v)): (a) the operation point C, (b) any point.

Angles from :func:`wmr.analysis.lines.planes_through`; :math:`D_P` is then recomputed as the
concurrency point of the three wheel-plane lines and compared with the point asked for.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr.analysis import lines as ln

from ..text import bound
from ..text import residual as residual_text
from .common import ABS_DET_J, centred_robot, drawing, residual
from .configs import beta_text, singular_config

__all__ = ["NUMBER", "TITLE", "PAPER_CAPTION", "Fig12Data", "data", "draw", "caption"]

NUMBER = "12"
TITLE = "Singular configurations: all wheel planes through one point"
PAPER_CAPTION = (
    "Singular configurations for the intersection of the planes of all the wheels: (a) at the operation "
    "point and (b) at an arbitrary point."
)


@dataclass(frozen=True)
class Fig12Data:
    r"""The numbers of Fig. 12.

    Attributes
    ----------
    D_arbitrary : tuple (2,)
        The point of panel (b), units of L.
    targets : dict
        Panel letter -> the point the planes are to pass through.
    panels : dict
        Panel letter -> :class:`~edition.figures.configs.SingularConfig` (exact :math:`\det\mathbf J` for (a),
        whose angles are whole degrees).
    D_P_error : dict
        Panel letter -> distance of the computed :math:`D_P` from the target.
    robot : wmr.Robot
        Drawing only: the robot drawn (:func:`~edition.figures.common.centred_robot`).
    """

    D_arbitrary: tuple
    targets: dict
    panels: dict
    D_P_error: dict = residual()
    robot: object = drawing(default=None)


def data(D_arbitrary=(-0.5, 1.8)):
    """Steer the wheel planes through C and through ``D_arbitrary`` (item (v) after (59)).

    Parameters
    ----------
    D_arbitrary : tuple (2,), optional
        The point of panel (b) (body frame, units of L).

    Returns
    -------
    Fig12Data
    """
    bot = centred_robot()
    targets = {"a": (0.0, 0.0), "b": tuple(map(float, D_arbitrary))}
    panels, err = {}, {}
    for letter, D in targets.items():
        b = ln.planes_through(bot, D)
        bdeg = np.degrees(b)
        whole = bool(np.all(np.abs(bdeg - np.round(bdeg)) < 1e-9))
        panels[letter] = cfg = singular_config(bot, b, exact_deg=[int(round(v)) for v in bdeg] if whole else None)
        err[letter] = float(np.linalg.norm(np.asarray(cfg.D_P) - D)) if cfg.D_P is not None else float("inf")
    return Fig12Data(D_arbitrary=targets["b"], targets=targets, panels=panels, D_P_error=err, robot=bot)


def draw(data, fig=None):
    """Draw Fig. 12 from its data.

    Parameters
    ----------
    data : Fig12Data
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
        fig, axes = new_figure(1, 2, width=7.2, height=4.1, fig=fig)
        views = []
        for ax, (letter, cfg) in zip(axes, data.panels.items(), strict=True):
            at_C = letter == "a"
            g, ext = draw_singular(
                ax,
                data.robot,
                cfg,
                dp_label="$D_P = C$" if at_C else "$D_P$",
                dp_offset=(8, 6) if at_C else (8, 2),
                frame=not at_C,
            )
            views.append(ext)
            panel_title(
                ax,
                letter,
                "planes meet at the operation point $C$" if at_C else "planes meet at an arbitrary point $D_P$",
            )
        common_view(axes, views, pad=0.1)
        fig.legend(
            handles=an.legend_handles(LINES_LEGEND + [("$D_P$", f"marker:D:{ROLE['dp']}")]),
            loc="outside lower center",
            ncols=4,
        )
    return fig


def caption(data):
    """Our caption of Fig. 12 (Markdown with ``$...$``).

    Parameters
    ----------
    data : Fig12Data
        The numbers (:func:`data`).

    Returns
    -------
    str
        Markdown with ``$...$`` math.
    """
    a, b = data.panels["a"], data.panels["b"]
    D = data.D_arbitrary
    ranks = " and ".join(sorted(set(str(c.rank_F) for c in (a, b))))
    mobs = " and ".join(sorted(set(str(c.mobility) for c in (a, b))))
    return (
        r"Singular configurations with the planes of all three wheels through one point $D_P$ (item (v)): (a) the "
        rf"operation point $C$ ({beta_text(a.beta_deg)}; $\det\mathbf{{J}} = {a.det_J_exact}$ exactly), "
        rf"(b) an arbitrary point $D_P = ({D[0]:g}, {D[1]:g})L$ (angles from `planes_through`: "
        rf"{beta_text(b.beta_deg, 4)}; computed ${residual_text(ABS_DET_J, abs(b.det_J))}$; distance of the "
        rf"computed concurrency point from $D_P$: ${bound(data.D_P_error['b'], latex=True)}$). The axles cross "
        rf"pairwise at three different points (open circles), so rank $\mathbf{{F}} = {ranks}$: mobility {mobs}, "
        r"the robot cannot move; (a) can serve as a brake."
    )
