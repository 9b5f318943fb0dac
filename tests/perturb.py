"""Another CPU, simulated: inputs moved by one ulp (:func:`nudge`) and NumPy's transcendental functions one ulp off
(:func:`another_cpu`).

Another CPU computes the same numbers with arithmetic that differs in the last bits (another ``sin``, SIMD or libm,
another BLAS kernel).  The tests that check that committed files do not depend on those bits
(``tests/edition/test_reproducible.py`` for the figures, ``tests/test_written_files.py`` for every file a writer of
wmr or the edition writes) make such differences here: one source for both.
"""

from __future__ import annotations

import contextlib
import dataclasses

import numpy as np

import wmr

__all__ = ["TRANSCENDENTAL", "nudge", "another_cpu"]

#: the NumPy functions whose last bit differs between CPUs (vectorised implementations and libm)
TRANSCENDENTAL = ("sin", "cos", "tan", "arcsin", "arccos", "arctan", "arctan2", "hypot", "sqrt", "exp", "log", "log10")


def nudge(x, direction, magnitude=False):
    """``x`` with every finite float moved one ulp towards ``direction`` (kept >= 0 where it is a ``magnitude``).

    A :class:`wmr.Robot` is rebuilt from its nudged units (mount points, radii, offsets, angles; a value the unit
    refuses when moved, e.g. a roller angle of exactly pi/2 moved up, is kept); data classes,
    arrays, floats, tuples, lists and dicts are nudged field by field; anything else is returned as it is.  A data
    class field marked ``metadata={"json": "residual"}`` (the edition's figures) is a magnitude.
    """
    if isinstance(x, wmr.Robot):
        return wmr.Robot([_unit(u, direction) for u in x.wheels], name=x.name)
    if dataclasses.is_dataclass(x) and not isinstance(x, type):
        return dataclasses.replace(
            x,
            **{
                f.name: nudge(getattr(x, f.name), direction, f.metadata.get("json") == "residual")
                for f in dataclasses.fields(x)
                if f.init
            },
        )
    if isinstance(x, np.ndarray) and x.dtype.kind == "f":
        y = np.where(np.isfinite(x), np.nextafter(x, direction), x)
        return np.abs(y) if magnitude else y
    if isinstance(x, (float, np.floating)):
        z = float(np.nextafter(x, direction)) if np.isfinite(x) else float(x)
        return abs(z) if magnitude else z
    if isinstance(x, (tuple, list)):
        return type(x)(nudge(v, direction, magnitude) for v in x)
    if isinstance(x, dict):
        return {k: nudge(v, direction, magnitude) for k, v in x.items()}
    return x


def _unit(u, direction):
    """A wheel unit nudged field by field, each field the unit accepts moved (its checks are the library's)."""
    try:
        return nudge(u, direction)
    except wmr.errors.InputValueError:
        for f in dataclasses.fields(u):
            if f.init:
                with contextlib.suppress(wmr.errors.InputValueError):
                    u = dataclasses.replace(u, **{f.name: nudge(getattr(u, f.name), direction)})
        return u


@contextlib.contextmanager
def another_cpu(direction):
    """NumPy's transcendental functions (:data:`TRANSCENDENTAL`) return results one ulp off (as another CPU's may)."""
    saved = {name: getattr(np, name) for name in TRANSCENDENTAL}

    def off(fn):
        def f(*args, **kw):
            r = fn(*args, **kw)
            return (
                np.where(np.isfinite(r), np.nextafter(r, direction), r)
                if np.ndim(r)
                else (np.nextafter(r, direction) if np.isfinite(r) else r)
            )

        for method in ("reduce", "accumulate", "outer"):  # a ufunc's methods (np.hypot.reduce), one ulp off too
            if hasattr(fn, method):
                setattr(f, method, off(getattr(fn, method)))
        return f

    try:
        for name, fn in saved.items():
            setattr(np, name, off(fn))
        yield
    finally:
        for name, fn in saved.items():
            setattr(np, name, fn)
