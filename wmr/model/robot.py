r"""The assembled robot: platform + wheel units, :math:`\mathbf J_1`, :math:`\mathbf J_2`, :math:`\mathbf F`.

Stacking the no-slip equation of every unit gives (21),
:math:`\mathbf J_1\mathbf t = \mathbf J_2\dot{\boldsymbol\theta}`, and its homogeneous form (22)-(23),
:math:`\mathbf F\dot{\mathbf q} = \mathbf 0` with the functional matrix
:math:`\mathbf F = [\mathbf J_1\ \ -\mathbf J_2]` (24) and the generalised rates
:math:`\dot{\mathbf q} = [\mathbf t^T\ \dot{\boldsymbol\theta}^T]^T` (25).  The layout of
:math:`\dot{\mathbf q}` is named (:attr:`Robot.qdot_names`) so that a reader can see which column
of :math:`\mathbf F` is which rate.

A robot is frozen and derives everything once, when it is made: its sizes and names, and (numeric and exact
robots) its mount points, :math:`\mathbf J_1`, the units' local blocks :math:`\mathbf L_i` and
:math:`\mathbf E\mathbf L_i` side by side (so that :math:`\mathbf J_2`, :math:`\mathbf F` and :math:`\mathbf J`
are sums of :class:`~wmr.model.trig.Terms`, with no loop over the units) and the column norms of :math:`\mathbf F`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any, NoReturn

import numpy as np

from ..errors import FrozenError, InputTypeError, InputValueError
from . import checks
from .backend import NUMERIC, SYMBOLIC, Backend, choose
from .lazysympy import sp
from .limits import check
from .platform import moved_points, point_row
from .tolerance import column_norms
from .trig import Terms, combine_checked
from .types import ArrayLike, FloatArray, IntArray, Matrix, Numbers, Point, Symbolic
from .wheels import WheelUnit, wheel_kinds

__all__ = ["Robot"]

#: the names of the twist's rates, the first columns of F
TWIST_NAMES = ("psi_dot", "x_dot", "y_dot")
#: what a robot with free symbols does not have (its numbers)
NUMBERS = ("mount_points", "F_column_norms", "_J1", "_L", "_EL", "_rate_unit", "_own", "_own_angle", "_J2", "_F")


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
    Frozen: setting or deleting an attribute raises :class:`~wmr.errors.FrozenError`; the attributes are
    derived once, when the robot is made (an exact robot's numbers when first asked for: turning its SymPy
    numbers into floats takes milliseconds).  Equality and hashing are by identity.

    Examples
    --------
    >>> from wmr import Robot, CentredWheel
    >>> bot = Robot([CentredWheel((1, 0), r=0.1), CentredWheel((-1, 0), r=0.1)])
    >>> bot.qdot_names
    ('psi_dot', 'x_dot', 'y_dot', 'theta_dot_1', 'theta_dot_2')
    >>> bot.F([0.0, 0.0]).shape
    (4, 5)
    """

    #: the units, in their numbering order
    wheels: tuple[WheelUnit, ...]
    #: the robot's name
    name: str
    #: number of wheel units
    w: int
    #: length of the joint-rate vector :math:`\dot{\boldsymbol\theta}`
    n_rates: int
    #: slice of each unit's rates inside :math:`\dot{\boldsymbol\theta}`
    rate_slices: tuple[slice, ...]
    #: True for the units with a steering joint (offset, centred, dual); :meth:`effective_beta`
    steered: tuple[bool, ...]
    #: names of the joint rates, in the column order of :math:`\mathbf J_2`
    rate_names: tuple[str, ...]
    #: names of the generalised rates (25): the columns of :math:`\mathbf F`
    qdot_names: tuple[str, ...]
    #: True when a mount point or a length of some unit is a SymPy expression
    is_symbolic: bool
    #: the SymPy symbols in the mount points and lengths (empty for numeric and exact robots)
    free_symbols: frozenset[Symbolic]
    #: the :math:`\mathbf d_i` as floats, (w, 2), read-only (not for robots with free symbols)
    mount_points: FloatArray
    #: lengths of the columns of :math:`\mathbf F` (22)-(24), the same at every configuration, (3 + n_rates,):
    #: :math:`\sqrt{\sum_i\|\mathbf d_i\|^2}`, :math:`\sqrt w`, :math:`\sqrt w`, then those of the units' local
    #: blocks; zero columns get 1 (:mod:`wmr.model.tolerance`; not for robots with free symbols)
    F_column_norms: FloatArray
    _J1: FloatArray
    _L: FloatArray
    _EL: FloatArray
    _rate_unit: IntArray
    _own: IntArray
    _own_angle: FloatArray
    _J2: Terms
    _F: Terms
    _twin: Robot
    _kept: dict

    def __init__(self, wheels: Iterable[WheelUnit], name: str | None = None) -> None:
        if not (name is None or isinstance(name, str)):
            raise checks.kind_error("name", name, "a string or None")
        if isinstance(wheels, (str, bytes, WheelUnit)) or not hasattr(wheels, "__iter__"):
            raise InputTypeError(f"wheels must be a sequence of wheel units, got {checks.show(wheels)}")
        wheels = tuple(wheels)
        if len(wheels) == 0:
            raise InputValueError("wheels must contain at least one wheel unit, got 0")
        check("wheels", len(wheels), "wheels")
        for k, u in enumerate(wheels):
            if not isinstance(u, WheelUnit):
                kinds = ", ".join(t.__name__ for t in wheel_kinds().values())
                raise InputTypeError(f"wheels[{k}] must be a wheel unit ({kinds}, ...), got {checks.show(u)}")
        stops = np.cumsum([u.n_rates for u in wheels]).tolist()
        symbolic = any(u.is_symbolic for u in wheels)
        names = tuple(f"{n}_dot_{i}{suffix}" for i, u in enumerate(wheels, 1) for n, _, suffix in u.RATES)
        made = object.__setattr__  # the only assignments: the robot is frozen from here on
        for attr, value in dict(
            wheels=wheels,
            name=name or "robot",
            w=len(wheels),
            n_rates=stops[-1],
            rate_slices=tuple(slice(a, b) for a, b in zip([0] + stops[:-1], stops)),
            steered=tuple(bool(u.steered) for u in wheels),
            rate_names=names,
            qdot_names=TWIST_NAMES + names,
            is_symbolic=symbolic,
            free_symbols=frozenset().union(*(u.free_symbols for u in wheels)) if symbolic else frozenset(),
            _kept={},
        ).items():
            made(self, attr, value)
        if not symbolic:
            made(self, "_twin", self)
            for attr, value in _numbers(wheels).items():
                made(self, attr, value)

    def __getattr__(self, attr: str) -> Any:
        """The numbers of a symbolic robot (only they are missing): its float twin's, made when first asked for."""
        if (attr in NUMBERS or attr == "_twin") and "free_symbols" in self.__dict__:
            if not self.free_symbols:  # exact: SymPy numbers to floats (milliseconds: not before they are needed)
                twin = Robot([u.numeric() for u in self.wheels], name=self.name)
                for name in NUMBERS:
                    object.__setattr__(self, name, getattr(twin, name))
                object.__setattr__(self, "_twin", twin)
                return getattr(self, attr)
            for u in self.wheels:
                for v in u.position:
                    checks.number("position", v)
            raise InputValueError(
                f"robot has free symbols {sorted(map(str, self.free_symbols))}: it has no {attr.strip('_')}"
            )
        raise AttributeError(f"{type(self).__name__!r} object has no attribute {attr!r}")

    def __setattr__(self, attr: str, value: Any = None) -> NoReturn:
        raise FrozenError(f"a Robot cannot be changed once made ({attr}): build a new one, Robot(wheels, name=...)")

    __delattr__ = __setattr__

    def __repr__(self):
        kinds = ", ".join(f"{u.kind}@{tuple(u.position)}" for u in self.wheels)
        return f"Robot({self.name!r}: {kinds})"

    def _memo(self, key: object, make: Callable[[], Any]) -> Any:
        """``make()``, computed once per robot and ``key`` (constant data an analysis derives from the robot)."""
        if key not in self._kept:
            self._kept[key] = make()
        return self._kept[key]

    # --- symbols ---------------------------------------------------------------------------------
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
        if self._own.size:  # (a copy: the caller's array is not changed)
            beta = beta.copy()
            beta[..., self._own] = self._own_angle
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
        M = self._J1.copy()  # then its first column / L
        with np.errstate(over="ignore"):
            M[:, 0] /= float(L)
        if not np.isfinite(M).all():
            raise InputValueError(
                f"L (characteristic length) = {L!r} is too small for mount points of size "
                f"{np.abs(self.mount_points).max():.3g}: d_i / L overflows"
            )
        return M

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
            return combine_checked(b, self._J2)
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
        return combine_checked(self._beta(beta, bk), self._F)  # [J1  -J2]

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
            terms = _J_terms(self, self.J1(L, backend=NUMERIC))  # J = J_L1^T J2, term by term
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
        if self.free_symbols:
            raise InputValueError(
                f"robot has free symbols {sorted(map(str, self.free_symbols))}: it has no numeric "
                f"counterpart ({checks.show(self)})"
            )
        return self._twin

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


