"""Package facts behind notebooks 05 (equations (60)-(65)) and 06 (dual wheels, conclusions).

Each test fails if the model (frames, no-slip blocks, steering law) changes in a way that would
change a verdict: the printed (60) and (65) must fail under the package's frames and the
derived forms must hold.
"""

import numpy as np
import pytest
import sympy as sp

import wmr
from edition import printed
from edition import symbols as S
from edition.verify import SEED, symbolic_equal
from wmr.analysis.mobility import admissible_twists, mobility, rank_F
from wmr.analysis.steering import AT_INFINITY, FINITE, STILL
from wmr.model.tolerance import TOL

N = 500


@pytest.fixture
def rng():
    return np.random.default_rng(SEED)


def rotations(rng, n=N):
    tw = rng.normal(size=(n, 3))
    tw[:, 0] = np.sign(tw[:, 0]) * rng.uniform(0.2, 2.0, n)
    return tw


def evaluate(expr, syms, *cols):
    exprs = list(expr) if isinstance(expr, sp.MatrixBase) else [expr]
    vals = sp.lambdify(syms, exprs, "numpy")(*cols)
    out = np.stack(np.broadcast_arrays(*[np.asarray(v, dtype=float) for v in vals]), axis=-1)
    return out if isinstance(expr, sp.MatrixBase) else out[..., 0]


@pytest.mark.parametrize("eq", ["60", "61", "62", "63", "64", "65"])
def test_printed_forms_registered(eq):
    p = printed(eq)
    assert p.section.startswith("5.4") and p.latex and p.expr is not None


def test_instantaneous_centre_is_printed_63_and_at_rest(rng):
    tw = rotations(rng)
    ic = wmr.instantaneous_centre(tw)
    assert np.all(ic.kind == FINITE)
    uc = evaluate(printed(63).expr, (S.psi_dot, S.x_dot, S.y_dot), *tw.T)
    assert np.max(np.abs(uc - ic.point)) < TOL
    assert np.max(np.abs(wmr.point_velocity(tw, ic.point))) < TOL


def test_instantaneous_centre_limits():
    kinds = [int(wmr.instantaneous_centre(t).kind) for t in ([0, 1.0, 2.0], [0, 0, 0], [1.0, 0, 0])]
    assert kinds == [AT_INFINITY, STILL, FINITE]
    far = wmr.instantaneous_centre([1e-8, 0.3, -0.4])
    assert np.allclose(far.direction, wmr.instantaneous_centre([0, 0.3, -0.4]).direction)


def test_centre_to_wheels_is_printed_64(rng):
    bot = wmr.paper_robot("centred", L=0.4, r=0.1)
    tw, d = rotations(rng), bot.mount_points
    ui = np.stack(
        [evaluate(printed(64).expr, (S.psi_dot, S.x_dot, S.y_dot, S.dx, S.dy), *tw.T, *d[i]) for i in range(3)], axis=1
    )
    assert np.max(np.abs(ui - wmr.centre_to_wheels(tw, d))) < TOL


def test_point_velocity_is_printed_62(rng):
    tw, uc = rng.normal(size=(N, 3)), rng.normal(size=(N, 2))
    v = evaluate(printed(62).expr, (S.psi_dot, S.x_dot, S.y_dot, *S.u_c), *tw.T, *uc.T)
    assert np.max(np.abs(v - wmr.point_velocity(tw, uc))) < TOL


@pytest.mark.parametrize("kind", ["centred", "dual"])
def test_steering_angles_axles_point_at_centre(kind, rng):
    bot = wmr.paper_robot(kind, L=0.4, r=0.1, b=0.05) if kind == "dual" else wmr.paper_robot(kind, L=0.4, r=0.1)
    tw = rotations(rng)
    beta = wmr.steering_angles(bot, tw)
    assert np.all(rank_F(bot, beta) == 3 + bot.n_rates - mobility(bot, beta))
    assert np.all(mobility(bot, beta) == 1 + (3 if kind == "dual" else 0))
    assert wmr.inverse(bot, beta, tw).admissible.all()
    ui = wmr.centre_to_wheels(tw, bot.mount_points)
    cross = np.cos(beta) * ui[..., 1] - np.sin(beta) * ui[..., 0]  # i_i x u_i
    assert np.max(np.abs(cross) / np.linalg.norm(ui, axis=-1)) < TOL


