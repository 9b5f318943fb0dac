"""wmr's centred-wheel kinematics against WPILib's SwerveDriveKinematics (robotpy-wpimath, an independent library).

Mapping (wmr.model.conventions): twist [psi_dot, x_dot, y_dot] = ChassisSpeeds(vx, vy, omega) reordered;
WPILib module angle alpha = beta - pi/2 (beta: wmr's axle angle); speed = r * theta_dot.
Layouts of 3, 4 and 6 modules with unequal wheel radii, many random twists.
"""

import numpy as np
import pytest

import wmr
from wmr import swerve
from wmr.model.conventions import angle_from, angle_to, twist_from, twist_to

wk = pytest.importorskip("wpimath.kinematics")  # in environment.lock: runs here
from wpimath.geometry import Rotation2d, Translation2d  # noqa: E402

ChassisSpeeds, SwerveModuleState = wk.ChassisSpeeds, wk.SwerveModuleState
KINEMATICS = {3: wk.SwerveDrive3Kinematics, 4: wk.SwerveDrive4Kinematics, 6: wk.SwerveDrive6Kinematics}

LAYOUTS = {
    3: [(0.35, 0.0), (-0.2, 0.3), (-0.2, -0.28)],
    4: [(0.31, 0.27), (0.31, -0.27), (-0.29, 0.27), (-0.29, -0.27)],  # FRC: FL, FR, BL, BR
    6: [(0.4 * np.cos(a), 0.3 * np.sin(a)) for a in np.radians([10, 70, 130, 190, 250, 310])],
}
N = 300


def _robot(points, seed=0):
    r = np.random.default_rng(seed).uniform(0.03, 0.08, len(points))  # unequal wheel radii
    return wmr.Robot([wmr.CentredWheel(p, r=float(ri)) for p, ri in zip(points, r)])


def _wpilib(points):
    return KINEMATICS[len(points)](*[Translation2d(float(x), float(y)) for x, y in points])


def _twists(seed=1):
    rng = np.random.default_rng(seed)
    return np.column_stack([rng.normal(0, 3, N), rng.normal(0, 2, N), rng.normal(0, 2, N)])  # psi_dot, x_dot, y_dot


def _angle_gap(a, b):
    return np.abs(np.angle(np.exp(1j * (np.asarray(a) - np.asarray(b)))))


@pytest.mark.parametrize("w", sorted(LAYOUTS))
def test_inverse_kinematics_agrees_with_toSwerveModuleStates(w):
    points = LAYOUTS[w]
    bot, kin, twists = _robot(points), _wpilib(points), _twists()
    # wmr: the paper's steering angles and the rolling rates of (21), all twists at once
    beta = wmr.steering_angles(bot, twists)
    rates = wmr.inverse(bot, beta, twists).value
    speed = rates * swerve.radii(bot)
    assert np.all(rates >= 0)  # steering_angles: theta_dot >= 0
    alpha = angle_to(beta, "wpilib")
    # WPILib, twist by twist
    ref = np.array(
        [
            [(s.speed, s.angle.radians()) for s in kin.toSwerveModuleStates(ChassisSpeeds(vx, vy, om))]
            for om, vx, vy in twists
        ]
    )
    assert np.max(np.abs(speed - ref[..., 0])) < 1e-12 * np.abs(ref[..., 0]).max()
    assert np.max(_angle_gap(alpha, ref[..., 1])) < 1e-12
    # the convenience call is the same computation
    cmd = swerve.module_commands(bot, twists)
    np.testing.assert_allclose(cmd.speed, ref[..., 0], rtol=0, atol=1e-12)
    assert np.max(_angle_gap(angle_to(cmd.beta, "wpilib"), ref[..., 1])) < 1e-12


