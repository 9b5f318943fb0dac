"""wmr.analysis.sweep: chunked sweeps against a direct evaluation of every configuration."""

import math

import numpy as np
import pytest

import wmr
from wmr.analysis import reference as R
from wmr.analysis.sweep import ANALYSES, SKETCH_ACCURACY, Grid, Sample, sweep
from wmr.io.decimals import quantise

QS = (0.0, 0.01, 0.25, 0.5, 0.9, 0.99, 1.0)


def _direct(robot, name, beta, L):
    """Every value, from the dense reference definitions."""
    if name == "rank_F":
        return R.rank_F(robot, beta).astype(float)
    if name == "mobility":
        return (3 + robot.n_rates - R.rank_F(robot, beta)).astype(float)
    if name == "det_J":
        return R.det(R.J(robot, beta, L))
    if name == "kappa_J":
        return R.condition_number(R.J(robot, beta, L))
    if name == "actuated_mobility":
        return np.array([_actuated_dense(robot, b) for b in beta], dtype=float)
    return np.full(len(beta), float(R.condition_number(robot.J1(L))))


def _twist_dim(F, cols):
    """dim of the twist part of N(F[:, cols]) by SVDs of the column-scaled dense matrix (cols include the twist)."""
    A = F[:, cols] / np.linalg.norm(F[:, cols], axis=0).clip(1e-300)
    _, s, Vt = np.linalg.svd(A)
    r = int((s > wmr.TOL * s[0]).sum())
    N = Vt[r:].T  # null space, scaled coordinates
    if N.shape[1] == 0:
        return 0
    sv = np.linalg.svd(N[:3], compute_uv=False)
    return int((sv > 1e-6).sum())


def _actuated_dense(robot, beta):
    """dim T - dim U from the dense F: every rate column free, then only the passive ones."""
    from wmr.analysis.actuation import driven_columns

    F = robot.F(beta)
    passive = np.flatnonzero(~driven_columns(robot)) + 3
    return _twist_dim(F, list(range(F.shape[1]))) - _twist_dim(F, [0, 1, 2, *passive])


def test_det_J_of_a_non_square_J_is_refused():
    for kind in ("offset", "dual"):
        with pytest.raises(ValueError, match="needs a square J"):
            sweep(_robots()[kind], "det_J", Grid(3))


def _all_configurations(angles, w):
    return angles.configurations(w, 0, angles.size(w))


def _robots():
    return {
        "centred": wmr.paper_robot("centred", L=0.3, r=0.05),
        "offset": wmr.paper_robot("offset", L=0.3, r=0.05),
        "dual": wmr.paper_robot("dual", L=0.3, r=0.05, b=0.04),
    }


#: (robot, analysis) pairs that exist: det J only for a square J (the centred robot's n_rates = 3)
CASES = [
    (kind, name)
    for kind, robot in _robots().items()
    for name in sorted(ANALYSES)
    if not (ANALYSES[name].square and robot.n_rates != 3)
]


@pytest.mark.parametrize("kind, name", CASES)
def test_sweep_equals_direct_evaluation(kind, name):
    robot = _robots()[kind]
    grid = Grid(11)  # includes -pi, 0 and the singular parallel settings
    beta = _all_configurations(grid, robot.w)
    L = wmr.characteristic_length(robot)
    want = _direct(robot, name, beta, L)
    res = sweep(robot, name, grid, quantiles=QS, chunk=97, keep=True)
    an = ANALYSES[name]
    assert res.values is not None  # keep=True
    assert res.count == len(beta) == 11**3
    fin = np.isfinite(want)
    assert np.array_equal(np.isinf(res.values), ~fin)
    assert np.allclose(res.values[fin], want[fin], rtol=1e-9, atol=1e-12)
    assert res.infinite == int(np.sum(~fin))
    # the extremes, and where they are: the first value equal to the extreme as written (12 digits, wmr.io.decimals),
    # so that round-off (a constant analysis; another CPU's last bits) does not choose the configuration
    v = res.values
    q = quantise(v, 1.0)
    assert res.min == v.min() and res.max == v.max()
    assert np.array_equal(res.argmin, beta[np.argmin(q)]) and np.array_equal(res.argmax, beta[np.argmax(q)])
    k = {"min": np.argmin(q), "max": np.argmax(q), "min_abs": np.argmin(np.abs(q))}[an.worst]
    worst = {"min": v.min(), "max": v.max(), "min_abs": np.abs(v).min()}[an.worst]
    assert res.worst_index == k and np.array_equal(res.worst_angles, beta[k]) and res.worst == worst
    assert abs(quantise(v[k], 1.0)) == abs(quantise(worst, 1.0))
    # quantiles: exact for integer analyses, within the sketch's relative accuracy otherwise
    for q, got in res.quantiles.items():
        exact = np.quantile(v, q, method="lower")
        if an.integer or q in (0.0, 1.0) or not np.isfinite(exact):
            assert got == exact, (q, got, exact)
        else:
            assert abs(got - exact) <= SKETCH_ACCURACY * abs(exact) * (1 + 1e-12), (q, got, exact)
    if an.integer:
        values, counts = np.unique(v.astype(int), return_counts=True)
        assert res.counts == dict(zip(values.tolist(), counts.tolist()))


