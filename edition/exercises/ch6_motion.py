r"""Chapter 6 exercises (dual wheels and continuous motion): fair checks (:func:`~.framework.exercise`).

The steering rates of 6.1 are computed from the model (``wmr.steering_angles`` along the commanded
motion, differentiated); the jump of 6.2 is judged by whether the new twist keeps the instantaneous centre.
"""

from __future__ import annotations

import numpy as np

from wmr.analysis.kinematics import inverse
from wmr.model.robots import paper_robot

from ..text import number
from . import answers
from .feedback import right, wrong
from .framework import exercise
from .tolerance import angle_gap, sig_figs, within

__all__ = ["TOL_6_1", "TOL_6_2", "V_6_1", "OMEGA_6_1", "TWIST_6_2", "curved_translation", "reversal"]

TOL_6_1 = sig_figs(3)
TOL_6_2 = within("within 0.1% in direction", rel=1e-3)
#: exercise 6.1: speed (m/s) and turning rate of the velocity direction (rad/s)
V_6_1, OMEGA_6_1 = 0.2, 0.5
#: exercise 6.2: the twist the wheels are steered for
TWIST_6_2 = (0.0, 0.2, 0.1)


def _robot():
    return paper_robot("centred", L=0.4, r=0.1)


def _twist(t):
    return np.array([0.0, V_6_1 * np.cos(OMEGA_6_1 * t), V_6_1 * np.sin(OMEGA_6_1 * t)])


def needed_rates(t=0.0, h=1e-3):
    """The steering rates that keep the robot of 6.1 slip-free at time ``t``: steering angles differentiated.

    Parameters
    ----------
    t : float
    h : float
        Step of the central difference (s).

    Returns
    -------
    numpy.ndarray (3,)
        rad/s.
    """
    from wmr.analysis.steering import steering_angles

    bot = _robot()
    a, b = steering_angles(bot, _twist(t - h)), steering_angles(bot, _twist(t + h))
    d = np.mod(b - a + np.pi / 2, np.pi) - np.pi / 2  # a wheel turned round is the same line
    return d / (2 * h)


@exercise("6.1", answer="three steering rates in rad/s", tolerance=TOL_6_1, units={"beta_dot": "rad"})
def curved_translation(beta_dot):
    r"""Exercise 6.1: the constant steering rates that keep the centred-wheel robot translating while its velocity
    direction turns at :data:`OMEGA_6_1`.

    Parameters
    ----------
    beta_dot : array_like (3,)
        rad/s.

    Returns
    -------
    Result
    """
    rates = answers.vector(beta_dot, 3, "three steering rates in rad/s")
    need = needed_rates()
    if TOL_6_1.accepts(rates, need):
        return right(
            r"The wheels turn together at the rate of the velocity direction, stay parallel, and the robot "
            "changes direction without stopping and without slip. Mobility 1 is not the same as having to "
            "stop."
        )
    from wmr.analysis.integration import integrate
    from wmr.analysis.steering import steering_angles

    bot, t_end = _robot(), 2.0
    run = integrate(
        bot,
        lambda t, s: inverse(bot, s[1], _twist(t)).value,
        steering_angles(bot, _twist(0.0)),
        t_end=t_end,
        dt=0.01,
        steer=rates,
    )
    miss = float(np.max(np.abs(run.twist - np.array([_twist(t) for t in run.t]))))
    drift = angle_gap(run.beta[-1], steering_angles(bot, _twist(t_end)))
    return wrong(
        f"With these rates the axles do not stay perpendicular to the velocity: after {t_end:g} s they are "
        f"${number(np.degrees(drift))}^\\circ$ off, and the robot misses the commanded velocity by "
        f"${number(miss)}$ m/s."
    )


@exercise("6.2", answer="a twist `(psi_dot, x_dot, y_dot)`", tolerance=TOL_6_2)
def reversal(twist_plus):
    r"""Exercise 6.2: a jump of the twist, from :data:`TWIST_6_2`, that the robot executes without re-steering and that
    changes the heading.

    Parameters
    ----------
    twist_plus : array_like (3,)
        :math:`(\dot\psi, \dot x, \dot y)`.

    Returns
    -------
    Result
    """
    tp = answers.vector(twist_plus, 3, "a twist `(psi_dot, x_dot, y_dot)`")
    tm = np.asarray(TWIST_6_2, dtype=float)
    size = float(np.linalg.norm(tp))
    if size <= 1e-12 * np.linalg.norm(tm):
        return wrong("A twist of zero stops the robot: it has no heading. Give a motion.")
    across = float(np.linalg.norm(np.cross(tp, tm))) / (size * float(np.linalg.norm(tm)))
    if across > TOL_6_2.rel:
        return wrong(
            "At the current steering angles this twist needs slip: only multiples of the current twist "
            "share its instantaneous centre, every other one needs re-steering."
        )
    lam = float(tp @ tm / (tm @ tm))
    if lam > 0:
        return wrong("Executable, but it is the same heading at another speed: make the heading jump.")
    return right(
        f"$\\mathbf t^+ = {number(lam)}\\,\\mathbf t^-$: a reversal, the heading jumps by $180^\\circ$ "
        "and the wheels simply roll the other way. Every other jump needs re-steering."
    )
