"""WPILib kinematics objects in and out (wmr.io.from_wpilib, wmr.io.to_wpilib) and WPILib's values in wmr's conventions,
checked against robotpy-wpimath itself: the robot read from an object gives the object's wheel speeds."""

from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.errors import InputTypeError, InputValueError
from wmr.io import from_wpilib, to_wpilib
from wmr.io import layouts as L
from wmr.io.wpilib import (
    chassis_speeds,
    from_module_states,
    is_chassis_speeds,
    module_positions,
    module_states,
    twist_of,
)

wk = pytest.importorskip("wpimath.kinematics")  # in environment.lock: runs here
from wpimath.geometry import Rotation2d, Translation2d, Twist2d  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
TWISTS = np.random.default_rng(3).normal(0, 1.5, (40, 3))  # psi_dot, x_dot, y_dot


def _drive_speeds(bot, twists):
    """wmr's inverse kinematics: r_i theta_dot_i of the drive joints (ground speeds, m/s)."""
    rates = wmr.inverse(bot, np.full(bot.w, np.pi / 2), twists).value
    cols = [k for k, n in enumerate(bot.rate_names) if n.startswith("theta")]
    return rates[:, cols] * [float(u.r) for u in bot.wheels]


def test_swerve_kinematics_in_one_line_and_back():
    points = [(0.31, 0.27), (0.31, -0.27), (-0.29, 0.27), (-0.29, -0.27)]
    kin = wk.SwerveDrive4Kinematics(*(Translation2d(x, y) for x, y in points))
    bot = from_wpilib(kin, wheel_radius=0.0508)
    assert [u.kind for u in bot.wheels] == ["centred"] * 4 and wmr.campion_class(bot).label == "(1,2)"
    np.testing.assert_allclose(bot.mount_points, points, rtol=0, atol=0)
    again = to_wpilib(bot)
    assert type(again) is wk.SwerveDrive4Kinematics
    assert [(t.x, t.y) for t in again.getModules()] == [(t.x, t.y) for t in kin.getModules()]


@pytest.mark.parametrize("n", [2, 3, 6])
def test_swerve_of_other_sizes_round_trips(n):
    a = 2 * np.pi * np.arange(n) / n + 0.1
    bot = L.swerve(np.column_stack([0.4 * np.cos(a), 0.3 * np.sin(a)]), [0.05 + 0.01 * k for k in range(n)])
    back = from_wpilib(to_wpilib(bot), wheel_radius=[float(u.r) for u in bot.wheels])
    np.testing.assert_allclose(back.mount_points, bot.mount_points, rtol=0, atol=1e-15)
    assert [u.r for u in back.wheels] == [u.r for u in bot.wheels]


def test_mecanum_kinematics_gives_wpilibs_wheel_speeds():
    """The rollers wmr puts on WPILib's mecanum wheels (+45, -45, -45, +45 deg) give toWheelSpeeds exactly."""
    corners = [(0.3, 0.25), (0.28, -0.26), (-0.27, 0.24), (-0.3, -0.25)]  # not even a rectangle
    kin = wk.MecanumDriveKinematics(*(Translation2d(x, y) for x, y in corners))
    bot = from_wpilib(kin, wheel_radius=0.0762)
    assert wmr.campion_class(bot).label == "(3,0)"
    ref = np.array(
        [
            [(s := kin.toWheelSpeeds(wk.ChassisSpeeds(vx, vy, om))).frontLeft, s.frontRight, s.rearLeft, s.rearRight]
            for om, vx, vy in TWISTS
        ]
    )
    np.testing.assert_allclose(_drive_speeds(bot, TWISTS), ref, rtol=1e-12, atol=1e-12)
    back = to_wpilib(bot)
    assert [
        (t.x, t.y) for t in (back.getFrontLeft(), back.getFrontRight(), back.getRearLeft(), back.getRearRight())
    ] == corners


