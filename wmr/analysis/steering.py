r"""Steering: the instantaneous centre of rotation and compatible steering angles (60)-(65).

At the instantaneous centre U the platform velocity vanishes (62):
:math:`\dot{\mathbf u} = \dot{\mathbf c} + \dot\psi\mathbf E\mathbf u_c = \mathbf 0`, hence (63)
:math:`\mathbf u_c = \tfrac1{\dot\psi}\mathbf E\dot{\mathbf c}` and (64)
:math:`\mathbf u_i = \mathbf u_c - \mathbf d_i`.  A centred or dual wheel rolls without slip exactly
when its rolling direction :math:`\mathbf j_i` is parallel to the velocity of :math:`P_i`, i.e. its
axle :math:`\mathbf i_i` points at U (or, in translation, all wheel planes are parallel to
:math:`\dot{\mathbf c}`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.platform import point_velocity
from ..model.robot import Robot
from ..model.tolerance import TOL
from ..model.types import ArrayLike, FloatArray, TwistLike
from ._batch import for_chunks
from .lines import AT_INFINITY, FINITE, STILL

__all__ = [
    "InstantCentre",
    "instantaneous_centre",
    "steering_angles",
    "centre_to_wheels",
    "FINITE",
    "AT_INFINITY",
    "STILL",
]


@dataclass(frozen=True)
class InstantCentre:
    """The instantaneous centre of a batch of twists.

    Attributes
    ----------
    kind : numpy.ndarray of int (...)
        :data:`FINITE` (rotation), :data:`AT_INFINITY` (translation) or :data:`STILL` (zero twist).
    point : numpy.ndarray (..., 2)
        :math:`\\mathbf u_c = \\overrightarrow{CU}` (63), body frame, where ``kind == FINITE``;
        ``inf`` where the centre is at infinity and ``nan`` where the platform is still (both
        flagged by ``kind``).
    direction : numpy.ndarray (..., 2)
        Unit vector pointing from C towards the centre,
        :math:`\\operatorname{sign}(\\dot\\psi)\\,\\mathbf E\\dot{\\mathbf c}/\\|\\dot{\\mathbf c}\\|`; for a
        translation :math:`\\mathbf E\\dot{\\mathbf c}/\\|\\dot{\\mathbf c}\\|` (the side of the motion on
        which the centre has receded to infinity is a convention: the left).  Zero when U = C
        (a spin about C), ``nan`` when still.
    """

    kind: np.ndarray
    point: np.ndarray
    direction: np.ndarray


def instantaneous_centre(twist: TwistLike, length: float | None = None) -> InstantCentre:
    r"""Instantaneous centre of rotation (63) of platform twists.

    The centre is **at infinity** (a translation) when :math:`|\dot\psi|\,\ell \le \mathrm{TOL}\,
    \|\dot{\mathbf c}\|`, i.e. when it is farther from C than :math:`\ell/\mathrm{TOL}` for a robot of
    size :math:`\ell` (``length``); without a length, only :math:`\dot\psi = 0` is a translation.
    The platform is **still** only for the zero twist.  Both decisions are the same in every unit of
    length and time (:mod:`wmr.model.tolerance`).

    Parameters
    ----------
    twist : array (..., 3)
        :math:`[\dot\psi, \dot x, \dot y]`, body frame.
    length : float, optional
        The size of the robot (e.g. :func:`wmr.characteristic_length`), in the unit of
        :math:`\dot x/\dot\psi`; default: no tolerance.

    Returns
    -------
    InstantCentre

    Examples
    --------
    >>> ic = instantaneous_centre([1.0, 0.0, 2.0])   # moving along +y, turning left
    >>> ic.point.tolist()
    [-2.0, 0.0]
    """
    t = validation.twist_array("twist", twist)
    length = None if length is None else validation.number("length", validation.positive("length", length))
    psi, c = t[..., 0], t[..., 1:]
    big = np.max(np.abs(c), axis=-1)  # speeds up to 2.4e308: scaled first
    m = np.where(big > 0, big, 1.0)
    speed = np.hypot(c[..., 0] / m, c[..., 1] / m)  # |c_dot| / m
    Ec = np.stack([-c[..., 1], c[..., 0]], axis=-1)  # E c_dot
    still = (psi == 0) & (big == 0)
    if length is None:
        infinite = (psi == 0) & ~still
    else:
        with np.errstate(over="ignore", under="ignore"):  # the rule of near_zero: |psi| l <= TOL |c_dot|
            infinite = (np.abs(psi) * (length / m) <= TOL * speed) & ~still
    kind = np.where(still, STILL, np.where(infinite, AT_INFINITY, FINITE))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        point = Ec / np.where(kind == FINITE, psi, 1.0)[..., None]  # (63)
        sign = np.where(kind == FINITE, np.sign(psi), 1.0)
        direction = (sign / np.where(speed == 0, 1.0, speed))[..., None] * (Ec / m[..., None])
    if not np.isfinite(point[kind == FINITE]).all():
        raise InputValueError(
            "twist has a centre |c_dot| / |psi_dot| beyond double precision: give length (the "
            "robot's "
            "size) to call it at infinity"
        )
    point = np.where((kind == AT_INFINITY)[..., None], np.inf, point)
    point = np.where((kind == STILL)[..., None], np.nan, point)
    direction = np.where(still[..., None], np.nan, direction)
    return InstantCentre(kind, point, direction)


def steering_angles(robot: Robot, twist: TwistLike, current: ArrayLike | None = None) -> FloatArray:
    r"""Steering angles :math:`\beta_i` that make ``twist`` admissible for centred and dual wheels.

    Each wheel plane is set parallel to the velocity :math:`\dot{\mathbf p}_i = \dot{\mathbf c} +
    \dot\psi\mathbf E\mathbf d_i` of its mount point (2), choosing the angle that makes the
    rolling rate positive: :math:`\mathbf j_i = -\dot{\mathbf p}_i/\|\dot{\mathbf p}_i\|`, i.e.
    :math:`\beta_i = \operatorname{atan2}(\dot p_x, -\dot p_y)`.  Equivalently the axle
    :math:`\mathbf i_i` points at the instantaneous centre.  Where the mount point is still (it
    is the centre, or the twist is zero) every angle is admissible and ``current`` is kept;
    offset wheels (full mobility) also keep ``current``; fixed and Swedish wheels (no steering
    joint) get their own constant angle.  "Still" means
    :math:`\|\dot{\mathbf p}_i\| \le \mathrm{TOL}\,s` with
    :math:`s = \max(|\dot x|, |\dot y|) + |\dot\psi|\max_{i,k}|d_{ik}|`, the size of the terms of
    :math:`\dot{\mathbf p}_i` (the rule of :func:`wmr.model.tolerance.near_zero`).

    Parameters
    ----------
    robot : Robot
    twist : array (..., 3)
    current : array (..., w), optional
        Angles to keep where the choice is free (default 0).

    Returns
    -------
    numpy.ndarray (..., w)
        Angles in :math:`(-\pi, \pi]`.

    Examples
    --------
    >>> from wmr.model.robots import paper_robot
    >>> beta = steering_angles(paper_robot("centred"), [1.0, 0.0, 0.0])   # spin about C
    >>> np.degrees(beta).round(9).tolist()                              # axles point at C
    [0.0, -120.0, 120.0]
    """
    robot = validation.numeric_robot(robot)
    t = validation.twist_array("twist", twist)
    w = robot.w
    if current is not None:
        current = validation.finite_array("current", current, last=w)
    batch = validation.batch_shape({"twist": t, "current": current})
    tw = np.broadcast_to(t, batch + (3,)).reshape(-1, 3)
    cur = None if current is None else np.broadcast_to(current, batch + (w,)).reshape(-1, w)
    d = robot.mount_points  # (w, 2)
    dmax = float(np.abs(d).max())
    keep = np.array([not (u.steered and u.rolls_in_plane) for u in robot.wheels])  # free, or their own angle
    own = [(i, float(u.constant_angle)) for i, u in enumerate(robot.wheels) if u.constant_angle is not None]
    N = tw.shape[0]
    beta = np.empty((N, w))

    def chunk(a, b):
        psi, cx, cy = tw[a:b, 0:1], tw[a:b, 1:2], tw[a:b, 2:3]
        pdot = point_velocity(tw[a:b, None, :], d)  # (2): c_dot + psi_dot E d_i
        px, py = pdot[..., 0], np.negative(pdot[..., 1])  # j_i = -p_dot_i / |p_dot_i|
        # the mount point is still when |p_dot| <= TOL scale (relative); hypot: no overflow of squares
        scale = np.maximum(np.abs(cx), np.abs(cy))
        scale += np.abs(psi) * dmax
        scale *= TOL
        free = np.hypot(px, py) <= scale
        free |= keep
        np.arctan2(px, py, out=beta[a:b])
        np.copyto(beta[a:b], 0.0 if cur is None else cur[a:b], where=free)
        for i, angle in own:  # fixed and Swedish: their own angle
            beta[a:b, i] = angle

    for_chunks(chunk, N)
    return beta.reshape(batch + (w,))


def centre_to_wheels(twist: TwistLike, d: ArrayLike) -> FloatArray:
    r"""Vectors from the mount points to U, :math:`\mathbf u_i = \mathbf E\dot{\mathbf c}/\dot\psi - \mathbf d_i` (64).

    Parameters
    ----------
    twist : array (..., 3), with :math:`\dot\psi \ne 0`
        The centre must be finite for a robot of the size of ``d`` (:func:`instantaneous_centre`).
    d : array (w, 2)

    Returns
    -------
    numpy.ndarray (..., w, 2)

    Examples
    --------
    >>> centre_to_wheels([1.0, 0.0, 2.0], [[1.0, 0.0]]).tolist()          # U = (-2, 0)
    [[-3.0, 0.0]]
    """
    d = validation.finite_array("d", d, last=2)
    ic = instantaneous_centre(twist, length=float(np.abs(d).max()) or None)
    if np.any(ic.kind != FINITE):
        bad = np.asarray(twist)[ic.kind != FINITE][:1].tolist()
        raise InputValueError(f"u_i needs a finite instantaneous centre (psi_dot != 0); got twist {bad}")
    return ic.point[..., None, :] - d
