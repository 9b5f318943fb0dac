"""Singular configurations of the three-centred-wheel robot (wmr.analysis.singularities).

The checks are tied to the model (Robot.J) and to the paper's statements; the mutant tests show
that they fail when the model is wrong (a flipped rotation or a flipped sign in J2).
"""

import dataclasses

import numpy as np
import pytest
import sympy as sp

import edition.symbols
import wmr
from edition import families as catalogue
from edition.verify import symbolic_equal
from wmr.analysis import lines as ln
from wmr.analysis import singularities as sg
from wmr.model.platform import rotation
from wmr.model.tolerance import TOL
from wmr.model.wheels import CentredWheel

DEG = np.pi / 180


@pytest.fixture(scope="module")
def bot():
    return wmr.paper_robot("centred", L=1.0, r=0.25)


@pytest.fixture(scope="module")
def fams():
    return {f.key: f for f in catalogue.families()}


def printed_59():
    """The printed (59) (from edition when transcribed there, else as printed in the paper)."""
    b1, b2, b3 = sp.symbols("beta1:4", real=True)
    try:
        from edition import printed

        e = printed("59").expr
        if isinstance(e, sp.Equality):
            e = e.rhs
        if e is not None:
            return e
    except (ValueError, ImportError):
        pass
    s3 = sp.sqrt(3)
    return (
        -s3 / 2 * sp.cos(b1 - b2 - b3)
        + sp.Rational(3, 4) * sp.sin(b1 - b2 + b3)
        - sp.Rational(3, 4) * sp.sin(b1 + b2 - b3)
        + s3 / 4 * sp.cos(b1 + b2 - b3)
        + s3 / 4 * sp.cos(b1 - b2 + b3)
    )


# ----------------------------------------------------------------------------- exact statements
def test_printed_list_holds_for_every_free_angle():
    res = catalogue.check_paper_items()
    assert res == {k: True for k in res}
    assert set(res) == {"(i)", "(ii) 60", "(ii) -120", "(iii) -60", "(iii) 120", "(iv) 0", "(iv) 180", "(v)"}


def test_characterisation_is_exact():
    S = edition.symbols
    ch = sg.characterisation(wmr.paper_robot("centred", L=S.L, r=S.r, exact=True), L=S.L)
    assert ch["identity_general"]  # det J = -(r1 r2 r3 / L) det W for any three mount points
    assert ch["identity_robot"]
    assert ch["independent_of_L"]
    assert ch["irreducible"]


def test_det_J_is_r_cubed_times_printed_59():
    S = edition.symbols
    det = sg.det_J_symbolic(wmr.paper_robot("centred", L=S.L, r=S.r, exact=True), L=S.L)
    assert symbolic_equal(det, S.r**3 * printed_59())


def test_det_J_numeric_matches_symbolic(bot):
    rng = np.random.default_rng(7)
    beta = rng.uniform(-np.pi, np.pi, (50, 3))
    b = edition.symbols.beta
    f = sp.lambdify(b, 0.25**3 * printed_59(), "numpy")
    assert np.allclose(sg.det_J(bot, beta), f(*beta.T), atol=1e-14)
    assert sg.det_J(bot, beta.reshape(5, 10, 3)).shape == (5, 10)