@pytest.mark.parametrize("w", sorted(LAYOUTS))
def test_forward_kinematics_agrees_with_toChassisSpeeds(w):
    """Least squares on (21) = WPILib's pseudo-inverse, for incompatible (slipping) module states too."""
    points = LAYOUTS[w]
    bot, kin = _robot(points), _wpilib(points)
    rng = np.random.default_rng(w)
    alpha = rng.uniform(-np.pi, np.pi, (N, w))
    speed = rng.normal(0, 2, (N, w))  # arbitrary: mostly incompatible
    sol = swerve.chassis_twist(bot, angle_from(alpha, "wpilib"), speed)
    ref = np.array(
        [
            [c.omega, c.vx, c.vy]
            for c in (
                kin.toChassisSpeeds([SwerveModuleState(float(s), Rotation2d(float(a))) for s, a in zip(ss, aa)])
                for ss, aa in zip(speed, alpha)
            )
        ]
    )
    assert np.max(np.abs(sol.value - ref)) < 1e-12 * np.abs(ref).max()
    assert not sol.admissible.any()  # random states slip ...
    twists = _twists(seed=w)  # ... states of a twist do not
    back = swerve.chassis_twist(bot, *vars(swerve.module_commands(bot, twists)).values())
    np.testing.assert_allclose(back.value, twists, rtol=0, atol=1e-12)
    assert back.admissible.all()


def test_the_angle_mapping_is_a_quarter_turn():
    """beta = 90 deg (axle along y) rolls forward: WPILib angle 0; beta = 0 rolls backwards at positive rate."""
    assert angle_to(np.pi / 2, "wpilib") == 0.0
    np.testing.assert_allclose(angle_to(0.0, "wpilib"), -np.pi / 2)
    np.testing.assert_allclose(angle_from(angle_to([0.3, -2.0, 3.0], "wpilib"), "wpilib"), [0.3, -2.0, 3.0])
    assert twist_to([3.0, 1.0, 2.0], "wpilib").tolist() == [1.0, 2.0, 3.0]
    assert twist_from(twist_to([3.0, 1.0, 2.0], "wpilib"), "wpilib").tolist() == [3.0, 1.0, 2.0]


@pytest.mark.parametrize("w", sorted(LAYOUTS))
def test_per_module_optimize_is_wpilibs(w):
    points = LAYOUTS[w]
    bot, kin, twists = _robot(points), _wpilib(points), _twists(seed=5)
    current = np.random.default_rng(6).uniform(-np.pi, np.pi, (N, w))
    ch = swerve.optimize_modules(bot, twists, current)
    for tw, cur, b, s in zip(twists, current, ch.beta, ch.speed):
        states = kin.toSwerveModuleStates(ChassisSpeeds(tw[1], tw[2], tw[0]))
        for st, c in zip(states, angle_to(cur, "wpilib")):
            st.optimize(Rotation2d(float(c)))
        ref = np.array([(st.speed, st.angle.radians()) for st in states])
        np.testing.assert_allclose(s, ref[:, 0], rtol=0, atol=1e-12)
        assert np.max(_angle_gap(angle_to(b, "wpilib"), ref[:, 1])) < 1e-12


def test_per_module_optimize_turns_neighbours_opposite_ways_and_robot_level_does_not():
    """A 90 degree change of direction with encoders 1 degree apart: WPILib's optimize turns the modules
    opposite ways and, while they turn, the wheels slip; the robot-level choice turns all one way: no slip."""
    points = LAYOUTS[4]
    bot, kin = _robot(points), _wpilib(points)
    now_alpha = np.radians([1.0, -1.0, -1.0, 1.0])  # driving forward (alpha ~ 0)
    left = np.array([0.0, 0.0, 1.5])  # then: drive left (alpha = 90 deg)
    states = kin.toSwerveModuleStates(ChassisSpeeds(0.0, 1.5, 0.0))
    for st, c in zip(states, now_alpha):
        st.optimize(Rotation2d(float(c)))
    wp_speed = np.array([st.speed for st in states])
    assert np.any(wp_speed > 0) and np.any(wp_speed < 0)  # WPILib: some reversed, some not
    now = angle_from(now_alpha, "wpilib")
    per, rob = swerve.optimize_modules(bot, left, now), swerve.optimize_robot(bot, left, now)
    np.testing.assert_allclose(per.speed, wp_speed, atol=1e-12)
    turn = lambda ch: np.sign(angle_to(ch.beta, "wpilib") - now_alpha)  # noqa: E731  (sense of each turn)
    assert len(set(turn(per))) == 2 and len(set(turn(rob))) == 1
    assert per.slip > 0.3  # modules fight through the turn
    assert rob.slip < 0.02  # parallel all the way
    assert rob.resteer <= per.resteer + np.radians(4.0 + 1e-9)  # at most the 1 degree offsets, twice
    # both end at the same wheel velocities: the commanded twist
    for ch in (per, rob):
        np.testing.assert_allclose(swerve.chassis_twist(bot, ch.beta, ch.speed).value, left, atol=1e-12)


