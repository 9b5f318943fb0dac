"""Physics does not depend on the unit of length (issue 11, part 1).

Every rank, nullity, mobility, admissibility, isotropy and singularity decision is made on
dimensionless quantities (:mod:`wmr.model.tolerance`): scaling every length of a robot (mount
points, radii, offsets, separations, the characteristic length, the translational rates) by
``10**k``, ``k = -6 .. 6``, gives the same answer, and both rank paths (``wmr.rank(bot.F(beta))``
and ``wmr.rank_F(bot, beta)``) agree.  Results from finite input are finite, or the call raises.
"""

import warnings

import numpy as np
import pytest

import wmr
from wmr.analysis import linalg as LA
from wmr.analysis import reference as R
from wmr.analysis import singularities as S

KS = range(-6, 7)
SPIN = np.radians([0.0, -120.0, 120.0])  # axles through C: spin about C (mobility 1)
E1 = np.array([1.0, 0.0, 0.0])


def robot(kind, scale=1.0, L=1.0, r=0.1):
    """A three-wheel robot of the paper or a mixed one, every length times ``scale``."""
    if kind == "mixed":
        return wmr.Robot(
            [
                wmr.OffsetWheel((scale * L, 0.2 * scale), r=scale * r, d=0.5 * scale * r),
                wmr.CentredWheel((-0.5 * scale * L, 0.9 * scale * L), r=scale * r),
                wmr.DualWheel((-0.4 * scale * L, -scale * L), r=scale * r, b=0.7 * scale * r),
            ]
        )
    return wmr.paper_robot(kind, L=scale * L, r=scale * r)


#: steering angles of the centred robot: exactly singular, perturbed by 1e-12 (still singular within
#: the angular tolerance), by 1e-7 and 1e-4 rad (regular), and generic
CONFIGS = {
    "spin": SPIN,
    "spin+1e-12": SPIN + 1e-12 * E1,
    "spin+1e-7": SPIN + 1e-7 * E1,
    "spin+1e-4": SPIN + 1e-4 * E1,
    "parallel": np.zeros(3),
    "parallel+1e-12": 1e-12 * E1,
    "parallel+1e-7": 1e-7 * E1,
    "parallel+1e-4": 1e-4 * E1,
    "generic": np.array([0.1, 0.2, 0.3]),
}
WANT_CENTRED = {
    "spin": 1,
    "spin+1e-12": 1,
    "spin+1e-7": 0,
    "spin+1e-4": 0,
    "parallel": 1,
    "parallel+1e-12": 1,
    "parallel+1e-7": 0,
    "parallel+1e-4": 0,
    "generic": 0,
}


def _by_unit(f, kind):
    return {k: f(robot(kind, 10.0**k)) for k in KS}


@pytest.mark.parametrize("name", sorted(CONFIGS))
def test_mobility_of_the_centred_robot_in_every_unit(name):
    got = _by_unit(lambda bot: int(wmr.mobility(bot, CONFIGS[name])), "centred")
    assert set(got.values()) == {WANT_CENTRED[name]}, got


@pytest.mark.parametrize("kind", ["offset", "dual", "mixed"])
def test_mobility_of_other_robots_in_every_unit(kind):
    beta = np.random.default_rng(3).uniform(-np.pi, np.pi, (200, 3))
    beta[:20] = SPIN  # dual wheels: the spin about C again
    beta[20:40] = 0.0
    base = wmr.mobility(robot(kind), beta)
    for k in KS:
        assert np.array_equal(wmr.mobility(robot(kind, 10.0**k), beta), base), k


@pytest.mark.parametrize("L, r", [(1e300, 1e299), (1e-8, 1e-9), (1e12, 1e11), (1e-150, 1e-151), (1e4, 1e-4)])
def test_mobility_at_extreme_lengths(L, r):
    bot = wmr.paper_robot("centred", L=L, r=r)
    for name in ("spin", "parallel", "generic", "spin+1e-4"):
        assert int(wmr.mobility(bot, CONFIGS[name])) == WANT_CENTRED[name], (name, L, r)


