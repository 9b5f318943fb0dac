"""wmr.analysis.overview: the numbers `wmr analyze` reports, checked against the library and the paper."""

import numpy as np
import pytest

import wmr
from wmr.analysis.advice import Suggestion
from wmr.analysis.linalg import rank
from wmr.analysis.overview import configurations, overview, singular_families
from wmr.analysis.sweep import Grid
from wmr.analysis.unit_design import dead_zone_radius

EXAMPLES = __import__("pathlib").Path(__file__).resolve().parent.parent / "examples"


def test_configurations_hold_the_grid_and_the_motion_configurations():
    bot = wmr.paper_robot("centred")
    beta = configurations(bot, grid=1000, twists=50)
    assert beta.shape == (1000 + 4 + 3 + 50, 3)
    assert np.array_equal(beta[:1000], Grid(10).configurations(3, 0, 1000))
    # every motion configuration admits its twist: rank F drops to 5 there
    assert (wmr.rank_F(bot, beta[1000:]) == 5).all()


def test_configurations_have_at_least_four_values_per_angle():
    bot = wmr.paper_robot("offset", d=0.5)
    assert configurations(bot, grid=16, twists=0).shape == (4**3 + 4 + 3, 3)


def test_configurations_grid_only_the_steered_angles():
    bot = wmr.load(EXAMPLES / "tricycle.toml")
    beta = configurations(bot, grid=100, twists=0)
    assert beta.shape == (100 + 4 + 3, 3) and np.array_equal(beta[:100, 1:], np.zeros((100, 2)))
    assert np.unique(beta[:100, 0]).size == 100


def test_characteristic_length_minimises_kappa_JL1_anywhere():
    """The module's claim: L^2 = mean |d_i|^2 minimises kappa(J_L1) even with C off the centroid."""
    bot = wmr.paper_robot("centred", L=0.4).moved(origin=(0.1, -0.05))
    L = wmr.characteristic_length(bot)

    def k(s):
        return float(wmr.condition_number(bot.J1(L=L * s)))

    assert k(1.0) < min(k(0.99), k(1.01)) and k(1.0) > 1.0001
    d = bot.mount_points
    c = np.linalg.norm(d.sum(0)) * np.sqrt(3 / (d**2).sum())
    assert np.isclose(k(1.0), np.sqrt((3 + c) / (3 - c)), rtol=1e-12)
    o = overview(bot, grid=200, twists=20)
    assert not o.isotropic["J_L1"] and o.advice[0].suggestion is Suggestion.MOVE_C


@pytest.mark.parametrize("scale", [1.0, 1e-3, 1e4])
def test_paper_robots(scale):
    c = overview(wmr.paper_robot("centred", L=0.3 * scale, r=0.05 * scale), grid=3000, twists=200)
    assert (c.rank_F, c.nullity, c.rank_F_range, c.nullity_range) == (6, 0, (5, 6), (0, 1))
    assert np.isclose(c.L, 0.3 * scale) and np.isclose(c.kappa_JL1, 1) and c.kappa_J2 == 1.0
    assert c.kappa_J["max"] == np.inf and 1 <= c.kappa_J["min"] < 1.5 and c.dead_zone is None and not c.advice
    assert {"i", "i'", "v-C", "v-P", "v"} <= {f["family"] for f in c.singular}
    o = overview(wmr.paper_robot("offset", L=0.3 * scale, r=0.05 * scale), grid=3000, twists=200)
    assert (o.rank_F, o.nullity, o.rank_F_range) == (6, 3, (6, 6)) and o.singular == []
    assert np.allclose([o.kappa_J[k] for k in ("min", "median", "p95", "max")], 1.0)
    assert o.dead_zone is not None and np.isclose(o.dead_zone, 0.05 * scale)
    d = overview(wmr.paper_robot("dual", L=0.3 * scale, r=0.05 * scale), grid=3000, twists=200)
    assert (
        (d.rank_F, d.nullity_range) == (6, (3, 4))
        and d.kappa_J2 == np.inf
        and d.advice[0].suggestion is Suggestion.SINGULAR
    )


