"""Answer tables of the exercises of chapters 4, 5, 6 and 8: right, rounded-right, wrong, trivial, the other angle
unit, malformed -- and every case issue 20 names (4.2 trivial [30, 30, 30]; 5.1/5.2 rounded to 4 decimals; 5.3
U = (-0.7, 0) without a false message; 8.3 U = (0, 0.3606) not told kappa = 1.21e4)."""

from __future__ import annotations

import numpy as np
import pytest

import wmr
from edition import design_study as study
from edition import exercises as X
from edition.checks.centred import planes_through
from edition.exercises.ch4_singularities import TOL_4_1, TOL_4_2
from edition.exercises.ch5_steering import TOL_5_1, TOL_5_2, printed_65_angles
from edition.exercises.table import junk_cases, malformed_case, missing_case, right_case, rounded, verify, wrong_case
from wmr.analysis.motion_kappa import mount_circle

PAPER = wmr.paper_robot("centred", L=0.4, r=0.1)


def _turned_round(beta):
    """The same wheel-plane lines, every wheel turned by 180 degrees (radians)."""
    return np.asarray(beta, dtype=float) + np.pi


# ----------------------------------------------------------------------------------------------- 4.1
BETA_4_1 = [-60.0, 120.0, -60.0]  # every j_i along 30 deg, wheel 2 turned round: (i) and (iii) miss it
TABLE_4_1 = [
    right_case("a wheel turned round", BETA_4_1, says="misses a wheel turned by"),
    right_case("another wheel turned round", [120.0, -60.0, 120.0]),
    right_case("rounded to 0.01 degree", rounded(np.array(BETA_4_1) + [0.004, -0.003, 0.0049], TOL_4_1)),
    right_case("off by less than the tolerance", np.array(BETA_4_1) + 0.009),
    wrong_case("trivial: all equal, along 30 degrees", [-60.0, -60.0, -60.0], says="item \\(i\\)"),
    wrong_case("trivial: [30, 30, 30]", [30.0, 30.0, 30.0], says="another direction", never_says="-60"),
    wrong_case("stated by item (iii)", [-60.0, -60.0, 120.0], says="item \\(iii\\)"),
    wrong_case("off by more than the tolerance", np.array(BETA_4_1) + [0.0, 0.02, 0.0], says="Wheel 2 rolls"),
    wrong_case("the paper's example direction, not 30 degrees", [20.0, 200.0, 20.0], says="another direction"),
    wrong_case("radians for degrees", np.radians(BETA_4_1), says="right in radians"),
    malformed_case("two angles", [10.0, 20.0], says="three angles in degrees"),
    malformed_case("a matrix", np.zeros((3, 3)), says="three angles in degrees"),
    missing_case(),
    *junk_cases(),
]


@pytest.mark.parametrize("case", TABLE_4_1, ids=str)
def test_4_1(case):
    verify(X.unlisted_singularity, case)


# ----------------------------------------------------------------------------------------------- 4.2
def _beta_4_2(alpha=0.7):
    """Every wheel plane through a point of the circle through the mount points (degrees)."""
    bot = X.robot_4_2()
    circle = mount_circle(bot)
    assert circle is not None
    c, R = circle
    return np.degrees(planes_through(bot, c + R * np.array([np.cos(alpha), np.sin(alpha)])))


def _beta_4_2_inside():
    bot = X.robot_4_2()
    circle = mount_circle(bot)
    assert circle is not None
    c, R = circle
    return np.degrees(planes_through(bot, c + 0.5 * R * np.array([1.0, 0.0])))


TABLE_4_2 = [
    right_case("D_P on the circle", _beta_4_2(), says="can turn about"),
    right_case("another point of the circle", _beta_4_2(2.5)),
    right_case("rounded to 0.01 degree", rounded(_beta_4_2(), TOL_4_2)),
    # rounding moves each line by up to 0.005 degree: it passes wherever on the circle D_P lies, also where a wheel
    # is close to the turning point (a student's rounded solution was once refused there)
    *[
        right_case(f"rounded to 0.01 degree, D_P at {a} rad on the circle", np.round(_beta_4_2(a), 2))
        for a in np.linspace(0.0, 2 * np.pi, 24, endpoint=False).round(3)
    ],
    right_case("each wheel turned round", _beta_4_2() + 180.0),
    wrong_case("trivial: [30, 30, 30]", [30.0, 30.0, 30.0], says="parallel", never_says="can turn about"),
    wrong_case("trivial: all zero", [0.0, 0.0, 0.0], says="cannot turn about a point"),
    wrong_case("D_P inside the circle: singular but immobile", _beta_4_2_inside(), says="cannot move"),
    wrong_case("not singular", [10.0, 50.0, 80.0], says="not singular"),
    wrong_case("off by 0.1 degree", _beta_4_2() + [0.1, 0.0, 0.0]),
    wrong_case("radians for degrees", np.radians(_beta_4_2()), says="right in radians"),
    malformed_case("four angles", [1.0, 2.0, 3.0, 4.0], says="three angles"),
    missing_case(),
    *junk_cases(),
]


