r"""Chapter 4, equations (51)-(59): centred wheels -- kinematics, mobility, isotropy and singular configurations.

Two lines through each mount point :math:`P_i` organise the chapter: the **axle line** (along
:math:`\mathbf i_i`) and the **wheel-plane line** (along :math:`\mathbf j_i`).  The robot can move
iff the axle lines are concurrent or all parallel (rank F = 5, :func:`mobility_centred`);
:math:`\mathbf J` is singular iff the wheel-plane lines are (:func:`singular_configurations`).
Matrices come from :class:`wmr.Robot` for general mount points :data:`edition.symbols.D` or the
paper's placement, and are compared with the printed forms (:mod:`edition.transcription`).

The checks, by equation group:

================  ==================================================================================================
:mod:`.mobility`  centred wheels, (51)-(57): kinematics, F, mobility and the isotropic kinematics
:mod:`.singular`  singular configurations, (58): det J from the wheel-plane lines, the printed determinant
:mod:`.zero_set`  the zero set of det J against the paper's list (59): line classes, items (i)-(v), item (v) on the circle
================  ==================================================================================================
"""

from .mobility import L_NUM, R_NUM, functional_matrix, isotropic_kinematics, kinematics, mobility_centred
from .singular import printed_determinant, singular_configurations
from .zero_set import LINE_CLASSES, classify_lines, planes_through, singular_list, singular_v

__all__ = [
    "L_NUM",
    "R_NUM",
    "kinematics",
    "functional_matrix",
    "mobility_centred",
    "isotropic_kinematics",
    "singular_configurations",
    "printed_determinant",
    "classify_lines",
    "singular_list",
    "singular_v",
    "planes_through",
    "LINE_CLASSES",
]
