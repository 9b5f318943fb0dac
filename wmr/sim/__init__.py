r"""Any :class:`wmr.Robot` in a physics engine (MuJoCo): export, run, measure.

wmr's model has rigid bodies, point contacts and no slip; in MuJoCo wheels have mass, contacts friction and servos
limits (:class:`Params`), so that what the model predicts can be measured.  No wheel kind is known here: each unit
describes its bodies and joints (:func:`wmr.io.mechanism.mechanism`) and which are driven.  :func:`to_mjcf` writes
the model, :class:`Simulation` runs it in wmr's variables, :func:`run` drives it along a :class:`Schedule` into a
:class:`Recording`, and :class:`Validity` says whether the run can be trusted.  MuJoCo is imported only when a
:class:`Simulation` is made (``pip install 'wmr-kinematics[sim]'``).
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
