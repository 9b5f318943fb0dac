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
