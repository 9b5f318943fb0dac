r"""Any :class:`wmr.Robot` in a physics engine (MuJoCo): export, run, measure.

wmr's model is the paper's: rigid bodies, point contacts, no slip.  This package puts a robot into MuJoCo,
where wheels have mass, contacts have friction and servos have limits (:class:`Params`), so that what the model
predicts can be measured.  It knows no wheel kind: each unit describes its own bodies and joints
(:func:`wmr.io.mechanism.mechanism`) and says which are driven (``driven=``; a castor is an offset wheel with
both joints passive).  :func:`to_mjcf` writes the model, :class:`Simulation` runs it in wmr's variables,
:func:`run` drives it along a :class:`Schedule` (e.g. :func:`twist_schedule`) into a :class:`Recording`, and
:class:`Validity` says whether the run can be trusted.

MuJoCo is imported only when a :class:`Simulation` is made (``pip install 'wmr-kinematics[sim]'``).

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