@pytest.mark.parametrize("case", TABLE_4_2, ids=str)
def test_4_2(case):
    verify(X.mobile_and_singular, case)


def test_4_2_the_robot_is_not_the_papers_and_the_circle_matters():
    """The geometry the check uses agrees with wmr's classification on exact configurations."""
    from wmr.analysis.singularities import classify

    bot = X.robot_4_2()
    on = classify(bot, np.radians(_beta_4_2()))
    inside = classify(bot, np.radians(_beta_4_2_inside()))
    assert on.singular and on.rank_F == 5 and inside.singular and inside.rank_F == 6
    assert not np.allclose(np.linalg.norm(bot.mount_points, axis=1), np.linalg.norm(bot.mount_points[0]))


# ----------------------------------------------------------------------------------------------- 5.1, 5.2
def _beta_5_1():
    """Axles perpendicular to the fixed-frame velocity (0.3, 0.4) at psi = 30 degrees (radians)."""
    return np.full(3, np.arctan2(0.4, 0.3) + np.pi / 2 - np.radians(30.0))


def _beta_5_2():
    u_i = np.array([0.5, 0.3]) - PAPER.mount_points
    return np.arctan2(u_i[:, 1], u_i[:, 0])


TABLE_5_1 = [
    right_case("exact", _beta_5_1(), says="perpendicular"),
    right_case("rounded to 4 decimals (issue 20)", np.round(_beta_5_1(), 4)),
    right_case("rounded to 3 decimals", rounded(_beta_5_1(), TOL_5_1)),
    right_case("wheels turned round", _turned_round(_beta_5_1()) + [0.0, -2 * np.pi, 0.0]),
    wrong_case("the printed (60)", np.full(3, np.arctan2(0.4, 0.3) - np.radians(30.0)), says="printed \\(60\\)"),
    wrong_case("trivial: all zero", [0.0, 0.0, 0.0], says="are not steered"),
    wrong_case("one wheel off", _beta_5_1() + [0.0, 0.0, 0.01], says="wheel 3 is not steered", never_says="Close"),
    wrong_case("rounded to 1 decimal (issue 32)", np.round(_beta_5_1(), 1), says="outside the stated tolerance"),
    wrong_case(
        "wheel 2 rounded to 2 decimals, turned round (issue 32)",
        _beta_5_1() * [1, 0, 1] + [0.0, np.round(_beta_5_1()[1] + np.pi, 2), 0.0],
        says="angle of wheel 2, rounded",
    ),
    wrong_case("psi forgotten", np.full(3, np.arctan2(0.4, 0.3) + np.pi / 2)),
    wrong_case("degrees for radians", np.degrees(_beta_5_1()), says="right in degrees"),
    malformed_case("one angle", 0.5, says="three angles in radians"),
    missing_case(),
    *junk_cases(),
]

TABLE_5_2 = [
    right_case("exact", _beta_5_2(), says="points at U"),
    right_case("rounded to 4 decimals (issue 20)", np.round(_beta_5_2(), 4)),
    right_case("rounded to 3 decimals", rounded(_beta_5_2(), TOL_5_2)),
    right_case("wheels turned round", _turned_round(_beta_5_2())),
    wrong_case("trivial: all zero", [0.0, 0.0, 0.0], says="does not point at U", never_says="Close"),
    wrong_case("rounded to 2 decimals (issue 32)", np.round(_beta_5_2(), 2), says="outside the stated tolerance"),
    wrong_case("the printed (65)", printed_65_angles(np.array([0.5, 0.3]), PAPER.mount_points)),
    wrong_case("measured from CU", _beta_5_2() - np.arctan2(0.3, 0.5)),
    wrong_case("degrees for radians", np.degrees(_beta_5_2()), says="right in degrees"),
    malformed_case("a 3x1 list of lists of lists", [[[0.1]], [[0.2]], [[0.3]]], says="three angles in radians"),
    missing_case(),
    *junk_cases(),
]


