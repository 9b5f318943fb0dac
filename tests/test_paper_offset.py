"""Package-level facts that notebooks 01 and 02 rely on (equations (6)-(29) and the drift claims).

Each test compares the package with a first-principles computation (rigid-body velocities of
wheel centres, no slip along the rolling direction), so that flipping a sign in the model fails.
"""

from __future__ import annotations

import numpy as np
import pytest

import wmr
from wmr.model.platform import point_velocity
from wmr.model.tolerance import TOL

SEED = 20020101


def _axes(beta):
    beta = np.asarray(beta, dtype=float)
    i = np.stack([np.cos(beta), np.sin(beta)], -1)
    j = np.stack([-np.sin(beta), np.cos(beta)], -1)
    return i, j


def _locked(robot, beta):
    """Columns of F for the twist and the steering rates (drives locked, theta_dot = 0)."""
    F = robot.F(beta)
    keep = [c for c, n in enumerate(robot.qdot_names) if not n.startswith("theta_dot")]
    return F[..., keep]


# --- dual wheel, (15)-(16) ---------------------------------------------------------------------


def test_dual_wheel_spin_counterexample():
    """Platform spins about C with axles through C and units locked: beta_dot = 0, yet
    -(r/2b)(theta_dot_1 - theta_dot_2) = psi_dot (the printed (15) would give beta_dot = psi_dot)."""
    r, b = 0.1, 0.08
    bot = wmr.paper_robot("dual", L=0.5, r=r, b=b)
    beta = np.arctan2(bot.mount_points[:, 1], bot.mount_points[:, 0])
    twist = np.array([1.0, 0.0, 0.0])
    sol = wmr.inverse(bot, beta, twist)
    assert bool(sol.admissible)
    i, j = _axes(beta)
    for k, (unit, sl) in enumerate(zip(bot.wheels, bot.rate_slices)):
        v1 = point_velocity(twist, bot.mount_points[k] + b * i[k])  # wheel 1 at P + b i (rigid, beta frozen)
        v2 = point_velocity(twist, bot.mount_points[k] - b * i[k])
        assert abs(i[k] @ v1) < TOL and abs(i[k] @ v2) < TOL  # no sideways slip
        rates = np.array([-j[k] @ v1 / r, -j[k] @ v2 / r])  # (13), (14)
        np.testing.assert_allclose(sol.value[sl], rates, atol=TOL)
        assert abs(unit.beta_rate(twist[0], rates)) < TOL  # beta stays fixed
        assert abs(-r / (2 * b) * (rates[0] - rates[1]) - twist[0]) < TOL  # = phi_dot = psi_dot


def test_dual_wheel_steering_law_random():
    """DualWheel.beta_rate returns beta_dot for rigid-body wheel velocities at random states."""
    rng = np.random.default_rng(SEED)
    for _ in range(50):
        r, b = rng.uniform(0.05, 0.5, 2)
        beta, psi_dot, beta_dot, s = rng.uniform(-3, 3, 4)
        _, j = _axes(beta)
        phi_dot = psi_dot + beta_dot
        v1, v2 = (s + b * phi_dot) * j, (s - b * phi_dot) * j  # p_dot + phi_dot k x (+-b i)
        rates = np.array([-j @ v1 / r, -j @ v2 / r])
        unit = wmr.DualWheel((0.3, -0.2), r=r, b=b)
        assert abs(unit.beta_rate(psi_dot, rates) - beta_dot) < TOL


# --- offset wheel, (9)-(10) --------------------------------------------------------------------


def test_offset_block_matches_rigid_body():
    """block(beta) [phi_dot, theta_dot] = velocity of P_i from a rolling wheel centre at P_i - d j_i."""
    rng = np.random.default_rng(SEED)
    r, d = 0.1, 0.04
    unit = wmr.OffsetWheel((0.2, 0.1), r=r, d=d)
    beta = rng.uniform(-np.pi, np.pi, 200)
    phi_dot, theta_dot = rng.uniform(-3, 3, (2, 200))
    i, j = _axes(beta)
    pts = unit.points(beta)
    np.testing.assert_allclose(pts["H"], pts["P"] - d * j, atol=TOL)
    h_dot = -r * theta_dot[:, None] * j  # (6)
    P_minus_H = d * j
    p_dot = h_dot + phi_dot[:, None] * np.stack([-P_minus_H[:, 1], P_minus_H[:, 0]], -1)  # + phi_dot k x (P - H)
    got = (unit.block(beta) @ np.stack([phi_dot, theta_dot], -1)[..., None])[..., 0]
    np.testing.assert_allclose(got, p_dot, atol=TOL)


# --- mobility, (26)-(27) -----------------------------------------------------------------------


@pytest.mark.parametrize("seed", range(5))
def test_offset_robot_rank_6_nullity_3(seed):
    rng = np.random.default_rng(SEED + seed)
    bot = wmr.Robot([wmr.OffsetWheel(tuple(p), r=0.1, d=0.05) for p in rng.uniform(-1, 1, (3, 2))])
    beta = rng.uniform(-np.pi, np.pi, (100, 3))
    assert set(wmr.rank(bot.F(beta)).tolist()) == {6}
    assert set(wmr.mobility(bot, beta).tolist()) == {3}
    assert wmr.admissible_twists(bot, beta[0]).shape[1] == 3


def test_zero_offset_nullity_is_pure_steering():
    bot = wmr.paper_robot("offset", L=0.3, r=0.1, d=0.0)
    beta = np.array([0.3, -1.1, 2.0])
    assert int(wmr.mobility(bot, beta)) == 3
    assert wmr.admissible_twists(bot, beta).shape[1] == 0


# --- drift with the drives locked, (28)-(29) ---------------------------------------------------


def test_locked_steering_jams_unless_arms_concurrent_or_parallel():
    rng = np.random.default_rng(SEED)
    bot = wmr.paper_robot("offset", L=0.3, r=0.1, d=0.05)
    generic = rng.uniform(-np.pi, np.pi, (200, 3))
    assert set(wmr.rank(_locked(bot, generic)).tolist()) == {6}
    assert int(wmr.rank(_locked(bot, np.full(3, 0.7)))) == 5  # parallel arms
    u = np.array([0.1, 0.05])
    v = bot.mount_points - u
    concurrent = np.arctan2(-v[:, 0], v[:, 1])  # j_i parallel to d_i - u
    M = _locked(bot, concurrent)
    assert int(wmr.rank(M)) == 5
    x = wmr.null_space(M)[:, 0]
    x = x / x[0]
    np.testing.assert_allclose(x[1:3], -wmr.E() @ u, atol=1e-12)  # rotation about u


def test_dead_zone_circle():
    """All beta equal, one full steering turn, drives locked: C circles C_f at radius d."""
    d = 0.05
    bot = wmr.paper_robot("offset", L=0.3, r=0.1, d=d)
    T = 2 * np.pi
    rates = np.zeros(6)
    rates[0::2] = 2 * np.pi / T
    run = wmr.integrate(bot, rates, np.full(3, 0.4), t_end=T, dt=T / 100)
    C = run.pose[:, 1:]
    G = np.stack([run.unit_points(i, "H") for i in range(3)], axis=1)
    Cf = G.mean(axis=1)
    assert np.ptp(G, axis=0).max() < 1e-8  # contact points fixed
    np.testing.assert_allclose(np.linalg.norm(C - Cf[0], axis=1), d, atol=1e-8)
    assert np.ptp(run.pose[:, 0]) < TOL and run.slip.max() < TOL
