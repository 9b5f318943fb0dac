"""Robots that mix wheel kinds (fixed, Swedish, centred, offset): every analysis on them, the entries of units
without a steering joint ignored everywhere, and the line helpers."""

import dataclasses

import numpy as np
import pytest

import wmr
from wmr.analysis import lines, reference
from wmr.model.wheels import wheel_kinds

from conftest import transform_twist

PI = np.pi


def omni3(L=0.3, r=0.05):
    """Three omni wheels, axles radial."""
    return wmr.Robot(
        [
            wmr.SwedishWheel(tuple(p), r=r, angle=float(np.arctan2(p[1], p[0])), roller=PI / 2)
            for p in wmr.equilateral_mounts(L)
        ],
        name="three omni wheels",
    )


def mecanum4(a=0.3, b=0.2, r=0.05):
    """Four mecanum wheels rolling along body x (axles along y), rollers of both hands (X layout)."""
    pts = [(a, b), (a, -b), (-a, b), (-a, -b)]
    return wmr.Robot(
        [wmr.SwedishWheel(p, r=r, angle=PI / 2, roller=PI / 4 if p[0] * p[1] > 0 else -PI / 4) for p in pts],
        name="four mecanum wheels",
    )


def diff_castor(s=0.2, r=0.05):
    return wmr.Robot(
        [
            wmr.FixedWheel((0.0, s), r=r, angle=PI / 2),
            wmr.FixedWheel((0.0, -s), r=r, angle=PI / 2),
            wmr.OffsetWheel((-0.3, 0.0), r=0.03, d=0.03),
        ],
        name="differential drive + castor",
    )


def mixed():
    return wmr.Robot(
        [
            wmr.SwedishWheel((0.4, 0.1), r=0.06, angle=0.3, roller=-PI / 4),
            wmr.FixedWheel((-0.2, 0.5), r=0.05, angle=1.1),
            wmr.CentredWheel((-0.3, -0.4), r=0.04),
            wmr.OffsetWheel((0.1, -0.6), r=0.03, d=0.02),
        ]
    )


def test_unit_types_and_steered():
    kinds = wheel_kinds()
    assert {"offset", "centred", "dual", "fixed", "swedish"} <= set(kinds)
    assert kinds["fixed"] is wmr.FixedWheel and kinds["swedish"] is wmr.SwedishWheel
    assert mixed().steered == (False, False, True, True)
    assert wmr.paper_robot("dual").steered == (True, True, True)
    bot = mixed()
    assert bot.rate_names == ("theta_dot_1", "sigma_dot_1", "theta_dot_2", "theta_dot_3", "phi_dot_4", "theta_dot_4")
    assert np.allclose(bot.F_column_norms[3:], [0.06, 0.06, 0.05, 0.04, 0.02, 0.03])


# --------------------------------------------------------------------------- the robot ignores their entries
@pytest.mark.parametrize("make", [mixed, diff_castor, mecanum4, omni3])
def test_unsteered_entries_are_ignored_everywhere(make):
    bot = make()
    rng = np.random.default_rng(5)
    b1 = rng.uniform(-PI, PI, (7, bot.w))
    b2 = b1.copy()
    unsteered = ~np.array(bot.steered)
    b2[:, unsteered] = rng.uniform(-PI, PI, (7, int(unsteered.sum())))
    eff = bot.effective_beta(b1)
    assert np.allclose(eff, bot.effective_beta(b2))
    assert np.allclose(eff[:, unsteered], [float(u.angle) for u in bot.wheels if not u.steered])
    assert np.allclose(eff[:, ~unsteered], b1[:, ~unsteered])
    t = rng.normal(size=(7, 3))
    rates = rng.normal(size=(7, bot.n_rates))
    same = [
        lambda b: bot.J2(b),
        lambda b: bot.F(b),
        lambda b: bot.J(b, L=0.5),
        lambda b: wmr.rank_F(bot, b),
        lambda b: wmr.mobility(bot, b),
        lambda b: wmr.inverse(bot, b, t).value,
        lambda b: wmr.forward(bot, b, rates).value,
        lambda b: reference.J2(bot, b),
        lambda b: lines.axle_lines(bot, b)[1],
        lambda b: wmr.admissible_twists(bot, b[0]),
    ]
    for f in same:
        assert np.allclose(f(b1), f(b2))
    # the kernels agree with the dense reference (which uses each unit's own angle, independently)
    assert np.allclose(bot.J2(b1), reference.J2(bot, b1), atol=1e-15)
    assert np.array_equal(wmr.rank_F(bot, b1), reference.rank_F(bot, b1))
    S = bot.J2(None)  # symbolic: their columns have no beta symbol
    for i, (u, sl) in enumerate(zip(bot.wheels, bot.rate_slices)):
        syms = S[2 * i : 2 * i + 2, sl].free_symbols
        assert (syms == set()) if not u.steered else (syms <= {bot.beta_symbols[i]})


def test_steering_angles_return_the_own_angles():
    bot = mixed()
    beta = wmr.steering_angles(bot, np.random.default_rng(1).normal(size=(5, 3)), current=np.full((5, 4), 0.25))
    assert np.allclose(beta[:, 0], 0.3) and np.allclose(beta[:, 1], 1.1)
    assert np.allclose(beta[:, 3], 0.25)  # offset: current kept


def test_line_helpers_return_the_own_angles():
    bot = mixed()
    for f in (lines.planes_through, lines.axles_through):
        beta = f(bot, np.random.default_rng(2).normal(size=(3, 2)))
        assert beta.shape == (3, 4) and np.allclose(beta[:, :2], [0.3, 1.1])
    from wmr.analysis.det_exact import plane_line_matrix

    M = plane_line_matrix(bot, None, L=1)  # symbolic: only the steered units have symbols
    assert M[:, :2].free_symbols == set() and M[:, 2].free_symbols == {bot.beta_symbols[2]}
    assert np.allclose(np.array(M[:, :2].evalf(), float), plane_line_matrix(bot, np.zeros(4), L=1)[:, :2])


