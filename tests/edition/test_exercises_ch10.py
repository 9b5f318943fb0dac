"""Answer tables of chapter 10's exercises (Campion's classes; edition.exercises.ch10_classes): right, rounded,
wrong, trivial, other unit and malformed answers, each with the verdict and what the message must (not) say."""

from __future__ import annotations

import numpy as np
import pytest

import wmr
from edition.exercises import ch10_classes as X
from edition.exercises.table import junk_cases, malformed_case, missing_case, right_case, rounded, verify, wrong_case
from edition.exercises.tolerance import sig_figs

AGV = wmr.campion_class(X.AGV)
DM, DS = AGV.delta_m, AGV.delta_s
BETA0 = X.ONE_HANDED.effective_beta(np.zeros(X.ONE_HANDED.w))
MOTORS = np.column_stack([X.motor_rates(X.ONE_HANDED, BETA0, e) for e in np.eye(3)])
PASSIVE = wmr.null_space(MOTORS, scale=np.ones(3))[:, 0]  # computed, not typed
SPIN = np.degrees(wmr.steering_angles(X.SWERVE, [1.0, 0.0, 0.0]))
TRANSLATE = np.degrees(wmr.steering_angles(X.SWERVE, [0.0, 1.0, 0.0]))
OTHER_CENTRE = np.degrees(wmr.steering_angles(X.SWERVE, [1.0, 0.0, 0.5]))  # a spin about (-0.5, 0)

TABLES = {
    "10.1": (
        X.check_10_1,
        [
            right_case("the class", (DM, DS), says=r"class \(1,2\)"),
            right_case("floats that are whole", [float(DM), float(DS)]),
            wrong_case("swapped", (DS, DM), says="other order"),
            wrong_case("delta_s off", (DM, DS - 1), says=r"\\delta_m\$ is right"),
            wrong_case("delta_m off", (DM + 1, DS), says=r"\\delta_s\$ is right"),
            wrong_case("both off: the omnidirectional class", (3, 0), says="Neither"),
            wrong_case("trivial zeros", (0, 0), says="Neither"),
            wrong_case("not whole", (1.5, 2), says="whole numbers"),
            malformed_case("one number", 1, says="two whole numbers"),
            malformed_case("three numbers", (1, 2, 3), says="two whole numbers"),
            missing_case(),
        ],
    ),
    "10.2": (
        X.check_10_2,
        [
            right_case("the null space of the motor map", PASSIVE, says="No drive motor turns"),
            right_case("rounded to 4 significant figures", rounded(PASSIVE, sig_figs(4))),
            right_case("scaled by -3", -3 * PASSIVE),
            wrong_case("trivial: at rest", [0.0, 0.0, 0.0], says="at rest"),
            wrong_case("a spin", [1.0, 0.0, 0.0], says="4 of the four", never_says=f"{abs(PASSIVE[1]):.3f}"),
            wrong_case("the perpendicular translation", [0.0, PASSIVE[2], -PASSIVE[1]], says="motors must turn"),
            wrong_case("one component off by 1.4 %", PASSIVE * [1, 1, 1.014], says="motors must turn"),
            malformed_case("two numbers", PASSIVE[:2], says="a twist"),
            missing_case(),
        ],
    ),
    "10.3": (
        X.check_10_3,
        [
            right_case("the spin angles", SPIN, says="spins on the spot"),
            right_case("rounded to 1 decimal place", rounded(SPIN, X.TOL_10_3)),
            right_case("each wheel turned round by 180 degrees", SPIN + 180.0),
            wrong_case("radians for degrees", np.radians(SPIN), says="would be right in radians"),
            wrong_case("trivial: all zero", [0.0, 0.0, 0.0, 0.0], says="translate, but not turn"),
            wrong_case("a translation", TRANSLATE, says="translate"),
            wrong_case("a spin about another point", OTHER_CENTRE, says="not at C"),
            wrong_case(
                "the spin angles in the order FR, FL, RL, RR (issue 32)",
                SPIN[[1, 0, 2, 3]],
                says="another order of the modules",
                never_says="cannot move",
            ),
            wrong_case("one wheel off by 1 degree", SPIN + [1.0, 0, 0, 0], says="cannot move at all"),
            malformed_case("three angles", SPIN[:3], says="four angles in degrees; got"),
            malformed_case("text", "45, 135, -45, -135", says="text"),
            missing_case(),
        ],
    ),
}


@pytest.mark.parametrize(
    "number,case", [(n, c) for n, (_, cases) in TABLES.items() for c in cases], ids=lambda x: str(x)
)
def test_answer_table(number, case):
    verify(TABLES[number][0], case)


@pytest.mark.parametrize("number", list(TABLES))
def test_junk_answers(number):
    for case in junk_cases():
        verify(TABLES[number][0], case)


def test_the_table_covers_every_exercise_of_the_chapter_and_the_worked_answers_are_not_trivial():
    from edition.exercises.framework import registered

    assert {n for n in registered() if n.startswith("10.")} == set(TABLES)
    assert np.linalg.norm(PASSIVE) > 0.5 and np.ptp(np.mod(SPIN, 180)) > 1.0
    # the passive twist is a translation (no spin): a motion the rollers alone carry
    assert abs(PASSIVE[0]) < 1e-9 and np.allclose(MOTORS @ PASSIVE, 0, atol=1e-9)
