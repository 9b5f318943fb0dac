r"""Singular configurations of a WMR with three centred wheels: the zero set of :math:`\det\mathbf J` (58)-(59).

For centred wheels the i-th column of :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` (56) is
:math:`-r_i[\tfrac1L\mathbf d_i^T\mathbf E^T\mathbf j_i,\ \mathbf j_i^T]^T`, and
:math:`(\mathbf E\mathbf d_i)^T\mathbf j_i = \mathbf d_i\times\mathbf j_i = \mathbf d_i^T\mathbf i_i`.  So the
column is (up to the factor :math:`-r_i`) the Plücker vector
:math:`\mathbf w_i = [\,m_i/L,\ \mathbf j_i^T]^T`, :math:`m_i = \mathbf d_i^T\mathbf i_i`, of the
**wheel-plane line** :math:`\ell_i` (the trace of the wheel plane on the floor: through :math:`P_i`
along :math:`\mathbf j_i`), and

.. math::

    \det\mathbf J = -\frac{r_1r_2r_3}{L}\Big[m_1\sin(\beta_3-\beta_2) + m_2\sin(\beta_1-\beta_3)
                    + m_3\sin(\beta_2-\beta_1)\Big] = -\frac{r_1r_2r_3}{L}\det\mathbf W ,

an identity checked exactly by :func:`wmr.analysis.det_exact.characterisation` for symbolic mount points.  A point
:math:`D` lies on :math:`\ell_i` iff :math:`[-1,\ -D_y,\ D_x]\,\mathbf W_{L=1}\mathbf e_i = 0`; hence
:math:`\det\mathbf J = 0` **iff the three wheel-plane lines are concurrent at a point**
:math:`D_P` **or all parallel** (concurrent at infinity), and :math:`D_P` is read off the left null
vector of :math:`\mathbf W` (:func:`wmr.analysis.lines.concurrency_point`).  The zero set is one irreducible surface
in the torus of :math:`(\beta_1,\beta_2,\beta_3)` (for the paper's robot :math:`\det\mathbf J` is an
irreducible trilinear form in :math:`(\cos\beta_i,\sin\beta_i)`), swept by :math:`D_P` over the
projective plane with the 8 choices :math:`\beta_i` or :math:`\beta_i+\pi`; the paper's items
(i)-(v) are pieces of it.

A different matrix decides mobility: :math:`\operatorname{rank}\mathbf F = 5` (mobility 1) iff
the three **axle** lines (through :math:`P_i` along :math:`\mathbf i_i`) are concurrent, at the
instantaneous centre U; otherwise 6.  Both happen at once iff every :math:`P_i` sees
:math:`U` and :math:`D_P` at a right angle, i.e. (Thales) :math:`U` and :math:`D_P` are antipodal
on the circle through :math:`P_1,P_2,P_3`, or both are at infinity: a rotation about any point
of that circle passes through a singular :math:`\mathbf J` (:func:`classify` calls it
``"v-circle"``; the catalogue of the paper's families is :mod:`edition.families`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.platform import wrap_angle
from ..model.robot import Robot
from ..model.tolerance import TOL, near_zero
from ..model.types import ArrayLike, BoolArray, FloatArray
from .det_exact import characterisation as characterisation  # importable here too (not in __all__)
from .det_exact import det_J_polynomial, exact_zero
from .det_exact import det_J_symbolic as det_J_symbolic
from .det_exact import plane_line_matrix as plane_line_matrix
from .linalg import det
from .lines import (
    AT_INFINITY,
    COINCIDENT,
    FINITE,
    NONE,
    Concurrency,
    axles_concurrency,
    axles_through,
    circumcircle,
    concurrency_point,
    pair_intersections,
    wheel_plane_lines,
)
from .mobility import rank_F
from .square import default_L, exact_robot, require_square

__all__ = [
    "det_J",
    "is_singular",
    "Classification",
    "classify",
    "singular_motions",
    "exact_robot",
    "numeric_robot",
    # the exact side of det J, from wmr.analysis.det_exact
    "det_J_polynomial",
    "exact_zero",
]


def numeric_robot(robot: Robot) -> Robot:
    """The same robot with float coordinates and radii (from an exact one).

    Parameters
    ----------
    robot : Robot
        Without free symbols.

    Returns
    -------
    Robot
    """
    return validation.robot(robot).numeric()


# ------------------------------------------------------------------------------------- det J
def det_J(robot: Robot, beta: ArrayLike, L: float | None = None) -> FloatArray:
    r""":math:`\det\mathbf J(\boldsymbol\beta)` (58) for a batch of configurations.

    Parameters
    ----------
    robot : Robot
        Three centred wheels (``n_rates == 3``).
    beta : array (..., 3)
    L : float, optional
        Characteristic length of :math:`\mathbf J_{L1}` (default: :func:`wmr.characteristic_length`,
        which is the paper's L for its robot).

    Returns
    -------
    numpy.ndarray (...)

    Examples
    --------
    >>> import wmr
    >>> bot = wmr.paper_robot("centred")
    >>> abs(float(det_J(bot, [0.3, 0.3, 0.3]))) < 1e-15      # item (i)
    True
    """
    return det(_square_J(robot, beta, L))  # closed form, batched


def _square_J(robot, beta, L):
    """:math:`\\mathbf J` (..., 3, 3) of a robot of three centred wheels (checked here)."""
    robot = validation.numeric_robot(robot)
    require_square(robot)
    return robot.J(beta, L=default_L(robot, L))


def is_singular(robot: Robot, beta: ArrayLike, L: float | None = None) -> BoolArray:
    r"""True where :math:`|\det\mathbf J| \le` ``TOL`` times the Hadamard bound (batched).

    Parameters
    ----------
    robot : Robot
        Three centred wheels.
    beta : array (..., 3)
    L : float, optional
        As for :func:`det_J`.

    Returns
    -------
    numpy.ndarray of bool (...)
    """
    return _singular(_square_J(robot, beta, L))[1]


def _singular(J):
    r""":math:`\det\mathbf J` and whether it is zero against the Hadamard bound :math:`\prod_i\|\mathbf J\mathbf e_i\|`."""
    dj = det(J)
    return dj, near_zero(dj, np.prod(np.linalg.norm(J, axis=-2), axis=-1))


# -------------------------------------------------------------------------------- classify
@dataclass(frozen=True)
class Classification:
    r"""What a configuration is (see :func:`classify`).

    Attributes
    ----------
    beta : numpy.ndarray (3,)
    det_J : float
    singular : bool
    rank_F : int
    mobility : int
    planes : Concurrency
        Where the wheel-plane lines meet (:math:`D_P`).
    axles : Concurrency
        Where the axles meet (the IC).
    coincident : tuple of (i, j)
        Pairs of wheels whose planes coincide.
    family : str
        The family (see :func:`classify`), ``"regular"`` where :math:`\det\mathbf J \ne 0`.
    """

    beta: np.ndarray
    det_J: float
    singular: bool
    rank_F: int
    mobility: int
    planes: Concurrency
    axles: Concurrency
    coincident: tuple = field(default_factory=tuple)
    family: str = "regular"


def _same_angle(a, b, period=2 * np.pi):
    """True when a = b modulo ``period`` (within TOL)."""
    x = np.mod(a - b + period / 2, period) - period / 2
    return bool(near_zero(x))


def classify(robot: Robot, beta: ArrayLike, L: float | None = None) -> Classification:
    r"""Classify one configuration of a three-centred-wheel robot.

    Families: ``"i"`` (all wheel planes parallel, equal angles),
    ``"i'"`` (parallel, some wheel turned by :math:`\pi`), ``"pair-ij"`` / ``"pair-ij'"`` (planes of
    wheels i, j on the line :math:`P_iP_j`, with equal / half-turn-apart angles), ``"v-C"``
    (:math:`D_P = C`), ``"v-P"`` (:math:`D_P` at a mount point), ``"v-circle"`` (axles also
    concurrent: rotation about a point of the circle through the :math:`P_i`), ``"v"`` (any other
    finite :math:`D_P`).

    Parameters
    ----------
    robot : Robot
    beta : array (3,)
    L : float, optional
        Characteristic length of :math:`\mathbf J_{L1}` (default :func:`wmr.characteristic_length`).

    Returns
    -------
    Classification
    """
    require_square(robot)
    robot = validation.numeric_robot(robot)
    beta = robot.effective_beta(beta)
    if beta.ndim != 1:
        raise InputValueError(f"beta must be one configuration of shape (3,) for classify, got shape {beta.shape}")
    dj, sing = (x.item() for x in _singular(robot.J(beta, L=default_L(robot, L))))
    rk = int(rank_F(robot, beta))
    mob = 3 + robot.n_rates - rk
    planes = concurrency_point(robot, beta)
    axles = axles_concurrency(robot, beta)
    P, u = wheel_plane_lines(robot, beta)
    pairs = tuple(k for k, (kind, _) in pair_intersections(P, u).items() if kind == COINCIDENT)
    fam = "regular"
    if sing:
        scale = float(np.abs(robot.mount_points).max())
        if planes.kind == AT_INFINITY:
            equal = all(_same_angle(beta[k], beta[0]) for k in range(1, robot.w))
            fam = "i" if equal else "i'"
        elif pairs:
            i, j = pairs[0]
            fam = f"pair-{i}{j}" + ("" if _same_angle(beta[i - 1], beta[j - 1]) else "'")
        elif axles.kind != NONE:
            fam = "v-circle"
        elif planes.kind == FINITE and near_zero(np.linalg.norm(planes.point), scale):
            fam = "v-C"
        elif planes.kind == FINITE and np.min(np.linalg.norm(robot.mount_points - planes.point, axis=1)) <= TOL * scale:
            fam = "v-P"
        else:
            fam = "v"
    return Classification(beta, dj, sing, rk, mob, planes, axles, pairs, fam)


def singular_motions(robot: Robot, beta1: float) -> tuple[FloatArray, list[str]]:
    r"""Configurations with :math:`\beta_1` fixed where :math:`\det\mathbf J = 0` **and** rank F = 5.

    These are the points where a slice :math:`\beta_1 = {\rm const}` of the singular surface meets
    the set of configurations that admit motion: all planes parallel (families (i), (i')) and
    rotations about the second point :math:`U^*` where the axle of wheel 1 meets the circle through
    the :math:`P_i` (family v-circle; none when the axle is tangent to the circle).

    Parameters
    ----------
    robot : Robot
        Three centred wheels.
    beta1 : float
        Radians.

    Returns
    -------
    beta : numpy.ndarray (n, 3)
        In :math:`(-\pi, \pi]`.
    family : list of str
        From :func:`classify`.
    """
    require_square(robot)
    robot = validation.numeric_robot(robot)
    beta1 = validation.number("beta1", beta1)
    rows = []
    for a in (0.0, np.pi):
        for b in (0.0, np.pi):
            rows.append([beta1, beta1 + a, beta1 + b])
    c, R = circumcircle(robot.mount_points)
    p = robot.mount_points[0]
    i1 = np.array([np.cos(beta1), np.sin(beta1)])
    t = -2.0 * float(i1 @ (p - c))
    if not near_zero(t, R):
        U = p + t * i1
        base = axles_through(robot, U)
        for a in (0.0, np.pi):
            for b in (0.0, np.pi):
                rows.append([beta1, base[1] + a, base[2] + b])
    beta = wrap_angle(np.array(rows))
    return beta, [classify(robot, b_).family for b_ in beta]
