"""Answer tables of chapters 1-3's exercises (edition.exercises.ch1_wheels, ch2_mobility, ch3_isotropy): right,
rounded, wrong, trivial, other unit and malformed answers, each with the verdict and what the message must (not)
say, including the cases of issue 20 (1.1 in the student's own symbols, 2.2's zero answer, 3.1's L = 0.5033)."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

import wmr
from edition import exercises as X
from edition import symbols as S
from edition.exercises import ch1_wheels as C1
from edition.exercises import ch2_mobility as C2
from edition.exercises import ch3_isotropy as C3
from edition.exercises.table import junk_cases, malformed_case, missing_case, right_case, rounded, verify, wrong_case

# ----------------------------------------------------------------------------------------------- 1.1
# the expected velocity from the model (OffsetWheel.block, psi = 0), the centre moved to the other side by d -> -d
P9 = wmr.OffsetWheel((0, 0), r=S.r, d=S.d).block(S.phi_i) * sp.Matrix([S.phi_dot_i, S.theta_dot_i])
P11 = P9.subs(S.d, -S.d)
r, d, phi, phid, thd = sp.symbols("r d phi_i phidot_i thetadot_i")  # the student's own, no assumptions
OWN = P11.xreplace({S.r: r, S.d: d, S.phi_i: phi, S.phi_dot_i: phid, S.theta_dot_i: thd})
ROTATED = sp.Matrix([[sp.cos(phi), -sp.sin(phi)], [sp.sin(phi), sp.cos(phi)]]) * sp.Matrix([d * phid, -r * thd])
LATEX_11 = sp.latex(P11[0])

# ----------------------------------------------------------------------------------------------- 1.2
DUAL = wmr.paper_robot("dual", **C1.DUAL_1_2)
TWIST = np.array([0.5, 0.2, -0.1])
BETA = wmr.steering_angles(DUAL, TWIST)
SPIN_C = np.array([1.0, 0.0, 0.0])

# ----------------------------------------------------------------------------------------------- 1.3
RATES, _ = C1._dual_rates(0.1, 0.05, 1.0)

# ----------------------------------------------------------------------------------------------- 2.1
OFFSET = wmr.paper_robot("offset", **C2.PAPER_2_1)
V = OFFSET.mount_points - np.array([0.2, -0.1])
CONCURRENT = np.arctan2(-V[:, 0], V[:, 1])  # every arm line through (0.2, -0.1)

# ----------------------------------------------------------------------------------------------- 2.2
C_DOT = C2.locked_c_dot(C2.D4, C2.BETA4, C2.PHI_DOT4)
names = {
    s: sp.Symbol(n)
    for s, n in zip(
        C2.SYMBOLS_2_2,
        [
            "d_1x",
            "d_1y",
            "d_2x",
            "d_2y",
            "d_3x",
            "d_3y",
            "d_4x",
            "d_4y",
            "beta1",
            "beta2",
            "beta3",
            "beta4",
            "phidot_1",
            "phidot_2",
            "phidot_3",
            "phidot_4",
            "d",
            "psidot",
        ],
        strict=True,
    )
}
C_DOT_OWN = C_DOT.xreplace(names)
THREE_WHEEL = C2.locked_c_dot(C2.D4[:3], C2.BETA4[:3], C2.PHI_DOT4[:3])

# ----------------------------------------------------------------------------------------------- 3.1
FIXED = np.array(C3.FIXED_3_1)
POINTS = np.vstack([FIXED, -FIXED.sum(axis=0)])
L_ISO = float(np.sqrt(np.mean(np.sum(POINTS**2, axis=1))))

# ----------------------------------------------------------------------------------------------- 3.2
B = wmr.DualWheel((0, 0), r=S.r, b=S.b).block(S.beta_i)
UPS = B * B.T
rr, bb, be = sp.symbols("r b beta_i")
OFFSET_UPS = wmr.OffsetWheel((0, 0), r=S.r, d=S.b).block(S.beta_i)

TABLES = {
    "1.1": (
        X.offset_other_side,
        [
            right_case("the model's velocity", P11, says="changes sign"),
            right_case("in the student's own symbols (no assumptions, own spelling)", OWN, says="changes sign"),
            right_case("an equivalent form: rotated wheel-frame components", ROTATED),
            wrong_case("the printed side, (9) itself", P9, says="That is \\(9\\) itself", never_says=LATEX_11),
            wrong_case(
                "rolling term off",
                P11 + sp.Matrix([S.r * S.theta_dot_i, 0]),
                says="rolling term is off",
                never_says=LATEX_11,
            ),
            wrong_case(
                "steering term off",
                P11.subs(S.phi_dot_i, 2 * S.phi_dot_i),
                says="steering term is not",
                never_says=LATEX_11,
            ),
            wrong_case("trivial: zero", sp.zeros(2, 1), says="Both terms", never_says=LATEX_11),
            malformed_case("a 3-vector", sp.Matrix([1, 2, 3]), says="shape"),
            malformed_case("a symbol the exercise does not have", P11 + sp.Matrix([sp.Symbol("q"), 0]), says="q"),
            malformed_case("text", "-r*thetadot*j + d*phidot*i", says="text"),
            missing_case(),
        ],
    ),
    "1.2": (
        X.dual_counterexample,
        [
            right_case("angles of a rotation about a point other than C", (BETA, TWIST), says=r"\\dot\\psi"),
            right_case("angles rounded to 4 decimal places", (np.round(BETA, 4), TWIST)),
            right_case("each wheel turned round by 180 degrees", (BETA + np.pi, 2 * TWIST)),
            wrong_case("degrees for radians", (np.degrees(BETA), TWIST), says="right in degrees"),
            wrong_case(
                "the chapter's spin about C (stated in the prose)",
                (wmr.steering_angles(DUAL, SPIN_C), SPIN_C),
                says="spin about C",
            ),
            wrong_case(
                "a translation: the printed (15) holds there",
                (wmr.steering_angles(DUAL, [0, 1.0, 0]), [0, 1.0, 0]),
                says="does not turn",
            ),
            wrong_case("trivial: zero twist", (np.zeros(3), np.zeros(3)), says="must move"),
            wrong_case("angles off by 0.01 rad", (BETA + 0.01, TWIST), says="slip"),
            malformed_case("only the angles", BETA, says="pair"),
            malformed_case("two angles", (BETA[:2], TWIST), says="three steering angles"),
            missing_case(),
        ],
    ),
    "1.3": (
        X.dual_spin_in_place,
        [
            right_case("the rates", RATES, says="at rest"),
            right_case("rounded to 3 significant figures", rounded(RATES, C1.TOL_1_3)),
            wrong_case("degrees per second for radians per second", np.degrees(RATES), says="right in degrees"),
            wrong_case("the other direction", -RATES, says="turns at \\$-1\\$"),
            wrong_case("equal rates: P moves", [0.5, 0.5], says="moves"),
            wrong_case("trivial: zero", [0.0, 0.0], says="stands still"),
            wrong_case("off by 1 %", RATES * 1.01),
            malformed_case("three rates", [1.0, 2.0, 3.0], says="two wheel rates"),
            missing_case(),
        ],
    ),
    "2.1": (
        X.locked_steering,
        [
            right_case("arms through (0.2, -0.1)", CONCURRENT, says="meet at"),
            right_case("rounded to 3 decimal places", np.round(CONCURRENT, 3)),
            right_case("a unit turned round by 180 degrees", CONCURRENT + [np.pi, 0, 0]),
            wrong_case("degrees for radians", np.degrees(CONCURRENT), says="right in degrees"),
            wrong_case("trivial: all equal (parallel)", [0.3, 0.3, 0.3], says="parallel"),
            wrong_case("trivial: zeros (parallel)", [0.0, 0.0, 0.0], says="parallel"),
            wrong_case("generic angles: the steering jams", [0.1, 0.7, -1.2], says="jams"),
            wrong_case("one angle off by 0.01 rad", CONCURRENT + [0.01, 0, 0], says="jams"),
            malformed_case("two angles", CONCURRENT[:2], says="three angles"),
            missing_case(),
        ],
    ),
    "2.2": (
        X.drift_of_c_general,
        [
            right_case("the derived drift", C_DOT, says="centroid"),
            right_case("in the student's own symbols", C_DOT_OWN),
            right_case("expanded", C_DOT.applyfunc(sp.expand)),
            wrong_case("divided by 3 as for three wheels", C_DOT * sp.Rational(3, 4), says="four block rows"),
            wrong_case("without the platform rows, as (28)", C_DOT.subs(S.psi_dot, 0), says="missing"),
            wrong_case("the three-wheel result", THREE_WHEEL),
            wrong_case(
                "trivial: zero (issue 20: must not print the formula)",
                sp.zeros(2, 1),
                says="Sum the four",
                never_says="\\frac",
            ),
            malformed_case("a scalar", S.d, says="one expression|matrix"),
            malformed_case("a symbol the exercise does not have", C_DOT + sp.Matrix([sp.Symbol("w"), 0]), says="w"),
            missing_case(),
        ],
    ),
    "3.1": (
        X.isotropic_placement,
        [
            right_case("exact", (POINTS, L_ISO), says="0.5033"),
            right_case("L = 0.5033, as the success message prints it (issue 20)", (POINTS, 0.5033)),
            right_case("rounded to 4 significant figures", (rounded(POINTS, C3.TOL_3_1), rounded(L_ISO, C3.TOL_3_1))),
            wrong_case(
                "L the mean distance, not the RMS",
                (POINTS, float(np.mean(np.linalg.norm(POINTS, axis=1)))),
                says="mean squared distance",
                never_says="Close",
            ),
            wrong_case("L = 0.4", (POINTS, 0.4), says="mean squared distance", never_says="0.503"),
            wrong_case(
                "L rounded to 2 figures (issue 32)",
                (POINTS, 0.50),
                says="you gave the right .L., rounded",
                never_says="0.503",
            ),
            wrong_case(
                "centroid off", (POINTS + [[0, 0], [0, 0], [0, 0.1]], L_ISO), says="centroid", never_says="0.3, -0.5"
            ),
            wrong_case("wheels 1 and 2 swapped", (POINTS[[1, 0, 2]], L_ISO), says="stay at"),
            wrong_case("L negative", (POINTS, -L_ISO), says="positive"),
            wrong_case("trivial: zeros", (np.zeros((3, 2)), 0.0), says="stay at"),
            malformed_case("points only", POINTS, says="pair"),
            malformed_case("two points", (POINTS[:2], L_ISO), says="shape \\(3, 2\\)"),
            missing_case(),
        ],
    ),
    "3.2": (
        X.dual_upsilon,
        [
            right_case("B B^T", UPS, says="rank 1"),
            right_case("in the student's own symbols", UPS.xreplace({S.r: rr, S.b: bb, S.beta_i: be})),
            right_case("simplified", UPS.applyfunc(sp.trigsimp)),
            wrong_case("B^T B", B.T * B, says="other way round"),
            wrong_case("the offset wheel's Upsilon", OFFSET_UPS * OFFSET_UPS.T, says="offset wheel"),
            wrong_case("trivial: zero", sp.zeros(2, 2), says="no-slip rows", never_says="r^{2}"),
            # a wrong answer is told what to do, never shown the solution's code
            wrong_case("the identity", sp.eye(2), says="no-slip rows", never_says="DualWheel"),
            wrong_case("not symmetric", sp.Matrix([[1, 2], [3, 4]]), says="not symmetric", never_says="DualWheel"),
            malformed_case("a 2-vector", sp.Matrix([1, 2]), says="shape"),
            missing_case(),
        ],
    ),
    "3.3": (
        X.offset_for_kappa,
        [
            right_case("both offsets", [0.05, 0.2], says="d = r/2"),
            right_case("in the other order, as a tuple", (0.2, 0.05)),
            right_case("rounded to 3 significant figures", rounded([0.1 / 2, 0.1 * 2], C3.TOL_3_3)),
            wrong_case("one of them", [0.2], says="one more", never_says="0.05"),
            wrong_case("the same one twice", [0.05, 0.05], says="one more"),
            wrong_case("d = r (isotropic)", [0.1], says="not 2"),
            wrong_case("a wrong value", [0.05, 0.3], says="not 2"),
            wrong_case("millimetres for metres", [50.0, 200.0], says="millimetres"),
            wrong_case("trivial: zero", [0.0], says="positive"),
            malformed_case("text", "0.05, 0.2", says="text"),
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


def test_the_tables_cover_every_exercise_of_chapters_1_to_3():
    from edition.exercises.framework import registered

    assert {n for n in registered() if n.split(".")[0] in {"1", "2", "3"}} == set(TABLES)


def test_the_worked_answers_are_not_trivial():
    assert abs(TWIST[0]) > 0 and np.hypot(*TWIST[1:]) > 0 and np.ptp(np.mod(CONCURRENT, np.pi)) > 0.1
    assert RATES[0] == pytest.approx(-RATES[1]) and abs(RATES[0]) > 0.1
    assert abs(L_ISO - 0.5033) < 5e-5 and np.ptp(np.linalg.norm(POINTS, axis=1)) > 0.05  # not equilateral
    assert sp.Matrix(UPS).rank() == 1 and C_DOT != sp.zeros(2, 1)
