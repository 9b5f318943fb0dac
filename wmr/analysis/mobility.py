r"""Mobility: rank, nullity and null space of the functional matrix (23)-(27).

The mobility of a WMR is the nullity :math:`\nu(\mathbf F) = \dim\mathcal N(\mathbf F)` (27): the number
of generalised rates :math:`\dot{\mathbf q}` (25) that can be assigned freely without violating the
no-slip constraints.  All rank decisions use :data:`wmr.model.tolerance.TOL` on the dimensionless
:math:`\hat{\mathbf F}` (each column divided by its length, :attr:`wmr.Robot.F_column_norms`), so
that mobility does not depend on the unit of length.

For batches of configurations, :func:`mobility` does not take an SVD of every
:math:`2w\times(3+n)` matrix :math:`\mathbf F`.  It uses the structure
:math:`\mathbf F = [\mathbf J_1\ \ -\mathrm{blockdiag}(\mathbf R_{bwi}\mathbf L_i)]`, where the
:math:`\mathbf L_i` are the units' constant local blocks, to write exactly

.. math:: \operatorname{rank}\mathbf F = \sum_i\operatorname{rank}\mathbf L_i
          + \operatorname{rank}\mathbf A(\boldsymbol\beta),\qquad
          \mathbf A = \begin{bmatrix}\vdots\\ \mathbf N_i^T\mathbf R_{bwi}^T[\mathbf E\mathbf d_i\ \ \mathbf 1]\\
          \vdots\end{bmatrix},

with :math:`\mathbf N_i` an orthonormal basis of the left null space of :math:`\mathbf L_i` (for a
centred or dual wheel, the axle direction).  The same identity holds for :math:`\hat{\mathbf F}`,
whose twist columns are those of :math:`\mathbf F` divided by their lengths: :func:`rank_F` ranks
:math:`\mathbf A` with those column sizes, :func:`wmr.rank` of ``robot.F(beta)`` ranks
:math:`\hat{\mathbf F}` directly, and the two agree.  The rows of :math:`\mathbf A` are the constraints the
platform twist must satisfy; :math:`\mathbf A` is :math:`k\times 3` with :math:`k` small.
"""

from __future__ import annotations

import functools

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.backend import NUMERIC
from ..model.platform import E
from ..model.robot import Robot
from ..model.trig import Terms, combine_checked
from ..model.types import ArrayLike, FloatArray, IntArray
from .linalg import left_null_space, null_space, rank

__all__ = ["twist_constraints", "rank_F", "mobility", "admissible_twists"]


def twist_constraints(robot: Robot, beta: ArrayLike, free: ArrayLike | None = None) -> tuple[FloatArray, int]:
    r"""The constraint rows :math:`\mathbf A(\boldsymbol\beta)` on the platform twist (see module notes).

    A twist :math:`\mathbf t` is admissible (some joint rates realise it without slip) exactly when
    :math:`\mathbf A\mathbf t = \mathbf 0`.  With ``free``, only the rate columns it marks may take
    any value and the others are held at zero: unit i then contributes the left null space of its
    free columns :math:`\mathbf L_i^{f}` (both rows, :math:`\mathbf N_i = \mathbf 1`, when it has none),
    and :math:`\mathbf A\mathbf t = \mathbf 0` says that the free joints alone realise
    :math:`\mathbf t` (with ``free`` = the passive joints: a motion the robot makes with every motor
    stopped, :mod:`wmr.analysis.actuation`).

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)
    free : array of bool (n_rates,), optional
        Which columns of :math:`\mathbf J_2` may move (default: all).

    Returns
    -------
    A : numpy.ndarray (..., k, 3)
    base_rank : int
        :math:`\sum_i \operatorname{rank}\mathbf L_i`.

    Examples
    --------
    >>> from wmr.model.robots import paper_robot
    >>> A, base = twist_constraints(paper_robot("centred"), [0.0, 0.0, 0.0])
    >>> A.shape, base
    ((3, 3), 3)
    """
    robot = validation.numeric_robot(robot)
    beta = robot.effective_beta(beta)
    free = np.ones(robot.n_rates, dtype=bool) if free is None else np.asarray(free, dtype=bool)
    terms, base_rank = robot._memo(("twist_constraints", free.tobytes()), lambda: _constraint_terms(robot, free))
    return combine_checked(beta, terms), base_rank


