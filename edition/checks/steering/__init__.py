r"""Chapter 5, equations (60)-(65): steering three centred wheels, and the instantaneous centre.

Everything rests on one scalar per wheel: the axle component of the mount point's velocity,
:math:`g_i = \mathbf i_i^{\mathrm T}[\mathbf E\mathbf d_i\ \ \mathbf 1]\,\mathbf t`, which a centred wheel
cannot produce (derived in the chapter, checked by :func:`no_slip`).  A twist is executable iff
every :math:`g_i = 0`.  The printed steering laws are substituted into :math:`g_i` exactly and tested
numerically with the package's inverse kinematics (:func:`feasibility`); the instantaneous centre is
derived (in the chapter) by differentiating the position of a platform point.

The checks, by equation group:

==================  =========================================================================
:mod:`.constraint`  the no-slip constraint of a centred wheel and the feasibility of a twist
:mod:`.laws`        the steering laws, (60) and (65): translation, and rotation about a point
:mod:`.centre`      the instantaneous centre, (61)-(64)
==================  =========================================================================
"""

from .centre import centre_to_wheel, instant_centre, instant_centre_velocity
from .constraint import KIND_NAMES, TWIST, evaluate, feasibility, no_slip, robot
from .laws import rotation_angles, translation

__all__ = [
    "robot",
    "TWIST",
    "no_slip",
    "feasibility",
    "evaluate",
    "translation",
    "instant_centre_velocity",
    "instant_centre",
    "centre_to_wheel",
    "rotation_angles",
    "KIND_NAMES",
]
