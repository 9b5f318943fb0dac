r"""Lines in the floor plane: the axle and wheel-plane lines of a robot, where lines meet, the circumcircle.

Two lines through each mount point :math:`P_i` organise the steering and singularity analyses:

* the **axle line** through the wheel centre along :math:`\mathbf i_i`: all axle lines meet at the
  instantaneous centre exactly when a rotation about it is admissible (mobility);
* the **wheel-plane line** :math:`\ell_i` through :math:`P_i` along :math:`\mathbf j_i` (the trace of
  the wheel plane on the floor): for three centred wheels :math:`\det\mathbf J = 0` exactly when
  the three are concurrent (:mod:`wmr.analysis.singularities`).

A line :math:`p + s\,u` has the Plücker coordinates :math:`[\,p\times u,\ u^T]^T`; a point
:math:`D` lies on it iff :math:`[-1,\ -D_y,\ D_x]\,[p\times u,\ u^T]^T = 0`, so the common point of
several lines is the left null vector of the matrix of their Plücker columns
(:func:`lines_concurrency`).  Where lines (or an instantaneous centre) are is one of the
:class:`Meet` values.
"""

from ...model.platform import line_angle
from .geometry import (
    AT_INFINITY,
    COINCIDENT,
    FINITE,
    NONE,
    PARALLEL,
    STILL,
    Concurrency,
    Meet,
    circumcircle,
    concurrencies,
    line_intersection,
    lines_concurrency,
    pair_intersections,
)
from .robot import (
    axle_lines,
    axles_concurrency,
    axles_through,
    concurrency_point,
    pair_line_angle,
    planes_through,
    wheel_plane_lines,
)

__all__ = [
    "Meet",
    "FINITE",
    "AT_INFINITY",
    "STILL",
    "NONE",
    "COINCIDENT",
    "PARALLEL",
    "Concurrency",
    "line_intersection",
    "pair_intersections",
    "lines_concurrency",
    "concurrencies",
    "circumcircle",
    "wheel_plane_lines",
    "axle_lines",
    "concurrency_point",
    "axles_concurrency",
    "planes_through",
    "axles_through",
    "pair_line_angle",
    "line_angle",
]