@pytest.mark.parametrize("case", TABLE_5_1, ids=str)
def test_5_1(case):
    verify(X.translation_angles, case)


@pytest.mark.parametrize("case", TABLE_5_2, ids=str)
def test_5_2(case):
    verify(X.rotation_angles, case)


# ----------------------------------------------------------------------------------------------- 5.3
TABLE_5_3 = [
    right_case("on the positive body x-axis", (0.7, 0.0), says="along the body axis"),
    right_case(
        "U = (-0.7, 0): on the negative half (issue 20: no false message)",
        (-0.7, 0.0),
        says="-\\\\mathbf i",
        never_says="positive",
    ),
    right_case("within 1 mm of the axis", (0.7, 0.0009)),
    right_case("between C and wheel 1", (-0.2, 0.0)),
    wrong_case("trivial: U = C", (0.0, 0.0), says="0/0"),
    wrong_case("the mount point of wheel 1", (-0.4, 0.0), says="mount point of wheel 1"),
    wrong_case("off the axis by 2 mm", (0.7, 0.002), says="jammed"),
    wrong_case("on the body y-axis", (0.0, 0.7), says="jammed"),
    wrong_case("the point of exercise 5.2", (0.5, 0.3), says="jammed"),
    malformed_case("three numbers", (0.7, 0.0, 0.0), says="a point"),
    missing_case(),
    *junk_cases(),
]


@pytest.mark.parametrize("case", TABLE_5_3, ids=str)
def test_5_3(case):
    verify(X.printed_65_region, case)


def test_5_3_the_printed_rule_works_along_the_whole_axis_and_nowhere_else():
    """What the check accepts is where the printed (65) is exact: sampled on and off the body x-axis."""
    from edition.exercises.ch5_steering import printed_65_angles, rotation_twist
    from wmr.analysis.kinematics import inverse

    for x in (-1.5, -0.7, -0.2, 0.3, 0.7, 2.0):
        u = np.array([x, 0.0])
        assert inverse(PAPER, printed_65_angles(u, PAPER.mount_points), rotation_twist(u)).admissible
        assert X.printed_65_region(u).passed
    for off in ([0.7, 0.05], [0.0, 0.7], [-0.5, -0.3]):
        u = np.array(off)
        assert not inverse(PAPER, printed_65_angles(u, PAPER.mount_points), rotation_twist(u)).admissible
        assert not X.printed_65_region(u).passed


# ----------------------------------------------------------------------------------------------- 6.1, 6.2
TABLE_6_1 = [
    right_case("exact", [0.5, 0.5, 0.5], says="without stopping"),
    right_case("rounded to 3 significant figures", [0.5002, 0.4998, 0.5]),
    wrong_case("trivial: no steering", [0.0, 0.0, 0.0], says="do not stay perpendicular"),
    wrong_case("one wheel too slow", [0.5, 0.5, 0.4], says="misses the commanded velocity"),
    wrong_case("the wrong sense", [-0.5, -0.5, -0.5]),
    wrong_case("degrees per second for rad/s", np.degrees([0.5, 0.5, 0.5]), says="right in degrees"),
    malformed_case("one rate", [0.5], says="three steering rates"),
    missing_case(),
    *junk_cases(),
]

TABLE_6_2 = [
    right_case("a reversal", (0.0, -0.4, -0.2), says="reversal"),
    right_case("a slower reversal, rounded", (0.0, -0.1, -0.05001)),
    wrong_case("trivial: zero", (0.0, 0.0, 0.0), says="stops the robot"),
    wrong_case("the same twist", (0.0, 0.2, 0.1), says="same heading"),
    wrong_case("the same heading, faster", (0.0, 0.4, 0.2), says="same heading"),
    wrong_case("a spin", (1.0, 0.0, 0.0), says="needs slip"),
    wrong_case("another direction", (0.0, 0.2, 0.2), says="needs slip"),
    malformed_case("two numbers", (0.2, 0.1), says="a twist"),
    missing_case(),
    *junk_cases(),
]


@pytest.mark.parametrize("case", TABLE_6_1, ids=str)
def test_6_1(case):
    verify(X.curved_translation, case)


@pytest.mark.parametrize("case", TABLE_6_2, ids=str)
def test_6_2(case):
    verify(X.reversal, case)


def test_6_1_needed_rates_come_from_the_model():
    from edition.exercises.ch6_motion import needed_rates

    assert np.allclose(needed_rates(), 0.5, rtol=1e-6) and np.allclose(needed_rates(1.3), 0.5, rtol=1e-6)


