r"""The offset (castor) wheel: a wheel centred at :math:`H_i = P_i - d\,\mathbf j_i`, off its steering axis by ``d``.

Its rates are the absolute steering rate :math:`\dot\phi_i = \dot\psi + \dot\beta_i` (7) and the rolling
rate :math:`\dot\theta_i`; its local block is :math:`\mathbf L_i = \mathrm{diag}(-d, -r)` (20), so the
steering-axis point moves as (9), :math:`\dot{\mathbf p}_i = -r\dot\theta_i\mathbf j_i - d\dot\phi_i\mathbf i_i`.
With :math:`d > 0` the block is invertible: an offset wheel puts no constraint on the platform twist.
The paper's offset wheels are *active* (a steering and a driving motor, section 3); a castor is the
same unit with both joints passive (``driven={"steer": False, "drive": False}``).

In a robot file::

    [[wheel]]
    type = "offset"
    position = [-0.3, 0.0]    # d_i, metres
    radius = 0.05             # r > 0
    offset = 0.03             # d >= 0
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import checks
from ..backend import NUMERIC, Backend
from ..types import ArrayLike, FloatArray, Matrix
from .joints import Joint
from .unit import WheelUnit

__all__ = ["OffsetWheel"]


@dataclass(frozen=True)
class OffsetWheel(WheelUnit):
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
    driven : mapping or sequence of bool, optional
        Actuation of the joints ``steer`` and ``drive`` (default: both driven, the paper's active
        offset wheel; both passive for a castor).

    Examples
    --------
    >>> castor = OffsetWheel((-0.3, 0.0), r=0.03, d=0.03, driven={"steer": False, "drive": False})
    >>> [(j.name, j.driven) for j in castor.joints]
    [('steer', False), ('drive', False)]
    """

    d: float = 0.0
    kind = "offset"
    JOINTS = (
        Joint("steer", "steer", driven=True, rate=("phi", r"\phi", ""), absolute=True),  # phi = psi + beta (7)
        Joint("drive", "drive", driven=True, rate=("theta", r"\theta", "")),
    )

    def _validate(self):
        super()._validate()
        object.__setattr__(self, "d", checks.nonnegative("d (offset)", self.d))

    def local_block(self, backend: Backend = NUMERIC) -> Matrix:
        r"""(20)/(21): :math:`\mathbf L_i = \mathrm{diag}(-d, -r)`, columns :math:`(\dot\phi_i, \dot\theta_i)`.

        Parameters
        ----------
        backend : NUMERIC or SYMBOLIC, optional

        Returns
        -------
        numpy.ndarray (2, 2) or sympy.Matrix (2, 2)
        """
        return backend.matrix([[-self.d, 0], [0, -self.r]])

    @np.errstate(over="ignore", invalid="ignore")  # overflow is checked on the result
    def beta_rate(self, psi_dot: ArrayLike, rates: ArrayLike, steer: ArrayLike | None = None) -> FloatArray:
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
        psi_dot, rates, _, _ = self._rates_in(psi_dot, rates, steer)
        return self._finite_rate(rates[..., 0] - psi_dot, rates)

    def _points(self, P, i_dir, j_dir):
        H = P - self.d * j_dir
        return {"P": P, "H": H, "wheels": H[..., None, :], "i": i_dir, "j": j_dir}
