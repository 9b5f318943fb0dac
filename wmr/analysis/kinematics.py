r"""Forward and inverse kinematics of the assembled robot, batched over configurations.

Both problems solve (21), :math:`\mathbf J_1\mathbf t = \mathbf J_2\dot{\boldsymbol\theta}`:

* **forward** (joint rates :math:`\to` twist): :math:`\mathbf J_1` is :math:`2w\times3` and constant,
  so :math:`\mathbf t = \mathbf J_1^{+}\mathbf J_2\dot{\boldsymbol\theta}` is the least-squares twist; the
  residual :math:`\mathbf J_1\mathbf t - \mathbf J_2\dot{\boldsymbol\theta}` is the slip the wheels would
  need, zero exactly when the joint rates are compatible.
* **inverse** (twist :math:`\to` joint rates): :math:`\mathbf J_2` is block-diagonal with blocks
  :math:`\mathbf R_{bwi}\mathbf L_i`, so each unit is solved alone,
  :math:`\dot{\boldsymbol\theta}_i = \mathbf L_i^{+}\mathbf R_{bwi}^T[\mathbf E\mathbf d_i\ \mathbf 1]\mathbf t`:
  exact where :math:`\mathbf L_i` is square and invertible (offset wheel, :math:`d>0`), least squares
  otherwise (centred and dual wheels), with a residual that is zero exactly when the twist is
  admissible at these steering angles.

With isotropic Jacobians these reduce to the paper's (49)-(50) and (55)-(57).
"""

from __future__ import annotations

import contextlib
import functools
import warnings
from dataclasses import dataclass

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.backend import NUMERIC
from ..model.limits import check
from ..model.platform import rotated
from ..model.robot import Robot
from ..model.tolerance import TOL, column_norms
from ..model.types import ArrayLike, FloatArray, TwistLike
from ._batch import for_chunks
from .actuation import driven_columns, uncontrolled
from .linalg import rank

__all__ = ["Solution", "forward", "inverse"]


@dataclass(frozen=True)
class Solution:
    """Result of a kinematics solve.

    Attributes
    ----------
    value : numpy.ndarray (..., k)
        The twist (forward) or the joint rates (inverse).
    residual : numpy.ndarray (..., 2w)
        :math:`\\mathbf J_1\\mathbf t - \\mathbf J_2\\dot{\\boldsymbol\\theta}` at the solution.
    admissible : numpy.ndarray of bool (...)
        ``no_slip`` and ``actuated``: no wheel slips and the motors command the motion.
    no_slip : numpy.ndarray of bool (...)
        The residual is zero within :data:`~wmr.model.tolerance.TOL` (forward: or within the
        ``slip_tolerance`` given): no wheel slips.
    actuated : numpy.ndarray of bool (...)
        Inverse: no part of the twist is a motion the robot makes with every motor stopped, i.e.
        none needs a passive joint to move by itself (:func:`wmr.analysis.actuation.uncontrolled`).
        Forward: True (every joint rate is given).
    """

    value: np.ndarray
    residual: np.ndarray
    admissible: np.ndarray
    no_slip: np.ndarray
    actuated: np.ndarray


@dataclass(frozen=True)
class _Constants:
    r"""What the kernels need of a robot, as matrices over all units (numbers).

    ``J1`` (2w, 3); ``pinv_J1`` (3, 2w), column-scaled (:func:`pinv_columns`);
    ``L``, ``EL`` (2w, n_rates): the block diagonals of the units' :math:`\mathbf L_i` and
    :math:`\mathbf E\mathbf L_i`, so that :math:`\mathbf J_2(\boldsymbol\beta)\dot{\boldsymbol\theta}` is
    ``rotated((cos, sin), L @ theta, EL @ theta)`` with each unit's cosine and sine repeated over
    its two rows; ``Lp`` (n_rates, 2w), the block diagonal of the :math:`\mathbf L_i^+`; ``steer``,
    (unit, its rates' slice, :math:`\mathbf c_i`, :math:`\mathbf c_i^T/\mathbf c_i\mathbf c_i^T`) of each unit
    with a steering row (:meth:`~wmr.model.wheels.WheelUnit.steering_row`: a dual wheel); ``chunk``,
    configurations per chunk; ``passive``, some twist may need no motor (a passive joint, or
    :math:`\mathbf J_1` of rank < 3: :func:`~wmr.analysis.actuation.uncontrolled` decides).
    """

    J1: np.ndarray
    pinv_J1: np.ndarray
    full_rank: bool
    L: np.ndarray
    EL: np.ndarray
    Lp: np.ndarray
    steer: tuple
    chunk: int
    passive: bool