def test_result_does_not_depend_on_chunks():
    robot = _robots()["centred"]
    sample = Sample(5000, seed=7)
    results = [sweep(robot, "kappa_J", sample, chunk=c) for c in (1, 4999, 5000, 1 << 20)]
    first = results[0]
    for r in results[1:]:
        assert (r.min, r.max, r.worst_index, r.quantiles, r.infinite) == (
            first.min,
            first.max,
            first.worst_index,
            first.quantiles,
            first.infinite,
        )
    a = sweep(robot, "det_J", Grid(9), chunk=10, keep=True)
    b = sweep(robot, "det_J", Grid(9), chunk=729, keep=True)
    assert a.values is not None and b.values is not None
    assert np.array_equal(a.values, b.values) and a.quantiles == b.quantiles and a.worst_index == b.worst_index


def test_sample_is_reproducible_and_in_range():
    s = Sample(200_000, seed=3, lo=-1.0, hi=2.0)
    whole = s.configurations(4, 0, 200_000)
    assert whole.shape == (200_000, 4) and whole.min() >= -1.0 and whole.max() < 2.0
    assert np.array_equal(s.configurations(4, 65_000, 140_001), whole[65_000:140_001])
    assert not np.array_equal(Sample(10, seed=4).configurations(2, 0, 10), Sample(10, seed=3).configurations(2, 0, 10))


@pytest.mark.parametrize("w, start, stop", [(3, 0, 10), (5, 1000, 2000), (2, 65_530, 65_540), (7, 131_071, 131_073)])
def test_sample_rows_are_those_of_the_whole_block(w, start, stop):
    """A chunk drawn alone (the block's generator advanced past the rows before it) is the block's rows."""
    from wmr.analysis.sweep.configurations import BLOCK

    s = Sample(200_000, seed=5, lo=-2.0, hi=1.0)
    first = start // BLOCK
    blocks = np.concatenate([np.random.default_rng([5, j]).uniform(-2.0, 1.0, (BLOCK, w)) for j in (first, first + 1)])
    assert np.array_equal(s.configurations(w, start, stop), blocks[start - first * BLOCK : stop - first * BLOCK])


def test_grid_numbering():
    g = Grid((2, 3), lo=0.0, hi=3.0)
    assert g.size(2) == 6
    got = g.configurations(2, 0, 6)
    want = np.array([[a, b] for a in (0.0, 1.5) for b in (0.0, 1.0, 2.0)])
    assert np.array_equal(got, want)
    assert np.array_equal(g.configurations(2, 4, 6), want[4:])


def test_explicit_angles_and_progress():
    robot = _robots()["centred"]
    beta = np.random.default_rng(1).uniform(-np.pi, np.pi, (1000, 3))
    seen = []
    res = sweep(robot, "rank_F", beta, chunk=300, progress=lambda done, total: seen.append((done, total)))
    assert seen == [(300, 1000), (600, 1000), (900, 1000), (1000, 1000)]
    assert res.counts == dict(zip(*[a.tolist() for a in np.unique(R.rank_F(robot, beta), return_counts=True)]))


def test_worst_configuration_is_singular():
    """The worst det J of the paper's robot on a grid through beta = 0 is an exact zero (parallel wheels)."""
    robot = _robots()["centred"]
    res = sweep(robot, "det_J", Grid(8))
    assert res.worst == 0.0
    assert abs(float(R.det(R.J(robot, res.worst_angles, wmr.characteristic_length(robot))))) < 1e-15
    assert sweep(robot, "kappa_J", Grid(8)).worst == math.inf


def test_kappa_JL1_is_constant():
    robot = wmr.Robot([wmr.CentredWheel(p, r=0.1) for p in [(1.0, 0.0), (-0.5, 0.5), (-0.2, -0.9)]])
    res = sweep(robot, "kappa_JL1", Sample(100))
    want = float(R.condition_number(robot.J1(wmr.characteristic_length(robot))))
    assert res.min == res.max == want and all(v == want for v in res.quantiles.values())


