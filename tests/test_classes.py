"""wmr.analysis.classes: Campion, Bastin & d'Andrea-Novel's five classes on robots built in Python."""

import dataclasses
import re

import numpy as np
import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st

import wmr
from wmr.analysis.classes import CLASS_NAMES, CampionClass, campion_class

PI = np.pi


def _robots():
    F, S, C, Off = wmr.FixedWheel, wmr.SwedishWheel, wmr.CentredWheel, wmr.OffsetWheel
    rect = [(0.3, 0.25), (0.3, -0.25), (-0.3, 0.25), (-0.3, -0.25)]
    return {
        "three omni wheels": (
            wmr.Robot(
                [
                    S(tuple(p), r=0.05, angle=float(np.arctan2(p[1], p[0])), roller=PI / 2)
                    for p in wmr.equilateral_mounts(0.25)
                ]
            ),
            (3, 0),
        ),
        "four mecanum wheels": (
            wmr.Robot([S(p, r=0.05, angle=PI / 2, roller=PI / 4 if p[0] * p[1] > 0 else -PI / 4) for p in rect]),
            (3, 0),
        ),
        "differential drive + castor": (
            wmr.Robot(
                [
                    F((0.0, 0.2), r=0.05, angle=PI / 2),
                    F((0.0, -0.2), r=0.05, angle=PI / 2),
                    Off((-0.3, 0.0), r=0.03, d=0.04),
                ]
            ),
            (2, 0),
        ),
        "steered wheel + two castors": (
            wmr.Robot([C((0.35, 0.0), r=0.05), Off((-0.2, 0.2), r=0.03, d=0.04), Off((-0.2, -0.2), r=0.03, d=0.04)]),
            (2, 1),
        ),
        "tricycle": (
            wmr.Robot(
                [F((0.0, 0.2), r=0.05, angle=PI / 2), F((0.0, -0.2), r=0.05, angle=PI / 2), C((0.5, 0.0), r=0.05)]
            ),
            (1, 1),
        ),
        "car (front axle of two steered wheels)": (
            wmr.Robot(
                [
                    F((0.0, 0.2), r=0.05, angle=PI / 2),
                    F((0.0, -0.2), r=0.05, angle=PI / 2),
                    C((0.5, 0.2), r=0.05),
                    C((0.5, -0.2), r=0.05),
                ]
            ),
            (1, 1),
        ),
        "paper, three centred wheels": (wmr.paper_robot("centred", L=0.3, r=0.05), (1, 2)),
        "four-module swerve": (wmr.Robot([C(p, r=0.05) for p in rect]), (1, 2)),
        "paper, offset wheels": (wmr.paper_robot("offset", L=0.3, r=0.05), (3, 0)),
        "paper, dual wheels": (wmr.paper_robot("dual", L=0.3, r=0.05), (1, 2)),
        "one omni wheel + one fixed wheel": (
            wmr.Robot([S((0.3, 0.0), r=0.05, angle=0.0, roller=PI / 2), F((-0.3, 0.0), r=0.05, angle=0.0)]),
            (2, 0),
        ),
        "two steered + one castor": (
            wmr.Robot([C((0.3, 0.0), r=0.05), C((-0.3, 0.0), r=0.05), Off((0.0, 0.3), r=0.03, d=0.03)]),
            (1, 2),
        ),
    }


ROBOTS = _robots()
NAMES = list(ROBOTS)


@pytest.mark.parametrize("name", NAMES)
def test_class(name):
    bot, want = ROBOTS[name]
    c = campion_class(bot)
    assert (c.delta_m, c.delta_s) == want
    assert c.label == f"({want[0]},{want[1]})" and re.fullmatch(r"\(\d,\d\)", c.label)
    assert c.standard and c.name == CLASS_NAMES[want] and c.maneuverability == sum(want)
    assert len(c.beta) == bot.w and len(c.twist) == 3


@pytest.mark.parametrize("name", NAMES)
def test_example_configuration_attains_the_class(name):
    """At the returned configuration the generic twist is admissible; the admissible twists have dimension delta_m."""
    bot, (dm, ds) = ROBOTS[name]
    c = campion_class(bot)
    assert bool(wmr.inverse(bot, c.beta, c.twist).admissible)
    assert wmr.admissible_twists(bot, c.beta).shape[1] == dm
    assert np.allclose(np.array(c.beta)[~np.array(bot.steered)], [u.angle for u in bot.wheels if not u.steered])


def _scaled(bot, s):
    """Every length times s (mount points, radii, offsets, half separations); angles unchanged."""
    units = []
    for u in bot.wheels:
        lengths = {f: getattr(u, f) * s for f in ("r", "d", "b") if hasattr(u, f)}
        units.append(dataclasses.replace(u, position=(u.position[0] * s, u.position[1] * s), **lengths))
    return wmr.Robot(units)


@pytest.mark.parametrize("name", NAMES)
def test_class_is_unit_invariant(name):
    bot, want = ROBOTS[name]
    got = {k: (lambda c: (c.delta_m, c.delta_s))(campion_class(_scaled(bot, 10.0**k))) for k in range(-6, 7)}
    assert set(got.values()) == {want}, got


@pytest.mark.parametrize("name", NAMES)
def test_class_is_frame_invariant_and_deterministic(name):
    bot, want = ROBOTS[name]
    a, b = campion_class(bot), campion_class(bot)
    assert a == b
    moved = bot.moved(origin=(0.17, -0.31), angle=0.9)
    c = campion_class(moved)
    assert (c.delta_m, c.delta_s) == want


