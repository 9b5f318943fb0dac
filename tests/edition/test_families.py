"""The paper's singular families (edition.families): every sample, rank count and verdict checked
against independent line geometry; the prose is Markdown with $...$ math; the CSV is deterministic."""

import csv
import re
from typing import Any

import numpy as np
import pytest

import wmr
from edition import families as fam

from conftest import axle, rolling_dir

DEG = np.pi / 180
P = wmr.paper_robot("centred").mount_points  # L = 1: the circumcircle has radius 1


def line_det(dirs):
    """det of the lines through the P_i along ``dirs`` (..., 3, 2): 0 iff concurrent or all parallel."""
    n = np.stack([-dirs[..., 1], dirs[..., 0]], axis=-1)
    c = -np.sum(n * P, axis=-1)
    return np.linalg.det(np.concatenate([n, c[..., None]], axis=-1))


def cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def same(a, b):
    """a = b modulo 360 degrees (radians in)."""
    return np.abs(np.mod(a - b + np.pi, 2 * np.pi) - np.pi) < 1e-9


@pytest.fixture(scope="module")
def families():
    return {f.key: f for f in fam.families()}


def test_every_sample_has_concurrent_wheel_planes(families):
    for f in families.values():
        assert np.all(np.abs(line_det(rolling_dir(f.samples))) <= 1e-12), f.key
        assert f.det_J_exact_zero is True and f.det_J_max <= 1e-12, f.key


def test_rank_counts_are_the_concurrent_axles(families):
    for f in families.values():
        counts = {int(r): int(k) for r, k, _ in re.findall(r"(\d) \((\d+)/(\d+)\)", f.rank_F)}
        concurrent = int(np.sum(np.abs(line_det(axle(f.samples))) <= 1e-9))  # rank F = 5 iff axles concurrent
        assert counts.get(5, 0) == concurrent, f.key
        assert counts.get(5, 0) + counts.get(6, 0) == len(f.samples), f.key


def test_rotation_about_a_point_of_the_circumcircle(families):
    b = families["v-circle"].samples
    i1, i2 = axle(b[:, 0]), axle(b[:, 1])
    s = cross(P[1] - P[0], i2) / cross(i1, i2)  # axle 1 meets axle 2 at U
    U = P[0] + s[:, None] * i1
    assert np.allclose(np.linalg.norm(U, axis=1), 1.0, atol=1e-9)  # on the circle through the P_i
    assert np.all(np.abs(line_det(axle(b))) <= 1e-9)


PRINTED: dict[str, Any] = {
    "(i)": None,
    "(ii)": ((1, 3), (60, -120)),
    "(iii)": ((1, 2), (-60, 120)),
    "(iv)": ((2, 3), (0, 180)),
}


def printed_holds(item, b):
    """Whether the samples b (n, 3) satisfy the paper's item literally."""
    if PRINTED[item] is None:
        return same(b[:, 0], b[:, 1]) & same(b[:, 1], b[:, 2])
    (i, j), vals = PRINTED[item]
    return same(b[:, i - 1], b[:, j - 1]) & np.any([same(b[:, i - 1], v * DEG) for v in vals], axis=0)


def test_listed_in_paper_agrees_with_the_printed_items(families):
    for key, f in families.items():
        item = f.paper_item
        if item in PRINTED:
            holds = printed_holds(item, f.samples)
            assert holds.all() if f.listed_in_paper == "yes" else not holds.any(), key
    assert {k for k, f in families.items() if f.listed_in_paper == "no"} == {
        "i'",
        "pair-13'",
        "pair-12'",
        "pair-23'",
        "v-circle",
    }


def test_check_paper_items_against_sampled_geometry():
    res = fam.check_paper_items()
    tau = np.linspace(-np.pi, np.pi, 37)
    for key, verdict in res.items():
        item, _, value = key.partition(" ")
        if item == "(i)":
            b = np.stack([tau, tau, tau], axis=1)
        elif item == "(v)":
            D = np.stack([np.cos(3 * tau), np.sin(2 * tau)], axis=1) * 2.3  # planes through D
            v = D[:, None, :] - P
            b = np.arctan2(-v[..., 0], v[..., 1])
        else:
            (i, j), _ = PRINTED[item]
            b = np.stack([tau] * 3, axis=1)
            b[:, [i - 1, j - 1]] = float(value) * DEG
        assert verdict == bool(np.all(np.abs(line_det(rolling_dir(b))) <= 1e-12)), key


def test_prose_is_markdown_with_math(families):
    ascii_math = re.compile(r"\bdeg\b|\brank F\b|\bdet J\b|\bP\d\b|!=|<=|>=|<=>|_dot|\^T\b")
    for f in families.values():
        for text in (f.family, f.configuration, f.geometric_meaning, f.note):
            assert text.count("$") % 2 == 0, (f.key, text)
            prose = re.sub(r"\$[^$]*\$", "", text)
            assert not ascii_math.search(prose), (f.key, text)
            assert "\\" not in prose, (f.key, text)  # TeX only inside $...$


def test_write_csv_is_deterministic_and_atomic(tmp_path):
    rows = fam.write_csv(tmp_path / "a.csv", n=12, exact=False)
    fam.write_csv(tmp_path / "b.csv", n=12, exact=False)
    assert (tmp_path / "a.csv").read_bytes() == (tmp_path / "b.csv").read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.csv", "b.csv"]  # no temporary files left
    with open(tmp_path / "a.csv", newline="", encoding="utf-8") as f:
        back = list(csv.DictReader(f))
    assert back == [{k: str(v) for k, v in r.items()} for r in rows]
    assert list(back[0]) == list(fam.COLUMNS)