def _constraint_terms(robot, free):
    """The :class:`~wmr.model.trig.Terms` of :func:`twist_constraints` and its base rank (constant for a robot)."""
    Ns = []
    for u, sl in zip(robot.wheels, robot.rate_slices):
        Lf = np.asarray(u.local_block(NUMERIC), dtype=float)[:, free[sl]]
        Ns.append(_left_null(Lf.tobytes(), Lf.shape) if Lf.shape[1] else np.eye(2))  # (2, k_i), constant
    # R(beta)^T = cos(beta) 1 + sin(beta) E^T (11), so the rows N_i^T R^T [E d_i 1] are
    # cos(beta_i) P_i + sin(beta_i) Q_i with constant P_i = N_i^T J1_i, Q_i = N_i^T E^T J1_i.
    J1, Et = robot.J1(), E(NUMERIC).T
    units, Ps, Qs, base_rank = [], [], [], 0
    for i, N in enumerate(Ns):
        base_rank += 2 - N.shape[1]  # rank L_i (of its free columns)
        Ji = J1[2 * i : 2 * i + 2]
        units += [i] * N.shape[1]
        Ps.append(N.T @ Ji)
        Qs.append(N.T @ Et @ Ji)
    P, Q = np.concatenate(Ps), np.concatenate(Qs)  # (k, 3): unit units[r]'s row r
    k = P.shape[0]
    entry = np.arange(3 * k)
    unit = np.repeat(np.array(units, dtype=np.intp), 3)
    p, q = P.ravel(), Q.ravel()
    keep = (p != 0.0) | (q != 0.0)
    return Terms((k, 3), entry[keep], unit[keep], p[keep], q[keep]), base_rank


@functools.lru_cache(maxsize=256)
def _left_null(data, shape):
    """:func:`~wmr.analysis.linalg.left_null_space` of a unit's block, by value (units of one kind and size share it)."""
    N = left_null_space(np.frombuffer(data).reshape(shape))
    N.setflags(write=False)
    return N


def rank_F(robot: Robot, beta: ArrayLike) -> IntArray:
    r"""Rank of the functional matrix :math:`\mathbf F(\boldsymbol\beta)` for a batch of configurations.

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)

    Returns
    -------
    numpy.ndarray of int (...)

    Examples
    --------
    >>> from wmr.model.robots import paper_robot
    >>> rank_F(paper_robot("centred"), [[0.0, 0.0, 0.0], [0.1, 0.2, 0.3]]).tolist()
    [5, 6]
    """
    robot = validation.numeric_robot(robot)
    A, base = twist_constraints(robot, beta)
    return base + rank(A, scale=robot.F_column_norms[:3])  # the twist columns of F, scaled as in rank(F)


def mobility(robot: Robot, beta: ArrayLike) -> IntArray:
    r"""Mobility :math:`\nu(\mathbf F) = (3 + n) - \operatorname{rank}\mathbf F` (27), batched.

    Parameters
    ----------
    robot : Robot
    beta : array (..., w)
        Steering angles.

    Returns
    -------
    numpy.ndarray of int (...)

    Examples
    --------
    >>> from wmr.model.robots import paper_robot
    >>> int(mobility(paper_robot("offset", d=0.5), [0.1, 0.2, 0.3]))
    3
    >>> int(mobility(paper_robot("centred"), [0.0, 0.0, 0.0]))   # parallel wheels: translation
    1
    """
    rank = rank_F(robot, beta)
    return 3 + robot.n_rates - rank


def admissible_twists(robot: Robot, beta: ArrayLike) -> FloatArray:
    r"""Orthonormal basis (3, m) of the admissible platform twists at one configuration.

    The projection of :math:`\mathcal N(\mathbf F)` onto the twist coordinates: the twists that some
    joint rates realise without slip (the null space of :func:`twist_constraints`).

    Parameters
    ----------
    robot : Robot
    beta : array (w,)
        Steering angles of one configuration.

    Returns
    -------
    numpy.ndarray (3, m)

    Examples
    --------
    >>> from wmr.model.robots import paper_robot
    >>> basis = admissible_twists(paper_robot("centred"), [0.0, 0.0, 0.0])   # axles along x
    >>> np.abs(basis.ravel()).round(12).tolist()                              # only y translation
    [0.0, 0.0, 1.0]
    """
    robot = validation.numeric_robot(robot)
    beta = robot.effective_beta(beta)
    if beta.ndim != 1:
        raise InputValueError(
            f"beta must be one configuration of shape ({robot.w},) for admissible_twists, got shape {beta.shape}"
        )
    A, _ = twist_constraints(robot, beta)
    if A.shape[0] == 0:
        return np.eye(3)
    return null_space(A, scale=robot.F_column_norms[:3])