# ----------------------------------------------------------------------------- geometry
def test_zero_set_is_concurrency_of_wheel_planes(bot, fams):
    rng = np.random.default_rng(11)
    for beta in rng.uniform(-np.pi, np.pi, (200, 3)):  # generic: regular, lines not concurrent
        assert not sg.is_singular(bot, beta)
        assert ln.concurrency_point(bot, beta).kind == ln.NONE
    for f in fams.values():  # every family: concurrent, singular
        for beta in f.samples[:: max(1, len(f.samples) // 40)]:
            assert sg.is_singular(bot, beta)
            assert ln.concurrency_point(bot, beta).kind != ln.NONE


def test_concurrency_point_is_where_the_planes_meet(bot):
    for D in ([0.0, 0.0], [0.7, -1.9], [-2.0, 3.0]):
        beta = ln.planes_through(bot, D)
        c = ln.concurrency_point(bot, beta)
        assert c.kind == ln.FINITE and np.allclose(c.point, D, atol=1e-9)
        assert sg.is_singular(bot, beta)


def test_axles_through_a_point_give_mobility_one(bot):
    U = np.array([0.4, 2.3])
    beta = ln.axles_through(bot, U)
    assert int(wmr.rank_F(bot, beta)) == 5
    assert np.allclose(ln.axles_concurrency(bot, beta).point, U, atol=1e-9)


def test_line_intersection_kinds():
    assert ln.line_intersection([0, 0], [1, 0], [0, 1], [1, 0])[0] == ln.PARALLEL
    assert ln.line_intersection([0, 0], [1, 0], [2, 0], [-1, 0])[0] == ln.COINCIDENT
    k, p = ln.line_intersection([0, 0], [1, 1], [2, 0], [0, 1])
    assert k == ln.FINITE and p is not None and np.allclose(p, [2, 2])


# ----------------------------------------------------------------------------- classification
def _cases(bot):
    P3 = bot.mount_points[2]
    vP = ln.planes_through(bot, P3)
    vP[2] = 17 * DEG
    U = np.array([np.cos(40 * DEG), np.sin(40 * DEG)])  # on the circle through the P_i (radius L)
    return {
        "i": [0.3, 0.3, 0.3],
        "i'": [0.3, 0.3 + np.pi, 0.3],
        # the paper's items (ii)-(iv), their half-turn variants
        "pair-13": np.array([60, 17, 60]) * DEG,
        "pair-13'": np.array([60, 17, -120]) * DEG,
        "pair-12": np.array([-60, -60, 17]) * DEG,
        "pair-12'": np.array([120, -60, 17]) * DEG,
        "pair-23": np.array([17, 0, 0]) * DEG,
        "pair-23'": np.array([17, 180, 0]) * DEG,
        "v-C": np.array([90, -30, 30]) * DEG,
        "v-P": vP,
        "v-circle": ln.axles_through(bot, U),
        "v": ln.planes_through(bot, [0.7, -1.9]),
        "regular": [0.1, 0.5, -0.7],
    }


def test_classify(bot):
    for fam, beta in _cases(bot).items():
        c = sg.classify(bot, np.asarray(beta, dtype=float))
        assert c.family == fam, (fam, c)
        assert c.singular == (fam != "regular")


def test_rank_F_of_the_families(bot):
    cases = _cases(bot)
    ranks = {k: int(wmr.rank_F(bot, np.asarray(v, dtype=float))) for k, v in cases.items()}
    assert ranks["i"] == ranks["i'"] == ranks["v-circle"] == 5  # singular J, yet the robot can move
    for k in ("pair-13", "pair-13'", "pair-12", "pair-23", "v-C", "v-P", "v", "regular"):
        assert ranks[k] == 6, k


def test_singular_motions(bot):
    for b1 in (20.0, 60.0, -75.0):
        beta, fam = sg.singular_motions(bot, b1 * DEG)
        assert np.all(np.abs(sg.det_J(bot, beta)) <= TOL)
        assert np.all(wmr.rank_F(bot, beta) == 5)
        assert set(fam) <= {"i", "i'", "v-circle"}


# ----------------------------------------------------------------------------- the table
def test_families_table(fams):
    assert set(fams) == {
        "i",
        "i'",
        "pair-13",
        "pair-13'",
        "pair-12",
        "pair-12'",
        "pair-23",
        "pair-23'",
        "v",
        "v-C",
        "v-P",
        "v-circle",
    }
    for f in fams.values():
        assert f.det_J_exact_zero is True, f.key
        assert f.det_J_max <= 1e-12, f.key
    missed = {k for k, f in fams.items() if f.listed_in_paper == "no"}
    assert missed == {"i'", "pair-13'", "pair-12'", "pair-23'", "v-circle"}
    assert fams["v-circle"].rank_F.startswith("5 (")
    assert fams["v-C"].rank_F.startswith("6 (")
    # the pair angles are computed from the geometry and agree with the paper's (ii)-(iv)
    assert "60^\\circ" in fams["pair-13"].configuration and "-120^\\circ" in fams["pair-13"].configuration
    assert "-60^\\circ" in fams["pair-12"].configuration and "120^\\circ" in fams["pair-12"].configuration
    assert "0^\\circ" in fams["pair-23"].configuration and "180^\\circ" in fams["pair-23"].configuration


def test_write_csv(tmp_path):
    import csv

    rows = catalogue.write_csv(tmp_path / "s.csv", n=12, exact=False)
    with open(tmp_path / "s.csv", newline="", encoding="utf-8") as f:
        back = list(csv.DictReader(f))
    assert [r["family"] for r in back] == [r["family"] for r in rows]
    assert list(back[0]) == list(catalogue.COLUMNS)


# ----------------------------------------------------------------------------- mutants
@dataclasses.dataclass(frozen=True)
class _MirroredWheel(CentredWheel):
    """A wrong model: the intermediate body turned by -beta instead of beta."""

    def block(self, beta, backend=None):
        from wmr.model.backend import choose

        bk = choose(beta, self.r, *self.position, backend=backend)
        return rotation(-beta, bk) @ self.local_block(bk)


@dataclasses.dataclass(frozen=True)
class _FlippedWheel(CentredWheel):
    """A wrong model: h_dot = +r theta_dot j (sign of J2 flipped)."""

    def local_block(self, backend=None):
        return backend.matrix([[0], [self.r]])


def _mutant(cls):
    return wmr.Robot([cls(u.position, r=u.r) for u in wmr.paper_robot("centred", exact=True).wheels])


def test_checks_fail_for_a_mirrored_model():
    res = catalogue.check_paper_items(_mutant(_MirroredWheel))
    assert res["(i)"]  # parallel planes stay singular under any model of this kind
    assert not all(res[k] for k in res if k.startswith(("(ii)", "(iii)", "(iv)")))


def test_checks_fail_for_a_flipped_J2():
    det = sg.det_J_symbolic(_mutant(_FlippedWheel), L=1)
    assert not symbolic_equal(det, printed_59())
