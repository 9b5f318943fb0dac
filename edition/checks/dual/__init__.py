r"""Chapter 6: dual wheels, omnidirectionality and discontinuous heading (claims of Sections 3.2, 5, 6, 7).

"Kinematically equivalent" is tested as: the same admissible platform twists at every steering
angle (:math:`\mathbf F^{\text{dual}} = \mathbf F^{\text{centred}}\mathbf T`); "mobility" as the
dimension of the admissible twists; "omnidirectional" in the paper's own sense of Section 4.2
(every twist executable at once).  Motions are integrated with :func:`wmr.integrate`, which moves
dual units by the corrected (15) and reports the slip (the residual of (21)).

The checks, by job:

=====================  ==========================================================================================
:mod:`.robots`         the chapter's robots: centred, dual and offset wheels on the same mount points
:mod:`.equivalence`    dual against centred wheels: the same admissible twists; the mobility as the paper counts it
:mod:`.motions`        a 90-degree corner and a curvilinear translation, integrated
:mod:`.heading`        not omnidirectional; a jump in the direction of travel needs re-steering
=====================  ==========================================================================================
"""

from .equivalence import equivalence, mobility_dual
from .heading import discontinuous_heading, omnidirectional
from .motions import corner, curved_translation
from .robots import ROBOT, robots

__all__ = [
    "ROBOT",
    "robots",
    "equivalence",
    "mobility_dual",
    "corner",
    "curved_translation",
    "omnidirectional",
    "discontinuous_heading",
]
