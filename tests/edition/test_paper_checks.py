"""edition.checks: verdicts follow the transcription -- a corrected transcription re-grades its row to ok,
a broken one of a true equation stops the chapter -- and the claims record their own evidence."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
import sympy as sp

from edition import symbols as S
from edition.checks import assembly, centred, dual, isotropy, steering, wheels
from edition.derivations import derived
from edition.ledger import Ledger, grade
from edition.transcription import printed, table


@pytest.fixture
def transcribe(monkeypatch):
    """Replace the SymPy form of a printed equation for one test (as an edit of its line in the table would)."""
    equations = table().equations

    def set_(id, expr=None, **extra):
        old = equations[str(id)]
        new = dataclasses.replace(old, expr=old.expr if expr is None else expr, extra={**old.extra, **extra})
        monkeypatch.setitem(equations, str(id), new)
        return new

    return set_


def ch3_j2_product():
    d = derived("03_kinetostatic_isotropy")
    return isotropy.J2_product(d["JJ"], d["ptilde"], d["ptilde2"])


def ch3_placement(n):
    d = derived("03_kinetostatic_isotropy")
    return isotropy.placement(d["pts"], d["G_ce"], d["L2"], n=n)


def verdicts(derivation):
    return {f.id: grade(f) for f in derivation.findings}


def det_J_paper():
    """det J of the paper's centred-wheel robot (symbolic L, r): what Chapter 4 derives and hands to its checks."""
    import wmr

    return wmr.paper_robot("centred", L=S.L, r=S.r, exact=True).J(L=S.L).det()


# ----------------------------------------------------------------------------------------------- re-grading
def test_a_corrected_transcription_regrades_typo_42_to_ok(transcribe):
    assert verdicts(ch3_j2_product())["42"] == "typo"
    transcribe(42, sp.Eq(S.ptilde2, sp.diag(S.d**2, S.r**2), evaluate=False))
    assert verdicts(ch3_j2_product())["42"] == "ok"


def test_a_corrected_transcription_regrades_wrong_15_to_ok(transcribe):
    transcribe(15, sp.Eq(S.beta_dot_i, -S.r / (2 * S.b) * (S.theta_dot_i1 - S.theta_dot_i2) - S.psi_dot))
    d = derived("01_platform_and_wheels")
    assert verdicts(wheels.dual_steering(d["phi_dot"], d["rigid"], d["i_i"], n=20))["15"] == "ok"


def test_a_corrected_transcription_regrades_59_to_ok(transcribe):
    p = printed(59)
    transcribe(59, sp.Eq(p.expr.lhs, S.r**3 * p.expr.rhs))
    assert verdicts(centred.printed_determinant(det_J_paper(), n=20))["59"] == "ok"


def test_a_corrected_transcription_regrades_60_to_ok(transcribe):
    p = printed(60)
    transcribe(60, sp.Eq(p.expr.lhs, sp.atan2(S.Y_dot, S.X_dot) + sp.pi / 2))
    with pytest.raises(AssertionError):  # the evidence that the printed angles slip no longer holds
        steering.translation(
            S.X_dot * sp.cos(S.phi_i) + S.Y_dot * sp.sin(S.phi_i), sp.atan2(S.Y_dot, S.X_dot) + sp.pi / 2, n=50
        )


@pytest.mark.parametrize(
    "id, expr, check",
    [
        (
            63,
            lambda p: -p.expr,
            lambda: steering.instant_centre(sp.Matrix([-S.y_dot, S.x_dot]) / S.psi_dot, S.psi_dot**2, n=20),
        ),
        (
            6,
            lambda p: sp.Eq(p.expr.lhs, -p.expr.rhs, evaluate=False),
            lambda: wheels.rolling_disk(*(derived("01_platform_and_wheels")[x] for x in ("h_dot", "i_i", "j_i"))),
        ),
        (38, None, None),
    ],
)
def test_a_broken_transcription_of_a_true_equation_fails_loudly(transcribe, id, expr, check):
    if id == 38:  # (38) is judged wrong: transcribing the corrected condition re-grades it
        mean = sum((sp.Matrix(p).T * sp.Matrix(p))[0] for p in S.D) / 3
        assert verdicts(ch3_placement(10))["38"] == "wrong"
        transcribe(38, (sp.Eq(mean, S.L**2),))
        assert verdicts(ch3_placement(10))["38"] == "ok"
        return
    transcribe(id, expr(printed(id)))
    derivation = check()
    row = next(f for f in derivation.findings if f.id == str(id))
    assert row.printed_holds is False
    with pytest.raises(ValueError, match=rf"\({id}\): the printed form is refuted"):
        Ledger("nb").add(row)


def test_every_row_names_what_it_proved():
    ch1 = derived("01_platform_and_wheels")
    ch2 = derived("02_offset_wheels_and_mobility")
    matrices = assembly.functional_matrix(*(ch2[x] for x in "F q_dot J1 J2".split()))
    for d in (wheels.platform_point(ch1["p_dot"], n=10), matrices, ch3_j2_product()):
        for f in d.findings:
            assert f.check.startswith("printed form proven" if f.printed_holds else "printed form refuted")


def test_equation_1_is_judged_from_the_chapters_body_axes(transcribe):
    ch1 = derived("01_platform_and_wheels")
    d = wheels.centre_velocity(ch1["i_B"], ch1["j_B"], n=10)
    assert verdicts(d) == {"1": "ok"} and d["1"].check.startswith("printed form proven")
    # read with the body axes turned the other way, the printed identity is refuted: the verdict is computed
    c, s = sp.cos(S.psi), sp.sin(S.psi)
    transcribe(1, sp.Eq(sp.Matrix([[c, s], [-s, c]]) * S.c_dot, sp.Matrix([S.X_dot, S.Y_dot]), evaluate=False))
    assert wheels.centre_velocity(ch1["i_B"], ch1["j_B"], n=10)["1"].printed_holds is False


