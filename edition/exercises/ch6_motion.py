r"""Chapter 6 exercises (dual wheels and continuous motion): checks that say whether an answer is right and why not.

See :mod:`edition.exercises` for how the checks are used.
"""
from __future__ import annotations

import numpy as np

from wmr.analysis.kinematics import inverse
from wmr.model.robots import paper_robot

from ..text import bound
from .feedback import Feedback, missing

__all__ = ["curved_translation", "reversal"]


def curved_translation(beta_dot, v=0.2, omega=0.5, t_end=2.0):
    r"""Exercise 6.1: the steering rates that keep a centred-wheel robot translating while its velocity direction turns
    at ``omega``.

    Parameters
    ----------
    beta_dot : array (3,) or None
        Steering rates (rad/s), held constant.
    v, omega : float
        Speed and turning rate of the velocity direction.
    t_end : float
        Simulated time.

    Returns
    -------
    Feedback
    """
    from wmr.analysis.simulation import simulate
    from wmr.analysis.steering import steering_angles
    fb = missing(beta_dot, "three steering rates (rad/s)")
    if fb is not None:
        return fb
    bd = np.asarray(beta_dot, dtype=float) * np.ones(3)
    cen = paper_robot("centred", L=0.4, r=0.1)
    def twist(t):
        return np.array([0.0, v * np.cos(omega * t), v * np.sin(omega * t)])
    run = simulate(cen, lambda t, s: inverse(cen, s[1], twist(t)).value, steering_angles(cen, twist(0.0)),
                   t_end=t_end, dt=0.01, steer=bd)
    miss = float(np.max(np.abs(run.twist - np.array([twist(t) for t in run.t]))))
    slip = float(run.slip.max())
    if miss < 1e-6 and slip < 1e-6:
        return Feedback(True, rf"The robot follows the turning velocity (largest error ${bound(miss, latex=True)}$ "
                              r"m/s) without slip: the wheels turn together at $\omega$, stay parallel, and the robot "
                              r"changes direction without stopping. Mobility 1 is not the same as having to stop.")
    return Feedback(False, rf"The robot misses the commanded velocity by up to ${miss:.3g}$ m/s after {t_end:g} s: the "
                           r"axles must stay perpendicular to the velocity, whose direction turns at $\omega$.")


def reversal(twist_plus, twist_minus=(0.0, 0.2, 0.1)):
    r"""Exercise 6.2: a jump of the twist that a centred-wheel robot executes without re-steering, and that changes the
    heading.

    Parameters
    ----------
    twist_plus : array (3,) or None
        The new twist.
    twist_minus : array (3,)
        The current twist; the wheels are steered for it.

    Returns
    -------
    Feedback
    """
    from wmr.analysis.steering import steering_angles
    fb = missing(twist_plus, "a twist")
    if fb is not None:
        return fb
    cen = paper_robot("centred", L=0.4, r=0.1)
    tm, tp = np.asarray(twist_minus, dtype=float), np.asarray(twist_plus, dtype=float)
    sol = inverse(cen, steering_angles(cen, tm), tp)
    if not bool(sol.admissible):
        return Feedback(False, "At the current steering angles this twist needs slip "
                               f"(${np.abs(sol.residual).max():.3g}$): only multiples of the current twist share its "
                               "instantaneous centre.")
    lam = float(tp @ tm / (tm @ tm))
    if lam > 0:
        return Feedback(False, "Executable, but it is the same heading at another speed: make the heading jump.")
    return Feedback(True, rf"$\mathbf t^+ = {lam:.3g}\,\mathbf t^-$: a reversal, the heading jumps by $180^\circ$ and "
                          r"the wheels simply roll the other way. Every other jump needs re-steering.")
