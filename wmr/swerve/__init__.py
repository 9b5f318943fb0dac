r"""Swerve practice: what swerve-drive users need beyond the paper's kinematics.

A swerve module is a centred steered wheel (:class:`wmr.CentredWheel`); a swerve robot is a :class:`wmr.Robot` of
them.  WPILib's conventions are converted in :mod:`wmr.model.conventions` (checked against ``robotpy-wpimath`` in
``tests/test_swerve_wpilib.py``).  :mod:`~wmr.swerve.modules` (inverse and forward kinematics),
:mod:`~wmr.swerve.optimize` (which way to turn), :mod:`~wmr.swerve.limits` (desaturation, cosine compensation,
discretisation), :mod:`~wmr.swerve.profiles` and :mod:`~wmr.swerve.transient` (the re-steering study),
:mod:`~wmr.swerve.plot` (its figure).

>>> import wmr
>>> from wmr import swerve
>>> bot = wmr.Robot([wmr.CentredWheel((x, y), r=0.05) for x, y in [(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3)]])
>>> swerve.desaturate(bot, [4.0, 1.0, 0.0], max_speed=1.0).round(4).tolist()
[1.5962, 0.399, 0.0]
"""

from .limits import cosine_compensate, desaturate, desaturation_scale, discretize, se2_exp, se2_log
from .modules import ModuleCommand, chassis_twist, module_commands, module_speeds, radii, swerve_robot
from .optimize import MAX_MODULES, SteeringChoice, optimize_modules, optimize_robot, transition_slip
from .profiles import TwistProfile, direction_change, spin_and_translate
from .transient import STRATEGIES, Transient, TransientStudy, resteer_study, resteer_transient

__all__ = [
    "ModuleCommand",
    "swerve_robot",
    "radii",
    "module_commands",
    "module_speeds",
    "chassis_twist",
    "SteeringChoice",
    "optimize_modules",
    "optimize_robot",
    "transition_slip",
    "MAX_MODULES",
    "desaturate",
    "desaturation_scale",
    "cosine_compensate",
    "se2_exp",
    "se2_log",
    "discretize",
    "TwistProfile",
    "Transient",
    "TransientStudy",
    "direction_change",
    "spin_and_translate",
    "resteer_transient",
    "resteer_study",
    "STRATEGIES",
]
