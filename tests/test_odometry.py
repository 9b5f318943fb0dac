"""Wheel odometry (wmr.odometry): against WPILib's SwerveDriveOdometry, MecanumDriveOdometry and
DifferentialDriveOdometry on the same wheel measurements, against wmr's own simulation, and the slip residual.

Agreement with WPILib: the same least squares, the module angles of each step's end, the same SE(2) exponential
(Pose2d.exp), the gyro's increment replacing the wheels' heading increment.  Stated tolerance: 1e-12 of the path's
size in position, 1e-12 rad in heading, over 2000 steps with noisy (slipping) module measurements; measured about
4e-14 m over a 10 m path (tests print nothing; the numbers are in the report of issue 24).
"""

from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr import swerve
from wmr.errors import InputValueError
from wmr.io import from_wpilib, to_wpilib
from wmr.io.layouts import differential
from wmr.io.wpilib import module_positions
from wmr.odometry import measured_joints, wheel_odometry

ROOT = Path(__file__).resolve().parent.parent
TOL_POSE = 1e-12


def _angle_gap(a, b):
    return np.abs(np.angle(np.exp(1j * (np.asarray(a) - np.asarray(b)))))


def _swerve_run(bot, T=2000, seed=0):
    """A driving profile: module angles and travels from a smooth twist, with noise (the modules slip)."""
    rng = np.random.default_rng(seed)
    t = np.linspace(0.0, 20.0, T)
    twists = np.column_stack([0.8 * np.sin(0.3 * t), 2 * np.cos(0.2 * t), np.sin(0.5 * t)])
    cmd = swerve.module_commands(bot, twists)
    beta = cmd.beta + rng.normal(0, 0.01, cmd.beta.shape)
    distance = np.cumsum(cmd.speed * (t[1] - t[0]), axis=0) + 1e-5 * rng.normal(0, 1, cmd.speed.shape).cumsum(axis=0)
    return beta, distance


def _wpilib_poses(odometry, T, gyro, positions):
    out = [(odometry.getPose().rotation().radians(), odometry.getPose().X(), odometry.getPose().Y())]
    wpimath_geometry = pytest.importorskip("wpimath.geometry")
    for k in range(1, T):
        p = odometry.update(wpimath_geometry.Rotation2d(float(gyro[k])), positions(k))
        out.append((p.rotation().radians(), p.X(), p.Y()))
    return np.array(out)


@pytest.mark.parametrize("with_gyro", [False, True])
def test_swerve_odometry_agrees_with_wpilib(with_gyro):
    wk = pytest.importorskip("wpimath.kinematics")
    from wpimath.geometry import Pose2d, Rotation2d

    bot = wmr.load(ROOT / "examples" / "swerve4.toml")
    beta, distance = _swerve_run(bot)
    T = len(beta)
    angles = distance / swerve.radii(bot)
    odo = wheel_odometry(bot, beta, angles)
    gyro = odo.pose[:, 0] + (np.random.default_rng(1).normal(0, 0.02, T) if with_gyro else 0.0)
    if with_gyro:
        odo = wheel_odometry(bot, beta, angles, heading=gyro)
    assert odo.slip.max() > 1e-4  # the measurements do slip
    wp = wk.SwerveDrive4Odometry(
        to_wpilib(bot), Rotation2d(float(gyro[0])), tuple(module_positions(beta[0], distance[0])), Pose2d()
    )
    ref = _wpilib_poses(wp, T, gyro, lambda k: tuple(module_positions(beta[k], distance[k])))
    size = np.abs(odo.pose[:, 1:]).max()
    assert size > 5.0
    assert np.abs(ref[:, 1:] - odo.pose[:, 1:]).max() <= TOL_POSE * size
    assert _angle_gap(ref[:, 0], odo.pose[:, 0]).max() <= TOL_POSE


