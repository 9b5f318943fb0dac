"""wmr.swerve without WPILib: conventions, batching, the robot-level choice, desaturation, the SE(2) exponential."""

import numpy as np
import pytest

import wmr
from wmr import swerve
from wmr.model.conventions import angle_to, twist_from

SQUARE = [(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3)]


def _bot(points=SQUARE, r=0.05):
    return wmr.Robot([wmr.CentredWheel(p, r=r) for p in points])


def test_wheel_velocity_is_speed_along_the_wpilib_angle():
    """(6): h_dot = -r theta_dot j = s (cos alpha, sin alpha) with alpha = beta - pi/2, s = r theta_dot."""
    bot = _bot()
    twist = np.array([0.7, 1.0, -0.4])
    cmd = swerve.module_commands(bot, twist)
    alpha = angle_to(cmd.beta, "wpilib")
    v = cmd.speed[:, None] * np.column_stack([np.cos(alpha), np.sin(alpha)])
    np.testing.assert_allclose(v, wmr.point_velocity(twist, bot.mount_points), atol=1e-12)


def test_batched_over_twists_and_configurations():
    bot = _bot()
    rng = np.random.default_rng(0)
    tw = rng.normal(size=(5, 7, 3))
    cmd = swerve.module_commands(bot, tw)
    assert cmd.beta.shape == cmd.speed.shape == (5, 7, 4)
    one = swerve.module_commands(bot, tw[2, 3])
    np.testing.assert_allclose(cmd.speed[2, 3], one.speed)
    cur = rng.uniform(-np.pi, np.pi, (5, 7, 4))
    for f in (swerve.optimize_modules, swerve.optimize_robot):
        ch = f(bot, tw, cur)
        assert ch.beta.shape == ch.speed.shape == ch.flipped.shape == (5, 7, 4)
        assert ch.resteer.shape == ch.slip.shape == (5, 7)
        single = f(bot, tw[4, 6], cur[4, 6])
        np.testing.assert_allclose(ch.speed[4, 6], single.speed, atol=1e-12)
        # every choice realises the commanded twist once the modules arrive
        np.testing.assert_allclose(swerve.chassis_twist(bot, ch.beta, ch.speed).value, tw, atol=1e-12)
    assert swerve.desaturate(bot, tw, 1.0).shape == (5, 7, 3)
    assert swerve.discretize(tw, 0.02).shape == (5, 7, 3)


def test_robot_level_never_turns_more_than_it_must_when_the_modules_agree():
    """Already there: nothing turns, nothing slips. Small changes: the per-module choice is kept."""
    bot = _bot()
    rng = np.random.default_rng(1)
    tw = rng.normal(size=(50, 3))
    cmd = swerve.module_commands(bot, tw)
    ch = swerve.optimize_robot(bot, tw, cmd.beta)
    assert np.all(ch.resteer < 1e-12) and np.all(ch.slip < 1e-12) and not ch.flipped.any()
    near = swerve.module_commands(bot, tw * [1.0, 1.02, 0.98]).beta  # a slightly different twist
    per, rob = swerve.optimize_modules(bot, tw, near), swerve.optimize_robot(bot, tw, near)
    np.testing.assert_array_equal(per.flipped, rob.flipped)


def test_robot_level_choice_is_never_worse_in_its_cost_than_per_module():
    bot = _bot([(0.4, 0.1), (-0.1, 0.35), (-0.3, -0.3), (0.2, -0.4), (0.0, 0.0)])
    rng = np.random.default_rng(2)
    tw, cur = rng.normal(size=(200, 3)), rng.uniform(-np.pi, np.pi, (200, 5))
    per, rob = swerve.optimize_modules(bot, tw, cur), swerve.optimize_robot(bot, tw, cur)
    J = lambda ch: ch.resteer + bot.w * ch.slip  # noqa: E731
    assert np.all(J(rob) <= J(per) + 1e-12)
    assert np.mean(rob.slip) < np.mean(per.slip)


def test_a_still_module_keeps_its_angle():
    """Spin about a module's mount point: that module has no speed and does not turn (either way)."""
    bot = _bot()
    tw = np.array([1.0, 0.3, -0.3])  # centre at module 1 (0.3, 0.3): c = -psi E d
    cur = np.radians([17.0, 90.0, 90.0, 90.0])
    for f in (swerve.optimize_modules, swerve.optimize_robot):
        ch = f(bot, tw, cur)
        assert ch.speed[0] == 0.0 and ch.beta[0] == pytest.approx(cur[0])


def test_transition_slip_is_zero_for_parallel_turns_and_one_at_worst():
    bot = _bot()
    assert swerve.transition_slip(bot, np.zeros(4), np.full(4, 1.2), np.ones(4)) < 1e-12
    s = swerve.transition_slip(bot, np.zeros(4), [1.2, -1.2, 1.2, -1.2], np.ones(4))
    assert 0.1 < s <= 1.0
    assert swerve.transition_slip(bot, np.zeros(4), np.zeros(4), np.zeros(4)) == 0.0


