r"""What explains a drawing beside it: a scale bar, a box of text, the handles of a legend."""

from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D

from ..errors import InputValueError
from .marks import label
from .style import DASHES, FONT_SMALL, PALETTE

__all__ = ["scale_bar", "legend_handles"]


def scale_bar(ax, length, text, *, loc=(0.04, 0.05), color=None):
    """A scale bar of ``length`` data units at axes fraction ``loc`` (left end); call after the limits are set.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    length : float
    text : str
        Label above the bar.
    loc : tuple (2,), optional
    color : str, optional

    Returns
    -------
    None
    """
    col = color or PALETTE["dark"]
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    p = np.array([x0 + loc[0] * (x1 - x0), y0 + loc[1] * (y1 - y0)])
    ax.plot([p[0], p[0] + length], [p[1], p[1]], color=col, linewidth=1.6, solid_capstyle="butt", zorder=9)
    for x in (p[0], p[0] + length):
        ax.plot([x, x], [p[1] - 0.015 * (y1 - y0), p[1] + 0.015 * (y1 - y0)], color=col, linewidth=1.0, zorder=9)
    label(ax, (p[0] + length / 2, p[1]), text, offset=(0, 3), ha="center", va="bottom", fontsize=FONT_SMALL)


def legend_handles(items):
    """Line2D proxies for a legend.

    Parameters
    ----------
    items : list of (text, kind)
        ``kind``: ``"axle"``, ``"plane"``, ``"path:<colour>"``, ``"point:<colour>"``,
        ``"marker:<marker>:<colour>"`` (filled) or ``"open:<marker>:<colour>"`` (white face).

    Returns
    -------
    list of Line2D
    """
    hs = []
    for text, kind in items:
        if kind in DASHES:
            col, ls, w = DASHES[kind]
            hs.append(Line2D([], [], color=col, linestyle=ls, linewidth=w, label=text))
        elif kind.startswith("path:"):
            hs.append(Line2D([], [], color=kind[5:], linewidth=1.3, label=text))
        elif kind.startswith("point:"):
            hs.append(Line2D([], [], color=kind[6:], marker="o", markersize=4, linestyle="none", label=text))
        elif kind.startswith(("marker:", "open:")):
            how, m, c = kind.split(":")
            hs.append(
                Line2D(
                    [],
                    [],
                    color=c,
                    marker=m,
                    markersize=5,
                    linestyle="none",
                    label=text,
                    markerfacecolor="white" if how == "open" else c,
                )
            )
        else:
            raise InputValueError(
                f"legend item kind must be axle, plane, thin, path:, point:, marker: or open:, got {kind!r}"
            )
    return hs