def test_mecanum_odometry_agrees_with_wpilib():
    """Rollers are unknowns here (solved with the twist): the same least squares as WPILib's 4 x 3 matrix."""
    wk = pytest.importorskip("wpimath.kinematics")
    from wpimath.geometry import Pose2d, Rotation2d

    bot = wmr.load(ROOT / "examples" / "mecanum4.toml")
    rng = np.random.default_rng(5)
    T = 500
    travel = np.cumsum(rng.normal(0.0, 0.02, (T, 4)) + [0.01, 0.02, 0.015, 0.012], axis=0)  # metres, slipping
    odo = wheel_odometry(bot, np.zeros((T, 4)), travel / 0.05)
    assert measured_joints(bot) == ("theta_dot_1", "theta_dot_2", "theta_dot_3", "theta_dot_4")
    gyro = odo.pose[:, 0]

    def positions(k):
        p = wk.MecanumDriveWheelPositions()
        p.frontLeft, p.frontRight, p.rearLeft, p.rearRight = (float(x) for x in travel[k])
        return p

    wp = wk.MecanumDriveOdometry(to_wpilib(bot), Rotation2d(0.0), positions(0), Pose2d())
    ref = _wpilib_poses(wp, T, gyro, positions)
    assert np.abs(ref[:, 1:] - odo.pose[:, 1:]).max() <= TOL_POSE * np.abs(odo.pose[:, 1:]).max()
    assert odo.unknown.shape == (T - 1, 4)  # the four roller increments


def test_differential_odometry_agrees_with_wpilib():
    wk = pytest.importorskip("wpimath.kinematics")
    from wpimath.geometry import Pose2d, Rotation2d

    kin = wk.DifferentialDriveKinematics(0.55)
    bot = from_wpilib(kin, wheel_radius=0.0762)
    T = 400
    rng = np.random.default_rng(2)
    travel = np.cumsum(rng.normal(0.02, 0.01, (T, 2)), axis=0)
    odo = wheel_odometry(bot, np.zeros((T, 2)), travel / 0.0762)
    assert odo.slip.max() < 1e-14  # two wheels: any travels are a rigid motion
    wp = wk.DifferentialDriveOdometry(Rotation2d(0.0), float(travel[0, 0]), float(travel[0, 1]), Pose2d())
    out = [(0.0, 0.0, 0.0)]
    for k in range(1, T):
        p = wp.update(Rotation2d(float(odo.pose[k, 0])), float(travel[k, 0]), float(travel[k, 1]))
        out.append((p.rotation().radians(), p.X(), p.Y()))
    ref = np.array(out)
    assert np.abs(ref[:, 1:] - odo.pose[:, 1:]).max() <= TOL_POSE * np.abs(odo.pose[:, 1:]).max()
    np.testing.assert_allclose(np.diff(odo.pose[:, 0]), np.diff(travel[:, 1] - travel[:, 0]) / 0.55, atol=1e-14)


# ------------------------------------------------------------------------------------------ wmr's own motion
def test_odometry_of_a_differential_drive_with_a_castor():
    """Constant drive rates: a constant twist, whose motion is one SE(2) exponential; the castor's rates are
    unknowns (no encoder) and its angles do not matter."""
    castor = wmr.OffsetWheel((-0.3, 0.0), r=0.03, d=0.03, driven={"steer": False, "drive": False})
    bot = wmr.Robot(list(differential(0.4, 0.08).wheels) + [castor])
    twist = np.array([0.7, 0.5, 0.0])
    rates = wmr.inverse(bot, wmr.steering_angles(bot, twist), twist).value
    assert measured_joints(bot) == ("theta_dot_1", "theta_dot_2")  # the castor has no encoder
    t = np.linspace(0.0, 3.0, 301)
    beta = np.random.default_rng(4).uniform(-np.pi, np.pi, (len(t), 3))  # the castor turns any way
    odo = wheel_odometry(bot, beta, t[:, None] * rates[:2])
    expected = np.vstack([[0.0, 0.0, 0.0], swerve.se2_exp(np.outer(t[1:], twist))])
    np.testing.assert_allclose(odo.pose, expected, rtol=0, atol=1e-12)
    assert odo.slip.max() < 1e-12


