r"""Chapter 2, equations (20)-(29): assembling offset-wheel units, the functional matrix, mobility, drift, dead zone.

The robot's matrices come from :class:`wmr.Robot` (``J1``, ``J2``, ``F``), built for three units
at *general* mount points :math:`\mathbf d_k = (d_{kx}, d_{ky})` with symbolic steering angles,
and are compared with the printed forms (:mod:`edition.transcription`).  With the drives locked
(:math:`\dot\theta_i = 0`) the unknowns are the twist and the steering rates: the square system
:math:`\mathbf M(\boldsymbol\beta)[\mathbf t;\dot{\boldsymbol\phi}] = \mathbf 0` of
:func:`locked_system` decides whether the robot can steer at all, and :func:`locked_motion` gives
the motion when it can.

The checks, by equation group:

=================  =======================================================================================
:mod:`.matrices`   stacking the units, (20)-(27): J1, J2, F, its null space, the mobility of offset wheels
:mod:`.locked`     the drives locked: the system M(beta), its motion, and when the robot can steer
:mod:`.drift`      drift, (28)-(29): how C and psi move when the drives are locked
:mod:`.dead_zone`  the dead zone: the circle C traces when every unit turns with the drives locked
=================  =======================================================================================
"""

from .dead_zone import dead_zone, dead_zone_claim
from .drift import drift, drift_of_c, drift_of_psi
from .locked import concurrent_angles, drift_motions, locked_motion, locked_steering, locked_system
from .matrices import PAPER, functional_matrix, general_robot, mobility_offset, null_space_of_F, one_unit, stacking

__all__ = [
    "PAPER",
    "general_robot",
    "one_unit",
    "stacking",
    "functional_matrix",
    "null_space_of_F",
    "mobility_offset",
    "locked_system",
    "locked_motion",
    "concurrent_angles",
    "locked_steering",
    "drift_motions",
    "drift_of_c",
    "drift_of_psi",
    "drift",
    "dead_zone",
    "dead_zone_claim",
]
