r"""The numbers of one configuration (:class:`SteeringState`) or one placement of mount points (:class:`MountState`).

No matplotlib, no widgets.

Part of the interactive chapter: :mod:`edition.interactive`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr.analysis.isotropy import characteristic_length
from wmr.analysis.linalg import condition_number
from wmr.analysis.lines import axles_concurrency, concurrency_point
from wmr.analysis.mobility import admissible_twists, rank_F
from wmr.analysis.steering import steering_angles
from wmr.model import validation as V
from wmr.model.robot import Robot
from wmr.model.robots import paper_robot
from wmr.model.wheels import OffsetWheel

__all__ = ["SteeringState", "MountState", "steering_state", "mount_state"]


@dataclass(frozen=True)
class SteeringState:
    r"""One configuration of a three-centred-wheel robot and what it means.

    Attributes
    ----------
    robot : wmr.Robot
    beta : numpy.ndarray (3,)
        Steering angles (radians).
    twist : numpy.ndarray (3,) or None
        The commanded twist, if the angles were set for one.
    det_J : float
        :math:`\det\mathbf J` with :math:`L` the characteristic length (:func:`wmr.characteristic_length`).
    rank_F : int
    kappa_J : float
        :math:`\kappa(\mathbf J)` (``inf`` when singular).
    axles : wmr.analysis.lines.Concurrency
        Where the axle lines meet: the instantaneous centre when the robot can move.
    planes : wmr.analysis.lines.Concurrency
        Where the wheel-plane lines meet (:math:`D_P`).
    motion : numpy.ndarray (3,) or None
        A unit basis vector of the admissible twists (rank F = 5), else None.
    """

    robot: Robot
    beta: np.ndarray
    twist: object
    det_J: float
    rank_F: int
    kappa_J: float
    axles: object
    planes: object
    motion: object

    @property
    def mobility(self):
        """Dimension of the admissible twists (0 or 1 for three centred wheels)."""
        return 3 + self.robot.n_rates - self.rank_F


def steering_state(robot=None, beta=None, twist=None):
    r"""The numbers of one configuration: steering angles ``beta``, or those that make ``twist`` executable.

    Parameters
    ----------
    robot : wmr.Robot, optional
        Three centred wheels (default: the paper's robot, L = 1 m, r = 0.2 m).
    beta : array (3,), optional
        Steering angles (radians); ignored when ``twist`` is given.
    twist : array (3,), optional
        :math:`(\dot\psi, \dot x, \dot y)`; the angles come from :func:`wmr.steering_angles`.

    Returns
    -------
    SteeringState

    Examples
    --------
    >>> s = steering_state(twist=[1.0, 0.0, 0.0])          # spin about C
    >>> s.rank_F, round(s.kappa_J, 6), s.axles.kind.name
    (5, 1.414214, 'FINITE')
    """
    robot = robot or paper_robot("centred", L=1.0, r=0.2)
    if robot.n_rates != 3 or any(u.kind != "centred" for u in robot.wheels):
        raise ValueError(f"robot must have three centred wheels, got {robot!r}")
    if twist is not None:
        twist = V.finite_array("twist", twist, last=3)
        beta = steering_angles(robot, twist, current=None if beta is None else beta)
    beta = V.finite_array("beta", np.zeros(3) if beta is None else beta, last=3)
    L = characteristic_length(robot)
    J = robot.J(beta, L=L)
    rk = int(rank_F(robot, beta))
    basis = admissible_twists(robot, beta)
    motion = None
    if basis.shape[1] == 1:
        m = basis[:, 0]
        motion = m / np.linalg.norm(m) * (1.0 if (m[0] if abs(m[0]) > 1e-12 else m[np.argmax(np.abs(m))]) > 0 else -1.0)
    return SteeringState(
        robot,
        beta,
        twist,
        float(np.linalg.det(J)),
        rk,
        float(condition_number(J)),
        axles_concurrency(robot, beta),
        concurrency_point(robot, beta),
        motion,
    )


@dataclass(frozen=True)
class MountState:
    r"""A placement of three mount points and the isotropy of :math:`\mathbf J_{L1}`.

    Attributes
    ----------
    points : numpy.ndarray (3, 2)
    L : float
        The characteristic length used.
    L_rms : float
        The root-mean-square distance of the mount points from C (the best L when the centroid is at C).
    centroid : numpy.ndarray (2,)
        :math:`\tfrac13\sum_i\mathbf d_i`.
    kappa : float
        :math:`\kappa(\mathbf J_{L1})`.
    kappa_best : float
        :math:`\kappa(\mathbf J_{L1})` at ``L_rms``.
    """

    points: np.ndarray
    L: float
    L_rms: float
    centroid: np.ndarray
    kappa: float
    kappa_best: float


def mount_state(points, L=None):
    r"""The isotropy of :math:`\mathbf J_{L1}` for three mount points and a characteristic length.

    Parameters
    ----------
    points : array (3, 2)
        Mount points :math:`\mathbf d_i` (body frame).
    L : float, optional
        Default: the RMS distance.

    Returns
    -------
    MountState

    Examples
    --------
    >>> s = mount_state([(2, 0), (-1, 1), (-1, -1)])       # isosceles, centroid at C
    >>> round(s.kappa, 9), round(s.L_rms ** 2, 9)
    (1.0, 2.666666667)
    """
    pts = V.finite_array("points", points, last=2)
    if pts.shape != (3, 2):
        raise ValueError(f"points must have shape (3, 2), got {pts.shape}")
    L_rms = float(np.sqrt(np.mean(np.sum(pts**2, axis=1))))
    if L_rms == 0:
        raise ValueError("points must not all be at C")
    L = L_rms if L is None else V.positive("L", L)
    bot = Robot([OffsetWheel(tuple(p), r=1.0, d=1.0) for p in pts])
    return MountState(
        pts,
        float(L),
        L_rms,
        pts.mean(axis=0),
        float(condition_number(bot.J1(L))),
        float(condition_number(bot.J1(L_rms))),
    )
