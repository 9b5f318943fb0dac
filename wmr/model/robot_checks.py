"""The robot checks, now in :mod:`wmr.model.validation` (this module path kept: the same names import from here)."""

from .validation import free_symbols, numeric_robot, robot

__all__ = ["robot", "numeric_robot", "free_symbols"]
