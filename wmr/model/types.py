r"""The types of the public API's arguments and results, named once (for annotations and mypy).

Shapes are in the docstrings (numpydoc), not in the types.  SymPy ships no type information, so to
mypy a SymPy object is ``Any``, and so is every type that admits one (``Symbolic``, ``Numbers``,
``Matrix``, ``Point``): the names say what is meant, the docstrings say the shapes, and the code that
takes such a value converts it (:mod:`wmr.model.validation`) before it computes with it.
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from typing import Any, TypeAlias

import numpy as np
from numpy.typing import ArrayLike as _ArrayLike
from numpy.typing import NDArray

__all__ = [
    "ArrayLike",
    "BoolArray",
    "FloatArray",
    "IntArray",
    "JointNames",
    "Matrix",
    "Numbers",
    "PathLike",
    "Point",
    "Symbolic",
    "TwistLike",
    "WheelJoints",
]

#: what NumPy converts to an array: numbers, nested sequences, arrays (``numpy.typing.ArrayLike``)
ArrayLike: TypeAlias = _ArrayLike
#: a NumPy array of floats
FloatArray: TypeAlias = "NDArray[np.floating[Any]]"  # (a string: Sphinx documents it as data)
#: a NumPy array of integers
IntArray: TypeAlias = "NDArray[np.integer[Any]]"
#: a NumPy array of bools
BoolArray: TypeAlias = "NDArray[np.bool_]"
#: a SymPy expression or matrix (to mypy: ``Any``)
Symbolic: TypeAlias = Any
#: numbers (``ArrayLike``) or SymPy expressions (to mypy: ``Any``)
Numbers: TypeAlias = Any
#: a NumPy array or a SymPy matrix, as a backend builds it (to mypy: ``Any``)
Matrix: TypeAlias = Any
#: a point (x, y): two numbers or two SymPy expressions (to mypy: ``Any``)
Point: TypeAlias = Any
#: a twist (..., 3) in wmr's order, a :class:`wmr.Twist`, or objects with the fields of a ChassisSpeeds or Twist2d,
#: read by field (:func:`wmr.model.checks.twist_array`; to mypy: ``Any``)
TwistLike: TypeAlias = Any
#: a file name
PathLike: TypeAlias = str | os.PathLike[str]
#: a URDF file's wheel joints: names, ``{name: radius or None}``, or ``"name[=radius],..."``
WheelJoints: TypeAlias = Mapping[str, float | None] | Sequence[str] | str
#: the joints' names of each wheel unit: ``joint_names[i][joint]``
JointNames: TypeAlias = Sequence[Mapping[str, str]]
