r"""Any :class:`wmr.Robot` in a physics engine (MuJoCo): export, run, measure.

wmr's model is the paper's: rigid bodies, point contacts, no slip.  This package puts a robot into
MuJoCo, where wheels have mass, contacts have friction and servos have limits, so that what the
model predicts can be measured.

- :mod:`wmr.sim.params`: :class:`Params`, the physical parameters (masses, friction, servo limits)
  with their stated defaults;
- :mod:`wmr.sim.chains`: each wheel unit as a chain of bodies and joints (:func:`unit_chain`, one
  description per wheel kind);
- :mod:`wmr.sim.mjcf`: :func:`to_mjcf`, the MJCF text of any robot (no MuJoCo needed);
- :mod:`wmr.sim.simulation`: :class:`Simulation`, a robot in MuJoCo commanded and measured in wmr's
  variables (servos, drive locks, pushes);
- :mod:`wmr.sim.recording`: :class:`Schedule` (commands over time), :class:`Sample` and :class:`Recording`
  (measurements);
- :mod:`wmr.sim.runner`: :func:`run`, a simulation driven along a schedule;
- :mod:`wmr.sim.commands`: :func:`twist_schedule`, the joint commands of a twist from wmr's inverse
  kinematics.

MuJoCo is imported only when a :class:`Simulation` is made: ``import wmr`` and ``import wmr.sim`` do
not need it (``pip install wmr[sim]`` installs it).

Examples
--------
>>> import wmr
>>> from wmr.sim import to_mjcf
>>> '<freejoint name="platform"/>' in to_mjcf(wmr.load("examples/swerve4.toml"))   # doctest: +SKIP
True
"""
from .chains import Chain, Joint, Link, Shape, unit_chain
from .commands import start_angles, twist_schedule
from .mjcf import Export, default_passive, export, to_mjcf
from .params import Params
from .recording import Recording, Sample, Schedule
from .runner import run
from .simulation import Simulation

__all__ = [
           "Chain",
           "Export",
           "Joint",
           "Link",
           "Params",
           "Recording",
           "Sample",
           "Schedule",
           "Shape",
           "Simulation",
           "default_passive",
           "export",
           "run",
           "start_angles",
           "to_mjcf",
           "twist_schedule",
           "unit_chain",
]
