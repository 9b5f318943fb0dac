"""The array checks, now in :mod:`wmr.model.checks` (this module path kept: the same names import from here)."""

from .checks import (
    TWIST_OBJECTS,
    batch_shape,
    finite_array,
    symbolic_matrix,
    symbolic_vector,
    twist_array,
    twist_kind,
)

__all__ = [
    "finite_array",
    "twist_array",
    "twist_kind",
    "TWIST_OBJECTS",
    "batch_shape",
    "symbolic_vector",
    "symbolic_matrix",
]
