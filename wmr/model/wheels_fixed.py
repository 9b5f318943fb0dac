r"""Wheels without a steering joint: the fixed conventional wheel and the Swedish (omni / mecanum) wheel.

The paper models steered units only (offset, centred and dual wheels, :mod:`wmr.model.wheels`).  The
two units here are mounted at :math:`P_i` (``position`` = :math:`\mathbf d_i`) with a **constant**
wheel-frame angle :math:`\beta_i` = ``angle``: the axle is :math:`\mathbf i_i = \mathbf R(\beta_i)[1\ 0]^T`
and the rolling direction :math:`\mathbf j_i = \mathbf R(\beta_i)[0\ 1]^T = \mathbf E\mathbf i_i`, as for
every unit (:mod:`wmr.model.conventions`).  They enter the no-slip equation in the same form,
:math:`[\mathbf E\mathbf d_i\ \mathbf 1]\,\mathbf t = \mathbf B_i\dot{\boldsymbol\theta}_i` with
:math:`\mathbf B_i = \mathbf R(\beta_i)\mathbf L_i` (the i-th block row of (21)), so every kernel of the
package (:math:`\mathbf J_2`, :math:`\mathbf F`, :math:`\mathbf J`, mobility, kinematics) handles them
unchanged.  A robot's configuration keeps one entry per unit; the entry of a unit without a
steering joint is ignored and its own ``angle`` used (:meth:`wmr.Robot.effective_beta`).

=====================  =======================================  =====================================================================================
unit                   rates :math:`\dot{\boldsymbol\theta}_i`  local block :math:`\mathbf L_i` (:math:`\mathbf B_i = \mathbf R(\beta_i)\mathbf L_i`)
=====================  =======================================  =====================================================================================
:class:`FixedWheel`    :math:`\dot\theta_i`                     :math:`[0\ \ -r]^T` (the centred wheel's (51), not steered)
:class:`SwedishWheel`  :math:`\dot\theta_i,\ \dot\sigma_i`      :math:`\begin{bmatrix}0 & r\sin\gamma\\ -r & -r\cos\gamma\end{bmatrix}`
=====================  =======================================  =====================================================================================

Examples
--------
>>> import numpy as np
>>> omni = SwedishWheel((0.0, 0.0), r=0.5, angle=0.0, roller=np.pi / 2)
>>> (omni.block(0.0).round(12) + 0.0).tolist()      # rolls along j (theta) and along i (free roller)
[[0.0, 0.5], [-0.5, 0.0]]
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from . import validation as V
from .backend import NUMERIC, choose
from .platform import rotated
from .tolerance import TOL
from .wheel_base import _Unit
from .wheels import CentredWheel

__all__ = ["FixedWheel", "SwedishWheel"]


def _constant(name, value):
    """A constant angle: a finite real number (float), or an exact SymPy number kept exact (no free symbols)."""
    f = V.number(name, value)                       # TypeError for symbols, ValueError for NaN, inf, 10**400
    value = V.real(name, value)
    return value if isinstance(value, sp.Basic) else f


@dataclass(frozen=True)
class _Unsteered(_Unit):
    """A unit without a steering joint: its wheel frame is at the constant angle ``angle``."""

    angle: float

    steered = False

    def __post_init__(self):
        super().__post_init__()
        object.__setattr__(self, "angle", _constant("angle", self.angle))

    def own_angle(self, beta):
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
        >>> FixedWheel((0, 0), r=1, angle=0.5).own_angle([0.0, 3.0]).tolist()
        [0.5, 0.5]
        """
        beta = V.finite_array("beta", beta)
        return np.full(beta.shape, V.number("angle", self.angle))

    def block(self, beta, backend=None):
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
        >>> FixedWheel((0.0, 0.0), r=2.0, angle=0.0).block(1.0).tolist()     # beta = 1 ignored
        [[0.0], [-2.0]]
        """
        bk = choose(beta, *self._values(), backend=backend)
        if bk is NUMERIC:
            angle = self.own_angle(beta)
        else:
            V.real("beta", beta)
            angle = self.angle
        return rotated(angle, *self.block_terms(bk), backend=bk)

    def points(self, beta):
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
        >>> FixedWheel((1.0, 0.0), r=0.1, angle=np.pi / 2).points(0.0)["i"].round(12).tolist()
        [0.0, 1.0]
        """
        return super().points(self.own_angle(beta))

    def beta_rate(self, psi_dot, rates, steer=None):
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
        >>> FixedWheel((0, 0), r=1, angle=0.0).beta_rate(0.3, [2.0]).tolist()
        0.0
        """
        psi_dot, rates, steer = self._rates_in(psi_dot, rates, steer)
        shape = V.batch_shape({"psi_dot": psi_dot, "rates": rates[..., 0], "steer": steer}, core=0)
        return np.zeros(shape)


@dataclass(frozen=True)
class FixedWheel(_Unsteered):
    r"""Fixed conventional wheel: a centred wheel without a steering joint, at the constant angle ``angle``.

    The wheel centre is :math:`P_i`; rolling without slip is :math:`\dot{\mathbf p}_i =
    -r\dot\theta_i\mathbf j_i` (6) with :math:`\mathbf j_i = \mathbf R(\text{angle})[0\ 1]^T`, so its block is
    the centred wheel's (51) at :math:`\beta_i = \text{angle}`,
    :math:`\mathbf B_i = \mathbf R(\text{angle})[0\ \ -r]^T`.  It imposes on the platform twist the
    constraint orthogonal to the wheel plane, :math:`\mathbf i_i^T[\mathbf E\mathbf d_i\ \mathbf 1]\mathbf t = 0`
    (no lateral slip), at every configuration.

    Parameters
    ----------
    position : pair
        :math:`\mathbf d_i = \overrightarrow{CP_i}`, body frame.
    r : float
        Wheel radius, > 0.
    angle : float
        The constant wheel-frame angle :math:`\beta_i` (radians; an exact SymPy number such as
        ``sympy.pi / 2`` is kept exact): 0 puts the axle along the body x axis (the wheel rolls
        along body y).

    Examples
    --------
    >>> left = FixedWheel((0.0, 0.2), r=0.05, angle=np.pi / 2)     # axle along y: rolls along x
    >>> (left.block(0.0).round(12) + 0.0).tolist()
    [[0.05], [0.0]]
    """

    kind = "fixed"

    # a centred wheel held at beta_i = angle: its rolling rate and its block (51), written once there
    RATES = CentredWheel.RATES
    _local_block = CentredWheel._local_block


@dataclass(frozen=True)
class SwedishWheel(_Unsteered):
    r"""Swedish wheel (omni or mecanum): a fixed wheel whose rim carries free rollers at ``roller`` to the axle.

    **Model.**  The wheel frame is at the constant angle :math:`\beta_i` = ``angle`` (axle
    :math:`\mathbf i_i`, rolling direction :math:`\mathbf j_i = \mathbf E\mathbf i_i`); the axis of the
    roller in contact with the ground makes the angle :math:`\gamma` = ``roller`` with the axle,
    counter-clockwise seen from above:

    .. math:: \mathbf a_i = \cos\gamma\,\mathbf i_i + \sin\gamma\,\mathbf j_i .

    The contact point of the roller does not slip, so the wheel spin :math:`\dot\theta_i` (about
    :math:`\mathbf i_i`) moves the hub by :math:`-r\dot\theta_i\mathbf j_i`, as for any wheel (6), and
    the roller spin about :math:`\mathbf a_i` moves it along the roller's own rolling direction
    :math:`\mathbf E\mathbf a_i` by :math:`-r\dot\sigma_i\mathbf E\mathbf a_i`:

    .. math:: \dot{\mathbf p}_i = -r\dot\theta_i\,\mathbf j_i - r\dot\sigma_i\,\mathbf E\mathbf a_i ,
              \qquad
              \mathbf L_i = \begin{bmatrix}0 & r\sin\gamma\\ -r & -r\cos\gamma\end{bmatrix},
              \quad \mathbf B_i = \mathbf R(\beta_i)\mathbf L_i .

    :math:`\dot\sigma_i` is the free roller rate expressed at the wheel radius (a roller of contact
    radius :math:`\rho` spinning at :math:`\omega` gives :math:`\dot\sigma_i = \rho\omega/r`), so that both
    columns of :math:`\mathbf B_i` are lengths like every column of :math:`\mathbf J_2` and its
    condition number does not depend on the unit of length.

    **The constraint.**  Projected on the roller axis (:math:`\mathbf a_i^T\mathbf E\mathbf a_i = 0`,
    :math:`\mathbf a_i^T\mathbf j_i = \sin\gamma`), the no-slip equation leaves one relation, which
    involves the wheel rate only (Campion, Bastin & d'Andrea-Novel 1996, with their angle
    :math:`\pi/2 - \gamma` measured from the wheel plane):

    .. math:: \mathbf a_i^T[\mathbf E\mathbf d_i\ \ \mathbf 1]\,\mathbf t = -r\sin\gamma\,\dot\theta_i .

    :math:`\det\mathbf L_i = r^2\sin\gamma \ne 0`: every hub velocity is realised by some
    :math:`(\dot\theta_i, \dot\sigma_i)`, so a Swedish wheel puts **no** constraint on the platform
    twist (it adds nothing to Campion's :math:`\mathbf C_1^*`), and inverse kinematics is exact.
    :math:`\gamma \to 0` makes the rollers parallel to the axle: the two columns become parallel and
    the wheel a conventional one (use :class:`FixedWheel`), so ``roller`` = 0 is rejected.

    Parameters
    ----------
    position : pair
        :math:`\mathbf d_i = \overrightarrow{CP_i}`, body frame.
    r : float
        Wheel radius, > 0.
    angle : float
        The constant wheel-frame angle :math:`\beta_i` (radians; 0: axle along body x; an exact
        SymPy number is kept exact).
    roller : float
        :math:`\gamma`, the angle from the axle to the roller axes (radians), in
        :math:`(-\pi/2, \pi/2]` and not 0: :math:`\pi/2` is an omni wheel, :math:`\pm\pi/4` the two
        hands of a mecanum wheel (a mecanum robot mixes both).

    Examples
    --------
    >>> mec = SwedishWheel((0.3, 0.2), r=0.05, angle=0.0, roller=np.pi / 4)
    >>> mec.rate_names(1)
    ('theta_dot_1', 'sigma_dot_1')
    >>> (mec.block(0.0) / 0.05).round(6).tolist()
    [[0.0, 0.707107], [-1.0, -0.707107]]
    """

    roller: float

    kind = "swedish"
    RATES = (("theta", r"\theta", ""), ("sigma", r"\sigma", ""))

    def __post_init__(self):
        super().__post_init__()
        name = "roller (angle of the rollers to the axle)"
        g = _constant(name, self.roller)
        if not -np.pi / 2 < float(g) <= np.pi / 2 or abs(float(g)) <= TOL:
            raise ValueError(f"{name} must be in (-pi/2, pi/2] and not 0 (0: rollers parallel to the axle, "
                             f"a conventional wheel: use FixedWheel), got {V.show(self.roller)}")
        object.__setattr__(self, "roller", g)

    def _local_block(self, bk):
        # p_dot = -r theta_dot j - r sigma_dot E a, a = (cos g, sin g), E a = (-sin g, cos g)
        r, g = self.r, self.roller
        return bk.matrix([[0, r * bk.sin(g)], [-r, -r * bk.cos(g)]])

    def roller_axis(self):
        r"""The roller axis :math:`\mathbf a_i = \mathbf R(\beta_i)[\cos\gamma\ \ \sin\gamma]^T`, body frame (numbers).

        Returns
        -------
        numpy.ndarray (2,)

        Examples
        --------
        >>> SwedishWheel((0, 0), r=1, angle=np.pi / 2, roller=np.pi / 2).roller_axis().round(12).tolist()
        [-1.0, 0.0]
        """
        t = V.number("angle", self.angle) + V.number("roller", self.roller)
        return np.array([np.cos(t), np.sin(t)])
