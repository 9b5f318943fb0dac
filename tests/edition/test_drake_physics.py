"""Chapter 9's second engine (``edition.physics.drake``): the Drake plant is the robot ``wmr.sim`` exports, its
physics rolls and slides where it should, its verdicts come from the MuJoCo experiments' criterion functions, an
invalid run gives none, and ``figures/engines.csv`` round-trips and agrees with its own numbers."""

from __future__ import annotations

import re

import numpy as np
import pytest

from conftest import ROOT

pytest.importorskip("pydrake")
pytest.importorskip("mujoco")

from edition.physics import contact, drift, friction
from edition.physics.common import FAILS, HOLDS, INVALID, paper
from edition.physics.drake import experiments as X
from edition.physics.drake import table as T
from edition.physics.drake.model import build
from edition.physics.drake.run import simulate
from wmr.sim import Params, export
from wmr.sim.params import GRAVITY

COMMITTED = ROOT / "figures" / "engines.csv"


@pytest.mark.parametrize("kind", ["offset", "centred", "dual"])
def test_the_plant_is_the_exported_robot(kind):
    """Mass, joints and servos of the Drake plant are those of the MJCF export of the same robot."""
    robot = paper(kind)
    m = build(robot, contact="point")
    ex = export(robot)
    assert m.plant.CalcTotalMass(m.plant_context) == pytest.approx(ex.weight / GRAVITY, rel=1e-12)
    assert m.weight == pytest.approx(ex.weight, rel=1e-12)
    assert sorted(m.joints) == sorted(ex.name(i, j.name) for i, mech in enumerate(ex.mechanisms) for j in mech.joints)
    assert sorted(m.servo_names) == sorted(ex.servo_names)
    assert len(m.wheels) == sum(len(mech.wheels) for mech in ex.mechanisms)
    # the servo limits are the MJCF's (steering 0.1 W r, drive 0.5 W r)
    r = float(robot.wheels[0].r)
    p = Params()
    for name, limit in zip(m.servo_names, m.limit):
        expected = (p.steer_torque if name.endswith("steer") else p.drive_torque) * ex.weight * r
        assert limit == pytest.approx(expected, rel=1e-12), name


def test_wheels_roll_at_omega_r_and_slide_only_past_mu_w():
    """A rigid-body sanity check of the point contact: driven wheels roll the platform at omega r; with the drives
    locked, a sideways push below mu W holds and one above it slides."""
    robot = paper("centred")
    w = 2.0
    rates = {f"u{i + 1}_drive": w for i in range(3)}
    m = build(robot, contact="point", ramp=(rates, 10.0))
    rec = simulate(m, 1.0)
    v = (rec.pose[-1, 1:] - rec.pose[-21, 1:]) / (rec.t[-1] - rec.t[-21])  # the last 0.1 s
    r = float(robot.wheels[0].r)
    # wmr's sign: theta_dot > 0 moves the wheel centre along -j (j = y at beta = 0)
    assert v[1] == pytest.approx(-w * r, rel=0.02)
    assert abs(v[0]) < 0.01 * w * r
    for push, slides in ((0.5, False), (1.5, True)):
        m = build(robot, contact="point", locked_drives=True)
        rec = simulate(m, 0.3, push=lambda t, m=m, push=push: (push * m.weight, 0.0))
        moved = abs(rec.pose[-1, 1] - rec.pose[0, 1])
        assert (moved > 0.01) == slides, (push, moved)


def test_drake_verdicts_use_the_mujoco_criteria():
    """The Drake experiments judge by the very functions the MuJoCo experiments do (no thresholds typed twice)."""
    assert X.dead_zone_verdict is drift.dead_zone_verdict
    assert X.jam_verdict is drift.jam_verdict
    assert X.brake_verdict is contact.brake_verdict
    assert X.reorient_verdict is friction.reorient_verdict
    assert friction.reorient_verdict(0.01, 0.2) == HOLDS and friction.reorient_verdict(0.03, 0.2) == FAILS
    assert contact.brake_verdict(0.5, 0.04) == HOLDS and contact.brake_verdict(0.5, 0.06) == FAILS


def test_an_invalid_run_gives_no_verdict(monkeypatch):
    """With the penetration limit at 0, every resting wheel is 'sunk': the dead zone is refused, not judged."""
    import wmr.sim.validity as V

    monkeypatch.setattr(V, "PENETRATION", 0.0)
    r = X.dead_zone("point")
    assert r.verdict.startswith(INVALID) and "sank" in r.verdict
    assert r.problems


def _number(pattern, text):
    found = re.search(pattern, text)
    assert found, (pattern, text)
    return float(found.group(1))


