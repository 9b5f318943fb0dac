r"""The types of the public API's arguments and results, named once (for annotations and mypy).

==================  ===================================================================================
name                what it stands for
==================  ===================================================================================
``FloatArray``      a NumPy array of floats: a matrix, a stack of matrices, a batch of numbers
``IntArray``        a NumPy array of integers: ranks, mobilities, counts of a batch
``BoolArray``       a NumPy array of bools: a verdict per member of a batch
``Symbolic``        a SymPy expression or matrix
``Numbers``         numbers (``numpy.typing.ArrayLike``) or SymPy expressions: angles, lengths, rates
``Matrix``          what a backend builds: a NumPy array (numbers) or a SymPy matrix (symbols)
``Point``           a point of the platform plane, :math:`(x, y)`: two numbers or two SymPy expressions
``PathLike``        a file name: ``str`` or ``os.PathLike``
``WheelJoints``     a URDF file's wheel joints: names, ``{name: radius or None}``, or ``"name[=radius],..."``
``JointNames``      the joints' names of each wheel unit: ``joint_names[i][joint]``
==================  ===================================================================================

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
from numpy.typing import ArrayLike, NDArray

__all__ = ["ArrayLike", "BoolArray", "FloatArray", "IntArray", "JointNames", "Matrix", "Numbers", "PathLike", "Point",
           "Symbolic", "WheelJoints"]

FloatArray: TypeAlias = NDArray[np.floating[Any]]
IntArray: TypeAlias = NDArray[np.integer[Any]]
BoolArray: TypeAlias = NDArray[np.bool_]
Symbolic: TypeAlias = Any
Numbers: TypeAlias = Any               # ArrayLike | Symbolic
Matrix: TypeAlias = Any                # FloatArray | Symbolic
Point: TypeAlias = Any                 # tuple of two numbers or SymPy expressions
PathLike: TypeAlias = str | os.PathLike[str]
WheelJoints: TypeAlias = Mapping[str, float | None] | Sequence[str] | str
JointNames: TypeAlias = Sequence[Mapping[str, str]]
