r"""Robots in and out: wmr's TOML robot files, URDF, ROS 2 controller parameters and WPILib kinematics objects.

:func:`load` reads a robot file of any of the file formats by its suffix, :func:`dump` writes one;
WPILib's objects come and go through :func:`from_wpilib` and :func:`to_wpilib`.  Which format
expresses which wheel kind:

==================  ========  ========  ========  ========  ========  =================================================
format              centred   offset    dual      fixed     Swedish   what it holds
==================  ========  ========  ========  ========  ========  =================================================
TOML (``.toml``)    yes       yes       yes       yes       yes       every unit, its actuation (:mod:`wmr.io.toml`)
URDF (``.urdf``)    yes       yes       yes       yes       yes       the joints; Swedish wheels with roller joints;
                                                                      actuation from ``<ros2_control>``
                                                                      (:mod:`~wmr.io.urdf_read`,
                                                                      :mod:`~wmr.io.urdf_write`)
ROS 2 (``.yaml``)   layouts   no        no        layouts   layouts   one drive controller's layout: differential,
                                                                      mecanum, omni, swerve, bicycle, tricycle,
                                                                      Ackermann (:mod:`wmr.io.ros2_controllers`)
WPILib objects      swerve    no        no        diff.     mecanum   ``SwerveDrive{2,3,4,6}Kinematics``,
                                                                      ``MecanumDriveKinematics``,
                                                                      ``DifferentialDriveKinematics``
                                                                      (:mod:`wmr.io.wpilib`, chassis speeds too)
==================  ========  ========  ========  ========  ========  =================================================

"layouts" means: only in the arrangements of :mod:`wmr.io.layouts`.  A robot a format cannot express
is refused with :class:`~wmr.errors.InputValueError`, whose message says, layout by layout, why.
Passive castors (an offset wheel with both joints passive) constrain nothing and are commanded by no
controller: ROS 2 and WPILib leave them out.  Lost on the way: the wheel radius in WPILib's objects
(give it to :func:`from_wpilib`), :math:`l_x` and :math:`l_y` apart in ROS 2's mecanum parameters
(their sum is kept), the steered wheels' radius in ROS 2's steering controllers, and the wheel
order where a layout has its own (ROS 2; WPILib's mecanum FL, FR, RL, RR).

Every writer writes its floats by one rule, :mod:`wmr.io.decimals` (12 significant digits, nothing
below :math:`10^{-11}` of the quantity's scale), so that the same robot gives the same bytes on every
CPU; a file read back holds its numbers to 12 digits.

The optional packages (yourdfpy, PyYAML, robotpy-wpimath) are imported only when a bridge is used
(:mod:`wmr.io.extras`).

Examples
--------
>>> import wmr
>>> bot = wmr.paper_robot("dual", L=0.4, r=0.05)
>>> text = dump(bot, format="urdf")                           # any robot: every kind has its joints
>>> import pathlib, tempfile
>>> path = pathlib.Path(tempfile.mkdtemp()) / "bot.urdf"
>>> _ = path.write_text(text)
>>> back = load(path)
>>> [u.kind for u in back.wheels], wmr.campion_class(back).label
(['dual', 'dual', 'dual'], '(1,2)')
"""

from .files import FORMATS, dump, format_of, load
from .ros2 import from_ros2, to_ros2
from .toml import RobotFileError, loads
from .urdf_read import from_urdf
from .urdf_write import to_urdf
from .wheel_tables import wheel_keys
from .wpilib import from_wpilib, to_wpilib

__all__ = [
    "RobotFileError",
    "wheel_keys",
    "load",
    "loads",
    "dump",
    "FORMATS",
    "format_of",
    "from_urdf",
    "to_urdf",
    "from_ros2",
    "to_ros2",
    "from_wpilib",
    "to_wpilib",
]