def test_engines_csv_round_trips_and_its_verdicts_follow_from_its_numbers(tmp_path):
    rows = T.read_csv(COMMITTED)
    assert tuple(rows[0]) == T.ENGINE_COLUMNS
    assert T.write_csv(rows, tmp_path / "engines.csv").read_bytes() == COMMITTED.read_bytes()
    assert [r["experiment"] for r in rows if r["engine"].startswith("MuJoCo")] == list(T.EXPERIMENTS)
    # MuJoCo's rows are chapter 9's nominal runs, as physics.csv has them
    from edition import physics

    nominal = {r["experiment"]: r for r in physics.read_csv(ROOT / "figures" / "physics.csv")}
    for r in rows:
        if r["engine"].startswith("MuJoCo"):
            assert r["measurement"] == nominal[r["experiment"]]["measurement"]
            assert nominal[r["experiment"]]["nominal"].startswith(r["verdict"] + " (")
    drake = [r for r in rows if r["engine"].startswith("Drake")]
    assert {r["contact"].split(",")[0] for r in drake} == {"point", "hydroelastic"}
    for r in drake:
        m = r["measurement"]
        if r["experiment"] == "dual-wheel":
            dual = _number(r"spin-resisting part ([0-9.e-]+) N m", m)
            centred = _number(r"centred wheel's ([0-9.e-]+) N m", m)
            assert r["verdict"] == friction.reorient_verdict(dual, centred)
        elif r["experiment"] == "braking":
            a = _number(r"([0-9.e-]+) W in Fig. 12a", m)
            b = _number(r"([0-9.e-]+) W parked", m)
            assert r["verdict"] == contact.brake_verdict(a, b)
        elif r["experiment"] == "dead-zone":
            assert r["verdict"] == drift.dead_zone_verdict(_number(r"circle ([0-9.e-]+) % of d", m) / 100)
    # the report's paragraph states the agreement computed from the verdicts
    md = T.engines_markdown(COMMITTED)
    agree = T.agreement(rows)
    for key, v in agree.items():
        if v.startswith("agree"):
            assert key.replace("-", " ") in md.split("differ for")[0]
    assert md.count("\n| ") == len(rows) + 1  # the header and one line per row


def test_agreement_separates_engines_that_disagree():
    rows = [
        {"experiment": "x", "engine": "MuJoCo 4", "contact": "point", "verdict": HOLDS},
        {"experiment": "x", "engine": "Drake 1", "contact": "hydroelastic, E = 1e7 Pa", "verdict": FAILS},
        {"experiment": "y", "engine": "Drake 1", "contact": "point", "verdict": f"{INVALID} (a: b)"},
    ]
    out = T.agreement(rows)
    assert out["x"].startswith("depends on the engine or contact") and "Drake hydroelastic: does not hold" in out["x"]
    assert out["y"] == "no valid run"


def test_a_drake_run_is_repeatable():
    """Two runs of one experiment give the same text (the table is written from rounded numbers)."""
    a, b = X.dead_zone("point"), X.dead_zone("point")
    assert a.measurement == b.measurement and a.verdict == b.verdict
    assert np.array_equal(a.data["C"], b.data["C"])


@pytest.mark.parametrize("module", ["model", "run", "experiments", "table"])
def test_doctests_and_docstrings(module):
    import doctest
    import importlib

    mod = importlib.import_module(f"edition.physics.drake.{module}")
    assert mod.__doc__ and mod.__all__
    assert doctest.testmod(mod, optionflags=doctest.ELLIPSIS).failed == 0


@pytest.mark.parametrize("direction", [np.inf, -np.inf], ids=["up", "down"])
def test_a_drake_row_does_not_depend_on_the_last_bits(monkeypatch, direction):
    """The dead zone with point contact, every physical parameter and the robot's size moved by one ulp (as another
    CPU would move them), prints the committed row of engines.csv."""
    import dataclasses

    from edition.physics import common

    for k, v in list(common.SIZE.items()):
        monkeypatch.setitem(common.SIZE, k, float(np.nextafter(v, direction)))
    p = Params()
    nudged = {
        f.name: float(np.nextafter(getattr(p, f.name), direction))
        for f in dataclasses.fields(p)
        if isinstance(getattr(p, f.name), float) and getattr(p, f.name) > 0
    }
    committed = T.read_csv(COMMITTED)
    r = X.dead_zone("point", params=p.replace(**nudged))
    row = next(x for x in committed if x["experiment"] == "dead-zone" and x["contact"] == "point")
    assert (r.measurement, r.verdict) == (row["measurement"], row["verdict"])
    if (
        direction < 0
    ):  # the most sensitive row: a stiff hydroelastic patch (it moved by 5 % before its mesh was refined)
        r, _ = X.dual_wheel(1e8, params=p.replace(**nudged))
        row = next(x for x in committed if x["experiment"] == "dual-wheel" and "1e8" in x["contact"])
        assert (r.measurement, r.verdict) == (row["measurement"], row["verdict"])


def test_a_patch_resists_spin_and_a_point_does_not():
    """Reoriented in place with rolling disabled, a centred wheel meets no spin torque with Drake's point contact (it
    has no torsional coefficient) and a friction torque with the hydroelastic patch, of the order mu N times the
    patch's size (a few millimetres here)."""
    point, _ = X.reorient("centred", "point", 0.0, seconds=1.5)
    patch, rec = X.reorient("centred", "hydroelastic", 1e7, seconds=1.5)
    N = 12.1 * GRAVITY / 3
    assert abs(point) < 1e-3 * N * 0.05
    assert 0.001 * N < patch < 0.02 * N  # the patch's lever: between 1 and 20 mm
    assert rec.validity.valid()
