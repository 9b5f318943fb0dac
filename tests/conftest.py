"""Shared test set-up: a deterministic Hypothesis profile, strategies and first-principles helpers.

Everything here is computed *independently of the package* (3D cross products, explicit frame
changes) so that the tests compare :mod:`wmr` with the physics, not with itself.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

import wmr
from wmr.io.decimals import DIGITS

# --- determinism: a fixed, bounded Hypothesis profile -------------------------------------------
settings.register_profile(
    "wmr",
    derandomize=True,
    database=None,
    max_examples=25,
    deadline=None,
    print_blob=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much, HealthCheck.function_scoped_fixture],
)
settings.load_profile("wmr")


def pytest_configure(config):
    """Before collection: nbformat imports jsonschema, which compiles the grammar of ``rfc3987_syntax``
    when it is installed (3 s of every test process) for the "iri" format, which no notebook schema uses."""
    sys.modules.setdefault("rfc3987_syntax", None)  # type: ignore[arg-type]


#: the repository this test suite belongs to
ROOT = Path(__file__).resolve().parents[1]

#: how far a number read back from a file wmr wrote may be from the number written, relative to its scale: the
#: files keep DIGITS significant digits (:mod:`wmr.io.decimals`), and matrices rebuilt from them add round-off
WRITTEN = 10.0 ** (2 - DIGITS)

KINDS = ("offset", "centred", "dual")
K = np.array([0.0, 0.0, 1.0])


# --- first principles (no wmr) --------------------------------------------------------------------
def vec3(v2):
    """Planar vector(s) (..., 2) -> spatial (..., 3) with zero z."""
    v2 = np.asarray(v2, dtype=float)
    return np.concatenate([v2, np.zeros(v2.shape[:-1] + (1,))], axis=-1)


def rigid_velocity(omega, v_ref, r_rel):
    """Velocity of a point of a body turning at ``omega`` about k: v_ref + (omega k) x r_rel (3D cross)."""
    omega = np.asarray(omega, dtype=float)
    w3 = omega[..., None] * K
    return np.asarray(v_ref, dtype=float) + np.cross(w3, vec3(r_rel))[..., :2]


def axle(beta):
    """i_i = (cos beta, sin beta), the axle direction in the body frame."""
    beta = np.asarray(beta, dtype=float)
    return np.stack([np.cos(beta), np.sin(beta)], axis=-1)


def rolling_dir(beta):
    """j_i = k x i_i, the rolling direction (computed with a cross product)."""
    return np.cross(K, vec3(axle(beta)))[..., :2]


def wheel_centre_velocity(theta_dot, phi_dot, beta, r):
    """Velocity of a wheel centre H from no slip at the contact point Q = H - r k.

    The wheel turns at theta_dot about its axle i and at phi_dot about k; Q has zero velocity:
    v_H = -omega x (Q - H) = omega x (r k).
    """
    i3 = vec3(axle(beta))
    omega = np.asarray(theta_dot, float)[..., None] * i3 + np.asarray(phi_dot, float)[..., None] * K
    return np.cross(omega, r * K)[..., :2]


def hub_velocity(kind, beta, r, rates, roller=None):
    """Velocity of the hub of a wheel without a steering joint, from no slip at the contact point (3D, no wmr).

    Fixed wheel: omega = theta_dot i, v_H = omega x (r k).  Swedish wheel: the roller (axis a,
    horizontal) spins at sigma_dot about a; with a contact radius r the hub moves by
    (theta_dot i + sigma_dot a) x (r k) (see SwedishWheel's docstring for a general roller radius).
    """
    i3 = vec3(axle(beta))
    omega = rates[0] * i3
    if kind == "swedish":
        a3 = vec3(axle(beta + roller))  # the roller axis: the axle turned by gamma
        omega = omega + rates[1] * a3
    return np.cross(omega, r * K)[:2]


def unit_mount_velocity(unit, beta, rates, psi_dot=0.0):
    """Velocity of the steering-axis point P of one unit from its wheels' no-slip conditions.

    Returns (v_P, phi_dot): phi_dot is the absolute turning rate of the intermediate body
    (None for a centred wheel, whose steering is decoupled).
    """
    rates = np.asarray(rates, dtype=float)
    i_dir, j_dir = axle(beta), rolling_dir(beta)
    if unit.kind == "centred":
        return wheel_centre_velocity(rates[..., 0], 0.0, beta, unit.r), None
    if unit.kind == "offset":
        phi_dot, theta_dot = rates[..., 0], rates[..., 1]
        vH = wheel_centre_velocity(theta_dot, phi_dot, beta, unit.r)
        # H = P - d j  =>  P - H = d j
        return rigid_velocity(phi_dot, vH, unit.d * j_dir), phi_dot
    # dual: wheel k at P +/- b i; both centres are points of the intermediate body
    th1, th2 = rates[..., 0], rates[..., 1]
    v1 = wheel_centre_velocity(th1, 0.0, beta, unit.r)
    v2 = wheel_centre_velocity(th2, 0.0, beta, unit.r)
    # rigid body: v1 - v2 = phi_dot k x (2 b i) = 2 b phi_dot j
    phi_dot = np.sum((v1 - v2) * j_dir, axis=-1) / (2 * unit.b)
    vP = rigid_velocity(phi_dot, v1, -unit.b * i_dir)
    return vP, phi_dot


def transform_twist(twist, origin, angle):
    """Twist seen from a body frame with origin at ``origin`` (old body coords) rotated by ``angle``."""
    twist = np.asarray(twist, dtype=float)
    psi = twist[..., 0]
    vO = rigid_velocity(psi, twist[..., 1:], np.broadcast_to(np.asarray(origin, float), twist[..., 1:].shape))
    c, s = np.cos(angle), np.sin(angle)
    new = np.stack([c * vO[..., 0] + s * vO[..., 1], -s * vO[..., 0] + c * vO[..., 1]], axis=-1)
    return np.concatenate([psi[..., None], new], axis=-1)


def twist_map(origin, angle):
    """The 3x3 linear map of :func:`transform_twist`."""
    return np.stack([transform_twist(e, origin, angle) for e in np.eye(3)], axis=-1)


def same_subspace(A, B, tol=1e-7):
    """True when the columns of A and B span the same subspace."""
    A, B = np.asarray(A, float), np.asarray(B, float)
    if A.shape[1] != B.shape[1]:
        return False
    if A.shape[1] == 0:
        return True
    qa, _ = np.linalg.qr(A)
    qb, _ = np.linalg.qr(B)
    return np.allclose(qa @ qa.T, qb @ qb.T, atol=tol)


def wrap(a):
    """Angles to (-pi, pi]."""
    return -((-np.asarray(a, float) + np.pi) % (2 * np.pi) - np.pi)


def angle_close(a, b, atol=1e-9, period=2 * np.pi):
    d = (np.asarray(a, float) - np.asarray(b, float)) % period
    return np.all(np.minimum(d, period - d) <= atol)


def steered_beta(robot, twist, seed=0):
    """Steering angles that make ``twist`` admissible: centred/dual from steering_angles,
    offset wheels random (they can realise any twist at any angle)."""
    rng = np.random.default_rng(seed)
    current = rng.uniform(-np.pi, np.pi, robot.w)
    return wmr.steering_angles(robot, twist, current=current)


def noncollinear(points, rel=0.05):
    """The points are well away from lying on one line (smallest singular value of [x y 1])."""
    P = np.asarray(points, float)
    if len(P) < 3:
        return False
    M = np.column_stack([P - P.mean(axis=0), np.zeros(len(P))])
    s = np.linalg.svd(M[:, :2], compute_uv=False)
    return s[-1] >= rel * max(1.0, s[0])


# --- strategies ----------------------------------------------------------------------------------
seeds = st.integers(0, 2**32 - 1)
angles = st.floats(-np.pi, np.pi, allow_nan=False, allow_infinity=False)
lengths = st.floats(0.02, 1.0, allow_nan=False, allow_infinity=False)
# coordinates of a robot in its own unit: 0 or 1e-3 .. 2 in size (robots whose mount points are
# 1e-300 apart while the twist is of order 1 make ill-posed problems; every unit is tried in test_units)
coords = st.one_of(st.just(0.0), st.floats(1e-3, 2.0), st.floats(-2.0, -1e-3))


def make_unit(kind, position, r, d=None, b=None):
    if kind == "offset":
        return wmr.OffsetWheel(position, r=r, d=d)
    if kind == "centred":
        return wmr.CentredWheel(position, r=r)
    return wmr.DualWheel(position, r=r, b=b)


@st.composite
def mount_sets(draw, w_min=1, w_max=4, spread=False):
    """Mount points; ``spread`` places them around a centre so that w >= 3 are never collinear."""
    w = draw(st.integers(w_min, w_max))
    if not spread:
        return [(draw(coords), draw(coords)) for _ in range(w)]
    cx, cy = draw(st.floats(-1, 1)), draw(st.floats(-1, 1))
    pts = []
    for k in range(w):
        a = 2 * np.pi * k / w + draw(st.floats(-0.4, 0.4))
        rad = draw(st.floats(0.3, 2.0))
        pts.append((cx + rad * np.cos(a), cy + rad * np.sin(a)))
    return pts


@st.composite
def robots(draw, kinds=KINDS, w_min=1, w_max=4, spread=False, same_kind=False):
    """Random robots: random mount points, radii, offsets (> 0), separations, wheel types, mixtures."""
    pts = draw(mount_sets(w_min, w_max, spread))
    if spread and len(pts) >= 3:
        from hypothesis import assume

        assume(noncollinear(pts))
    kind0 = draw(st.sampled_from(kinds))
    units = []
    for p in pts:
        kind = kind0 if same_kind else draw(st.sampled_from(kinds))
        units.append(make_unit(kind, p, draw(lengths), d=draw(lengths), b=draw(lengths)))
    return wmr.Robot(units)


def with_kind(robot, kind):
    """The same geometry (mount points, radii) with every unit replaced by ``kind``."""
    return wmr.Robot(
        [make_unit(kind, u.position, u.r, d=getattr(u, "d", u.r) or u.r, b=getattr(u, "b", u.r)) for u in robot.wheels]
    )


def random_twist(seed, scale=1.0):
    rng = np.random.default_rng(seed)
    return rng.normal(size=3) * scale


@pytest.fixture
def paper_centred():
    return wmr.paper_robot("centred", L=0.3, r=0.05)


# --- properties shared by several test modules (and the mutation test) ----------------------------
def check_J1_first_principles(robot, twist):
    """J1 t stacks the velocities of the mount points, computed with 3D cross products."""
    got = (robot.J1() @ twist).reshape(robot.w, 2)
    want = rigid_velocity(twist[0], twist[1:], robot.mount_points)
    assert np.allclose(got, want, atol=1e-12), (got, want)


def check_J2_first_principles(robot, beta, rates):
    """J2 theta_dot stacks the mount-point velocities implied by the wheels' no-slip conditions."""
    got = (robot.J2(beta) @ rates).reshape(robot.w, 2)
    for i, (u, sl) in enumerate(zip(robot.wheels, robot.rate_slices)):
        want, _ = unit_mount_velocity(u, beta[i], rates[sl])
        assert np.allclose(got[i], want, atol=1e-12), (u.kind, got[i], want)


def check_round_trip(robot, twist, seed=0):
    """forward(inverse(t)) = t at steering angles that make t admissible."""
    beta = steered_beta(robot, twist, seed)
    inv = wmr.inverse(robot, beta, twist)
    assert bool(inv.admissible), inv.residual
    fwd = wmr.forward(robot, beta, inv.value)
    assert bool(fwd.admissible)
    assert np.allclose(fwd.value, twist, atol=1e-9 * max(1.0, np.abs(twist).max()))


def check_positive_rolling(robot, twist):
    """steering_angles chooses the wheel orientation that rolls forwards (theta_dot > 0)."""
    beta = wmr.steering_angles(robot, twist)
    rates = wmr.inverse(robot, beta, twist).value
    for u, sl in zip(robot.wheels, robot.rate_slices):
        if u.kind == "centred":
            assert rates[sl][0] > 0, rates
        elif u.kind == "dual":
            assert rates[sl].sum() > 0, rates


def check_offset_steer_only(robot, omega=0.7, t_end=1.0, dt=0.01):
    """All offset arms parallel, steered without driving: C moves on a circle of radius d and the
    wheel centres (contact points) do not move."""
    beta0 = np.full(robot.w, 0.3)
    rates = np.zeros(robot.n_rates)
    rates[0::2] = omega  # phi_dot_i = omega, theta_dot_i = 0
    traj = wmr.integrate(robot, rates, beta0, t_end, dt)
    d = robot.wheels[0].d
    # first principles: with the platform translating (psi = 0), C - H_1 = d_1 + d j(beta)
    C = traj.pose[:, 1:]
    H1 = traj.unit_points(0, "H")
    assert np.allclose(H1, H1[0], atol=1e-8), "wheel centre moved without rolling"
    centre = C[0] - d * rolling_dir(beta0[0])
    assert np.allclose(np.linalg.norm(C - centre, axis=-1), d, atol=1e-8)
    assert np.allclose(traj.pose[:, 0], 0.0, atol=1e-10)
    assert np.allclose(traj.slip, 0.0, atol=1e-9)
