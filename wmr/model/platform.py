r"""Platform kinematics: the rigid platform, its twist and the rows :math:`[\mathbf{E d}_i\ \mathbf{1}]`.

The platform's twist is :math:`\mathbf t = [\dot\psi\ \ \dot{\mathbf c}^T]^T` (4), with
:math:`\dot{\mathbf c} = [\dot x\ \dot y]^T` expressed in the body frame :math:`\mathcal B`.
The velocity of a platform point :math:`P_i` with :math:`\mathbf d_i = \overrightarrow{CP_i}` is

.. math::

    \dot{\mathbf p}_i = \dot{\mathbf c} + \dot\psi\,\mathbf E\mathbf d_i
    = [\mathbf E\mathbf d_i\ \ \mathbf 1]\,\mathbf t ,\qquad
    \mathbf E = \begin{bmatrix} 0 & -1\\ 1 & 0\end{bmatrix}

(equations (2), (3) and (5) of the paper).
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from ..errors import InputTypeError, InputValueError
from .backend import NUMERIC, Backend, choose
from .checks import (
    batch_shape,
    finite_array,
    integer,
    number,
    point,
    positive,
    real,
    show,
    symbolic_matrix,
    twist_array,
)
from .lazysympy import is_sympy
from .tolerance import TOL
from .types import ArrayLike, FloatArray, Matrix, Numbers, Point, TwistLike

__all__ = [
    "E",
    "rotation",
    "rotated",
    "wrap_angle",
    "line_angle",
    "point_row",
    "point_velocity",
]


def E(backend: Backend = NUMERIC) -> Matrix:
    r"""The counter-clockwise quarter turn :math:`\mathbf E` (3): :math:`\mathbf E\mathbf v = \mathbf k\times\mathbf v`.

    Parameters
    ----------
    backend : NUMERIC or SYMBOLIC, optional

    Returns
    -------
    numpy.ndarray (2, 2) or sympy.Matrix (2, 2)

    Examples
    --------
    >>> E().tolist()
    [[0.0, -1.0], [1.0, 0.0]]
    """
    return choose(backend=backend).matrix([[0, -1], [1, 0]])


def rotation(angle: Numbers, backend: Backend = NUMERIC) -> Matrix:
    r"""Rotation matrix through ``angle`` (11): :math:`\mathbf R_{bwi}` when ``angle`` is :math:`\beta_i`.

    Parameters
    ----------
    angle : float, array (...) or sympy.Expr
        Counter-clockwise angle, radians.
    backend : NUMERIC or SYMBOLIC, optional

    Returns
    -------
    numpy.ndarray (..., 2, 2) or sympy.Matrix (2, 2)

    Examples
    --------
    >>> (rotation(np.pi / 2).round(12) + 0.0).tolist()
    [[0.0, -1.0], [1.0, 0.0]]
    >>> rotation(np.zeros(5)).shape
    (5, 2, 2)
    """
    backend = choose(backend=backend)
    angle = finite_array("angle", angle) if backend is NUMERIC else real("angle", angle)
    c, s = backend.cos(angle), backend.sin(angle)
    return backend.matrix([[c, -s], [s, c]])


def rotated(beta: Numbers, M: Matrix, EM: Matrix, axes: int = 2, backend: Backend | None = None) -> Matrix:
    r"""A block rotated by :math:`\beta`: :math:`\cos\beta\,\mathbf M + \sin\beta\,\mathbf E\mathbf M`, batched.

    The rotation (11) is linear in :math:`(\cos\beta, \sin\beta)`,
    :math:`\mathbf R(\beta) = \cos\beta\,\mathbf 1 + \sin\beta\,\mathbf E`, so every wheel block
    :math:`\mathbf B_i = \mathbf R_{bwi}\mathbf L_i` (20), (21) and any constant linear image of it is
    evaluated from two constant blocks, with no batched 2x2 product.
    :math:`\mathbf R(\beta)^T = \mathbf R(-\beta)` is ``rotated((cos, -sin), M, EM)``.

    Parameters
    ----------
    beta : array (...), sympy.Expr, or pair (cos_beta, sin_beta) of arrays (...)
        The angle, or its cosine and sine when the caller already has them.
    M, EM : array (..., \*block) or sympy.Matrix
        The block and its image :math:`\mathbf E\mathbf M` (or the same linear image of both);
        broadcast against ``beta``.
    axes : int, optional
        Number of trailing axes of ``M`` that form one block (2 for matrices, 1 for vectors).
    backend : NUMERIC or SYMBOLIC, optional
        Default: SymPy if ``beta`` is symbolic.

    Returns
    -------
    numpy.ndarray (..., \*block) or sympy.Matrix

    Examples
    --------
    >>> L = np.array([[0.0], [-2.0]])                       # a centred wheel's local block (51)
    >>> (rotated(np.pi / 2, L, E() @ L).round(12) + 0.0).tolist()   # R(pi/2) L
    [[2.0], [0.0]]
    >>> rotated(np.zeros(4), L, E() @ L).shape
    (4, 2, 1)
    """
    checked = False
    if isinstance(beta, tuple):  # (cos, sin) from the caller: the kernels' inner loops
        c, s = beta
    else:
        bk = choose(beta, backend=backend)
        if bk is NUMERIC:
            beta, M, EM = (finite_array(n, a) for n, a in (("beta", beta), ("M", M), ("EM", EM)))
            if np.shape(M) != np.shape(EM) or np.ndim(M) < integer("axes", axes, minimum=0):
                raise InputValueError(
                    f"M and EM must be blocks of one shape with at least axes = {axes} axes, "
                    f"got shapes {np.shape(M)} and {np.shape(EM)}"
                )
            c, s = np.cos(beta), np.sin(beta)
            checked = True
        else:
            beta = real("beta", beta)
            M, EM = (symbolic_matrix(n, a) for n, a in (("M", M), ("EM", EM)))
            c, s = bk.cos(beta), bk.sin(beta)
    if isinstance(c, np.ndarray):
        index = (Ellipsis,) + (None,) * axes
        c, s = c[index], s[index]
    if not checked:
        return _combination(c, s, M, EM)
    with np.errstate(over="ignore", invalid="ignore"):
        try:
            out = _combination(c, s, M, EM)
        except ValueError:
            raise InputValueError(
                f"beta {np.shape(beta)} and the blocks M, EM {np.shape(M)} must broadcast "
                f"(beta's axes, then {axes} block axes)"
            ) from None
    if not np.isfinite(out).all():
        raise InputValueError(f"M and EM are too large: R(beta) M overflows (largest |M| = {np.abs(M).max():.3g})")
    return out


def _combination(c, s, M, EM):
    return c * M + s * EM  # (11): R(beta) M = cos(beta) M + sin(beta) E M


def wrap_angle(angle: ArrayLike) -> FloatArray:
    r"""Angles mapped to :math:`(-\pi, \pi]` (element-wise).

    Parameters
    ----------
    angle : float or array (...)
        Radians.

    Returns
    -------
    numpy.ndarray (...)

    Examples
    --------
    >>> np.degrees(wrap_angle(np.radians([180.0, -180.0, 270.0]))).round(9).tolist()
    [180.0, 180.0, -90.0]
    """
    return _wrap("angle", angle, 2 * np.pi)


def line_angle(beta: ArrayLike) -> FloatArray:
    r"""The angle of a line through the origin, in :math:`(-\pi/2, \pi/2]` (``beta`` and ``beta + pi``: one line).

    Parameters
    ----------
    beta : float or array (...)
        Radians.

    Returns
    -------
    numpy.ndarray (...)

    Examples
    --------
    >>> np.degrees(line_angle(np.radians([-90.0, 135.0, 180.0]))).round(9).tolist()
    [90.0, -45.0, 0.0]
    """
    return _wrap("beta", beta, np.pi)


def _wrap(name, angle, period):
    """Angles mapped to (-period/2, period/2] (within TOL of -period/2 counts as +period/2)."""
    w = np.mod(finite_array(name, angle) + period / 2, period) - period / 2
    return np.where(np.isclose(w, -period / 2, atol=TOL, rtol=0), period / 2, w)


def point_row(d: Point, L: Numbers = 1, backend: Backend | None = None) -> Matrix:
    r"""The 2x3 block :math:`[\tfrac1L\mathbf E\mathbf d_i\ \ \mathbf 1]` of (5), (21) and (32).

    Maps the twist :math:`\mathbf t_L=[L\dot\psi\ \dot{\mathbf c}^T]^T` (33) (or :math:`\mathbf t`
    when ``L = 1``) to the velocity of the platform point at :math:`\mathbf d`.

    Parameters
    ----------
    d : pair (dx, dy)
        Vector from the operation point C to the point, body frame.
    L : float or sympy.Expr, optional
        Characteristic length (32); 1 gives the row of :math:`\mathbf J_1`.
    backend : NUMERIC or SYMBOLIC, optional
        Default: SymPy if ``d`` or ``L`` is symbolic.

    Returns
    -------
    numpy.ndarray (2, 3) or sympy.Matrix (2, 3)

    Examples
    --------
    >>> point_row((2.0, 0.0)).tolist()
    [[-0.0, 1.0, 0.0], [2.0, 0.0, 1.0]]
    """
    d = point("d", d)
    L = positive("L", L)
    bk = choose(*d, L, backend=backend)
    dx, dy = d
    # (5): p_dot = [E d  1] t ;  E d = [-dy, dx]
    with np.errstate(over="ignore", invalid="ignore"):
        M = bk.matrix([[-dy / L, 1, 0], [dx / L, 0, 1]])
    if bk is NUMERIC and not np.isfinite(M).all():
        raise InputValueError(f"L = {L!r} is too small for d = {show(d)}: d / L overflows")
    return M


def point_velocity(twist: TwistLike, d: ArrayLike) -> FloatArray:
    r"""Velocity :math:`\dot{\mathbf p} = \dot{\mathbf c} + \dot\psi\mathbf E\mathbf d` (2) of platform points.

    Parameters
    ----------
    twist : array (..., 3)
        :math:`[\dot\psi, \dot x, \dot y]`, body frame.
    d : array (..., 2)
        Points relative to C, body frame (broadcast against ``twist``).

    Returns
    -------
    numpy.ndarray (..., 2)

    Examples
    --------
    >>> point_velocity([1.0, 0.0, 0.0], [2.0, 0.0]).tolist()     # spin: (psi_dot k) x d
    [0.0, 2.0]
    """
    t = twist_array("twist", twist)
    d = finite_array("d", d, last=2)
    batch_shape({"twist": t, "d": d})
    with np.errstate(over="ignore", invalid="ignore"):
        v = np.stack([t[..., 1] - t[..., 0] * d[..., 1], t[..., 2] + t[..., 0] * d[..., 0]], axis=-1)
    if not np.isfinite(v).all():
        raise InputValueError(
            f"twist and d are too large: the velocity overflows "
            f"(largest |twist| = {np.abs(t).max():.3g}, "
            f"|d| = {np.abs(d).max():.3g})"
        )
    return v


def moved_points(
    points: Iterable[Point] | FloatArray, origin: Point = (0.0, 0.0), angle: Numbers = 0.0
) -> list[tuple[Numbers, Numbers]]:
    r"""Points (n, 2) of the body frame seen from another one, of origin ``origin`` and turned by ``angle`` (radians).

    :math:`\mathbf d' = \mathbf R(-\text{angle})(\mathbf d - \text{origin})`; SymPy coordinates stay SymPy
    (:meth:`wmr.Robot.moved`).
    """
    if isinstance(points, (str, bytes)) or not hasattr(points, "__iter__"):
        raise InputTypeError(f"points must be a sequence of pairs (n, 2), got {show(points)}")
    pts = [point(f"points[{k}]", p) for k, p in enumerate(points)]
    ox, oy = point("origin", origin)
    angle = number("angle", angle)
    c, s = np.cos(angle), np.sin(angle)
    out = []
    with np.errstate(over="ignore", invalid="ignore"):
        for px, py in pts:
            x, y = px - ox, py - oy
            out.append((c * x + s * y, -s * x + c * y))
    if not all(np.isfinite(float(v)) for p in out for v in p if not is_sympy(v)):
        raise InputValueError(f"origin = {show(origin)} is too far from the mount points (their coordinates overflow)")
    return out
