"""The re-steering transient simulator (wmr.swerve.transient): physically justified properties, no timing."""

import numpy as np
import pytest

import wmr
from wmr.swerve import transient as T

SQUARE = [(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3)]
LAYOUTS = {
    3: [(0.35 * np.cos(a), 0.35 * np.sin(a)) for a in np.radians([0, 120, 240])],
    4: SQUARE,
    6: [(0.4 * np.cos(a), 0.3 * np.sin(a)) for a in np.radians([10, 70, 130, 190, 250, 310])],
}


def _bot(points=SQUARE):
    return wmr.Robot([wmr.CentredWheel(p, r=0.05) for p in points])


@pytest.fixture(scope="module")
def turn():
    """A 90 degree change of direction while turning slowly (the modules' targets spread by a few degrees)."""
    return T.resteer_study(_bot(), T.direction_change(spin=0.5))


@pytest.mark.parametrize(
    "profile",
    [T.direction_change(angle=0.0), T.TwistProfile("arc", 0.01, np.tile([1.5, 0.8, -0.3], (80, 1)))],
    ids=["straight", "constant arc"],
)
def test_no_slip_and_no_path_error_when_no_resteer_is_needed(profile):
    for run in T.resteer_study(_bot(), profile).runs:
        assert run.slip.max() < 1e-12 and run.max_path_error < 1e-12 and run.steering_travel < 1e-12


def test_reference_path_and_steering_rate_limit(turn):
    ref = turn.runs[0].reference
    np.testing.assert_allclose(ref[-1, 1:], [0.25, 0.75], atol=0.02)  # 0.25 s along x, then 0.75 s along y
    for run in turn.runs:
        assert np.abs(np.diff(run.beta, axis=0)).max() <= turn.steer_rate * turn.profile.dt * (1 + 1e-12)


def test_the_90_degree_turn_slips_and_robot_level_choice_slips_least(turn):
    per, rob, plain = turn.run("module"), turn.run("robot"), turn.run("plain")
    assert per.slip_distance > 0.05  # neighbours turning opposite ways scrub
    assert rob.slip_distance < 0.5 * per.slip_distance  # measured 0.073 m vs 0.197 m
    assert rob.peak_slip < 0.5 * per.peak_slip  # 0.36 vs 1.53 m/s
    assert rob.slip_distance <= plain.slip_distance + 1e-12


def test_a_pure_translation_turn_does_not_slip_but_lags():
    """All modules need the same 90 degrees: they stay parallel (a translation at every instant), so
    nothing slips; the robot keeps going the old way meanwhile: a path error, which cosine compensation cuts."""
    study = T.resteer_study(_bot(), T.direction_change())
    for run in study.runs:
        assert run.slip.max() < 1e-9
        assert run.final_path_error > 0.05
    assert study.run("robot + cos").final_path_error < study.run("robot").final_path_error


def test_cosine_compensation_cuts_the_scrub_of_fighting_modules_and_the_lag_of_parallel_ones(turn):
    assert turn.run("module + cos").slip_distance < turn.run("module").slip_distance
    assert turn.run("robot + cos").max_path_error < turn.run("robot").max_path_error


@pytest.mark.parametrize("w", sorted(LAYOUTS))
@pytest.mark.parametrize(
    "make",
    [lambda: T.direction_change(spin=0.5), lambda: T.direction_change(spin=-0.3, angle=1.75), T.spin_and_translate],
    ids=["turn", "turn100", "spin"],
)
def test_robot_level_never_slips_more_than_per_module(w, make):
    study = T.resteer_study(_bot(LAYOUTS[w]), make(), strategies=[("module", False), ("robot", False)])
    assert study.run("robot").slip_distance <= study.run("module").slip_distance * (1 + 1e-9)


def test_slower_steering_slips_longer():
    bot, prof = _bot(), T.spin_and_translate()
    slips = [
        T.resteer_transient(bot, prof, "robot", steer_rate=rate).slip_distance for rate in (np.pi, 2 * np.pi, 4 * np.pi)
    ]
    assert slips[0] > slips[1] > slips[2] > 0


def test_spin_and_translate_slips_only_once_spinning():
    prof = T.spin_and_translate(t_start=0.3)
    run = T.resteer_transient(_bot(), prof, "robot")
    before = prof.t < 0.3 - 1e-9
    assert run.slip[before].max() < 1e-12 and run.slip[~before].max() > 0.1
    assert 0.8 * run.reference[-1, 0] < run.pose[-1, 0] < run.reference[-1, 0]  # turning, with a lag


def test_table_has_one_row_per_strategy(turn):
    rows = turn.table()
    assert (
        [r["strategy"] for r in rows]
        == [r.label for r in turn.runs]
        == ["plain", "module", "module + cos", "robot", "robot + cos"]
    )
    assert all(np.isfinite(v) for r in rows for k, v in r.items() if k != "strategy")


def test_figure_draws_every_run(turn):
    pytest.importorskip("matplotlib")
    from wmr.swerve.plot import transient_figure

    fig = transient_figure(turn)
    assert len(fig.axes) == 3 and len(fig.axes[1].lines) == len(turn.runs)


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: T.resteer_transient(_bot(), "profile"), "profile"),  # type: ignore[arg-type]
        (lambda: T.resteer_transient(_bot(), T.direction_change(), strategy="wpilib"), "strategy"),
        (lambda: T.resteer_transient(_bot(), T.direction_change(), steer_rate=0.0), "steer_rate"),
        (lambda: T.resteer_transient(_bot(), T.direction_change(), cosine="yes"), "cosine"),  # type: ignore[arg-type]
        (lambda: T.resteer_transient(_bot(), T.direction_change(), beta0=[0.0]), "beta0"),
        (lambda: T.resteer_transient(wmr.paper_robot("dual"), T.direction_change()), "robot"),
        (lambda: T.direction_change(t_change=2.0, t_end=1.0), "t_change"),
        (lambda: T.direction_change(speed=-1.0), "speed"),
        (lambda: T.spin_and_translate(dt=1e-9), "dt"),
        (lambda: T.resteer_study(_bot(), T.direction_change(), strategies=[]), "strategies"),
    ],
)
def test_bad_input_names_the_argument(call, name):
    with pytest.raises((TypeError, ValueError), match=rf"\b{name}\b"):
        call()
