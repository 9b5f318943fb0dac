r"""Kinetostatic isotropy: condition numbers (30)-(31) and isotropy tests (34)-(50).

The condition number :math:`\kappa = \sigma_l / \sigma_s` (30) of an :math:`m\times n` matrix lies in
:math:`[1, \infty]` (31); a matrix is isotropic when :math:`\kappa = 1`, i.e. when
:math:`\mathbf A^T\mathbf A` (for :math:`m\ge n`) or :math:`\mathbf A\mathbf A^T` (for :math:`m<n`) is a
multiple of the identity.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.robot import Robot
from ..model.tolerance import TOL
from ..model.types import ArrayLike, BoolArray
from .linalg import condition_number

__all__ = ["is_isotropic", "characteristic_length"]


def is_isotropic(A: ArrayLike) -> BoolArray:
    """True where the condition number equals 1 within ``TOL`` (batched).

    Parameters
    ----------
    A : array_like (..., m, n)

    Returns
    -------
    numpy.ndarray of bool (...)

    Examples
    --------
    >>> is_isotropic([[[2.0, 0.0], [0.0, 2.0]], [[2.0, 0.0], [0.0, 1.0]]]).tolist()
    [True, False]
    """
    return np.abs(condition_number(A) - 1.0) <= TOL


def characteristic_length(robot: Robot) -> float:
    r"""Characteristic length :math:`L^2 = \tfrac1w\sum_i\|\mathbf d_i\|^2` that makes :math:`\mathbf J_{L1}` best conditioned.

    With :math:`a = \sum_i\|\mathbf d_i\|^2`, :math:`\mathbf b = \sum_i\mathbf E\mathbf d_i`, (34) reads
    :math:`\mathbf J_{L1}^T\mathbf J_{L1} = \begin{bmatrix}a/L^2 & \mathbf b^T/L\\ \mathbf b/L & w\mathbf 1\end{bmatrix}`,
    whose eigenvalues are :math:`w` and :math:`\mu_\pm` with :math:`\mu_+ + \mu_- = a/L^2 + w`,
    :math:`\mu_+\mu_- = (a/L^2)(w - \|\mathbf b\|^2/a)`; :math:`\kappa^2 = \mu_+/\mu_-` is smallest at
    :math:`L^2 = a/w` wherever C is, where :math:`\kappa(\mathbf J_{L1}) = \sqrt{(w + c)/(w - c)}`,
    :math:`c = \|\sum_i\mathbf d_i\|\sqrt{w/a}`: isotropic exactly when C is the centroid of the mount points.

    Parameters
    ----------
    robot : Robot
        A numeric robot.

    Returns
    -------
    float

    Raises
    ------
    ValueError
        If every mount point is at C.

    Examples
    --------
    >>> from wmr import Robot, CentredWheel
    >>> bot = Robot([CentredWheel(p, r=0.1) for p in [(2.0, 0.0), (-1.0, 1.0), (-1.0, -1.0)]])
    >>> round(characteristic_length(bot) ** 2, 12)        # 8/3: a scalene triangle is isotropic too
    2.666666666667
    """
    d = validation.numeric_robot(robot).mount_points
    big = float(np.abs(d).max())  # scaled first: no overflow at 1e300, no underflow at 1e-300
    L = big * float(np.sqrt(np.mean(np.sum((d / big) ** 2, axis=1)))) if big > 0 else 0.0
    if L == 0:
        raise InputValueError(
            f"robot has all its mount points at C: no characteristic length exists (got L = 0): {validation.show(robot)}"
        )
    return L
