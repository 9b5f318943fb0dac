"""The figures: the numbers each one asserts, checked from the data functions (no rendering) against
independent computations, and the files: deterministic, atomic, no per-build data, no matplotlib in data paths."""

import dataclasses
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import wmr
from edition import figures as F
from edition.figures import common
from wmr.model.tolerance import TOL

from conftest import ROOT, axle, rolling_dir

DEG = np.pi / 180
P = wmr.paper_robot("centred", L=1.0, r=0.25).mount_points  # the paper's d_i, L = 1


@pytest.fixture(scope="module")
def data():
    """Each figure's data, computed once for the module."""
    cache = {}

    def get(key):
        if key not in cache:
            cache[key] = F.FIGURES[key].data()
        return cache[key]

    return get


# ----------------------------------------------------------------------------- independent geometry
def cross(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def line_det(points, dirs):
    """det of the homogeneous lines through ``points`` (..., 3, 2) along ``dirs``: 0 iff concurrent or all parallel."""
    n = np.stack([-dirs[..., 1], dirs[..., 0]], axis=-1)  # normals
    c = -np.sum(n * points, axis=-1)
    return np.linalg.det(np.concatenate([n, c[..., None]], axis=-1))


def planes_det(beta):
    """Wheel-plane lines (through P_i along j_i = k x i_i) of the paper's robot: 0 iff det J = 0."""
    return line_det(np.broadcast_to(P, np.shape(beta) + (2,)), rolling_dir(beta))


def axles_det(beta):
    """Axle lines (through P_i along i_i): 0 iff the axles are concurrent, i.e. rank F = 5."""
    return line_det(np.broadcast_to(P, np.shape(beta) + (2,)), axle(beta))


def J_first_principles(beta, r=0.25, L=1.0):
    """J of three centred wheels from no slip: column i = -r [d_i x j_i / L, j_i] (j_i = k x i_i)."""
    j = rolling_dir(beta)  # (..., 3, 2)
    top = cross(np.broadcast_to(P, j.shape), j) / L
    return -r * np.concatenate([top[..., None, :], np.swapaxes(j, -1, -2)], axis=-2)


# ----------------------------------------------------------------------------- every figure
@pytest.mark.parametrize("key", F.KEYS)
def test_every_figure_module_has_the_interface(key, data):
    mod = F.FIGURES[key]
    assert mod.TITLE and mod.__doc__ and mod.data.__doc__ and mod.draw.__doc__ and mod.caption.__doc__
    if key.startswith("fig"):  # the paper's number; this edition's own: E1, E2, ...
        assert mod.NUMBER == key[3:].lstrip("0")
    else:
        assert mod.NUMBER[:1] == "E" and mod.NUMBER[1:].isdigit()
    assert [F.FIGURES[k].NUMBER for k in F.KEYS].count(mod.NUMBER) == 1, "two figures with one number"
    assert bool(mod.PAPER_CAPTION) == mod.NUMBER.isdigit()
    d = data(key)
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(d, next(iter(d.__dataclass_fields__)), None)
    cap = mod.caption(d)
    assert cap.count("$") % 2 == 0, "unbalanced inline math"
    for ascii_math in ("!=", "<=", ">=", "<=>", "psi_dot", "^T", "e-1", "e-0"):
        assert ascii_math not in cap.replace("$", " "), ascii_math
    rec = F.output.record(key, mod, d)
    json.dumps(rec, allow_nan=False)  # valid JSON: no NaN, no inf


PAPER = Path("/work/shared/paper/leow-low-loh-2002-wmr-kinematics.md")


@pytest.mark.skipif(not PAPER.exists(), reason="the paper's text is not on this machine")
def test_paper_captions_are_transcribed_from_the_paper():
    def flat(t):
        return "".join(t.replace("**", "").replace("$", "").split())

    text = flat(PAPER.read_text(encoding="utf-8"))
    for key in F.KEYS[:7]:
        mod = F.FIGURES[key]
        assert flat(f"Figure {mod.NUMBER}. {mod.PAPER_CAPTION}") in text, key


# ----------------------------------------------------------------------------- Fig. 7
def test_fig07_dead_zone_is_a_circle_of_radius_d_about_C_f(data):
    d7 = data("fig07")
    omega, dt = 2 * np.pi / d7.T, d7.T / d7.steps
    assert d7.tolerance == pytest.approx(d7.d * (omega * dt) ** 4)
    assert d7.tolerance < 1e-5 * d7.d
    # C_f: the centroid of the contact points H_i = P_i - d j_i(beta0) (first principles: j = k x i)
    G = P - d7.d * rolling_dir(np.full(3, d7.beta0 * DEG))
    assert np.allclose(d7.C_f, G.mean(axis=0), atol=1e-12)
    assert np.allclose(d7.centre, d7.C_f, atol=d7.tolerance)
    assert d7.radius_error == abs(d7.radius - d7.d) <= d7.tolerance
    assert d7.centre_error <= d7.tolerance and d7.contact_drift <= d7.tolerance
    assert d7.psi_max <= TOL and d7.slip_max <= TOL
    # the whole path: fixed contact points with psi = 0 give c(t) = C_f + d j(beta_1(t))
    expected = np.asarray(d7.C_f) + d7.d * rolling_dir(d7.beta[:, 0])
    assert np.max(np.linalg.norm(d7.pose[:, 1:] - expected, axis=1)) <= d7.tolerance + 1e-6


# ----------------------------------------------------------------------------- Fig. 8
def test_fig08_translations_against_the_integrated_rolling_velocity(data):
    d8 = data("fig08")
    for run in (d8.rectilinear, d8.curvilinear):
        assert run.psi_max <= TOL and run.congruence_error <= TOL and run.slip_max <= TOL
        assert run.rank_F == (5,)
    assert d8.rectilinear.straightness <= TOL
    assert d8.rectilinear.distance == pytest.approx(d8.speed * d8.t_end, abs=1e-9)
    # no slip: c_dot = -r theta_dot j(beta(t)); integrate beta(t) = 90 deg + A sin(2 pi t / T) finely
    t = np.linspace(0.0, d8.t_end, 200_001)
    beta = (90 + d8.amplitude * np.sin(2 * np.pi * t / d8.t_end)) * DEG
    v = -d8.speed * rolling_dir(beta)
    c_end = np.trapezoid(v, t, axis=0)
    assert d8.curvilinear.distance == pytest.approx(np.linalg.norm(c_end), abs=1e-6)
    assert np.allclose(d8.curvilinear.pose[-1, 1:], c_end, atol=1e-6)
    assert np.allclose(d8.rectilinear.pose[-1, 1:], -d8.speed * d8.t_end * rolling_dir(d8.beta_rect * DEG), atol=1e-6)


# ----------------------------------------------------------------------------- Fig. 9
def test_fig09_axles_pass_through_the_IC_and_C_circles_it(data):
    d9 = data("fig09")
    for run in (d9.C, d9.U):
        b = np.radians(run.beta_deg)
        assert np.allclose(cross(axle(b), np.asarray(run.u_c) - P), 0, atol=1e-12)  # U on every axle
        assert abs(axles_det(b)) <= 1e-12
        assert run.rank_F == 5 and run.mobility == 1
        assert run.axles.kind == "finite" and run.axles.error <= 1e3 * TOL
        assert np.allclose(run.axles.point, run.u_c, atol=1e-12)
        assert run.slip_max <= TOL
        assert run.turn_deg == pytest.approx(d9.turn, abs=1e-9) and run.psi_rate == pytest.approx(1.0)
    assert d9.C.radius <= TOL
    assert d9.U.radius == pytest.approx(np.hypot(*d9.uc_U), abs=1e-7) == d9.U.radius_expected


# ----------------------------------------------------------------------------- Figs. 10-12
def test_fig10_parallel_planes(data):
    d10 = data("fig10")
    cfg, b = d10.config, np.full(3, d10.beta * DEG)
    assert cfg.det_J_exact == "0" and abs(cfg.det_J) <= TOL
    assert abs(np.linalg.det(J_first_principles(b))) <= 1e-15
    assert abs(planes_det(b)) <= 1e-12 and abs(axles_det(b)) <= 1e-12  # both sets parallel
    assert cfg.rank_F == 5 and cfg.mobility == 1 and not np.isfinite(cfg.kappa_J)
    assert (cfg.planes_meet, cfg.axles_meet, cfg.family) == ("at_infinity", "at_infinity", "i")
    # the one admissible twist: translation along the wheel planes
    assert np.allclose(d10.admissible, [0.0, *rolling_dir(d10.beta * DEG)], atol=1e-12) or np.allclose(
        d10.admissible, [0.0, *-rolling_dir(d10.beta * DEG)], atol=1e-12
    )

    # three wheels, three axle lines and three plane lines drawn: none hides another
    def gap(beta_deg):  # where each line crosses the perpendicular through C, axles and planes
        b = beta_deg * DEG
        P = d10.robot.mount_points
        return min(np.diff(np.sort(P @ u)).min() for u in (rolling_dir(b), axle(b)))

    assert d10.line_gap == pytest.approx(gap(d10.beta), abs=1e-12) and d10.line_gap > 0.25
    assert gap(30.0) < 1e-12 and F.FIGURES["fig10"].data(30.0).line_gap < 1e-12  # two axles on one line


def test_fig11_two_planes_on_a_side_of_the_mount_triangle(data):
    d11 = data("fig11")
    pairs = {"a": (1, 3), "b": (1, 2), "c": (2, 3)}  # the paper's (ii), (iii), (iv)
    for letter, cfg in d11.panels.items():
        i, j = pairs[letter]
        k = 6 - i - j
        b = np.radians(d11.configs[letter])
        jd = rolling_dir(b)
        side = P[j - 1] - P[i - 1]
        assert abs(cross(jd[i - 1], side)) <= 1e-12 and abs(cross(jd[j - 1], side)) <= 1e-12
        assert cfg.coincident == ((i, j),) and cfg.family == f"pair-{i}{j}"
        assert cfg.det_J_exact == "0" and abs(cfg.det_J) <= TOL and abs(planes_det(b)) <= 1e-12
        D = np.asarray(cfg.D_P)  # D_ik = D_jk: on the side and on plane k
        assert abs(cross(side, D - P[i - 1])) <= 1e-12 and abs(cross(jd[k - 1], D - P[k - 1])) <= 1e-12
        assert cfg.rank_F == 6 and cfg.mobility == 0 and abs(axles_det(b)) > 1e-3
        assert len(cfg.axle_crossings) == 2  # "the axles intersect at two different locations"


def test_fig12_three_planes_through_one_point(data):
    d12 = data("fig12")
    for letter, cfg in d12.panels.items():
        D = np.asarray(d12.targets[letter])
        b = np.radians(cfg.beta_deg)
        assert np.allclose(cross(rolling_dir(b), D - P), 0, atol=1e-12)  # every plane through D
        assert np.allclose(cfg.D_P, D, atol=1e-12) and d12.D_P_error[letter] <= 1e-12
        assert abs(cfg.det_J) <= TOL and cfg.rank_F == 6 and cfg.mobility == 0
        X = np.asarray(cfg.axle_crossings)
        assert len(X) == 3  # "the axles intersect at three different locations"
        on = np.abs(cross(axle(b)[None], X[:, None, :] - P[None]))  # (crossing, wheel)
        assert np.all(np.sum(on <= 1e-9, axis=1) == 2)
    assert d12.panels["a"].det_J_exact == "0" and d12.panels["a"].family == "v-C"
    assert d12.panels["a"].beta_deg == pytest.approx((90.0, -30.0, 30.0))


# ----------------------------------------------------------------------------- Fig. 13
def test_fig13_axles_meet_at_U_and_65_is_not_the_steering_angle(data):
    d13 = data("fig13")
    u_c, u_i = np.asarray(d13.u_c), np.asarray(d13.u_i)
    beta = np.radians(d13.beta_deg)
    assert np.allclose(u_c, [1.7, 1.1])
    assert np.allclose(u_i, u_c - P)  # (64)
    assert np.allclose(cross(axle(beta), u_i), 0, atol=1e-12)  # i_i || u_i
    cosines = u_i @ u_c / (np.linalg.norm(u_i, axis=1) * np.linalg.norm(u_c))
    assert np.allclose(d13.printed65_deg, np.degrees(np.arccos(cosines)))
    assert np.max(np.abs(np.asarray(d13.printed65_deg) - d13.beta_deg)) > 1.0
    assert d13.admissible and d13.slip <= TOL and d13.rank_F == 5 and d13.mobility == 1
    assert d13.axles.kind == "finite" and d13.axles.error <= 1e3 * TOL and np.allclose(d13.axles.point, u_c)


# ----------------------------------------------------------------------------- det J map
def test_detmap_against_J_from_first_principles(data):
    dm = data("detmap")
    g = -180.0 + (np.arange(dm.n) + 0.5) * 360.0 / dm.n
    B2, B3 = np.meshgrid(g, g, indexing="xy")
    for sl in dm.slices:
        beta = np.stack([np.full_like(B2, sl.beta1), B2, B3], axis=-1) * DEG
        J = J_first_principles(beta)
        D = np.linalg.det(J) / 0.25**3
        assert sl.det_min == pytest.approx(D.min(), abs=1e-12) and sl.det_max == pytest.approx(D.max(), abs=1e-12)
        assert np.allclose(sl.det, D, atol=1e-6)
        s = np.linalg.svd(J, compute_uv=False)
        assert sl.kappa_min == pytest.approx((s[..., 0] / s[..., -1]).min(), rel=1e-9)
        assert sl.kappa_min > 1.0 + 1e-3  # not isotropic on these slices
        m = np.radians([[sl.beta1, a, b] for a, b, _ in sl.singular_motions])
        assert len(m) == 8
        assert np.all(np.abs(planes_det(m)) <= 1e-12) and np.all(np.abs(axles_det(m)) <= 1e-12)
        assert sl.singular_motion_det_max <= TOL and sl.singular_motion_ranks == (5,)
        assert {f for _, _, f in sl.singular_motions} <= {"i", "i'", "v-circle"}
    vortex = np.radians(dm.vortex_beta_deg)
    s = np.linalg.svd(J_first_principles(vortex), compute_uv=False)
    assert s[0] / s[-1] == pytest.approx(1.0, abs=1e-12)
    assert abs(dm.kappa_vortex - 1) <= 1e3 * TOL and abs(dm.kappa_vortex_minus - 1) <= 1e3 * TOL


# ----------------------------------------------------------------------------- conventions
def test_conventions_from_first_principles(data):
    dc = data("conventions")
    b = dc.beta * DEG
    assert np.allclose(dc.i, axle(b)) and np.allclose(dc.j, rolling_dir(b))  # j = k x i
    assert np.allclose(dc.H_minus_P, -dc.d * rolling_dir(b))  # H_i = P_i - d j_i
    assert np.allclose(dc.dual_wheels, [dc.b * axle(b), -dc.b * axle(b)])  # wheel 1 at +b i_i
    angles = np.radians([180.0, 60.0, -60.0])  # the paper's numbering
    assert np.allclose(dc.mount_points, np.stack([np.cos(angles), np.sin(angles)], axis=1))
    cap = F.FIGURES["conventions"].caption(dc)
    assert r"\frac{\sqrt{3}}{2}" in cap and r"L\left(-1, 0\right)" in cap


# ----------------------------------------------------------------------------- helpers
def test_exact_det_J_matches_J_from_first_principles():
    for beta_deg in ([10, 20, 30], [0, 0, 90], [45, -60, 120]):
        exact = float(common.exact_det_J(beta_deg, r=0.25))
        assert exact == pytest.approx(np.linalg.det(J_first_principles(np.radians(beta_deg))), abs=1e-14)


def test_fit_circle_recovers_a_noisy_circle():
    t = np.random.default_rng(1).uniform(0, 2 * np.pi, 400)
    xy = np.stack([0.3 + 1.7 * np.cos(t), -2 + 1.7 * np.sin(t)], axis=1)
    c, R = common.fit_circle(xy + 1e-9 * np.random.default_rng(2).standard_normal(xy.shape))
    assert np.allclose(c, [0.3, -2], atol=1e-8) and R == pytest.approx(1.7, abs=1e-8)


def test_numbers_print_residuals_as_bounds_and_round_values():
    @dataclasses.dataclass(frozen=True)
    class D:
        x: float
        e: float = common.residual()
        s: float = common.small(default=4.93e-11)
        a: object = common.drawing(default=None)

    out = common.numbers(D(0.1 + 0.2, -3e-17, a=np.ones(3)))
    assert out == {"x": 0.3, "e": "< 1e-12", "s": 4.9e-11}


# ----------------------------------------------------------------------------- files
def test_save_is_deterministic_atomic_and_has_no_build_data(tmp_path, data):
    for key in ("fig10", "conventions"):
        d = data(key)
        a = F.save(key, d, tmp_path / "a")
        b = F.save(key, d, tmp_path / "b")
        assert sorted(p.name for p in a) == sorted(f"{key}.{x}" for x in ("svg", "pdf", "json"))
        for p, q in zip(a, b):
            blob = p.read_bytes()
            assert blob == q.read_bytes(), f"{p.name} differs between two saves"
            assert str(tmp_path).encode() not in blob and b"commit" not in blob.lower()
            assert b"CreationDate" not in blob and b"<dc:date>" not in blob
        rec = json.loads((tmp_path / "a" / f"{key}.json").read_text(encoding="utf-8"))
        assert list(rec) == ["key", "number", "title", "paper_caption", "caption", "numbers", "formats"]
        assert rec["caption"] == F.FIGURES[key].caption(d)
        assert rec["numbers"] == common.numbers(d)
    assert not list((tmp_path / "a").glob(".*"))  # no temporary files left behind


def test_no_figure_is_committed_as_a_raster():
    """Rasters anti-alias last-bit differences into different pixels: figures are SVG and PDF."""
    assert all(F.output.formats(F.FIGURES[k]) == ("svg", "pdf") for k in F.KEYS)
    tracked = subprocess.run(["git", "ls-files", "figures"], cwd=ROOT, capture_output=True, text=True, check=True)
    assert not [f for f in tracked.stdout.split() if f.endswith((".png", ".jpg", ".jpeg", ".gif", ".webp"))]


def test_write_all_and_the_command_line(tmp_path, capsys):
    F.write_all(tmp_path, keys=["conventions"], csv=False)
    F.write_all(tmp_path, keys=["fig13"], csv=False)
    caps = {k: json.loads((tmp_path / f"{k}.json").read_text(encoding="utf-8")) for k in ("fig13", "conventions")}
    assert caps["fig13"]["number"] == "13" and caps["conventions"]["number"] == "E1"
    assert caps["fig13"]["caption"] and not (tmp_path / "captions.json").exists()
    assert F.main([str(tmp_path), "nope"]) == 2
    assert F.main([]) == 2
    with pytest.raises(ValueError, match="key must be one of"):
        F.save("fig99", None, tmp_path)


def test_show_displays_saves_and_returns_the_data(tmp_path, data):
    pytest.importorskip("IPython")
    d = data("fig13")
    assert F.show("fig13", d, outdir=tmp_path) is d
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fig13.json", "fig13.pdf", "fig13.svg"]


def test_data_paths_do_not_import_matplotlib():
    code = (
        "import sys, edition.figures.fig08 as f; f.data(); "
        "import edition.figures as F; [F.FIGURES[k].data() for k in ('fig10', 'fig13', 'conventions')]; "
        "sys.exit('matplotlib' in sys.modules)"
    )
    assert subprocess.run([sys.executable, "-c", code]).returncode == 0


# ----------------------------------------------------------------------------- doctests of this stream's modules
@pytest.mark.parametrize(
    "module",
    [
        "edition.text",
        "edition.files",
        "edition.families",
        "edition.families.family",
        "edition.families.catalogue",
        "edition.families.coverage",
        "edition.families.counts",
        "edition.problems",
        "edition.report_cells",
        "edition.page_breaks",
        "edition.cards",
        "edition.ledger.verdict",
        "edition.figures",
        "edition.figures.common",
        "edition.figures.output",
        "wmr.plot.style",
        "wmr.plot.annotate",
        "wmr.plot.marks",
        "wmr.plot.lines",
        "wmr.plot.legend",
        "wmr.plot.robot",
        "wmr.plot.units",
    ],
)
def test_doctests(module):
    import doctest
    import importlib

    result = doctest.testmod(importlib.import_module(module), optionflags=doctest.ELLIPSIS)
    assert result.failed == 0, f"{result.failed} doctest(s) failed in {module}"


def test_detmap_minimum_is_refined_and_the_isotropic_example_is_immobile(data):
    """The caption's smallest kappa(J) is not above any grid value, and the isotropic example has rank F = 6."""
    dm = data("detmap")
    for sl in dm.slices:
        assert sl.kappa_min_refined <= sl.kappa_min
        assert sl.kappa_min_refined >= 1.0 + 1e-3
    assert dm.vortex_rank_F == 6
    bot = wmr.paper_robot("centred", L=1.0, r=1.0)
    assert int(wmr.rank_F(bot, np.radians(dm.vortex_beta_deg))) == 6
    assert dm.kappa_mobile_min >= np.sqrt(2) * (1 - 1e-9)
    assert dm.kappa_mobile_min == pytest.approx(np.sqrt(2), rel=1e-9)  # reached by the spin about C
    from edition.figures import detmap

    text = detmap.caption(dm)
    assert "rank $\\mathbf{F} = 6$ and the robot cannot move" in text
    assert f"{min(s.kappa_min_refined for s in dm.slices):.4f}" in text