def test_the_mecanum_example_in_any_order_becomes_wpilibs_mecanum():
    bot = wmr.load(ROOT / "examples" / "mecanum4.toml")
    shuffled = wmr.Robot([bot.wheels[k] for k in (3, 1, 0, 2)])
    kin = to_wpilib(shuffled)
    assert (kin.getFrontLeft().x, kin.getFrontLeft().y, kin.getRearRight().x) == (0.25, 0.2, -0.25)
    np.testing.assert_allclose(from_wpilib(kin, 0.05).mount_points, bot.mount_points, atol=0)


def test_differential_kinematics_gives_wpilibs_wheel_speeds():
    kin = wk.DifferentialDriveKinematics(0.6)
    bot = from_wpilib(kin, wheel_radius=0.0762)
    assert wmr.campion_class(bot).label == "(2,0)"
    fwd = TWISTS * [1, 1, 0]
    ref = np.array([[(s := kin.toWheelSpeeds(wk.ChassisSpeeds(vx, 0.0, om))).left, s.right] for om, vx, _ in fwd])
    np.testing.assert_allclose(_drive_speeds(bot, fwd), ref, rtol=1e-12, atol=1e-12)
    assert to_wpilib(bot).trackWidth == 0.6
    castor = wmr.OffsetWheel((-0.3, 0.0), r=0.03, d=0.03, driven={"steer": False, "drive": False})
    assert to_wpilib(wmr.Robot(list(bot.wheels) + [castor])).trackWidth == 0.6  # a passive castor is left out


@pytest.mark.parametrize(
    "robot",
    [
        L.differential(0.55, 0.0762),
        wmr.load(ROOT / "examples" / "swerve4.toml"),
        wmr.load(ROOT / "examples" / "mecanum4.toml"),
    ],
    ids=["differential", "swerve", "mecanum"],
)
def test_round_trip(robot):
    """wmr -> WPILib -> wmr: the same kinds, mount points and Campion class (the radii given back: WPILib has none)."""
    back = from_wpilib(to_wpilib(robot), wheel_radius=[float(u.r) for u in robot.wheels])
    assert [type(u) for u in back.wheels] == [type(u) for u in robot.wheels]
    np.testing.assert_allclose(back.mount_points, robot.mount_points, rtol=0, atol=0)
    assert [u.parameters() for u in back.wheels] == [u.parameters() for u in robot.wheels]
    assert wmr.campion_class(back).label == wmr.campion_class(robot).label


@pytest.mark.parametrize(
    "name, why",
    [
        ("tricycle", "not differential: needs exactly two fixed wheels"),
        ("omni3", "not mecanum: needs exactly four Swedish wheels"),
        ("steered_castors", "not swerve: needs two swerve modules or more, has 1"),
    ],
)
def test_robots_wpilib_cannot_express(name, why):
    with pytest.raises(InputValueError, match="WPILib .* cannot express") as err:
        to_wpilib(wmr.load(ROOT / "examples" / f"{name}.toml"))
    assert why in str(err.value)


def test_a_castor_with_motors_is_not_left_out():
    bot = wmr.load(ROOT / "examples" / "differential.toml")  # its castor is passive: WPILib leaves it out
    assert to_wpilib(bot).trackWidth == 0.4
    active = wmr.Robot(list(bot.wheels[:2]) + [wmr.OffsetWheel((-0.3, 0.0), r=0.03, d=0.03)])
    with pytest.raises(InputValueError, match="wheel 3 constrains nothing but has motors"):
        to_wpilib(active)