@pytest.mark.parametrize("w", sorted(LAYOUTS))
def test_desaturation_keeps_the_centre_and_equals_wpilibs_module_scaling(w):
    points = LAYOUTS[w]
    bot, kin, twists = _robot(points), _wpilib(points), _twists(seed=7)
    vmax = 2.0
    scaled = swerve.desaturate(bot, twists, vmax)
    cmd = swerve.module_commands(bot, scaled)
    assert cmd.speed.max() <= vmax * (1 + 1e-12)
    fast = np.abs(swerve.module_commands(bot, twists).speed).max(axis=-1) > vmax
    np.testing.assert_allclose(cmd.speed.max(axis=-1)[fast], vmax)  # the fastest module at the limit
    ic0, ic1 = wmr.instantaneous_centre(twists), wmr.instantaneous_centre(scaled)
    np.testing.assert_allclose(ic1.point, ic0.point, rtol=1e-12)  # no drift of the centre (63)
    for tw, b, s in zip(twists, cmd.beta, cmd.speed):
        states = kin.toSwerveModuleStates(ChassisSpeeds(tw[1], tw[2], tw[0]))
        ref = np.array([(st.speed, st.angle.radians()) for st in type(kin).desaturateWheelSpeeds(states, vmax)])
        np.testing.assert_allclose(s, ref[:, 0], rtol=0, atol=1e-12)
        assert np.max(_angle_gap(angle_to(b, "wpilib"), ref[:, 1])) < 1e-12


def test_desaturating_after_discretizing_drifts_and_before_does_not():
    """WPILib's pipeline (discretize, then desaturate module speeds) leaves the commanded arc; wmr's
    order (desaturate the twist, then discretize) ends on it: the pose over a period is t_scaled * dt."""
    points = LAYOUTS[4]
    bot, kin, dt, vmax = _robot(points), _wpilib(points), 0.1, 3.0
    twist = np.array([6.0, 4.0, 0.0])  # fast spin while driving forward
    k = swerve.desaturation_scale(bot, twist, vmax)
    assert k < 0.7
    want = twist * k * dt  # "as if the components were independent"
    ours = swerve.se2_exp(swerve.discretize(swerve.desaturate(bot, twist, vmax), dt), dt)
    np.testing.assert_allclose(ours, want, atol=1e-12)
    d = kin.toSwerveModuleStates(ChassisSpeeds.discretize(ChassisSpeeds(twist[1], twist[2], twist[0]), dt))
    states = type(kin).desaturateWheelSpeeds(d, vmax)
    c = kin.toChassisSpeeds(states)
    theirs = swerve.se2_exp([c.omega, c.vx, c.vy], dt)
    skew = lambda pose: np.degrees(np.arctan2(pose[2], pose[1]))  # noqa: E731  direction of net motion
    assert abs(skew(ours)) < 1e-9  # straight ahead, as commanded
    assert abs(skew(theirs)) > 1.0  # WPILib: skewed sideways (measured -8.9 deg)


