r"""Swerve practice: what swerve-drive users need beyond the paper's kinematics.

A swerve module is a centred steered wheel (:class:`wmr.CentredWheel`); a swerve robot is a
:class:`wmr.Robot` of them.  Frames, twist order and the mapping to WPILib
(:math:`\alpha = \beta - \pi/2`, :math:`s = r\dot\theta`, ``ChassisSpeeds(vx, vy, omega)`` =
:math:`[\dot\psi, \dot x, \dot y]` reordered) are stated and converted in :mod:`wmr.model.conventions`
(:func:`~wmr.model.conventions.angle_to`, :func:`~wmr.model.conventions.twist_to` and back); the
project's tests check them against ``robotpy-wpimath`` (``tests/test_swerve_wpilib.py``).

- :mod:`wmr.swerve.modules`: module angles and speeds (inverse kinematics), least-squares chassis
  twist (forward);
- :mod:`wmr.swerve.optimize`: WPILib's per-module ``optimize`` and the robot-level steering choice;
- :mod:`wmr.swerve.limits`: desaturation keeping the instantaneous centre, cosine compensation,
  discretisation of a twist over a control period (the SE(2) exponential);
- :mod:`wmr.swerve.profiles`: the commanded twists of a transient (a change of direction, a spin while
  translating);
- :mod:`wmr.swerve.transient`: the re-steering transient simulator (rate-limited modules following a
  twist profile; slip and path error for each strategy);
- :mod:`wmr.swerve.plot`: its figure (matplotlib, imported only there).

Usage
-----
>>> import numpy as np, wmr
>>> from wmr import swerve
>>> bot = wmr.Robot([wmr.CentredWheel((x, y), r=0.05)
...                  for x, y in [(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3)]])
>>> cmd = swerve.module_commands(bot, [0.0, 1.0, 0.0])       # beta (axle angles), speeds r*theta_dot
>>> np.degrees(wmr.conventions.angle_to(cmd.beta, "wpilib")).round(9).tolist()  # WPILib module angles
[0.0, 0.0, 0.0, 0.0]
>>> now = np.radians([89.0, 91.0, 91.0, 89.0])                 # driving forward; then: drive left
>>> swerve.optimize_modules(bot, [0.0, 0.0, 1.0], now).flipped.tolist()   # WPILib: opposite ways
[True, False, False, True]
>>> choice = swerve.optimize_robot(bot, [0.0, 0.0, 1.0], now)             # robot level: one way
>>> len(set(choice.flipped.tolist())), choice.beta.shape, choice.speed.shape
(1, (4,), (4,))
>>> swerve.desaturate(bot, [4.0, 1.0, 0.0], max_speed=1.0).round(4).tolist()
[1.5962, 0.399, 0.0]

The re-steering study (:func:`resteer_study`: every strategy of :data:`STRATEGIES` on a :class:`TwistProfile`) is
drawn by ``wmr.swerve.plot.transient_figure(study)``.
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
