"""The fused kernel of a drivable kappa(J) sweep (wmr.analysis.sweep.swerve_kappa) against a plain SVD.

The reference is the definition, written out: the coordinated steering angles of each twist
(wmr.steering_angles), J (56) from the dense reference product J_L1^T J_2, and kappa = s_max / s_min
from numpy.linalg.svd, inf where s_min <= TOL s_max (31).
"""

from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.analysis import reference as R
from wmr.analysis.sweep import Drivable, sweep
from wmr.analysis.sweep.motions import fused_kernel, kappa_J_of_twists
from wmr.analysis.sweep.swerve_kappa import SwerveKappa, swerve_like

EPS = np.finfo(float).eps
EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
SWERVE = wmr.load(EXAMPLES / "swerve4.toml")


def _robot(points, radii):
    return wmr.Robot([wmr.CentredWheel(tuple(p), r=float(r)) for p, r in zip(points, radii)], name="swerve-like")


def _lopsided(w, seed):
    """w centred wheels at random places with random radii (no symmetry at all)."""
    rng = np.random.default_rng(seed)
    return _robot(rng.uniform(-1.0, 1.0, (w, 2)), rng.uniform(0.03, 0.2, w))


ROBOTS = {
    "swerve4": SWERVE,
    "paper centred": wmr.paper_robot("centred"),
    "lopsided 4": _lopsided(4, 1),
    "lopsided 5": _lopsided(5, 2),
    "lopsided 6": _lopsided(6, 3),
}


def reference(robot, twist, L, current=None):
    """kappa(J) at the steering angles of each twist, by numpy.linalg.svd."""
    beta = wmr.steering_angles(robot, twist, current)
    s = np.linalg.svd(R.J(robot, beta, L), compute_uv=False)
    with np.errstate(divide="ignore"):
        return np.where(s[:, -1] <= wmr.TOL * s[:, 0], np.inf, s[:, 0] / s[:, -1])


def close(got, want):
    """Same singular members; elsewhere within 1e-12 or the SVD's own accuracy (~ eps kappa)."""
    fin = np.isfinite(want)
    if not np.array_equal(np.isfinite(got), fin):
        return False
    return bool(np.all(np.abs(got[fin] / want[fin] - 1) <= 1e-12 + 64 * EPS * want[fin]))


def _kernel(robot, twist, L):
    out, redo = np.empty(len(twist)), np.empty(len(twist), dtype=bool)
    SwerveKappa(robot, L)(np.asarray(twist, dtype=float), out, redo)
    return out, redo


@pytest.mark.parametrize("name", sorted(ROBOTS))
def test_kernel_equals_the_svd_on_sampled_twists(name):
    bot = ROBOTS[name]
    L = wmr.characteristic_length(bot)
    tw, _ = Drivable(20_000, seed=5).bind(bot).twists(0, 20_000)
    want = reference(bot, tw, L)
    out, redo = _kernel(bot, tw, L)
    # the closed form does the work (it is not the SVD fallback passing the test) and is right where it says so
    assert redo.mean() < 0.02
    assert close(out[~redo], want[~redo])
    assert close(kappa_J_of_twists(bot, tw, L), want)


def _exact(robot, twist, L):
    """kappa(J) in 40-digit arithmetic (mpmath), from the twist: columns (C_i a_i + S_i b_i) / |p_i|."""
    import mpmath

    from wmr.model.backend import NUMERIC

    mpmath.mp.dps = 40
    JL1, d = robot.J1(L=L), robot.mount_points
    out = []
    for psi, vx, vy in (map(mpmath.mpf, map(float, t)) for t in twist):
        M = mpmath.matrix(3, robot.w)
        for i, u in enumerate(robot.wheels):
            Li, ELi = (np.asarray(x, dtype=float)[:, 0] for x in u.block_terms(NUMERIC))
            A = mpmath.matrix(JL1[2 * i : 2 * i + 2].T.tolist())
            S, C = vx - psi * float(d[i, 1]), -vy - psi * float(d[i, 0])
            col = (C * (A * mpmath.matrix(Li.tolist())) + S * (A * mpmath.matrix(ELi.tolist()))) / mpmath.sqrt(
                S * S + C * C
            )
            for r in range(3):
                M[r, i] = col[r]
        s = mpmath.svd_r(M, compute_uv=False)
        out.append(float(max(s) / min(s)))
    return np.array(out)


