r"""2-D line geometry: where two lines meet, whether several are concurrent (Plücker coordinates), the circumcircle.

Part of :mod:`wmr.analysis.lines`; nothing here knows about robots.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass
from typing import Any

import numpy as np

from ...errors import InputTypeError, InputValueError
from ...model import validation
from ...model.lazysympy import is_sympy, sp
from ...model.tolerance import near_zero
from ...model.types import ArrayLike, FloatArray, IntArray, Numbers, Point

__all__ = [
    "concurrencies",
    "Meet",
    "FINITE",
    "AT_INFINITY",
    "STILL",
    "NONE",
    "COINCIDENT",
    "PARALLEL",
    "Concurrency",
    "line_intersection",
    "pair_intersections",
    "lines_concurrency",
    "circumcircle",
]


class Meet(enum.IntEnum):
    """Where lines meet, or where an instantaneous centre is (an ``int``, so it fills NumPy arrays)."""

    FINITE = 0  #: at a finite point
    AT_INFINITY = 1  #: all parallel: they meet at a point at infinity (a translation's centre)
    STILL = 2  #: no motion, no centre (instantaneous centre of a zero twist)
    NONE = 3  #: nowhere: the lines are not concurrent
    COINCIDENT = 4  #: two lines that are the same line
    PARALLEL = 5  #: two distinct parallel lines


FINITE, AT_INFINITY, STILL, NONE, COINCIDENT, PARALLEL = tuple(Meet)


def line_intersection(p1: ArrayLike, u1: ArrayLike, p2: ArrayLike, u2: ArrayLike) -> tuple[Meet, FloatArray | None]:
    r"""Intersection of the lines :math:`p_1 + s u_1` and :math:`p_2 + t u_2` (one pair).

    Parameters
    ----------
    p1, u1, p2, u2 : array (2,)
        A point and a direction of each line.

    Returns
    -------
    (Meet, numpy.ndarray (2,) or None)
        ``FINITE`` with the point, ``PARALLEL`` or ``COINCIDENT`` with None.

    Examples
    --------
    >>> kind, point = line_intersection([0, 0], [1, 0], [1, -1], [0, 1])
    >>> kind.name, point.tolist()
    ('FINITE', [1.0, 0.0])
    """
    p1, u1, p2, u2 = (
        validation.finite_array(n, a, last=2) for n, a in (("p1", p1), ("u1", u1), ("p2", p2), ("u2", u2))
    )
    for name, v in (("p1", p1), ("p2", p2), ("u1", u1), ("u2", u2)):
        if v.ndim != 1:
            raise InputValueError(f"{name} must be one point or direction of shape (2,), got shape {v.shape}")
    for name, u in (("u1", u1), ("u2", u2)):
        if not np.any(u):
            raise InputValueError(f"{name} must be a non-zero direction, got {validation.show(u)}")
    return _meet(p1, u1, p2, u2)


def _meet(p1, u1, p2, u2):
    """:func:`line_intersection` of checked points and non-zero directions (2,)."""
    n1, n2 = u1 / np.hypot(*u1), u2 / np.hypot(*u2)
    cross = n1[0] * n2[1] - n1[1] * n2[0]  # sine of the angle between the lines
    w = p2 - p1
    if near_zero(cross):
        off = n1[0] * w[1] - n1[1] * w[0]  # distance of p2 from line 1
        size = float(max(np.abs(p1).max(), np.abs(p2).max()))  # relative to where the lines are
        return (COINCIDENT, None) if near_zero(off, size) else (PARALLEL, None)
    with np.errstate(over="ignore", invalid="ignore"):
        s = (w[0] * n2[1] - w[1] * n2[0]) / cross
        point = p1 + s * n1
    if not np.isfinite(point).all():
        raise InputValueError(
            "p1, u1, p2, u2: the intersection is beyond double precision "
            f"(p1 = {validation.show(p1)}, p2 = {validation.show(p2)})"
        )
    return FINITE, point


def pair_intersections(
    points: ArrayLike, directions: ArrayLike
) -> dict[tuple[int, int], tuple[Meet, FloatArray | None]]:
    r"""All pairwise intersections :math:`D_{ij}` of lines (one configuration).

    Parameters
    ----------
    points, directions : array (w, 2)

    Returns
    -------
    dict
        ``(i, j) -> (Meet, point or None)`` for 1-based line numbers ``i < j``.
    """
    points = validation.finite_array("points", points, last=2)
    directions = validation.finite_array("directions", directions, last=2)
    if points.ndim != 2 or points.shape != directions.shape:
        raise InputValueError(
            f"points and directions must both have shape (w, 2), got {points.shape} and {directions.shape}"
        )
    if not np.all(np.any(directions != 0, axis=-1)):
        raise InputValueError(f"directions must be non-zero vectors, got {validation.show(directions)}")
    out = {}
    n = len(points)
    for i in range(n):
        for j in range(i + 1, n):
            out[(i + 1, j + 1)] = _meet(points[i], directions[i], points[j], directions[j])
    return out


@dataclass(frozen=True)
class Concurrency:
    """Where a set of lines meet (one configuration).

    Attributes
    ----------
    kind : Meet
        ``FINITE`` (all meet at ``point``), ``AT_INFINITY`` (all parallel to ``direction``) or ``NONE``.
    point : numpy.ndarray (2,) or None
    direction : numpy.ndarray (2,) or None
    residual : float
        Smallest singular value of the normalised Plücker matrix (0 when concurrent).
    """

    kind: Meet
    point: Any  # numpy.ndarray (2,) when kind is FINITE, else None
    direction: Any  # numpy.ndarray (2,) when kind is AT_INFINITY, else None
    residual: float


def lines_concurrency(points: ArrayLike, directions: ArrayLike) -> Concurrency:
    r"""Common point of lines :math:`p_k + s\,u_k` (one configuration), via the Plücker matrix.

    A point D lies on every line iff :math:`[-1, -D_y, D_x]\,[p_k\times u_k,\ u_k]^T = 0`; the
    left null vector of the :math:`3\times n` Plücker matrix gives D in homogeneous coordinates.
    The moments are divided by the largest coordinate, so the decision does not depend on the
    unit of length.  :func:`concurrencies` decides a batch.

    Parameters
    ----------
    points, directions : array (n, 2), n >= 2

    Returns
    -------
    Concurrency

    Examples
    --------
    >>> c = lines_concurrency([[1, 0], [0, 1], [-1, -1]], [[-1, 0], [0, -1], [1, 1]])
    >>> c.kind.name, (c.point.round(12) + 0.0).tolist()
    ('FINITE', [0.0, 0.0])
    """
    p = validation.finite_array("points", points, last=2)
    if p.ndim != 2:
        raise InputValueError(f"points and directions must both have shape (n, 2) with n >= 2, got {p.shape}")
    kind, point, direction, residual = concurrencies(p[None], np.asarray(directions)[None])
    k = Meet(int(kind[0]))
    return Concurrency(
        k,
        point[0] if k is FINITE else None,
        direction[0] if k is AT_INFINITY else None,
        float(residual[0]),
    )


def concurrencies(points: ArrayLike, directions: ArrayLike) -> tuple[IntArray, FloatArray, FloatArray, FloatArray]:
    r"""Where the lines :math:`p_k + s\,u_k` of each configuration of a batch meet (see :func:`lines_concurrency`).

    Parameters
    ----------
    points, directions : array (..., n, 2), n >= 2

    Returns
    -------
    kind : numpy.ndarray of int (...)
        The :class:`Meet` value (``FINITE``, ``AT_INFINITY`` or ``NONE``).
    point : numpy.ndarray (..., 2)
        The common point where ``kind`` is ``FINITE`` (zero elsewhere).
    direction : numpy.ndarray (..., 2)
        The unit direction where ``kind`` is ``AT_INFINITY`` (zero elsewhere).
    residual : numpy.ndarray (...)
        Smallest singular value of the normalised Plücker matrix (0 when concurrent).

    Examples
    --------
    >>> kind, point, _, _ = concurrencies([[[1, 0], [0, 1]], [[0, 0], [0, 1]]], [[[0, 1], [1, 0]], [[1, 0], [1, 0]]])
    >>> [Meet(int(k)).name for k in kind], point[0].tolist()
    (['FINITE', 'AT_INFINITY'], [1.0, 1.0])
    """
    p = validation.finite_array("points", points, last=2)
    u = validation.finite_array("directions", directions, last=2)
    if p.ndim < 2 or p.shape != u.shape or p.shape[-2] < 2:
        raise InputValueError(
            f"points and directions must both have shape (..., n, 2) with n >= 2, got {p.shape} and {u.shape}"
        )
    big = np.abs(u).max(axis=-1, keepdims=True)
    if np.any(big == 0):
        raise InputValueError(f"directions must be non-zero vectors, got {validation.show(u)}")
    u = u / big  # (scaled first: no overflow for huge directions)
    u = u / np.linalg.norm(u, axis=-1, keepdims=True)
    scale = np.abs(p).max(axis=(-2, -1))  # the size of the figure, in its own unit
    scale = np.where(scale > 0, scale, 1.0)
    m = (p[..., 0] * u[..., 1] - p[..., 1] * u[..., 0]) / scale[..., None]
    W = np.stack([m, u[..., 0], u[..., 1]], axis=-2)  # (..., 3, n)
    n = W.shape[-1]
    U, s, _ = np.linalg.svd(W, full_matrices=n < 3)  # U (..., 3, 3): its last column is the left null vector
    res = s[..., -1] if n >= 3 else np.zeros(W.shape[:-2])
    h = U[..., :, -1]
    none = ~near_zero(res)
    at_inf = ~none & near_zero(h[..., 0], np.abs(h[..., 1:]).max(axis=-1))
    finite = ~none & ~at_inf
    kind = np.where(none, NONE.value, np.where(at_inf, AT_INFINITY.value, FINITE.value))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # used only where finite
        point = np.stack([-h[..., 2] / h[..., 0], h[..., 1] / h[..., 0]], axis=-1) * scale[..., None]
        dirn = np.stack([-h[..., 2], h[..., 1]], axis=-1)
        dirn = dirn / np.linalg.norm(dirn, axis=-1, keepdims=True)
    return kind, np.where(finite[..., None], point, 0.0), np.where(at_inf[..., None], dirn, 0.0), res


def circumcircle(points: Numbers) -> tuple[Point, Numbers]:
    r"""Centre and radius of the circle through three points; exact for SymPy coordinates.

    .. math:: \mathbf c = \frac{1}{2\Delta}\Big[\sum_{\rm cyc}|P_a|^2(y_b - y_c),\
              \sum_{\rm cyc}|P_a|^2(x_c - x_b)\Big],\qquad
              \Delta = \sum_{\rm cyc} x_a(y_b - y_c)

    Parameters
    ----------
    points : sequence of 3 pairs
        Floats (NumPy result) or SymPy expressions (exact result).

    Returns
    -------
    centre : numpy.ndarray (2,) or tuple of 2 sympy.Expr
    radius : float or sympy.Expr

    Raises
    ------
    ValueError
        If the points are collinear.

    Examples
    --------
    >>> c, R = circumcircle([(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)])
    >>> c.tolist(), R
    ([0.0, 0.0], 1.0)
    >>> import sympy as sp
    >>> circumcircle([(-1, 0), (sp.Rational(1, 2), sp.sqrt(3) / 2), (sp.Rational(1, 2), -sp.sqrt(3) / 2)])
    ((0, 0), 1)
    """
    if isinstance(points, (str, bytes)) or not hasattr(points, "__len__") or is_sympy(points):
        raise InputTypeError(f"points must be three points (pairs), got {validation.show(points)}")
    pts = [validation.point(f"points[{k}]", q) for k, q in enumerate(points)]
    if len(pts) != 3:
        raise InputValueError(f"points must be three points, got {len(pts)}")
    if not any(is_sympy(v) for q in pts for v in q):
        size = float(np.abs(pts).max()) or 1.0  # scaled to the figure's size: no overflow, any unit
        (ux, uy), R2 = _circle([(x / size, y / size) for x, y in pts], near_zero, pts)
        centre, radius = np.array([ux, uy]) * size, float(np.sqrt(R2)) * size
        if not (np.isfinite(centre).all() and np.isfinite(radius)):
            raise InputValueError(f"points are too large: their circumcircle overflows, got {pts}")
        return centre, radius
    exact = [tuple(sp.sympify(v) for v in q) for q in points]  # ints stay exact
    (ux, uy), R2 = _circle(exact, lambda dd: sp.simplify(dd) == 0, pts)
    ux, uy = sp.radsimp(ux), sp.radsimp(uy)
    return (ux, uy), sp.sqrt(sp.radsimp((exact[0][0] - ux) ** 2 + (exact[0][1] - uy) ** 2))


def _circle(pts, is_zero, shown):
    """Centre and squared radius of the circle through three points (floats or SymPy), by the formula above."""
    (ax, ay), (bx, by), (cx, cy) = pts
    dd = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    if is_zero(dd):
        raise InputValueError(f"points are collinear: no circumcircle, got {shown}")
    a2, b2, c2 = ax**2 + ay**2, bx**2 + by**2, cx**2 + cy**2
    ux = (a2 * (by - cy) + b2 * (cy - ay) + c2 * (ay - by)) / dd
    uy = (a2 * (cx - bx) + b2 * (ax - cx) + c2 * (bx - ax)) / dd
    return (ux, uy), (ax - ux) ** 2 + (ay - uy) ** 2
