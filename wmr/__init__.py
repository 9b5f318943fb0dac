r"""wmr: kinematics of wheeled mobile robots, after Leow, Low & Loh (2002).

A robot is a platform carried by wheel units (offset, centred, dual, fixed or Swedish wheels) mounted at
points :math:`P_i`.  The package builds the paper's matrices once, for SymPy (exact derivations)
and NumPy (batched numbers): :math:`\mathbf J_1`, :math:`\mathbf J_{L1}`, :math:`\mathbf J_2`,
:math:`\mathbf F = [\mathbf J_1\ -\mathbf J_2]`, :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2`, and
analyses them: mobility (rank and nullity of F), condition numbers and isotropy, forward and
inverse kinematics, the instantaneous centre and compatible steering angles, and time
integration.  Conventions: see :mod:`wmr.conventions`.

Examples
--------
>>> import numpy as np, wmr
>>> bot = wmr.paper_robot("centred", L=0.3, r=0.05)
>>> beta = wmr.steering_angles(bot, [1.0, 0.0, 0.0])     # spin about C
>>> int(wmr.mobility(bot, beta))
1
"""

from . import deprecated as deprecated  # the names that moved, kept for one release (wmr.deprecated)
from . import errors, swerve
from ._version import __version__ as __version__  # one source: wmr/_version.py
from .analysis.classes import campion_class
from .analysis.integration import integrate
from .analysis.isotropy import characteristic_length, is_isotropic
from .analysis.kinematics import forward, inverse
from .analysis.linalg import condition_number, null_space, nullity, rank
from .analysis.mobility import admissible_twists, mobility, rank_F
from .analysis.steering import centre_to_wheels, instantaneous_centre, steering_angles
from .analysis.sweep import sweep
from .deprecated import simulate as simulate  # deprecated: wmr.integrate
from .io import dump, load
from .model import conventions
from .model.backend import NUMERIC, SYMBOLIC
from .model.conventions import Twist
from .model.platform import E, point_velocity, rotation
from .model.robot import Robot
from .model.robots import equilateral_mounts, paper_robot
from .model.tolerance import TOL
from .model.wheels import CentredWheel, DualWheel, FixedWheel, OffsetWheel, SwedishWheel
from .odometry import wheel_odometry

__all__ = [
    "Robot",
    "Twist",
    "OffsetWheel",
    "CentredWheel",
    "DualWheel",
    "FixedWheel",
    "SwedishWheel",
    "paper_robot",
    "equilateral_mounts",
    "E",
    "rotation",
    "point_velocity",
    "rank",
    "nullity",
    "null_space",
    "rank_F",
    "mobility",
    "admissible_twists",
    "condition_number",
    "is_isotropic",
    "characteristic_length",
    "forward",
    "inverse",
    "instantaneous_centre",
    "steering_angles",
    "centre_to_wheels",
    "integrate",
    "sweep",
    "campion_class",
    "TOL",
    "NUMERIC",
    "SYMBOLIC",
    "conventions",
    "load",
    "dump",
    "swerve",
    "errors",
    "wheel_odometry",
]
