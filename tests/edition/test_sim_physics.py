"""Chapter 9's experiments: verdicts computed from the measurements (a different physics flips them), and
``figures/physics.csv`` the same file when every input is moved by one ulp (as another CPU would move it)."""

from __future__ import annotations

import csv
import dataclasses
import io
import os
from pathlib import Path

import numpy as np
import pytest

from conftest import ROOT

pytest.importorskip("mujoco")

from edition import physics
from edition.physics import box, common
from edition.physics.common import FAILS, HOLDS, INVALID, fmt, sig, verdict
from wmr.sim import Params

COMMITTED = ROOT / "figures" / "physics.csv"


def test_table_has_one_row_per_experiment_and_the_columns_asked_for():
    rows = list(csv.DictReader(io.StringIO(COMMITTED.read_text(encoding="utf-8"))))
    assert [r["experiment"] for r in rows] == [
        "dead-zone",
        "jam",
        "incompatible-steering",
        "braking",
        "dual-wheel",
        "isotropy-noise",
        "resteer",
    ]
    assert tuple(rows[0]) == physics.COLUMNS
    assert {"nominal", "verdict", "box_fraction", "box_invalid", "flips", "quote"} <= set(physics.COLUMNS)
    for r in rows:
        assert r["verdict"].split(" (")[0] in (HOLDS, FAILS, box.DEPENDS, INVALID)
        assert r["nominal"].startswith((HOLDS, FAILS, INVALID))
        held, valid = (int(x) for x in r["box_holds"].split(" valid")[0].split(" of "))
        assert r["verdict"].split(" (")[0] == box.rule(held, valid)  # the stated rule, from the counts
        assert r["box_fraction"] == f"{held / valid:.2f}"
        assert (r["whose"] == "paper") == bool(r["quote"])  # every claim of the paper quotes its sentence
        assert all(r[k].strip() for k in r if k != "quote")
    # the paper's claims are those whose sentence the paper prints; the edition's own models are counted apart
    assert {r["experiment"] for r in rows if r["whose"] == "edition"} == {"jam", "isotropy-noise", "resteer"}


def test_each_quote_is_the_papers_sentence():
    """A quoted sentence is found, word for word, in the paper's text (spaces and TeX of C_f aside)."""
    import re

    text = Path(os.environ.get("WMR_PAPER_TEXT", "/work/shared/paper/leow-low-loh-2002-wmr-kinematics.md"))
    if not text.exists():
        pytest.skip("the paper's text is not on this machine")

    def norm(t):
        t = re.sub(r"\s+", " ", re.sub(r"\$\s*C_\{\\rm f\}\s*\$", "C_f", t))
        return re.sub(r" ([,;.])", r"\1", t).strip()

    paper = norm(text.read_text(encoding="utf-8"))
    for r in physics.read_csv(COMMITTED):
        if r["quote"]:
            sentence = r["quote"].split("“")[1].split("”")[0]
            assert norm(sentence) in paper, r["experiment"]


def test_rounding_and_verdicts():
    assert sig(0.012345) == 0.012 and sig(-98765.0) == -99000.0 and fmt(0.049373) == "0.049"
    assert verdict(0.0149, 0.02, 0.1) == HOLDS and verdict(0.05, 0.02, 0.1) == "holds within 5.0 %"
    assert verdict(0.1049, 0.02, 0.1) == "holds within 10 %" and verdict(0.106, 0.02, 0.1) == FAILS  # rounded first


def test_a_stronger_servo_turns_the_jam_into_a_skid():
    """The jam verdict is computed: steering servos stronger than the friction moment mu N d drag the wheels, and the
    jam's own rerun with servos of 3 mu N d says what the platform does (from the run, not typed)."""
    weak = physics.jam_experiment()
    strong = physics.jam_experiment(Params(steer_torque=1.0))
    assert weak.verdict == HOLDS and strong.verdict == FAILS and weak.valid and strong.valid
    assert strong.data["generic"]["travel"] > 0.5 and weak.data["generic"]["travel"] < 0.02
    rerun = weak.data["strong"]
    assert rerun["travel"] > 0.5 and rerun["does"] == ("scrubs and drifts" if rerun["moved"] > 0.1 else "scrubs")
    assert f"it {rerun['does']}" in weak.measurement


def test_an_invalid_run_gives_no_verdict():
    """A run with a validity problem is counted invalid over the box, whatever its numbers say; the rule reads the
    valid runs only, and flips are named by parameter and value."""
    nominal = physics.dead_zone_experiment()
    unstable = dataclasses.replace(nominal, problems=("turn: u1_steer chattered",))

    def experiment(params, **kw):
        return unstable if params.integrator == "Euler" else nominal if params.sliding >= 1.0 else failing

    failing = dataclasses.replace(nominal, verdict=FAILS)
    judged = box.judge(experiment)
    b = judged.box
    assert b.invalid == 1 and b.valid == len(box.points()) - 1 and b.verdict == box.DEPENDS
    assert "integrator Euler: invalid run (servo chatter)" in b.flips and "sliding 0.5: does not hold" in b.flips
    assert judged.row()["verdict"].startswith(box.DEPENDS) and judged.row()["box_invalid"] == "1"
    assert box.rule(3, 3) == HOLDS and box.rule(0, 2) == FAILS and box.rule(0, 0) == INVALID


