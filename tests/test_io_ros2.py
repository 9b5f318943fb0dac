"""ROS 2 controller parameters in and out (wmr.io.from_ros2, wmr.io.to_ros2): the example files read as their robots,
the layouts round-trip, the controllers' own wheel-speed formulas agree with wmr's inverse kinematics of the robot read,
and bad files get one-line errors naming the file, the line and the node.key."""

from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.errors import InputValueError, MissingDependencyError, RobotFileError
from wmr.io import from_ros2, load, to_ros2
from wmr.io import layouts as L

yaml = pytest.importorskip("yaml")  # in environment.lock: runs here

ROOT = Path(__file__).resolve().parent.parent
ROS2 = ROOT / "examples" / "ros2"
TWISTS = np.random.default_rng(7).normal(0, 1, (50, 3))  # psi_dot, x_dot, y_dot


def _drive_rates(bot, twists, beta=None):
    """wmr's inverse kinematics: the drive joints' rates (theta_dot_i; Swedish rollers left out)."""
    beta = np.zeros(bot.w) if beta is None else beta
    rates = wmr.inverse(bot, beta, twists).value
    cols = [k for k, n in enumerate(bot.rate_names) if n.startswith("theta")]
    return rates[..., cols]


def _round_trip(bot, tmp_path, name="bot.yaml"):
    path = tmp_path / name
    to_ros2(bot, path)
    return from_ros2(path)


# ------------------------------------------------------------------------------------------ the examples
def test_diff_drive_example():
    bot = load(ROS2 / "diff_drive.yaml")
    assert [u.kind for u in bot.wheels] == ["fixed", "fixed"]
    np.testing.assert_allclose(bot.mount_points, [[0, 0.2], [0, -0.2]], atol=1e-15)
    assert [float(u.r) for u in bot.wheels] == [0.08, 0.08] and wmr.campion_class(bot).label == "(2,0)"
    # diff_drive_controller: left = (v - omega s / 2) / r, right = (v + omega s / 2) / r (v = vx)
    v, w = TWISTS[:, 1], TWISTS[:, 0]
    fwd = TWISTS * [1, 1, 0]  # no lateral velocity: admissible
    np.testing.assert_allclose(
        _drive_rates(bot, fwd), np.column_stack([(v - w * 0.2) / 0.08, (v + w * 0.2) / 0.08]), rtol=1e-12
    )


def test_mecanum_example_and_the_controllers_wheel_speeds():
    """mecanum_drive_controller.cpp: FL = (vx - vy - k w)/r, FR = (vx + vy + k w)/r, RL = (vx + vy - k w)/r,
    RR = (vx - vy + k w)/r with k = lx + ly: the rollers wmr reads give exactly these rates."""
    bot = load(ROS2 / "mecanum_drive.yaml")  # under the wildcard namespace /**
    assert [u.kind for u in bot.wheels] == ["swedish"] * 4 and wmr.campion_class(bot).label == "(3,0)"
    np.testing.assert_allclose(np.abs(bot.mount_points), 0.225, atol=1e-15)  # lx = ly = (lx + ly) / 2
    w, vx, vy = TWISTS.T
    k, r = 0.45, 0.05
    want = np.column_stack([vx - vy - k * w, vx + vy + k * w, vx + vy - k * w, vx - vy + k * w]) / r
    np.testing.assert_allclose(_drive_rates(bot, TWISTS), want, rtol=1e-12, atol=1e-12)
    # the 0.5 x 0.4 robot the file was written for has the same wheel speeds
    np.testing.assert_allclose(
        _drive_rates(wmr.load(ROOT / "examples" / "mecanum4.toml"), TWISTS), want, rtol=1e-12, atol=1e-12
    )


def test_tricycle_steering_example():
    bot = load(ROS2 / "tricycle_steering.yaml")
    assert [u.kind for u in bot.wheels] == ["centred", "fixed", "fixed"]
    np.testing.assert_allclose(bot.mount_points, [[0.5, 0], [0, 0.25], [0, -0.25]], atol=1e-15)
    assert bot.wheels[0].driven == (True, False)  # the controller steers it and drives the rear
    assert wmr.campion_class(bot).label == wmr.campion_class(wmr.load(ROOT / "examples" / "tricycle.toml")).label


