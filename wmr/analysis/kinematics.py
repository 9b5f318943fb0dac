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

from dataclasses import dataclass

import numpy as np

from ..model import validation as V
from ..model.backend import NUMERIC
from ..model.platform import E, rotated
from ..model.tolerance import near_zero
from .linalg import pinv_columns, rank

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
        Residual is zero within :data:`~wmr.model.tolerance.TOL` (relative to the size of the terms).
    """

    value: np.ndarray
    residual: np.ndarray
    admissible: np.ndarray


def _mul(X, M):
    """``X @ M`` for a batch of row vectors ``X (..., k)`` and a small constant ``M (k, m)``.

    (``einsum`` instead of ``@``: BLAS is slow for such thin products on long batches.)
    """
    return np.einsum("...k,km->...m", X, M)


def _unit_velocities(robot, twist):
    # (5): [E d_i 1] t for every unit, shape (..., w, 2)
    J1 = robot.J1()
    v = _mul(twist, J1.T)                             # (..., 2w)
    return v.reshape(v.shape[:-1] + (robot.w, 2))


def _finite(name, given, *results):
    """Overflow is detected, not propagated: finite input must give finite results."""
    if not all(np.isfinite(r).all() for r in results):
        raise ValueError(f"{name} is too large: the kinematics overflow double precision "
                         f"(largest |{name}| = {np.abs(given).max():.3g})")


@np.errstate(over="ignore", invalid="ignore")        # overflow is checked on the results (_finite)
def forward(robot, beta, rates):
    r"""Platform twist from joint rates (least squares on (21)).

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)
        Steering angles.
    rates : array (..., n_rates)
        Joint rates :math:`\dot{\boldsymbol\theta}` in the order of :attr:`Robot.rate_names`.

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
    robot = V.numeric_robot(robot)
    beta = V.finite_array("beta", beta, last=robot.w)
    rates = V.finite_array("rates", rates, last=robot.n_rates)
    J1 = robot.J1()
    if int(rank(J1)) < 3:                              # columns of different units: scaled (tolerance.py)
        raise ValueError(
            f"J1 has rank < 3 (fewer than two distinct mount points: {robot.mount_points.tolist()}): "
            "the twist is not determined")
    batch = np.broadcast_shapes(beta.shape[:-1], rates.shape[:-1])
    rhs = np.empty(batch + (robot.w, 2))              # J2 theta_dot, unit by unit (no J2 formed)
    for i, (u, sl) in enumerate(zip(robot.wheels, robot.rate_slices)):
        L, EL = u.block_terms(NUMERIC)                # B_i theta_i = R(beta_i) L theta_i (11)
        th = rates[..., sl]
        rhs[..., i, :] = rotated(beta[..., i], _mul(th, L.T), _mul(th, EL.T), axes=1)
    rhs = rhs.reshape(batch + (2 * robot.w,))         # (..., 2w)
    t = _mul(rhs, pinv_columns(J1).T)                # (..., 3)
    res = _mul(t, J1.T) - rhs
    _finite("rates", rates, t, res)
    scale = np.max(np.abs(rhs), axis=-1)
    return Solution(t, res, np.all(near_zero(res, scale[..., None]), axis=-1))


@np.errstate(over="ignore", invalid="ignore")
def inverse(robot, beta, twist, beta_dot=None):
    r"""Joint rates that realise a platform twist (unit by unit, exact or least squares).

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)
        Steering angles.
    twist : array (..., 3)
        :math:`[\dot\psi, \dot x, \dot y]`, body frame.
    beta_dot : array (..., w), optional
        Wanted steering rates of dual-wheel units (their wheel-rate difference steers them, the
        corrected (15)); default 0, i.e. the unit keeps its angle on the platform.  Ignored
        for other units (offset wheels' steering rate follows from the twist; centred wheels
        steer independently).

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
    """
    robot = V.numeric_robot(robot)
    beta = V.finite_array("beta", beta, last=robot.w)
    twist = V.finite_array("twist", twist, last=3)
    if beta_dot is not None:
        beta_dot = V.finite_array("beta_dot", beta_dot, last=robot.w)
    v = _unit_velocities(robot, twist)
    batch = np.broadcast_shapes(beta.shape[:-1], v.shape[:-2])
    v = np.broadcast_to(v, batch + v.shape[-2:])
    beta = np.broadcast_to(beta, batch + beta.shape[-1:])
    rates = np.zeros(batch + (robot.n_rates,))
    res = np.zeros(batch + (robot.w, 2))
    Emat = E(NUMERIC)
    for i, (u, sl) in enumerate(zip(robot.wheels, robot.rate_slices)):
        L, EL = u.block_terms(NUMERIC)                 # B_i = R(beta_i) L (11)
        c, s = np.cos(beta[..., i]), np.sin(beta[..., i])
        vi = v[..., i, :]
        local_v = rotated((c, -s), vi, _mul(vi, Emat.T), axes=1)              # R^T [E d 1] t = R(-beta) v
        th = _mul(local_v, pinv_columns(L).T)                                  # L^+ R^T v
        if u.kind == "dual":
            # free differential rate fixed by the steering wanted: phi_dot = psi_dot + beta_dot
            bd = 0.0 if beta_dot is None else beta_dot[..., i]
            diff = -(2 * u.b / u.r) * (twist[..., 0] + bd)                  # theta_1 - theta_2
            th = th + 0.5 * np.stack([diff, -diff], axis=-1)
        rates[..., sl] = th
        res[..., i, :] = rotated((c, s), _mul(th, L.T), _mul(th, EL.T), axes=1) - vi   # B_i theta_i - [E d_i 1] t
    res = -res.reshape(batch + (2 * robot.w,))                             # J1 t - J2 theta_dot
    _finite("twist", twist, rates, res)
    scale = np.max(np.abs(v), axis=(-2, -1))
    return Solution(rates, res, np.all(near_zero(res, scale[..., None]), axis=-1))
