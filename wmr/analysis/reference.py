r"""Dense reference computations: the plain definitions every fast kernel is checked against.

Every matrix is formed in full from the model's definitions,
:math:`\mathbf J_2 = \mathrm{blockdiag}(\mathbf R(\beta_i)\mathbf L_i)` (11), (21),
:math:`\mathbf F = [\mathbf J_1\ -\mathbf J_2]` (24), :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` (56);
every rank and condition number comes from a full SVD with the rules of :mod:`wmr.analysis.sv_decisions`
(ranks of the matrix with unit-length columns); kinematics are pseudo-inverse solutions of the whole
system (21).  The tests and ``make bench`` compare the batched kernels with these on random, singular and
nearly singular configurations.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.backend import NUMERIC
from ..model.robot import Robot
from ..model.tolerance import column_norms, near_zero
from ..model.types import ArrayLike, BoolArray, FloatArray, IntArray, TwistLike
from .sv_decisions import kappa_from_singular_values, rank_from_singular_values

__all__ = ["J2", "F", "J", "rank", "rank_F", "det", "condition_number", "forward", "inverse"]


def J2(robot: Robot, beta: ArrayLike) -> FloatArray:
    r""":math:`\mathbf J_2(\boldsymbol\beta)`, block by block: :math:`\mathbf R(\beta_i)\mathbf L_i` (11), (21).

    A unit without a steering joint (fixed, Swedish) uses its own ``angle`` for :math:`\beta_i`.

    Parameters
    ----------
    robot : Robot
    beta : array_like (..., w)

    Returns
    -------
    numpy.ndarray (..., 2w, n_rates)
    """
    robot = validation.numeric_robot(robot)
    return _J2(robot, validation.finite_array("beta", beta, last=robot.w))


def _J2(robot, beta):
    """:func:`J2` of a numeric robot and angles (..., w) checked by the caller."""
    out = np.zeros(beta.shape[:-1] + (2 * robot.w, robot.n_rates))
    for i, (u, sl) in enumerate(zip(robot.wheels, robot.rate_slices)):
        own = u.constant_angle  # unsteered: own angle
        b = beta[..., i] if own is None else np.full(beta.shape[:-1], float(own))
        c, s = np.cos(b), np.sin(b)
        R = np.stack([np.stack([c, -s], -1), np.stack([s, c], -1)], -2)  # (11)
        out[..., 2 * i : 2 * i + 2, sl] = R @ np.asarray(u.local_block(NUMERIC), dtype=float)
    return out


def F(robot: Robot, beta: ArrayLike) -> FloatArray:
    r""":math:`\mathbf F = [\mathbf J_1\ \ -\mathbf J_2]` (24), formed in full.

    Parameters
    ----------
    robot : Robot
    beta : array_like (..., w)

    Returns
    -------
    numpy.ndarray (..., 2w, 3 + n_rates)
    """
    robot = validation.numeric_robot(robot)
    B = _J2(robot, validation.finite_array("beta", beta, last=robot.w))
    J1 = np.broadcast_to(robot.J1(), B.shape[:-2] + (2 * robot.w, 3))
    return np.concatenate([J1, -B], axis=-1)


def J(robot: Robot, beta: ArrayLike, L: float = 1.0) -> FloatArray:
    r""":math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` (56) as a matrix product.

    Parameters
    ----------
    robot : Robot
    beta : array_like (..., w)
    L : float, optional

    Returns
    -------
    numpy.ndarray (..., 3, n_rates)
    """
    robot = validation.numeric_robot(robot)
    B = _J2(robot, validation.finite_array("beta", beta, last=robot.w))
    with np.errstate(over="ignore", invalid="ignore"):
        return _finite("robot", robot.J1(L).T @ B)


def _matrices(A: ArrayLike, square: bool = False) -> FloatArray:
    A = validation.finite_array("A", A)
    if A.ndim < 2 or min(A.shape[-2:]) == 0 or (square and A.shape[-1] != A.shape[-2]):
        raise InputValueError(
            f"A must have shape (..., m, n) with m, n >= 1{' and m = n' if square else ''}, got {A.shape}"
        )
    return A


def _finite(name, *results):
    if not all(np.isfinite(r).all() for r in results):
        raise InputValueError(f"{name} is too large: the result overflows double precision")
    return results[0] if len(results) == 1 else results


def _sv(A):
    """Singular values of each matrix (checked by the caller) divided by its largest entry (the rules are scale-free)."""
    m = np.max(np.abs(A), axis=(-2, -1), keepdims=True)
    return np.linalg.svd(A / np.where(m > 0, m, 1.0), compute_uv=False)


def rank(A: ArrayLike) -> IntArray:
    """Rank from a full SVD by the package's rule.

    The columns are divided by their lengths, then the singular values above ``TOL * s_max`` counted.

    Parameters
    ----------
    A : array_like (..., m, n)

    Returns
    -------
    numpy.ndarray of int (...)
    """
    A = _matrices(A)
    return rank_from_singular_values(_sv(A / column_norms(A)[..., None, :]))


def rank_F(robot: Robot, beta: ArrayLike) -> IntArray:
    """:math:`\\operatorname{rank}\\mathbf F` from an SVD of the full matrix.

    Parameters
    ----------
    robot : Robot
    beta : array_like (..., w)

    Returns
    -------
    numpy.ndarray of int (...)
    """
    return rank(F(robot, beta))


def det(A: ArrayLike) -> FloatArray:
    """Determinant by LU (``numpy.linalg.det``).

    Parameters
    ----------
    A : array_like (..., n, n)

    Returns
    -------
    numpy.ndarray (...)
    """
    with np.errstate(over="ignore", invalid="ignore"):
        return _finite("A", np.linalg.det(_matrices(A, square=True)))


def condition_number(A: ArrayLike) -> FloatArray:
    r""":math:`\kappa = \sigma_l/\sigma_s` (30) from a full SVD, ``inf`` where the rank rule says singular.

    Parameters
    ----------
    A : array_like (..., m, n)

    Returns
    -------
    numpy.ndarray (...)
    """
    return kappa_from_singular_values(_sv(_matrices(A)))


@np.errstate(over="ignore", invalid="ignore")  # overflow is checked on the results
def forward(robot: Robot, beta: ArrayLike, rates: ArrayLike) -> tuple[FloatArray, FloatArray, BoolArray]:
    r"""Least-squares twist :math:`\mathbf t = \mathbf J_1^+\mathbf J_2\dot{\boldsymbol\theta}` and the slip.

    Parameters
    ----------
    robot : Robot
    beta : array_like (..., w)
    rates : array_like (..., n_rates)

    Returns
    -------
    twist : numpy.ndarray (..., 3)
    residual : numpy.ndarray (..., 2w)
        :math:`\mathbf J_1\mathbf t - \mathbf J_2\dot{\boldsymbol\theta}`.
    admissible : numpy.ndarray of bool (...)
    """
    robot = validation.numeric_robot(robot)
    rates = validation.finite_array("rates", rates, last=robot.n_rates)
    beta = validation.finite_array("beta", beta, last=robot.w)
    validation.batch_shape({"beta": beta, "rates": rates})
    rhs = (_J2(robot, beta) @ rates[..., None])[..., 0]
    J1 = robot.J1()
    t = (np.linalg.pinv(J1) @ rhs[..., None])[..., 0]
    res = (J1 @ t[..., None])[..., 0] - rhs
    scale = np.max(np.abs(rhs), axis=-1, keepdims=True)
    t, res = _finite("rates", t, res)
    return t, res, np.all(near_zero(res, scale), axis=-1)


@np.errstate(over="ignore", invalid="ignore")
def inverse(
    robot: Robot, beta: ArrayLike, twist: TwistLike, beta_dot: ArrayLike | None = None
) -> tuple[FloatArray, FloatArray, BoolArray]:
    r"""Joint rates from the pseudo-inverse of the whole system, the units' steering rows appended.

    Solves, in the least-squares sense, :math:`\mathbf J_2\dot{\boldsymbol\theta} = \mathbf J_1\mathbf t`
    together with one row :math:`\mathbf c_i\dot{\boldsymbol\theta}_i = \dot\psi + \dot\beta_i` per unit
    whose rates steer it (:meth:`~wmr.model.wheels.WheelUnit.steering_row`): for a dual wheel the
    corrected (15), :math:`-\tfrac{r}{2b}(\dot\theta_{i1} - \dot\theta_{i2}) = \dot\psi + \dot\beta_i`.

    Parameters
    ----------
    robot : Robot
    beta : array_like (..., w)
    twist : array_like (..., 3)
    beta_dot : array_like (..., w), optional
        Steering rates wanted of the units with a steering row (dual wheels; default 0).

    Returns
    -------
    rates : numpy.ndarray (..., n_rates)
    residual : numpy.ndarray (..., 2w)
        :math:`\mathbf J_1\mathbf t - \mathbf J_2\dot{\boldsymbol\theta}`.
    admissible : numpy.ndarray of bool (...)
    """
    robot = validation.numeric_robot(robot)
    twist = validation.twist_array("twist", twist)
    beta_dot = None if beta_dot is None else validation.finite_array("beta_dot", beta_dot, last=robot.w)
    beta = validation.finite_array("beta", beta, last=robot.w)
    validation.batch_shape({"beta": beta, "twist": twist, "beta_dot": beta_dot})
    B = _J2(robot, beta)
    v = (robot.J1() @ twist[..., None])[..., 0]
    batch = np.broadcast_shapes(B.shape[:-2], v.shape[:-1])
    rows, rhs = [np.broadcast_to(B, batch + B.shape[-2:])], [np.broadcast_to(v, batch + v.shape[-1:])]
    bd = np.zeros(robot.w) if beta_dot is None else beta_dot
    for i, (u, sl) in enumerate(zip(robot.wheels, robot.rate_slices)):
        c = u.steering_row()  # c theta_i = psi_dot + beta_dot_i, e.g. (15)
        if c is not None:
            row = np.zeros(robot.n_rates)
            row[sl] = c
            rows.append(np.broadcast_to(row, batch + (1, robot.n_rates)))
            rhs.append(np.broadcast_to(twist[..., :1] + bd[..., i : i + 1], batch + (1,)))
    A, y = np.concatenate(rows, axis=-2), np.concatenate(rhs, axis=-1)
    rates = (np.linalg.pinv(A) @ y[..., None])[..., 0]
    res = rhs[0] - (rows[0] @ rates[..., None])[..., 0]
    scale = np.max(np.abs(rhs[0]), axis=-1, keepdims=True)
    rates, res = _finite("twist", rates, res)
    return rates, res, np.all(near_zero(res, scale), axis=-1)
