"""The command line on URDF and ROS 2 files: `wmr analyze` reads them as it reads TOML, `wmr convert` moves a robot
between formats, bad files and missing extras are one line and exit status 2; `import wmr` needs none of the extras."""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.cli import main

from conftest import WRITTEN

ROOT = Path(__file__).resolve().parent.parent


def _run(capsys, *argv):
    code = main([str(a) for a in argv])
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.mark.parametrize(
    "path, label",
    [
        ("urdf/diffbot.urdf", "(2,0)"),
        ("urdf/swerve.urdf", "(1,2)"),
        ("ros2/diff_drive.yaml", "(2,0)"),
        ("ros2/mecanum_drive.yaml", "(3,0)"),
        ("ros2/tricycle_steering.yaml", "(1,1)"),
    ],
)
def test_analyze_reads_urdf_and_ros2_files(capsys, path, label):
    pytest.importorskip("yourdfpy")
    pytest.importorskip("yaml")
    code, out, err = _run(capsys, "analyze", ROOT / "examples" / path, "--json", "--grid", "100", "--twists", "10")
    assert code == 0 and err == ""
    assert json.loads(out)["class"] == label == wmr.campion_class(wmr.load(ROOT / "examples" / path)).label


def test_convert_round_trip(capsys, tmp_path):
    pytest.importorskip("yourdfpy")
    urdf, toml = tmp_path / "bot.urdf", tmp_path / "bot.toml"
    assert _run(capsys, "convert", ROOT / "examples" / "paper_dual.toml", urdf)[0] == 0
    assert _run(capsys, "convert", urdf, toml)[0] == 0
    back, want = wmr.load(toml).F([0.1, 0.2, 0.3]), wmr.load(ROOT / "examples" / "paper_dual.toml").F([0.1, 0.2, 0.3])
    np.testing.assert_allclose(back, want, rtol=0, atol=WRITTEN)  # the files keep 12 digits (wmr.io.decimals)
    code, out, _ = _run(capsys, "convert", ROOT / "examples" / "tricycle.toml", "--to", "ros2")
    assert code == 0 and "tricycle_steering_controller:" in out


def test_convert_urdf_to_ros2_keeps_the_joint_names(capsys, tmp_path):
    pytest.importorskip("yourdfpy")
    yaml = pytest.importorskip("yaml")
    out = tmp_path / "diffbot.yaml"
    assert _run(capsys, "convert", ROOT / "examples" / "urdf" / "diffbot.urdf", out)[0] == 0
    params = yaml.safe_load(out.read_text())["diff_drive_controller"]["ros__parameters"]
    assert (params["left_wheel_names"], params["right_wheel_names"]) == (["left_wheel_joint"], ["right_wheel_joint"])
    assert "passive castors (wheel 3) are not joints of the controller" in out.read_text()
    assert wmr.campion_class(wmr.load(out)).label == "(2,0)"
    code, text, _ = _run(capsys, "convert", ROOT / "examples" / "urdf" / "swerve.urdf", "--to", "ros2")
    assert code == 0 and "front_left_axle_joint: front_left_steer_joint" in text


def test_convert_refuses_what_a_format_cannot_express(capsys):
    code, out, err = _run(capsys, "convert", ROOT / "examples" / "paper_dual.toml", "--to", "ros2")
    assert (code, out) == (2, "") and len(err.splitlines()) == 1
    assert err.startswith("wmr convert: ROS 2's drive controllers") and "not swerve: needs centred wheels only" in err


def test_a_bad_urdf_is_one_line_with_its_line(capsys, tmp_path):
    pytest.importorskip("yourdfpy")
    text = (
        (ROOT / "examples" / "urdf" / "diffbot.urdf")
        .read_text()
        .replace('<cylinder radius="0.08" length="0.04"/>', '<sphere radius="0.08"/>')
    )
    (tmp_path / "d.urdf").write_text(text)
    line = text[: text.index('<joint name="left_wheel_joint"')].count("\n") + 1
    code, _, err = _run(capsys, "analyze", tmp_path / "d.urdf")
    assert code == 2 and len(err.splitlines()) == 1
    assert err.startswith(f"wmr analyze: {tmp_path / 'd.urdf'}:{line}: joint 'left_wheel_joint': ")
    code, out, err = _run(
        capsys,
        "analyze",
        tmp_path / "d.urdf",
        "--wheel-joints",
        "left_wheel_joint=0.08,right_wheel_joint=0.08",
        "--json",
        "--grid",
        "50",
        "--twists",
        "5",
    )
    assert code == 0 and json.loads(out)["class"] == "(2,0)"


def test_a_missing_extra_is_one_line(capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "yaml", None)
    code, _, err = _run(capsys, "analyze", ROOT / "examples" / "ros2" / "diff_drive.yaml")
    assert code == 2 and len(err.splitlines()) == 1 and "pip install 'wmr-kinematics[ros]'" in err


def test_import_wmr_needs_none_of_the_extras():
    extras = {"yaml", "yourdfpy", "lxml", "trimesh", "wpimath"}
    code = f"import sys, wmr, wmr.io, wmr.odometry; print(sorted({{m.split('.')[0] for m in sys.modules}} & {extras}))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_the_extras_are_declared():
    import tomllib

    extras = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]
    from wmr.io.extras import EXTRAS

    for extra, (_, dist) in EXTRAS.items():
        assert any(d.lower().startswith(dist) for d in extras[extra]), extra
