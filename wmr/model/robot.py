r"""The assembled robot: platform + wheel units, :math:`\mathbf J_1`, :math:`\mathbf J_2`, :math:`\mathbf F`.

Stacking the no-slip equation of every unit gives (21),
:math:`\mathbf J_1\mathbf t = \mathbf J_2\dot{\boldsymbol\theta}`, and its homogeneous form (22)-(23),
:math:`\mathbf F\dot{\mathbf q} = \mathbf 0` with the functional matrix
:math:`\mathbf F = [\mathbf J_1\ \ -\mathbf J_2]` (24) and the generalised rates
:math:`\dot{\mathbf q} = [\mathbf t^T\ \dot{\boldsymbol\theta}^T]^T` (25).  The layout of
:math:`\dot{\mathbf q}` is named (:attr:`Robot.qdot_names`) so that a reader can see which column
of :math:`\mathbf F` is which rate.
"""

from __future__ import annotations

import functools
from collections.abc import Iterable
from typing import Any, NoReturn

import numpy as np

from ..errors import FrozenError, InputValueError
from . import checks
from .backend import NUMERIC, SYMBOLIC, Backend, choose
from .layout import Layout
from .lazysympy import sp
from .platform import moved_points, point_row
from .tolerance import column_norms
from .trig import combine_checked
from .types import ArrayLike, FloatArray, Matrix, Numbers, Point, Symbolic
from .wheels import WheelUnit, wheel_units

__all__ = ["Robot"]

#: the names of the twist's rates, the first columns of F
TWIST_NAMES = ("psi_dot", "x_dot", "y_dot")


