"""Package facts that notebooks 03 and 04 rely on (equations (30)-(59) and the isotropy/singularity claims).

The expected values are computed from first principles (hand-built J_L1, rolling directions
j_i = k x i_i, line geometry), so that a sign or numbering change in the model makes a test fail.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

import edition.symbols
import wmr
from edition import printed
from wmr.analysis.isotropy import condition_number
from wmr.analysis.mobility import rank_F, twist_constraints
from wmr.model.tolerance import TOL

SEED = 20020101
SQ3 = np.sqrt(3.0)


def _i(beta):
    beta = np.asarray(beta, float)
    return np.stack([np.cos(beta), np.sin(beta)], -1)


def _j(beta):
    beta = np.asarray(beta, float)
    return np.stack([-np.sin(beta), np.cos(beta)], -1)


def _JL1(points, L):
    """J_L1 (32) built by hand: rows [-d_y/L, 1, 0] and [d_x/L, 0, 1]."""
    rows = []
    for dx, dy in np.asarray(points, float):
        rows += [[-dy / L, 1.0, 0.0], [dx / L, 0.0, 1.0]]
    return np.array(rows)


def _printed_det(beta):
    """(59) as printed in the paper."""
    b1, b2, b3 = np.moveaxis(np.asarray(beta, float), -1, 0)
    return (
        -SQ3 / 2 * np.cos(b1 - b2 - b3)
        + 0.75 * np.sin(b1 - b2 + b3)
        - 0.75 * np.sin(b1 + b2 - b3)
        + SQ3 / 4 * np.cos(b1 + b2 - b3)
        + SQ3 / 4 * np.cos(b1 - b2 + b3)
    )


def test_printed_forms_registered():
    for n in range(30, 60):
        p = printed(n)
        assert p.latex and p.section.startswith(("4.3", "5."))
    # the transcription of (59) agrees with the paper's text used in these tests
    f = sp.lambdify(edition.symbols.beta, printed(59).expr.rhs, "numpy")
    B = np.random.default_rng(SEED).uniform(-np.pi, np.pi, (50, 3))
    assert np.allclose(f(*B.T), _printed_det(B), atol=1e-14)


def test_JL1_and_gram_general_placement():
    rng = np.random.default_rng(SEED)
    for _ in range(20):
        pts, L = rng.normal(size=(3, 2)), rng.uniform(0.2, 2.0)
        bot = wmr.Robot([wmr.OffsetWheel(p, r=0.1, d=0.1) for p in pts])
        JL1 = bot.J1(L)
        assert np.allclose(JL1, _JL1(pts, L), atol=1e-14)
        s = pts.sum(axis=0)
        Es = np.array([-s[1], s[0]])
        want = np.block([[np.array([[np.sum(pts**2) / L**2]]), Es[None, :] / L], [Es[:, None] / L, 3 * np.eye(2)]])
        assert np.allclose(JL1.T @ JL1, want, atol=1e-12)  # (34)
        t = rng.normal(size=3)
        assert np.allclose(bot.J1() @ t, JL1 @ (np.diag([L, 1, 1]) @ t))  # (33): J1 t = J_L1 t_L


def test_isotropy_needs_centroid_and_rms_length_not_equilateral():
    ce = wmr.Robot([wmr.OffsetWheel(p, r=0.1, d=0.1) for p in [(2, 0), (-1, 1), (-1, -1)]])
    assert abs(condition_number(ce.J1(np.sqrt(8 / 3))) - 1) <= TOL  # isosceles, isotropic
    assert condition_number(ce.J1(np.sqrt(8 / 3) * 1.1)) > 1.01
    rng = np.random.default_rng(SEED)
    for _ in range(20):
        d12 = rng.normal(size=(2, 2))
        pts = np.vstack([d12, -d12.sum(0)])
        bot = wmr.Robot([wmr.CentredWheel(p, r=0.1) for p in pts])
        L = np.sqrt(np.mean(np.sum(pts**2, 1)))
        assert abs(condition_number(bot.J1(L)) - 1) <= 1e-9
        shifted = wmr.Robot([wmr.CentredWheel(p + 0.3, r=0.1) for p in pts])  # C off the centroid
        assert condition_number(shifted.J1(np.sqrt(np.mean(np.sum((pts + 0.3) ** 2, 1))))) > 1 + 1e-6


@pytest.mark.parametrize("d, r", [(0.1, 0.1), (0.05, 0.1), (0.1, 0.03), (0.0, 0.1)])
def test_offset_J2_singular_values_are_d_and_r(d, r):
    bot = wmr.paper_robot("offset", L=0.4, r=r, d=d)
    B = np.random.default_rng(SEED).uniform(-np.pi, np.pi, (200, 3))
    J2 = bot.J2(B)
    s = np.sort(np.linalg.svd(J2, compute_uv=False), axis=-1)
    assert np.allclose(s, np.sort([d, d, d, r, r, r]), atol=1e-12)
    # first principles: block i maps (phi_dot, theta_dot) to -d phi_dot i_i - r theta_dot j_i  (9)
    blk = J2[0, 0:2, 0:2]
    assert np.allclose(blk, np.column_stack([-d * _i(B[0, 0]), -r * _j(B[0, 0])]))
    k = condition_number(J2)
    assert np.all(np.isinf(k)) if d == 0 else np.allclose(k, max(d, r) / min(d, r))


def test_composite_J_isotropic_for_offset_d_equals_r_not_for_centred():
    B = np.random.default_rng(SEED).uniform(-np.pi, np.pi, (500, 3))
    off = wmr.paper_robot("offset", L=0.4, r=0.1)
    J = off.J(B, L=0.4)
    assert np.allclose(J @ np.swapaxes(J, -1, -2), 3 * 0.1**2 * np.eye(3), atol=1e-14)
    cen = wmr.paper_robot("centred", L=0.4, r=0.1)
    assert np.all(np.abs(condition_number(cen.J2(B)) - 1) <= 1e-9)
    k = condition_number(cen.J(B, L=0.4))
    assert k.min() > 1.01 and k.max() > 100
    assert np.isinf(condition_number(cen.J([0.2, 0.2 + np.pi, 0.2], L=0.4)))


def test_det_J_equals_r3_times_printed_with_paper_numbering_only():
    B = np.random.default_rng(SEED).uniform(-np.pi, np.pi, (300, 3))
    for L, r in [(1.0, 1.0), (0.4, 0.1), (2.5, 0.3)]:
        bot = wmr.paper_robot("centred", L=L, r=r)
        assert np.allclose(bot.mount_points, L * np.array([[-1, 0], [0.5, SQ3 / 2], [0.5, -SQ3 / 2]]), atol=1e-15)
        assert np.allclose(np.linalg.det(bot.J(B, L=L)), r**3 * _printed_det(B), atol=1e-12)
    for first, cw in [(180, False), (0, True), (90, True), (60, False)]:
        bot = wmr.Robot([wmr.CentredWheel(q, r=1.0) for q in wmr.equilateral_mounts(1.0, first, cw)])
        assert not np.allclose(np.linalg.det(bot.J(B, L=1.0)), _printed_det(B), atol=1e-6)


def test_det_J_is_the_concurrency_determinant_of_the_wheel_plane_lines():
    rng = np.random.default_rng(SEED)
    for _ in range(20):
        pts, L, r = rng.normal(size=(3, 2)), rng.uniform(0.2, 2), rng.uniform(0.02, 0.3)
        bot = wmr.Robot([wmr.CentredWheel(p, r=r) for p in pts])
        beta = rng.uniform(-np.pi, np.pi, 3)
        # first principles: J = J_L1^T J2 with J2 columns -r j_i
        J2 = np.zeros((6, 3))
        for k in range(3):
            J2[2 * k : 2 * k + 2, k] = -r * _j(beta[k])
        J = _JL1(pts, L).T @ J2
        assert np.allclose(bot.J(beta, L=L), J, atol=1e-13)
        i = _i(beta)
        lines = np.column_stack([i, np.sum(i * pts, 1)])
        assert np.isclose(np.linalg.det(J), -(r**3) / L * np.linalg.det(lines), atol=1e-12)


def _planes_through(points, U):
    w = U - points
    return np.arctan2(-w[:, 0], w[:, 1])  # j_i parallel to U - P_i


def test_singular_families_and_concurrency():
    bot = wmr.paper_robot("centred", L=1.0, r=1.0)
    rng = np.random.default_rng(SEED)
    b = rng.uniform(-np.pi, np.pi, 50)
    z = rng.uniform(-np.pi, np.pi, 50)
    fams = [
        np.c_[b, b, b],
        np.c_[b, b + np.pi, b],
        np.c_[b, b, b + np.pi],  # (i) and mod pi
        np.c_[np.full(50, np.pi / 3), z, np.full(50, -2 * np.pi / 3)],  # (ii), mixed values
        np.c_[np.full(50, -np.pi / 3), np.full(50, 2 * np.pi / 3), z],  # (iii)
        np.c_[z, np.zeros(50), np.full(50, np.pi)],
    ]  # (iv)
    fams += [np.array([_planes_through(bot.mount_points, U) for U in rng.normal(size=(50, 2)) * 3])]  # (v)
    for F in fams:
        assert np.max(np.abs(np.linalg.det(bot.J(F, L=1.0)))) < 1e-12
    assert np.min(np.abs(np.linalg.det(bot.J(rng.uniform(-np.pi, np.pi, (500, 3)), L=1.0)))) > 1e-6


def test_rank_F_centred_is_5_or_6_for_noncollinear_mounts():
    bot = wmr.paper_robot("centred", L=0.4, r=0.1)
    rng = np.random.default_rng(SEED)
    assert set(rank_F(bot, rng.uniform(-np.pi, np.pi, (5000, 3))).tolist()) == {6}
    twists = np.vstack([rng.normal(size=(100, 3)), np.c_[np.zeros(50), rng.normal(size=(50, 2))]])
    assert set(rank_F(bot, wmr.steering_angles(bot, twists)).tolist()) == {5}
    g = np.linspace(-np.pi, np.pi, 24, endpoint=False)
    grid = np.stack(np.meshgrid(g, g, g, indexing="ij"), -1).reshape(-1, 3)
    assert set(rank_F(bot, grid).tolist()) == {5, 6}
    # SVD rank agrees with the structured rank; A rows are i_i^T [E d_i 1] (first principles, up to sign)
    B = rng.uniform(-np.pi, np.pi, (50, 3))
    assert np.array_equal(wmr.rank(bot.F(B)), rank_F(bot, B))
    A, base = twist_constraints(bot, B)
    i = _i(B)
    d = bot.mount_points
    want = np.concatenate([(i[..., 0] * -d[:, 1] + i[..., 1] * d[:, 0])[..., None], i], -1)
    assert base == 3 and np.allclose(np.abs(A), np.abs(want), atol=1e-14)
    line = wmr.Robot([wmr.CentredWheel((x, 0.0), r=0.1) for x in (-0.4, 0.1, 0.4)])
    assert int(rank_F(line, [0.0, np.pi, 0.0])) == 4


def test_concurrent_wheel_planes_on_the_circumcircle_keep_mobility_one():
    bot = wmr.paper_robot("centred", L=0.4, r=0.1)
    for a in np.deg2rad([10, 100, 200, 290]):
        beta = _planes_through(bot.mount_points, 0.4 * np.array([np.cos(a), np.sin(a)]))
        assert abs(np.linalg.det(bot.J(beta, L=0.4))) < 1e-12
        assert int(wmr.mobility(bot, beta)) == 1
    assert int(wmr.mobility(bot, _planes_through(bot.mount_points, np.zeros(2)))) == 0


@pytest.mark.parametrize("kind", ["offset", "centred"])
def test_isotropic_kinematics_are_the_least_squares_of_forward_inverse(kind):
    L, r = 0.4, 0.1
    bot = wmr.paper_robot(kind, L=L, r=r)
    rng = np.random.default_rng(SEED)
    S = np.diag([L, 1.0, 1.0])
    JL1 = _JL1(bot.mount_points, L)
    for _ in range(20):
        beta = rng.uniform(-np.pi, np.pi, 3)
        J2 = bot.J2(beta)
        th = rng.normal(size=bot.n_rates)
        tL = JL1.T @ J2 @ th / 3  # (49) / (55)
        assert np.allclose(np.linalg.solve(S, tL), wmr.forward(bot, beta, th).value, atol=1e-12)
        t = rng.normal(size=3)
        th_inv = J2.T @ JL1 @ (S @ t) / r**2  # (50) / (57)
        inv = wmr.inverse(bot, beta, t)
        assert np.allclose(th_inv, inv.value, atol=1e-12)
        assert bool(inv.admissible) == (kind == "offset")