def test_odometry_of_offset_wheels_converges_at_first_order():
    """The paper's offset-wheel robot: steering rates are absolute (phi = psi + beta, (7)); the step's end angles
    make the error of order dt, so halving the step halves it."""
    bot = wmr.paper_robot("offset", L=0.5, r=0.1)
    rates = np.array([0.3, -1.0, -0.2, 2.0, 0.5, 1.0])
    fine = wmr.integrate(bot, rates, [0.2, 1.0, -0.5], t_end=2.0, dt=1e-3)
    assert measured_joints(bot) == bot.rate_names  # steering through beta, drives through angles
    drive = [k for k, n in enumerate(bot.rate_names) if n.startswith("theta")]
    errors = []
    for every in (40, 20, 10):
        k = np.arange(0, len(fine.t), every)
        odo = wheel_odometry(bot, fine.beta[k], fine.t[k, None] * rates[drive])
        errors.append(np.abs(odo.pose[-1] - fine.pose[k[-1]]).max())
    ratios = np.array(errors[:-1]) / errors[1:]
    assert np.all((ratios > 1.7) & (ratios < 2.3)), errors


def test_the_slip_residual_is_the_travel_no_rigid_motion_explains():
    bot = wmr.load(ROOT / "examples" / "swerve4.toml")
    T = 5
    beta = np.full((T, 4), np.pi / 2)
    angles = np.outer(np.arange(T), np.full(4, 2.0))  # straight ahead: no slip
    angles[3:, 1] += 0.5  # module 2 slips at step 2 (samples 2..3)
    odo = wheel_odometry(bot, beta, angles)
    assert np.all(odo.slip[[0, 1, 3]] < 1e-14) and odo.slip[2] > 0.0
    J1, J2 = bot.J1(), bot.J2(beta[3])
    e = J2 @ (angles[3] - angles[2])
    expected = J1 @ np.linalg.lstsq(J1, e, rcond=None)[0] - e  # the part of J2 d_theta outside range(J1)
    np.testing.assert_allclose(odo.residual[2], expected, atol=1e-14)


# ------------------------------------------------------------------------------------------ bad input
def test_bad_input():
    bot = differential(0.4, 0.08)
    with pytest.raises(InputValueError, match="do not determine the platform's motion at step 0"):
        wheel_odometry(bot, np.zeros((3, 2)), np.zeros((3, 1)), measured=["theta_dot_1"])
    with pytest.raises(InputValueError, match=r"angles \(T, 2\) with 2 <= T"):
        wheel_odometry(bot, np.zeros((1, 2)), np.zeros((1, 2)))
    with pytest.raises(InputValueError, match=r"beta must be \(T, 2\)"):
        wheel_odometry(bot, np.zeros((3, 2)), np.zeros((4, 2)))
    with pytest.raises(InputValueError, match="measured must name distinct rates"):
        wheel_odometry(bot, np.zeros((3, 2)), np.zeros((3, 2)), measured=["theta_dot_1", "theta_dot_9"])
    with pytest.raises(InputValueError, match=r"heading must have shape \(3,\)"):
        wheel_odometry(bot, np.zeros((3, 2)), np.zeros((3, 2)), heading=[0.0, 1.0])
    offset = wmr.paper_robot("offset", L=0.5, r=0.1)
    with pytest.raises(InputValueError, match=r"angles must have shape \(\.\.\., 1\)"):
        wheel_odometry(offset, np.zeros((3, 3)), np.zeros((3, 2)), measured=["phi_dot_1", "theta_dot_1"])


def test_straight_run_without_slip():
    """20 rad of a 0.05 m wheel on every module, axles along y: 1 m forward, no slip (the former doctest)."""
    bot = wmr.Robot([wmr.CentredWheel((x, y), r=0.05) for x, y in [(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3)]])
    angles = np.linspace(0.0, 20.0, 11)[:, None] * np.ones(4)
    odo = wheel_odometry(bot, np.full((11, 4), np.pi / 2), angles)
    np.testing.assert_allclose(odo.pose[-1], [0.0, 1.0, 0.0], atol=1e-12)
    assert odo.slip.max() < 1e-12
