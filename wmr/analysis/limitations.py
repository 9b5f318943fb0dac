r"""What a robot cannot do, in plain sentences: from its class, its actuation and its steering joints.

``wmr analyze`` prints these sentences (JSON: ``limitations``).  Each is computed, never typed per
robot:

* **from Campion's class** :math:`(\delta_m, \delta_s)` (:func:`wmr.campion_class`) at its generic
  configuration: a robot with :math:`\delta_m < 3` cannot make some twists at all; which ones is
  read off the constraint rows :math:`\mathbf C_1^*` (a twist along a row is forbidden) or off the
  one twist left (:math:`\delta_m = 1`), and said in words by
  :func:`~wmr.analysis.actuation.describe_twist`;
* **from the actuation** (:mod:`wmr.analysis.actuation`): when the actuated mobility
  :math:`\delta_a` is below :math:`\delta_m`, each direction of :math:`\mathcal U` (a motion the robot
  makes with every motor stopped) is named: the motors can neither drive nor stop it;
* **from the steering joints**: a steered unit whose steering joint is passive, that rolls in its
  plane and has no steering row (nothing turns it: no motor, no offset to trail behind, no pair
  of wheels) has an angle nothing controls.

Examples
--------
>>> import numpy as np, wmr
>>> skid = wmr.Robot([wmr.FixedWheel((x, y), r=0.1, angle=np.pi / 2) for x in (0.4, 0.0, -0.4) for y in (0.3, -0.3)])
>>> limitations(skid)
['turning requires skidding: it can only drive straight ahead (along x)']
"""

from __future__ import annotations

import numpy as np

from ..model import validation
from .actuation import actuated_mobility, describe_twist, free_twists
from .classes import campion_class
from .linalg import null_space
from .mobility import twist_constraints

__all__ = ["limitations", "steering_limitations"]


def _class_sentences(robot, c) -> list[str]:
    """What the class forbids (see the module notes)."""
    s = robot.F_column_norms[:3]
    t = np.asarray(c.twist)
    if c.delta_m == 0:
        return ["it cannot move at all without skidding: its wheels' constraints admit no motion"]
    if c.delta_m == 1 and c.delta_s == 0:
        motion = describe_twist(robot, t)
        if abs(t[0] * s[0]) <= 1e-9 * np.abs(t * s).max():
            return [f"turning requires skidding: it can only drive {motion}"]
        return [f"driving straight requires skidding: it can only move {motion}"]
    if c.delta_m == 1 and c.rank_C1f >= 1:
        return [
            "it cannot move sideways or choose its centre of rotation freely: every motion turns about a "
            "point on the line of its fixed wheels' axles (or drives straight along their planes), "
            "and steering picks the point (car-like)"
        ]
    if c.delta_m == 1:
        return [
            "at any one steering it has a single motion: to change the direction of motion it must re-steer "
            "its wheels first (it cannot change direction instantly)"
        ]
    if c.delta_m == 2:
        beta = np.asarray(c.beta)
        A, _ = twist_constraints(robot, beta)  # the rows of C1*
        normals = null_space(null_space(A / s, scale=np.ones(3)).T, scale=np.ones(3)) if A.size else np.zeros((3, 0))
        words = [describe_twist(robot, normals[:, k] / s) for k in range(normals.shape[1])]
        what = " or ".join(words) or "one direction"
        if c.delta_s == 0:
            return [
                f"it cannot move {what}: no motion may have a part of that (non-holonomic, like a differential drive)"
            ]
        return [f"at any one steering it cannot move {what}: that needs its steered wheel re-steered first"]
    return []


def steering_limitations(robot) -> list[str]:
    """Steered units whose angle nothing controls (see the module notes).

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    list of str
        One sentence per such unit.

    Examples
    --------
    >>> import wmr
    >>> free = wmr.CentredWheel((0.3, 0.0), r=0.05, driven={"steer": False})
    >>> print(*steering_limitations(wmr.Robot([free, wmr.CentredWheel((-0.3, 0.0), r=0.05)]))[0].split(": ")[::2])
    wheel 1 its angle is not under control
    """
    robot = validation.robot(robot)
    out = []
    for k, u in enumerate(robot.wheels, 1):
        passive_steer = any(j.steering and not j.driven for j in u.joints)
        if passive_steer and u.rolls_in_plane and u.steering_row() is None:
            out.append(
                f"wheel {k}: its steering joint is passive and nothing turns it (no motor, no offset to "
                "trail behind): its angle is not under control"
            )
    return out


def limitations(robot, campion=None) -> list[str]:
    """What the robot cannot do, as plain sentences (see the module notes); empty when nothing is limited.

    Parameters
    ----------
    robot : Robot
        A numeric robot.
    campion : CampionClass, optional
        Its class (:func:`wmr.campion_class`), when already computed.

    Returns
    -------
    list of str
    """
    robot = validation.numeric_robot(robot)
    c = campion_class(robot) if campion is None else campion
    out = _class_sentences(robot, c)
    beta = np.asarray(c.beta)
    da = int(actuated_mobility(robot, beta))
    if da < c.delta_m:
        U = free_twists(robot, beta)
        for k in range(U.shape[1]):
            out.append(
                f"the motors cannot move it {describe_twist(robot, U[:, k])}: it moves that way with every "
                f"motor stopped (its passive joints roll freely), so the motors can neither drive nor stop "
                f"that motion (actuated mobility {da} < delta_m = {c.delta_m})"
            )
    return out + steering_limitations(robot)
