r"""The five classes of wheeled mobile robots of Campion, Bastin & d'Andrea-Novel (1996).

("Structural properties and classification of kinematic and dynamic models of wheeled mobile
robots", IEEE Trans. Robotics and Automation 12(1), 1996).  They sort every robot by two integers read
off the constraints **orthogonal to the wheel planes** of its wheels with a fixed wheel plane through
the wheel centre:

* :math:`\mathbf C_{1f}`: one row per fixed wheel, :math:`\mathbf i_i^T[\mathbf E\mathbf d_i\ \ \mathbf 1]`
  (the hub of a fixed wheel cannot move along its axle :math:`\mathbf i_i`);
* :math:`\mathbf C_{1s}(\boldsymbol\beta_s)`: the same row for each steerable centred wheel (in
  ``wmr``: centred and dual units), at its steering angle;
* :math:`\mathbf C_1^* = [\mathbf C_{1f};\ \mathbf C_{1s}(\boldsymbol\beta_s)]`.  Offset (castor) and
  Swedish wheels add no row: their hubs can move in every direction (their local blocks are
  invertible, :mod:`wmr.model.wheels.swedish`); an offset wheel with :math:`d = 0` is a centred
  wheel and counts as one.

These rows are the twist constraints of :func:`wmr.analysis.mobility.twist_constraints`.  Then

.. math:: \delta_m = \dim\mathcal N(\mathbf C_1^*(\boldsymbol\beta_s)) = 3 - \operatorname{rank}\mathbf C_1^*,
          \qquad \delta_s = \operatorname{rank}\mathbf C_{1s}(\boldsymbol\beta_s),

the *degree of mobility* (the dimension of the admissible platform twists) and the *degree of
steerability* (how many steering angles can be chosen independently), evaluated at a generic
configuration in which the robot can move.  Campion assumes the steered wheels' rows independent
of the fixed wheels', :math:`\operatorname{rank}\mathbf C_1^* = \operatorname{rank}\mathbf C_{1f} +
\operatorname{rank}\mathbf C_{1s}`; ``wmr`` computes
:math:`\delta_s = \operatorname{rank}\mathbf C_1^* - \operatorname{rank}\mathbf C_{1f}`, the same number under
that assumption, and otherwise the number of steering angles that can still be chosen
independently: a car whose two front wheels are steered (an Ackermann linkage keeps them
compatible) has :math:`\operatorname{rank}\mathbf C_{1s} = 2` but :math:`\delta_s = 1`, the class (1,1)
Campion gives it.  Robots with :math:`\operatorname{rank}\mathbf C_{1f} \le 1` (non-degenerate: otherwise
the fixed wheels leave at most a rotation about one point) fall in five classes: (3,0)
omnidirectional, (2,0) differential drive, (2,1) one steered wheel, (1,1) car-like and (1,2) two or
more independently steered wheels.  Other robots get their :math:`(\delta_m, \delta_s)` and
``standard = False``.

The generic configuration is built, not searched: a platform twist :math:`\mathbf t` in the null
space of :math:`\mathbf C_{1f}` (the projection of a fixed pseudo-random vector, in the
dimensionless coordinates of :mod:`wmr.model.tolerance`), then the steered wheels set compatible
with it (:func:`wmr.steering_angles`; wheels at the instantaneous centre get fixed pseudo-random
angles).  Of a few such draws (fixed seed) the one with the smallest :math:`\delta_m` (then the
largest :math:`\delta_s`) is kept, so the rank drops of special configurations do not count.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model import validation
from ..model.robot import Robot
from ..model.tolerance import TOL
from .linalg import null_space, rank
from .mobility import twist_constraints
from .steering import steering_angles

__all__ = ["CampionClass", "campion_class"]

#: Campion's five classes of non-degenerate robots, (delta_m, delta_s) -> a short description.
CLASS_NAMES = {
    (3, 0): "omnidirectional",
    (2, 0): "differential drive (unicycle-like)",
    (2, 1): "one steered wheel",
    (1, 1): "car-like",
    (1, 2): "independently steered wheels",
}

_SEED = 1996  # the generic draws: fixed, so that the class of a robot never changes
_DRAWS = 3


@dataclass(frozen=True)
class CampionClass:
    r"""The class :math:`(\delta_m, \delta_s)` of a robot, with a configuration where it is attained.

    Attributes
    ----------
    delta_m : int
        Degree of mobility :math:`\delta_m = 3 - \operatorname{rank}\mathbf C_1^*` (0 to 3).
    delta_s : int
        Degree of steerability :math:`\delta_s = \operatorname{rank}\mathbf C_1^* - \operatorname{rank}\mathbf C_{1f}`:
        Campion's :math:`\operatorname{rank}\mathbf C_{1s}` when the steered wheels' rows are
        independent of the fixed wheels' (see the module notes).
    label : str
        ``"(delta_m,delta_s)"``, e.g. ``"(1,2)"`` (ASCII).
    name : str
        Campion's description of the class, or why the robot is outside the five classes.
    standard : bool
        True for the five classes (3,0), (2,0), (2,1), (1,1), (1,2) of robots with
        :math:`\operatorname{rank}\mathbf C_{1f} \le 1` (Campion's non-degenerate robots).
    maneuverability : int
        The degree of maneuverability :math:`\delta_M = \delta_m + \delta_s`.
    rank_C1f : int
        :math:`\operatorname{rank}\mathbf C_{1f}` (the fixed wheels' rows).
    rank_C1s : int
        :math:`\operatorname{rank}\mathbf C_{1s}` at ``beta`` (the steered wheels' rows).
    twist : tuple of 3 float
        The generic admissible twist :math:`[\dot\psi, \dot x, \dot y]` used (zero when the robot
        cannot move).
    beta : tuple of w float
        A configuration where the class is attained (steered wheels compatible with ``twist``;
        the entries of fixed and Swedish wheels are their own angles).
    """

    delta_m: int
    delta_s: int
    label: str
    name: str
    standard: bool
    maneuverability: int
    rank_C1f: int
    rank_C1s: int
    twist: tuple
    beta: tuple


def _rows(robot, keep, beta):
    """The twist-constraint rows (k, 3) of the units ``keep`` (indices) at ``beta`` (w,): C1f or C1s."""
    if not keep:
        return np.zeros((0, 3))
    sub = Robot([robot.wheels[i] for i in keep], name="part")  # same mount points, same operation point C
    A, _ = twist_constraints(sub, beta[keep])
    return A


def _translation(t, scale):
    """The twist is a translation: its dimensionless rotation part is zero (the rule of near_zero)."""
    th = np.abs(np.asarray(t) * scale)
    return bool(th[0] <= TOL * th.max())


def _rank(A, scale):
    return int(rank(A, scale=scale)) if A.shape[0] else 0


def campion_class(robot: Robot) -> CampionClass:
    r"""Degree of mobility and of steerability of ``robot``: Campion's class :math:`(\delta_m, \delta_s)`.

    See the module notes for the definitions and the generic configuration.

    Parameters
    ----------
    robot : Robot
        A numeric robot (or an exact one, evaluated in floats); any wheel types.

    Returns
    -------
    CampionClass

    Examples
    --------
    >>> import wmr
    >>> campion_class(wmr.paper_robot("centred")).label          # three steered wheels
    '(1,2)'
    >>> campion_class(wmr.paper_robot("offset")).label           # three castors: omnidirectional
    '(3,0)'
    >>> car = wmr.Robot([wmr.FixedWheel((0.0, 0.3), r=0.1, angle=np.pi / 2),
    ...                  wmr.FixedWheel((0.0, -0.3), r=0.1, angle=np.pi / 2),
    ...                  wmr.CentredWheel((1.0, 0.0), r=0.1)])
    >>> c = campion_class(car)
    >>> c.delta_m, c.delta_s, c.name
    (1, 1, 'car-like')
    >>> skid = wmr.Robot([wmr.FixedWheel((x, y), r=0.1, angle=np.pi / 2) for x in (0.4, -0.4) for y in (0.3, -0.3)])
    >>> campion_class(skid).name
    'degenerate: the fixed wheels allow only a translation along one direction (no turning)'

    """
    robot = validation.numeric_robot(robot)
    w = robot.w
    scale = robot.F_column_norms[:3]  # the twist columns of F (wmr.model.tolerance)
    fixed = [i for i, u in enumerate(robot.wheels) if not u.steered]
    steered = [i for i, u in enumerate(robot.wheels) if u.steered]
    rng = np.random.default_rng(_SEED)
    Cf = _rows(robot, fixed, robot.effective_beta(np.zeros(w)))
    # admissible twists of the fixed wheels, in dimensionless coordinates t_hat = t * scale
    N = null_space(Cf / scale, scale=np.ones(3)) if Cf.shape[0] else np.eye(3)
    rf = _rank(Cf, scale)
    best: tuple | None = None
    for _ in range(_DRAWS):
        g, current = rng.normal(size=3), rng.uniform(-np.pi, np.pi, w)
        t = (N @ (N.T @ g)) / scale  # projection onto N(C1f): any basis gives the same t
        beta = steering_angles(robot, t, current=current)
        Cs = _rows(robot, steered, beta)
        r_star = _rank(np.vstack([Cf, Cs]), scale)  # rank C1*
        dm, ds, rs = 3 - r_star, r_star - rf, _rank(Cs, scale)
        if best is None or (dm, -ds) < (best[0], -best[1]):
            best = (dm, ds, rs, t, beta)
    assert best is not None  # (_DRAWS >= 1)
    dm, ds, rs, t, beta = best
    standard = (dm, ds) in CLASS_NAMES and rf <= 1
    if standard:
        name = CLASS_NAMES[(dm, ds)]
    elif dm == 0:
        name = "degenerate: the wheels admit no motion"
    elif rf >= 2:  # one twist left: a translation or a rotation
        name = "degenerate: the fixed wheels allow only " + (
            "a translation along one direction (no turning)" if _translation(t, scale) else "a rotation about one point"
        )
    else:
        name = "outside Campion's five classes"
    return CampionClass(
        delta_m=int(dm),
        delta_s=int(ds),
        label=f"({dm},{ds})",
        name=name,
        standard=standard,
        maneuverability=int(dm + ds),
        rank_C1f=int(rf),
        rank_C1s=int(rs),
        twist=tuple(float(x) for x in t),
        beta=tuple(float(b) for b in beta),
    )
