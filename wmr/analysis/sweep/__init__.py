r"""Sweeps: one analysis evaluated over millions of configurations, in chunks, with bounded memory.

A design study asks questions such as "what is the largest :math:`\kappa(\mathbf J)` over all
steering angles?" or "where does :math:`\operatorname{rank}\mathbf F` drop?".  :func:`sweep` answers
them for a grid (:class:`Grid`) or a random sample (:class:`Sample`) of configurations
:math:`\boldsymbol\beta\in\mathbb R^w` without ever holding all of them: the configurations of one
chunk are generated, the analysis is evaluated on them with the batched kernels, and the chunk
is folded into a running reduction (count, minimum, maximum, the extreme configurations, the
distribution of values).  Peak memory is that of one chunk plus the reduction, whatever the
number of configurations.

The chunks are independent, so the same code runs on a Dask cluster when ``client`` is given
(``pip install wmr-kinematics[dask]``); the reduction is associative and ties go to the lower
configuration index, so the result does not depend on the chunk size, on the order in which
chunks finish, or on where they ran.

Analyses (:data:`ANALYSES`):

=====================  =================================================================================  ==================
name                   value at a configuration                                                           "worst" end
=====================  =================================================================================  ==================
``rank_F``             :math:`\operatorname{rank}\mathbf F` (24)                                          smallest
``mobility``           :math:`\nu = (3+n) - \operatorname{rank}\mathbf F` (27)                            smallest
``actuated_mobility``  the dimension of the twists the motors can command (driven joints only)            smallest
``det_J``              :math:`\det\mathbf J`, :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` (56), (58)  smallest magnitude
``kappa_J``            :math:`\kappa(\mathbf J)` (30), ``inf`` where singular                             largest
``kappa_JL1``          :math:`\kappa(\mathbf J_{L1})` (32): independent of :math:`\boldsymbol\beta`       largest
=====================  =================================================================================  ==================

The "worst" end is the one a designer worries about: for rank F, a rank drop (a singular
:math:`\mathbf F`); for the mobilities, the fewest directions the robot can drive in; for
:math:`\mathbf J`, the closest approach to a singular matrix.
"""

from .analyses import ANALYSES
from .configurations import Grid, Sample
from .execute import CHUNK, QUANTILES, sweep
from .motions import Drivable
from .reduction import SKETCH_ACCURACY
from .result import Sweep

__all__ = ["ANALYSES", "Drivable", "Grid", "Sample", "Sweep", "sweep", "QUANTILES", "SKETCH_ACCURACY", "CHUNK"]
