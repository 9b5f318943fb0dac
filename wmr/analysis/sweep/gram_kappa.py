"""The names of :mod:`wmr.analysis.gram_kappa` (the certified condition number from a 3x3 Gram matrix), from their old home.

The kernel moved up to :mod:`wmr.analysis` because :func:`wmr.condition_number` uses it too; code that
imports it from here gets the same objects.
"""

from __future__ import annotations

from ..gram_kappa import SCRATCH, UPPER, kappa_by_lapack, kappa_from_gram

__all__ = ["UPPER", "SCRATCH", "kappa_from_gram", "kappa_by_lapack"]