def test_swedish_robots_realise_every_twist():
    for bot in (omni3(), mecanum4()):
        rng = np.random.default_rng(2)
        beta, t = rng.uniform(-PI, PI, (20, bot.w)), rng.normal(size=(20, 3))
        assert np.all(wmr.mobility(bot, beta) == 3)  # rank F = sum rank L_i = 2w: no twist constraint
        inv = wmr.inverse(bot, beta, t)
        assert inv.admissible.all()
        assert np.allclose(wmr.forward(bot, beta, inv.value).value, t)
        # the driven wheel rates alone determine the twist: a^T [E d 1] t = -r sin(g) theta_dot, rank 3
        rows = np.array([u.roller_axis() @ bot.J1()[2 * i : 2 * i + 2] for i, u in enumerate(bot.wheels)])
        assert wmr.rank(rows) == 3
        assert np.allclose(
            rows @ t[0], [-u.r * np.sin(u.roller) * inv.value[0, 2 * i] for i, u in enumerate(bot.wheels)]
        )


def test_same_handed_mecanum_cannot_be_driven_sideways_by_its_wheels():
    """All rollers of one hand: the wheel-rate map loses rank (why SwedishWheel accepts negative roller angles)."""
    pts = [(0.3, 0.2), (0.3, -0.2), (-0.3, 0.2), (-0.3, -0.2)]
    bot = wmr.Robot([wmr.SwedishWheel(p, r=0.05, angle=0.0, roller=PI / 4) for p in pts])
    units: list = list(bot.wheels)
    rows = np.array([u.roller_axis() @ bot.J1()[2 * i : 2 * i + 2] for i, u in enumerate(units)])
    assert wmr.rank(rows) == 2


def test_fixed_wheels_constrain_the_twist():
    bot = diff_castor()
    beta = np.random.default_rng(3).uniform(-PI, PI, (10, 3))
    assert np.all(wmr.mobility(bot, beta) == 2)  # 3 + 4 rates - (4 + 1 constraint: both axles along y)
    # admissible twists: spin about C and drive along x (the fixed wheels roll along body x)
    basis = wmr.admissible_twists(bot, beta[0])
    assert basis.shape == (3, 2) and np.allclose(basis[2], 0)
    assert not bool(wmr.inverse(bot, beta[0], [0.0, 0.0, 1.0]).admissible)  # sideways: slip
    sol = wmr.inverse(bot, [9.0, -9.0, 0.4], [0.5, 1.0, 0.0])  # the castor realises anything
    assert bool(sol.admissible)
    # wheel speeds of a differential drive: hub speed v -/+ omega s along x = -r theta_dot j, j = (-1, 0)
    assert np.allclose(sol.value[:2], [(1.0 - 0.5 * 0.2) / 0.05, (1.0 + 0.5 * 0.2) / 0.05])


def test_simulated_differential_drive_drives_straight():
    bot = diff_castor()  # equal wheel rates, the castor trailing (axle along y) and rolling at the same speed
    traj = wmr.integrate(bot, [20.0, 20.0, 0.0, 1.0 / 0.03], [0.0, 0.0, PI / 2], t_end=0.5, dt=0.01)
    assert np.allclose(traj.beta, traj.beta[0])  # nothing turns
    assert np.allclose(traj.twist, [0.0, 1.0, 0.0]) and np.allclose(traj.slip, 0, atol=1e-12)
    assert np.allclose(traj.pose[-1], [0.0, 0.5, 0.0])


def test_moved_keeps_the_robot():
    bot = mixed()
    origin, angle = (0.3, -0.2), 0.7
    moved = bot.moved(origin, angle)
    assert np.isclose(moved.wheels[0].angle, 0.3 - 0.7) and np.isclose(moved.wheels[1].angle, 1.1 - 0.7)
    rng = np.random.default_rng(4)
    beta, t = rng.uniform(-PI, PI, (6, 4)), rng.normal(size=(6, 3))
    assert np.array_equal(wmr.rank_F(bot, beta), wmr.rank_F(moved, beta - angle))
    a = wmr.inverse(bot, beta, t)
    b = wmr.inverse(moved, beta - angle, transform_twist(t, origin, angle))
    assert np.allclose(a.value, b.value) and np.array_equal(a.admissible, b.admissible)


def test_sweep_and_drawing():
    bot = mixed()
    sw = wmr.sweep(bot, "rank_F", wmr.analysis.sweep.Sample(200, seed=1))
    assert sw.min == sw.max == 8  # sum rank L_i = 2 + 1 + 1 + 2, plus the fixed and centred rows
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from wmr.plot.robot import draw_robot

    fig, ax = plt.subplots()
    for b in (omni3(), mecanum4(), diff_castor(), bot):
        draw_robot(ax, b, np.zeros(b.w))
    plt.close(fig)


# --------------------------------------------------------------------------- bad input
def test_bad_beta_is_still_rejected_for_unsteered_units():
    bot = mixed()
    with pytest.raises(ValueError, match=r"\bbeta\b"):
        bot.effective_beta(np.zeros(3))
    with pytest.raises(ValueError, match=r"\bbeta\b"):
        bot.wheels[0].block([np.nan])
    with pytest.raises(TypeError, match=r"\bbeta\b"):
        bot.wheels[1].points("a")
    with pytest.raises(ValueError, match=r"\broller\b"):
        dataclasses.replace(bot.wheels[0], roller=0)