def test_kernel_is_exact_near_translation():
    """Where kappa -> inf like 1/psi_dot the kernel keeps full accuracy (det J = psi_dot Q(t)); the SVD does not."""
    L = wmr.characteristic_length(SWERVE)
    psi = np.geomspace(1e-3, 1e-8, 6)
    tw = np.stack([psi, np.full(6, 0.6), np.full(6, -0.8)], axis=1)
    out, redo = _kernel(SWERVE, tw, L)
    assert not redo.any()
    assert np.all(np.abs(out / _exact(SWERVE, tw, L) - 1) <= 64 * EPS)
    assert close(out, reference(SWERVE, tw, L))


def _degenerate(bot):
    d = bot.mount_points
    U = np.array([0.2921 * np.sqrt(2.0), 0.0])  # on the circle through the four mount points
    return np.array(
        [
            [1.0, d[0, 1], -d[0, 0]],  # rotation about module 1 (rotation_twists): its mount point is still
            [1.0, d[2, 1], -d[2, 0]],  # about module 3
            [0.0, 0.0, 0.0],  # zero twist: every angle kept
            [0.0, 1.0, 0.0],  # translation: J singular
            [0.0, 0.3, -2.0],
            [1.0, 0.0, 0.0],  # spin about C
            [1.0, U[1], -U[0]],  # rotation about a point of the mount circle: J singular
            [1.0, 0.5, 0.25],
            [1.0, d[1, 1] + 1e-11, -d[1, 0]],  # 1e-11 from module 2: still by the rule of steering_angles
        ]
    )


def test_degenerate_twists():
    L = wmr.characteristic_length(SWERVE)
    tw = _degenerate(SWERVE)
    out, redo = _kernel(SWERVE, tw, L)
    assert redo[[0, 1, 2, 3, 4, 6, 8]].all()  # still wheels, zero twist, singular: the general kernels decide
    assert not redo[[5, 7]].any()
    want = reference(SWERVE, tw, L)
    assert np.isinf(want[[2, 3, 4, 6]]).all() and np.isfinite(want[[0, 1, 5, 7, 8]]).all()
    assert close(kappa_J_of_twists(SWERVE, tw, L), want)
    # a still wheel keeps the caller's angle, on which kappa depends: the kernel cannot decide those
    current = np.full((len(tw), 4), 0.7)
    assert not np.allclose(reference(SWERVE, tw, L, current)[[0, 1, 8]], want[[0, 1, 8]])


@pytest.mark.parametrize("unit", [1e-150, 1e-3, 1.0, 1e3, 1e150])
@pytest.mark.parametrize("speed", [1e-150, 1.0, 1e150])
def test_decisions_do_not_depend_on_units(unit, speed):
    """Every length times ``unit`` (mount points, radii, L, translational rates), the twist times ``speed``."""
    base = ROBOTS["lopsided 4"]
    bot = _robot(base.mount_points * unit, [u.r * unit for u in base.wheels])
    L = wmr.characteristic_length(base)
    tw, _ = Drivable(3000, seed=7).bind(base).twists(0, 3000)
    tw = np.concatenate([tw, _degenerate(base)])
    want = reference(base, tw, L)
    scaled = tw * [speed, speed * unit, speed * unit]
    got = kappa_J_of_twists(bot, scaled, L * unit)
    assert close(got, want)
    out, redo = _kernel(bot, scaled, L * unit)
    assert redo.mean() < 0.02 and close(out[~redo], want[~redo])


