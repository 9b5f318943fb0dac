r"""Chapter 5 exercises (steering and the instantaneous centre): checks that say whether an answer is right and why not.

See :mod:`edition.exercises` for how the checks are used.
"""
from __future__ import annotations

import numpy as np

from wmr.analysis.kinematics import inverse

from .feedback import Feedback, as_angles, missing

__all__ = ["translation_angles", "rotation_angles", "printed_65_region"]


def translation_angles(beta, velocity=(0.3, 0.4), psi_deg=30.0):
    r"""Exercise 5.1: steering angles :math:`\beta_i` for a translation with fixed-frame velocity ``velocity`` at
    heading ``psi_deg``.

    Parameters
    ----------
    beta : array (3,) or None
        Radians.
    velocity : pair
        :math:`(\dot X, \dot Y)` in the fixed frame (m/s).
    psi_deg : float
        Platform orientation :math:`\psi` (degrees).

    Returns
    -------
    Feedback
    """
    from ..checks.steering import robot
    beta, fb = as_angles(beta)
    if fb is not None:
        return fb
    psi = np.radians(psi_deg)
    v = np.asarray(velocity, dtype=float)
    c = np.array([[np.cos(psi), np.sin(psi)], [-np.sin(psi), np.cos(psi)]]) @ v      # body components R(psi)^T v
    twist = np.r_[0.0, c]
    sol = inverse(robot(), beta, twist)
    if bool(sol.admissible):
        return Feedback(True, r"Every axle is perpendicular to the velocity and the wheels roll along it: "
                              r"$\phi_i = \psi + \beta_i = \operatorname{atan2}(\dot Y, \dot X) + \pi/2$ (mod $\pi$).")
    from ..algebra import mod_pi
    if np.allclose(mod_pi(beta + psi - np.arctan2(v[1], v[0])), 0.0, atol=1e-9):
        return Feedback(False, "These are the angles of the printed (60): the *axles* point along the velocity and "
                               f"the wheels would slide sideways at the full speed (${np.linalg.norm(v):.3g}$ m/s).")
    return Feedback(False, f"The wheels would slip (residual ${np.abs(sol.residual).max():.3g}$ m/s). In translation "
                           "every "
                           r"point moves with $\dot{\mathbf c}$: each axle $\mathbf i_i$ (absolute angle "
                           r"$\psi + \beta_i$) must be perpendicular to it.")


def rotation_angles(beta, U=(0.5, 0.3)):
    r"""Exercise 5.2: steering angles for a rotation about the body point ``U``.

    Parameters
    ----------
    beta : array (3,) or None
        Radians.
    U : pair
        The instantaneous centre, body frame (m).

    Returns
    -------
    Feedback
    """
    from ..checks.steering import robot
    beta, fb = as_angles(beta)
    if fb is not None:
        return fb
    u = np.asarray(U, dtype=float)
    twist = np.r_[1.0, np.array([u[1], -u[0]])]          # c_dot = -psi_dot E u
    sol = inverse(robot(), beta, twist)
    if bool(sol.admissible):
        return Feedback(True, r"Every axle points at U: $\beta_i = \operatorname{atan2}(u_{iy}, u_{ix})$ (mod $\pi$) "
                              r"with $\mathbf u_i = \mathbf u_c - \mathbf d_i$ (64).")
    return Feedback(False, rf"The wheels would slip (residual ${np.abs(sol.residual).max():.3g}$ m/s at "
                           r"$\dot\psi = 1$): each "
                           r"axle $\mathbf i_i$ must be parallel to $\mathbf u_i = \overrightarrow{P_iU}$, the angle "
                           r"measured from the body axis $\mathbf i$, not from $\overrightarrow{CU}$ as the printed "
                           r"(65) does.")


def printed_65_region(U):
    r"""Exercise 5.3: a centre U (not C) at which the printed (65), with the better sign of arccos per wheel, steers
    correctly.

    Parameters
    ----------
    U : pair or None
        Body frame (m).

    Returns
    -------
    Feedback
    """
    from ..checks.steering import robot
    fb = missing(U, "a point $U = (u_x, u_y)$")
    if fb is not None:
        return fb
    u = np.asarray(U, dtype=float)
    if np.linalg.norm(u) < 1e-9:
        return Feedback(False, r"At U = C the printed (65) is $0/0$: undefined. Try another point.")
    bot = robot()
    ui = u - bot.mount_points
    cos_pr = (ui @ u) / (np.linalg.norm(ui, axis=1) * np.linalg.norm(u))
    b = np.arccos(np.clip(cos_pr, -1, 1))
    def lateral(x):
        return np.abs(ui[:, 1] * np.cos(x) - ui[:, 0] * np.sin(x))
    b = np.where(lateral(b) <= lateral(-b), b, -b)
    twist = np.r_[1.0, np.array([u[1], -u[0]])]
    if bool(inverse(bot, b, twist).admissible):
        return Feedback(True, r"Here the printed angle between $\overrightarrow{CU}$ and $\overrightarrow{P_iU}$ is "
                              r"the angle from the body axis $\mathbf i$: U lies on the positive body $x$-axis, the "
                              r"only place where the printed (65) works.")
    return Feedback(False, r"At this U the printed angles leave the axles off U: the robot is jammed. The printed "
                           r"angle is measured from $\overrightarrow{CU}$; where does that line coincide with the body "
                           r"axis $\mathbf i$?")
