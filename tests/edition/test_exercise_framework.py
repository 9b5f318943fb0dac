"""The fair-check framework (edition.exercises.framework and friends), tested with answer tables on small checks
made here, and every registered exercise of the edition against missing and junk answers."""

from __future__ import annotations

import re

import numpy as np
import pytest
import sympy as sp

from edition import symbols as S
from edition.exercises import answers
from edition.exercises.feedback import Result, right, undecided, wrong
from edition.exercises.framework import by_name, exercise, registered
from edition.exercises.symbolic import compare, equivalent, map_symbols, spelling
from edition.exercises.table import (
    JUNK,
    Case,
    junk_cases,
    malformed_case,
    missing_case,
    problems,
    right_case,
    rounded,
    verify,
    wrong_case,
)
from edition.exercises.tolerance import angle_gap, decimals, sig_figs, unit_hint, within

# ------------------------------------------------------------------ three checks built as the chapters build theirs
TOL_ANG = decimals(2, "degrees")
BETA = np.array([30.0, 150.0, 270.0])  # computed stand-ins: three lines 120 degrees apart


@exercise("T.1", answer="three steering angles in degrees", tolerance=TOL_ANG, units={"beta": "deg"}, register=False)
def angles_demo(beta):
    b = answers.vector(beta, 3, "three steering angles in degrees")
    if np.ptp(np.mod(b, 180)) < 1e-9:
        return wrong("All three wheel planes are parallel: that needs no work. Give three different lines.")
    if angle_gap(np.radians(b), np.radians(BETA)) <= np.radians(TOL_ANG.allowed(1.0)):
        return right("The three wheel-plane lines are 120 degrees apart.")
    return wrong("The lines are not 120 degrees apart.")


TOL_L = sig_figs(3)
L_TRUE = float(np.sqrt(2) * 0.355894)  # a length with a scale: relative tolerance


@exercise("T.2", answer="the length $L$ in metres", tolerance=TOL_L, register=False)
def length_demo(L):
    x = answers.number(L, "the length $L$ in metres")
    if x <= 0:
        return wrong("$L$ must be a positive length.")
    if TOL_L.accepts(x, L_TRUE):
        return right(f"$L = {TOL_L.show(x)}$ m makes the matrix isotropic.")
    return wrong(f"With $L = {TOL_L.show(x)}$ m the matrix is not isotropic.")


THETA = S.r * S.theta_dot_i * sp.cos(S.beta_i) + S.d * S.phi_dot_i


@exercise("T.3", answer="an expression in $r$, $d$, the rates and $\\beta_i$", register=False)
def symbolic_demo(expr):
    mapped, same = compare(expr, THETA, [S.r, S.d, S.theta_dot_i, S.phi_dot_i, S.beta_i], "an expression")
    if same is None:
        return undecided("This expression could not be evaluated at sample points; simplify it and try again.")
    if same:
        return right("The rolling and steering terms are both there.")
    if mapped == 0 or not mapped.free_symbols:
        return wrong("The answer must depend on the wheel's rates.")
    return wrong("Not equal to the velocity of the contact point.")


@exercise("T.4", answer="a number", register=False)
def broken_demo(x):
    return right(str(1 / (answers.number(x) - 1)))  # a defect: divides by zero at x = 1


r_, d_, thd_, phd_, b_ = sp.symbols("r d thetadot_i phi_dot_i beta_i")  # the student's own, no assumptions

