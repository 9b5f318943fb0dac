"""Issue 24, points 6 and 7: the conventions users bring (WPILib, ROS), WPILib objects, degrees and radians,
``--current-angles``, the drawing's arrows, and a slip tolerance the user sets."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.cli import main
from wmr.errors import InputError
from wmr.model.conventions import angle_from, angle_to, twist_from, twist_to

ROOT = Path(__file__).resolve().parent.parent
SWERVE = ROOT / "examples" / "swerve4.toml"
wpimath = pytest.importorskip("wpimath")


def _run(capsys, *argv):
    code = main([str(a) for a in argv])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_a_chassis_speeds_is_read_by_its_fields():
    from wpimath.geometry import Translation2d
    from wpimath.kinematics import ChassisSpeeds, SwerveDrive4Kinematics

    bot = wmr.load(SWERVE)
    speeds = ChassisSpeeds(1.0, 0.5, 0.8)  # vx, vy, omega
    cmd = wmr.swerve.module_commands(bot, speeds)
    want = wmr.swerve.module_commands(bot, [0.8, 1.0, 0.5])  # wmr's order
    assert np.allclose(cmd.beta, want.beta) and np.allclose(cmd.speed, want.speed)
    kin = SwerveDrive4Kinematics(*[Translation2d(*map(float, p)) for p in bot.mount_points])
    states = kin.toSwerveModuleStates(speeds)
    assert np.allclose([s.speed for s in states], cmd.speed, rtol=1e-12)
    assert np.allclose(np.degrees(angle_to(cmd.beta, "wpilib")), [s.angle.degrees() for s in states], atol=1e-9)
    assert np.allclose(wmr.inverse(bot, cmd.beta, speeds).value, wmr.inverse(bot, cmd.beta, [0.8, 1.0, 0.5]).value)
    assert np.allclose(twist_from(speeds, "wpilib"), [0.8, 1.0, 0.5])
    sol = wmr.swerve.chassis_twist(bot, cmd.beta, cmd.speed)
    assert np.allclose(twist_to(sol.value, "wpilib"), [1.0, 0.5, 0.8])


def test_a_twist_object_is_never_read_as_numbers_where_none_is_expected():
    from wpimath.kinematics import ChassisSpeeds

    bot = wmr.load(SWERVE)
    with pytest.raises(InputError, match="ChassisSpeeds"):
        wmr.steering_angles(bot, [0.8, 1.0, 0.5], current=ChassisSpeeds(1.0, 2.0, 3.0))  # type: ignore[arg-type]


def test_twist2d_and_a_list_of_chassis_speeds():
    from wpimath.geometry import Twist2d
    from wpimath.kinematics import ChassisSpeeds

    bot = wmr.load(SWERVE)
    assert np.allclose(wmr.steering_angles(bot, Twist2d(1.0, 0.5, 0.8)), wmr.steering_angles(bot, [0.8, 1.0, 0.5]))
    many = wmr.steering_angles(bot, [ChassisSpeeds(1.0, 0.0, 0.0), ChassisSpeeds(0.0, 1.0, 0.0)])
    assert np.allclose(many, wmr.steering_angles(bot, [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]))


def test_degrees_and_radians_are_named():
    with pytest.raises(InputError, match=r"radians.*angle_deg=90"):
        wmr.FixedWheel((0.0, 0.2), r=0.05, angle=90)
    with pytest.raises(InputError, match="roller_deg=45"):
        wmr.SwedishWheel((0.0, 0.2), r=0.05, angle=0.0, roller=45)
    a = wmr.FixedWheel((0.0, 0.2), r=0.05, angle_deg=90)
    assert a.angle == pytest.approx(math.pi / 2) and a == wmr.FixedWheel((0.0, 0.2), r=0.05, angle=math.pi / 2)
    b = wmr.SwedishWheel((0.0, 0.2), r=0.05, angle_deg=90, roller_deg=45)
    text = wmr.dump(wmr.Robot([a, b]))  # the file's keys: the same degrees
    assert "angle_deg = 90.0" in text and "roller_deg = 45.0" in text
    with pytest.raises(InputError, match="not both"):
        wmr.FixedWheel((0.0, 0.2), r=0.05, angle=1.0, angle_deg=30)


def test_conventions_are_inverse_of_each_other():
    beta = np.linspace(-3, 3, 13)
    for name in ("wmr", "wpilib", "ros"):
        assert np.allclose(np.cos(angle_from(angle_to(beta, name), name) - beta), 1.0)
    assert float(np.degrees(angle_to(np.pi / 2, "wpilib"))) == pytest.approx(0.0)  # rolls forward: 0 in WPILib


def test_ik_in_wpilib_convention(capsys):
    code, out, _ = _run(capsys, "ik", SWERVE, "--vx", "1", "--json", "--convention", "wpilib")
    data = json.loads(out)
    assert code == 0 and np.allclose(data["angles_deg"], 0.0) and np.allclose(data["resteer_deg"], 0.0)
    assert list(data["twist"]) == ["vx", "vy", "omega"] and data["admissible_without_resteering"]
    code, out, _ = _run(capsys, "ik", SWERVE, "--vx", "1", "--convention", "wpilib")
    assert "heading_deg" in out and "vx = 1 m/s, vy = 0 m/s, omega = 0 rad/s" in out
    code, out, _ = _run(capsys, "ik", SWERVE, "--vx", "1", "--json")
    data = json.loads(out)
    assert np.allclose(np.abs(data["angles_deg"]), 90.0) and list(data["twist"]) == ["omega", "vx", "vy"]


@pytest.mark.parametrize("convention", ["wmr", "wpilib"])
def test_current_angles_default_is_what_help_says(capsys, convention):
    argv = ["ik", SWERVE, "--vx", "1", "--vy", "0.5", "--omega", "0.8", "--json", "--convention", convention]
    _, default, _ = _run(capsys, *argv)
    _, zeros, _ = _run(capsys, *argv, "--current-angles", "0", "0", "0", "0")
    assert json.loads(default) == json.loads(zeros)
    assert all(abs(a) <= 90 + 1e-9 for a in json.loads(default)["resteer_deg"])  # the nearer of beta, beta + pi


def test_fk_in_wpilib_convention_matches_wpilib(capsys):
    from wpimath.geometry import Rotation2d, Translation2d
    from wpimath.kinematics import SwerveDrive4Kinematics, SwerveModuleState

    bot = wmr.load(SWERVE)
    kin = SwerveDrive4Kinematics(*[Translation2d(*map(float, p)) for p in bot.mount_points])
    heading, speed = [10.0, 20.0, 30.0, 40.0], [1.0, 1.2, 0.8, 1.1]
    states = [SwerveModuleState(s, Rotation2d.fromDegrees(a)) for a, s in zip(heading, speed)]
    cs = kin.toChassisSpeeds((states[0], states[1], states[2], states[3]))
    rates = [s / 0.0508 for s in speed]
    code, out, _ = _run(
        capsys, "fk", SWERVE, "--angles", *heading, "--rates", *rates, "--convention", "wpilib", "--json"
    )
    data = json.loads(out)
    assert code == 0 and np.allclose([data["vx"], data["vy"], data["omega"]], [cs.vx, cs.vy, cs.omega], atol=1e-12)


def test_draw_robot_arrows_point_where_the_robot_drives():
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import FancyArrowPatch

    from wmr.plot.robot import draw_robot

    bot = wmr.load(SWERVE)
    twist = [0.0, 1.0, 0.0]  # forward
    beta = wmr.steering_angles(bot, twist)
    assert (wmr.inverse(bot, beta, twist).value > 0).all()  # positive rates
    for arrows, sign in (("travel", 1.0), ("j", -1.0)):
        fig, ax = plt.subplots()
        draw_robot(ax, bot, beta, arrows=arrows)
        tips = [p for p in ax.patches if isinstance(p, FancyArrowPatch) and p.get_facecolor()[:3] == (1.0, 1.0, 1.0)]
        assert len(tips) == 4
        for p in tips:
            (x0, _), (x1, _) = p._posA_posB  # type: ignore[attr-defined]  # tail, head
            assert sign * (x1 - x0) > 0
        plt.close(fig)


# ------------------------------------------------------------------------------------ 7. slip tolerance
def test_rounded_rates_do_not_slip_by_default(capsys):
    bot = wmr.load(SWERVE)
    twist = [0.8, 1.0, 0.5]
    beta = wmr.steering_angles(bot, twist)
    rates = np.round(wmr.inverse(bot, beta, twist).value, 4)
    argv = ["fk", SWERVE, "--angles", *np.round(np.degrees(beta), 10), "--rates", *rates, "--json"]
    code, out, _ = _run(capsys, *argv)
    data = json.loads(out)
    tol = 0.0508 * 2 * np.pi / (2048 * 0.02)  # one count per 20 ms at the rim
    assert code == 0 and data["admissible"] and data["slip_tolerance"] == pytest.approx(tol)
    assert 1e-7 < data["slip_max_wheel"] < 1e-4  # the rounding, far below a count
    code, out, _ = _run(capsys, *argv, "--slip-tolerance", "0")
    assert not json.loads(out)["admissible"]
    code, out, _ = _run(capsys, *argv, "--slip-tolerance", "1e-7")
    assert not json.loads(out)["admissible"]
    code, out, _ = _run(capsys, *argv[:-1])
    assert "tolerance   0.00779 m/s (one count of a 2048-count encoder per 0.02 s at the wheel rim)" in out


def test_forward_slip_tolerance_in_python():
    bot = wmr.load(SWERVE)
    beta = np.zeros(4)
    rates = np.array([10.0, 10.0, 10.0, 10.0 + 1e-3])  # wheel 4 off by 1e-3 rad/s
    assert not wmr.forward(bot, beta, rates).admissible
    assert wmr.forward(bot, beta, rates, slip_tolerance=1e-4).admissible  # slip ~ 0.0508e-3 * 3/4 m/s
    assert not wmr.forward(bot, beta, rates, slip_tolerance=1e-5).admissible
    with pytest.raises(InputError, match="slip_tolerance"):
        wmr.forward(bot, beta, rates, slip_tolerance=-1.0)


def test_a_convention_is_checked_by_name():
    from wmr.model.conventions import checked

    assert checked("wpilib") == "wpilib"
    with pytest.raises(InputError, match="convention must be one of wmr, wpilib, ros"):
        checked("WPILib")
