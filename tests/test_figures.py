"""The figures: the numbers each one asserts (not pixels), provenance, and byte-for-byte reproducibility."""
import json

import numpy as np
import pytest

import wmr
from wmr.paper import figures as F
from wmr.model.tolerance import TOL


@pytest.fixture(scope="module")
def figs():
    return {}


def get(figs, key):
    if key not in figs:
        figs[key] = F.FIGURES[key][0]()
    return figs[key]


@pytest.mark.parametrize("key", list(F.FIGURES))
def test_every_figure_has_title_caption_numbers(figs, key):
    fig = get(figs, key)
    assert fig.wmr_title and fig.wmr_caption and isinstance(fig.wmr_numbers, dict)
    assert F.FIGURES[key][0].__doc__
    assert fig.wmr_caption.count("$") % 2 == 0          # balanced inline math


def test_fig07_dead_zone_radius_is_the_offset(figs):
    n = get(figs, "fig07").wmr_numbers
    # RK4 error bound from the step: d (omega dt)^4, itself far below d
    assert n["tolerance"] == pytest.approx(n["d"] * (2 * np.pi / n["T"] * n["dt"]) ** 4)
    assert n["tolerance"] < 1e-5 * n["d"]
    assert abs(n["radius"] - n["d"]) <= n["tolerance"]
    assert n["centre_error"] <= n["tolerance"]          # the circle is centred on C_f
    assert n["contact_drift"] <= n["tolerance"]         # the contact points G_i stay put
    assert n["psi_max"] <= TOL and n["slip_max"] <= TOL
    assert np.allclose(n["C_f"], [0.0, -n["d"]])        # C_f = C - d j(beta0), beta0 = 0


def test_fig08_translations(figs):
    n = get(figs, "fig08").wmr_numbers
    for k in ("rectilinear", "curvilinear"):
        assert n[k]["psi_max"] <= TOL
        assert n[k]["congruence_error"] <= TOL
        assert n[k]["slip_max"] <= TOL
        assert n[k]["rank_F"] == [5]
    assert n["rectilinear"]["straightness"] <= TOL


def test_fig09_rotation(figs):
    n = get(figs, "fig09").wmr_numbers
    for k in ("C", "U"):
        assert n[k]["rank_F"] == 5 and n[k]["mobility"] == 1
        assert n[k]["axle_meet_kind"] == "finite" and n[k]["axle_meet_error"] <= 1e3 * TOL
        assert n[k]["slip_max"] <= TOL
        assert n[k]["turn_deg"] == pytest.approx(60.0, abs=1e-6)
    assert n["C"]["radius"] <= TOL                      # C stays at the IC
    assert n["U"]["radius"] == pytest.approx(n["U"]["radius_expected"], abs=1e-7)


def test_fig10_translation_singularity(figs):
    n = get(figs, "fig10").wmr_numbers
    assert n["det_J_exact"] == "0" and abs(n["det_J"]) <= TOL
    assert n["rank_F"] == 5 and n["mobility"] == 1 and not np.isfinite(n["kappa_J"])
    assert n["planes_meet"] == "at_infinity" and n["axles_meet"] == "at_infinity" and n["family"] == "i"


def test_fig11_two_planes_coincident(figs):
    n = get(figs, "fig11").wmr_numbers
    pairs = {"a": [1, 3], "b": [1, 2], "c": [2, 3]}          # the paper's (ii), (iii), (iv)
    for k, pair in pairs.items():
        assert n[k]["det_J_exact"] == "0" and abs(n[k]["det_J"]) <= TOL
        assert n[k]["rank_F"] == 6 and n[k]["mobility"] == 0
        assert n[k]["coincident"] == [pair]
        assert n[k]["family"] == f"pair-{pair[0]}{pair[1]}"
        assert len(n[k]["axle_crossings"]) == 2             # "the axles intersect at two different locations"