def _numbers(wheels: tuple[WheelUnit, ...]) -> dict[str, Any]:
    r"""The numbers of a numeric robot: :math:`\mathbf d_i`, :math:`\mathbf J_1` (21), the blocks, the terms of J2, F."""
    w = len(wheels)
    d = np.array([u.position for u in wheels], dtype=float).reshape(w, 2)
    J1 = _J1_of(d)
    blocks = [u.block_terms(NUMERIC) for u in wheels]
    L = np.concatenate([np.asarray(b[0], dtype=float) for b in blocks], axis=1)  # (2, n): the L_i side by side
    EL = np.concatenate([np.asarray(b[1], dtype=float) for b in blocks], axis=1)
    unit = np.repeat(np.arange(w), [u.n_rates for u in wheels])  # the unit of each joint rate
    made = dict(
        _J2=_J2_terms(w, unit, L, EL),
        _F=_J2_terms(w, unit, -L, -EL, 3, np.concatenate([J1, np.zeros((2 * w, unit.size))], axis=1)),
    )
    own = [i for i, u in enumerate(wheels) if u.constant_angle is not None]
    d.setflags(write=False)
    return made | dict(
        mount_points=d,
        F_column_norms=np.concatenate([column_norms(J1), column_norms(L)]),
        _J1=J1,
        _L=L,
        _EL=EL,
        _rate_unit=unit,
        _own=np.array(own, dtype=np.intp),
        _own_angle=np.array([float(wheels[i].constant_angle) for i in own]),
    )


