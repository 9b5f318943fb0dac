r"""Annotations of a drawing, in one place: labels, points, arrows, frames, angles, construction lines, paths, boxes,
legends.

The functions are defined by what they draw, and offered here together:

======================  ==========================================================================
:mod:`wmr.plot.marks`   labels, points, arrows, frames, angles (:func:`~wmr.plot.marks.label`, ...)
:mod:`wmr.plot.lines`   construction lines and paths (:func:`~wmr.plot.lines.draw_line`, ...)
:mod:`wmr.plot.legend`  a scale bar, a box of text, legend handles (:func:`~wmr.plot.legend.scale_bar`, ...)
======================  ==========================================================================

All positions are in data coordinates of the axes (lengths in the robot's unit); offsets of
labels are in points.  Colours and dash patterns come from :mod:`wmr.plot.style`.
"""

from __future__ import annotations

from .legend import info_box as info_box  # implementation, importable here as before
from .legend import legend_handles, scale_bar
from .lines import draw_line, draw_path
from .lines import segment_through as segment_through
from .marks import draw_angle, draw_arrow, draw_frame, draw_point, label

__all__ = [
    "label",
    "draw_point",
    "draw_arrow",
    "draw_frame",
    "draw_angle",
    "draw_line",
    "draw_path",
    "scale_bar",
    "legend_handles",
]
