"""Committed figures do not depend on the last bits of floating point.

Another CPU computes the same figure with arithmetic that differs in the last bits: another ``sin``
(SIMD or libm), another BLAS kernel.  Each figure is therefore drawn here from inputs moved by one
ulp (``np.nextafter``, up and down: every float the figure's data holds, the robot's mount points
included), with NumPy's transcendental functions moved by one ulp as well while it is drawn, and each
committed file (SVG, PDF, JSON) must come out byte for byte the same.  The perturbations are those of
``tests/perturb.py``, which ``tests/test_written_files.py`` applies to the files the writers write.
"""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

import wmr
from edition import figures as F
from edition.figures import output

from conftest import ROOT
from perturb import another_cpu, nudge

FIGURES = ROOT / "figures"


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


@pytest.mark.parametrize("direction", [pytest.param(np.inf, id="up"), pytest.param(-np.inf, id="down")])
def test_edition_tables_do_not_depend_on_the_last_bits(direction):
    """``figures/singularities.csv`` from the paper's robot moved by one ulp; a float a table holds by the rule."""
    from edition.families import coverage
    from edition.files import csv_text

    committed = (ROOT / "figures" / "singularities.csv").read_text(encoding="utf-8")
    robot = wmr.paper_robot("centred").numeric()  # the robot coverage.table uses by default
    assert csv_text(coverage.table(), coverage.COLUMNS) == committed
    with another_cpu(direction):
        assert csv_text(coverage.table(nudge(robot, direction)), coverage.COLUMNS) == committed
    row = {"x": 1 / 3, "y": np.float64(0.1) * 3}
    assert csv_text([row], ("x", "y")) == csv_text([nudge(row, direction)], ("x", "y")) == "x,y\n0.333333333333,0.3\n"


def test_the_edition_writes_csv_floats_by_the_rule():
    """No CSV writer of the edition formats a number itself: ``edition.files.csv_text`` does (wmr.io.decimals)."""
    bypass = re.compile(r"repr\(float|format\(float|\"\.\d+g\"|:\.\d+g\}|csv\.(Dict)?[Ww]riter\(")
    text = (ROOT / "edition" / "physics" / "__init__.py").read_text(encoding="utf-8")
    found = [line.strip() for line in text.splitlines() if bypass.search(line)]
    assert not found, f"edition/physics writes numbers around wmr.io.decimals: {found}"
