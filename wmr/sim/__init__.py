r"""Any :class:`wmr.Robot` in a physics engine (MuJoCo): export, run, measure.

wmr's model is the paper's: rigid bodies, point contacts, no slip.  This package puts a robot into
MuJoCo, where wheels have mass, contacts have friction and servos have limits, so that what the
model predicts can be measured.  It knows no wheel kind: each unit describes its own bodies and
joints (:func:`wmr.io.mechanism.mechanism`, plain data) and says which joints are driven
(``driven=``; a castor is an offset wheel with both joints passive).

- :mod:`wmr.sim.params`: :class:`Params`, the physical parameters (masses, friction, servo limits)
  with their stated defaults;
- :mod:`wmr.sim.bodies`: a unit's mechanism in MuJoCo's terms (servos on the driven joints, masses,
  inertias, geoms);
- :mod:`wmr.sim.mjcf`: :func:`to_mjcf`, the MJCF text of any robot (no MuJoCo needed);
- :mod:`wmr.sim.simulation`: :class:`Simulation`, a robot in MuJoCo commanded and measured in wmr's
  variables (servos, drive locks, pushes);
- :mod:`wmr.sim.measure`: :class:`~wmr.sim.measure.Probe`, what a MuJoCo state says in wmr's variables (pose,
  twist, joint rates, contact forces, slip);
- :mod:`wmr.sim.recording`: :class:`Schedule` (commands over time), :class:`Reading` and :class:`Recording`
  (measurements);
- :mod:`wmr.sim.runner`: :func:`run`, a simulation driven along a schedule;
- :mod:`wmr.sim.validity`: :class:`Validity`, whether a run can be trusted (energy, penetration, servo
  saturation, MuJoCo's warnings);
- :mod:`wmr.sim.commands`: :func:`twist_schedule`, the joint commands of a twist from wmr's inverse
  kinematics.

MuJoCo is imported only when a :class:`Simulation` is made: ``import wmr`` and ``import wmr.sim`` do
not need it (``pip install 'wmr-kinematics[sim]'`` installs it).

Examples
--------
>>> import wmr
>>> from wmr.sim import to_mjcf
>>> '<freejoint name="platform"/>' in to_mjcf(wmr.load("examples/swerve4.toml"))   # doctest: +SKIP
True
"""

from .bodies import POSITION, VELOCITY, servo
from .commands import start_angles, twist_schedule
from .mjcf import Export, export, to_mjcf
from .params import Params
from .recording import Reading, Recording, Schedule
from .runner import run
from .simulation import Simulation
from .validity import Validity

__all__ = [
    "POSITION",
    "VELOCITY",
    "Export",
    "Params",
    "Recording",
    "Reading",
    "Schedule",
    "Simulation",
    "Validity",
    "export",
    "run",
    "servo",
    "start_angles",
    "to_mjcf",
    "twist_schedule",
]


def __getattr__(name: str) -> object:
    """``wmr.sim.Sample``, the name :class:`Reading` had (the sweeps have a ``Sample`` of their own): deprecated."""
    if name == "Sample":
        import warnings

        warnings.warn("wmr.sim.Sample is deprecated: use wmr.sim.Reading", DeprecationWarning, 2)
        return Reading
    raise AttributeError(f"module 'wmr.sim' has no attribute {name!r}")
