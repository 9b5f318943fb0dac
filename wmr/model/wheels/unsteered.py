r"""Wheel units without a steering joint: the wheel frame is at a constant angle of the unit's own.

The paper models steered units only (offset, centred and dual wheels).  A unit without a steering
joint (the fixed wheel, the Swedish wheel) is mounted at :math:`P_i` (``position`` =
:math:`\mathbf d_i`) with a **constant** wheel-frame angle :math:`\beta_i` = ``angle``: the axle is
:math:`\mathbf i_i = \mathbf R(\beta_i)[1\ 0]^T` and the rolling direction
:math:`\mathbf j_i = \mathbf R(\beta_i)[0\ 1]^T = \mathbf E\mathbf i_i`, as for every unit
(:mod:`wmr.model.conventions`).  It enters the no-slip equation in the same form,
:math:`[\mathbf E\mathbf d_i\ \mathbf 1]\,\mathbf t = \mathbf B_i\dot{\boldsymbol\theta}_i` with
:math:`\mathbf B_i = \mathbf R(\beta_i)\mathbf L_i` (the i-th block row of (21)), so every kernel of the
package (:math:`\mathbf J_2`, :math:`\mathbf F`, :math:`\mathbf J`, mobility, kinematics) handles it
unchanged.  A robot's configuration keeps one entry per unit; the entry of a unit without a
steering joint is ignored and its own ``angle`` used (:meth:`wmr.Robot.effective_beta`).
"""

from __future__ import annotations

import math
from dataclasses import InitVar, dataclass, field, replace
from typing import ClassVar, Self

import numpy as np

from ...errors import InputValueError
from .. import checks
from ..backend import NUMERIC, Backend, choose
from ..lazysympy import is_sympy
from ..platform import rotated
from ..types import ArrayLike, FloatArray, Matrix, Numbers, Point
from .unit import WheelUnit

__all__ = ["UnsteeredUnit"]


def constant(name: str, value: Numbers) -> Numbers:
    """A constant angle: a finite real number (as a float), or an exact SymPy number kept exact (no free symbols)."""
    f = checks.number(name, value)  # an input error for symbols, NaN, inf, 10**400
    value = checks.real(name, value)
    return value if is_sympy(value) else f


def in_degrees(owner, name, value, degrees):
    """A constant angle: a finite real number (a float), or an exact SymPy number kept exact (no free symbols)."""
    if degrees is not None:
        if value is not None:
            raise InputValueError(f"{name}_deg: give {owner} {name} (radians) or {name}_deg (degrees), not both")
        return math.radians(checks.number(f"{name}_deg (degrees)", degrees))
    if value is None:
        raise checks.kind_error(name, value, f"an angle in radians (or give {owner} {name}_deg in degrees)")
    return value


def radians(name, value):
    """A constant angle in radians, refused beyond +-2 pi (almost surely degrees given by mistake)."""
    value = constant(name, value)
    if abs(float(value)) > 2 * np.pi + 1e-9:
        raise InputValueError(
            f"{name} is in radians and must be within +-2 pi, got {checks.show(value)} (degrees? write "
            f"{name}=math.radians({checks.show(value)}) or {name}_deg={checks.show(value)})"
        )
    return value


