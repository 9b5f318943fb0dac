"""wmr.sim's export: every example robot loads and steps in MuJoCo or is refused with a reason; the model's
geometry is wmr's (checked against the units' own points); servos where each wheel kind has them; MuJoCo only
where asked for."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.sim import (
    Params,
    chains,
    default_passive,
    export,
    start_angles,
    to_mjcf,
    unit_chain,
)

mujoco = pytest.importorskip("mujoco")

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))


def _model(xml):
    return mujoco.MjModel.from_xml_string(xml)


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_every_example_loads_and_steps_or_is_refused(path):
    robot = wmr.load(path)
    if any(isinstance(u, wmr.SwedishWheel) for u in robot.wheels):
        with pytest.raises(NotImplementedError, match="Swedish wheel at .*rollers"):
            to_mjcf(robot)
        return
    # offset arms along the spin about C: the paper's offset robot (d = L) tips over at beta = 0, when C lies
    # outside the triangle of its contact points
    m = _model(to_mjcf(robot, beta=start_angles(robot, [1.0, 0.0, 0.0])))
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, 0)
    mujoco.mj_step(m, d, nstep=500)
    assert np.isfinite(d.qpos).all()
    wheels = sum(len(c.wheels) for c in export(robot).chains)
    assert d.ncon == wheels                                     # every wheel on the ground, nothing else touching
    assert abs(d.qpos[2] - max(u.r for u in robot.wheels)) < 0.01 * max(u.r for u in robot.wheels)


def _mixed():
    return wmr.Robot([wmr.OffsetWheel((0.3, 0.1), r=0.05, d=0.03), wmr.CentredWheel((-0.2, 0.25), r=0.04),
                      wmr.DualWheel((-0.2, -0.25), r=0.03, b=0.06), wmr.FixedWheel((0.25, -0.3), r=0.05, angle=0.4)])


def test_geometry_is_wmrs():
    """At any steering angles, every wheel centre of the model is where the unit's points() put it, at height r."""
    robot = _mixed()
    rng = np.random.default_rng(1)
    for _ in range(3):
        beta = robot.effective_beta(rng.uniform(-np.pi, np.pi, robot.w))
        ex = export(robot, beta)
        m = _model(ex.xml)
        d = mujoco.MjData(m)
        mujoco.mj_resetDataKeyframe(m, d, 0)
        mujoco.mj_forward(m, d)
        for i, (u, ch) in enumerate(zip(robot.wheels, ex.chains)):
            want = u.points(beta[i])["wheels"]
            for k, link in enumerate(ch.wheels):
                got = d.xpos[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, ex.name(i, link.name))]
                assert np.allclose(got[:2], want[k], atol=1e-9) and got[2] == pytest.approx(u.r)
                axle = d.xmat[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, ex.name(i, link.name))].reshape(3, 3)[:, 0]
                assert np.allclose(axle[:2], u.points(beta[i])["i"], atol=1e-9)          # drive hinge about i_i


def test_each_kind_has_its_servos_and_rates():
    robot = _mixed()
    xml = to_mjcf(robot, passive=[False] * 4)
    assert xml.count("<position ") == 2 and xml.count("<velocity ") == 5      # offset, centred; 1 + 1 + 2 + 1 drives
    ex = export(robot, passive=[False] * 4)
    for u, ch in zip(robot.wheels, ex.chains):
        assert sorted(j.rate for j in ch.joints if j.rate is not None) == list(range(u.n_rates))
        assert sum(j.steering for j in ch.joints) == (1 if u.steered else 0)
    dual = ex.chains[2]
    assert [j.servo for j in dual.joints] == [None, chains.VELOCITY, chains.VELOCITY]      # the pivot is passive
    offset = ex.chains[0]
    assert [(j.name, j.absolute) for j in offset.joints] == [("steer", True), ("drive", False)]   # phi = psi + beta (7)


def test_castors_are_passive_unless_said_otherwise():
    diff = wmr.load(ROOT / "examples" / "differential.toml")
    assert default_passive(diff) == (False, False, True)
    assert default_passive(wmr.paper_robot("offset")) == (False, False, False)
    xml = to_mjcf(diff)
    assert "u3_steer" in xml and 'joint="u3_' not in xml                    # a castor: its hinges, no servo
    m = _model(xml)
    assert export(diff).servo_names == tuple(m.actuator(a).name for a in range(m.nu)) == ("u1_drive", "u2_drive")
    assert to_mjcf(diff, passive=[False, False, False]).count('joint="u3_') == 2


def test_parameters_reach_the_model():
    robot = wmr.paper_robot("centred", L=0.3, r=0.05)
    m = _model(to_mjcf(robot, sliding=0.6, torsional=0.1, rolling=0.02, timestep=0.002))
    g = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, "u1_wheel")
    assert np.allclose(m.geom_friction[g], [0.6, 0.1 * 0.05, 0.02 * 0.05]) and m.opt.timestep == 0.002
    ex = export(robot)
    mass = float(sum(_model(ex.xml).body_mass))
    assert ex.weight == pytest.approx(mass * 9.81)
    limit = _model(ex.xml).actuator_forcerange
    assert limit[0, 1] == pytest.approx(Params().steer_torque * ex.weight * 0.05)
    assert limit[1, 1] == pytest.approx(Params().drive_torque * ex.weight * 0.05)


def test_export_is_deterministic_and_carries_the_start_angles():
    robot = wmr.paper_robot("offset", L=0.3, r=0.05)
    a, b = to_mjcf(robot, beta=[0.1, 0.2, 0.3]), to_mjcf(robot, beta=[0.1, 0.2, 0.3])
    assert a == b
    m = _model(a)
    assert np.allclose(m.key_qpos[0][[7, 9, 11]], [0.1, 0.2, 0.3])


def test_bad_input_is_named():
    robot = wmr.paper_robot("centred", L=0.3, r=0.05)
    with pytest.raises(ValueError, match="passive"):
        to_mjcf(robot, passive=[True])
    with pytest.raises(ValueError, match="sliding"):
        to_mjcf(robot, sliding=-1.0)
    with pytest.raises(TypeError, match="unknown parameter"):
        to_mjcf(robot, slidng=1.0)
    with pytest.raises(TypeError, match="params"):
        to_mjcf(robot, params={"sliding": 1.0})
    with pytest.raises(ValueError, match="beta"):
        to_mjcf(robot, beta=[0.0, 0.0])
    with pytest.raises(NotImplementedError, match="no physical description"):
        unit_chain(object(), 0.1)


def test_import_wmr_does_not_import_mujoco():
    for statement in ("import wmr", "import wmr.sim; wmr.sim.to_mjcf(wmr.paper_robot())"):
        out = subprocess.run([sys.executable, "-c", f"import sys; {statement}; print('mujoco' in sys.modules)"],
                             capture_output=True, text=True, check=True).stdout.strip()
        assert out == "False", statement
    out = subprocess.run([sys.executable, "-c", ("import sys, wmr.sim; wmr.sim.Simulation(wmr.paper_robot('centred', L=0.3, r=0.05), settle=0);"
                          " print('mujoco' in sys.modules)")], capture_output=True, text=True, check=True).stdout.strip()
    assert out == "True"                                     # the check above can see an import


def test_sim_is_an_optional_extra():
    import tomllib
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert any(d.startswith("mujoco") for d in meta["optional-dependencies"]["sim"])
    assert not any(d.startswith("mujoco") for d in meta["dependencies"])
