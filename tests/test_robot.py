"""wmr.model.robot: J1, J2, F and J of assembled robots; symbolic = numeric; first principles; frames.

The last test shows that the suite can fail: it plants a wrong sign in a Jacobian and checks
that the key properties then break.
"""

from types import SimpleNamespace

import numpy as np
import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st

import wmr

from conftest import (
    check_J1_first_principles,
    check_J2_first_principles,
    check_offset_steer_only,
    check_positive_rolling,
    check_round_trip,
    robots,
    seeds,
)

# the symbols of the paper's robot (edition.symbols defines the same ones for the chapters)
S = SimpleNamespace(
    L=sp.Symbol("L", positive=True), r=sp.Symbol("r", positive=True), beta=sp.symbols("beta1:4", real=True)
)


@given(robots(), seeds, st.sampled_from([(), (4,), (2, 3)]))
def test_shapes(bot, seed, batch):
    rng = np.random.default_rng(seed)
    beta = rng.uniform(-np.pi, np.pi, batch + (bot.w,))
    n = bot.n_rates
    assert n == sum(u.n_rates for u in bot.wheels)
    assert bot.J1().shape == (2 * bot.w, 3) == bot.J1(L=2.5).shape
    assert bot.J2(beta).shape == batch + (2 * bot.w, n)
    assert bot.F(beta).shape == batch + (2 * bot.w, 3 + n)
    assert bot.J(beta).shape == batch + (3, n)
    assert len(bot.qdot_names) == len(bot.qdot_symbols) == 3 + n
    assert len(bot.beta_symbols) == bot.w and bot.mount_points.shape == (bot.w, 2)


@given(robots(), seeds)
def test_first_principles(bot, seed):
    rng = np.random.default_rng(seed)
    check_J1_first_principles(bot, rng.normal(size=3))
    check_J2_first_principles(bot, rng.uniform(-np.pi, np.pi, bot.w), rng.normal(size=bot.n_rates))


@given(robots(), seeds)
def test_F_columns_follow_qdot_names(bot, seed):
    rng = np.random.default_rng(seed)
    beta, t, th = rng.uniform(-3, 3, bot.w), rng.normal(size=3), rng.normal(size=bot.n_rates)
    F = bot.F(beta)
    assert np.allclose(F @ np.concatenate([t, th]), bot.J1() @ t - bot.J2(beta) @ th)  # (22)-(24)
    assert bot.qdot_names[:3] == ("psi_dot", "x_dot", "y_dot")
    for i, (u, sl) in enumerate(zip(bot.wheels, bot.rate_slices), 1):
        assert bot.rate_names[sl] == u.rate_names(i)


@given(robots(w_max=3), seeds)
def test_symbolic_F_matches_numeric(bot, seed):
    Fs = bot.F()  # symbolic betas beta1..betaw
    assert isinstance(Fs, sp.MatrixBase)
    f = sp.lambdify(bot.beta_symbols, Fs, "numpy")
    betas = np.random.default_rng(seed).uniform(-np.pi, np.pi, (3, bot.w))
    Fn = bot.F(betas)
    for k in range(3):
        assert np.allclose(np.array(f(*betas[k]), float), Fn[k], atol=1e-13)


@given(robots(), st.floats(0.1, 10.0), seeds)
def test_JL1_and_J(bot, L, seed):
    rng = np.random.default_rng(seed)
    t, beta = rng.normal(size=3), rng.uniform(-3, 3, bot.w)
    tL = np.array([L * t[0], t[1], t[2]])  # (33)
    assert np.allclose(bot.J1(L) @ tL, bot.J1() @ t)
    assert np.allclose(bot.J(beta, L), bot.J1(L).T @ bot.J2(beta))  # (56)


