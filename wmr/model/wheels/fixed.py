r"""The fixed conventional wheel: a centred wheel without a steering joint, at a constant angle.

Its wheel centre is :math:`P_i`; rolling without slip is :math:`\dot{\mathbf p}_i = -r\dot\theta_i\mathbf j_i`
(6) with :math:`\mathbf j_i = \mathbf R(\text{angle})[0\ 1]^T`, so its block is the centred wheel's (51)
at :math:`\beta_i` = ``angle`` (:mod:`~wmr.model.wheels.unsteered`).  It holds :math:`P_i` to its wheel
plane: the twist constraint :math:`\mathbf i_i^T[\mathbf E\mathbf d_i\ \mathbf 1]\mathbf t = 0` at every
configuration (a differential drive's wheels).

In a robot file::

    [[wheel]]
    type = "fixed"
    position = [0.0, 0.2]     # d_i, metres
    radius = 0.05             # r > 0
    angle_deg = 90.0          # the constant angle beta_i (0: axle along body x, rolls along body y)
"""

from __future__ import annotations

from dataclasses import dataclass

from .centred import CentredWheel
from .unsteered import UnsteeredUnit

__all__ = ["FixedWheel"]


@dataclass(frozen=True)
class FixedWheel(UnsteeredUnit):
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
        The constant wheel-frame angle :math:`\beta_i` (radians, within :math:`\pm 2\pi`; an exact
        SymPy number such as ``sympy.pi / 2`` is kept exact): 0 puts the axle along the body x axis
        (the wheel rolls along body y).
    angle_deg : float, optional
        The same in degrees (keyword only, as the robot file's key): give ``angle`` or ``angle_deg``.
    driven : mapping or sequence of bool, optional
        Actuation of the joint ``drive`` (default: driven; ``{"drive": False}`` for an idler).

    Examples
    --------
    >>> import numpy as np
    >>> left = FixedWheel((0.0, 0.2), r=0.05, angle=np.pi / 2)     # axle along y: rolls along x
    >>> (left.block(0.0).round(12) + 0.0).tolist()
    [[0.05], [0.0]]
    """

    kind = "fixed"
    # a centred wheel held at beta_i = angle: its drive joint (rate) and its block (51), written once there
    JOINTS = (CentredWheel.JOINTS[-1],)
    local_block = CentredWheel.local_block
    rolls_in_plane = True
