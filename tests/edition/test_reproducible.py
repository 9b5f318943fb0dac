"""Committed figures do not depend on the last bits of floating point.

Another CPU computes the same figure with arithmetic that differs in the last bits: another ``sin``
(SIMD or libm), another BLAS kernel.  Each figure is therefore drawn here from inputs moved by one
ulp (``np.nextafter``, up and down: every float the figure's data holds, the robot's mount points
included), with NumPy's transcendental functions moved by one ulp as well while it is drawn, and each
committed file (SVG, PDF, JSON) must come out byte for byte the same.
"""

from __future__ import annotations

import contextlib
import dataclasses
import json

import numpy as np
import pytest

import wmr
from edition import figures as F
from edition.figures import output

from conftest import ROOT

FIGURES = ROOT / "figures"
#: the NumPy functions whose last bit differs between CPUs (vectorised implementations and libm)
TRANSCENDENTAL = ("sin", "cos", "tan", "arcsin", "arccos", "arctan", "arctan2", "hypot", "sqrt", "exp", "log", "log10")


def nudge(x, direction, magnitude=False):
    """``x`` with every finite float moved one ulp towards ``direction`` (kept >= 0 where it is a ``magnitude``)."""
    if isinstance(x, wmr.Robot):
        return wmr.Robot([nudge(u, direction) for u in x.wheels], name=x.name)
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


@contextlib.contextmanager
def another_cpu(direction):
    """NumPy's transcendental functions return results one ulp off (as another CPU's may)."""
    saved = {name: getattr(np, name) for name in TRANSCENDENTAL}

    def off(fn):
        def f(*args, **kw):
            r = fn(*args, **kw)
            return (
                np.where(np.isfinite(r), np.nextafter(r, direction), r)
                if np.ndim(r)
                else (np.nextafter(r, direction) if np.isfinite(r) else r)
            )

        return f

    try:
        for name, fn in saved.items():
            setattr(np, name, off(fn))
        yield
    finally:
        for name, fn in saved.items():
            setattr(np, name, fn)


def test_nudge_and_another_cpu_change_what_they_touch():
    """The perturbations are real: without snapping, they would change the numbers drawn."""
    d = F.FIGURES["fig13"].data()
    moved = nudge(d, np.inf)
    assert not np.array_equal(moved.beta, d.beta) and np.all(moved.beta > d.beta)
    assert nudge(d.robot, -np.inf).mount_points[0, 0] < d.robot.mount_points[0, 0]
    exact = np.sin(0.5)
    with another_cpu(np.inf):
        off = np.sin(0.5)
    assert off == np.nextafter(exact, np.inf) and np.sin(0.5) == exact


@pytest.mark.parametrize("key", F.KEYS)
def test_committed_figure_is_invariant_under_one_ulp(key):
    mod = F.module(key)
    data = mod.data()
    committed = {fmt: (FIGURES / f"{key}.{fmt}").read_bytes() for fmt in output.formats(mod)}
    committed_json = json.loads((FIGURES / f"{key}.json").read_text(encoding="utf-8"))
    for direction in (np.inf, -np.inf):
        moved = nudge(data, direction)
        with another_cpu(direction):
            files = F._render(key, moved)
        for fmt, blob in files.items():
            assert blob == committed[fmt], f"figures/{key}.{fmt} changes when its inputs move by one ulp ({direction})"
        assert output.record(key, mod, moved) == committed_json, f"figures/{key}.json changes under one ulp"
