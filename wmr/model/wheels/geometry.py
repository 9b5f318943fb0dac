r"""A wheel unit seen from above: its points (batched), in the body frame.

What every kind shares (:class:`UnitGeometry`, a base of :class:`~wmr.model.wheels.unit.WheelUnit`):
the axle and rolling directions :math:`\mathbf i_i = \mathbf R(\beta_i)[1\ 0]^T`,
:math:`\mathbf j_i = \mathbf R(\beta_i)[0\ 1]^T` (11) at the steering axis :math:`P_i`; a kind with other
points (an offset wheel's centre :math:`H_i`, a dual wheel's two wheels) extends
:meth:`UnitGeometry._points`.  How a unit is drawn is the drawing layer's (:mod:`wmr.plot.parts`).
"""

from __future__ import annotations

from typing import Any, ClassVar

import numpy as np

from .. import checks
from ..types import ArrayLike, FloatArray

__all__ = ["UnitGeometry"]


class UnitGeometry:
    """The points of a wheel unit (a base of every kind; see :class:`~wmr.model.wheels.unit.WheelUnit`)."""

    # what a unit provides (the dataclass fields and class attributes of WheelUnit)
    position: Any
    r: Any
    steered: ClassVar[bool] = False

    @property
    def constant_angle(self) -> Any:
        """The constant angle of a unit without a steering joint; None for a steered unit."""
        return None

    def points(self, beta: ArrayLike) -> dict[str, FloatArray]:
        r"""Points of the unit in the body frame (for drawing and for checks).

        Parameters
        ----------
        beta : float or array (...)
            Steering angle(s) :math:`\beta_i` (a unit with a constant angle uses its own).

        Returns
        -------
        dict of numpy.ndarray
            ``"P"`` (steering axis, (..., 2)), ``"H"`` (centre of the wheel, or of the pair,
            (..., 2)), ``"wheels"`` ((..., k, 2): wheel centres = ground contact points seen from
            above), ``"i"`` and ``"j"`` (unit axle and rolling directions, (..., 2)).

        Examples
        --------
        >>> from wmr import OffsetWheel
        >>> OffsetWheel((1.0, 0.0), r=0.1, d=0.2).points(0.0)["H"].tolist()    # H = P - d j
        [1.0, -0.2]
        """
        return self._at(checks.finite_array("beta", beta))

    def _at(self, beta):
        """:meth:`points` at checked float angles."""
        c, s = np.cos(beta), np.sin(beta)
        i_dir = np.stack([c, s], axis=-1)
        j_dir = np.stack([-s, c], axis=-1)
        P = np.broadcast_to(np.asarray(self.position, dtype=float), i_dir.shape)
        return self._points(P, i_dir, j_dir)

    def _points(self, P, i_dir, j_dir):
        """The unit's points from :math:`P_i` and its axle and rolling directions (kinds with others override this)."""
        return {"P": P, "H": P, "wheels": P[..., None, :], "i": i_dir, "j": j_dir}