def test_five_swerve_modules_and_non_wpilib_objects():
    with pytest.raises(InputValueError, match="2, 3, 4, 6 modules; the robot has 5"):
        to_wpilib(L.swerve([(np.cos(a), np.sin(a)) for a in range(5)], 0.05))
    with pytest.raises(InputTypeError, match="must be a WPILib kinematics object"):
        from_wpilib(wmr.load(ROOT / "examples" / "swerve4.toml"), 0.05)
    with pytest.raises(InputTypeError, match="must be SwerveDrive"):
        from_wpilib(wk.ChassisSpeeds(1, 2, 3), 0.05)
    kin = to_wpilib(wmr.load(ROOT / "examples" / "swerve4.toml"))
    with pytest.raises(InputValueError, match=r"radius must be one radius or one per wheel \(4\), got 3"):
        from_wpilib(kin, [0.05, 0.05, 0.05])


def test_chassis_speeds_and_twists():
    """A ChassisSpeeds is (vx, vy, omega), a wmr twist [psi_dot, x_dot, y_dot]: twist_of is the one conversion."""
    cs = wk.ChassisSpeeds(1.0, 2.0, 3.0)
    assert twist_of(cs).tolist() == [3.0, 1.0, 2.0]
    assert twist_of([cs, wk.ChassisSpeeds(0.0, 0.0, -1.0)]).tolist() == [[3.0, 1.0, 2.0], [-1.0, 0.0, 0.0]]
    assert twist_of(Twist2d(0.1, 0.2, 0.3)).tolist() == [0.3, 0.1, 0.2]
    back = chassis_speeds([3.0, 1.0, 2.0])
    assert (back.vx, back.vy, back.omega) == (1.0, 2.0, 3.0)
    with pytest.raises(InputTypeError, match="ChassisSpeeds"):
        twist_of(np.array([1.0, 2.0, 3.0]))  # an array's order would be a guess
    # the trap: a ChassisSpeeds iterates as (vx, vy, omega), so as an array it is a twist in the wrong order
    assert np.asarray(cs).tolist() == [1.0, 2.0, 3.0] != twist_of(cs).tolist()
    assert is_chassis_speeds(cs) and is_chassis_speeds([cs, cs]) and is_chassis_speeds(Twist2d(1, 2, 3))
    assert not is_chassis_speeds([3.0, 1.0, 2.0]) and not is_chassis_speeds(np.zeros(3)) and not is_chassis_speeds([])


def test_module_states_are_wpilibs_toSwerveModuleStates():
    bot = wmr.load(ROOT / "examples" / "swerve4.toml")
    kin = to_wpilib(bot)
    for twist in TWISTS[:10]:
        cmd = wmr.swerve.module_commands(bot, twist)
        ours = module_states(cmd.beta, cmd.speed)
        ref = kin.toSwerveModuleStates(chassis_speeds(twist))
        for a, b in zip(ours, ref):
            assert a.speed == pytest.approx(b.speed, abs=1e-12)
            assert abs(np.angle(np.exp(1j * (a.angle.radians() - b.angle.radians())))) < 1e-12
        beta, speed = from_module_states(ref)
        np.testing.assert_allclose(np.cos(beta - cmd.beta), 1.0, atol=1e-12)
        np.testing.assert_allclose(speed, cmd.speed, atol=1e-12)
    pos = module_positions([np.pi / 2, 0.0], [1.0, 2.0])
    assert [(p.distance, round(p.angle.degrees(), 9)) for p in pos] == [(1.0, 0.0), (2.0, -90.0)]
    assert from_module_states(pos)[1].tolist() == [1.0, 2.0]
    assert isinstance(pos[0].angle, Rotation2d)


def test_wmr_io_chassis_moved_into_wmr_io_wpilib():
    """wmr.deprecated: the module wmr.io.chassis is gone; its names warn and are wmr.io.wpilib's (issue 29)."""
    with pytest.warns(DeprecationWarning, match=r"wmr.io.chassis.twist_of is deprecated: use wmr.io.wpilib.twist_of"):
        from wmr.io.chassis import twist_of as old  # type: ignore[import-not-found]
    assert old is twist_of
    with pytest.warns(DeprecationWarning, match="wmr.io.wpilib.is_chassis_speeds"):
        assert wmr.io.chassis.is_chassis_speeds is is_chassis_speeds
