r"""The dual-wheel unit: two wheels on one intermediate body, steered by the difference of their rates.

Two wheels of radius ``r`` at :math:`P_i \pm b\,\mathbf i_i` on an intermediate body that turns freely
about the vertical axis through :math:`P_i` (a swivel: no steering motor).  The average rolling rate
drives :math:`P_i` as a centred wheel does (17)-(18); the difference steers the unit, the corrected (15):
:math:`\dot\phi_i = \dot\psi + \dot\beta_i = -\tfrac{r}{2b}(\dot\theta_{i1} - \dot\theta_{i2})`.  No slip
holds :math:`P_i` to the wheel plane, as for a centred wheel.

In a robot file::

    [[wheel]]
    type = "dual"
    position = [0.3, 0.0]     # d_i, metres
    radius = 0.05             # r > 0
    half_separation = 0.04    # b > 0
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import checks
from ..backend import NUMERIC, Backend
from ..types import ArrayLike, FloatArray, Matrix
from .joints import Joint
from .unit import WheelUnit

__all__ = ["DualWheel"]


@dataclass(frozen=True)
class DualWheel(WheelUnit):
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
    driven : mapping or sequence of bool, optional
        Actuation of the joints ``swivel``, ``drive1`` and ``drive2`` (default: the two wheels
        driven, the swivel passive).
    """

    b: float = 1.0
    kind = "dual"
    JOINTS = (
        Joint("swivel", "swivel", driven=False),
        Joint("drive1", "drive", driven=True, rate=("theta", r"\theta", "1")),
        Joint("drive2", "drive", driven=True, rate=("theta", r"\theta", "2")),
    )
    rolls_in_plane = True

    def _validate(self):
        super()._validate()
        object.__setattr__(self, "b", checks.positive("b (half wheel separation)", self.b))

    def local_block(self, backend: Backend = NUMERIC) -> Matrix:
        r"""(17): :math:`\dot{\mathbf h}_i = -\tfrac r2(\dot\theta_{i1} + \dot\theta_{i2})\mathbf j_i`, so
        :math:`\mathbf L_i = \begin{bmatrix}0&0\\-r/2&-r/2\end{bmatrix}`.

        Parameters
        ----------
        backend : NUMERIC or SYMBOLIC, optional

        Returns
        -------
        numpy.ndarray (2, 2) or sympy.Matrix (2, 2)
        """
        half = self.r / 2
        return backend.matrix([[0, 0], [-half, -half]])

    @np.errstate(over="ignore", invalid="ignore")  # overflow is checked on the result
    def beta_rate(self, psi_dot: ArrayLike, rates: ArrayLike, steer: ArrayLike | None = None) -> FloatArray:
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
        psi_dot, rates, _, _ = self._rates_in(psi_dot, rates, steer)
        return self._finite_rate(-(self.r / (2 * self.b)) * (rates[..., 0] - rates[..., 1]) - psi_dot, rates)

    def steering_row(self) -> FloatArray | None:
        r"""Corrected (15): the rate difference :math:`\mathbf c = [-\tfrac{r}{2b}\ \ \tfrac{r}{2b}]` turns the unit.

        Returns
        -------
        numpy.ndarray (2,)

        Examples
        --------
        >>> DualWheel((0, 0), r=0.2, b=0.1).steering_row().tolist()
        [-1.0, 1.0]
        """
        k = float(self.r) / (2 * float(self.b))
        return np.array([-k, k])

    def _points(self, P, i_dir, j_dir):
        wheels = np.stack([P + self.b * i_dir, P - self.b * i_dir], axis=-2)
        return {"P": P, "H": P, "wheels": wheels, "i": i_dir, "j": j_dir}