def test_symbolic_paper_robot_is_exact():
    bot = wmr.paper_robot("centred", L=S.L, r=S.r)
    J1 = bot.J1()
    assert not J1.atoms(sp.Float), J1  # L = 1 must not turn into 1.0
    assert J1[0, :] == sp.Matrix([[0, 1, 0]]) and J1[1, :] == sp.Matrix([[-S.L, 0, 1]])
    J = bot.J(L=S.L)
    assert not J.atoms(sp.Float)
    assert set(J.free_symbols) == {S.r, *S.beta}  # J_L1 with L = |d_i|: no L left
    num = wmr.paper_robot("centred", L=0.7, r=0.2)
    beta = np.array([0.3, -1.2, 2.0])
    f = sp.lambdify([S.L, S.r, *S.beta], J, "numpy")
    assert np.allclose(np.array(f(0.7, 0.2, *beta), float), num.J(beta, L=0.7))


def test_exact_mounts_give_exact_matrices():
    bot = wmr.paper_robot("offset", r=1, d=sp.Rational(1, 2), exact=True)
    assert not bot.F().atoms(sp.Float)


@given(robots(), st.tuples(st.floats(-2, 2), st.floats(-2, 2)), st.floats(-np.pi, np.pi))
def test_moved_round_trip(bot, origin, angle):
    moved = bot.moved(origin, angle)
    c, s = np.cos(angle), np.sin(angle)
    Rt = np.array([[c, s], [-s, c]])
    assert np.allclose(moved.mount_points, (bot.mount_points - origin) @ Rt.T)
    back = moved.moved(-Rt @ np.asarray(origin), -angle)
    assert np.allclose(back.mount_points, bot.mount_points)
    assert [u.kind for u in moved.wheels] == [u.kind for u in bot.wheels]


def test_repr_and_names():
    bot = wmr.Robot([wmr.OffsetWheel((1, 0), r=0.1, d=0.05), wmr.DualWheel((-1, 0), r=0.1, b=0.2)], name="mix")
    assert "mix" in repr(bot) and "offset" in repr(bot) and "dual" in repr(bot)
    assert bot.qdot_names == ("psi_dot", "x_dot", "y_dot", "phi_dot_1", "theta_dot_1", "theta_dot_21", "theta_dot_22")
    assert bot.rate_slices == (slice(0, 2), slice(2, 4))


BAD = [
    (lambda: wmr.Robot([]), "wheels", "0"),
    (lambda: wmr.Robot(3), "wheels", "3"),  # type: ignore[arg-type]
    (lambda: wmr.Robot([wmr.CentredWheel((0, 0), r=1), "wheel"]), "wheels[1]", "'wheel'"),  # type: ignore[list-item]
    (lambda: wmr.paper_robot().J2([0.0, 0.0]), "beta", "(2,)"),
    (lambda: wmr.paper_robot().F(np.zeros((5, 4))), "beta", "(5, 4)"),
    (lambda: wmr.paper_robot().J([0.0, np.nan, 0.0]), "beta", "nan"),
    (lambda: wmr.paper_robot().J2([0.0, np.inf, 0.0]), "beta", "inf"),
    (lambda: wmr.paper_robot().J1(L=0.0), "L", "0"),
    (lambda: wmr.paper_robot().J([0.0, 0.0, 0.0], L=-1.0), "L", "-1"),
    (lambda: wmr.paper_robot().moved((np.nan, 0.0)), "origin", "nan"),
    (lambda: wmr.paper_robot().moved((0.0, 0.0), angle=np.inf), "angle", "inf"),
    (lambda: wmr.paper_robot().J2([0.0, 0.0]) if False else wmr.paper_robot().F([1, 2]), "beta", "(2,)"),
    (lambda: wmr.paper_robot().J2(sp.Matrix([1, 2])), "beta", "(2, 1)"),
    (lambda: wmr.paper_robot("tricycle"), "kind", "'tricycle'"),
    (lambda: wmr.paper_robot(L=-1.0), "L", "-1"),
    (lambda: wmr.paper_robot("offset", d=-0.5), "d", "-0.5"),
    (lambda: wmr.equilateral_mounts(1.0, first_deg=np.nan), "first_deg", "nan"),
]


