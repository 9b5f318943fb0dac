r"""Actuation: the motions the motors command, and those the robot makes with every motor stopped.

Every joint of a wheel unit is driven (a motor turns it) or passive (the rollers of a Swedish
wheel, a castor's swivel and wheel, an unpowered wheel): :mod:`wmr.model.wheels.joints`, with a
default per kind and a unit's own ``driven``.  Split the rate columns of (21) accordingly,
:math:`\mathbf J_1\mathbf t = \mathbf J_{2a}\dot{\boldsymbol\theta}_a + \mathbf J_{2p}\dot{\boldsymbol\theta}_p`.

* The **admissible** twists :math:`\mathcal T(\boldsymbol\beta) = \mathcal N(\mathbf A)`: some joint
  rates realise them without slip (:func:`wmr.analysis.mobility.twist_constraints`).
* The **free** twists :math:`\mathcal U(\boldsymbol\beta) = \{\mathbf t : \mathbf J_1\mathbf t \in
  \operatorname{range}\mathbf J_{2p}\} = \mathcal N(\mathbf A_p)`: the passive joints alone realise
  them, so the robot makes them with every motor stopped -- the motors can neither produce nor
  prevent them (a push, a slope or inertia decides).  :math:`\mathbf A_p` is
  :func:`~wmr.analysis.mobility.twist_constraints` with only the passive columns free.
  :math:`\mathcal U \subseteq \mathcal T`.
* The **actuated mobility** :math:`\delta_a = \dim\mathcal T - \dim\mathcal U =
  \operatorname{rank}\mathbf A_p - \operatorname{rank}\mathbf A`: the dimension of the twists the
  motors command (the motor rates determine the twist up to :math:`\mathcal U`).

Example by hand: four mecanum wheels of the same hand, rollers at :math:`\gamma` to axles along y.
A Swedish wheel's one constraint is :math:`\mathbf a_i^T\mathbf v_i = -r\sin\gamma\,\dot\theta_i`
(:class:`wmr.SwedishWheel`), with the same roller axis :math:`\mathbf a` on every wheel, so the map
from the twist to the motor rates has the rows :math:`[\mathbf a^T\mathbf E\mathbf d_i,\ a_x,\ a_y]`,
of rank 2: the translation along :math:`\mathbf E\mathbf a` needs every motor at zero
(:math:`\dim\mathcal U = 1`), and :math:`\delta_a = 3 - 1 = 2`.  With the X pattern the rows have
rank 3 and :math:`\delta_a = 3`.

A twist :math:`\mathbf t\in\mathcal T` is **commanded** by the motors when it has no component in
:math:`\mathcal U` (orthogonal projection in the dimensionless coordinates of
:mod:`wmr.model.tolerance`): otherwise part of it is a motion that needs a passive joint to move
by itself (:func:`uncontrolled`; :func:`wmr.inverse` then calls it not admissible).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

import numpy as np

from ..errors import InputValueError
from ..io.decimals import quantise
from ..model import validation
from ..model.platform import line_angle
from ..model.tolerance import TOL
from ._batch import for_chunks
from .linalg import null_space, rank
from .lines import AT_INFINITY, FINITE
from .mobility import twist_constraints
from .sv_decisions import rank_from_singular_values

__all__ = ["actuated_mobility", "free_twists", "uncontrolled", "MotionKind", "Motion"]


def driven_columns(robot) -> np.ndarray:
    """Which rate columns of :math:`\\mathbf J_2` a motor drives (n_rates,), in the order of :attr:`wmr.Robot.rate_names`."""
    return np.array([j.driven for u in robot.wheels for j in u.joints if j.rate is not None], dtype=bool)


def _scale(robot):
    return robot.F_column_norms[:3]  # the twist columns of F: the dimensionless coordinates


def actuated_mobility(robot, beta) -> np.ndarray:
    r"""The actuated mobility :math:`\delta_a = \operatorname{rank}\mathbf A_p - \operatorname{rank}\mathbf A`, batched.

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)
        Steering angles (radians).

    Returns
    -------
    numpy.ndarray of int (...)
        From 0 to 3; the dimension of the admissible twists the motors command.

    Examples
    --------
    >>> import wmr
    >>> same = wmr.Robot([wmr.SwedishWheel(p, r=0.05, angle=np.pi / 2, roller=np.pi / 4)
    ...                   for p in [(0.25, 0.2), (0.25, -0.2), (-0.25, 0.2), (-0.25, -0.2)]])
    >>> int(actuated_mobility(same, np.zeros(4))), wmr.admissible_twists(same, np.zeros(4)).shape[1]
    (2, 3)
    """
    robot = validation.numeric_robot(robot)
    A, _ = twist_constraints(robot, beta)
    Ap, _ = twist_constraints(robot, beta, free=~driven_columns(robot))
    s = _scale(robot)
    ra = rank(A, scale=s) if A.shape[-2] else np.zeros(A.shape[:-2], dtype=int)
    rp = rank(Ap, scale=s) if Ap.shape[-2] else np.zeros(Ap.shape[:-2], dtype=int)
    return np.asarray(rp - ra)


def free_twists(robot, beta) -> np.ndarray:
    r"""Orthonormal basis (3, m) of :math:`\mathcal U(\boldsymbol\beta)`: the twists made with every motor stopped.

    Orthonormal in the dimensionless coordinates :math:`\hat{\mathbf t} = \mathbf t\circ\mathbf s`
    (``s`` the twist columns of :attr:`wmr.Robot.F_column_norms`), returned in physical units
    (:math:`\mathbf t = \hat{\mathbf t}/\mathbf s`).

    Parameters
    ----------
    robot : Robot
    beta : array (w,)
        One configuration.

    Returns
    -------
    numpy.ndarray (3, m)

    Examples
    --------
    >>> import wmr
    >>> omni = wmr.Robot([wmr.SwedishWheel(p, r=0.05, angle=np.pi / 2, roller=np.pi / 2)
    ...                   for p in [(0.25, 0.2), (0.25, -0.2), (-0.25, 0.2), (-0.25, -0.2)]])
    >>> u = free_twists(omni, np.zeros(4))           # parallel omni wheels: they roll sideways freely
    >>> (np.abs(u[:, 0]) / np.abs(u[:, 0]).max()).round(12).tolist()
    [0.0, 0.0, 1.0]
    """
    robot = validation.numeric_robot(robot)
    beta = robot.effective_beta(beta)
    if beta.ndim != 1:
        raise InputValueError(
            f"beta must be one configuration of shape ({robot.w},) for free_twists, got shape {beta.shape}"
        )
    Ap, _ = twist_constraints(robot, beta, free=~driven_columns(robot))
    s = _scale(robot)
    if Ap.shape[0] == 0:
        return np.diag(1.0 / s)
    return null_space(Ap / s, scale=np.ones(3)) / s[:, None]


def uncontrolled(robot, beta, twist) -> tuple[np.ndarray, np.ndarray]:
    r"""The part of each twist in :math:`\mathcal U`, and whether the motors command the twist (batched).

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)
    twist : array (..., 3)
        :math:`[\dot\psi, \dot x, \dot y]`, body frame.

    Returns
    -------
    part : numpy.ndarray (..., 3)
        The orthogonal projection of the twist on :math:`\mathcal U` (dimensionless coordinates),
        in physical units: the motion the motors leave to the passive joints.
    commanded : numpy.ndarray of bool (...)
        ``part`` is zero: :math:`\|\hat{\mathbf t}_{\mathcal U}\| \le \mathrm{TOL}\,\|\hat{\mathbf t}\|`.

    Examples
    --------
    >>> import wmr
    >>> omni = wmr.Robot([wmr.SwedishWheel(p, r=0.05, angle=np.pi / 2, roller=np.pi / 2)
    ...                   for p in [(0.25, 0.2), (0.25, -0.2), (-0.25, 0.2), (-0.25, -0.2)]])
    >>> part, ok = uncontrolled(omni, np.zeros(4), [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 1.0]])
    >>> ok.tolist(), (part[2].round(12) + 0.0).tolist()
    ([True, False, False], [0.0, 0.0, 1.0])
    """
    robot = validation.numeric_robot(robot)
    beta = robot.effective_beta(beta)
    t = validation.twist_array("twist", twist)
    batch = validation.batch_shape({"beta": beta, "twist": t})
    s = _scale(robot)
    # the dimensionless twist t o s, scaled to a largest entry of 1 (the decision does not depend on the
    # twist's size; nothing overflows however large the robot or the twist)
    mt = np.abs(t).max(axis=-1, keepdims=True)
    h = np.broadcast_to(t / np.where(mt > 0, mt, 1.0), batch + (3,)) * s
    mh = np.abs(h).max(axis=-1, keepdims=True)
    that = h / np.where(mh > 0, mh, 1.0)
    free = ~driven_columns(robot)
    if not free.any() and rank(robot.J1() / s) == 3:  # every joint driven: the motors hold every twist
        part_hat = np.zeros(batch + (3,))
    else:
        flat_beta = np.broadcast_to(beta, batch + (robot.w,)).reshape(-1, robot.w)
        flat_that = that.reshape(-1, 3)
        out = np.empty_like(flat_that)

        def chunk(a, z):
            Ap, _ = twist_constraints(robot, flat_beta[a:z], free=free)
            if Ap.shape[-2] == 0:
                out[a:z] = flat_that[a:z]
                return
            Ah = Ap / s
            full = Ah.shape[-2] < 3  # right vectors (k, 3, 3) either way; no (k, rows, rows) left ones
            _, sv, Vt = np.linalg.svd(Ah, full_matrices=full)
            null = np.arange(3) >= rank_from_singular_values(sv)[:, None]  # rows of Vt beyond the rank
            coef = np.einsum("...ij,...j->...i", Vt, flat_that[a:z]) * null
            out[a:z] = np.einsum("...ij,...i->...j", Vt, coef)

        for_chunks(chunk, flat_beta.shape[0], max(64, 2**17 // robot.w))  # (chunk, rows, 3): a few MB
        part_hat = out.reshape(batch + (3,))
    commanded = np.linalg.norm(part_hat, axis=-1) <= TOL * np.linalg.norm(that, axis=-1)
    with np.errstate(over="ignore"):  # (for display: a part beyond 1e308 is inf)
        part = part_hat / s * mh * mt
    return part, commanded


class MotionKind(enum.Enum):
    """How a twist moves the robot (:class:`Motion`)."""

    STILL = "still"  #: the zero twist
    TRANSLATION = "translation"  #: along a line (the centre beyond the robot's size / TOL)
    SPIN = "spin"  #: about C (the centre within 1e-3 of the robot's size of C)
    TURN = "turn"  #: about another point


@dataclass(frozen=True)
class Motion:
    """Where a twist moves the robot (:func:`motion`; in words: :func:`wmr.words.limitations.where`).

    Attributes
    ----------
    kind : MotionKind
    twist : tuple of float
        :math:`[\\dot\\psi, \\dot x, \\dot y]`, body frame; only its direction matters (either sign).
    heading : float or None
        A translation's line of travel, degrees from x in (-90, 90] (either way along it; within TOL of -90
        is 90: :func:`wmr.model.platform.line_angle`).
    centre : tuple of float or None
        A spin's or a turn's centre (x, y), body frame, a coordinate within round-off of 0 written 0.
    """

    kind: MotionKind
    twist: tuple[float, ...]
    heading: float | None = None
    centre: tuple[float, ...] | None = None


def motion(robot, twist) -> Motion:
    """Where a twist (3,) moves the robot: a translation, a spin about C, a turn about another point, or nowhere.

    The robot's size (its farthest mount point from C) decides what is a translation
    (:func:`wmr.instantaneous_centre` with that length) and a spin.
    """
    from .steering import instantaneous_centre

    robot = validation.numeric_robot(robot)
    t = validation.twist_array("twist", twist)
    size = float(np.abs(robot.mount_points).max()) or 1.0
    ic = instantaneous_centre(t, length=size)
    tw = tuple(float(v) for v in t)
    if int(ic.kind) == AT_INFINITY:
        line = line_angle(np.arctan2(t[2], t[1]))  # a line, either way: (-90, 90] deg, -90 within TOL is 90
        return Motion(MotionKind.TRANSLATION, tw, heading=float(np.degrees(line)))
    if int(ic.kind) != FINITE:
        return Motion(MotionKind.STILL, tw)
    x, y = (float(v) for v in quantise(ic.point, size))  # round-off of a zero coordinate (6e-17) written 0
    spin = np.hypot(x, y) <= 1e-3 * size
    return Motion(MotionKind.SPIN if spin else MotionKind.TURN, tw, centre=(x, y))
