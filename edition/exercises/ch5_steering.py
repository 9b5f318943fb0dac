r"""Chapter 5 exercises (steering and the instantaneous centre): fair checks (:func:`~.framework.exercise`).

The steering angles a twist needs are computed from the model (``wmr.steering_angles``) and compared
modulo :math:`\pi` (a wheel turned round rolls backwards along the same line) with the tolerance the
question states; a centre of rotation is judged with the printed (65) evaluated at it.
"""

from __future__ import annotations

import numpy as np

from wmr.analysis.kinematics import inverse
from wmr.analysis.steering import steering_angles

from ..text import number
from . import answers
from .feedback import right, wrong
from .framework import exercise
from .tolerance import angle_gap, decimals, within

__all__ = [
    "TOL_5_1",
    "TOL_5_2",
    "TOL_5_3",
    "translation_twist",
    "rotation_twist",
    "translation_angles",
    "rotation_angles",
    "printed_65_region",
]

TOL_5_1 = decimals(3)
TOL_5_2 = decimals(3)
TOL_5_3 = within("within 1 mm", abs=1e-3)


def _robot():
    from ..checks.steering import robot

    return robot()


def translation_twist(velocity=(0.3, 0.4), psi_deg=30.0):
    r"""The twist of exercise 5.1: fixed-frame velocity ``velocity`` at heading ``psi_deg``, no rotation.

    Parameters
    ----------
    velocity : pair
        :math:`(\dot X, \dot Y)` (m/s).
    psi_deg : float
        :math:`\psi` (degrees).

    Returns
    -------
    numpy.ndarray (3,)
        :math:`[0\ \ \dot x\ \ \dot y]` with :math:`\dot{\mathbf c}` in body components
        :math:`\mathbf R(\psi)^{\mathrm T}\mathbf v`.
    """
    psi = np.radians(psi_deg)
    v = np.asarray(velocity, dtype=float)
    return np.r_[0.0, np.array([[np.cos(psi), np.sin(psi)], [-np.sin(psi), np.cos(psi)]]) @ v]


def rotation_twist(U=(0.5, 0.3)):
    r"""The twist of a rotation about the body point ``U`` at :math:`\dot\psi = 1`:
    :math:`\dot{\mathbf c} = -\mathbf E\mathbf u`.

    Parameters
    ----------
    U : pair
        Body frame (m).

    Returns
    -------
    numpy.ndarray (3,)
    """
    u = np.asarray(U, dtype=float)
    return np.r_[1.0, u[1], -u[0]]


def _off(beta, expected, tol):
    """Wheels (1-based) whose angle misses the expected line by more than the tolerance."""
    return [k + 1 for k in range(3) if angle_gap([beta[k]], [expected[k]]) > tol.abs * 1.0000001]


def _coarse(beta, expected, tol, off):
    """True when the wheels ``off`` have their right angles (modulo pi) rounded to fewer decimals than stated."""
    k = [w - 1 for w in off]
    return tol.coarse(np.asarray(beta)[k], np.asarray(expected)[k], period=np.pi)


def _angles_of(off):
    return f"angle{'' if len(off) == 1 else 's'} of {_wheels(off)}"


def _wheels(ks):
    return ("wheel " if len(ks) == 1 else "wheels ") + ", ".join(str(k) for k in ks)


@exercise("5.1", answer="three steering angles in radians", tolerance=TOL_5_1, units={"beta": "rad"})
def translation_angles(beta):
    r"""Exercise 5.1: steering angles for the translation of :func:`translation_twist`.

    Parameters
    ----------
    beta : array_like (3,)
        Radians.

    Returns
    -------
    Result
    """
    beta = answers.angles(beta, 3, "rad")
    twist = translation_twist()
    expected = steering_angles(_robot(), twist)
    off = _off(beta, expected, TOL_5_1)
    if off and _coarse(beta, expected, TOL_5_1, off):
        return wrong(TOL_5_1.close(_angles_of(off)))
    if not off:
        return right(
            r"Every axle is perpendicular to the velocity and the wheels roll along it: "
            r"$\phi_i = \psi + \beta_i = \operatorname{atan2}(\dot Y, \dot X) + \pi/2$ (mod $\pi$)."
        )
    psi, v = np.radians(30.0), np.array([0.3, 0.4])
    printed_60 = np.full(3, np.arctan2(v[1], v[0]) - psi)
    if not _off(beta, printed_60, TOL_5_1):
        return wrong(
            "These are the angles of the printed (60): the *axles* point along the velocity and the wheels "
            f"would slide sideways at the full speed (${number(np.linalg.norm(v))}$ m/s)."
        )
    return wrong(
        f"The wheels would slip: {_wheels(off)} {'is' if len(off) == 1 else 'are'} not steered for this "
        "translation. In translation every "
        r"point moves with $\dot{\mathbf c}$: each axle $\mathbf i_i$ (absolute angle $\psi + \beta_i$) must "
        "be perpendicular to it."
    )