@pytest.mark.parametrize("scale", [1e-3, 1.0, 1e3])
def test_desaturation_is_the_same_in_every_unit(scale):
    bot = _bot([(x * scale, y * scale) for x, y in SQUARE])
    tw = np.array([4.0, 1.0 * scale, 0.5 * scale])
    k = swerve.desaturation_scale(bot, tw, 1.0 * scale)
    assert k == pytest.approx(swerve.desaturation_scale(_bot(), [4.0, 1.0, 0.5], 1.0), rel=1e-12)
    assert swerve.desaturation_scale(bot, tw, 100.0 * scale) == 1.0
    assert swerve.desaturation_scale(bot, [0.0, 0.0, 0.0], 1.0) == 1.0


def test_exponential_and_logarithm_are_inverse():
    rng = np.random.default_rng(3)
    tw = rng.normal(size=(100, 3)) * [2.0, 1.0, 1.0]
    dt = 0.3
    np.testing.assert_allclose(swerve.se2_log(swerve.se2_exp(tw, dt), dt), tw, atol=1e-12)
    # exp of a constant twist is the exact end of the motion: compare with wmr.integrate (RK4) of a wheel robot
    bot = _bot()
    t = np.array([1.3, 0.8, -0.2])
    cmd = swerve.module_commands(bot, t)
    tr = wmr.integrate(bot, cmd.speed / 0.05, cmd.beta, t_end=dt, dt=0.001)
    np.testing.assert_allclose(tr.pose[-1], swerve.se2_exp(t, dt), atol=1e-9)


def test_cosine_compensation():
    assert swerve.cosine_compensate(2.0, 0.0, np.pi / 2) == pytest.approx(0.0, abs=1e-15)
    assert swerve.cosine_compensate(2.0, np.pi, 0.0) == pytest.approx(-2.0)


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: swerve.module_commands(wmr.paper_robot("offset"), [0, 1, 0]), "robot"),
        (lambda: swerve.module_commands(_bot(), [0, 1]), "twist"),
        (lambda: swerve.optimize_robot(_bot(), [0, 1, 0], [0, 0, 0]), "current"),
        (lambda: swerve.optimize_robot(_bot(), [0, 1, 0], np.zeros(4), samples=0), "samples"),
        (lambda: swerve.desaturate(_bot(), [0, 1, 0], -1.0), "max_speed"),
        (lambda: swerve.discretize([0, 1, 0], 0.0), "dt"),
        (lambda: swerve.se2_log([7.0, 0, 0]), "delta"),
        (lambda: swerve.chassis_twist(_bot(), np.zeros(4), [np.nan] * 4), "speed"),
        (lambda: swerve.cosine_compensate(np.ones(3), np.ones(2), 0.0), "speed"),
        (lambda: angle_to("0.5", "wpilib"), "beta"),
        (lambda: twist_from([1, 2], "wpilib"), "twist"),
    ],
)
def test_bad_input_names_the_argument(call, name):
    with pytest.raises((TypeError, ValueError), match=rf"\b{name}\b"):
        call()


def test_too_many_modules_for_the_enumeration():
    bot = _bot([(np.cos(a), np.sin(a)) for a in np.linspace(0, 2 * np.pi, swerve.MAX_MODULES + 1, endpoint=False)])
    with pytest.raises(ValueError, match="robot"):
        swerve.optimize_robot(bot, [0, 1, 0], np.zeros(bot.w))


def test_the_conversions_that_left_swerve_warn_and_answer_as_before():
    """wmr.deprecated: to_wpilib, from_wpilib, to_chassis, from_chassis moved to wmr.conventions (issue 29)."""
    from wmr.model.conventions import angle_from, twist_to

    beta, speed, twist = np.array([0.3, -2.0, 3.0]), [1.0, -0.5, 2.0], [3.0, 1.0, 2.0]
    with pytest.warns(
        DeprecationWarning, match=r"wmr.swerve.to_wpilib is deprecated: use wmr.model.conventions.angle_to"
    ):
        alpha, same = swerve.to_wpilib(beta, speed)  # type: ignore[attr-defined]
    assert np.array_equal(alpha, angle_to(beta, "wpilib")) and same.tolist() == speed
    with pytest.warns(DeprecationWarning, match="angle_from"):
        assert np.array_equal(swerve.modules.from_wpilib(alpha), angle_from(alpha, "wpilib"))  # type: ignore[attr-defined]
    with pytest.warns(DeprecationWarning, match="twist_to"):
        assert swerve.to_chassis(twist).tolist() == twist_to(twist, "wpilib").tolist() == [1.0, 2.0, 3.0]  # type: ignore[attr-defined]
    with pytest.warns(DeprecationWarning, match="twist_from"):
        from wmr.swerve import from_chassis  # type: ignore[attr-defined]
    assert from_chassis([1.0, 2.0, 3.0]).tolist() == twist
    with pytest.warns(DeprecationWarning), pytest.raises(wmr.errors.InputError, match=r"\bchassis\b"):
        swerve.from_chassis([1, 2])  # type: ignore[attr-defined]