def test_fig12_planes_through_one_point(figs):
    n = get(figs, "fig12").wmr_numbers
    assert n["a"]["det_J_exact"] == "0" and np.allclose(n["a"]["D_P"], [0, 0], atol=1e-9)
    assert n["a"]["family"] == "v-C"
    for k in "ab":
        assert abs(n[k]["det_J"]) <= TOL and n[k]["rank_F"] == 6 and n[k]["mobility"] == 0
        assert n[k]["D_P_error"] <= 1e-9
        assert len(n[k]["axle_crossings"]) == 3             # "the axles intersect at three different locations"


def test_fig13_axles_meet_at_U(figs):
    n = get(figs, "fig13").wmr_numbers
    assert n["axle_meet_kind"] == "finite" and n["axle_meet_error"] <= 1e3 * TOL
    assert n["admissible"] and n["slip"] <= TOL and n["rank_F"] == 5
    u_c, u_i = np.array(n["u_c"]), np.array(n["u_i"])
    beta = np.radians(n["beta_deg"])
    axle = np.stack([np.cos(beta), np.sin(beta)], axis=1)
    assert np.allclose(axle[:, 0] * u_i[:, 1] - axle[:, 1] * u_i[:, 0], 0, atol=1e-12)   # i_i || u_i
    assert np.allclose(u_i, u_c - wmr.paper_robot("centred").mount_points)               # (64)
    assert np.max(np.abs(np.array(n["printed65_deg"]) - n["beta_deg"])) > 1.0            # (65) is not it


def test_det_map(figs):
    n = get(figs, "detmap").wmr_numbers
    assert n["n"] >= 400
    for key, v in n.items():
        if key.startswith("beta1="):
            assert v["singular_motion_det_max"] <= TOL and v["singular_motion_ranks"] == [5]
            assert v["kappa_min"] > 1.0 + 1e-3               # not isotropic on these two slices
            assert {f for _, _, f in v["singular_motions"]} <= {"i", "i'", "v-circle"}


def test_conventions_figure(figs):
    n = get(figs, "conventions").wmr_numbers
    j, i = np.array(n["j"]), np.array(n["i"])
    assert np.allclose(n["H_minus_P"], -0.3 * j)              # H_i = P_i - d j_i
    assert np.allclose(n["dual_wheels"], [0.45 * i, -0.45 * i])   # wheel 1 at +b i_i
    assert np.allclose(n["mount_points"][0], [-1, 0])


def test_writer_is_reproducible_and_records_provenance(tmp_path):
    keys = ["fig10", "conventions"]
    caps = F.write_all(tmp_path / "a", keys=keys, csv=False, commit="abc123")
    F.write_all(tmp_path / "b", keys=keys, csv=False, commit="abc123")
    for key in keys:
        for ext in ("svg", "pdf", "png"):
            a = (tmp_path / "a" / f"{key}.{ext}").read_bytes()
            b = (tmp_path / "b" / f"{key}.{ext}").read_bytes()
            assert a == b, f"{key}.{ext} differs between runs"
            assert f"wmr.paper.figures.{F.FIGURES[key][0].__name__}".encode() in a
            assert b"abc123" in a
    assert (tmp_path / "a" / "captions.json").read_bytes() == (tmp_path / "b" / "captions.json").read_bytes()
    data = json.loads((tmp_path / "a" / "captions.json").read_text())
    assert data == caps
    assert data["fig10"]["number"] == "10" and data["conventions"]["number"] == ""
    assert data["fig10"]["function"] == "wmr.paper.figures.fig10" and data["fig10"]["commit"] == "abc123"


def test_cli_rejects_unknown_keys(tmp_path, capsys):
    assert F.main([str(tmp_path), "nope"]) == 2


def test_det_map_isotropic_configuration(figs):
    n = get(figs, "detmap").wmr_numbers
    assert abs(n["kappa_vortex"] - 1) <= 1e3 * TOL and abs(n["kappa_vortex_minus"] - 1) <= 1e3 * TOL


def test_writing_a_subset_keeps_other_captions(tmp_path):
    F.write_all(tmp_path, keys=["conventions"], csv=False, commit="c1")
    F.write_all(tmp_path, keys=["fig10"], csv=False, commit="c1")
    data = json.loads((tmp_path / "captions.json").read_text())
    assert list(data) == ["fig10", "conventions"]
