r"""The one numerical tolerance of the package, and why its decisions do not depend on units.

Every "is this zero?" decision in :mod:`wmr` (rank, nullity, mobility, admissibility of a motion,
isotropy, singularity, where an instantaneous centre is) goes through :data:`TOL`, and every one
of them compares **dimensionless** numbers: a quantity is measured against the size of the terms
it comes from, never against 1 in some unit.  Scaling every length of a robot (mount points,
radii, offsets, the characteristic length, translational rates) by any factor changes no
decision, and neither does the unit of time.

Rules
-----
Relative zero
    ``near_zero(x, scale)`` is :math:`|x| \le \mathrm{TOL}\,|\mathrm{scale}|`, where ``scale`` is
    the size of the quantities whose difference ``x`` is (for a slip residual, the wheel
    velocities; for a determinant, the Hadamard bound :math:`\prod_j\|\mathbf A\mathbf e_j\|`).
    Angles are already dimensionless: their scale is 1.
Rank (:func:`wmr.analysis.linalg.rank`)
    The columns of a matrix are first divided by their lengths (its unknowns may have any
    units: :math:`\dot\psi` in 1/s, :math:`\dot x` in m/s); a singular value :math:`\sigma` of
    the scaled matrix :math:`\hat{\mathbf A}` counts as zero when
    :math:`\sigma \le \mathrm{TOL}\,\sigma_{max}(\hat{\mathbf A})`.  The rank is therefore the
    same for :math:`\mathbf A` and :math:`\mathbf A\mathbf D` with any positive diagonal
    :math:`\mathbf D` (a change of unit of each unknown), and for :math:`c\mathbf A`.
The functional matrix (:func:`wmr.rank_F`, :func:`wmr.mobility`)
    :math:`\mathbf F = [\mathbf J_1\ -\mathbf J_2]` (24) mixes units: its :math:`\dot\psi` column is
    :math:`[\mathbf E\mathbf d_i]` (a length), the :math:`\dot x, \dot y` columns are pure numbers,
    a rolling-rate column is :math:`r_i\mathbf j_i` (a length), an offset wheel's steering column
    :math:`d_i\mathbf i_i` (a length).  Its column lengths do not depend on :math:`\boldsymbol\beta`
    (:attr:`wmr.Robot.F_column_norms`: :math:`\sqrt{\sum_i\|\mathbf d_i\|^2}`, :math:`\sqrt w`,
    :math:`\sqrt w`, :math:`r_i`, :math:`d_i`, :math:`r_i/2`), so
    :math:`\hat{\mathbf F} = \mathbf F\,\mathrm{diag}(\|\mathbf F\mathbf e_j\|)^{-1}` is a
    dimensionless matrix of the same rank whose entries are cosines and sines of the steering
    angles and ratios of the robot's lengths.  ``wmr.rank(bot.F(beta))`` ranks
    :math:`\hat{\mathbf F}` by its SVD; :func:`wmr.rank_F` ranks it through the twist constraints
    (:mod:`wmr.analysis.mobility`), with the twist columns scaled the same way.
Condition number (:func:`wmr.condition_number`)
    :math:`\kappa = \sigma_{max}/\sigma_{min}` (30) of the matrix as given (it is the paper's
    measure, made homogeneous by the characteristic length L); :math:`\kappa = \infty` when
    :math:`\sigma_{min} \le \mathrm{TOL}\,\sigma_{max}`, i.e. :math:`\kappa \ge 1/\mathrm{TOL} = 10^9`.
    Isotropy is :math:`|\kappa - 1| \le \mathrm{TOL}`.

Near-singular configurations: the angular tolerance
---------------------------------------------------
In :math:`\hat{\mathbf F}`, turning one wheel by :math:`\delta` rad away from a configuration where the
rank drops moves the smallest singular value from 0 to about :math:`g\,\delta`, :math:`g` a geometric
factor of order one, so the rank counts as singular what lies within about :math:`\mathrm{TOL}/g` rad of
it, in every unit.  On the paper's centred and dual-wheel robots the mobility flips at
:math:`2.1\times10^{-9}` to :math:`4.2\times10^{-9}` rad (:math:`g = 0.24` to :math:`0.47`, the same for
every L and r); :data:`ANGULAR_TOLERANCE` rounds this up to :math:`5\times10^{-9}` rad, far below any
real steering error and far above the round-off of the angles (:math:`\sim 10^{-16}` rad).

``TOL = 1e-9`` sits well above the round-off of the small matrices built here (about ``1e-15``
relative) and far below any physically meaningful quantity.

Examples
--------
>>> bool(near_zero(1e-12)), bool(near_zero(1e-3))
(True, False)
>>> bool(near_zero(1e-12, scale=1e-6))          # relative: 1e-12 is not small next to 1e-6
False
"""

from __future__ import annotations

import numpy as np

from ..errors import InputValueError
from .checks import finite_array
from .types import ArrayLike, BoolArray, FloatArray

__all__ = ["TOL", "near_zero"]

#: The package-wide tolerance for numerical zero, relative (see module docstring).
TOL: float = 1e-9

#: Steering-angle distance (radians) within which a configuration counts as the singular one
#: next to it (about ``TOL`` over the geometric factor of the paper's robots; see module docstring).
ANGULAR_TOLERANCE: float = 5e-9


def near_zero(x: ArrayLike, scale: ArrayLike = 1.0) -> BoolArray:
    """True where ``|x| <= TOL * |scale|`` (element-wise): ``x`` is zero next to ``scale``.

    Parameters
    ----------
    x : array_like
        Values to test.
    scale : array_like, optional
        Size of the quantities whose difference ``x`` is, in the unit of ``x``; broadcast against
        ``x``.  The default 1 is for dimensionless ``x`` (angles, cosines).  A zero scale makes
        only an exact zero count.

    Returns
    -------
    numpy.ndarray of bool
        Same shape as ``np.broadcast(x, scale)``.

    Examples
    --------
    >>> near_zero([1e-12, 1e-3], scale=[1.0, 1e7]).tolist()
    [True, True]
    """
    x = np.abs(finite_array("x", x))
    scale = finite_array("scale", scale)
    if np.any(scale < 0):
        raise InputValueError(
            f"scale must be a size (>= 0), got negative values {scale[scale < 0].ravel()[:3].tolist()}"
        )
    try:
        return x <= TOL * scale
    except ValueError:
        raise InputValueError(f"x and scale must broadcast, got shapes {x.shape} and {scale.shape}") from None


def column_norms(A: ArrayLike) -> FloatArray:
    r"""Euclidean length of every column, :math:`\|\mathbf A\mathbf e_j\|` (..., n) of (..., m, n), without overflow.

    Zero columns get 1 (dividing by it leaves them zero): ranks are decided on the matrix divided by these.
    """
    A = finite_array("A", A)
    if A.ndim < 2:
        raise InputValueError(f"A must have shape (..., m, n), got shape {A.shape}")
    big = np.max(np.abs(A), axis=-2) if A.shape[-2] else np.zeros(A.shape[:-2] + A.shape[-1:])
    safe = np.where(big > 0, big, 1.0)
    with np.errstate(over="ignore"):
        norms = np.where(big > 0, safe * np.sqrt(np.sum((A / safe[..., None, :]) ** 2, axis=-2)), 1.0)
    if not np.isfinite(norms).all():
        raise InputValueError("A is too large: its column lengths overflow double precision")
    return norms