def test_printed_60_puts_axle_along_velocity(rng):
    bot = wmr.paper_robot("centred", L=0.4, r=0.1)
    psi = rng.uniform(-np.pi, np.pi, N)
    V = rng.normal(size=(N, 2))
    c, s = np.cos(psi), np.sin(psi)
    tw = np.column_stack([np.zeros(N), c * V[:, 0] + s * V[:, 1], -s * V[:, 0] + c * V[:, 1]])
    phi_printed = evaluate(printed(60).expr.rhs, (S.X_dot, S.Y_dot), *V.T)
    phi_true = np.arctan2(V[:, 1], V[:, 0]) + np.pi / 2
    for phi, ok in ((phi_printed, False), (phi_true, True)):
        beta = np.repeat((phi - psi)[:, None], 3, axis=1)
        sol = wmr.inverse(bot, beta, tw)
        assert np.all(sol.admissible == ok)
    sol = wmr.inverse(bot, np.repeat((phi_printed - psi)[:, None], 3, axis=1), tw)
    slip = np.linalg.norm(sol.residual.reshape(N, 3, 2), axis=-1)
    assert np.allclose(slip, np.linalg.norm(V, axis=-1)[:, None], atol=TOL)  # full speed sideways


def test_printed_65_jams_derived_does_not(rng):
    bot = wmr.paper_robot("centred", L=0.4, r=0.1)
    tw = rotations(rng)
    uc = wmr.instantaneous_centre(tw).point
    ui = wmr.centre_to_wheels(tw, bot.mount_points)
    cos_p = evaluate(printed(65).expr.rhs, (*S.u_c, *S.u_i), uc[:, None, 0], uc[:, None, 1], ui[..., 0], ui[..., 1])
    b = np.arccos(np.clip(cos_p, -1, 1))
    for sign in (1, -1):
        assert np.all(rank_F(bot, sign * b) == 6)
    derived = np.arctan2(ui[..., 1], ui[..., 0])
    assert np.all(rank_F(bot, derived) == 5)
    assert wmr.inverse(bot, derived, tw).admissible.all()


def test_printed_65_holds_when_centre_on_positive_x_axis():
    a = sp.Symbol("a", positive=True)
    rhs = printed(65).expr.rhs.subs({S.u_c[0]: a, S.u_c[1]: 0})
    assert symbolic_equal(rhs, sp.cos(sp.atan2(S.u_i[1], S.u_i[0])))


def test_dual_equivalent_to_centred(rng):
    avg = sp.Matrix([[sp.Rational(1, 2), sp.Rational(1, 2)]])
    cen_s = wmr.paper_robot("centred", L=S.L, r=S.r, exact=True)
    dual_s = wmr.paper_robot("dual", L=S.L, r=S.r, b=S.b, exact=True)
    assert symbolic_equal(dual_s.F(), cen_s.F() * sp.diag(sp.eye(3), avg, avg, avg))
    pts = rng.uniform(-1, 1, (3, 2))
    cen = wmr.Robot([wmr.CentredWheel(tuple(p), r=0.1) for p in pts])
    dual = wmr.Robot([wmr.DualWheel(tuple(p), r=0.1, b=0.07) for p in pts])
    for k in range(40):
        beta = wmr.steering_angles(cen, rng.normal(size=3)) if k % 2 else rng.uniform(-np.pi, np.pi, 3)
        A, B = admissible_twists(cen, beta), admissible_twists(dual, beta)
        assert A.shape == B.shape
        assert np.max(np.abs(A @ A.T - B @ B.T)) < TOL
        assert int(mobility(dual, beta)) == int(mobility(cen, beta)) + 3


def test_dual_corrected_steering_law_is_slip_free():
    dual = wmr.paper_robot("dual", L=0.4, r=0.1, b=0.05)
    tw = np.array([0.5, 0.2, -0.1])
    beta0 = wmr.steering_angles(dual, tw)
    rates = wmr.inverse(dual, beta0, tw).value
    th = rates.reshape(3, 2)
    assert np.allclose(th[:, 0] - th[:, 1], -(2 * 0.05 / 0.1) * tw[0])  # corrected (15)
    run = wmr.integrate(dual, rates, beta0, t_end=1.0, dt=0.02)
    assert run.slip.max() < TOL and np.abs(run.beta - beta0).max() < TOL
    printed_law = np.repeat(th.mean(axis=1), 2)  # printed (15): no difference
    run = wmr.integrate(dual, printed_law, beta0, t_end=1.0, dt=0.02)
    assert run.slip.max() > 0.01


def test_centred_needs_resteer_offset_does_not(rng):
    cen = wmr.paper_robot("centred", L=0.4, r=0.1)
    off = wmr.paper_robot("offset", L=0.4, r=0.1, d=0.1)
    t0, t1 = rng.normal(size=(N, 3)), rng.normal(size=(N, 3))
    b0 = wmr.steering_angles(cen, t0)
    assert not wmr.inverse(cen, b0, t1).admissible.any()
    assert wmr.inverse(cen, b0, -2.0 * t0).admissible.all()  # reversal: no re-steering
    assert wmr.inverse(off, rng.uniform(-np.pi, np.pi, (N, 3)), t1).admissible.all()