TABLE = {
    angles_demo: [
        right_case("exact", BETA.tolist()),
        right_case("rounded to 2 decimals", rounded(BETA + 0.004, TOL_ANG)),
        right_case("each line turned round (mod 180)", [210.0, -30.0, 90.0]),
        right_case("a SymPy column", sp.Matrix(BETA.tolist())),
        wrong_case("off by 1 degree", [31.0, 150.0, 270.0], says="not 120", never_says="30"),
        wrong_case("trivial: all equal", [30, 30, 30], says="parallel"),
        wrong_case("trivial: all zero", [0, 0, 0], says="parallel"),
        wrong_case("radians for degrees", np.radians(BETA), says="would be right in radians"),
        wrong_case("small wrong numbers (looks like radians)", [0.1, 0.2, 0.3], says="np.degrees"),
        malformed_case("two numbers", [30, 150], says=r"three steering angles in degrees; got a list of 2"),
        malformed_case("a 2 x 3 array", np.zeros((2, 3)), says="shape"),
        malformed_case("text", "30, 150, 270", says="text"),
        missing_case(),
        Case("two answers for one", (BETA, BETA), False, "malformed", ("takes 1 answer",)),
    ],
    length_demo: [
        right_case("exact", L_TRUE),
        right_case("to 3 significant figures", rounded(L_TRUE, TOL_L)),
        right_case("a SymPy number", sp.Float(L_TRUE)),
        wrong_case("2 significant figures", 0.50, says="not isotropic"),
        wrong_case("negative", -L_TRUE, says="positive"),
        wrong_case("zero", 0.0, says="positive"),
        malformed_case("a list of one", [L_TRUE], says="one number|list"),
        missing_case(),
    ],
    symbolic_demo: [
        right_case("the package's symbols", THETA),
        right_case("the student's own symbols, expanded differently", d_ * phd_ + r_ * thd_ * sp.cos(b_)),
        right_case(
            "an equivalent trigonometric form", S.d * S.phi_dot_i + S.r * S.theta_dot_i * sp.sin(S.beta_i + sp.pi / 2)
        ),
        wrong_case("rolling term off", d_ * phd_ + r_ * thd_ * sp.sin(b_), says="not equal"),
        wrong_case("trivial zero", sp.Integer(0), says="depend"),
        malformed_case("a stranger symbol", sp.Symbol("q") * r_, says="does not have"),
        malformed_case("a matrix for an expression", sp.Matrix([r_, d_]), says="one expression"),
        malformed_case("text", "r*thetadot_i", says="SymPy symbols"),
        missing_case(),
    ],
}


@pytest.mark.parametrize(
    "check,case", [(c, k) for c, ks in TABLE.items() for k in ks], ids=lambda x: getattr(x, "__name__", str(x))
)
def test_answer_table(check, case):
    verify(check, case)


@pytest.mark.parametrize("check", list(TABLE), ids=lambda c: c.__name__)
@pytest.mark.parametrize("case", junk_cases(), ids=str)
def test_junk_is_one_line_never_passed(check, case):
    r = verify(check, case)
    assert r.status in ("malformed", "wrong"), r


def test_the_success_message_prints_a_value_that_passes():
    r = length_demo(L_TRUE)
    found = re.search(r"L = ([0-9.]+)", r.message)
    assert found is not None, r.message
    printed = float(found.group(1))
    assert printed != L_TRUE and length_demo(printed).passed


def test_a_failing_check_is_one_line_with_status_error_and_the_harness_reports_it():
    r = broken_demo(1.0)
    assert r.status == "error" and not r.passed and r.points == 0 and "\n" not in r.message
    assert "ZeroDivisionError" in r.message and "Traceback" not in r.markdown()
    assert any("status error" in p for p in problems(r))
    with pytest.raises(AssertionError, match="status error"):
        verify(broken_demo, Case("x", (1.0,), False))


def test_result_points_and_markdown():
    r = angles_demo(BETA)
    assert isinstance(r, Result) and r.passed and r.points == 1.0 and r.exercise == "T.1"
    assert r.markdown().startswith("**Right.** Exercise T.1:") and r._repr_markdown_() == r.markdown()
    assert bool(r) and r.correct
    n = angles_demo(None)
    assert not n and n.points == 0 and n.status == "missing" and "No answer yet" in n.markdown()
    with pytest.raises(ValueError, match="status"):
        Result(True, "x", status="wrong")
    with pytest.raises(AssertionError, match="Not yet"):
        angles_demo([1, 2, 3]).require()


@pytest.mark.parametrize(
    "bad",
    [
        Result(True, "ok", max_points=2.0).__class__(False, "a\n\nb"),
        Result(False, "the gap is 2.88e-16"),
        Result(False, "one\ntwo", status="malformed"),
    ],
    ids=["two paragraphs", "raw e-notation", "malformed on two lines"],
)
def test_the_harness_catches_a_bad_verdict(bad):
    assert problems(bad)


