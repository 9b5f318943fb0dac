r"""What a robot's numeric kernels need, computed once per robot: its units' blocks side by side.

A :class:`~wmr.model.robot.Robot` keeps one :class:`Layout` for its tuple of units (the units are
frozen; a robot given other units computes a new one).  The layout stacks the units' constant
data as arrays, so that :math:`\mathbf J_2`, :math:`\mathbf F` and :math:`\mathbf J` (21), (24), (56)
are assembled for any number of units without a Python loop over the units
(:class:`~wmr.model.trig.Terms`), and the numbers are validated once, when the layout is made:

* ``rate_unit`` (n,): the unit of each joint rate (column of :math:`\mathbf J_2`);
* ``L``, ``EL`` (2, n): the units' local blocks :math:`\mathbf L_i` and :math:`\mathbf E\mathbf L_i`
  side by side (:meth:`~wmr.model.wheels.WheelUnit.block_terms`), so that column ``c`` of
  :math:`\mathbf J_2(\boldsymbol\beta)` is :math:`\mathbf R(\beta_{u(c)})` times column ``c`` of
  ``L``, at the rows of unit :math:`u(c)`;
* ``own``, ``own_angle``: the units without a steering joint and their constant angles
  (:meth:`~wmr.model.robot.Robot.effective_beta`);
* ``positions`` (w, 2): the mount points :math:`\mathbf d_i`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from . import checks
from .backend import NUMERIC
from .trig import Terms
from .types import FloatArray, IntArray, Symbolic

__all__: list[str] = []  # the robot's own cache: Robot makes it, nothing else does


@dataclass(frozen=True, eq=False)
class Layout:
    """A robot's units as arrays (see the module notes).  Made by :meth:`of`; numeric fields need a numeric robot.

    ``wheels`` are the units it was made from, ``symbolic`` whether one holds a SymPy value, ``free_symbols``
    the free symbols of their values.
    """

    wheels: tuple
    symbolic: bool
    free_symbols: frozenset[Symbolic]
    _numeric: dict = field(default_factory=dict, init=False, repr=False)

    @classmethod
    def of(cls, wheels: tuple) -> Layout:
        """The layout of a tuple of units (their symbols only; the arrays when first asked for)."""
        symbolic = any(u.is_symbolic for u in wheels)
        free = frozenset().union(*(u.free_symbols for u in wheels)) if symbolic else frozenset()
        return cls(wheels, symbolic, free)

    def _arrays(self) -> dict:
        """The numeric arrays (computed on first use; the units must be numeric)."""
        if "L" not in self._numeric:
            wheels = self.wheels
            blocks = [u.block_terms(NUMERIC) for u in wheels]
            n_rates = [np.shape(L)[1] for L, _ in blocks]
            L = np.concatenate([np.asarray(b[0], dtype=float) for b in blocks], axis=1)
            EL = np.concatenate([np.asarray(b[1], dtype=float) for b in blocks], axis=1)
            self._numeric.update(
                rate_unit=np.repeat(np.arange(len(wheels)), n_rates),
                L=L,
                EL=EL,
            )
        return self._numeric

    def memo(self, key: object, make):
        """``make()``, computed once per layout and ``key`` (constant data an analysis derives from the units)."""
        kept = self._numeric.setdefault("memo", {})
        if key not in kept:
            kept[key] = make()
        return kept[key]

    @property
    def positions(self) -> FloatArray:
        """The mount points :math:`\\mathbf d_i`, (w, 2), as floats (also of an exact robot)."""
        if "positions" not in self._numeric:
            # checked when each unit was made; a SymPy value is checked to be a number (no free symbol)
            number = checks.number if self.symbolic else lambda name, v: float(v)
            self._numeric["positions"] = np.array(
                [[number("position", v) for v in u.position] for u in self.wheels], dtype=float
            ).reshape(-1, 2)
        return self._numeric["positions"]

    def _own(self) -> tuple[IntArray, FloatArray]:
        if "own" not in self._numeric:
            own = [i for i, u in enumerate(self.wheels) if u.constant_angle is not None]
            number = checks.number if self.symbolic else lambda name, v: float(v)
            angles = [number("angle", self.wheels[i].constant_angle) for i in own]  # checked when made
            self._numeric["own"] = (np.array(own, dtype=np.intp), np.array(angles, dtype=float))
        return self._numeric["own"]

    @property
    def own(self) -> IntArray:
        """Indices of the units without a steering joint."""
        return self._own()[0]

    @property
    def own_angle(self) -> FloatArray:
        """Their constant angles (radians), in the order of :attr:`own`."""
        return self._own()[1]

    @property
    def rate_unit(self) -> IntArray:
        """The unit of each joint rate, (n,)."""
        return self._arrays()["rate_unit"]

    @property
    def L(self) -> FloatArray:
        """The local blocks side by side, (2, n)."""
        return self._arrays()["L"]

    @property
    def EL(self) -> FloatArray:
        """:math:`\\mathbf E` times the local blocks, (2, n)."""
        return self._arrays()["EL"]

    def J2_terms(self, sign: float = 1.0, offset: int = 0, const: FloatArray | None = None) -> Terms:
        r"""The terms of ``sign`` :math:`\mathbf J_2` placed at column ``offset`` of a (2w, offset + n) matrix.

        Column ``c`` of :math:`\mathbf J_2` has rows :math:`2u, 2u+1` (:math:`u` its unit):
        :math:`\cos\beta_u\,\mathbf L_{:,c} + \sin\beta_u\,\mathbf E\mathbf L_{:,c}` (11).  For
        :math:`\mathbf F` (24): ``sign`` -1, ``offset`` 3 and ``const`` :math:`[\mathbf J_1\ \mathbf 0]`.
        """
        u, L, EL = self.rate_unit, self.L, self.EL
        n = u.size
        width = offset + n
        cols = np.arange(n)
        entry = np.concatenate([(2 * u + r) * width + offset + cols for r in (0, 1)])
        p, q = sign * L.ravel(), sign * EL.ravel()
        keep = (p != 0.0) | (q != 0.0)
        return Terms((2 * len(self.wheels), width), entry[keep], np.tile(u, 2)[keep], p[keep], q[keep], const)

    def J_terms(self, JL1: FloatArray) -> Terms:
        r"""The terms of :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` (56), (3, n).

        Column ``c`` (unit :math:`u`) is :math:`\mathbf J_{L1,u}^T\mathbf R(\beta_u)\mathbf L_{:,c} =
        \cos\beta_u\,\mathbf J_{L1,u}^T\mathbf L_{:,c} + \sin\beta_u\,\mathbf J_{L1,u}^T\mathbf E\mathbf L_{:,c}`,
        with :math:`\mathbf J_{L1,u}` the unit's two rows of :math:`\mathbf J_{L1}` (2w, 3) (32).
        """
        u = self.rate_unit
        rows = JL1.reshape(-1, 2, 3)[u]  # (n, 2, 3): J_L1,u of each column
        P = np.einsum("nkr,kn->rn", rows, self.L)  # (3, n)
        Q = np.einsum("nkr,kn->rn", rows, self.EL)
        n = u.size
        entry = (np.arange(3)[:, None] * n + np.arange(n)).ravel()
        p, q = P.ravel(), Q.ravel()
        keep = (p != 0.0) | (q != 0.0)
        return Terms((3, n), entry[keep], np.tile(u, 3)[keep], p[keep], q[keep])
