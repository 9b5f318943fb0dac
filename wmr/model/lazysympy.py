"""SymPy, imported when a symbolic value or derivation first needs it: a numeric call never pays for it.

``import sympy`` costs about 0.2 s, half of what ``wmr analyze`` takes on a small robot.  The numeric
paths only ever ask whether a value *is* a SymPy object, and no value can be one before SymPy is
imported: :func:`is_sympy` answers that without importing it.  :data:`sp` stands for the module and
imports it on its first attribute (``sp.Matrix``, ``sp.symbols``): the symbolic paths read as before.

Examples
--------
>>> is_sympy(1.0)
False
>>> is_sympy(sp.Symbol("x")), is_sympy(sp.Matrix([1]), "MatrixBase")
(True, True)
"""

from __future__ import annotations

import importlib
import sys
from typing import Any

__all__ = ["sp"]


class _OnDemand:
    """The ``sympy`` module, imported on the first attribute asked of it."""

    def __getattr__(self, name: str) -> Any:
        return getattr(importlib.import_module("sympy"), name)

    def __repr__(self) -> str:
        return "<sympy, imported when first used>"


#: ``sympy`` (imported on first use)
sp: Any = _OnDemand()


def is_sympy(value: object, *kinds: str) -> bool:
    """True when ``value`` is an instance of SymPy's classes ``kinds`` (default ``Basic``), without importing SymPy."""
    module = sys.modules.get("sympy")
    return module is not None and isinstance(value, tuple(getattr(module, k) for k in kinds or ("Basic",)))