class Robot:
    r"""A planar WMR: a platform with operation point C carried by ``w`` wheel units.

    Parameters
    ----------
    wheels : sequence of wheel units
        The units (:mod:`wmr.model.wheels`: offset, centred, dual, fixed, Swedish, ...) in their
        numbering order (wheel 1 first); any number >= 1, any mount points, mixed kinds; a
        configuration has one entry per unit (:meth:`effective_beta`).
    name : str, optional

    Notes
    -----
    Frozen: setting or deleting an attribute raises :class:`~wmr.errors.FrozenError`, so what is
    derived from the units is made at first use and kept.  Equality and hashing are by identity.

    Examples
    --------
    >>> from wmr import Robot, CentredWheel
    >>> bot = Robot([CentredWheel((1, 0), r=0.1), CentredWheel((-1, 0), r=0.1)])
    >>> bot.qdot_names
    ('psi_dot', 'x_dot', 'y_dot', 'theta_dot_1', 'theta_dot_2')
    >>> bot.F([0.0, 0.0]).shape
    (4, 5)
    """

    wheels: tuple[WheelUnit, ...]
    name: str
    rate_slices: tuple[slice, ...]  #: slice of each unit's rates inside the joint-rate vector theta_dot

    def __init__(self, wheels: Iterable[WheelUnit], name: str | None = None) -> None:
        wheels = wheel_units(wheels)
        starts = np.cumsum([0] + [u.n_rates for u in wheels])
        made = object.__setattr__  # the only assignments: the robot is frozen from here on
        made(self, "wheels", wheels)
        made(self, "name", checks.optional_text("name", name) or "robot")
        made(self, "rate_slices", tuple(slice(int(a), int(b)) for a, b in zip(starts[:-1], starts[1:])))

    def __setattr__(self, attr: str, value: Any = None) -> NoReturn:
        raise FrozenError(f"a Robot cannot be changed once made ({attr}): build a new one, Robot(wheels, name=...)")

    __delattr__ = __setattr__

    def __repr__(self):
        kinds = ", ".join(f"{u.kind}@{tuple(u.position)}" for u in self.wheels)
        return f"Robot({self.name!r}: {kinds})"

    # --- sizes and names -----------------------------------------------------------------------
    @property
    def w(self) -> int:
        """Number of wheel units."""
        return len(self.wheels)

    @property
    def steered(self) -> tuple[bool, ...]:
        """Tuple of w bools: True for units with a steering joint (offset, centred, dual); :meth:`effective_beta`."""
        return tuple(bool(u.steered) for u in self.wheels)

    @property
    def n_rates(self) -> int:
        """Length of the joint-rate vector :math:`\\dot{\\boldsymbol\\theta}`."""
        return self.rate_slices[-1].stop

    @property
    def rate_names(self) -> tuple[str, ...]:
        """Names of the joint rates, in column order of :math:`\\mathbf J_2`."""
        return tuple(n for i, u in enumerate(self.wheels, 1) for n in u.rate_names(i))

    @property
    def qdot_names(self) -> tuple[str, ...]:
        """Names of the generalised rates (25): the columns of :math:`\\mathbf F`."""
        return TWIST_NAMES + self.rate_names

    @property
    def twist_symbols(self) -> tuple[Symbolic, ...]:
        r"""SymPy symbols :math:`(\dot\psi, \dot x, \dot y)`."""
        return sp.symbols(r"\dot{\psi} \dot{x} \dot{y}", real=True)

    @property
    def rate_symbols(self) -> tuple[Symbolic, ...]:
        """SymPy symbols of the joint rates, typeset as in the paper."""
        return tuple(s for i, u in enumerate(self.wheels, 1) for s in u.rate_symbols(i))

    @property
    def qdot_symbols(self) -> tuple[Symbolic, ...]:
        """SymPy symbols of the generalised rates (25), in the column order of :math:`\\mathbf F`."""
        return tuple(self.twist_symbols) + self.rate_symbols

    @property
    def beta_symbols(self) -> tuple[Symbolic, ...]:
        r"""SymPy symbols :math:`\beta_1, \dots, \beta_w` (real)."""
        return sp.symbols(f"beta1:{self.w + 1}", real=True)

    @functools.cached_property
    def _layout(self) -> Layout:
        """The units as arrays (:mod:`~wmr.model.layout`), made at first use and kept (the robot is frozen)."""
        return Layout.of(self.wheels)

    @property
    def mount_points(self) -> FloatArray:
        r"""Array (w, 2) of the :math:`\mathbf d_i` (numeric robots only)."""
        return self._layout.positions.copy()

    @property
    def is_symbolic(self) -> bool:
        """True when a mount point or a length of some unit is a SymPy expression."""
        return self._layout.symbolic

    @property
    def F_column_norms(self) -> FloatArray:
        r"""Lengths of the columns of :math:`\mathbf F` (22)-(24), the same at every configuration: (3 + n_rates,).

        :math:`\sqrt{\sum_i\|\mathbf d_i\|^2}`, :math:`\sqrt w`, :math:`\sqrt w`, then the lengths of the
        units' local blocks' columns; zero columns get 1 (:mod:`wmr.model.tolerance`).  Numeric robots only.
        """
        bot = self.numeric()
        L = bot._layout.L  # the units' local blocks side by side
        return np.concatenate([column_norms(bot.J1(backend=NUMERIC)), column_norms(L)])

    # --- matrices -------------------------------------------------------------------------------
    def effective_beta(self, beta: ArrayLike) -> FloatArray:
        r"""The configuration the model uses: ``beta`` with each unsteered unit's entry set to its own angle.

        Fixed and Swedish wheels have no steering joint: their entries are replaced by their ``angle``.

        Parameters
        ----------
        beta : array (..., w)
            Steering angles (radians).

        Returns
        -------
        numpy.ndarray (..., w)
            A checked float array (``beta`` itself when every unit is steered, else a copy).

        Examples
        --------
        >>> from wmr import CentredWheel, FixedWheel
        >>> bot = Robot([CentredWheel((1, 0), r=0.1), FixedWheel((-1, 0), r=0.1, angle=0.5)])
        >>> bot.effective_beta([[0.1, 0.2], [0.3, 0.4]]).tolist()
        [[0.1, 0.5], [0.3, 0.5]]
        """
        beta = checks.finite_array("beta", beta, last=self.w)
        lay = self._layout
        if lay.own.size:  # (a copy: the caller's array is not changed)
            beta = beta.copy()
            beta[..., lay.own] = lay.own_angle
        return beta

    def _beta(self, beta, bk):
        if bk is SYMBOLIC:
            b = list(self.beta_symbols) if beta is None else list(checks.symbolic_vector("beta", beta, self.w))
            return [
                b[i] if u.constant_angle is None else sp.sympify(u.constant_angle) for i, u in enumerate(self.wheels)
            ]
        return self.effective_beta(beta)

    def J1(self, L: Numbers = 1, backend: Backend | None = None) -> Matrix:
        r"""Platform Jacobian :math:`\mathbf J_1` (21), or :math:`\mathbf J_{L1}` (32) for ``L != 1``.

        .. math:: \mathbf J_{L1} = \begin{bmatrix}\tfrac1L\mathbf E\mathbf d_1 & \mathbf 1\\
                  \vdots&\vdots\\ \tfrac1L\mathbf E\mathbf d_w&\mathbf 1\end{bmatrix}

        Parameters
        ----------
        L : float or sympy.Expr, optional
            Characteristic length, > 0 (default 1: :math:`\mathbf J_1`).
        backend : NUMERIC or SYMBOLIC, optional
            Default: SymPy for a symbolic robot or symbolic ``L``, else NumPy.

        Returns
        -------
        numpy.ndarray (2w, 3) or sympy.Matrix (2w, 3)

        Examples
        --------
        >>> from wmr import CentredWheel
        >>> Robot([CentredWheel((2.0, 0.0), r=1.0)]).J1(L=2.0).tolist()
        [[-0.0, 1.0, 0.0], [1.0, 0.0, 1.0]]
        """
        L = checks.positive("L (characteristic length)", L)
        bk = choose(L, backend=backend) if not self.is_symbolic else SYMBOLIC
        if bk is SYMBOLIC:
            M = bk.zeros(2 * self.w, 3)
            for i, u in enumerate(self.wheels):
                bk.set_block(M, 2 * i, 0, point_row(u.position, L, backend=bk))  # (32)
            return M
        M = self._layout.memo("J1", self._J1_numeric).copy()  # J1 once per robot, then its first column / L
        with np.errstate(over="ignore"):
            M[:, 0] /= float(L)
        if not np.isfinite(M).all():
            raise InputValueError(
                f"L (characteristic length) = {L!r} is too small for mount points of size "
                f"{np.abs(self.mount_points).max():.3g}: d_i / L overflows"
            )
        return M

    def _J1_numeric(self):
        r""":math:`\mathbf J_1` (21) of the checked mount points, its rows :math:`[\mathbf E\mathbf d_i\ \mathbf 1]` (5)."""
        return np.concatenate([point_row(d, backend=NUMERIC) for d in self._layout.positions])

    def _backend(self, beta, backend):
        return SYMBOLIC if (beta is None or self.is_symbolic) else choose(beta, backend=backend)

    def J2(self, beta: Numbers | None = None, backend: Backend | None = None) -> Matrix:
        r"""Wheel Jacobian :math:`\mathbf J_2(\boldsymbol\beta)` (21): block-diagonal in the units' blocks.

        Parameters
        ----------
        beta : array (..., w), sequence of w SymPy expressions, or None
            Steering angles :math:`\beta_i`; ``None`` means the symbols :math:`\beta_1..\beta_w`.
        backend : NUMERIC or SYMBOLIC, optional
            Default: SymPy when ``beta`` is None or symbolic or the robot is symbolic, else NumPy.

        Returns
        -------
        numpy.ndarray (..., 2w, n_rates) or sympy.Matrix (2w, n_rates)
        """
        bk = self._backend(beta, backend)
        b = self._beta(beta, bk)
        if bk is NUMERIC:
            return combine_checked(b, self.numeric()._layout.J2_terms())
        M = bk.zeros(2 * self.w, self.n_rates)
        for i, (u, sl) in enumerate(zip(self.wheels, self.rate_slices)):
            bk.set_block(M, 2 * i, sl.start, u.block(b[i], backend=bk))
        return M

    def F(self, beta: Numbers | None = None, backend: Backend | None = None) -> Matrix:
        r"""Functional matrix :math:`\mathbf F = [\mathbf J_1\ \ -\mathbf J_2]` (22)-(24).

        Its columns follow :attr:`qdot_names`.

        Parameters
        ----------
        beta : array (..., w), sequence of w SymPy expressions, or None
            Steering angles; ``None`` means the symbols :math:`\beta_1..\beta_w`.
        backend : NUMERIC or SYMBOLIC, optional
            As for :meth:`J2`.

        Returns
        -------
        numpy.ndarray (..., 2w, 3 + n_rates) or sympy.Matrix (2w, 3 + n_rates)
        """
        bk = self._backend(beta, backend)
        if bk is SYMBOLIC:
            return bk.broadcast_hstack(self.J1(backend=SYMBOLIC), -self.J2(beta, SYMBOLIC))
        b = self._beta(beta, bk)
        const = np.concatenate([self.J1(backend=NUMERIC), np.zeros((2 * self.w, self.n_rates))], axis=-1)
        return combine_checked(b, self.numeric()._layout.J2_terms(-1.0, 3, const))  # [J1  -J2]

    def J(self, beta: Numbers | None = None, L: Numbers = 1, backend: Backend | None = None) -> Matrix:
        r"""The product :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` (56).

        Parameters
        ----------
        beta : array (..., w), sequence of w SymPy expressions, or None
            Steering angles; ``None`` means the symbols :math:`\beta_1..\beta_w`.
        L : float or sympy.Expr, optional
            Characteristic length of :math:`\mathbf J_{L1}` (default 1: :math:`\mathbf J_1^T\mathbf J_2`).
        backend : NUMERIC or SYMBOLIC, optional
            As for :meth:`J2`.

        Returns
        -------
        numpy.ndarray (..., 3, n_rates) or sympy.Matrix (3, n_rates)
        """
        bk = self._backend(beta, backend)
        if bk is SYMBOLIC:
            return self.J1(L, backend=SYMBOLIC).T * self.J2(beta, SYMBOLIC)
        b = self._beta(beta, bk)
        with np.errstate(over="ignore", invalid="ignore"):
            terms = self.numeric()._layout.J_terms(self.J1(L, backend=NUMERIC))  # J = J_L1^T J2, term by term
            ok = np.isfinite(2 * np.abs(terms.p) + 2 * np.abs(terms.q)).all()  # |entry| <= |P_i| + |Q_i|
        if not ok:
            raise InputValueError(
                f"J overflows for this robot and L = {L!r}: the wheel radii times d_i / L exceed "
                "the double-precision range"
            )
        return combine_checked(b, terms)

    def numeric(self) -> Robot:
        r"""The same robot with float mount points and lengths (itself when it has no SymPy values).

        Exact robots (``paper_robot(..., exact=True)``, SymPy numbers such as :math:`\sqrt3/2`) become
        their float counterparts, for the batched numeric analyses.

        Returns
        -------
        Robot

        Raises
        ------
        wmr.errors.InputValueError
            If a mount point or a length contains a free symbol.

        Examples
        --------
        >>> from wmr import paper_robot
        >>> paper_robot(L=2, exact=True).numeric().mount_points[1].round(12).tolist()
        [1.0, 1.732050807569]
        """
        if not self.is_symbolic:
            return self
        if self.free_symbols:
            raise InputValueError(
                f"robot has free symbols {sorted(map(str, self.free_symbols))}: it has no numeric "
                f"counterpart ({checks.show(self)})"
            )
        return self._layout.memo("robot", lambda: Robot([u.numeric() for u in self.wheels], name=self.name))

    @property
    def free_symbols(self) -> set[Symbolic]:
        """The SymPy symbols in the mount points and lengths (an empty set for numeric and exact robots)."""
        return set(self._layout.free_symbols)

    # --- frames ---------------------------------------------------------------------------------
    def moved(self, origin: Point = (0.0, 0.0), angle: Numbers = 0.0) -> Robot:
        """The same robot described from another body frame, of origin ``origin`` and rotated by ``angle``.

        Mount points become :math:`\\mathbf d_i' = \\mathbf R(-\\text{angle})(\\mathbf d_i - \\text{origin})`
        and steering angles (fixed and Swedish wheels' own too) shift by ``-angle``; a twist becomes
        :math:`\\dot\\psi' = \\dot\\psi`, :math:`\\dot{\\mathbf c}' = \\mathbf R(-\\text{angle})(\\dot{\\mathbf c} +
        \\dot\\psi\\mathbf E\\,\\text{origin})`; joint rates do not change.

        Parameters
        ----------
        origin : pair, optional
            The new operation point, in the current body frame.
        angle : float, optional
            Rotation of the new body frame relative to the current one (radians, CCW).

        Returns
        -------
        Robot

        Examples
        --------
        >>> from wmr import CentredWheel
        >>> bot = Robot([CentredWheel((1.0, 0.0), r=0.1), CentredWheel((-1.0, 0.0), r=0.1)])
        >>> (bot.moved(origin=(1.0, 0.0), angle=np.pi / 2).mount_points.round(12) + 0.0).tolist()
        [[0.0, 0.0], [0.0, 2.0]]
        """
        moved = moved_points([u.position for u in self.wheels], origin, angle)  # (w, 2), checked
        angle = checks.number("angle", angle)
        try:
            return Robot([u.remounted(p, angle) for u, p in zip(self.wheels, moved, strict=True)], name=self.name)
        except InputValueError as e:
            raise InputValueError(f"origin = {checks.show(origin)} is too far from the mount points ({e})") from None
