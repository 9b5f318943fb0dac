r"""Drawings that come out the same on every machine: coordinates snapped before matplotlib renders them.

Two machines compute the same figure with arithmetic that differs in the last bits (another CPU's
``sin``, another BLAS kernel), and a renderer turns such bits into different files when a coordinate
sits near a rounding boundary of the output format or when lines drawn on top of each other are
anti-aliased.  :func:`snap` removes the round-off from values a drawing receives and
:func:`snap_figure` from every coordinate a finished figure hands to the renderer.  NumPy only:
matplotlib is imported by :func:`snap_figure` alone.
"""

from __future__ import annotations

import numpy as np

__all__ = ["snap", "snap_figure"]

#: Decimal places kept of a coordinate (data units: a length :math:`L`, or degrees): far below a pixel, far
#: above round-off.
SNAP_DECIMALS = 7
#: Above this magnitude a value is rounded to :data:`SNAP_DIGITS` significant digits instead.
_SNAP_LARGE = 1e6
SNAP_DIGITS = 12


def snap(a):
    """Values for drawing, with round-off removed: ``SNAP_DECIMALS`` places, or ``SNAP_DIGITS`` digits if large.

    Infinities and NaN pass unchanged; ``-0.0`` becomes ``0.0``.

    Parameters
    ----------
    a : array_like (...)

    Returns
    -------
    numpy.ndarray (...)

    Examples
    --------
    >>> snap([1e-12, -1e-12, 0.123456789, 0.1 + 0.2]).tolist()
    [0.0, 0.0, 0.1234568, 0.3]
    >>> bool(snap(1e16) == snap(np.nextafter(1e16, 0)))
    True
    """
    a = np.asarray(a, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        small = np.round(a, SNAP_DECIMALS)
        mag = np.abs(a)
        big = np.isfinite(a) & (mag > _SNAP_LARGE)
        if np.any(big):
            q = 10.0 ** (np.floor(np.log10(np.where(big, mag, 1.0))) - (SNAP_DIGITS - 1))
            small = np.where(big, np.round(a / q) * q, small)
    return small + 0.0


def _snap_xy(xy):
    """A point snapped, as a tuple of floats."""
    return tuple(snap(xy).tolist())


def snap_figure(fig):
    """Snap (:func:`snap`) every data coordinate of a figure's artists in place, before it is saved.

    Lines, texts and annotations, circles, arcs, polygons, arrows, boxes and the axes limits; contours and images
    are drawn from arrays the caller snaps.

    Parameters
    ----------
    fig : matplotlib.figure.Figure

    Returns
    -------
    matplotlib.figure.Figure
        ``fig``.
    """
    from matplotlib.lines import Line2D
    from matplotlib.patches import Arc, Circle, FancyArrowPatch, FancyBboxPatch, Polygon
    from matplotlib.text import Annotation, Text

    for ax in fig.axes:
        ax.set_xlim(*snap(ax.get_xlim()).tolist())
        ax.set_ylim(*snap(ax.get_ylim()).tolist())
    for art in fig.findobj():
        if isinstance(art, Line2D):
            x, y = art.get_data(orig=True)
            if np.asarray(x).dtype.kind in "fiu" and np.asarray(y).dtype.kind in "fiu":
                art.set_data(snap(x), snap(y))
        elif isinstance(art, Annotation):
            art.xy = _snap_xy(art.xy)
            art.set_position(_snap_xy(art.get_position()))
        elif isinstance(art, Text):
            art.set_position(_snap_xy(art.get_position()))
        elif isinstance(art, Arc):  # before Circle's base Ellipse: an Arc is an Ellipse
            art.set_center(_snap_xy(art.get_center()))
            art.set_width(float(snap(art.get_width())))
            art.set_height(float(snap(art.get_height())))
            art.theta1, art.theta2 = (float(v) for v in snap([art.theta1, art.theta2]))
        elif isinstance(art, Circle):
            art.set_center(_snap_xy(art.get_center()))
            art.set_radius(float(snap(art.get_radius())))
        elif isinstance(art, Polygon):
            art.set_xy(snap(art.get_xy()))
        elif isinstance(art, FancyBboxPatch):
            art.set_bounds(*snap(art.get_bbox().bounds).tolist())
        elif isinstance(art, FancyArrowPatch):
            ends = art._posA_posB  # type: ignore[attr-defined]  # matplotlib has no public getter
            if ends is not None:
                art.set_positions(*(_snap_xy(p) for p in ends))
    return fig
