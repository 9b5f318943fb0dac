"""The design study: worst-case kappa(J) of a layout, the search over offset-wheel designs, kappa along motions."""

from __future__ import annotations

import numpy as np
import pytest

import wmr
from edition import design_study as study
from wmr.analysis import design as D
from wmr.analysis import motion_kappa as MK
from wmr.analysis.sweep import Grid


@pytest.fixture(scope="module")
def free():
    return D.search(n=300, starts=2, seed=0)


@pytest.fixture(scope="module")
def half():
    return D.search(ratio=0.5, n=300, starts=2, seed=1)


# ------------------------------------------------------------------------------------------ worst case
@pytest.mark.parametrize("ratio", [0.25, 0.5, 1.0, 2.0])
def test_equilateral_worst_case_is_kappa_J2(ratio):
    """C at the centroid, L the RMS distance: kappa(J) <= kappa(J2) = max(d/r, r/d), attained in translation."""
    bot = wmr.paper_robot("offset", L=0.3, r=0.05, d=0.05 * ratio)
    res = D.worst_kappa(bot)
    assert res.kappa == pytest.approx(max(ratio, 1 / ratio), rel=1e-9)
    L = wmr.characteristic_length(bot)
    assert float(wmr.condition_number(bot.J(res.beta, L=L))) == pytest.approx(res.kappa, rel=1e-12)
    assert res.grid_kappa <= res.kappa and res.count == D.FINE_STEPS**3


def test_worst_case_agrees_with_a_dense_random_sample():
    """The refined worst case is at least the largest of 20000 random configurations (and not far above it)."""
    x = D.WheelDesign(np.array([(-1.0, 0.0), (0.3, 1.1), (0.6, -0.7)]), 0.6, 1.0)
    bot = x.robot()
    res = D.worst_kappa(bot)
    beta = np.random.default_rng(3).uniform(0, 2 * np.pi, (20000, 3))
    sampled = wmr.condition_number(bot.J(beta, L=wmr.characteristic_length(bot))).max()
    assert sampled <= res.kappa * (1 + 1e-9) and res.kappa <= sampled * 1.02


def test_worst_case_bound_by_the_factors():
    """kappa(J) <= kappa(J_L1) kappa(J2) (J2 square and invertible) for an off-centre placement."""
    x = D.WheelDesign(np.array([(-1.0, 0.0), (0.2, 1.2), (0.5, -0.9)]), 0.5, 1.0)
    bot = x.robot()
    L = wmr.characteristic_length(bot)
    bound = float(wmr.condition_number(bot.J1(L))) * 2.0
    res = D.worst_kappa(bot)
    assert 2.0 < res.kappa <= bound * (1 + 1e-9)


def test_unit_invariance():
    """Every length times 1000 (or 1e-3): the same worst case, the same screening values."""
    x = D.WheelDesign(np.array([(-1.0, 0.0), (0.3, 1.1), (0.6, -0.7)]), 0.6, 1.0)
    k = D.worst_kappa(x.robot()).kappa
    for s in (1e3, 1e-3):
        assert D.worst_kappa(x.scaled(s).robot()).kappa == pytest.approx(k, rel=1e-9)
    beta = Grid(4, 0, np.pi).configurations(3, 0, 64)
    a, b = D.worst_kappa_designs([x, x.scaled(1e3)], beta)
    assert a == pytest.approx(b, rel=1e-9)


def test_screening_kernel_matches_worst_kappa_on_the_same_grid():
    designs = [D.equilateral_design(0.5), D.WheelDesign(np.array([(-1.0, 0.0), (0.2, 1.2), (0.5, -0.9)]), 1.3)]
    beta = Grid(6, 0, np.pi).configurations(3, 0, 216)
    got = D.worst_kappa_designs(designs, beta)
    want = [D.worst_kappa(x.robot(), angles=beta, refine=False).kappa for x in designs]
    assert got == pytest.approx(want, rel=1e-8)
    with pytest.raises(ValueError, match="beta"):
        D.worst_kappa_designs(designs, np.zeros((0, 3)))
    with pytest.raises(TypeError, match="designs"):
        D.worst_kappa_designs([wmr.paper_robot("offset")], beta)  # type: ignore[list-item]


# ------------------------------------------------------------------------------------------ the search
def test_search_is_at_least_as_good_as_the_paper(free):
    assert free.best_kappa <= free.paper_kappa * (1 + free.rtol)
    assert free.best_kappa >= 1.0  # (31)
    assert free.best.ratio == pytest.approx(1.0, abs=1e-3)  # it finds d = r
    assert free.best.centroid_offset() < 1e-3  # and C at the centroid


def test_the_paper_design_is_optimal_computed(free):
    """kappa >= 1 (31) and the paper's worst case is 1: optimal; the search confirms it within rtol."""
    assert free.paper_kappa == pytest.approx(1.0, abs=1e-9)
    assert free.paper_optimal
    s = np.sort(free.best.sides())  # ... and not the only optimum
    assert s[-1] - s[0] > 0.1 * s[-1]


