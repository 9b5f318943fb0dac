"""Benchmark of the batched kernels of wmr (a script, not a test): ``python tests/bench.py [N]``.

For N = 10**6 random configurations (fixed seed) of the paper's three-centred-wheel robot it
times building F, the rank of F (:func:`wmr.analysis.mobility.rank_F`), det J (``np.linalg.det`` of
:meth:`wmr.Robot.J`) and the condition number of J (:func:`wmr.analysis.isotropy.condition_number`);
then the mobility of the three-offset-wheel robot and forward / inverse kinematics.  Each row
is the best of 3 wall-clock runs.  The "check" column compares a slice of each result with a
plain reference computation (dense SVD, matrix inverse, round trip), so a fast kernel that
returned wrong numbers would show up here.  Target: under 2 s per row on a 2-core machine.
"""
from __future__ import annotations

import importlib
import os
import sys
import time

import numpy as np

import wmr
from wmr.model.tolerance import TOL

mobility_module = importlib.import_module("wmr.analysis.mobility")   # (wmr.analysis.mobility is also the function)
SEED = 20020101
TARGET = 2.0


def best_of(fn, repeat=3):
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), out


def svd_rank(A):
    s = np.linalg.svd(A, compute_uv=False)
    return np.sum(s > TOL * np.maximum(1.0, s[..., :1]), axis=-1)


def svd_kappa(A):
    s = np.linalg.svd(A, compute_uv=False)
    with np.errstate(divide="ignore"):
        return np.where(s[..., -1] <= TOL * np.maximum(1.0, s[..., 0]), np.inf, s[..., 0] / s[..., -1])


def main(n=10**6):
    rng = np.random.default_rng(SEED)
    centred = wmr.paper_robot("centred")
    offset = wmr.paper_robot("offset")
    L = wmr.characteristic_length(centred)
    beta = rng.uniform(-np.pi, np.pi, (n, 3))
    rates = rng.normal(size=(n, centred.n_rates))
    twist = rng.normal(size=(n, 3))
    k = min(n, 20000)                                         # slice checked against references

    def check_F(F):
        ref = np.concatenate([np.broadcast_to(centred.J1(), (k, 6, 3)), -centred.J2(beta[:k])], axis=-1)
        return np.allclose(F[:k], ref, atol=1e-15)

    def check_cond(kap):
        ref = svd_kappa(centred.J(beta[:k], L=L))
        fin = np.isfinite(ref)
        return (np.array_equal(np.isinf(kap[:k]), ~fin)
                and bool(np.all(np.abs(kap[:k][fin] / ref[fin] - 1) <= 20 * np.finfo(float).eps * ref[fin])))

    def check_inverse(sol):
        # residual = J1 t - J2 theta_dot, and theta_dot is the per-unit least-squares solution
        J2 = centred.J2(beta[:k])
        lhs = (centred.J1() @ twist[:k, :, None])[..., 0]
        ok = np.allclose(sol.residual[:k], lhs - (J2 @ sol.value[:k, :, None])[..., 0])
        return ok and np.allclose((np.swapaxes(J2, -1, -2) @ sol.residual[:k, :, None]), 0.0, atol=1e-12)

    rows = [
        ("build F (6x6), centred", lambda: centred.F(beta), check_F),
        ("rank F (mobility.rank_F)", lambda: mobility_module.rank_F(centred, beta),
         lambda r: np.array_equal(r[:k], svd_rank(centred.F(beta[:k])))),
        ("det J (np.linalg.det(Robot.J))", lambda: np.linalg.det(centred.J(beta, L=L)),
         lambda d: np.allclose(d[:k], np.linalg.det(np.swapaxes(centred.J1(L), 0, 1)[None] @ centred.J2(beta[:k])))),
        ("cond J (isotropy.condition_number)", lambda: wmr.condition_number(centred.J(beta, L=L)), check_cond),
        ("mobility, three offset wheels", lambda: wmr.mobility(offset, beta),
         lambda m: np.array_equal(m[:k], 3 + offset.n_rates - svd_rank(offset.F(beta[:k])))),
        ("forward kinematics", lambda: wmr.forward(centred, beta, rates),
         lambda s: np.allclose(s.value[:k], (np.linalg.pinv(centred.J1())
                                             @ (centred.J2(beta[:k]) @ rates[:k, :, None]))[..., 0])),
        ("inverse kinematics", lambda: wmr.inverse(centred, beta, twist), check_inverse),
    ]
    try:
        load = os.getloadavg()[0]
    except OSError:
        load = float("nan")
    print(f"wmr {wmr.__version__}, numpy {np.__version__}, N = {n:,} configurations, seed {SEED}, "
          f"{os.cpu_count()} cores, load average {load:.2f}")
    print(f"{'kernel':40s} {'seconds (best of 3)':>20s}  {'check':>6s}  {'< 2 s':>5s}")
    worst = 0.0
    for name, fn, check in rows:
        sec, out = best_of(fn)
        ok = bool(check(out))
        worst = max(worst, sec)
        print(f"{name:40s} {sec:20.3f}  {'ok' if ok else 'FAIL':>6s}  {'yes' if sec < TARGET else 'NO':>5s}")
    return worst


if __name__ == "__main__":
    main(int(float(sys.argv[1])) if len(sys.argv) > 1 else 10**6)
