r"""The wheel unit in general: what every kind of :mod:`wmr.model.wheels` shares and answers.

A unit mounted at :math:`P_i` (``position`` = :math:`\mathbf d_i`) contributes the block
:math:`\mathbf B_i(\beta_i) = \mathbf R_{bwi}\mathbf L_i` of :math:`\mathbf J_2` (21), where
:math:`\mathbf L_i` (2 x ``n_rates``) is its constant local block and :math:`\mathbf R_{bwi}` the
rotation (11) by the angle :math:`\beta_i` of its wheel frame.  Steered units take :math:`\beta_i` from
the robot's configuration; units without a steering joint (``steered = False``) have a constant
angle of their own.

A kind is a subclass of :class:`WheelUnit` (a frozen dataclass) that answers for itself:

=======================  ===========================================================================
what                     declared by the kind as
=======================  ===========================================================================
its name                 ``kind``, the ``type`` of its table in a robot file (registers the class)
its block of J2          :meth:`~WheelUnit.local_block` :math:`\mathbf L_i`; its twist constraints are
                         the left null space of that block (:func:`wmr.analysis.mobility.twist_constraints`)
its joints               ``JOINTS`` (:mod:`~wmr.model.wheels.joints`): steer, swivel, drive, roller,
                         each driven or passive by default; the rates are those of the joints
                         in :math:`\mathbf J_2`; ``steered`` follows from them
its steering             :meth:`~WheelUnit.beta_rate`; :meth:`~WheelUnit.steering_row` if its rates
                         turn it in a way the block leaves free (a dual wheel); ``rolls_in_plane``
its geometry             :meth:`~WheelUnit.points` (batched, :mod:`~wmr.model.wheels.geometry`); how it
                         is drawn is the drawing layer's entry for it (:mod:`wmr.plot.parts`)
its angles               ``ANGLES``: which of its parameters are angles (the others are lengths)
=======================  ===========================================================================

Defining the subclass registers the kind (:mod:`~wmr.model.wheels.registry`); the robot and the
analyses then take it without a change.  The outer layers hold their own entries per kind: its keys
in a robot file (:mod:`wmr.io.wheel_tables`), its bodies and joints for URDF and a physics engine
(:mod:`wmr.io.mechanism`), its drawing (:mod:`wmr.plot.parts`) and what the design advice makes of it
(:mod:`wmr.analysis.unit_design`; the defaults say nothing).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any, ClassVar, Self

import numpy as np

from ...errors import InputValueError
from .. import checks
from ..backend import NUMERIC, Backend, choose
from ..lazysympy import is_sympy, sp
from ..platform import E, rotated
from ..types import ArrayLike, FloatArray, Matrix, Numbers, Point, Symbolic
from .geometry import UnitGeometry
from .joints import Joint, actuation
from .registry import register

__all__ = ["WheelUnit"]


@dataclass(frozen=True)
class WheelUnit(UnitGeometry):
    r"""A wheel unit at :math:`P_i`: the base of every wheel kind.

    Parameters
    ----------
    position : pair
        :math:`\mathbf d_i = \overrightarrow{CP_i}`, body frame.
    r : float
        Wheel radius, > 0.
    driven : mapping of str to bool, or sequence of bool, optional
        Which joints a motor drives (keyword only): ``{joint name: bool}`` for the joints that
        differ from the kind's defaults (``JOINTS``), or one bool per joint; stored as a tuple of
        bools in the order of ``JOINTS`` (:attr:`joints`).
    """

    position: tuple
    r: float
    driven: Any = dataclasses.field(default=None, kw_only=True)

    #: the kind's name, the ``type`` of its table in a robot file; a class that sets it is registered
    kind: ClassVar[str] = ""
    #: the joints, with their default actuation (:mod:`~wmr.model.wheels.joints`)
    JOINTS: ClassVar[tuple[Joint, ...]] = ()
    #: the fields of its :meth:`parameters` that are angles (radians); the others are lengths
    ANGLES: ClassVar[tuple[str, ...]] = ()
    #: True when no slip holds the mount point to the wheel plane: :math:`P_i` moves only along
    #: :math:`\mathbf j_i` (a steered unit of this sort is steered to its mount point's velocity)
    rolls_in_plane: ClassVar[bool] = False
    # set from JOINTS for every subclass:
    #: the rate variables, in the order of the unit's columns of J2: (plain name, TeX letter, suffix)
    RATES: ClassVar[tuple[tuple[str, str, str], ...]] = ()
    n_rates: ClassVar[int] = 0
    #: True when the unit has a steering joint (its angle is an entry of the robot's configuration)
    steered: ClassVar[bool] = False
    # derived once, when a unit is made (instance attributes, set by __post_init__; not dataclass fields):
    #: True when the position or a length of the unit is a SymPy expression
    is_symbolic: ClassVar[bool]
    #: the SymPy symbols in the unit's position and parameters (empty for numbers and exact numbers)
    free_symbols: ClassVar[frozenset[Symbolic]]
    #: the unit's joints, with its own actuation (``driven``), in the order of ``JOINTS``
    joints: ClassVar[tuple[Joint, ...]]

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        names = [j.name for j in cls.JOINTS]
        if len(set(names)) != len(names):
            raise InputValueError(f"{cls.__name__}.JOINTS must have distinct names, got {names}")
        cls.RATES = tuple(j.rate for j in cls.JOINTS if j.rate is not None)
        cls.n_rates = len(cls.RATES)
        cls.steered = any(j.steering for j in cls.JOINTS)
        if "kind" in vars(cls) and cls.kind:
            register(cls)

    def __post_init__(self) -> None:
        object.__setattr__(self, "position", checks.point("position", self.position))
        object.__setattr__(self, "r", checks.positive("r (wheel radius)", self.r))
        object.__setattr__(self, "driven", actuation(self.JOINTS, self.driven, type(self).__name__))
        self._validate()
        values = self._values()
        symbolic = any(is_sympy(v) for v in values)
        made = object.__setattr__
        made(self, "is_symbolic", symbolic)
        made(self, "free_symbols", frozenset().union(*(v.free_symbols for v in values if is_sympy(v))))
        if not symbolic:
            with np.errstate(over="ignore", invalid="ignore"):
                if not np.isfinite(4 * np.abs(np.asarray(self.position, dtype=float))).all():
                    raise InputValueError(
                        f"position is too large for double-precision kinematics (4 |d_i| "
                        f"overflows): {checks.show(self.position)}"
                    )
                for name, v in self.parameters().items():  # a length whose reciprocal overflows (a subnormal)
                    if name not in self.ANGLES and v != 0 and not np.isfinite(1.0 / abs(float(v))):
                        raise InputValueError(
                            f"{name} is too small for double-precision kinematics (1/{name} overflows): {checks.show(v)}"
                        )
                L, EL = (np.asarray(m, dtype=float) for m in self.block_terms(NUMERIC))
                ok = np.isfinite(2 * np.abs(L) + 2 * np.abs(EL)).all()
            if not ok:
                raise InputValueError(
                    f"{type(self).__name__} has lengths too large for double-precision "
                    f"kinematics (R(beta) L_i would overflow): {checks.show(self)}"
                )
        made(self, "joints", tuple(dataclasses.replace(j, driven=d) for j, d in zip(self.JOINTS, self.driven)))

    def _validate(self) -> None:
        """Check and convert the kind's own fields (a kind with fields of its own extends this)."""

    # --- joints and rates ----------------------------------------------------------------------
    def rate_names(self, i: int) -> tuple[str, ...]:
        """Plain names of this unit's rate variables when it is wheel ``i``.

        Parameters
        ----------
        i : int
            The unit's number in the robot (1-based, the paper's numbering).

        Returns
        -------
        tuple of str
            ``n_rates`` names, in the order of the unit's columns of :math:`\\mathbf J_2`.

        Examples
        --------
        >>> from wmr import OffsetWheel, DualWheel
        >>> OffsetWheel((0, 0), r=1, d=0.5).rate_names(2)
        ('phi_dot_2', 'theta_dot_2')
        >>> DualWheel((0, 0), r=1, b=0.5).rate_names(3)
        ('theta_dot_31', 'theta_dot_32')
        """
        i = checks.integer("i", i, minimum=1)
        return tuple(f"{name}_dot_{i}{suffix}" for name, _, suffix in self.RATES)

    def rate_symbols(self, i: int) -> tuple[Symbolic, ...]:
        """SymPy symbols of the rate variables of wheel ``i``, typeset as in the paper.

        Parameters
        ----------
        i : int
            The unit's number in the robot (1-based).

        Returns
        -------
        tuple of sympy.Symbol
            ``n_rates`` real symbols, in the order of :meth:`rate_names`.

        Examples
        --------
        >>> from wmr import CentredWheel
        >>> CentredWheel((0, 0), r=1).rate_symbols(1)
        (\\dot{\\theta}_{1},)
        """
        i = checks.integer("i", i, minimum=1)
        return tuple(sp.Symbol(rf"\dot{{{tex}}}_{{{i}{suffix}}}", real=True) for _, tex, suffix in self.RATES)

    # --- steering --------------------------------------------------------------------------------
    def beta_rate(self, psi_dot: ArrayLike, rates: ArrayLike, steer: ArrayLike | None = None) -> FloatArray:
        """Steering rate :math:`\\dot\\beta_i` of the unit on the platform (used by the simulation).

        Parameters
        ----------
        psi_dot : float or array (...)
            Platform turning rate.
        rates : array (..., n_rates)
            The unit's joint rates.
        steer : float or array (...), optional
            Steering-rate input (for units steered independently of their rates).

        Returns
        -------
        numpy.ndarray (...)
        """
        raise NotImplementedError(f"{type(self).__name__} does not say how it steers (beta_rate)")

    def steering_row(self) -> FloatArray | None:
        r"""How the unit's rates turn it where its block leaves them free, or None.

        A row :math:`\mathbf c` with :math:`\mathbf c\,\dot{\boldsymbol\theta}_i = \dot\psi + \dot\beta_i`
        and :math:`\mathbf L_i\mathbf c^T = \mathbf 0` (a dual wheel's rate difference, the corrected (15)),
        which inverse kinematics adds for the steering rate wanted (:func:`wmr.inverse`'s ``beta_dot``).

        Returns
        -------
        numpy.ndarray (n_rates,) or None
            None for the other kinds (their steering is one of their rates, an independent input,
            or absent).
        """
        return None

    def _rates_in(
        self, psi_dot: ArrayLike, rates: ArrayLike, steer: ArrayLike | None
    ) -> tuple[FloatArray, FloatArray, FloatArray | None, tuple[int, ...]]:
        """``psi_dot`` (...), ``rates`` (..., n_rates) and ``steer`` (... or None), checked, and their batch shape."""
        psi_dot = checks.finite_array("psi_dot", psi_dot)
        rates = checks.finite_array("rates", rates, last=self.n_rates)
        steer = None if steer is None else checks.finite_array("steer", steer)
        shape = checks.batch_shape({"psi_dot": psi_dot, "rates": rates[..., 0], "steer": steer}, core=0)
        return psi_dot, rates, steer, shape

    @staticmethod
    def _finite_rate(out: FloatArray, rates: FloatArray) -> FloatArray:
        if not np.isfinite(out).all():
            raise InputValueError(
                f"rates or psi_dot are too large: the steering rate overflows "
                f"(largest |rates| = {np.abs(rates).max():.3g})"
            )
        return out

    # --- parameters --------------------------------------------------------------------------------
    def parameters(self) -> dict[str, Numbers]:
        """The unit's lengths and angles by field name (its dataclass fields but ``position`` and ``driven``).

        Returns
        -------
        dict of str to float or sympy.Expr

        Examples
        --------
        >>> from wmr import OffsetWheel
        >>> OffsetWheel((0, 0), r=0.1, d=0.02).parameters()
        {'r': 0.1, 'd': 0.02}
        """
        return {f.name: getattr(self, f.name) for f in dataclasses.fields(self) if f.name not in ("position", "driven")}

    def numeric(self) -> Self:
        """The same unit with float position and parameters (SymPy numbers such as :math:`\\sqrt3/2` evaluated).

        Returns
        -------
        WheelUnit
            Of the same kind (itself when it holds no SymPy values).

        Raises
        ------
        wmr.errors.InputValueError
            If a value has a free symbol.
        """
        if not self.is_symbolic:
            return self
        if self.free_symbols:
            raise InputValueError(
                f"{type(self).__name__} has free symbols {sorted(map(str, self.free_symbols))}: it "
                f"has no numeric counterpart ({checks.show(self)})"
            )

        def num(v):
            return float(v) if is_sympy(v) else v

        return dataclasses.replace(
            self, position=tuple(map(num, self.position)), **{k: num(v) for k, v in self.parameters().items()}
        )

    def _values(self):
        """The unit's parameters as a flat tuple (position coordinates, lengths, angles)."""
        return (*self.position, *self.parameters().values())

    def remounted(self, position: Point, turn: Numbers) -> Self:
        """The same unit described from a body frame turned by ``turn``, with its mount point at ``position``.

        Parameters
        ----------
        position : pair
            :math:`\\mathbf d_i` in the new body frame.
        turn : float
            The rotation of the new body frame relative to the old (radians).

        Returns
        -------
        WheelUnit
            Of the same kind (a unit with a constant angle has it shifted by ``-turn``).
        """
        return dataclasses.replace(self, position=position)

    # --- the block of J2 -------------------------------------------------------------------------
    def local_block(self, backend: Backend = NUMERIC) -> Matrix:
        r"""The unit's constant local block :math:`\mathbf L_i` (its block of :math:`\mathbf J_2` at :math:`\beta = 0`).

        Parameters
        ----------
        backend : NUMERIC or SYMBOLIC, optional

        Returns
        -------
        numpy.ndarray (2, n_rates) or sympy.Matrix (2, n_rates)
        """
        raise NotImplementedError(f"{type(self).__name__} does not give its block (local_block)")

    def block(self, beta: Numbers, backend: Backend | None = None) -> Matrix:
        r"""This unit's block :math:`\mathbf B_i(\beta_i) = \mathbf R_{bwi}\mathbf L_i` of :math:`\mathbf J_2`.

        Evaluated as :math:`\cos\beta_i\,\mathbf L_i + \sin\beta_i\,\mathbf E\mathbf L_i` (11) from :meth:`block_terms`.

        Parameters
        ----------
        beta : float, array (...) or sympy.Expr
            Steering angle :math:`\beta_i` of the intermediate body.
        backend : NUMERIC or SYMBOLIC, optional
            Default: SymPy if ``beta`` or the unit's parameters are symbolic, else NumPy.

        Returns
        -------
        numpy.ndarray (..., 2, n_rates) or sympy.Matrix (2, n_rates)

        Examples
        --------
        >>> from wmr import CentredWheel
        >>> CentredWheel((0.0, 0.0), r=2.0).block(0.0).tolist()     # (51): R(0) [0, -r]^T
        [[0.0], [-2.0]]
        """
        bk = choose(beta, *self._values(), backend=backend)
        beta = checks.finite_array("beta", beta) if bk is NUMERIC else checks.real("beta", beta)
        L, EL = self.block_terms(bk)
        return rotated((bk.cos(beta), bk.sin(beta)), L, EL)  # (11): R(beta) L = cos L + sin E L

    def block_terms(self, backend: Backend = NUMERIC) -> tuple[Matrix, Matrix]:
        r"""The constant pair :math:`(\mathbf L_i, \mathbf E\mathbf L_i)` with
        :math:`\mathbf B_i(\beta) = \cos\beta\,\mathbf L_i + \sin\beta\,\mathbf E\mathbf L_i`.

        Every batched kernel (J2, F, J, the mobility constraints, the kinematics) is assembled from this pair.

        Parameters
        ----------
        backend : NUMERIC or SYMBOLIC, optional

        Returns
        -------
        tuple of two numpy.ndarray (2, n_rates) or sympy.Matrix (2, n_rates)
        """
        L = self.local_block(backend)
        return L, E(backend) @ L