# ----------------------------------------------------------------------------------------------- claims
def test_drift_fails_on_whenever_and_records_rows_28_29():
    ch2 = derived("02_offset_wheels_and_mobility")
    c = assembly.drift_of_c(ch2["c_dot"], n=5)
    p = assembly.drift_of_psi(ch2["a"], ch2["b"], ch2["c"], ch2["J1"], n=5)
    locked = assembly.locked_steering(ch2["det_M"], ch2["plucker"], robots=5, per=2)
    f = assembly.drift(c["28"], p["29"], locked, ch2["J2"], per=50)["drift"]
    assert grade(f) == "wrong" and f.residual == max(c["28"].residual, p["29"].residual)
    # the label says how far the verdict reaches: the implication holds, its presupposition fails
    assert f.scope.startswith("presupposition fails: the implication holds") and "rows (28)" not in f.convention
    # (28) is ok only under sum d_i = 0, which the paper states later, at (37): found in the transcription
    assert grade(c["28"]) == "ok" and c["28"].scope.startswith("special case") and "(37), after (28)" in c["28"].scope
    assert r"\det\mathbf M" in f.check and r"\det\mathbf J_2 = d^3r^3" in f.note


def test_robust_control_bound_sqrt2_where_the_robot_moves():
    d = isotropy.robust_control(n=2000)
    assert d.identity and d.kappa_about_C == sp.sqrt(2)
    assert np.sqrt(2) - 1e-9 <= d.kappa_mobile_min < 1.6 and d.translations_infinite
    assert d.example["rank_F"] == 6 and abs(d.example["kappa"] - 1) < 1e-9
    f = d["robust-centred"]
    assert grade(f) == "wrong" and r"\sqrt2" in f.corrected and "rank" in f.note
    assert grade(d["robust-offset"]) == "ok" and abs(d.offset_kappa_max - 1) < 1e-9, "offset wheels, d = r: kappa 1"


def test_isotropy_d_zero_records_its_own_simulation():
    ch3 = derived("03_kinetostatic_isotropy")
    iso = isotropy.J2_isotropy(ch3["U1"], ch3["frob2"], ch3["d_sol"], ch3["J2"], pairs=3, n=50)
    d = isotropy.dead_zone_of_isotropy(iso)
    f = d["isotropy-d-zero"]
    assert grade(f) == "ok" and "simulated full steering turn" in f.check
    assert abs(d.radius_min - 0.1) < 1e-6 and abs(d.radius_max - 0.1) < 1e-6 and d.d == 0.1
    assert d.radius_error == pytest.approx(max(d.radius_max - 0.1, 0.1 - d.radius_min), abs=1e-15)


def test_omnidirectional_records_corner_and_curved_translation():
    curve = dual.curved_translation(t_end=1.0)
    assert curve["miss"] < 1e-9 and curve["psi"] < 1e-12 and abs(curve["turned"] - 0.5) < 0.05
    f = dual.omnidirectional(n=50)["omnidirectional"]
    assert grade(f) == "wrong" and "must stop only" in f.corrected and "curvilinear translation" in f.check


def test_discontinuous_heading_records_its_own_jumps():
    d = dual.discontinuous_heading(n=100)
    assert [r["executable"] for r in d.rows] == [0.0, 1.0, 1.0, 1.0]
    f = d["discontinuous-heading"]
    # mobility 2 tested: the differential drive with C ahead of its axle turns C's heading at once, so the claim
    # as stated for every mobility below 3 fails, and what is true (mobility 1 and 3 as the paper says) is proven
    assert d.tested == [1, 2, 3] and grade(f) == "wrong" and f.corrected_holds
    assert "differential drive" in f.check and "random jumps" in f.check and f.overturn


def test_singular_list_finds_the_half_turned_family():
    d = centred.singular_list(det_J_paper(), n=100, n_family=40, n_item=10)
    assert d.classes[centred.LINE_CLASSES[1]] > 0 and d.classes[centred.LINE_CLASSES[4]] == 0
    assert d.control[centred.LINE_CLASSES[4]] == 100 and np.isinf(d.missed["kappa"])
    assert grade(d["singular-list-complete"]) == "typo"


def test_classify_lines_by_plain_geometry():
    pts = wmr_paper_points()
    assert centred.classify_lines(np.radians([20, 20, 20]), pts) == centred.LINE_CLASSES[0]
    assert centred.classify_lines(np.radians([20, 200, 20]), pts) == centred.LINE_CLASSES[1]
    assert centred.classify_lines(np.radians([20, 30, 40]), pts) == centred.LINE_CLASSES[4]


def wmr_paper_points():
    import wmr

    return wmr.paper_robot("centred", L=1.0, r=1.0).mount_points


def test_a_derivation_that_is_not_the_models_is_refused():
    """The chapters hand their derived objects to the checks: a wrong one stops the check instead of being graded."""
    from edition.checks import CheckError

    with pytest.raises(CheckError, match="determinant of the paper's J"):
        centred.printed_determinant(2 * det_J_paper(), n=5)
    with pytest.raises(CheckError, match="velocity vanishes"):
        steering.instant_centre(sp.Matrix([S.y_dot, S.x_dot]) / S.psi_dot, S.psi_dot**2, n=5)
