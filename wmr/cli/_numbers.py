"""Numbers in and out of the commands: read from the command line (one number, or a list, space- or
comma-separated) with a one-line message, written in a table or as JSON (:func:`json_text`)."""

from __future__ import annotations

import json
import math

from ..errors import InputValueError
from ..io.decimals import DIGITS, quantise_all


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


def json_text(value, scale=1.0, scales=None, digits=DIGITS):
    """``value`` as the JSON a command prints (``--json``), every float by the rule of :mod:`wmr.io.decimals`.

    ``scales`` maps a top-level key to the scale of its numbers; the others are at ``scale`` (default 1:
    angles in radians and dimensionless numbers; ``None``: each number's own size).
    """
    if isinstance(value, dict):
        value = {k: quantise_all(v, (scales or {}).get(k, scale), digits) for k, v in value.items()}
    else:
        value = quantise_all(value, scale, digits)
    return json.dumps(value, indent=2)


def twist_words(twist, convention: str) -> dict:
    """A wmr twist ``[omega, vx, vy]`` as ``{name: value}`` in the order of ``convention``."""
    from ..model.conventions import TWIST_ORDER, Twist

    return dict(zip(TWIST_ORDER[convention], Twist(*(float(x) for x in twist)).in_convention(convention)))