def _grid():
    """2,430 points: 9 characteristic lengths x 5 radius ratios x 6 robot kinds/angle sets x 9 configurations."""
    out = []
    for L in 10.0 ** np.arange(-4, 5):
        for ratio in 10.0 ** np.arange(-4, 1):
            for kind in ("centred", "offset", "dual"):
                out.append((wmr.paper_robot(kind, L=L, r=ratio * L), np.array(list(CONFIGS.values()))))
                out.append((wmr.paper_robot(kind, L=L, r=ratio * L), np.array(list(CONFIGS.values())) + 0.3))
    return out


def test_rank_of_F_agrees_with_rank_F_on_a_grid():
    disagree = total = 0
    for bot, beta in _grid():
        dense = wmr.rank(bot.F(beta))
        fast = wmr.rank_F(bot, beta)
        assert np.array_equal(R.rank_F(bot, beta), dense)
        disagree += int(np.sum(dense != fast))
        total += len(beta)
    assert total == 2430 and disagree == 0, f"{disagree} of {total} grid points disagree"


def test_rank_does_not_depend_on_the_units_of_the_unknowns():
    rng = np.random.default_rng(0)
    A = rng.normal(size=(500, 4, 4))
    A[::2, :, 3] = A[::2, :, 0] - A[::2, :, 1] * 0.5  # exactly dependent columns
    base = wmr.rank(A)
    assert set(base.tolist()) == {3, 4}
    for k in KS:
        D = 10.0 ** rng.integers(-6, 7, size=4)  # a unit per unknown
        assert np.array_equal(wmr.rank(A * D), base), k
        assert np.array_equal(wmr.nullity(A * D), 4 - base)


@pytest.mark.parametrize("kind", ["centred", "offset", "dual", "mixed"])
def test_admissibility_in_every_unit(kind):
    rng = np.random.default_rng(11)
    twist = rng.normal(size=(60, 3))
    twist[:5, 0] = 0.0  # translations
    twist[5:10, 1:] = 0.0  # spins about C
    base = robot(kind)
    beta = rng.uniform(-np.pi, np.pi, (60, 3))
    beta[:30] = wmr.steering_angles(base, twist[:30], current=beta[:30])  # half of them steered to fit
    inv = wmr.inverse(base, beta, twist)
    want_inv, rates = inv.admissible, inv.value
    want_fwd = wmr.forward(base, beta, rates).admissible
    assert want_inv[:30].all() and want_fwd[:30].all()
    assert want_inv[30:].all() == (kind == "offset")  # offset wheels: any twist, any angles
    for k in [*KS, -100, -12, 12, 100]:  # and far beyond: no absolute zero anywhere
        s = 10.0**k
        bot = robot(kind, s)
        lin = np.array([1.0, s, s])  # [psi_dot, x_dot, y_dot] in the new unit
        assert np.array_equal(wmr.inverse(bot, beta, twist * lin).admissible, want_inv), k
        assert np.array_equal(wmr.forward(bot, beta, rates).admissible, want_fwd), k
        assert np.array_equal(wmr.steering_angles(bot, twist[:30] * lin, current=beta[:30]), beta[:30]) or np.allclose(
            wmr.steering_angles(bot, twist[:30] * lin, current=beta[:30]), beta[:30], atol=1e-12
        ), k


def test_admissible_twists_of_a_spin_in_every_unit():
    for k in KS:
        basis = wmr.admissible_twists(robot("centred", 10.0**k), SPIN)
        t = basis[:, 0] * [10.0**k, 1.0, 1.0]  # [L psi_dot, x_dot, y_dot]: one unit
        assert basis.shape == (3, 1) and np.allclose(np.abs(t) / np.linalg.norm(t), [1.0, 0.0, 0.0], atol=1e-12), k


