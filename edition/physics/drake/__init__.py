r"""The second engine: four of chapter 9's experiments in Drake, from the same robots, beside MuJoCo.

Issue 31 asked for the dead zone, the jam, the braking at Fig. 12a (v) and the dual wheel's torque in a second
physics engine, with point and hydroelastic contact, and the engines side by side in the report.

==========================================  ==================================================================
module                                      what it holds
==========================================  ==================================================================
:mod:`~edition.physics.drake.model`         a :class:`wmr.Robot` as a Drake MultibodyPlant (:func:`build`)
:mod:`~edition.physics.drake.run`           running it: servo targets, samples, each run's validity
:mod:`~edition.physics.drake.experiments`   the four experiments, judged by the MuJoCo experiments' criteria
:mod:`~edition.physics.drake.table`         ``engines.csv`` and the report's paragraph (:func:`engines_markdown`)
==========================================  ==================================================================

Drake (``pydrake``) is imported only when a model is built.
"""

from __future__ import annotations

from .experiments import Result, brake, dead_zone, dual_wheel, jam
from .model import build
from .table import (
    ENGINE_COLUMNS,
    EXPERIMENTS,
    agreement,
    available,
    engines_markdown,
    read_csv,
    rows,
    run_all,
    write_csv,
)

__all__ = [
    "ENGINE_COLUMNS",
    "EXPERIMENTS",
    "Result",
    "agreement",
    "available",
    "brake",
    "build",
    "dead_zone",
    "dual_wheel",
    "engines_markdown",
    "jam",
    "read_csv",
    "rows",
    "run_all",
    "write_csv",
]
