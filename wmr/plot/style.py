r"""The look of every drawing: palette, line and font sizes, matplotlib settings, figures and views.

The Okabe-Ito colour-blind-safe palette (:data:`PALETTE`, by role in :data:`ROLE`), one set of line widths and font
sizes (:data:`RC`, which also makes saved files deterministic: a fixed SVG hash salt, text as paths).  Figures are
plain :class:`matplotlib.figure.Figure` objects, not registered with pyplot.
"""

from __future__ import annotations

from contextlib import contextmanager
from typing import Any

import matplotlib
import matplotlib.patheffects as pe
import numpy as np
from matplotlib.figure import Figure

__all__ = [
    "PALETTE",
    "ROLE",
    "DASHES",
    "RC",
    "FONT_SMALL",
    "style",
    "new_figure",
    "plain_axes",
    "panel_title",
    "fit_view",
    "common_view",
]

#: Okabe & Ito (2008) colour-blind-safe palette, by name.
PALETTE = {
    "black": "#000000",
    "orange": "#E69F00",
    "sky": "#56B4E9",
    "green": "#009E73",
    "yellow": "#F0E442",
    "blue": "#0072B2",
    "vermillion": "#D55E00",
    "purple": "#CC79A7",
    "grey": "#7F7F7F",
    "light": "#EDEDED",
    "dark": "#2B2B2B",
}
#: Colours by what they show.
ROLE: dict[str, Any] = {
    "platform_face": "#EEEEEE",
    "platform_edge": "#8C8C8C",
    "wheel": PALETTE["dark"],
    "body": "#6E6E6E",
    "axle": PALETTE["blue"],
    "plane": PALETTE["vermillion"],
    "frame": PALETTE["black"],
    "fixed_frame": PALETTE["grey"],
    "point": PALETTE["black"],
    "path": (PALETTE["orange"], PALETTE["sky"], PALETTE["green"], PALETTE["purple"], PALETTE["vermillion"]),
    "ic": PALETTE["blue"],
    "dp": PALETTE["vermillion"],
    "annotation": PALETTE["dark"],
}
#: Construction lines: kind -> (colour, dash pattern, line width).
DASHES: dict[str, tuple[str, Any, float]] = {
    "axle": (ROLE["axle"], (0, (5, 3)), 0.9),  # along i_i
    "plane": (ROLE["plane"], (0, (8, 2, 1.5, 2)), 0.9),  # along j_i
    "thin": (PALETTE["grey"], (0, (2, 2)), 0.6),
}

#: Matplotlib settings of every figure (also what makes the output files deterministic).
RC: dict[Any, Any] = {
    "font.family": "DejaVu Sans",
    "font.size": 9.0,
    "mathtext.fontset": "dejavusans",
    "axes.titlesize": 10.0,
    "axes.titleweight": "normal",
    "axes.linewidth": 0.6,
    "lines.linewidth": 1.2,
    "lines.solid_capstyle": "round",
    "legend.fontsize": 8.0,
    "legend.frameon": False,
    "savefig.dpi": 200,
    "savefig.bbox": "standard",
    "figure.dpi": 100,
    "svg.hashsalt": "wmr-leow-low-loh-2002",
    "svg.fonttype": "path",
    "pdf.fonttype": 3,
    "image.cmap": "cividis",
    "path.simplify": False,
}

FONT_LABEL = 9.0
FONT_SMALL = 7.5
#: White outline behind labels, so that they stay legible over lines.
HALO: list[pe.AbstractPathEffect] = [pe.withStroke(linewidth=2.6, foreground="white")]


@contextmanager
def style():
    """Context in which figures are made and saved: matplotlib with the settings :data:`RC`.

    Returns
    -------
    contextlib.AbstractContextManager
    """
    with matplotlib.rc_context(RC):
        yield


def new_figure(nrows=1, ncols=1, width=7.0, height=3.2, *, fig=None, drawing=True, **subplot_kw):
    """A :class:`matplotlib.figure.Figure` (not registered with pyplot) and its axes, flattened.

    Parameters
    ----------
    nrows, ncols : int
    width, height : float
        Inches.
    fig : Figure, optional
        Draw into this (cleared) figure instead of a new one.
    drawing : bool
        Make every axes a drawing (:func:`plain_axes`); False for charts.
    **subplot_kw
        Passed to :meth:`matplotlib.figure.Figure.subplots`.

    Returns
    -------
    fig : Figure
    axes : list of Axes (length nrows * ncols)
    """
    if fig is None:
        fig = Figure(figsize=(width, height), layout="constrained")
    else:
        fig.clear()
        fig.set_size_inches(width, height)
        fig.set_layout_engine("constrained")
    axs = fig.subplots(nrows, ncols, squeeze=False, **subplot_kw)
    axes = list(axs.ravel())
    if drawing:
        for ax in axes:
            plain_axes(ax)
    return fig, axes


def plain_axes(ax):
    """Equal aspect, no ticks or spines: a drawing, not a chart.

    Parameters
    ----------
    ax : matplotlib.axes.Axes

    Returns
    -------
    None
    """
    ax.set_aspect("equal", adjustable="box")
    ax.set_xticks([])
    ax.set_yticks([])
    for s in ax.spines.values():
        s.set_visible(False)


def panel_title(ax, letter, text):
    """Panel title '(a) text', left-aligned (``letter=""``: the text alone).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    letter, text : str

    Returns
    -------
    None
    """
    ax.set_title(f"({letter}) {text}" if letter else text, loc="left", fontsize=RC["axes.titlesize"])


def fit_view(ax, points, pad=0.15):
    """Set limits that contain ``points`` (anything that reshapes to (n, 2)) with a margin of ``pad`` times the larger span.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    points : array_like (n, 2)
    pad : float, optional

    Returns
    -------
    None
    """
    p = np.asarray(points, dtype=float).reshape(-1, 2)
    lo, hi = p.min(axis=0), p.max(axis=0)
    m = pad * max(float((hi - lo).max()), 1e-9)
    ax.set_xlim(lo[0] - m, hi[0] + m)
    ax.set_ylim(lo[1] - m, hi[1] + m)


def common_view(axes, point_sets, pad=0.05):
    """Give every axes the same data span (same scale), each centred on its own points.

    Parameters
    ----------
    axes : sequence of matplotlib.axes.Axes
    point_sets : sequence of array_like (n_k, 2)
        The points each axes must show, one set per axes.
    pad : float, optional
        Margin, as a fraction of the largest half-span.

    Returns
    -------
    None
    """
    boxes = []
    for pts in point_sets:
        p = np.asarray(pts, dtype=float).reshape(-1, 2)
        boxes.append((p.min(axis=0), p.max(axis=0)))
    hw = max(float(hi[0] - lo[0]) / 2 for lo, hi in boxes) * (1 + pad)
    hh = max(float(hi[1] - lo[1]) / 2 for lo, hi in boxes) * (1 + pad)
    for ax, (lo, hi) in zip(axes, boxes):
        c = (lo + hi) / 2
        ax.set_xlim(c[0] - hw, c[0] + hw)
        ax.set_ylim(c[1] - hh, c[1] + hh)