def test_the_dual_wheel_under_euler_is_invalid_not_a_verdict():
    """The issue's case: under Euler the dual wheel's drive servos go unstable; the experiment refuses the run."""
    out = physics.reorient_experiment(Params(integrator="Euler"))
    assert not out.valid and any("dual" in p for p in out.problems)
    assert physics.reorient_experiment().valid


def test_without_torsional_friction_the_dual_wheel_claim_is_not_tested_away():
    """With no torsional friction anywhere, both units meet only what the paper says: the centred wheel nothing, the
    dual wheel its rolling friction c_rr N b (measured as power over rate, not typed)."""
    dual = physics.friction.reorient("dual", Params(torsional=0.0))
    centred = physics.friction.reorient("centred", Params(torsional=0.0))
    N = dual["weight"] / 3
    assert dual["torque"].mean() == pytest.approx(0.01 * N * 0.05, rel=0.05)
    assert centred["torque"].mean() < 0.01 * dual["torque"].mean()


def test_weakest_push_by_hand():
    """Parallel wheels along y: a push along y rolls them (c_rr), along x slides them all (mu)."""
    bot = common.paper("centred")
    assert physics.contact.weakest_push(bot, [0.0] * 3, (0.0, 1.0)) == pytest.approx(0.01)
    assert physics.contact.weakest_push(bot, [0.0] * 3, (1.0, 0.0)) == pytest.approx(1.0)


def _nudged(direction):
    """Every input of the experiments moved by one ulp: the robots' sizes and the physical parameters."""
    p = Params()
    return {
        f.name: float(np.nextafter(getattr(p, f.name), direction))
        for f in dataclasses.fields(p)
        if not isinstance(getattr(p, f.name), str)  # the integrator and the cone: names, no last bit
    }


@pytest.mark.parametrize("direction", [np.inf, -np.inf], ids=["up", "down"])
def test_physics_csv_does_not_depend_on_the_last_bits(monkeypatch, direction):
    """The committed table (written by chapter 9 through the build) comes out byte for byte from inputs moved by one
    ulp: measurements are rounded to two significant digits before they are printed or judged."""
    for k, v in list(common.SIZE.items()):
        monkeypatch.setitem(common.SIZE, k, float(np.nextafter(v, direction)))
    text = physics.csv_text(physics.run_all(Params(**_nudged(direction))))
    assert text == COMMITTED.read_text(encoding="utf-8")


@pytest.mark.parametrize(
    "module", ["box", "common", "contact", "drift", "friction", "noise", "resteer", "plot", "exercises"]
)
def test_doctests_and_docstrings(module):
    import doctest
    import importlib

    mod = importlib.import_module(f"edition.physics.{module}")
    assert mod.__doc__ and mod.__all__
    assert doctest.testmod(mod, optionflags=doctest.ELLIPSIS).failed == 0


def test_findings_section_is_made_from_the_published_table(tmp_path):
    rows = physics.read_csv(COMMITTED)
    md = physics.findings_markdown(COMMITTED)
    t = physics.tally(rows)
    for whose in ("paper", "edition"):  # counted apart, each from the rows of its kind
        group = [r for r in rows if r["whose"] == whose]
        held = sum(r["verdict"].startswith(HOLDS) for r in group)
        assert t[whose]["tested"] == len(group) and t[whose]["hold"] == held
        assert f"{len(group)} {'claims of the paper' if whose == 'paper' else 'predictions'}" in md
        assert f"there, {held} hold" in md or f"(counted apart: not claims of the paper), {held} hold" in md
    assert md.count("\n| ") == len(rows) + 1 and all(r["flips"].replace("|", "\\|") in md for r in rows)
    assert all(r["rests_on"] and r["overturn"] and r["whose"] in ("paper", "edition") for r in rows)
    bad = tmp_path / "x.csv"
    bad.write_text("a,b\n1,2\n")
    with pytest.raises(ValueError, match="not a physics.csv"):
        physics.read_csv(bad)


def test_while_nbgrader_grades_only_the_nominal_point_runs_and_no_verdict_is_claimed(monkeypatch):
    monkeypatch.setenv("NBGRADER_EXECUTION", "autograde")
    o = physics.run(physics.dead_zone_experiment)
    assert len(o.box.runs) == 1 and o.box.partial
    assert o.box.verdict.startswith("not judged over the box") and o.box.fraction_text == ""
    assert o.box.verdict not in (HOLDS, FAILS, box.DEPENDS) and "not run" in o.box.flips
    monkeypatch.delenv("NBGRADER_EXECUTION")
    assert len(physics.run(physics.dead_zone_experiment).box.runs) == len(box.points())  # the whole box
