"""URDF in and out (wmr.io.from_urdf, wmr.io.to_urdf): hand-written files read as the robots they describe, every
example robot round-trips, and bad files get one-line errors naming the file, the line and the joint or link."""

import importlib.util
from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.errors import MissingDependencyError, RobotFileError
from wmr.io import dump, from_urdf, load, to_urdf

from conftest import WRITTEN

# in environment.lock: runs here (imported by the tests that use it, not at collection)
if importlib.util.find_spec("yourdfpy") is None:
    pytest.skip("yourdfpy is not installed", allow_module_level=True)

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))


def _same(a, b):
    """Same kinds, mount points, radii, kind parameters and actuation, wheel by wheel."""
    assert [type(u) for u in a.wheels] == [type(u) for u in b.wheels]
    np.testing.assert_allclose(b.mount_points, a.mount_points, rtol=0, atol=WRITTEN)
    for u, v in zip(a.wheels, b.wheels):
        pu, pv = u.numeric().parameters(), v.numeric().parameters()
        assert pu.keys() == pv.keys()
        for k in pu:
            assert float(pv[k]) == pytest.approx(float(pu[k]), abs=WRITTEN), (u, k)
        assert u.driven == v.driven
    assert wmr.campion_class(a).label == wmr.campion_class(b).label


def _line(text, needle):
    """The line (from 1) of the first occurrence of ``needle`` in ``text``."""
    return text[: text.index(needle)].count("\n") + 1


# ------------------------------------------------------------------------------------------ reading
def test_diffbot_urdf_is_a_differential_drive_with_a_passive_castor():
    bot = load(ROOT / "examples" / "urdf" / "diffbot.urdf")
    assert bot.name == "diffbot"
    assert [u.kind for u in bot.wheels] == ["fixed", "fixed", "offset"]
    np.testing.assert_allclose(bot.mount_points, [[0, 0.2], [0, -0.2], [-0.3, 0]], atol=1e-12)
    assert [float(u.r) for u in bot.wheels] == [0.08, 0.08, 0.03]
    assert [float(u.angle) for u in bot.wheels[:2]] == [np.pi / 2, np.pi / 2]  # type: ignore[attr-defined]  # snapped
    assert float(bot.wheels[2].d) == pytest.approx(0.03, abs=1e-12)  # type: ignore[attr-defined]
    assert [u.driven for u in bot.wheels] == [(True,), (True,), (False, False)]  # from <ros2_control>
    assert wmr.campion_class(bot).label == "(2,0)"


def test_swerve_urdf_is_four_swerve_modules():
    bot = load(ROOT / "examples" / "urdf" / "swerve.urdf")
    assert [u.kind for u in bot.wheels] == ["centred"] * 4
    np.testing.assert_allclose(np.abs(bot.mount_points), 0.2921, atol=1e-12)
    assert {float(u.r) for u in bot.wheels} == {0.0508}
    assert all(u.driven == (True, True) for u in bot.wheels)
    assert wmr.campion_class(bot).label == "(1,2)"


def test_without_ros2_control_the_kinds_defaults_hold(tmp_path):
    text = (ROOT / "examples" / "urdf" / "diffbot.urdf").read_text()
    text = text[: text.index("<ros2_control")] + "</robot>\n"
    (tmp_path / "d.urdf").write_text(text)
    bot = load(tmp_path / "d.urdf")
    defaults = [tuple(j.driven for j in type(u).JOINTS) for u in bot.wheels]
    assert [u.driven for u in bot.wheels] == defaults == [(True,), (True,), (True, True)]


# ------------------------------------------------------------------------------------------ round trips
@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_every_example_round_trips_through_urdf(path, tmp_path):
    """load -> dump -> load: the same robot (kinds, mount points, radii, offsets, angles, rollers, actuation, class)."""
    bot = load(path)
    out = tmp_path / "bot.urdf"
    text = dump(bot, out)
    assert to_urdf(bot) == text == out.read_text()  # the same bytes every time
    back = load(out)
    assert back.name == bot.name
    _same(bot, back)


def test_round_trip_with_actuation_changed_and_a_dual_wheel(tmp_path):
    bot = wmr.Robot(
        [
            wmr.DualWheel((0.3, 0.1), r=0.05, b=0.04, driven={"swivel": True}),
            wmr.OffsetWheel((-0.2, 0.2), r=0.03, d=0.02, driven={"steer": False}),
            wmr.SwedishWheel((-0.2, -0.2), r=0.04, angle=0.3, roller=-0.6, driven={"roller": True}),
        ],
        name="mixed",
    )
    to_urdf(bot, tmp_path / "m.urdf")
    _same(bot, from_urdf(tmp_path / "m.urdf"))


