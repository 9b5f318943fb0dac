r"""Chapter 1, equations (1)-(19): the platform, the rolling disk, offset, centred and dual wheels.

Every result is derived from first principles -- rigid-body velocities with 3D cross products
(:math:`\dot{\mathbf p} = \dot{\mathbf c} + \boldsymbol\omega\times\mathbf d`) and the no-slip
condition of a thin disk -- and compared with the printed form (:func:`edition.printed`) exactly
(SymPy) and with the package's builders and kernels numerically.  Frames: :mod:`wmr.conventions`
(axle :math:`\mathbf i_i`, rolling direction :math:`\mathbf j_i = \mathbf k\times\mathbf i_i`,
offset wheel centre :math:`H_i = P_i - d\,\mathbf j_i`, dual wheels at :math:`P_i \pm b\,\mathbf i_i`).

The derivations themselves are in the chapter (``notebooks/01_platform_and_wheels.ipynb``): each check takes
what the chapter derived.  The checks, by equation group:

================  ================================================================================================
:mod:`.frames`    3D lifting, the vertical axis, time and the printed wheel axes, shared by the checks
:mod:`.platform`  the platform, (1)-(5): the velocity of C, E, the twist layout, the row of a point
:mod:`.wheel`     one wheel, (6)-(12): rolling disk, steering composition, offset and centred wheels
:mod:`.dual`      the dual wheel, (13)-(19): no slip, the turning rate, its integral and the average
================  ================================================================================================
"""

from .dual import dual_average, dual_average_angle, dual_integrated, dual_no_slip, dual_steering
from .frames import k, lift, planar, time
from .platform import centre_velocity, platform_point, platform_row, skew_matrix, twist_layout
from .wheel import centred_wheel, offset_in_body, offset_wheel, rolling_disk, steering_composition, wheel_frame

__all__ = [
    "k",
    "lift",
    "planar",
    "time",
    "centre_velocity",
    "platform_point",
    "skew_matrix",
    "twist_layout",
    "platform_row",
    "rolling_disk",
    "steering_composition",
    "offset_wheel",
    "wheel_frame",
    "offset_in_body",
    "centred_wheel",
    "dual_no_slip",
    "dual_steering",
    "dual_integrated",
    "dual_average",
    "dual_average_angle",
]
