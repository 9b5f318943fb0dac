r"""Annotations of a drawing in one place: :mod:`wmr.plot.marks` (labels, points, arrows, frames, angles),
:mod:`wmr.plot.lines` (construction lines, paths) and :mod:`wmr.plot.legend` (scale bars, boxes, legends).

Positions are in data coordinates (the robot's unit), label offsets in points, colours from :mod:`wmr.plot.style`.
"""

from __future__ import annotations

from .legend import legend_handles, scale_bar
from .lines import draw_line, draw_path
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
