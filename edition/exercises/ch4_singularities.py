r"""Chapter 4 exercises (centred wheels and singularities): checks that say whether an answer is right and why not.

See :mod:`edition.exercises` for how the checks are used.
"""
from __future__ import annotations

from wmr.model.robots import paper_robot

from .feedback import Feedback, as_angles

__all__ = ["unlisted_singularity", "mobile_and_singular"]


def _classified(beta_deg):
    """The answer's configuration of the paper's centred-wheel robot, classified
    (:func:`wmr.analysis.singularities.classify`), or the feedback on an answer that is not three angles."""
    from wmr.analysis.singularities import classify
    beta, fb = as_angles(beta_deg, degrees=True)
    if fb is not None:
        return fb
    if beta.shape != (3,):
        return Feedback(False, "Give three angles.")
    return classify(paper_robot("centred", L=1.0, r=1.0), beta)


def unlisted_singularity(beta_deg):
    r"""Exercise 4.1: a singular configuration of the paper's centred-wheel robot that its list (i)-(v) does not state.

    Parameters
    ----------
    beta_deg : array (3,) or None
        Steering angles in degrees.

    Returns
    -------
    Feedback
    """
    from ..families import paper_item
    c = _classified(beta_deg)
    if isinstance(c, Feedback):
        return c
    if not c.singular:
        return Feedback(False, rf"$\det\mathbf J = {c.det_J:.3g} \neq 0$: not singular. The wheel-plane lines must be "
                               "concurrent or all parallel.")
    item = paper_item(c.family)
    if item:
        return Feedback(False, f"Singular, but the paper lists it: item {item} (family `{c.family}`). Look for one the "
                               "literal list misses.")
    return Feedback(True, rf"$\det\mathbf J = 0$ (family `{c.family}`, rank $\mathbf F = {c.rank_F}$), and no item of "
                          r"the printed list states it: a wheel turned by $180^\circ$ keeps its wheel-plane line.")


def mobile_and_singular(beta_deg):
    r"""Exercise 4.2: steering angles at which :math:`\mathbf J` is singular although the robot can move.

    Parameters
    ----------
    beta_deg : array (3,) or None
        Steering angles in degrees.

    Returns
    -------
    Feedback
    """
    c = _classified(beta_deg)                # the same decision as in exercise 4.1
    if isinstance(c, Feedback):
        return c
    if not c.singular:
        return Feedback(False, rf"$\det\mathbf J = {c.det_J:.3g}$: $\mathbf J$ is not singular here.")
    if c.rank_F != 5:
        return Feedback(False, rf"$\mathbf J$ is singular, but rank $\mathbf F = {c.rank_F}$: the robot cannot move. "
                               r"The axle lines must be concurrent too.")
    return Feedback(True, r"$\det\mathbf J = 0$ and rank $\mathbf F = 5$: the robot can move although $\mathbf J$ is "
                          r"singular (all planes parallel, or the planes meet on the circle through the $P_i$).")