def test_sweep_on_dask_equals_in_process():
    distributed = pytest.importorskip("dask.distributed")
    robot = _robots()["centred"]
    grid = Grid(10)
    local = sweep(robot, "kappa_J", grid, chunk=100, keep=True)
    with (
        distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster,
        distributed.Client(cluster) as client,
    ):
        seen = []
        remote = sweep(
            robot, "kappa_J", grid, chunk=100, keep=True, client=client, progress=lambda done, total: seen.append(done)
        )
        ranks = sweep(robot, "rank_F", grid, chunk=64, client=client)
    assert remote.values is not None and local.values is not None
    assert np.array_equal(remote.values, local.values)
    assert (remote.min, remote.max, remote.worst_index, remote.quantiles, remote.infinite) == (
        local.min,
        local.max,
        local.worst_index,
        local.quantiles,
        local.infinite,
    )
    assert seen[-1] == 1000 and sorted(seen) == seen
    assert ranks.counts == sweep(robot, "rank_F", grid).counts


@pytest.mark.parametrize(
    "call, exc, words",
    [
        (lambda r: sweep("robot", "rank_F", Grid(3)), TypeError, "robot"),  # type: ignore[arg-type]
        (lambda r: sweep(r, 3, Grid(3)), TypeError, "analysis"),  # type: ignore[arg-type]
        (lambda r: sweep(r, "rank", Grid(3)), ValueError, "analysis"),
        (lambda r: sweep(wmr.paper_robot("offset"), "det_J", Grid(3)), ValueError, "square"),
        (lambda r: sweep(r, "rank_F", "grid"), TypeError, "angles"),
        (lambda r: sweep(r, "rank_F", np.zeros((4, 2))), ValueError, "angles"),
        (lambda r: sweep(r, "rank_F", np.full((4, 3), np.nan)), ValueError, "angles"),
        (lambda r: sweep(r, "rank_F", np.zeros((0, 3))), ValueError, "angles"),
        (lambda r: sweep(r, "rank_F", Grid(3), quantiles=[1.5]), ValueError, "quantiles"),
        (lambda r: sweep(r, "rank_F", Grid(3), chunk=0), ValueError, "chunk"),
        (lambda r: sweep(r, "rank_F", Grid(3), chunk=2.5), TypeError, "chunk"),  # type: ignore[arg-type]
        (lambda r: sweep(r, "rank_F", Grid(3), progress=5), TypeError, "progress"),  # type: ignore[arg-type]
        (lambda r: sweep(r, "rank_F", Grid(3), client=object()), TypeError, "client"),
        (lambda r: sweep(r, "kappa_J", Grid(3), L=-1.0), ValueError, "L"),
        (lambda r: sweep(r, "rank_F", Grid((3, 3))), ValueError, "steps"),
        (lambda r: Grid(0), ValueError, "steps"),
        (lambda r: Grid("many"), TypeError, "steps"),
        (lambda r: Grid(3, lo=1.0, hi=1.0), ValueError, "hi"),
        (lambda r: Sample(0), ValueError, "n"),
        (lambda r: Sample(10, seed=-1), ValueError, "seed"),
    ],
)
def test_bad_input(call, exc, words):
    with pytest.raises(exc, match=words):
        call(_robots()["centred"])


def test_first_written_is_the_whole_chunk_rounded():
    """The reduction's fast search for the first value written as an extreme equals rounding every value
    (wmr.io.decimals.quantise) and taking the first extreme: ties, values one ulp or one quantum apart, decade
    boundaries, zeros, infinities."""
    from wmr.analysis.sweep.reduction import first_written
    from wmr.io.decimals import quantise

    rng = np.random.default_rng(7)
    bases = [1.0, 0.999999999999, 10.0, 9.9999999999995, 123.456, 1e-13, 0.0, -5.0, 1e6, 5.0]
    for _ in range(3000):
        n, base = int(rng.integers(1, 40)), float(rng.choice(bases))
        step = float(rng.choice([0.0, 1e-16, 1e-13, 1e-12, 1e-11, 1e-5])) * max(abs(base), 1.0)
        x = base + rng.integers(-3, 4, n) * step
        if rng.random() < 0.1:
            x[rng.integers(n)] = np.inf
        q, ax = quantise(x, 1.0), np.abs(x)
        assert first_written(x, float(x.min())) == int(np.argmin(q))
        assert first_written(x, float(x.max())) == int(np.argmax(q))
        assert first_written(ax, float(ax.min())) == int(np.argmin(np.abs(q)))


def test_count_takes_a_float_of_integral_value():
    from wmr.analysis.sweep.configurations import count

    assert count("n", 1e6) == 1000000 and isinstance(count("n", 1e6), int)
