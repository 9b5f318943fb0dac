r"""What a robot cannot do, as data: from its class, its actuation and its steering joints.

``wmr analyze`` prints each :class:`Limitation` as a sentence (:mod:`wmr.words.limitations`; JSON:
``limitations``).  Each is computed, never typed per robot:

* **from Campion's class** :math:`(\delta_m, \delta_s)` (:func:`wmr.campion_class`) at its generic
  configuration: a robot with :math:`\delta_m < 3` cannot make some twists at all; which ones is
  read off the constraint rows :math:`\mathbf C_1^*` (a twist along a row is forbidden) or off the
  one twist left (:math:`\delta_m = 1`), each a :class:`~wmr.analysis.actuation.Motion`;
* **from the actuation** (:mod:`wmr.analysis.actuation`): when the actuated mobility
  :math:`\delta_a` is below :math:`\delta_m`, each direction of :math:`\mathcal U` (a motion the robot
  makes with every motor stopped): the motors can neither drive nor stop it;
* **from the steering joints**: a steered unit whose steering joint is passive, that rolls in its
  plane and has no steering row (nothing turns it: no motor, no offset to trail behind, no pair
  of wheels) has an angle nothing controls.

Examples
--------
>>> import numpy as np, wmr
>>> skid = wmr.Robot([wmr.FixedWheel((x, y), r=0.1, angle=np.pi / 2) for x in (0.4, 0.0, -0.4) for y in (0.3, -0.3)])
>>> [(x.kind.name, x.motions[0].kind.name, round(x.motions[0].heading, 9) + 0.0) for x in limitations(skid)]
[('NO_TURNING', 'TRANSLATION', 0.0)]
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

import numpy as np

from ..model import validation
from .actuation import Motion, actuated_mobility, free_twists, motion
from .classes import campion_class
from .linalg import null_space
from .mobility import twist_constraints

__all__ = ["LimitationKind", "Limitation", "limitations"]


class LimitationKind(enum.Enum):
    """What a :class:`Limitation` says the robot cannot do (the module notes)."""

    NO_MOTION = "no motion"  #: delta_m = 0: no motion without skidding
    NO_TURNING = "no turning"  #: delta_m = 1, delta_s = 0, the one motion a translation
    NO_STRAIGHT = "no straight"  #: delta_m = 1, delta_s = 0, the one motion a turn
    CAR_LIKE = "car-like"  #: delta_m = 1 with fixed wheels: turns about a point of their axles' line
    ONE_MOTION = "one motion"  #: delta_m = 1 otherwise: one motion per steering, re-steered to change it
    FORBIDDEN = "forbidden"  #: delta_m = 2, delta_s = 0: no motion has a part along ``motions``
    FORBIDDEN_AT_STEERING = "forbidden at a steering"  #: delta_m = 2, delta_s > 0: the same until re-steered
    UNCONTROLLED = "uncontrolled"  #: a motion the robot makes with every motor stopped
    UNSTEERED = "unsteered"  #: a unit's steering angle that nothing controls


@dataclass(frozen=True)
class Limitation:
    """What a robot cannot do (in words: :func:`wmr.words.limitations.sentence`).

    Attributes
    ----------
    kind : LimitationKind
    motions : tuple of Motion
        The one motion left (``NO_TURNING``, ``NO_STRAIGHT``), the directions forbidden
        (``FORBIDDEN``...), the motion with every motor stopped (``UNCONTROLLED``); else empty.
    unit : int or None
        ``UNSTEERED``: the unit's index in ``robot.wheels``.
    actuated_mobility : int or None
        ``UNCONTROLLED``: the actuated mobility, below :math:`\\delta_m`.
    delta_m : int or None
        ``UNCONTROLLED``: Campion's :math:`\\delta_m`.
    """

    kind: LimitationKind
    motions: tuple[Motion, ...] = ()
    unit: int | None = None
    actuated_mobility: int | None = None
    delta_m: int | None = None


def _of_class(robot, c) -> list[Limitation]:
    """What the class forbids (see the module notes)."""
    s = robot.F_column_norms[:3]
    t = np.asarray(c.twist)
    K = LimitationKind
    if c.delta_m == 0:
        return [Limitation(K.NO_MOTION)]
    if c.delta_m == 1 and c.delta_s == 0:
        turns = abs(t[0] * s[0]) > 1e-9 * np.abs(t * s).max()
        return [Limitation(K.NO_STRAIGHT if turns else K.NO_TURNING, (motion(robot, t),))]
    if c.delta_m == 1:
        return [Limitation(K.CAR_LIKE if c.rank_C1f >= 1 else K.ONE_MOTION)]
    if c.delta_m == 2:
        A, _ = twist_constraints(robot, np.asarray(c.beta))  # the rows of C1*
        normals = null_space(null_space(A / s, scale=np.ones(3)).T, scale=np.ones(3)) if A.size else np.zeros((3, 0))
        ways = tuple(motion(robot, normals[:, k] / s) for k in range(normals.shape[1]))
        return [Limitation(K.FORBIDDEN if c.delta_s == 0 else K.FORBIDDEN_AT_STEERING, ways)]
    return []


def steering_limitations(robot) -> list[Limitation]:
    """Steered units whose angle nothing controls: one ``UNSTEERED`` limitation each (see the module notes)."""
    return [
        Limitation(LimitationKind.UNSTEERED, unit=k)
        for k, u in enumerate(robot.wheels)
        if any(j.steering and not j.driven for j in u.joints) and u.rolls_in_plane and u.steering_row() is None
    ]


def limitations(robot, campion=None) -> list[Limitation]:
    """What the robot cannot do (see the module notes); empty when nothing is limited.

    Parameters
    ----------
    robot : Robot
        A numeric robot.
    campion : CampionClass, optional
        Its class (:func:`wmr.campion_class`), when already computed.

    Returns
    -------
    list of Limitation
        From the class, then the actuation (one per motion with every motor stopped), then the steering joints.
    """
    robot = validation.numeric_robot(robot)
    c = campion_class(robot) if campion is None else campion
    beta = np.asarray(c.beta)
    da = int(actuated_mobility(robot, beta))
    U = free_twists(robot, beta) if da < c.delta_m else np.zeros((3, 0))
    free = [Limitation(LimitationKind.UNCONTROLLED, (motion(robot, u),), None, da, int(c.delta_m)) for u in U.T]
    return _of_class(robot, c) + free + steering_limitations(robot)
