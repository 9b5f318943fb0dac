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
from ..model.platform import cos_sin, rotated
from ..model.tolerance import TOL
from ._batch import for_chunks
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


@dataclass(frozen=True)
class _UnitConstants:
    """What the kernels need of one unit: its rows of J1, L_i, E L_i, L_i^+ (numbers), rate slice."""

    J1: np.ndarray              # (2, 3): [E d_i 1] (5)
    L: np.ndarray
    EL: np.ndarray
    Lp: np.ndarray
    rates: slice
    dual: float | None          # 2 b / r for a dual wheel


def _constants(robot):
    r"""The constants of forward and inverse kinematics, from the model (once per call, not per configuration).

    Returns ``(units, pinv_J1, full_rank)``: a :class:`_UnitConstants` per unit,
    :math:`\mathbf J_1^+` (3, 2w), and whether :math:`\mathbf J_1` has rank 3.
    """
    J1 = robot.J1(backend=NUMERIC)
    units = []
    for i, (u, sl) in enumerate(zip(robot.wheels, robot.rate_slices)):
        L, EL = (np.asarray(m, dtype=float) for m in u.block_terms(NUMERIC))   # B = cos L + sin E L
        units.append(_UnitConstants(J1[2 * i:2 * i + 2], L, EL, pinv_columns(L), sl,
                                    2 * u.b / u.r if u.kind == "dual" else None))
    # J1's psi_dot column is a length, the others pure numbers: rank and pseudo-inverse with the
    # columns scaled (wmr.model.tolerance), so a robot 1e300 or 1e-300 in size is still determined
    return tuple(units), pinv_columns(J1), bool(rank(J1) == 3)


def _lin(coefs, xs):
    """``sum_j coefs[j] * xs[j]`` over the non-zero coefficients (``None`` when all are zero)."""
    acc = None
    for a, x in zip(coefs, xs):
        if a == 0.0 or x is None:
            continue
        term = x * a
        acc = term if acc is None else np.add(acc, term, out=acc)
    return acc


def _rot(c, s, x, y):
    """``c x + s y`` for two rows of a chunk (either may be ``None``, a zero row), through
    :func:`~wmr.model.platform.rotated`: with ``y`` the image under E of ``x``, this is (11)."""
    if x is None or y is None:
        return None if x is None and y is None else (c * x if y is None else s * y)
    return rotated((c, s), x, y, axes=0)


def _block_times(c, s, u, cols):
    r"""The wheel block applied to the unit's rates: :math:`\mathbf B_i\dot{\boldsymbol\theta}_i =
    \cos\beta_i\,\mathbf L_i\dot{\boldsymbol\theta}_i + \sin\beta_i\,\mathbf E\mathbf L_i\dot{\boldsymbol\theta}_i`,
    a pair of (k,) arrays (x and y rows; ``None`` for a zero row)."""
    return [_rot(c, s, _lin(Lrow, cols), _lin(ELrow, cols)) for Lrow, ELrow in zip(u.L, u.EL)]


def _max_abs(acc, xs):
    """Running element-wise maximum of ``|x|`` over the arrays ``xs`` (``None`` entries skipped)."""
    for x in xs:
        if x is not None:
            acc = np.abs(x) if acc is None else np.maximum(acc, np.abs(x), out=acc)
    return acc


def _admissible(res_max, term_max, k):
    """``max|res| <= TOL * max|terms|``, the (relative) rule of near_zero, per configuration."""
    if res_max is None:
        return np.ones(k, dtype=bool)
    big = np.zeros(k) if term_max is None else term_max
    return res_max <= TOL * big


def _finite(name, given, *results):
    """Overflow is detected, not propagated: finite input must give finite results."""
    if not all(np.isfinite(r).all() for r in results):
        raise ValueError(f"{name} is too large: the kinematics overflow double precision "
                         f"(largest |{name}| = {np.abs(given).max():.3g})")


def _flat(batch, *arrays):
    """Broadcast arrays ``(..., k_j)`` to a common batch and flatten it: (N, k_j) each."""
    return [np.broadcast_to(a, batch + a.shape[-1:]).reshape(-1, a.shape[-1]) for a in arrays]