def test_the_harness_catches_a_wrong_expectation():
    with pytest.raises(AssertionError, match="passed=True, expected False"):
        verify(angles_demo, wrong_case("claimed wrong", BETA))
    with pytest.raises(AssertionError, match="must not"):
        verify(angles_demo, right_case("leak", BETA, never_says="120"))
    with pytest.raises(AssertionError, match="does not say"):
        verify(angles_demo, right_case("words", BETA, says="isotropic"))


# ------------------------------------------------------------------ the parts
def test_tolerances_accept_what_they_state():
    t = sig_figs(3)
    assert t.statement == "to 3 significant figures"
    assert t.accepts(0.5033, 0.50332) and t.accepts(0.503, 0.50332) and not t.accepts(0.50, 0.50332)
    assert t.accepts(rounded(1.2098e4, t), 1.2098e4) and not t.accepts(1.0e4, 1.2098e4)
    assert t.accepts(float(t.show(0.50332)), 0.50332)
    d = decimals(4, "radians")
    assert d.statement == "to 4 decimal places of radians"
    assert d.accepts(0.7854, np.pi / 4) and not d.accepts(0.785, np.pi / 4)
    w = within("within 1 mm", abs=1e-3)
    assert w.accepts(0.3609, 0.3606) and not w.accepts(0.362, 0.3606)
    # units do not matter for a relative tolerance
    assert t.accepts(503.3, 503.32) == t.accepts(0.5033, 0.50332)
    for bad in (0, -1, 2.5, True):
        with pytest.raises(ValueError, match="n must be"):
            sig_figs(bad)


def test_unit_hints_say_only_what_is_true():
    assert "degrees?" in unit_hint([30, 150, 270], "rad")
    assert "np.degrees" in unit_hint([0.5, 2.6, 4.7], "deg")
    assert unit_hint([30, 150, 270], "deg") == "" and unit_hint([0.5, 1.0], "rad") == ""
    assert unit_hint([0, 90, 180], "deg") == ""  # whole numbers at most 2 pi are plausible degrees


def test_symbols_are_mapped_by_name_ignoring_assumptions():
    r, thd = sp.symbols("r thetadot_i")
    assert r != S.r and map_symbols(r * thd, [S.r, S.theta_dot_i]) == S.r * S.theta_dot_i
    assert spelling(r"\dot{\phi}_i") == spelling("phi_dot_i") == spelling("phidot_i")
    with pytest.raises(answers.AnswerError, match="does not have"):
        map_symbols(sp.Symbol("q"), [S.r])
    assert equivalent(sp.sin(S.r) ** 2 + sp.cos(S.r) ** 2, sp.Integer(1)) is True
    assert equivalent(S.r, S.d) is False


def test_answer_readers_give_one_line():
    assert answers.vector(sp.Matrix([[1, 2, 3]]), 3, "x").tolist() == [1, 2, 3]
    for value, n in [([1, 2], 3), ("1 2 3", 3), ([1, float("inf"), 2], 3), ([S.r, 1, 2], 3)]:
        with pytest.raises(answers.AnswerError) as e:
            answers.vector(value, n, "three numbers")
        assert "\n" not in str(e.value) and str(e.value).startswith("Expected three numbers")


# ------------------------------------------------------------------ every exercise of the edition
EXERCISES = list(registered().values())


def test_exercise_numbers_and_names_are_unique():
    names = [e.name for e in EXERCISES]
    assert len(names) == len(set(names))
    for e in EXERCISES:
        assert by_name(e.name) is e and e.points > 0


@pytest.mark.parametrize("ex", EXERCISES, ids=lambda e: e.number)
def test_every_exercise_survives_missing_and_junk_answers(ex):
    import inspect

    n = len([p for p in inspect.signature(ex.check).parameters.values() if p.default is inspect.Parameter.empty])
    verify(ex.check, missing_case("None", *([None] * n)))
    for case in junk_cases(n):
        verify(ex.check, case)
    assert len(JUNK) >= 10