def test_sweep_reductions_equal_those_of_the_general_kernels():
    """The fused sweep and a sweep of the same configurations as explicit angles (no fused kernel) agree."""
    n = 1 << 17
    fused = sweep(SWERVE, "kappa_J", Drivable(n, seed=3))
    beta = Drivable(n, seed=3).bind(SWERVE).configurations(4, 0, n)
    general = sweep(SWERVE, "kappa_J", beta)
    assert fused.count == general.count == n and fused.infinite == general.infinite
    assert fused.worst_index == general.worst_index
    assert np.array_equal(fused.argmax, general.argmax) and np.array_equal(fused.argmin, general.argmin)
    assert fused.max == pytest.approx(general.max, rel=1e-12 + 64 * EPS * general.max)
    assert fused.min == pytest.approx(general.min, rel=1e-12)
    for q, v in general.quantiles.items():
        assert fused.quantiles[q] == pytest.approx(v, rel=1e-3)


def test_no_fused_kernel_for_other_robots():
    bot = wmr.load(EXAMPLES / "engineers" / "rover6.toml")  # fixed wheels too
    assert not swerve_like(bot) and fused_kernel(bot, 1.0) is None
    assert kappa_J_of_twists(bot, np.ones((2, 3)), 1.0) is None


@pytest.mark.parametrize("name", ["lopsided 4", "lopsided 6"])
def test_a_still_wheel_is_left_to_the_general_kernels(name):
    """A rotation about a point within TOL of a module: that wheel keeps the caller's angle (steering_angles)."""
    bot = ROBOTS[name]
    L = wmr.characteristic_length(bot)
    d = bot.mount_points
    near = np.array([[1.0, d[i, 1] + f, -d[i, 0] - f] for i in range(bot.w) for f in (1e-11, -3e-12)])
    out, redo = _kernel(bot, near, L)
    assert redo.all()
    want = reference(bot, near, L)
    assert close(kappa_J_of_twists(bot, near, L), want)
    coordinated = wmr.condition_number(R.J(bot, np.arctan2(*_velocity_angles(bot, near)), L))
    assert not np.allclose(coordinated, want)  # the angle the twist would give that wheel changes kappa


def _velocity_angles(bot, twist):
    """(p_x, -p_y) of every mount point: atan2 of these is the coordinated angle, even for a still wheel."""
    d = bot.mount_points
    px = twist[:, 1:2] - twist[:, 0:1] * d[:, 1]
    py = twist[:, 2:3] + twist[:, 0:1] * d[:, 0]
    return px, -py


def test_fused_sweep_does_not_depend_on_the_chunk():
    """The default chunk of a fused sweep (FUSED_CHUNK, 16 blocks of twists) and one block per chunk agree exactly."""
    from wmr.analysis.sweep.configurations import BLOCK
    from wmr.analysis.sweep.execute import FUSED_CHUNK

    n = 3 * BLOCK + 5
    assert n < FUSED_CHUNK  # (one chunk by default)
    a = sweep(SWERVE, "kappa_J", Drivable(n, seed=2), keep=True)
    b = sweep(SWERVE, "kappa_J", Drivable(n, seed=2), keep=True, chunk=BLOCK)
    assert a.values is not None and b.values is not None
    assert np.array_equal(a.values, b.values) and a.quantiles == b.quantiles and a.worst_index == b.worst_index


def test_fused_sweep_on_dask_equals_in_process():
    """The bound source travels to the workers without its kernel, which each worker builds where it first uses it."""
    distributed = pytest.importorskip("dask.distributed")
    from wmr.analysis.sweep.configurations import BLOCK

    local = sweep(SWERVE, "kappa_J", Drivable(2 * BLOCK + 7, seed=4), keep=True)
    with (
        distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster,
        distributed.Client(cluster) as client,
    ):
        remote = sweep(SWERVE, "kappa_J", Drivable(2 * BLOCK + 7, seed=4), keep=True, chunk=BLOCK, client=client)
    assert remote.values is not None and local.values is not None
    assert np.array_equal(remote.values, local.values) and remote.quantiles == local.quantiles
    assert remote.worst_index == local.worst_index