def _log_mp(g):
    """se2_log in 50-digit arithmetic (mpmath): the reference for both."""
    import mpmath as mp

    mp.mp.dps = 50
    th, x, y = (mp.mpf(float(v)) for v in g)
    A = mp.sin(th) / th if th else mp.mpf(1)
    B = (1 - mp.cos(th)) / th if th else mp.mpf(0)
    n = A * A + B * B
    return [float(th), float((A * x + B * y) / n), float((A * y - B * x) / n)]


def test_discretize_agrees_with_wpilib():
    """Agreement to 1e-6 relative where |omega dt| < pi; wmr's sinc form is exact to 1e-13 (50-digit reference),
    WPILib's (1 - cos) form loses ~eps / (omega dt)^2 for small turns (measured 2e-8 here)."""
    twists = _twists(seed=9)
    for dt in (0.02, 0.1, 0.5):
        keep = np.abs(twists[:, 0]) * dt < np.pi  # WPILib wraps larger turns (Rotation2d)
        ours = swerve.discretize(twists[keep], dt)
        ref = np.array(
            [
                [c.omega, c.vx, c.vy]
                for c in (ChassisSpeeds.discretize(ChassisSpeeds(vx, vy, om), dt) for om, vx, vy in twists[keep])
            ]
        )
        np.testing.assert_allclose(ours, ref, rtol=1e-6, atol=1e-9)
        exact = np.array([_log_mp(g) for g in twists[keep] * dt]) / dt
        np.testing.assert_allclose(ours, exact, rtol=1e-13, atol=1e-13)
    tiny = np.array([1e-7, 1.0, 0.5])  # a turn of 1e-9 rad per period
    np.testing.assert_allclose(swerve.discretize(tiny, 0.01), np.array(_log_mp(tiny * 0.01)) / 0.01, rtol=1e-15)


def test_discretize_turns_the_commanded_way_beyond_half_a_turn_per_period():
    """|omega dt| in (pi, 2 pi): WPILib's Rotation2d wraps the turn (it reverses omega); wmr keeps it."""
    tw = np.array([40.0, 1.0, 2.0])
    c = ChassisSpeeds.discretize(ChassisSpeeds(1.0, 2.0, 40.0), 0.1)
    assert c.omega < 0
    ours = swerve.discretize(tw, 0.1)
    assert ours[0] == 40.0
    np.testing.assert_allclose(swerve.se2_exp(ours, 0.1), tw * 0.1, atol=1e-12)
    with pytest.raises(ValueError, match="twist"):
        swerve.discretize([70.0, 1.0, 0.0], 0.1)  # 7 rad per period: not unique


def test_cosine_compensation_agrees_with_cosineScale():
    rng = np.random.default_rng(11)
    speed, target, actual = rng.normal(0, 2, 200), rng.uniform(-np.pi, np.pi, 200), rng.uniform(-np.pi, np.pi, 200)
    ours = swerve.cosine_compensate(speed, actual, target)
    ref = []
    for s, a, c in zip(speed, angle_to(target, "wpilib"), angle_to(actual, "wpilib")):
        st = SwerveModuleState(float(s), Rotation2d(float(a)))
        st.cosineScale(Rotation2d(float(c)))
        ref.append(st.speed)
    np.testing.assert_allclose(ours, ref, rtol=0, atol=1e-12)


def test_the_shipped_frc_example_agrees_with_wpilib():
    """examples/swerve4.toml (the robot file a designer starts from) against SwerveDrive4Kinematics."""
    from pathlib import Path

    bot = wmr.load(Path(__file__).resolve().parent.parent / "examples" / "swerve4.toml")
    kin = _wpilib([tuple(map(float, p)) for p in bot.mount_points])
    twists = _twists(seed=12)
    cmd = swerve.module_commands(bot, twists)
    ref = np.array(
        [
            [(s.speed, s.angle.radians()) for s in kin.toSwerveModuleStates(ChassisSpeeds(vx, vy, om))]
            for om, vx, vy in twists
        ]
    )
    np.testing.assert_allclose(cmd.speed, ref[..., 0], rtol=0, atol=1e-12)
    assert np.max(_angle_gap(angle_to(cmd.beta, "wpilib"), ref[..., 1])) < 1e-12