def test_omni_controller_wheel_speeds(tmp_path):
    """omni_wheel_drive_controller.cpp: wheel i at a_i = offset + 2 pi i / n: (sin a vx - cos a vy - R w) / r."""
    bot = _round_trip(L.omni(4, 0.2, 0.02, offset=0.3), tmp_path)
    a = 0.3 + 2 * np.pi * np.arange(4) / 4
    w, vx, vy = TWISTS.T
    want = (np.sin(a) * vx[:, None] - np.cos(a) * vy[:, None] - 0.2 * w[:, None]) / 0.02
    np.testing.assert_allclose(_drive_rates(bot, TWISTS), want, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("name", ["swerve_drive", "omni_drive"])
def test_written_examples_are_what_wmr_writes(name):
    """examples/ros2/{swerve,omni}_drive.yaml are `wmr convert examples/{swerve4,omni3}.toml ...` (regenerate them)."""
    source = {"swerve_drive": "swerve4", "omni_drive": "omni3"}[name]
    assert (ROS2 / f"{name}.yaml").read_text() == to_ros2(wmr.load(ROOT / "examples" / f"{source}.toml"))


# ------------------------------------------------------------------------------------------ round trips
ROUND_TRIPS = {
    "differential": L.differential(0.4, 0.08),
    "differential, unequal radii": L.differential(0.4, 0.08, 0.081),
    "mecanum (square)": L.mecanum(L.rectangle(0.5, 0.5), 0.05),
    "omni": wmr.load(ROOT / "examples" / "omni3.toml"),
    "swerve": wmr.load(ROOT / "examples" / "swerve4.toml"),
    "swerve off-centre": L.swerve(L.rectangle(0.6, 0.5, (0.05, -0.02)), 0.05),
    "car-like (tricycle)": wmr.load(ROOT / "examples" / "tricycle.toml"),
    "bicycle": L.car(0.9, 0.0, 0.0, 0.2),
    "ackermann": L.car(2.7, 1.6, 1.5, 0.33),
}


@pytest.mark.parametrize("name", ROUND_TRIPS)
def test_round_trip(name, tmp_path):
    """load -> dump -> load: the same kinds, mount points, radii and Campion class, wheels in the layout's order."""
    bot = ROUND_TRIPS[name]
    back = _round_trip(bot, tmp_path)
    assert [u.kind for u in back.wheels] == [u.kind for u in bot.wheels]
    np.testing.assert_allclose(back.mount_points, bot.mount_points, rtol=0, atol=1e-12)
    np.testing.assert_allclose([float(u.r) for u in back.wheels], [float(u.r) for u in bot.wheels], rtol=1e-15)
    assert wmr.campion_class(back).label == wmr.campion_class(bot).label


def test_rectangular_mecanum_comes_back_square_with_the_same_kinematics(tmp_path):
    bot = wmr.load(ROOT / "examples" / "mecanum4.toml")
    text = to_ros2(bot)
    assert "lx = 0.25, ly = 0.2: the controller keeps their sum only" in text
    back = _round_trip(bot, tmp_path)
    np.testing.assert_allclose(np.abs(back.mount_points), 0.225, atol=1e-15)
    np.testing.assert_allclose(_drive_rates(back, TWISTS), _drive_rates(bot, TWISTS), rtol=1e-12, atol=1e-12)


def test_a_permuted_robot_comes_back_in_the_layouts_order(tmp_path):
    bot = wmr.load(ROOT / "examples" / "tricycle.toml")
    shuffled = wmr.Robot([bot.wheels[k] for k in (2, 0, 1)], name="shuffled")
    text = to_ros2(shuffled)
    assert 'traction_joints_names: ["wheel1_drive", "wheel3_drive"]' in text  # right, left; URDF's names
    back = _round_trip(shuffled, tmp_path)
    np.testing.assert_allclose(back.mount_points, bot.mount_points, atol=1e-15)


def test_passive_castors_are_left_out(tmp_path):
    castor = wmr.OffsetWheel((-0.3, 0.0), r=0.03, d=0.03, driven={"steer": False, "drive": False})
    bot = wmr.Robot(list(L.differential(0.4, 0.08).wheels) + [castor])
    text = to_ros2(bot)
    assert "passive castors (wheel 3) are not joints of the controller" in text
    assert _round_trip(bot, tmp_path).w == 2


def test_written_parameters_have_ros2s_types(tmp_path):
    """rclcpp's parameters are typed: update_rate an integer, lengths doubles, names strings."""
    data = yaml.safe_load(to_ros2(ROUND_TRIPS["ackermann"]))
    assert isinstance(data["controller_manager"]["ros__parameters"]["update_rate"], int)
    p = data["ackermann_steering_controller"]["ros__parameters"]
    assert all(isinstance(p[k], float) for k in ("wheelbase", "traction_track_width", "steering_track_width"))
    assert p["traction_joints_names"] == ["wheel4_drive", "wheel3_drive"]  # (right, left)
    assert p["steering_joints_names"] == ["wheel2_steer", "wheel1_steer"]


def test_joint_names_given(tmp_path):
    bot = L.differential(0.4, 0.08)
    text = to_ros2(bot, joint_names=[{"drive": "left_wheel_joint"}, {"drive": "right_wheel_joint"}])
    assert 'left_wheel_names: ["left_wheel_joint"]' in text and "joint names given" in text
    with pytest.raises(wmr.errors.InputTypeError, match="one mapping {joint: name} per wheel unit"):
        to_ros2(bot, joint_names=[{"drive": "left"}])
    with pytest.raises(InputValueError, match="has no name for joint 'drive' of wheel 2"):
        to_ros2(bot, joint_names=[{"drive": "left"}, {"steer": "right"}])


def test_the_older_parameter_names(tmp_path):
    """humble's ackermann_steering_controller: rear/front_wheels_names, *_wheel_track, *_wheels_radius."""
    path = tmp_path / "humble.yaml"
    path.write_text(
        "ackermann_steering_controller:\n  ros__parameters:\n    front_steering: true\n"
        "    rear_wheels_names: [rr, rl]\n    front_wheels_names: [fr, fl]\n    wheelbase: 2.7\n"
        "    front_wheel_track: 1.5\n    rear_wheel_track: 1.6\n    front_wheels_radius: 0.3\n"
        "    rear_wheels_radius: 0.33\n"
    )
    bot = from_ros2(path)
    np.testing.assert_allclose(bot.mount_points, [[2.7, 0.75], [2.7, -0.75], [0, 0.8], [0, -0.8]], atol=1e-15)
    assert [float(u.r) for u in bot.wheels] == [0.3, 0.3, 0.33, 0.33]


# ------------------------------------------------------------------------------------------ refusals
@pytest.mark.parametrize(
    "name, why",
    [
        (
            "steered_castors",
            "passive castors [2, 3] left out): not differential: needs exactly two fixed wheels, has 0 "
            "of 1 units; not mecanum",
        ),
        ("paper_dual", "not swerve: needs centred wheels only"),
        ("paper_offset", "wheel 1, 2, 3 constrains nothing but has motors"),
    ],
)
def test_robots_no_controller_expresses_are_refused(name, why):
    with pytest.raises(InputValueError, match="ROS 2's drive controllers .* cannot express") as err:
        to_ros2(wmr.load(ROOT / "examples" / f"{name}.toml"))
    assert why in str(err.value)


def test_a_swerve_off_a_rectangle_is_refused():
    bot = L.swerve([(0.3, 0.3), (0.3, -0.3), (-0.3, 0.31), (-0.3, -0.3)], 0.05)
    with pytest.raises(InputValueError, match="not the corners of a rectangle"):
        to_ros2(bot)


# ------------------------------------------------------------------------------------------ bad files
def _file(tmp_path, text, name="bad.yaml"):
    path = tmp_path / name
    path.write_text(text)
    return path


DIFF = (
    "diff_drive_controller:\n  ros__parameters:\n    left_wheel_names: [l]\n    right_wheel_names: [r]\n"
    "    wheel_separation: 0.4\n    wheel_radius: 0.08\n"
)


def test_a_missing_key_names_the_node_and_the_line(tmp_path):
    path = _file(tmp_path, DIFF.replace("    wheel_radius: 0.08\n", ""))
    with pytest.raises(RobotFileError) as err:
        from_ros2(path)
    e = err.value
    assert (e.file, e.line, e.key) == (str(path), 2, "diff_drive_controller.wheel_radius")
    assert e.reason.startswith("missing (the wheel radius in metres, > 0)")


def test_a_bad_value_names_its_line(tmp_path):
    with pytest.raises(RobotFileError, match=r"bad.yaml:5: diff_drive_controller.wheel_separation: must be positive"):
        from_ros2(_file(tmp_path, DIFF.replace("0.4", "-0.4")))
    with pytest.raises(RobotFileError, match=r"bad.yaml:6: diff_drive_controller.wheel_radius: must be a finite"):
        from_ros2(_file(tmp_path, DIFF.replace("0.08", "fast")))
    with pytest.raises(RobotFileError, match=r"bad.yaml:3: diff_drive_controller.left_wheel_names: 2 left and 1 right"):
        from_ros2(_file(tmp_path, DIFF.replace("[l]", "[l1, l2]")))


def test_a_nested_key_names_its_line(tmp_path):
    text = (ROS2 / "mecanum_drive.yaml").read_text().replace("wheels_radius: 0.05", "wheels_radius: 0")
    with pytest.raises(RobotFileError) as err:
        from_ros2(_file(tmp_path, text))
    assert err.value.key == "mecanum_drive_controller.kinematics.wheels_radius"
    assert err.value.line == text[: text.index("wheels_radius: 0")].count("\n") + 1


def test_floats_without_a_dot_are_floats_as_in_ros2(tmp_path):
    """ROS 2 reads 4e-1 as a double; PyYAML's YAML 1.1 would read it as a string."""
    bot = from_ros2(_file(tmp_path, DIFF.replace("0.4", "4e-1").replace("0.08", "8E-2")))
    np.testing.assert_allclose(bot.mount_points, [[0, 0.2], [0, -0.2]], atol=1e-15)
    with pytest.raises(RobotFileError, match=r"bad.yaml:2: diff_drive_controller: .*too large for double"):
        from_ros2(_file(tmp_path, DIFF.replace("0.4", "1e308")))


def test_yaml_syntax_errors_and_a_byte_order_mark(tmp_path):
    with pytest.raises(RobotFileError, match=r"bad.yaml:5: yaml: YAML syntax error: .* started at line 4\)"):
        from_ros2(_file(tmp_path, DIFF.replace("right_wheel_names: [r]", "right_wheel_names: [r")))
    assert from_ros2(_file(tmp_path, "\ufeff" + DIFF, "bom.yaml")).w == 2


def test_no_controller_and_two_controllers(tmp_path):
    with pytest.raises(RobotFileError, match="no drive controller wmr reads in the file"):
        from_ros2(_file(tmp_path, "imu_broadcaster:\n  ros__parameters:\n    sensor_name: imu\n"))
    two = DIFF + DIFF.replace("diff_drive_controller:", "other_diff:")
    with pytest.raises(RobotFileError, match=r"several drive controllers \(diff_drive_controller, other_diff\)"):
        from_ros2(_file(tmp_path, two))
    assert load(_file(tmp_path, two), controller="other_diff").w == 2
    with pytest.raises(RobotFileError, match=r"did you mean 'other_diff'\?"):
        from_ros2(_file(tmp_path, two), controller="other_dif")


def test_the_controller_manager_names_a_controller_without_parameters(tmp_path):
    text = (
        "controller_manager:\n  ros__parameters:\n    drive:\n"
        "      type: diff_drive_controller/DiffDriveController\nimu:\n  ros__parameters:\n    x: 1\n"
    )
    with pytest.raises(RobotFileError, match="names a diff_drive_controller/DiffDriveController 'drive', but the file"):
        from_ros2(_file(tmp_path, text))


def test_a_missing_pyyaml_names_the_extra(monkeypatch):
    monkeypatch.setitem(__import__("sys").modules, "yaml", None)
    with pytest.raises(MissingDependencyError, match=r"pip install 'wmr-kinematics\[ros\]'"):
        load(ROS2 / "diff_drive.yaml")
