"""Chapter 9's experiments: verdicts computed from the measurements (a different physics flips them), and
``figures/physics.csv`` the same file when every input is moved by one ulp (as another CPU would move it)."""

from __future__ import annotations

import csv
import dataclasses
import io

import numpy as np
import pytest

from conftest import ROOT

pytest.importorskip("mujoco")

from edition import physics
from edition.physics import common
from edition.physics.common import FAILS, HOLDS, fmt, sig, verdict
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
    assert list(rows[0]) == [
        "experiment",
        "claim",
        "prediction",
        "measurement",
        "agreement",
        "verdict",
        "parameters",
        "whose",
        "rests_on",
        "overturn",
    ]
    for r in rows:
        assert r["verdict"].split(" (")[0] in (HOLDS, FAILS) or r["verdict"].startswith("holds within ")
        assert all(r[k].strip() for k in r)


def test_rounding_and_verdicts():
    assert sig(0.012345) == 0.012 and sig(-98765.0) == -99000.0 and fmt(0.049373) == "0.049"
    assert verdict(0.0149, 0.02, 0.1) == HOLDS and verdict(0.05, 0.02, 0.1) == "holds within 5.0 %"
    assert verdict(0.1049, 0.02, 0.1) == "holds within 10 %" and verdict(0.106, 0.02, 0.1) == FAILS  # rounded first


def test_a_stronger_servo_turns_the_jam_into_a_skid():
    """The jam verdict is computed: steering servos stronger than the friction moment mu N d drag the wheels."""
    weak = physics.jam_experiment()
    strong = physics.jam_experiment(Params(steer_torque=1.0))
    assert weak.verdict == HOLDS and strong.verdict == FAILS
    assert strong.data["generic"]["travel"] > 0.5 and weak.data["generic"]["travel"] < 0.02


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
    return {f.name: float(np.nextafter(getattr(p, f.name), direction)) for f in dataclasses.fields(p)}


@pytest.mark.parametrize("direction", [np.inf, -np.inf], ids=["up", "down"])
def test_physics_csv_does_not_depend_on_the_last_bits(monkeypatch, direction):
    """The committed table (written by chapter 9 through the build) comes out byte for byte from inputs moved by one
    ulp: measurements are rounded to two significant digits before they are printed or judged."""
    for k, v in list(common.SIZE.items()):
        monkeypatch.setitem(common.SIZE, k, float(np.nextafter(v, direction)))
    text = physics.csv_text(physics.run_all(Params(**_nudged(direction))))
    assert text == COMMITTED.read_text(encoding="utf-8")


@pytest.mark.parametrize("module", ["common", "contact", "drift", "friction", "noise", "resteer", "plot", "exercises"])
def test_doctests_and_docstrings(module):
    import doctest
    import importlib

    mod = importlib.import_module(f"edition.physics.{module}")
    assert mod.__doc__ and mod.__all__
    assert doctest.testmod(mod, optionflags=doctest.ELLIPSIS).failed == 0


def test_findings_section_is_made_from_the_published_table(tmp_path):
    rows = physics.read_csv(COMMITTED)
    md = physics.findings_markdown(COMMITTED)
    for whose in ("paper", "edition"):  # counted apart, each from the rows of its kind
        group = [r for r in rows if r["whose"] == whose]
        held = sum(not r["verdict"].startswith(FAILS) for r in group)
        assert f"{len(group)} {'claims of the paper' if whose == 'paper' else 'predictions'}" in md
        assert f"there, {held} hold" in md or f"(counted apart: not claims of the paper), {held} hold" in md
    assert md.count("\n| ") == len(rows) + 1 and all(r["verdict"].replace("|", "\\|") in md for r in rows)
    assert all(r["rests_on"] and r["overturn"] and r["whose"] in ("paper", "edition") for r in rows)
    bad = tmp_path / "x.csv"
    bad.write_text("a,b\n1,2\n")
    with pytest.raises(ValueError, match="not a physics.csv"):
        physics.read_csv(bad)
