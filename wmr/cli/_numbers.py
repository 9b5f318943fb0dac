"""Numbers on the command line: one number, or a list (space- or comma-separated), checked with a one-line message."""

from __future__ import annotations

import math

from ..errors import InputValueError

__all__ = ["number", "numbers", "fmt", "clean"]


def number(text, option):
    """``text`` as a finite float, or an input error naming ``option``."""
    try:
        x = float(text)
    except (TypeError, ValueError):
        raise InputValueError(f"{option} must be a number, got {text!r}") from None
    if not math.isfinite(x):
        raise InputValueError(f"{option} must be a finite number, got {text!r}")
    return x


def numbers(items, option, count, what):
    """A list of ``count`` finite floats from ``items`` (strings, each possibly comma-separated)."""
    parts = [p for item in items for p in str(item).replace(",", " ").split()]
    values = [number(p, option) for p in parts]
    if len(values) != count:
        raise InputValueError(f"{option} needs {count} values ({what}), got {len(values)}: {' '.join(parts)!r}")
    return values


def fmt(x, digits=6):
    """A number for a table: ``digits`` significant digits, no negative zero."""
    return f"{x + 0.0:.{digits}g}" if math.isfinite(x) else str(x)


def clean(values, scale):
    """``values`` with the entries at most ``TOL * scale`` set to 0 (rounding noise, for display)."""
    import numpy as np

    from ..model.tolerance import near_zero

    values = np.asarray(values, dtype=float)
    return np.where(near_zero(values, scale), 0.0, values)
