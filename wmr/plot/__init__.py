"""Drawing robots with matplotlib (imported on demand: ``import wmr`` does not import matplotlib).

:mod:`~wmr.plot.style` (palette, sizes, figures and views), :mod:`~wmr.plot.annotate` (every annotation),
:mod:`~wmr.plot.robot` (the robot from above, part by part with :mod:`~wmr.plot.units`), :mod:`~wmr.plot.snapping`
(coordinates snapped so that a saved figure is the same file on every machine).
"""

__all__ = ["style", "annotate", "marks", "lines", "legend", "robot", "units", "snapping"]