def test_degenerate_robots_are_named():
    F, C = wmr.FixedWheel, wmr.CentredWheel
    stuck = wmr.Robot(
        [F((1.0, 0.0), r=0.1, angle=0.0), F((-0.5, 0.8), r=0.1, angle=0.3), F((-0.5, -0.8), r=0.1, angle=2.0)]
    )
    c = campion_class(stuck)
    assert (c.delta_m, c.standard) == (0, False) and "no motion" in c.name and c.twist == (0.0, 0.0, 0.0)
    pivot = wmr.Robot([F((1.0, 0.0), r=0.1, angle=0.0), F((0.0, 1.0), r=0.1, angle=PI / 2), C((-1.0, -1.0), r=0.1)])
    c = campion_class(pivot)  # axles meet at C: it can only spin about C
    assert (c.delta_m, c.standard) == (1, False) and "rotation about one point" in c.name
    assert np.allclose(np.array(c.twist)[1:], 0)
    aligned = wmr.Robot([F((0.0, 0.2), r=0.1, angle=PI / 2), F((0.0, -0.2), r=0.1, angle=PI / 2), C((0.0, 0.5), r=0.1)])
    c = campion_class(aligned)  # a steered wheel on the fixed axle: its row repeats theirs
    assert (c.delta_m, c.delta_s, c.rank_C1s, c.standard) == (2, 0, 1, True)


def test_car_with_two_steered_front_wheels_is_car_like():
    """rank C1s = 2, but with the rear axle only one steering angle is free: (1,1), as Campion classes a car."""
    c = campion_class(ROBOTS["car (front axle of two steered wheels)"][0])
    assert (c.delta_m, c.delta_s, c.rank_C1f, c.rank_C1s) == (1, 1, 1, 2)


def test_exact_robot_and_result_type():
    c = campion_class(wmr.paper_robot("centred", L=1, r=sp.Rational(1, 10), exact=True))
    assert isinstance(c, CampionClass) and c.label == "(1,2)"
    with pytest.raises(dataclasses.FrozenInstanceError):
        c.delta_m = 3  # type: ignore[misc]
    assert wmr.campion_class is campion_class


@pytest.mark.parametrize(
    "bad, exc",
    [(None, TypeError), ("robot", TypeError), (wmr.Robot, TypeError), ([wmr.CentredWheel((0, 0), r=1)], TypeError)],
)
def test_bad_robot(bad, exc):
    with pytest.raises(exc, match=r"\brobot\b"):
        campion_class(bad)


def test_symbolic_robot_is_rejected():
    x = sp.Symbol("x", positive=True)
    bot = wmr.Robot([wmr.CentredWheel((x, 0), r=1), wmr.CentredWheel((0, x), r=1)])
    with pytest.raises(ValueError, match=r"\brobot\b"):
        campion_class(bot)


#: angles: multiples of 15 degrees (exact alignments) or at least 1e-4 rad away from them, so that no
#: configuration is within the rank tolerance of a special one (there the class may flip, by design)
_ANGLES = st.one_of(
    st.integers(-12, 12).map(lambda k: k * PI / 12),
    st.floats(-PI, PI).filter(lambda a: np.min(np.abs(a - np.arange(-12, 13) * PI / 12)) > 1e-4),
)
#: mount points on a 0.05 grid (collinear exactly, or clearly not)
_POINTS = st.tuples(st.integers(-20, 20), st.integers(-20, 20)).map(lambda p: (p[0] / 20, p[1] / 20))


@st.composite
def mixed_robots(draw):
    """Random robots of every wheel type (two to five units, distinct mount points)."""
    w = draw(st.integers(2, 5))
    pts = draw(st.lists(_POINTS, min_size=w, max_size=w, unique=True))
    units: list = []
    for p in pts:
        kind = draw(st.sampled_from(["fixed", "swedish", "centred", "offset", "dual"]))
        angle = draw(_ANGLES)
        if kind == "fixed":
            units.append(wmr.FixedWheel(p, r=0.1, angle=angle))
        elif kind == "swedish":
            units.append(
                wmr.SwedishWheel(p, r=0.1, angle=angle, roller=draw(st.sampled_from([PI / 2, PI / 4, -PI / 4])))
            )
        elif kind == "centred":
            units.append(wmr.CentredWheel(p, r=0.1))
        elif kind == "offset":
            units.append(wmr.OffsetWheel(p, r=0.1, d=0.05))
        else:
            units.append(wmr.DualWheel(p, r=0.1, b=0.05))
    return wmr.Robot(units)


@given(mixed_robots(), st.integers(-6, 6))
def test_class_of_random_robots(bot, k):
    """delta_m is the dimension of the admissible twists at the returned configuration; the class
    does not change with the unit of length or the body frame; delta_m + delta_s <= 3."""
    c = campion_class(bot)
    assert 0 <= c.delta_m <= 3 and 0 <= c.delta_s and c.delta_m + c.delta_s <= 3
    assert wmr.admissible_twists(bot, c.beta).shape[1] == c.delta_m
    if c.delta_m:
        assert bool(wmr.inverse(bot, c.beta, c.twist).no_slip)
    for other in (_scaled(bot, 10.0**k), bot.moved(origin=(0.3, -0.1), angle=1.0)):
        d = campion_class(other)
        assert (d.delta_m, d.delta_s, d.standard) == (c.delta_m, c.delta_s, c.standard)