def test_urdf_to_toml_and_back(tmp_path):
    bot = load(ROOT / "examples" / "urdf" / "diffbot.urdf")
    dump(bot, tmp_path / "d.toml")
    dump(load(tmp_path / "d.toml"), tmp_path / "d.urdf")
    _same(bot, load(tmp_path / "d.urdf"))


@pytest.mark.parametrize("name", ["mecanum4", "tricycle"])
def test_written_examples_are_what_wmr_writes(name):
    """examples/urdf/{mecanum4,tricycle}.urdf are `wmr convert examples/NAME.toml`: regenerate them if this fails."""
    written = to_urdf(load(ROOT / "examples" / f"{name}.toml"))
    assert (ROOT / "examples" / "urdf" / f"{name}.urdf").read_text() == written


# ------------------------------------------------------------------------------------------ wheel_joints
def _mesh_wheels(tmp_path):
    text = (ROOT / "examples" / "urdf" / "diffbot.urdf").read_text()
    text = text.replace('<cylinder radius="0.08" length="0.04"/>', '<mesh filename="package://bot/wheel.dae"/>')
    path = tmp_path / "mesh.urdf"
    path.write_text(text)
    return path, text


def test_a_wheel_without_a_cylinder_is_an_error_naming_the_joint_and_its_line(tmp_path):
    path, text = _mesh_wheels(tmp_path)
    with pytest.raises(RobotFileError) as err:
        load(path)
    e = err.value
    assert (e.file, e.key) == (str(path), "joint 'left_wheel_joint'")
    assert e.line == _line(text, '<joint name="left_wheel_joint"')
    assert "no <cylinder>" in e.reason and "a mesh" in e.reason and "--wheel-joints" in e.reason


def test_wheel_joints_give_the_radius_of_a_mesh_wheel(tmp_path):
    path, _ = _mesh_wheels(tmp_path)
    bot = load(path, wheel_joints="left_wheel_joint=0.08, right_wheel_joint=0.08")
    assert [u.kind for u in bot.wheels] == ["fixed", "fixed"] and [float(u.r) for u in bot.wheels] == [0.08, 0.08]
    assert wmr.campion_class(bot).label == "(2,0)"
    assert load(path, wheel_joints={"left_wheel_joint": 0.08, "right_wheel_joint": 0.08}).w == 2
    with pytest.raises(RobotFileError, match="no <cylinder>: give its radius"):
        load(path, wheel_joints=["left_wheel_joint", "right_wheel_joint"])
    with pytest.raises(RobotFileError, match=r"did you mean 'left_wheel_joint'\?"):
        load(path, wheel_joints="left_wheel_jiont=0.08")


def test_a_wheel_axis_that_is_not_horizontal(tmp_path):
    text = (ROOT / "examples" / "urdf" / "diffbot.urdf").read_text()
    text = text.replace('<origin xyz="0 0.20 0" rpy="-1.5708 0 0"/>', '<origin xyz="0 0.20 0" rpy="-1.2 0 0"/>')
    (tmp_path / "tilt.urdf").write_text(text)
    with pytest.raises(RobotFileError) as err:
        load(tmp_path / "tilt.urdf", wheel_joints="left_wheel_joint,right_wheel_joint")
    assert err.value.key == "joint 'left_wheel_joint'" and "must be horizontal" in err.value.reason
    assert err.value.line == _line(text, '<joint name="left_wheel_joint"')


def test_a_cylinder_across_its_axle(tmp_path):
    text = (ROOT / "examples" / "urdf" / "swerve.urdf").read_text()
    text = text.replace('<origin xyz="0 0 0" rpy="1.5707963 0 0"/>', '<origin xyz="0 0 0" rpy="0 0 0"/>', 2)
    (tmp_path / "s.urdf").write_text(text)
    with pytest.raises(RobotFileError) as err:
        load(tmp_path / "s.urdf")
    assert err.value.key == "link 'front_left_wheel'" and "not along the axis" in err.value.reason
    assert err.value.line == _line(text, '<link name="front_left_wheel"')


# ------------------------------------------------------------------------------------------ bad files
def _write(tmp_path, body):
    path = tmp_path / "bad.urdf"
    path.write_text(f'<?xml version="1.0"?>\n<robot name="bad">\n{body}\n</robot>\n')
    return path


LINKS = (
    '<link name="base"/>\n'
    '<link name="a"><visual><geometry><cylinder radius="0.1" length="0.02"/></geometry></visual></link>'
)


def test_no_wheels(tmp_path):
    path = _write(
        tmp_path,
        '<link name="base"/>\n<link name="arm"/>\n<joint name="j" type="revolute"><parent '
        'link="base"/><child link="arm"/><axis xyz="0 1 0"/><limit lower="0" upper="1" effort="1" '
        'velocity="1"/></joint>',
    )
    with pytest.raises(RobotFileError, match=r"bad.urdf:2: robot: no wheels: .*moving joints: j \(revolute"):
        load(path)