@exercise("5.2", answer="three steering angles in radians", tolerance=TOL_5_2, units={"beta": "rad"})
def rotation_angles(beta):
    r"""Exercise 5.2: steering angles for the rotation about :math:`U = (0.5, 0.3)` m.

    Parameters
    ----------
    beta : array_like (3,)
        Radians.

    Returns
    -------
    Result
    """
    beta = answers.angles(beta, 3, "rad")
    expected = steering_angles(_robot(), rotation_twist())
    off = _off(beta, expected, TOL_5_2)
    if off and _coarse(beta, expected, TOL_5_2, off):
        return wrong(TOL_5_2.close(_angles_of(off)))
    if not off:
        return right(
            r"Every axle points at U: $\beta_i = \operatorname{atan2}(u_{iy}, u_{ix})$ (mod $\pi$) with "
            r"$\mathbf u_i = \mathbf u_c - \mathbf d_i$ (64)."
        )
    return wrong(
        f"The wheels would slip: the axle of {_wheels(off)} does not point at U. Each axle $\\mathbf i_i$ "
        r"must be parallel to $\mathbf u_i = \overrightarrow{P_iU}$, its angle measured from the body axis "
        r"$\mathbf i$."
    )


def printed_65_angles(u, points):
    r"""The printed (65) at the centre ``u``: :math:`\pm\arccos`, each wheel given the sign that slips less.

    Parameters
    ----------
    u : array (2,)
        The centre, body frame (m); not C and not a mount point.
    points : array (3, 2)
        Mount points.

    Returns
    -------
    numpy.ndarray (3,)
        Radians.
    """
    ui = u - points
    cos_pr = (ui @ u) / (np.linalg.norm(ui, axis=1) * np.linalg.norm(u))
    b = np.arccos(np.clip(cos_pr, -1, 1))

    def lateral(x):
        return np.abs(ui[:, 1] * np.cos(x) - ui[:, 0] * np.sin(x))

    return np.where(lateral(b) <= lateral(-b), b, -b)


@exercise("5.3", answer="a point `(u_x, u_y)` in metres", tolerance=TOL_5_3)
def printed_65_region(U):
    r"""Exercise 5.3: a centre U (not C, not a mount point) at which the printed (65), with the better sign of
    arccos per wheel, steers the robot correctly.

    Parameters
    ----------
    U : array_like (2,)
        Body frame (m).

    Returns
    -------
    Result
    """
    u = answers.vector(U, 2, "a point `(u_x, u_y)` in metres")
    bot = _robot()
    tol = TOL_5_3.abs
    if np.linalg.norm(u) <= tol:
        return wrong(r"At U = C the printed (65) is $0/0$: undefined. Try another point.")
    near = [k + 1 for k in range(3) if np.linalg.norm(u - bot.mount_points[k]) <= tol]
    if near:
        return wrong(
            f"U is the mount point of wheel {near[0]}: there $\\mathbf u_{near[0]} = \\mathbf 0$ and the "
            "printed (65) is $0/0$ for that wheel. Try another point."
        )
    # judged at the nearest point of the body x-axis when U is within the tolerance of it, else at U itself
    at = np.array([u[0], 0.0]) if abs(u[1]) <= tol else u
    ok = bool(inverse(bot, printed_65_angles(at, bot.mount_points), rotation_twist(at)).admissible)
    if not ok:
        return wrong(
            r"At this U the printed angles leave the axles off U: the robot is jammed. The printed angle is "
            r"measured from $\overrightarrow{CU}$; where does that line coincide with the body axis "
            r"$\mathbf i$?"
        )
    if at[1] == 0.0 and at[0] > 0:
        return right(
            r"Here $\overrightarrow{CU}$ points along the body axis $\mathbf i$, so the printed angle "
            r"between $\overrightarrow{CU}$ and $\overrightarrow{P_iU}$ is the angle from $\mathbf i$: the "
            "axles point at U."
        )
    if at[1] == 0.0:
        return right(
            r"Here $\overrightarrow{CU}$ points along $-\mathbf i$: the printed angle is $\pi - \beta_i$, and "
            r"the better sign of $\arccos$ gives $\beta_i - \pi$, the same axle line. The axles point at U."
        )
    return right("At this U the printed angles, each with the better sign, put every axle through U.")