def test_steering_and_instant_centre_in_every_unit():
    twists = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1e-12, 1.0, 0.0], [1.0, 0.3, -0.2], [0.0, 0.0, 0.0]])
    base = robot("centred")
    want_beta = wmr.steering_angles(base, twists)
    want_kind = wmr.instantaneous_centre(twists, length=1.0).kind
    for k in KS:
        s = 10.0**k
        bot = robot("centred", s)
        tw = twists * [1.0, s, s]
        assert np.allclose(wmr.steering_angles(bot, tw), want_beta, atol=1e-12), k
        assert np.array_equal(wmr.instantaneous_centre(tw, length=s).kind, want_kind), k


def test_isotropy_and_singularity_in_every_unit():
    beta = np.concatenate(
        [
            np.random.default_rng(5).uniform(-np.pi, np.pi, (300, 3)),
            [SPIN, np.zeros(3), [0.3, 0.3, 0.3], [2.0, 2.0 + np.pi, 2.0]],
        ]
    )
    base = robot("centred")
    L0 = wmr.characteristic_length(base)
    J0 = base.J(beta, L=L0)
    want_iso, want_inf = wmr.is_isotropic(J0), np.isinf(wmr.condition_number(J0))
    want_sing = S.is_singular(base, beta)
    assert want_sing[-3:].all() and want_inf[-3:].all() and not want_sing[:300].any()
    for k in KS:
        bot = robot("centred", 10.0**k)
        J = bot.J(beta, L=wmr.characteristic_length(bot))
        assert np.array_equal(wmr.is_isotropic(J), want_iso), k
        assert np.array_equal(np.isinf(wmr.condition_number(J)), want_inf), k
        assert np.array_equal(S.is_singular(bot, beta), want_sing), k
        assert np.array_equal(wmr.rank(J), LA.rank(J0)), k
        assert np.allclose(wmr.condition_number(J)[~want_inf], wmr.condition_number(J0)[~want_inf], rtol=1e-9)


@pytest.mark.parametrize("beta", [[0.3, 0.3, 0.3], [0.3, 0.3 + np.pi, 0.3], SPIN, [0.1, 0.5, -0.7]])
def test_classification_in_every_unit(beta):
    fams = {k: S.classify(robot("centred", 10.0**k), beta).family for k in KS}
    assert len(set(fams.values())) == 1, fams


# ------------------------------------------------------------------ finite in, finite out (or a clear error)
def test_characteristic_length_does_not_overflow():
    for L in (1e300, 1e-300, 1.0):
        got = wmr.characteristic_length(wmr.paper_robot("centred", L=L, r=L / 10))
        assert np.isfinite(got) and got == pytest.approx(L, rel=1e-12)


def test_tiny_L_overflows_loudly():
    bot = wmr.paper_robot("centred", L=1.0, r=0.1)
    for call in (lambda: bot.J([0.1, 0.2, 0.3], L=1e-320), lambda: bot.J1(L=1e-320)):
        with pytest.raises(ValueError, match=r"L .*1e-320"):
            call()


def test_huge_robots_and_twists():
    big = wmr.paper_robot("centred", L=1e300, r=1e299)
    sol = wmr.forward(big, [0.1, 0.2, 0.3], [1.0, 2.0, 3.0])  # was: "fewer than two distinct mount points"
    assert np.all(np.isfinite(sol.value)) and bool(sol.admissible) is False
    bot = wmr.paper_robot("centred", L=1.0, r=0.1)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            sol = wmr.inverse(bot, [0.0, 0.0, 0.0], [1.7e308] * 3)
        except ValueError as e:
            assert "twist" in str(e) and "1.7e+308" in str(e)
        else:
            assert np.all(np.isfinite(sol.value)) and np.all(np.isfinite(sol.residual))


def test_angular_tolerance_is_documented_and_true():
    """The decision of a near-singular configuration flips where tolerance.py says it does."""
    from wmr.model import tolerance

    bot = robot("centred")
    for family, base in (("spin", SPIN), ("parallel", np.zeros(3))):
        lo, hi = tolerance.ANGULAR_TOLERANCE / 100, tolerance.ANGULAR_TOLERANCE * 100
        assert int(wmr.mobility(bot, base + lo * E1)) == 1, family
        assert int(wmr.mobility(bot, base + hi * E1)) == 0, family
