r"""Lines of a drawing: construction lines (axles, wheel planes) cut to the points they must reach, and paths.

Positions are in data coordinates of the axes; colours and dash patterns come from :mod:`wmr.plot.style`.
"""

from __future__ import annotations

import numpy as np

from .style import DASHES, ROLE

__all__ = ["draw_line", "draw_path"]


def segment_through(p, u, include=(), margin=0.3, min_half=0.5):
    r"""Ends ``(t0, t1)`` of the segment of the line :math:`p + t\,u/\|u\|` covering ``p`` and ``include``.

    Each point :math:`q` of ``include`` projects to :math:`t_q = (q - p)\cdot u/\|u\|`; the segment reaches at least
    ``min_half`` either side of ``p``, plus ``margin`` at both ends.
    """
    p, u = np.asarray(p, dtype=float), np.asarray(u, dtype=float)
    u = u / np.linalg.norm(u)
    ts = [0.0, -min_half, min_half] + [float(np.dot(np.asarray(q, dtype=float) - p, u)) for q in include]
    return min(ts) - margin, max(ts) + margin


def draw_line(
    ax, p, u, include=(), *, kind="axle", margin=0.3, min_half=0.5, zorder=3.0, color=None, lw=None, alpha=1.0
):
    r"""A construction line through ``p`` along ``u``, long enough to reach the points ``include``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    p, u : array_like (2,)
        A point of the line and its direction.
    include : sequence of array_like (2,), optional
        Points the drawn segment must reach.
    kind : str, optional
        A key of :data:`wmr.plot.style.DASHES`: ``"axle"`` (along :math:`\mathbf i_i`), ``"plane"`` (wheel-plane
        lines, along :math:`\mathbf j_i`), ``"thin"``.
    margin, min_half : float, optional
        Added at both ends; the least reach either side of ``p`` (data units).
    color, lw, zorder, alpha : optional
        ``color`` and ``lw`` override those of ``kind``.

    Returns
    -------
    numpy.ndarray (2, 2)
        The end points drawn.
    """
    p, u = np.asarray(p, dtype=float), np.asarray(u, dtype=float)
    u = u / np.linalg.norm(u)
    t0, t1 = segment_through(p, u, include, margin, min_half)
    seg = np.stack([p + t0 * u, p + t1 * u])
    col, ls, w = DASHES[kind]
    ax.plot(*seg.T, color=color or col, linestyle=ls, linewidth=lw or w, zorder=zorder, alpha=alpha)
    return seg


def draw_path(ax, xy, *, color=None, lw=1.3, ls="-", zorder=2.5, alpha=1.0):
    """A trajectory through the points ``xy`` (n, 2), in order.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    xy : array_like (n, 2)
    color : str, optional
        Default: the first path colour of :data:`wmr.plot.style.ROLE`.
    lw, ls, zorder, alpha : optional

    Returns
    -------
    matplotlib.lines.Line2D
    """
    xy = np.asarray(xy, dtype=float)
    return ax.plot(
        xy[:, 0], xy[:, 1], color=color or ROLE["path"][0], linewidth=lw, linestyle=ls, zorder=zorder, alpha=alpha
    )[0]