def _J1_of(d: FloatArray) -> FloatArray:
    r""":math:`\mathbf J_1` (21) of mount points ``d`` (w, 2): its rows :math:`[\mathbf E\mathbf d_i\ \mathbf 1]` (5)."""
    J1 = np.zeros((2 * len(d), 3))
    J1[0::2, 0], J1[1::2, 0], J1[0::2, 1], J1[1::2, 2] = -d[:, 1], d[:, 0], 1.0, 1.0  # E d = [-dy, dx]
    return J1


def _J2_terms(w: int, unit: IntArray, L: FloatArray, EL: FloatArray, offset: int = 0, const: Any = None) -> Terms:
    r"""The terms of :math:`\mathbf J_2` (blocks ``L``, ``EL``) placed at column ``offset`` of a (2w, offset + n) matrix.

    Column ``c`` of :math:`\mathbf J_2` has rows :math:`2u, 2u+1` (:math:`u` its unit):
    :math:`\cos\beta_u\,\mathbf L_{:,c} + \sin\beta_u\,\mathbf E\mathbf L_{:,c}` (11).  For
    :math:`\mathbf F` (24): ``-L``, ``-EL``, ``offset`` 3 and ``const`` :math:`[\mathbf J_1\ \mathbf 0]`.
    """
    n = unit.size
    width = offset + n
    entry = np.concatenate([(2 * unit + r) * width + offset + np.arange(n) for r in (0, 1)])
    p, q = L.ravel(), EL.ravel()
    keep = (p != 0.0) | (q != 0.0)
    return Terms((2 * w, width), entry[keep], np.tile(unit, 2)[keep], p[keep], q[keep], const)


def _J_terms(robot: Robot, JL1: FloatArray) -> Terms:
    r"""The terms of :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` (56), (3, n).

    Column ``c`` (unit :math:`u`) is :math:`\cos\beta_u\,\mathbf J_{L1,u}^T\mathbf L_{:,c} + \sin\beta_u\,
    \mathbf J_{L1,u}^T\mathbf E\mathbf L_{:,c}`, with :math:`\mathbf J_{L1,u}` the unit's two rows of :math:`\mathbf J_{L1}` (32).
    """
    u = robot._rate_unit
    rows = JL1.reshape(-1, 2, 3)[u]  # (n, 2, 3): J_L1,u of each column
    P = np.einsum("nkr,kn->rn", rows, robot._L)  # (3, n)
    Q = np.einsum("nkr,kn->rn", rows, robot._EL)
    n = u.size
    entry = (np.arange(3)[:, None] * n + np.arange(n)).ravel()
    p, q = P.ravel(), Q.ravel()
    keep = (p != 0.0) | (q != 0.0)
    return Terms((3, n), entry[keep], np.tile(u, 3)[keep], p[keep], q[keep])