@pytest.mark.parametrize("make, name, value", BAD)
def test_bad_input_raises_with_name_and_value(make, name, value):
    wrong_kind = {("wheels", "3"), ("wheels[1]", "'wheel'")}
    with pytest.raises(TypeError if (name, value) in wrong_kind else ValueError) as exc:
        make()
    msg = str(exc.value)
    assert name in msg and value in msg, msg


# --- the suite can fail ---------------------------------------------------------------------------
def _flip_offset(self, bk):
    return bk.matrix([[self.d, 0], [0, -self.r]])  # wrong sign of the offset term of (20)


def _flip_centred(self, bk):
    return bk.matrix([[0], [self.r]])  # wrong sign of (51)


def _flip_dual(self, bk):
    return bk.matrix([[0, 0], [self.r / 2, -self.r / 2]])  # wrong sign on wheel 1 of (17)


def _flip_E(d):  # E -> -E in (5): the rows [-E d_i  1] of J1
    J1 = np.zeros((2 * len(d), 3))
    J1[0::2, 0], J1[1::2, 0], J1[0::2, 1], J1[1::2, 2] = d[:, 1], -d[:, 0], 1.0, 1.0
    return J1


MIXED = wmr.Robot(
    [
        wmr.OffsetWheel((1.0, 0.2), r=0.2, d=0.1),
        wmr.CentredWheel((-0.5, 0.9), r=0.3),
        wmr.DualWheel((-0.4, -1.0), r=0.25, b=0.15),
        wmr.CentredWheel((0.6, -0.7), r=0.1),
    ]
)
OFFSET_PAIR = wmr.Robot([wmr.OffsetWheel((1.0, 0.0), r=0.2, d=0.1), wmr.OffsetWheel((-1.0, 0.5), r=0.2, d=0.1)])
TWIST = np.array([0.8, 0.3, -0.5])
RNG = np.random.default_rng(7)
BETA, RATES = RNG.uniform(-3, 3, MIXED.w), RNG.normal(size=MIXED.n_rates)

# each check builds its robot anew: a robot computes its J1 and its units' blocks once, when made, so a
# mutation made after a robot was made would not reach it
CHECKS = {
    "J1 first principles": lambda: check_J1_first_principles(wmr.Robot(MIXED.wheels), TWIST),
    "J2 first principles": lambda: check_J2_first_principles(wmr.Robot(MIXED.wheels), BETA, RATES),
    "forward(inverse(t)) = t": lambda: check_round_trip(wmr.Robot(MIXED.wheels), TWIST),
    "steering rolls forward": lambda: check_positive_rolling(wmr.Robot(MIXED.wheels), TWIST),
    "offset steer-only circle": lambda: check_offset_steer_only(wmr.Robot(OFFSET_PAIR.wheels)),
}
MUTATIONS = {  # mutation -> the checks that must catch it
    "offset d sign": (
        ("OffsetWheel", "local_block", _flip_offset),
        ["J2 first principles", "offset steer-only circle"],
    ),
    "centred r sign": (
        ("CentredWheel", "local_block", _flip_centred),
        ["J2 first principles", "steering rolls forward"],
    ),
    "dual wheel sign": (("DualWheel", "local_block", _flip_dual), ["J2 first principles"]),
    "E sign in J1": (("robot", "_J1_of", _flip_E), ["J1 first principles", "forward(inverse(t)) = t"]),
}


@pytest.mark.parametrize("check", sorted(CHECKS))
def test_key_properties_hold(check):
    CHECKS[check]()


@pytest.mark.parametrize("mutation", sorted(MUTATIONS))
def test_suite_detects_wrong_sign(mutation, monkeypatch):
    (owner, attr, fake), must_fail = MUTATIONS[mutation]
    target = wmr.model.robot if owner == "robot" else getattr(wmr.model.wheels, owner)
    monkeypatch.setattr(target, attr, fake)
    failed = []
    for name, check in CHECKS.items():
        try:
            check()
        except AssertionError:
            failed.append(name)
    missing = set(must_fail) - set(failed)
    assert not missing, f"a wrong sign ({mutation}) went unnoticed by: {sorted(missing)}"