# ----------------------------------------------------------------------------------------------- 8.1 - 8.3
R_8_3 = float(np.hypot(0.3, 0.2))
TABLE_8_1 = [
    right_case("exact", 0.04, says="r/d"),
    right_case("rounded to 3 significant figures", 0.0400),
    right_case("within 3 significant figures", 0.04002),
    wrong_case("d > r with the same worst case", 0.0625, says="larger than"),
    wrong_case("trivial: d = 0", 0.0, says="centred wheels"),
    wrong_case("d = r", 0.05),
    wrong_case("negative", -0.04, says="cannot be negative"),
    wrong_case("tiny: no raw e-notation", 1e-5, never_says="e-05"),
    malformed_case("a list", [0.04, 0.05], says="an offset"),
    missing_case(),
    *junk_cases(),
]

TABLE_8_2 = [
    right_case("a scalene triangle centred at C", [(-0.5, 0.0), (0.1, 0.4), (0.4, -0.4)], says="Only the centroid"),
    right_case("the same in millimetres", [(-500.0, 0.0), (100.0, 400.0), (400.0, -400.0)]),
    wrong_case("equilateral", np.array(wmr.equilateral_mounts(1.0)), says="scalene"),
    wrong_case("centroid off C", [(-0.5, 0.0), (0.1, 0.4), (0.5, -0.4)], says="centroid"),
    wrong_case("trivial: all at C", [(0.0, 0.0)] * 3, says="no triangle"),
    wrong_case("collinear", [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)], says="collinear"),
    malformed_case("two points", [(0.0, 0.0), (1.0, 0.0)], says="three mount points"),
    missing_case(),
    *junk_cases(),
]

TABLE_8_3 = [
    right_case("exact", (0.0, R_8_3), says="on the circle"),
    right_case("U = (0, 0.3606), rounded (issue 20)", (0.0, 0.3606), never_says="1.21"),
    right_case("another point of the circle", (R_8_3, 0.0)),
    wrong_case("trivial: U = C", (0.0, 0.0), says="not singular"),
    wrong_case("a module", (0.3, 0.2), says="mount point"),
    wrong_case("inside the circle", (0.0, 0.3), says="not singular"),
    wrong_case("5 mm off the circle", (0.0, R_8_3 + 0.005), says="not singular", never_says="e+0"),
    malformed_case("a single number", 0.36, says="a point"),
    missing_case(),
    *junk_cases(),
]


@pytest.mark.parametrize("case", TABLE_8_1, ids=str)
def test_8_1(case):
    verify(study.offset_for_worst_case, case)


@pytest.mark.parametrize("case", TABLE_8_2, ids=str)
def test_8_2(case):
    verify(study.scalene_optimum, case)


@pytest.mark.parametrize("case", TABLE_8_3, ids=str)
def test_8_3(case):
    verify(study.singular_rotation, case)


def test_8_3_the_circle_is_where_kappa_is_infinite():
    from wmr.analysis.motion_kappa import motion_kappa, rotation_twists

    bot = study.swerve(0.6, 0.4)
    assert np.isinf(motion_kappa(bot, rotation_twists(np.array([0.0, R_8_3]))))
    assert np.isfinite(motion_kappa(bot, rotation_twists(np.array([0.0, 0.3606]))))


# ----------------------------------------------------------------------------------------------- the prose
def _markdown(name):
    import nbformat

    from conftest import ROOT

    nb = nbformat.read(ROOT / "notebooks" / f"{name}.ipynb", as_version=4)
    return " ".join(" ".join(c.source.split()) for c in nb.cells if c.cell_type == "markdown")


def test_no_answer_in_the_prose_of_4_1_4_2_5_3():
    """The chapters' prose (statements included) does not state the answers: 4.1's angles (-60 or 120 degrees),
    4.2's robot's circle, 5.3's axis."""
    md4 = _markdown("04_centred_wheels_and_singularities")
    assert not any(a in md4 for a in ("-60^", "120^", "-60,", "120,", "-60 ", "120 ")), "4.1's angles in the prose"
    assert "0.5, 0" in md4 and "circumcentre" not in md4 and "circle of radius" not in md4.split("4.2")[-1]
    md5 = _markdown("05_steering_and_instant_centre")
    assert not any(a in md5 for a in ("x-axis", "x$-axis", "positive body", "U = (0.7")), "5.3's answer in the prose"
