r"""Every input check of the package under one name: ``from wmr.model import validation``.

The checks themselves live in three modules, by what they check:

=================================  ===================================================================
:mod:`~wmr.model.checks`           scalars, points, flags, integers, text; the rule of the two exception types
:mod:`~wmr.model.arrays`           finite numeric batches and their broadcast shapes, SymPy vectors and matrices
:mod:`~wmr.model.robot_checks`     a :class:`wmr.Robot` instance, a numeric one, the symbols in one
=================================  ===================================================================

Bad input raises :class:`~wmr.errors.InputTypeError` (the wrong kind of thing) or
:class:`~wmr.errors.InputValueError` (a bad value), whose messages name the argument and show its
value.  The analyses use this module; the modules a robot is built from (platform, wheels,
robot) use :mod:`~wmr.model.checks` and :mod:`~wmr.model.arrays` directly, since
:mod:`~wmr.model.robot_checks` needs the robot.

Examples
--------
>>> positive("r", 0.1), finite_array("beta", [0.5, 1]).tolist()
(0.1, [0.5, 1.0])
"""

from __future__ import annotations

from .arrays import batch_shape, finite_array, symbolic_matrix, symbolic_vector, twist_array, twist_kind
from .checks import (
    finite_float,
    flag,
    integer,
    kind_error,
    nonnegative,
    number,
    optional_text,
    point,
    positive,
    real,
    show,
)
from .robot_checks import free_symbols, numeric_robot, robot

__all__ = [
    "real",
    "number",
    "positive",
    "nonnegative",
    "point",
    "flag",
    "optional_text",
    "integer",
    "show",
    "kind_error",
    "finite_float",
    "finite_array",
    "twist_array",
    "twist_kind",
    "batch_shape",
    "symbolic_vector",
    "symbolic_matrix",
    "robot",
    "numeric_robot",
    "free_symbols",
]
