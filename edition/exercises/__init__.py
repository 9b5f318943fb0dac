r"""The exercises of the chapters: one check function each, that says whether an answer is right and why not.

Each chapter ends with two or three exercises (cells tagged ``exercise``) and their worked
solutions (tagged ``solution``; ``make student`` drops them).  A student writes an answer and
calls the exercise's check, e.g.::

    answer = sp.Matrix([...])
    exercises.offset_other_side(answer)

The check returns a :class:`Feedback` (shown as a Markdown paragraph): right, or not yet with
the reason -- computed from the model, never compared with a typed-in answer.  ``None`` (the
template's placeholder) gives "no answer yet" without failing, so the student notebooks run.

Chapter by chapter:

=====  ==============================  =====================================================================
ch.    check                           the exercise
=====  ==============================  =====================================================================
1      :func:`offset_other_side`       the velocity of :math:`P_i` with the wheel centre on the other side
1      :func:`dual_counterexample`     a slip-free motion about a point other than C that refutes (15)
1      :func:`dual_spin_in_place`      wheel rates that turn a dual wheel on the spot
2      :func:`locked_steering`         steering angles at which the locked robot can still steer
2      :func:`drift_of_c_general`      (28) for four wheels with C anywhere
3      :func:`isotropic_placement`     move wheel 2 and find the L that makes :math:`\mathbf J_{L1}` isotropic
3      :func:`dual_upsilon`            :math:`\Upsilon_i` of a dual-wheel unit: is its J2 ever isotropic?
3      :func:`offset_for_kappa`        the offset that gives :math:`\kappa(\mathbf J_2) = 2`
4      :func:`unlisted_singularity`    a singular translation the paper's list does not state
4      :func:`mobile_and_singular`     angles where another robot turns although :math:`\mathbf J` is singular
5      :func:`translation_angles`      steering angles for a translation, and the slip of the printed (60)
5      :func:`rotation_angles`         steering angles for a rotation about a given point
5      :func:`printed_65_region`       where the centre must lie for the printed (65) to hold
6      :func:`curved_translation`      steering while translating, without stopping
6      :func:`reversal`                a discontinuous heading that needs no re-steering
=====  ==============================  =====================================================================

"Your own robot" cells use :func:`describe_robot`.

The checks live one module per chapter (:mod:`~edition.exercises.ch1_wheels` ...
:mod:`~edition.exercises.ch6_motion`), the verdict type in :mod:`~edition.exercises.feedback`
and the "your own robot" summary in :mod:`~edition.exercises.own_robot`.
"""

from .ch1_wheels import dual_counterexample, dual_spin_in_place, offset_other_side
from .ch2_mobility import BETA4, D4, PHI_DOT4, drift_of_c_general, locked_steering
from .ch3_isotropy import dual_upsilon, isotropic_placement, offset_for_kappa
from .ch4_singularities import mobile_and_singular, robot_4_2, unlisted_singularity
from .ch5_steering import printed_65_region, rotation_angles, translation_angles
from .ch6_motion import curved_translation, reversal
from .feedback import Feedback
from .own_robot import describe_robot

__all__ = [
    "Feedback",
    "offset_other_side",
    "dual_counterexample",
    "dual_spin_in_place",
    "locked_steering",
    "drift_of_c_general",
    "D4",
    "BETA4",
    "PHI_DOT4",
    "isotropic_placement",
    "dual_upsilon",
    "offset_for_kappa",
    "unlisted_singularity",
    "mobile_and_singular",
    "robot_4_2",
    "translation_angles",
    "rotation_angles",
    "printed_65_region",
    "curved_translation",
    "reversal",
    "describe_robot",
]
