r"""The configurations a robot can drive in: the steering angles of sampled twists (:class:`~wmr.analysis.sweep.Drivable`).

A steered robot moves only where its wheels are coordinated: every centred or dual wheel rolls in
the direction of its mount point's velocity (:func:`wmr.steering_angles`).  Those configurations
have measure zero on the torus of all steering angles, so a :class:`~wmr.analysis.sweep.Grid` or a
:class:`~wmr.analysis.sweep.Sample` essentially never visits one.  :class:`~wmr.analysis.sweep.Drivable` samples **twists**
instead and takes the steering angles that make each admissible:

* twist k is drawn in the dimensionless coordinates :math:`\hat{\mathbf t} = \mathbf t\circ\mathbf s`
  (``s`` the twist columns of :attr:`wmr.Robot.F_column_norms`: :math:`\dot\psi` times the
  characteristic length, :math:`\dot x`, :math:`\dot y`), uniformly over the directions the fixed
  wheels allow (a standard normal vector in :math:`\mathcal N(\mathbf C_{1f})`; every direction when
  there is no fixed wheel), so the result does not depend on the unit of length or of time;
* the steered units that roll in their plane get :func:`wmr.steering_angles`; the others, whose
  angle any twist admits (castors, offset wheels), get a uniform random angle.

Twist k depends only on the seed and k (blocks of :data:`~wmr.analysis.sweep.configurations.BLOCK`
drawn by ``numpy.random.default_rng([seed, block, 24])``), never on the chunking.

For robots of 3 to 6 swerve-like units (steered, rolling in their plane, one rate) ``kappa_J``
over drivable configurations has a fused kernel (:mod:`~wmr.analysis.sweep.swerve_kappa`): the
condition number in closed form straight from each twist; a member it cannot certify goes through
the general kernels.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ...errors import InputValueError
from ...model import validation
from ...model.tolerance import TOL
from .._batch import for_chunks
from ..isotropy import characteristic_length
from ..linalg import condition_number, null_space
from ..mobility import twist_constraints
from ..steering import steering_angles
from .configurations import BLOCK, count
from .reduction import Partial
from .swerve_kappa import SwerveKappa, swerve_like

__all__ = ["Drivable"]


@dataclass(frozen=True)
class Drivable:
    """``n`` configurations in which the robot can move: the steering angles of ``n`` sampled twists.

    See the module notes.  Bound to a robot by :meth:`bind` (:func:`wmr.sweep` does it).

    Parameters
    ----------
    n : int
        Number of twists (configurations), >= 1.
    seed : int, optional
        Non-negative seed.

    Examples
    --------
    >>> import wmr
    >>> src = Drivable(1000, seed=1).bind(wmr.paper_robot("centred"))
    >>> beta = src.configurations(3, 0, 1000)
    >>> int(wmr.mobility(wmr.paper_robot("centred"), beta).min())       # every one can move
    1
    """

    n: int
    seed: int = 0

    def __post_init__(self):
        object.__setattr__(self, "n", count("n", self.n))
        object.__setattr__(self, "seed", count("seed", self.seed, minimum=0))

    @property
    def covers(self):
        """The set of configurations, in words (for the reductions)."""
        return (
            f"drivable configurations: the steering angles of {self.n:,} twists sampled over the directions "
            f"the robot can move in (seed {self.seed})"
        )

    def size(self, w):
        """Number of configurations (``n``).

        Parameters
        ----------
        w : int

        Returns
        -------
        int
        """
        return self.n

    def bind(self, robot):
        """The source of these configurations for ``robot``.

        Parameters
        ----------
        robot : Robot
            A numeric robot.

        Returns
        -------
        Motions
        """
        return Motions(validation.numeric_robot(robot), self.n, self.seed)


class Motions:
    """:class:`Drivable` bound to a robot: twist k and its configuration, for any range of k.

    ``L``: the characteristic length of the fused kernel of ``kappa_J`` (a swerve-like robot), or None.
    """

    def __init__(self, robot, n, seed, L=None):
        self.robot, self.n, self.seed, self.L = robot, n, seed, L
        self.scale = robot.F_column_norms[:3]
        fixed = [i for i, u in enumerate(robot.wheels) if not u.steered]
        # the directions the fixed wheels allow, N(C1f) in dimensionless twists, as the projector onto them:
        # unique where a basis of N is not (an SVD picks any rotation of it, and the last bits pick which),
        # so the same draws give the same twists on every CPU; entries within TOL of 0 are 0
        self.projector = np.eye(3)
        if fixed:
            sub = type(robot)([robot.wheels[i] for i in fixed], name="fixed")
            Cf, _ = twist_constraints(sub, np.zeros(len(fixed)))
            if Cf.shape[0]:
                N = null_space(Cf / self.scale, scale=np.ones(3))
                P = N @ N.T
                self.projector = np.where(np.abs(P) <= TOL, 0.0, P)
        self.free = [i for i, u in enumerate(robot.wheels) if u.steered and not u.rolls_in_plane]

    def twists(self, start, stop):
        """Twists ``start .. stop-1`` (k, 3) and the angles of the freely steered units (k, w) or None."""
        first, last = start // BLOCK, (stop - 1) // BLOCK
        tws, curs = [], []
        for j in range(first, last + 1):
            rng = np.random.default_rng([self.seed, j, 24])
            tws.append(rng.standard_normal((3, BLOCK)))
            if self.free:
                curs.append(rng.uniform(-math.pi, math.pi, (BLOCK, len(self.free))))
        a, b = start - first * BLOCK, stop - first * BLOCK
        g = np.concatenate(tws, axis=1)[:, a:b] if len(tws) > 1 else tws[0][:, a:b]
        current = None
        if self.free:
            current = np.zeros((b - a, self.robot.w))
            current[:, self.free] = np.concatenate(curs)[a:b]
        # t = (P g) / s, written out (a BLAS product of (3, k) by (3, 3) would start threads for nothing);
        # entry-major: each component of the twists is one contiguous vector.  P g is a standard normal
        # draw over the allowed directions (P projects orthogonally)
        M = self.projector / self.scale[:, None]
        if not np.any(M - np.diag(np.diag(M))):  # a diagonal map (no fixed wheel, or axis-aligned ones), in place
            g *= np.diag(M)[:, None]  # (g is a fresh draw: changed in place)
            return g.T, current
        tw = np.zeros((3, b - a))
        for c in range(3):
            for j in range(3):
                if M[c, j] != 0.0:
                    tw[c] += g[j] * M[c, j]
        return tw.T, current

    def configurations(self, w, start, stop):
        """Configurations ``start .. stop-1``: the steering angles of the twists (k, w)."""
        return steering_angles(self.robot, *self.twists(start, stop))

    @cached_property
    def kernel(self):
        """The fused kernel of ``kappa_J`` (:func:`fused_kernel`), built where it is first used, or None."""
        return fused_kernel(self.robot, self.L)

    def kappa_J(self, start, stop, keep):
        r"""The :class:`Partial` of :math:`\kappa(\mathbf J)` over ``start .. stop-1`` by the fused kernel, block by block.

        Each block of twists is drawn, evaluated and reduced in one task (any thread); ``start`` is a multiple
        of :data:`~wmr.analysis.sweep.configurations.BLOCK`.
        """
        parts: dict[int, Partial] = {}

        def block(a, b):
            x = _evaluate(self, self.robot, self.twists(start + a, start + b)[0], self.L)
            parts[a] = Partial().add(start + a, x, False, keep)

        for_chunks(block, stop - start, BLOCK)
        whole = Partial()
        for a in sorted(parts):
            whole.merge(parts[a])
        return whole


def fused_kernel(robot, L=None):
    """The fused kernel of ``kappa_J`` for ``robot`` and ``L`` (default its characteristic length), or None."""
    if not swerve_like(robot):
        return None
    try:
        return SwerveKappa(robot, characteristic_length(robot) if L is None else L)
    except InputValueError:  # det J does not vanish in translation: no fused kernel
        return None


def _evaluate(source, robot, twist, L):
    """The kernel of ``source`` on ``twist (k, 3)``, and the general kernels on the members it did not certify."""
    out = np.empty(twist.shape[0])
    redo = np.ones(twist.shape[0], dtype=bool)
    if source.kernel is not None:
        source.kernel(twist, out, redo)
    if redo.any():
        rows = np.flatnonzero(redo)
        out[rows] = condition_number(robot.J(steering_angles(robot, twist[rows]), L=L))
    return out


def kappa_J_of_twists(robot, twist, L):
    r""":math:`\kappa(\mathbf J)` at the steering angles that make each twist admissible (None: no fused kernel).

    ``twist`` (k, 3) gives (k,): ``condition_number(robot.J(steering_angles(robot, twist), L=L))`` within a
    relative :data:`~wmr.analysis.gram_kappa.ACCURACY` or ``KAPPA_ERROR * eps * kappa``.
    """
    robot = validation.numeric_robot(robot)
    twist = validation.finite_array("twist", twist, last=3).reshape(-1, 3)
    L = validation.number("L", validation.positive("L", L))
    source = Motions(robot, 0, 0, L)
    if source.kernel is None:
        return None
    out = np.empty(twist.shape[0])

    def chunk(a, b):
        out[a:b] = _evaluate(source, robot, twist[a:b], L)

    for_chunks(chunk, twist.shape[0], BLOCK)
    return out