def test_with_the_offset_fixed_the_placement_does_not_matter_beyond_the_centroid(half):
    assert half.ratio_fixed and half.best.ratio == 0.5
    assert half.best_kappa == pytest.approx(2.0, rel=1e-3)
    assert half.reference_kappa == pytest.approx(2.0, rel=1e-9) and half.reference_optimal


def test_a_perturbed_design_is_worse():
    paper = D.equilateral_design(1.0)
    base = D.worst_kappa(paper.robot()).kappa
    moved = paper.mounts.copy()
    moved[1] += (0.05, 0.0)
    assert D.worst_kappa(D.WheelDesign(moved, 1.0).robot()).kappa > base + 1e-3
    assert D.worst_kappa(D.equilateral_design(1.05).robot()).kappa > base + 1e-3


def test_search_checks_its_arguments():
    with pytest.raises(ValueError, match="ratio"):
        D.search(ratio=-1.0)
    with pytest.raises(ValueError, match="n"):
        D.search(n=1, starts=2)
    with pytest.raises(ValueError, match="mounts"):
        D.WheelDesign(np.zeros((3, 3)), 1.0)
    with pytest.raises(ValueError, match="offset"):
        D.WheelDesign(np.zeros((3, 2)), -1.0)


def test_landscape_data():
    land = D.landscape(n=9, m=9)
    assert land.kappa_paper == pytest.approx(np.maximum(land.ratios, 1 / land.ratios), rel=1e-9)
    assert np.all(land.kappa_moved > land.kappa_paper)
    assert land.kappa_map.shape == (9, 9) and land.kappa_map.min() >= 1.0


# ------------------------------------------------------------------------------------ along the motions
def test_kappa_along_motions_of_a_rectangle():
    bot = study.swerve(0.6, 0.4, r=0.05)
    circle = MK.mount_circle(bot)
    assert circle is not None
    c, R = circle
    assert np.allclose(c, 0) and R == pytest.approx(np.hypot(0.3, 0.2))
    ang = np.radians(np.arange(10.0, 360.0, 30.0))
    on = MK.motion_kappa(bot, MK.rotation_twists(R * np.stack([np.cos(ang), np.sin(ang)], -1)))
    off = MK.motion_kappa(bot, MK.rotation_twists(0.9 * R * np.stack([np.cos(ang), np.sin(ang)], -1)))
    assert np.isinf(on).all() and np.isfinite(off).all()
    assert np.isinf(MK.motion_kappa(bot, [0.0, 0.3, -0.2]))  # translation
    assert float(MK.motion_kappa(bot, [1.0, 0.0, 0.0])) >= np.sqrt(2) - 1e-12


def test_a_kite_is_singular_only_in_translation():
    kite = wmr.Robot([wmr.CentredWheel(p, r=0.05) for p in [(0.4, 0.0), (0.0, 0.2), (-0.3, 0.0), (0.0, -0.2)]])
    assert MK.mount_circle(kite) is None
    mm = MK.motion_map(kite, n=41)
    assert np.isfinite(mm.kappa).all() and np.isinf(mm.kappa_translation)
    assert mm.kappa_min >= np.sqrt(2) - 1e-12


def test_motion_kappa_is_unit_invariant():
    bot = study.swerve(0.6, 0.4)
    big = study.swerve(600.0, 400.0, r=50.0)
    U = np.array([[0.1, 0.05], [0.5, -0.3], [-0.2, 0.6]])
    assert MK.motion_kappa(bot, MK.rotation_twists(U)) == pytest.approx(
        MK.motion_kappa(big, MK.rotation_twists(U * 1000)), rel=1e-9
    )


# ------------------------------------------------------------------------------------------- exercises
def test_describe_design():
    assert "not concyclic" in study.describe_design(
        wmr.Robot([wmr.CentredWheel(p, r=0.05) for p in [(0.35, 0.2), (-0.3, 0.25), (-0.3, -0.25), (0.3, -0.2)]])
    )
    assert "worst-case" in study.describe_design(wmr.paper_robot("offset", L=0.3, r=0.05))


# ------------------------------------------------------------------------------------------ Figure E7
def test_figure_8_3_tells_every_strategy_apart():
    """plain and robot move alike here: the figure gives every run its own marker and names the coincident one."""
    import matplotlib

    matplotlib.use("Agg")
    from edition.transient_plot import coincident_runs, distinguished_transient_figure
    from wmr.swerve import direction_change, resteer_study

    tr = resteer_study(study.swerve(0.6, 0.4, r=0.05), direction_change(spin=0.5, dt=0.05), steer_rate=2 * np.pi)
    labels = [run.label for run in tr.runs]
    same = coincident_runs(tr)
    assert same[labels.index("robot")] == "plain" and same[labels.index("module")] is None
    assert same.count(None) == len(labels) - 1
    fig = distinguished_transient_figure(tr)
    for ax in fig.axes:
        markers = [ln.get_marker() for ln in ax.get_lines() if ln.get_label() != "commanded"]
        assert len(markers) == len(labels) and len(set(markers)) == len(labels)
    legend = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "robot (same motion as plain)" in legend and "plain" in legend
