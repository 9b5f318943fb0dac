r"""Chapter 3, equations (30)-(50): the condition number, isotropy of :math:`\mathbf J_{L1}` and :math:`\mathbf J_2`,
robustness.

The Jacobians come from :class:`wmr.Robot` (``J1(L)`` is :math:`\mathbf J_{L1}`, ``J2``, ``J``) for
general (symbolic) mount points or the paper's placement, and are compared with the printed forms
of the transcription (:mod:`edition.transcription`).  The last check, :func:`robust_control`, asks whether isotropic
factors make the composite map :math:`\mathbf J = \mathbf J_{L1}^{\mathrm T}\mathbf J_2` (56) well
conditioned, and proves a bound: for three centred wheels, wherever the robot can move,
:math:`\kappa(\mathbf J) \ge \sqrt 2`.

The checks, by equation group:

=================  ==================================================================================================
:mod:`.condition`  the condition number, (30)-(31): the definition applied to J_L1, against wmr.condition_number
:mod:`.jl1`        isotropy of J_L1, (32)-(39): homogeneous Jacobian, Gram matrix, isotropy conditions, placement, L
:mod:`.j2`         isotropy of J2, (40)-(50): its product, d = r, the dead zone of isotropy, the isotropic kinematics
:mod:`.robust`     robust control: J = J_L1^T J2 isotropic for offset wheels (d = r), kappa >= sqrt 2 for centred
=================  ==================================================================================================
"""

from .condition import RHO, condition_number_def
from .j2 import J2_isotropy, J2_product, dead_zone_of_isotropy, isotropic_kinematics
from .jl1 import (
    general_robot,
    gram,
    homogeneous_jacobian,
    isotropic_gram,
    isotropy_conditions,
    placement,
)
from .robust import robust_control

__all__ = [
    "general_robot",
    "condition_number_def",
    "homogeneous_jacobian",
    "gram",
    "isotropy_conditions",
    "placement",
    "isotropic_gram",
    "J2_product",
    "J2_isotropy",
    "dead_zone_of_isotropy",
    "isotropic_kinematics",
    "robust_control",
    "RHO",
]
