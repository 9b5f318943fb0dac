"""Drawing robots with matplotlib (imported on demand: ``import wmr`` does not import matplotlib).

- :mod:`wmr.plot.style`: palette, line and font sizes, matplotlib settings, figures and views;
- :mod:`wmr.plot.annotate`: labels, points, arrows, frames, angles, construction lines, boxes, legends;
- :mod:`wmr.plot.robot`: the robot seen from above (platform, wheel units, axle and wheel-plane lines);
- :mod:`wmr.plot.snapping`: coordinates snapped so that a saved figure is the same file on every machine.
"""

__all__ = ["style", "annotate", "robot", "snapping"]