@contextlib.contextmanager
def constants_kept(robot):
    """Deprecated: a robot keeps its kinematic constants itself (it is frozen); use the robot without this block."""
    warnings.warn(
        "wmr.analysis.kinematics.constants_kept is deprecated and does nothing: a Robot is frozen and keeps "
        "its kinematic constants itself; call forward/inverse on the robot directly",
        DeprecationWarning,
        stacklevel=3,
    )
    yield


def _constants(robot):
    """The constants of forward and inverse kinematics, computed at the robot's first solve and kept on it."""
    return robot._memo("kinematics", lambda: _from_model(robot))


def _from_model(robot):
    w, n = robot.w, robot.n_rates
    check("memory_mb", 3 * 8 * 2 * w * n / 2**20, f"the kinematics of this robot ({w} wheel units, {n} rates)")
    J1 = robot.J1(backend=NUMERIC)
    L, EL, Lp = np.zeros((2 * w, n)), np.zeros((2 * w, n)), np.zeros((n, 2 * w))
    steer = []
    for i, (u, sl) in enumerate(zip(robot.wheels, robot.rate_slices)):
        L[2 * i : 2 * i + 2, sl], EL[2 * i : 2 * i + 2, sl] = u.block_terms(NUMERIC)  # B = cos L + sin E L
        Lp[sl, 2 * i : 2 * i + 2] = _pinv_rank(L[2 * i : 2 * i + 2, sl])[0]
        c = u.steering_row()  # c theta_i = psi_dot + beta_dot_i, L_i c^T = 0
        if c is not None:
            steer.append((i, sl, c, c / (c @ c)))
    # J1's psi_dot column is a length, the others pure numbers: rank and pseudo-inverse with the
    # columns scaled (wmr.model.tolerance), so a robot 1e300 or 1e-300 in size is still determined
    pinv_J1, rank_J1 = _pinv_rank(J1)
    # chunks small enough that the (2w x n) @ (n x chunk) products stay single-threaded in BLAS
    chunk = int(max(256, min(8192, 2**18 // max(1, 2 * w * max(n, 3)))))
    passive = bool((~driven_columns(robot)).any()) or rank_J1 < 3  # some motion may need no motor
    return _Constants(J1, pinv_J1, rank_J1 == 3, L, EL, Lp, tuple(steer), chunk, passive)


def _pinv_rank(M):
    """``(pinv_columns(M), rank(M))`` of a small constant matrix, remembered by its value.

    The cache by value serves robots made anew with the same units (a design search).
    """
    M = np.ascontiguousarray(M, dtype=float)
    return _pinv_rank_of(M.tobytes(), M.shape)


def pinv_columns(A: FloatArray) -> FloatArray:
    r"""Pseudo-inverse ``(n, m)`` of a finite matrix, columns scaled: :math:`\mathbf D^{-1}(\mathbf A\mathbf D^{-1})^+`.

    Singular values at most ``TOL`` times the largest are dropped (the rank rule), so for full column
    rank this is :math:`\mathbf A^+` whatever the units of the columns.
    """
    scale = column_norms(A)
    with np.errstate(over="ignore", invalid="ignore"):
        P = np.linalg.pinv(A / scale, rcond=TOL) / scale[:, None]
    _finite("A", A, P)
    return P


@functools.lru_cache(maxsize=256)
def _pinv_rank_of(data, shape):
    M = np.frombuffer(data).reshape(shape)
    P = pinv_columns(M)
    P.setflags(write=False)
    return P, int(rank(M))


def _wheel_rows(c, s):
    """Each unit's cosine and sine repeated over its two rows: (w, k) -> (2w, k) each."""
    return np.repeat(c, 2, axis=0), np.repeat(s, 2, axis=0)


def _admissible(res, terms):
    """``max|res| <= TOL * max|terms|`` per configuration (columns of (2w, k) arrays): near_zero's rule."""
    return np.abs(res).max(axis=0) <= TOL * np.abs(terms).max(axis=0)


def _finite(name, given, *results):
    """Overflow is detected, not propagated: finite input must give finite results."""
    if not all(np.isfinite(r).all() for r in results):
        raise InputValueError(
            f"{name} is too large: the kinematics overflow double precision "
            f"(largest |{name}| = {np.abs(given).max():.3g})"
        )


def _flat(batch, *arrays):
    """Broadcast arrays ``(..., k_j)`` to a common batch and flatten it: (N, k_j) each."""
    return [np.broadcast_to(a, batch + a.shape[-1:]).reshape(-1, a.shape[-1]) for a in arrays]


@np.errstate(over="ignore", invalid="ignore")  # overflow is checked on the results (_finite)
def forward(robot: Robot, beta: ArrayLike, rates: ArrayLike, slip_tolerance: float | None = None) -> Solution:
    r"""Platform twist from joint rates (least squares on (21)).

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)
        Steering angles (radians).
    rates : array (..., n_rates)
        Joint rates :math:`\dot{\boldsymbol\theta}` (rad/s) in the order of :attr:`Robot.rate_names`.
    slip_tolerance : float, optional
        A slip speed (in the unit of length per unit of time of the robot, e.g. m/s) below which
        a wheel counts as not slipping: measured rates are never exactly compatible (encoder
        resolution, rounding).  ``admissible`` is then: every unit's residual
        :math:`\|(\mathbf J_1\mathbf t - \mathbf J_2\dot{\boldsymbol\theta})_i\|` at most this.
        Default: the round-off rule of :data:`~wmr.model.tolerance.TOL` (exactly compatible rates).

    Returns
    -------
    Solution
        ``value`` is the twist :math:`[\dot\psi, \dot x, \dot y]` (..., 3), body frame.

    Raises
    ------
    ValueError
        If the mount points do not determine the twist (all coincide), or on bad input.

    Examples
    --------
    >>> from wmr.model.robots import paper_robot
    >>> bot = paper_robot("centred", L=1.0, r=0.5)
    >>> sol = forward(bot, [0.0, 0.0, 0.0], [-2.0, -2.0, -2.0])   # all wheels along x: drive along +y
    >>> (sol.value.round(12) + 0.0).tolist(), bool(sol.admissible)
    ([0.0, 0.0, 1.0], True)
    """
    robot = validation.numeric_robot(robot)
    beta = robot.effective_beta(beta)
    rates = validation.finite_array("rates", rates, last=robot.n_rates)
    if slip_tolerance is not None:
        slip_tolerance = validation.number("slip_tolerance", validation.nonnegative("slip_tolerance", slip_tolerance))
    K = _constants(robot)
    if not K.full_rank:
        raise InputValueError(
            f"robot has J1 of rank < 3 (fewer than two distinct mount points: {robot.mount_points.tolist()}): "
            "the twist is not determined"
        )
    batch = validation.batch_shape({"beta": beta, "rates": rates})
    b, th = _flat(batch, beta, rates)
    N, w = b.shape[0], robot.w
    t, res, adm = np.empty((N, 3)), np.empty((N, 2 * w)), np.empty(N, dtype=bool)

    def chunk(a, z):
        # configurations are columns here: (rows, k) arrays
        c, s = _wheel_rows(np.cos(b[a:z].T), np.sin(b[a:z].T))
        th_k = th[a:z].T
        rhs = rotated((c, s), K.L @ th_k, K.EL @ th_k, axes=0)  # J2 theta_dot = sum_i R(beta_i) L_i theta_i (21)
        t_k = K.pinv_J1 @ rhs  # t = J1^+ J2 theta_dot
        r_k = K.J1 @ t_k
        r_k -= rhs  # J1 t - J2 theta_dot
        t[a:z], res[a:z], adm[a:z] = t_k.T, r_k.T, _admissible(r_k, rhs)

    for_chunks(chunk, N, K.chunk)
    _finite("rates", rates, t, res)
    if slip_tolerance is not None:  # each unit's slip speed against the user's bound
        adm = np.hypot(res[:, 0::2], res[:, 1::2]).max(axis=1, initial=0.0) <= slip_tolerance
    return Solution(
        t.reshape(batch + (3,)),
        res.reshape(batch + (2 * w,)),
        adm.reshape(batch),
        adm.reshape(batch),
        np.ones(batch, dtype=bool),
    )


@np.errstate(over="ignore", invalid="ignore")
def inverse(robot: Robot, beta: ArrayLike, twist: TwistLike, beta_dot: ArrayLike | None = None) -> Solution:
    r"""Joint rates that realise a platform twist (unit by unit, exact or least squares).

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)
        Steering angles.
    twist : array (..., 3)
        :math:`[\dot\psi, \dot x, \dot y]`, body frame.
    beta_dot : array (..., w), optional
        Wanted steering rates of the units whose rates steer them (a dual wheel: its wheel-rate
        difference, the corrected (15); :meth:`~wmr.model.wheels.WheelUnit.steering_row`); default 0,
        i.e. the unit keeps its angle on the platform.  Ignored for other units (offset wheels' steering
        rate follows from the twist; centred wheels steer independently).

    Returns
    -------
    Solution
        ``value`` is :math:`\dot{\boldsymbol\theta}` (..., n_rates).

    Examples
    --------
    >>> from wmr.model.robots import paper_robot
    >>> bot = paper_robot("centred", L=1.0, r=0.5)
    >>> sol = inverse(bot, [0.0, 0.0, 0.0], [0.0, 0.0, 1.0])
    >>> (sol.value.round(12) + 0.0).tolist(), bool(sol.admissible)
    ([-2.0, -2.0, -2.0], True)
    >>> bool(inverse(bot, [0.0, 0.0, 0.0], [0.0, 1.0, 0.0]).admissible)   # sideways: the wheels slip
    False

    Four omni wheels with parallel axles roll sideways with every motor stopped: no slip, but the
    motors do not command that motion, so it is not admissible for them.

    >>> import wmr
    >>> omni = wmr.Robot([wmr.SwedishWheel(p, r=0.05, angle=np.pi / 2, roller=np.pi / 2)
    ...                   for p in [(0.25, 0.2), (0.25, -0.2), (-0.25, 0.2), (-0.25, -0.2)]])
    >>> sol = inverse(omni, np.zeros(4), [0.0, 0.0, 1.0])
    >>> bool(sol.admissible), bool(sol.no_slip), bool(sol.actuated)
    (False, True, False)
    >>> (sol.value.round(12) + 0.0).tolist()        # every motor at zero, the rollers turn
    [0.0, 20.0, 0.0, 20.0, 0.0, 20.0, 0.0, 20.0]
    """
    robot = validation.numeric_robot(robot)
    beta = robot.effective_beta(beta)
    twist = validation.twist_array("twist", twist)
    arrays = [beta, twist]
    if beta_dot is not None:
        arrays.append(validation.finite_array("beta_dot", beta_dot, last=robot.w))
    K = _constants(robot)
    w = robot.w
    batch = validation.batch_shape(dict(zip(("beta", "twist", "beta_dot"), arrays)))
    flat = _flat(batch, *arrays)
    b, tw, bd = flat[0], flat[1], (flat[2] if beta_dot is not None else None)
    N = b.shape[0]
    rates, res, adm = np.empty((N, robot.n_rates)), np.empty((N, 2 * w)), np.empty(N, dtype=bool)

    def chunk(a, z):
        # configurations are columns here: (rows, k) arrays
        c, s = _wheel_rows(np.cos(b[a:z].T), np.sin(b[a:z].T))
        v = K.J1 @ tw[a:z].T  # (5): v_i = [E d_i 1] t, (2w, k)
        Ev = np.empty_like(v)  # E v_i, unit by unit
        Ev[0::2], Ev[1::2] = -v[1::2], v[0::2]
        local = rotated((c, -s), v, Ev, axes=0)  # R(beta_i)^T v_i = R(-beta_i) v_i (11)
        th = K.Lp @ local  # theta_i = L_i^+ R^T v_i
        for i, sl, row, gain in K.steer:
            # the rates the block leaves free (L_i c^T = 0) set by the steering wanted: c theta_i = phi_dot_i,
            # phi_dot_i = psi_dot + beta_dot_i (a dual wheel: theta_1 - theta_2 = -(2b/r) phi_dot, corrected (15))
            phi = tw[a:z, 0] if bd is None else tw[a:z, 0] + bd[a:z, i]
            th[sl] += gain[:, None] * (phi - row @ th[sl])
        r_k = v - rotated((c, s), K.L @ th, K.EL @ th, axes=0)  # J1 t - J2 theta_dot
        rates[a:z], res[a:z], adm[a:z] = th.T, r_k.T, _admissible(r_k, v)

    for_chunks(chunk, N, K.chunk)
    _finite("twist", twist, rates, res)
    if K.passive:  # a motion with every motor stopped is not commanded
        actuated = uncontrolled(robot, b, tw)[1]
    else:  # every joint driven, J1 of rank 3: no such motion
        actuated = np.ones(N, dtype=bool)
    return Solution(
        rates.reshape(batch + (robot.n_rates,)),
        res.reshape(batch + (2 * w,)),
        (adm & actuated).reshape(batch),
        adm.reshape(batch),
        actuated.reshape(batch),
    )
