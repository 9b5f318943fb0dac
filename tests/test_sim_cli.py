"""`wmr simulate`: JSON that matches the runner, the model written with --mjcf, refusals and bad input in one line."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from wmr.cli import main

mujoco = pytest.importorskip("mujoco")

ROOT = Path(__file__).resolve().parents[1]


def _run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_simulate_json_and_model(capsys, tmp_path):
    xml = tmp_path / "swerve.xml"
    code, out, err = _run(
        capsys,
        "simulate",
        str(ROOT / "examples" / "swerve4.toml"),
        "--vx",
        "0.8",
        "--vy",
        "0.2",
        "--omega",
        "0.4",
        "--seconds",
        "2",
        "--mjcf",
        str(xml),
        "--json",
    )
    assert code == 0 and err == ""
    data = json.loads(out)
    for key, want in (("omega", 0.4), ("vx", 0.8), ("vy", 0.2)):
        assert data["simulated"][key] == pytest.approx(want, abs=0.02)
        assert data["forward_from_encoders"][key] == pytest.approx(data["simulated"][key], abs=0.01)
    assert data["encoder_slip_residual"] < 1e-3 and 0 < data["servo_load"] < 1
    assert mujoco.MjModel.from_xml_string(xml.read_text()).nu == 8


def test_simulate_table_and_export_only(capsys, tmp_path):
    code, out, _ = _run(
        capsys, "simulate", str(ROOT / "examples" / "differential.toml"), "--omega", "1", "--seconds", "1"
    )
    assert code == 0 and out.splitlines()[0].startswith("commanded") and "from encoders" in out
    xml = tmp_path / "tri.xml"
    code, out, _ = _run(
        capsys, "simulate", str(ROOT / "examples" / "tricycle.toml"), "--seconds", "0", "--mjcf", str(xml)
    )
    assert code == 0 and xml.read_text().startswith("<mujoco")


@pytest.mark.parametrize(
    "argv, message",
    [
        (["examples/omni3.toml"], "cannot export .*Swedish wheel"),
        (["examples/swerve4.toml", "--param", "sliding=-1"], "sliding"),
        (["examples/swerve4.toml", "--param", "grip=1"], "--param must be NAME=VALUE"),
        (["examples/swerve4.toml", "--seconds", "-1"], "--seconds must be >= 0"),
        (["examples/swerve4.toml", "--vx", "fast"], "--vx must be a number"),
    ],
)
def test_simulate_bad_input(capsys, argv, message):
    import re

    code, out, err = _run(capsys, "simulate", *[str(ROOT / a) if a.endswith(".toml") else a for a in argv])
    assert code == 2 and out == "" and re.search(message, err) and len(err.strip().splitlines()) == 1


def test_simulate_warns_of_a_twist_that_is_not_admissible(capsys):
    """A differential drive cannot move sideways: the run is made, and its wheels must slip, and it says so."""
    code, out, err = _run(capsys, "simulate", str(ROOT / "examples" / "differential.toml"), "--vy", "0.3",
                          "--seconds", "1", "--json")  # fmt: skip
    assert code == 0 and err == ""
    assert any("not admissible" in w for w in json.loads(out)["warnings"])
    code, out, _ = _run(capsys, "simulate", str(ROOT / "examples" / "differential.toml"), "--vx", "0.3",
                        "--seconds", "1", "--json")  # fmt: skip
    assert json.loads(out)["warnings"] == []


def test_simulate_warns_of_a_robot_that_cannot_stand(capsys, tmp_path):
    """Two wheels on one axle and nothing else: the platform tips over, and the run says so."""
    robot = tmp_path / "two.toml"
    text = (ROOT / "examples" / "differential.toml").read_text(encoding="utf-8")
    robot.write_text(text.split("[[wheel]]                   # castor")[0], encoding="utf-8")
    code, out, _ = _run(capsys, "simulate", str(robot), "--vx", "0.3", "--seconds", "1")
    assert code == 0 and "warning" in out and "does not stand on its contacts" in out


def test_simulate_warns_of_an_invalid_run(capsys):
    """An explicit integrator with a long step: the drive servos saturate and chatter, and the run says so."""
    code, out, _ = _run(capsys, "simulate", str(ROOT / "examples" / "paper_centred.toml"), "--vx", "1", "--omega",
                        "2", "--seconds", "1", "--param", "integrator=Euler", "timestep=0.004", "--json")  # fmt: skip
    assert code == 0 and any(w.startswith("the run is not valid") for w in json.loads(out)["warnings"])
