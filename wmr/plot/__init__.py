"""Drawing robots with matplotlib (imported on demand: ``import wmr`` does not import matplotlib).

:mod:`wmr.plot.style` holds the palette and the figure style; :mod:`wmr.plot.robot` the drawing
primitives (platform, wheel units, axle and wheel-plane lines, frames, arrows, labels).
"""