def _columns(X, a, b):
    """Rows ``a .. b-1`` of ``X (N, m)`` as m contiguous (b - a,) arrays."""
    return list(np.ascontiguousarray(X[a:b].T))


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

    Notes
    -----
    :math:`\mathbf J_1^+` is computed once per robot; the batch is processed in chunks on all
    cores, and :math:`\mathbf J_2` is never formed: unit :math:`i` contributes
    :math:`\cos\beta_i\,\mathbf L_i\dot{\boldsymbol\theta}_i + \sin\beta_i\,\mathbf E\mathbf L_i\dot{\boldsymbol\theta}_i`.

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
    units, pinv, full_rank = _constants(robot)
    if not full_rank:
        raise ValueError(
            f"robot has J1 of rank < 3 (fewer than two distinct mount points: {robot.mount_points.tolist()}): "
            "the twist is not determined")
    batch = V.batch_shape({"beta": beta, "rates": rates})
    b, th = _flat(batch, beta, rates)
    N, w = b.shape[0], robot.w
    t, res, adm = np.empty((N, 3)), np.empty((N, 2 * w)), np.empty(N, dtype=bool)

    @np.errstate(over="ignore", invalid="ignore")      # (per thread: the chunks run on the pool)
    def chunk(a, z):
        c, s = cos_sin(np.ascontiguousarray(b[a:z].T))
        cols = _columns(th, a, z)
        rhs = []                                            # J2 theta_dot (21), unit by unit
        for i, u in enumerate(units):
            rhs += _block_times(c[i], s[i], u, cols[u.rates])
        tw = [_lin(P_row, rhs) for P_row in pinv]           # t = J1^+ J2 theta_dot
        tw = [np.zeros(z - a) if x is None else x for x in tw]
        t[a:z] = np.stack(tw, axis=1)
        big = worst = None
        for i, u in enumerate(units):                       # J1 t - J2 theta_dot: [E d_i 1] t - B_i theta_i
            vx, vy = (_lin(row, tw) for row in u.J1)
            rx = vx if rhs[2 * i] is None else np.subtract(vx, rhs[2 * i], out=vx)
            ry = vy if rhs[2 * i + 1] is None else np.subtract(vy, rhs[2 * i + 1], out=vy)
            res[a:z, 2 * i], res[a:z, 2 * i + 1] = rx, ry
            worst = _max_abs(worst, (rx, ry))
            big = _max_abs(big, rhs[2 * i:2 * i + 2])
        adm[a:z] = _admissible(worst, big, z - a)

    for_chunks(chunk, N)
    _finite("rates", rates, t, res)
    return Solution(t.reshape(batch + (3,)), res.reshape(batch + (2 * w,)), adm.reshape(batch))


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

    Notes
    -----
    Per unit, :math:`\dot{\boldsymbol\theta}_i = \mathbf L_i^+\mathbf R(\beta_i)^T\mathbf v_i` with
    :math:`\mathbf v_i = [\mathbf E\mathbf d_i\ \mathbf 1]\mathbf t` (5) and
    :math:`\mathbf R^T\mathbf v = (\cos\beta\,v_x + \sin\beta\,v_y,\ \cos\beta\,v_y - \sin\beta\,v_x)`;
    the :math:`\mathbf L_i^+` are computed once per robot and the batch is processed in chunks.

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
    arrays = [beta, twist]
    if beta_dot is not None:
        arrays.append(V.finite_array("beta_dot", beta_dot, last=robot.w))
    units, _, _ = _constants(robot)
    w = robot.w
    batch = V.batch_shape(dict(zip(("beta", "twist", "beta_dot"), arrays)))
    flat = _flat(batch, *arrays)
    b, tw, bd = flat[0], flat[1], (flat[2] if beta_dot is not None else None)
    N = b.shape[0]
    rates, res, adm = np.empty((N, robot.n_rates)), np.empty((N, 2 * w)), np.empty(N, dtype=bool)

    @np.errstate(over="ignore", invalid="ignore")      # (per thread: the chunks run on the pool)
    def chunk(a, z):
        c, s = cos_sin(np.ascontiguousarray(b[a:z].T))
        t = _columns(tw, a, z)
        psi = t[0]
        big = worst = None
        for i, u in enumerate(units):
            vx, vy = (_lin(row, t) for row in u.J1)         # (5): v_i = [E d_i 1] t
            # R(beta_i)^T v_i = (c v_x + s v_y, c v_y - s v_x) = R(-beta_i) v_i (11)
            lx, ly = _rot(c[i], s[i], vx, vy), _rot(c[i], s[i], vy, -vx)
            th = [_lin(row, (lx, ly)) for row in u.Lp]      # L_i^+ R^T v_i
            th = [np.zeros(z - a) if x is None else x for x in th]
            if u.dual is not None:
                # free differential rate fixed by the steering wanted: phi_dot = psi_dot + beta_dot,
                # theta_1 - theta_2 = -(2b/r) phi_dot
                half = 0.5 * u.dual * (psi if bd is None else psi + bd[a:z, i])
                th[0] -= half
                th[1] += half
            for j, x in enumerate(th):
                rates[a:z, u.rates.start + j] = x
            bx, by = _block_times(c[i], s[i], u, th)        # B_i theta_i
            rx = vx - bx if bx is not None else vx.copy()   # J1 t - J2 theta_dot
            ry = vy - by if by is not None else vy.copy()
            res[a:z, 2 * i], res[a:z, 2 * i + 1] = rx, ry
            worst = _max_abs(worst, (rx, ry))
            big = _max_abs(big, (vx, vy))
        adm[a:z] = _admissible(worst, big, z - a)

    for_chunks(chunk, N)
    _finite("twist", twist, rates, res)
    return Solution(rates.reshape(batch + (robot.n_rates,)), res.reshape(batch + (2 * w,)), adm.reshape(batch))
