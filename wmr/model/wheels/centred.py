r"""The centred steered wheel: the steering axis passes through the wheel centre (:math:`H_i = P_i`).

Its only rate in :math:`\mathbf J_2` is the rolling rate :math:`\dot\theta_i`; its block is
:math:`\mathbf R_{bwi}[0\ \ -r]^T` (51).  The steering rate :math:`\dot\beta_i` is decoupled from rolling: it
enters only through the angle :math:`\beta_i`, set by the steering motor (a swerve module).  No slip
holds :math:`P_i` to the wheel plane: its velocity must lie along :math:`\mathbf j_i`.

In a robot file::

    [[wheel]]
    type = "centred"
    position = [0.3, 0.0]     # d_i, metres
    radius = 0.05             # r > 0
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..backend import NUMERIC, Backend
from ..types import ArrayLike, FloatArray, Matrix
from .joints import Joint
from .unit import WheelUnit

__all__ = ["CentredWheel"]


@dataclass(frozen=True)
class CentredWheel(WheelUnit):
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
    driven : mapping or sequence of bool, optional
        Actuation of the joints ``steer`` and ``drive`` (default: both driven).
    """

    kind = "centred"
    JOINTS = (Joint("steer", "steer", driven=True), Joint("drive", "drive", driven=True, rate=("theta", r"\theta", "")))
    rolls_in_plane = True

    def local_block(self, backend: Backend = NUMERIC) -> Matrix:
        r"""(51): :math:`\mathbf L_i = [0\ \ -r]^T`, the column of :math:`\dot\theta_i`.

        Parameters
        ----------
        backend : NUMERIC or SYMBOLIC, optional

        Returns
        -------
        numpy.ndarray (2, 1) or sympy.Matrix (2, 1)
        """
        return backend.matrix([[0], [-self.r]])

    def beta_rate(self, psi_dot: ArrayLike, rates: ArrayLike, steer: ArrayLike | None = None) -> FloatArray:
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
        _, _, steer, shape = self._rates_in(psi_dot, rates, steer)
        return np.zeros(shape) if steer is None else np.broadcast_to(steer, shape).copy()
