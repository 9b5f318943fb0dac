"""Drawing robots with matplotlib (imported on demand: ``import wmr`` does not import matplotlib).

- :mod:`wmr.plot.style`: palette, line and font sizes, matplotlib settings, figures and views;
- :mod:`wmr.plot.annotate`: every annotation in one place, defined in
  :mod:`wmr.plot.marks` (labels, points, arrows, frames, angles), :mod:`wmr.plot.lines` (construction lines,
  paths) and :mod:`wmr.plot.legend` (scale bars, boxes, legends);
- :mod:`wmr.plot.robot`: the robot seen from above (platform, wheel units, axle and wheel-plane lines), whose
  parts (the platform, a wheel unit) :mod:`wmr.plot.units` draws;
- :mod:`wmr.plot.snapping`: coordinates snapped so that a saved figure is the same file on every machine.
"""

__all__ = ["style", "annotate", "marks", "lines", "legend", "robot", "units", "snapping"]