def test_offset_not_equal_radius_is_advised():
    o = overview(wmr.paper_robot("offset", r=0.1, d=0.03), grid=100, twists=10)
    assert np.isclose(o.kappa_J2, 0.1 / 0.03) and not o.isotropic["J2"] and o.advised == [True]
    tip = o.advice[0]
    assert tip.suggestion is Suggestion.CHANGE_UNITS and tip.units == (0, 1, 2) and tip.after["kappa_J2"] == 1.0
    assert {c.kind.name for c in tip.changes} == {"OFFSET_EQUALS_RADIUS"} and tip.changes[0].unit.d == 0.1


def test_dead_zone_needs_equal_offsets():
    """(The radius agrees with the edition's simulation of the dead zone: tests/edition/test_dead_zone.py.)"""
    mixed = wmr.Robot([wmr.OffsetWheel(p, r=0.1, d=d) for p, d in zip(wmr.equilateral_mounts(0.4), (0.04, 0.05, 0.04))])
    assert dead_zone_radius(mixed) is None
    assert dead_zone_radius(wmr.paper_robot("offset", r=0.1, d=0.03)) == 0.03
    assert dead_zone_radius(wmr.paper_robot("centred")) is None


def test_singular_families_are_singular_and_the_others_are_not():
    bot = wmr.load(EXAMPLES / "swerve4.toml")
    fams = singular_families(bot)
    assert [f["family"] for f in fams] == ["parallel", "through-C", "through-P", "through-point"]
    L = wmr.characteristic_length(bot)
    beta = np.array([f["beta"] for f in fams])
    assert (rank(bot.J(beta, L=L)) == 2).all()
    assert (rank(bot.J(beta + [0.0, 0.0, 0.0, 0.3], L=L)) == 3).all()  # wheel 4 turned: regular again
    assert singular_families(wmr.paper_robot("offset", d=0.2)) == []


def test_bad_arguments():
    with pytest.raises(TypeError, match="robot"):
        overview("robot")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="grid"):
        configurations(wmr.paper_robot(), grid=0)
    with pytest.raises(ValueError, match="L"):
        singular_families(wmr.paper_robot(), L=-1.0)


def test_fixed_wheels_keep_their_angles_and_meet_only_at_infinity():
    bot = wmr.load(EXAMPLES / "tricycle.toml")
    fams = singular_families(bot)
    assert [f["family"] for f in fams] == ["parallel"]  # the rear planes never meet
    assert np.allclose(np.degrees(fams[0]["beta"])[1:], 90.0) and np.isclose(abs(np.degrees(fams[0]["beta"][0])), 90.0)
    o = overview(wmr.load(EXAMPLES / "differential.toml"), grid=100, twists=10)
    assert (o.rank_F, o.nullity_range) == (5, (2, 2)) and o.singular == [] and not o.isotropic["J_L1"]
    m = overview(wmr.load(EXAMPLES / "mecanum4.toml"), grid=100, twists=10)
    assert (
        np.isclose(m.kappa_J2, 1 + np.sqrt(2)) and m.advice[0].changes[0].kind.name == "OMNI_ROLLERS"
    )  # sqrt((1 + c) / (1 - c))
    assert overview(wmr.load(EXAMPLES / "omni3.toml"), grid=100, twists=10).isotropic == {"J_L1": True, "J2": True}


def test_many_steered_units_get_a_sample_not_a_huge_grid():
    ring = [(np.cos(a), np.sin(a)) for a in np.linspace(0, 2 * np.pi, 12, endpoint=False)]
    bot = wmr.Robot([wmr.CentredWheel(p, r=0.1) for p in ring])  # 4 ** 12 = 1.7e7 grid points
    beta = configurations(bot, grid=500, twists=10)
    assert beta.shape == (500 + 4 + 12 + 10, 12)
    o = overview(bot, grid=500, twists=10)
    assert (o.rank_F, o.rank_F_range) == (12 + 3, (12 + 2, 12 + 3))  # generic rank F = w + 3
