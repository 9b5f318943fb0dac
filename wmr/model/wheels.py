r"""Wheel units: the intermediate body and its wheel(s), each a block of :math:`\mathbf J_2`.

A wheel unit is mounted on the platform at :math:`P_i` (``position`` = :math:`\mathbf d_i`,
body frame) through a vertical steering joint of angle :math:`\beta_i` (the angle of the
intermediate body relative to the platform, :math:`\mathbf R_{bwi}` of (11)).  In the wheel frame
:math:`\mathcal W_i`, :math:`\mathbf i_i = \mathbf R_{bwi}[1\ 0]^T` is the axle direction and
:math:`\mathbf j_i = \mathbf R_{bwi}[0\ 1]^T` the rolling direction; the no-slip condition (6) is
:math:`\dot{\mathbf h}_i = -r\dot\theta_i\mathbf j_i` (wheel spin :math:`\dot\theta_i` positive by the
right-hand rule about :math:`\mathbf i_i`, :math:`\mathbf k` upward).

Each unit contributes the block of the no-slip equation
:math:`[\mathbf E\mathbf d_i\ \mathbf 1]\,\mathbf t = \mathbf B_i(\beta_i)\,\dot{\boldsymbol\theta}_i`
(the i-th block row of (21)), where :math:`\dot{\boldsymbol\theta}_i` are its rate variables:

=====================  =========================================  ======================================================================================================
unit                   rates :math:`\dot{\boldsymbol\theta}_i`    block :math:`\mathbf B_i` (a block of :math:`\mathbf J_2`)
=====================  =========================================  ======================================================================================================
:class:`OffsetWheel`   :math:`\dot\phi_i,\ \dot\theta_i`          :math:`\mathbf R_{bwi}\,\mathrm{diag}(-d,-r)` (20)
:class:`CentredWheel`  :math:`\dot\theta_i`                       :math:`\mathbf R_{bwi}[0\ \ -r]^T` (51)
:class:`DualWheel`     :math:`\dot\theta_{i1},\ \dot\theta_{i2}`  :math:`\mathbf R_{bwi}\begin{bmatrix}0&0\\-r/2&-r/2\end{bmatrix}` (17)
:class:`FixedWheel`    :math:`\dot\theta_i`                       :math:`\mathbf R(\text{angle})[0\ \ -r]^T`, not steered (:mod:`~wmr.model.wheels_fixed`)
:class:`SwedishWheel`  :math:`\dot\theta_i,\ \dot\sigma_i`        :math:`\mathbf R(\text{angle})\begin{bmatrix}0&r\sin\gamma\\-r&-r\cos\gamma\end{bmatrix}`, not steered
=====================  =========================================  ======================================================================================================

The shared behaviour of a unit (its block from the pair :math:`(\mathbf L_i, \mathbf E\mathbf L_i)`, its
points, its rate names) is in :mod:`wmr.model.wheel_base`.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import validation as V
from .wheel_base import _Unit

__all__ = ["OffsetWheel", "CentredWheel", "DualWheel", "FixedWheel", "SwedishWheel", "UNIT_TYPES"]


@dataclass(frozen=True)
class OffsetWheel(_Unit):
    r"""Offset (castor) wheel: centre :math:`H_i = P_i - d\,\mathbf j_i`, offset ``d`` from the steering axis.

    With this placement the velocity of the steering-axis point is (9),
    :math:`\dot{\mathbf p}_i = -r\dot\theta_i\mathbf j_i - d\dot\phi_i\mathbf i_i`, where
    :math:`\dot\phi_i = \dot\psi + \dot\beta_i` (7) is the absolute steering rate.

    Parameters
    ----------
    position : pair
        :math:`\mathbf d_i = \overrightarrow{CP_i}`, body frame.
    r : float
        Wheel radius, > 0.
    d : float
        Offset, >= 0 (``d = 0`` is a centred wheel whose steering rate still counts as a rate).
    """

    d: float = 0.0
    kind = "offset"
    RATES = (("phi", r"\phi", ""), ("theta", r"\theta", ""))

    def __post_init__(self):
        super().__post_init__()
        object.__setattr__(self, "d", V.nonnegative("d (offset)", self.d))

    def _local_block(self, bk):
        # (20)/(21): p~ = diag(-d, -r)
        return bk.matrix([[-self.d, 0], [0, -self.r]])

    @np.errstate(over="ignore", invalid="ignore")       # overflow is checked on the result
    def beta_rate(self, psi_dot, rates, steer=None):
        r"""(7): :math:`\dot\beta_i = \dot\phi_i - \dot\psi`, with :math:`\dot\phi_i` = ``rates[..., 0]``.

        Parameters
        ----------
        psi_dot : float or array (...)
            Platform turning rate.
        rates : array (..., 2)
            :math:`(\dot\phi_i, \dot\theta_i)`.
        steer : ignored
            (The steering of an offset wheel follows from its rates.)

        Returns
        -------
        float or numpy.ndarray (...)

        Examples
        --------
        >>> float(OffsetWheel((0, 0), r=1, d=0.5).beta_rate(0.25, np.array([1.0, 3.0])))
        0.75
        """
        psi_dot, rates, _ = self._rates_in(psi_dot, rates, steer)
        return self._finite_rate(rates[..., 0] - psi_dot, rates)

    def _points(self, P, i_dir, j_dir):
        H = P - self.d * j_dir
        return {"P": P, "H": H, "wheels": H[..., None, :], "i": i_dir, "j": j_dir}


@dataclass(frozen=True)
class CentredWheel(_Unit):
    r"""Centred steered wheel: the steering axis passes through the wheel centre (d = 0).

    Its only rate in :math:`\mathbf J_2` is the rolling rate :math:`\dot\theta_i` (51); the
    steering rate :math:`\dot\beta_i` is decoupled and enters only through the angle
    :math:`\beta_i`.

    Parameters
    ----------
    position : pair
        :math:`\mathbf d_i`, body frame.
    r : float
        Wheel radius, > 0.
    """

    kind = "centred"
    RATES = (("theta", r"\theta", ""),)

    def _local_block(self, bk):
        # (51): R_bwi [0, -r]^T
        return bk.matrix([[0], [-self.r]])

    def beta_rate(self, psi_dot, rates, steer=None):
        """The steering rate is an independent input (decoupled from rolling): ``steer`` or 0.

        Parameters
        ----------
        psi_dot : float or array (...)
            Platform turning rate (sets the shape of the default zero).
        rates : array (..., 1)
            :math:`\\dot\\theta_i` (does not steer the wheel).
        steer : float or array (...), optional
            The steering-rate input :math:`\\dot\\beta_i`.

        Returns
        -------
        float or numpy.ndarray (...)
        """
        psi_dot, rates, steer = self._rates_in(psi_dot, rates, steer)
        shape = V.batch_shape({"psi_dot": psi_dot, "rates": rates[..., 0], "steer": steer}, core=0)
        return np.zeros(shape) if steer is None else np.broadcast_to(steer, shape).copy()


@dataclass(frozen=True)
class DualWheel(_Unit):
    r"""Dual-wheel: two wheels of radius ``r`` at :math:`H_i \pm b\,\mathbf i_i` on one intermediate body.

    Wheel 1 is at :math:`H_{i1} = P_i + b\,\mathbf i_i`, wheel 2 at :math:`H_{i2} = P_i - b\,\mathbf i_i`
    (the intermediate body is centred, :math:`H_i = P_i`).  The average rolling rate
    :math:`\dot\theta_i = (\dot\theta_{i1} + \dot\theta_{i2})/2` (18) drives :math:`P_i` as a centred
    wheel does (17); the difference steers the unit: the *absolute* heading rate of the
    intermediate body is :math:`\dot\phi_i = \dot\psi + \dot\beta_i = -\tfrac{r}{2b}(\dot\theta_{i1}-\dot\theta_{i2})`
    (the paper's (15) writes :math:`\dot\beta_i` on the left, which holds only when :math:`\dot\psi = 0`).

    Parameters
    ----------
    position : pair
        :math:`\mathbf d_i`, body frame.
    r : float
        Wheel radius, > 0.
    b : float
        Half the wheel separation, > 0.
    """

    b: float = 1.0
    kind = "dual"
    RATES = (("theta", r"\theta", "1"), ("theta", r"\theta", "2"))

    def __post_init__(self):
        super().__post_init__()
        object.__setattr__(self, "b", V.positive("b (half wheel separation)", self.b))

    def _local_block(self, bk):
        # (17): h_dot_i = -(r/2)(theta_dot_i1 + theta_dot_i2) j_i
        half = self.r / 2
        return bk.matrix([[0, 0], [-half, -half]])

    @np.errstate(over="ignore", invalid="ignore")       # overflow is checked on the result
    def beta_rate(self, psi_dot, rates, steer=None):
        r"""Corrected (15): :math:`\dot\beta_i = -\tfrac{r}{2b}(\dot\theta_{i1} - \dot\theta_{i2}) - \dot\psi`.

        Parameters
        ----------
        psi_dot : float or array (...)
            Platform turning rate.
        rates : array (..., 2)
            :math:`(\dot\theta_{i1}, \dot\theta_{i2})`.
        steer : ignored
            (A dual-wheel unit is steered by the difference of its wheel rates.)

        Returns
        -------
        float or numpy.ndarray (...)

        Examples
        --------
        >>> float(DualWheel((0, 0), r=0.2, b=0.1).beta_rate(0.0, np.array([1.0, 0.0])))
        -1.0
        """
        psi_dot, rates, _ = self._rates_in(psi_dot, rates, steer)
        return self._finite_rate(-(self.r / (2 * self.b)) * (rates[..., 0] - rates[..., 1]) - psi_dot, rates)

    def _points(self, P, i_dir, j_dir):
        wheels = np.stack([P + self.b * i_dir, P - self.b * i_dir], axis=-2)
        return {"P": P, "H": P, "wheels": wheels, "i": i_dir, "j": j_dir}


from .wheels_fixed import FixedWheel, SwedishWheel        # noqa: E402  (they build on the units above)

#: Every kind of wheel unit a :class:`wmr.Robot` accepts.
UNIT_TYPES = (OffsetWheel, CentredWheel, DualWheel, FixedWheel, SwedishWheel)