def test_malformed_xml_names_its_line(tmp_path):
    path = _write(tmp_path, LINKS + "\n<joint name='x' type='continuous'>\n<parent link='base'/>\n</robot>")
    with pytest.raises(RobotFileError, match=r"bad.urdf:\d+: xml: not well-formed XML"):
        load(path)


def test_a_malformed_cylinder_names_its_line(tmp_path):
    text = (ROOT / "examples" / "urdf" / "diffbot.urdf").read_text()
    text = text.replace(
        '<cylinder radius="0.08" length="0.04"/></geometry>\n    </collision>',
        '<cylinder radius="8 cm" length="0.04"/></geometry>\n    </collision>',
        1,
    )
    (tmp_path / "c.urdf").write_text(text)
    with pytest.raises(RobotFileError) as err:
        load(tmp_path / "c.urdf")
    assert (err.value.line, err.value.key) == (_line(text, '<cylinder radius="8 cm"'), "<cylinder radius>")


def test_a_joint_naming_a_missing_link(tmp_path):
    body = LINKS + '\n<joint name="w" type="continuous">\n<parent link="base"/><child link="wheel"/>\n</joint>'
    path = _write(tmp_path, body)
    with pytest.raises(RobotFileError) as err:
        load(path)
    assert err.value.key == "joint 'w'" and err.value.line == _line(path.read_text(), '<joint name="w"')
    assert "does not define" in err.value.reason


def test_a_malformed_origin(tmp_path):
    body = LINKS + (
        '\n<joint name="w" type="continuous"><parent link="base"/><child link="a"/>\n<origin xyz="0 a 0"/></joint>'
    )
    with pytest.raises(RobotFileError, match=r"bad.urdf:6: joint 'w' <origin xyz>: must be three numbers"):
        load(_write(tmp_path, body))


def test_a_tilted_joint_between_platform_and_wheel(tmp_path):
    body = (
        '<link name="base"/>\n<link name="arm"/>\n<link name="w"><collision><origin rpy="1.5708 0 0"/><geometry>'
        '<cylinder radius="0.1" length="0.02"/></geometry></collision></link>\n'
        '<joint name="hinge" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="1 0 0"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>\n'
        '<joint name="wheel" type="continuous"><parent link="arm"/><child link="w"/><axis xyz="0 1 0"/></joint>'
    )
    with pytest.raises(
        RobotFileError,
        match=r"joint 'hinge': a revolute joint about \[1.0, 0.0, 0.0\] between the "
        r"platform and wheel joint 'wheel'",
    ):
        load(_write(tmp_path, body))


def test_a_steering_joint_over_three_wheels(tmp_path):
    wheels = "".join(
        f'<link name="w{k}"><collision><origin rpy="1.5708 0 0"/><geometry><cylinder radius="0.1" '
        f'length="0.02"/></geometry></collision></link>\n<joint name="d{k}" type="continuous"><parent '
        f'link="body"/><child link="w{k}"/><origin xyz="{0.1 * k} 0 0"/><axis xyz="0 1 0"/></joint>\n'
        for k in range(3)
    )
    body = (
        '<link name="base"/>\n<link name="body"/>\n<joint name="steer" type="continuous"><parent link="base"/>'
        '<child link="body"/><axis xyz="0 0 1"/></joint>\n' + wheels
    )
    with pytest.raises(RobotFileError, match=r"bad.urdf:5: joint 'steer': steers 3 wheels"):
        load(_write(tmp_path, body))


def test_a_missing_yourdfpy_names_the_extra(tmp_path, monkeypatch):
    monkeypatch.setitem(__import__("sys").modules, "yourdfpy", None)
    with pytest.raises(MissingDependencyError, match=r"pip install 'wmr-kinematics\[urdf\]'"):
        load(ROOT / "examples" / "urdf" / "swerve.urdf")


def test_an_axis_written_to_five_digits_snaps_to_its_direction():
    from wmr.io.urdf_tree import snap

    assert snap([0.0, 1.0, -3.7e-6]).tolist() == [0.0, 1.0, 0.0]


def test_wheel_joints_as_the_command_line_gives_them_and_the_file_s_joint_names():
    from wmr.io.urdf_read import parse_wheel_joints, read_urdf

    wanted = {"left_wheel_joint": None, "right_wheel_joint": 0.05}
    assert parse_wheel_joints("left_wheel_joint, right_wheel_joint=0.05") == wanted
    _, names = read_urdf(ROOT / "examples" / "urdf" / "diffbot.urdf")
    assert names == [
        {"drive": "left_wheel_joint"},
        {"drive": "right_wheel_joint"},
        {"steer": "caster_swivel_joint", "drive": "caster_wheel_joint"},
    ]
