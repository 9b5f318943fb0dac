r"""Conditioning along the motions a robot with steered wheels can make: :math:`\kappa(\mathbf J)` per centre.

A robot with centred (or dual) wheels moves only in the configurations that make some twist
admissible: every axle points at the instantaneous centre U (:func:`wmr.steering_angles`).  Over
*all* configurations its worst case :math:`\sup_{\boldsymbol\beta}\kappa(\mathbf J)` is infinite (a
translation makes :math:`\mathbf J` singular, Chapter 3), so the informative measure is
:math:`\kappa(\mathbf J)` (30), (56) along the admissible motions: a rotation about each point U,

.. math:: \mathbf t = (\dot\psi, \dot{\mathbf c}) = (1,\ \mathbf E(\mathbf c - \mathbf U)),\qquad
          \boldsymbol\beta = \boldsymbol\beta(\mathbf t),\qquad
          \kappa_U = \kappa\big(\mathbf J(\boldsymbol\beta, L)\big),

with :math:`\mathbf c = \mathbf 0` (C is the origin of the body frame) and the characteristic length
:math:`L` of :func:`wmr.characteristic_length`.  Translations are rotations about a point at
infinity.  :math:`\mathbf J` is singular exactly when some twist moves every mount point along its
axle (:mod:`wmr.analysis.singularities`); for a rotation about U that twist is a rotation about a
point D with every :math:`P_i` seeing U and D at a right angle: the mount points lie on the circle
of diameter UD.  So a layout whose mount points are concyclic (three wheels; four at the corners of
a rectangle) is singular for every rotation centre on that circle; a layout with four or more
mount points not on one circle is singular only in translation.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model import validation
from ..model.robot import Robot
from ..model.tolerance import near_zero
from ..model.types import ArrayLike, FloatArray, TwistLike
from .isotropy import characteristic_length
from .linalg import condition_number
from .lines import circumcircle
from .steering import steering_angles

__all__ = ["rotation_twists", "motion_kappa", "mount_circle", "MotionMap", "motion_map"]


def rotation_twists(centres: ArrayLike) -> FloatArray:
    r"""Unit-rate rotations about points U: the twists :math:`(1,\ U_y,\ -U_x)` (array (..., 3)).

    Parameters
    ----------
    centres : array_like (..., 2)
        Instantaneous centres, body frame.

    Returns
    -------
    numpy.ndarray (..., 3)

    Examples
    --------
    >>> rotation_twists([0.0, 2.0]).tolist()           # about (0, 2): C moves along +x
    [1.0, 2.0, -0.0]
    """
    return _rotations(validation.finite_array("centres", centres, last=2))


def _rotations(U):
    """:func:`rotation_twists` of checked centres."""
    return np.stack([np.ones(U.shape[:-1]), U[..., 1], -U[..., 0]], axis=-1)


def motion_kappa(robot: Robot, twist: TwistLike, L: float | None = None) -> FloatArray:
    r""":math:`\kappa(\mathbf J)` at the steering angles that make each twist admissible (batched).

    Parameters
    ----------
    robot : Robot
        A numeric robot with centred or dual wheels.
    twist : array_like (..., 3)
        Twists :math:`(\dot\psi, \dot x, \dot y)`.
    L : float, optional
        Characteristic length (default :func:`wmr.characteristic_length`).

    Returns
    -------
    numpy.ndarray (...)
        ``inf`` where :math:`\mathbf J` is singular.

    Examples
    --------
    >>> import wmr
    >>> bot = wmr.paper_robot("centred", L=0.4, r=0.1)
    >>> round(float(motion_kappa(bot, [1.0, 0.0, 0.0])), 9), float(motion_kappa(bot, [0.0, 1.0, 0.0]))
    (1.414213562, inf)
    """
    return _kappa(validation.numeric_robot(robot), twist, _length(robot, L))


def _length(robot, L):
    """``L`` checked, or the characteristic length of a checked ``robot``."""
    return characteristic_length(robot) if L is None else validation.number("L", validation.positive("L", L))


def _kappa(robot, twist, L):
    """:func:`motion_kappa` of a checked robot and length."""
    return condition_number(robot.J(steering_angles(robot, twist), L=L))


def mount_circle(robot: Robot) -> tuple[FloatArray, float] | None:
    """The circle through every mount point, or None when they are not concyclic (or fewer than 3, or collinear).

    Parameters
    ----------
    robot : Robot
        A numeric robot.

    Returns
    -------
    tuple (centre numpy.ndarray (2,), radius float) or None
    """
    return _circle(validation.numeric_robot(robot).mount_points)


def _circle(d):
    """:func:`mount_circle` of the mount points ``d`` (w, 2)."""
    if len(d) < 3:
        return None
    try:
        centre, R = circumcircle(d[:3])
    except ValueError:  # collinear
        return None
    on = near_zero(np.linalg.norm(d - centre, axis=1) - R, R)
    return (centre, float(R)) if bool(np.all(on)) else None


@dataclass(frozen=True)
class MotionMap:
    r""":math:`\kappa(\mathbf J)` of the rotations about the points of a square grid (data of a figure).

    Attributes
    ----------
    x : numpy.ndarray (n,)
        Grid abscissae (body frame).
    y : numpy.ndarray (n,)
        Grid ordinates.
    kappa : numpy.ndarray (n, n)
        :math:`\kappa_U` for U = (x[j], y[i]) (row i, column j); ``inf`` where singular.
    mounts : numpy.ndarray (w, 2)
        Mount points.
    circle : tuple or None
        :func:`mount_circle`.
    kappa_min : float
        Smallest :math:`\kappa_U` on the grid.
    argmin : numpy.ndarray (2,)
        A centre where it is attained.
    kappa_translation : float
        :math:`\kappa(\mathbf J)` in translation (along body x), ``inf`` for centred wheels.
    """

    x: np.ndarray
    y: np.ndarray
    kappa: np.ndarray
    mounts: np.ndarray
    circle: object
    kappa_min: float
    argmin: np.ndarray
    kappa_translation: float


def motion_map(robot: Robot, n: int = 121, half_width: float | None = None, L: float | None = None) -> MotionMap:
    r""":math:`\kappa(\mathbf J)` of the rotation about every point of an ``n`` x ``n`` grid centred on C.

    Parameters
    ----------
    robot : Robot
        A numeric robot with centred or dual wheels.
    n : int, optional
        Points per axis, >= 2.
    half_width : float, optional
        Half the side of the grid (default 2.5 times the largest mount distance).
    L : float, optional
        Characteristic length (default :func:`wmr.characteristic_length`).

    Returns
    -------
    MotionMap
    """
    robot = validation.numeric_robot(robot)
    n = validation.integer("n", n, minimum=2)
    L = _length(robot, L)
    d = robot.mount_points
    if half_width is None:
        h = 2.5 * float(np.linalg.norm(d, axis=1).max())
    else:
        h = float(validation.number("half_width", validation.positive("half_width", half_width)))
    x = y = np.linspace(-h, h, n)
    U = np.stack(np.meshgrid(x, y), axis=-1)  # (n, n, 2)
    K = _kappa(robot, _rotations(U), L)
    k = int(np.argmin(K))
    return MotionMap(
        x=x,
        y=y,
        kappa=K,
        mounts=d,
        circle=_circle(d),
        kappa_min=float(K.flat[k]),
        argmin=U.reshape(-1, 2)[k].copy(),
        kappa_translation=float(_kappa(robot, np.array([0.0, 1.0, 0.0]), L)),
    )