@dataclass(frozen=True)
class UnsteeredUnit(WheelUnit):
    """A unit without a steering joint: its wheel frame is at the constant angle ``angle`` (radians).

    Parameters
    ----------
    position : pair
        :math:`\\mathbf d_i`, body frame.
    r : float
        Wheel radius, > 0.
    angle : float
        The constant wheel-frame angle :math:`\\beta_i` in radians (an exact SymPy number is kept
        exact), within :math:`\\pm 2\\pi`.
    angle_deg : float, optional
        The same in degrees (keyword only), as the robot file's key: give ``angle`` or ``angle_deg``.
    driven : mapping or sequence of bool, optional
        Actuation of the joints.
    """

    angle: float = None  # type: ignore[assignment]
    angle_deg: InitVar[float | None] = field(default=None, kw_only=True)
    ANGLES: ClassVar[tuple[str, ...]] = ("angle",)

    def __post_init__(self, angle_deg=None, *more) -> None:
        object.__setattr__(self, "angle", in_degrees(type(self).__name__, "angle", self.angle, angle_deg))
        self._init_degrees(*more)
        super().__post_init__()

    def _init_degrees(self, *more) -> None:
        """Angles of a kind's own given in degrees (a kind with more extends this)."""

    def _validate(self):
        super()._validate()
        object.__setattr__(self, "angle", radians("angle", self.angle))

    @property
    def constant_angle(self) -> Numbers:
        """The unit's own angle (``angle``), which replaces its configuration entry."""
        return self.angle

    def remounted(self, position: Point, turn: Numbers) -> Self:
        """The same unit seen from a body frame turned by ``turn``: at ``position``, ``angle`` shifted by ``-turn``.

        Parameters
        ----------
        position : pair
        turn : float

        Returns
        -------
        UnsteeredUnit
        """
        return replace(self, position=position, angle=self.angle - turn)

    def own_angle(self, beta: ArrayLike) -> FloatArray:
        r"""The unit's constant angle, in the shape of ``beta`` (whose values are ignored, only checked).

        Parameters
        ----------
        beta : float or array (...)
            A configuration entry for this unit (validated, then ignored).

        Returns
        -------
        numpy.ndarray (...)
            ``angle`` everywhere.

        Examples
        --------
        >>> from wmr import FixedWheel
        >>> FixedWheel((0, 0), r=1, angle=0.5).own_angle([0.0, 3.0]).tolist()
        [0.5, 0.5]
        """
        return np.full(checks.finite_array("beta", beta).shape, float(self.angle))  # angle: checked when made

    def block(self, beta: Numbers, backend: Backend | None = None) -> Matrix:
        r"""This unit's block :math:`\mathbf B_i = \mathbf R(\text{angle})\mathbf L_i` of :math:`\mathbf J_2`.

        Parameters
        ----------
        beta : float, array (...) or sympy.Expr
            The configuration entry of this unit: checked, then ignored (the wheel is not steered;
            its own ``angle`` is used).  Sets the batch shape of a NumPy result.
        backend : NUMERIC or SYMBOLIC, optional
            Default: SymPy if ``beta`` or the unit's parameters are symbolic, else NumPy.

        Returns
        -------
        numpy.ndarray (..., 2, n_rates) or sympy.Matrix (2, n_rates)

        Examples
        --------
        >>> from wmr import FixedWheel
        >>> FixedWheel((0.0, 0.0), r=2.0, angle=0.0).block(1.0).tolist()     # beta = 1 ignored
        [[0.0], [-2.0]]
        """
        bk = choose(beta, *self._values(), backend=backend)
        angle: Numbers
        if bk is NUMERIC:
            angle = self.own_angle(beta)
        else:
            checks.real("beta", beta)
            angle = self.angle
        L, EL = self.block_terms(bk)
        return rotated((bk.cos(angle), bk.sin(angle)), L, EL)  # (11), at its own angle

    def points(self, beta: ArrayLike) -> dict[str, FloatArray]:
        r"""Points of the unit in the body frame, at its own angle (``beta`` sets the batch shape only).

        Parameters
        ----------
        beta : float or array (...)
            The configuration entry of this unit (ignored but for its shape).

        Returns
        -------
        dict of numpy.ndarray
            As :meth:`wmr.OffsetWheel.points`: ``"P"``, ``"H"`` (both :math:`P_i`), ``"wheels"``,
            ``"i"``, ``"j"``.

        Examples
        --------
        >>> from wmr import FixedWheel
        >>> FixedWheel((1.0, 0.0), r=0.1, angle=np.pi / 2).points(0.0)["i"].round(12).tolist()
        [0.0, 1.0]
        """
        return self._at(self.own_angle(beta))

    def beta_rate(self, psi_dot: ArrayLike, rates: ArrayLike, steer: ArrayLike | None = None) -> FloatArray:
        """The wheel frame does not turn on the platform: :math:`\\dot\\beta_i = 0`.

        Parameters
        ----------
        psi_dot : float or array (...)
            Platform turning rate (sets the shape).
        rates : array (..., n_rates)
            The unit's joint rates.
        steer : float or array (...), optional
            Ignored (there is no steering joint); checked.

        Returns
        -------
        numpy.ndarray (...)

        Examples
        --------
        >>> from wmr import FixedWheel
        >>> FixedWheel((0, 0), r=1, angle=0.0).beta_rate(0.3, [2.0]).tolist()
        0.0
        """
        return np.zeros(self._rates_in(psi_dot, rates, steer)[3])
