r"""The Swedish wheel (omni or mecanum): a fixed wheel whose rim carries free rollers at an angle to the axle.

Its rates are the wheel spin :math:`\dot\theta_i` (driven) and the roller spin :math:`\dot\sigma_i`
(passive); its local block :math:`\mathbf L_i = \begin{bmatrix}0 & r\sin\gamma\\ -r & -r\cos\gamma\end{bmatrix}`
is invertible, so a Swedish wheel puts no constraint on the platform twist
(:class:`SwedishWheel`).  Like the fixed wheel it has no steering joint
(:mod:`~wmr.model.wheels.unsteered`).

In a robot file::

    [[wheel]]
    type = "swedish"
    position = [0.3, 0.2]     # d_i, metres
    radius = 0.05             # r > 0
    angle_deg = 90.0          # the constant angle beta_i
    roller_deg = 45.0         # the rollers' angle to the axle (90: omni wheel, +-45: mecanum wheel)
"""

from __future__ import annotations

from dataclasses import InitVar, dataclass, field

import numpy as np

from ...errors import InputValueError
from .. import checks
from ..backend import NUMERIC, Backend
from ..tolerance import TOL
from ..types import FloatArray, Matrix
from .joints import Joint
from .unsteered import UnsteeredUnit, in_degrees, radians

__all__ = ["SwedishWheel"]


@dataclass(frozen=True)
class SwedishWheel(UnsteeredUnit):
    r"""Swedish wheel (omni or mecanum): a fixed wheel whose rim carries free rollers at ``roller`` to the axle.

    The axis of the roller touching the ground makes the angle :math:`\gamma` = ``roller`` with the axle,
    counter-clockwise seen from above, :math:`\mathbf a_i = \cos\gamma\,\mathbf i_i + \sin\gamma\,\mathbf j_i`.
    The wheel spin moves the hub by :math:`-r\dot\theta_i\mathbf j_i` (6), the roller spin along the
    roller's rolling direction by :math:`-r\dot\sigma_i\mathbf E\mathbf a_i`:

    .. math:: \mathbf L_i = \begin{bmatrix}0 & r\sin\gamma\\ -r & -r\cos\gamma\end{bmatrix},
              \quad \mathbf B_i = \mathbf R(\beta_i)\mathbf L_i ,

    with :math:`\dot\sigma_i` the roller rate expressed at the wheel radius (so that both columns are
    lengths).  :math:`\det\mathbf L_i = r^2\sin\gamma \ne 0`: the wheel puts no constraint on the twist
    (the projection on :math:`\mathbf a_i`, :math:`\mathbf a_i^T[\mathbf E\mathbf d_i\ \ \mathbf 1]\,\mathbf t
    = -r\sin\gamma\,\dot\theta_i`, involves its wheel rate only: Campion, Bastin & d'Andrea-Novel 1996) and
    inverse kinematics is exact; ``roller`` = 0 (rollers parallel to the axle, a :class:`~wmr.FixedWheel`)
    is refused.

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
    angle_deg, roller_deg : float, optional
        ``angle`` and ``roller`` in degrees instead (keywords, as the robot file's keys).
    driven : mapping or sequence of bool, optional
        Actuation of the joints ``drive`` (default driven) and ``roller`` (default passive).

    Examples
    --------
    >>> mec = SwedishWheel((0.3, 0.2), r=0.05, angle=0.0, roller=np.pi / 4)
    >>> mec.rate_names(1)
    ('theta_dot_1', 'sigma_dot_1')
    >>> (mec.block(0.0) / 0.05).round(6).tolist()
    [[0.0, 0.707107], [-1.0, -0.707107]]
    >>> omni = SwedishWheel((0.0, 0.0), r=0.5, angle=0.0, roller=np.pi / 2)
    >>> (omni.block(0.0).round(12) + 0.0).tolist()      # rolls along j (theta) and along i (free roller)
    [[0.0, 0.5], [-0.5, 0.0]]
    """

    roller: float = None  # type: ignore[assignment]
    roller_deg: InitVar[float | None] = field(default=None, kw_only=True)

    kind = "swedish"
    JOINTS = (
        Joint("drive", "drive", driven=True, rate=("theta", r"\theta", "")),
        Joint("roller", "roller", driven=False, rate=("sigma", r"\sigma", "")),
    )
    ANGLES = ("angle", "roller")

    def _init_degrees(self, roller_deg=None, *more):
        super()._init_degrees(*more)
        object.__setattr__(self, "roller", in_degrees(type(self).__name__, "roller", self.roller, roller_deg))

    def _validate(self):
        super()._validate()
        name = "roller (angle of the rollers to the axle, radians)"
        g = radians("roller", self.roller)
        if not -np.pi / 2 < float(g) <= np.pi / 2 or abs(float(g)) <= TOL:
            raise InputValueError(
                f"{name} must be in (-pi/2, pi/2] and not 0 (0: rollers parallel to the axle, "
                f"a conventional wheel: use FixedWheel), got {checks.show(self.roller)}"
            )
        object.__setattr__(self, "roller", g)

    def local_block(self, backend: Backend = NUMERIC) -> Matrix:
        r"""The local block :math:`\mathbf L_i = \begin{bmatrix}0 & r\sin\gamma\\ -r & -r\cos\gamma\end{bmatrix}`.

        Its columns are those of :math:`\dot\theta_i` and :math:`\dot\sigma_i`.

        Parameters
        ----------
        backend : NUMERIC or SYMBOLIC, optional

        Returns
        -------
        numpy.ndarray (2, 2) or sympy.Matrix (2, 2)
        """
        # p_dot = -r theta_dot j - r sigma_dot E a, a = (cos g, sin g), E a = (-sin g, cos g)
        r, g = self.r, self.roller
        return backend.matrix([[0, r * backend.sin(g)], [-r, -r * backend.cos(g)]])

    def roller_axis(self) -> FloatArray:
        r"""The roller axis :math:`\mathbf a_i = \mathbf R(\beta_i)[\cos\gamma\ \ \sin\gamma]^T`, body frame (numbers).

        Returns
        -------
        numpy.ndarray (2,)

        Examples
        --------
        >>> SwedishWheel((0, 0), r=1, angle=np.pi / 2, roller=np.pi / 2).roller_axis().round(12).tolist()
        [-1.0, 0.0]
        """
        t = checks.number("angle", self.angle) + checks.number("roller", self.roller)
        return np.array([np.cos(t), np.sin(t)])
