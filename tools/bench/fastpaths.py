"""Each fast path of wmr against the plain implementation it replaces (issue 29: keep a fast path only at >= 3x).

The plain implementations are the dense definitions of :mod:`wmr.analysis.reference`.
Run ``.venv/bin/python -m tools.bench.fastpaths [N]``
(default N = 10**6 configurations, fixed seed); each row prints the best of three wall-clock times and
the gain (plain / fast).  The results are compared as well: a fast path that disagrees is reported.
"""

from __future__ import annotations

import sys

import numpy as np

import wmr
from tools.bench.floors import SEED, best_of, same_kappa, swerve_robot
from wmr.analysis import linalg as LA
from wmr.analysis import reference as R
from wmr.analysis.motion_kappa import motion_kappa
from wmr.analysis.sweep.motions import kappa_J_of_twists
from wmr.analysis.sweep.reduction import first_written
from wmr.io.decimals import quantise


def rows(n):
    """``(name, fast, plain, same)`` for every fast path, on ``n`` configurations."""
    rng = np.random.default_rng(SEED)
    centred, dual, swerve = wmr.paper_robot("centred"), wmr.paper_robot("dual"), swerve_robot()
    L, L_sw = wmr.characteristic_length(centred), wmr.characteristic_length(swerve)
    beta = rng.uniform(-np.pi, np.pi, (n, 3))
    twist = rng.normal(size=(n, 3))
    rates = rng.normal(size=(n, 3))
    rng.uniform(-np.pi, np.pi, n)  # the angles of a row removed with cos_sin: later draws unchanged
    sw_beta = wmr.steering_angles(swerve, twist)
    chunk = min(n, 1 << 18)  # a sweep reduces chunk by chunk
    kappa_like, rank_like = 1 + 10 * rng.random(chunk), rng.integers(5, 7, chunk).astype(float)

    def plain_swerve():
        return R.inverse(swerve, sw_beta, twist)[0]

    return [
        ("rank F, 3 centred (6x6)", lambda: wmr.rank_F(centred, beta), lambda: R.rank_F(centred, beta), np.array_equal),
        (
            "kappa(J), 3 centred (3x3)",
            lambda: wmr.condition_number(centred.J(beta, L=L)),
            lambda: R.condition_number(R.J(centred, beta, L)),
            same_kappa,
        ),
        (
            "det J, 3 centred (3x3 cofactors)",
            lambda: LA.det(centred.J(beta, L=L)),
            lambda: R.det(R.J(centred, beta, L)),
            lambda a, b: np.allclose(a, b, rtol=1e-12, atol=1e-14),
        ),
        (
            "kappa(J) from twists, swerve (fused)",
            lambda: kappa_J_of_twists(swerve, twist, L_sw),
            lambda: R.condition_number(R.J(swerve, wmr.steering_angles(swerve, twist), L_sw)),
            _same_fused,
        ),
        (
            "motion_kappa, 3 centred (from twists)",
            lambda: motion_kappa(centred, twist, L),
            lambda: R.condition_number(R.J(centred, wmr.steering_angles(centred, twist), L)),
            same_kappa,
        ),
        (
            "J only, 3 dual (3x6)",
            lambda: dual.J(beta, L=L),
            lambda: R.J(dual, beta, L),
            lambda a, b: np.allclose(a, b, rtol=1e-12, atol=1e-14),
        ),
        (
            "forward kinematics, 3 centred",
            lambda: wmr.forward(centred, beta, rates).value,
            lambda: R.forward(centred, beta, rates)[0],
            lambda a, b: np.allclose(a, b, rtol=1e-12, atol=1e-12),
        ),
        (
            "inverse kinematics, 3 dual",
            lambda: wmr.inverse(dual, beta, twist).value,
            lambda: R.inverse(dual, beta, twist)[0],
            lambda a, b: np.allclose(a, b, rtol=1e-12, atol=1e-12),
        ),
        (
            "swerve IK (given the angles), 4 modules",
            lambda: wmr.inverse(swerve, sw_beta, twist).value,
            plain_swerve,
            lambda a, b: np.allclose(a, b, rtol=1e-12, atol=1e-12),
        ),
        (
            "sweep's extremes as written, kappa-like",
            lambda: _extremes_fast(kappa_like),
            lambda: _extremes_plain(kappa_like),
            lambda a, b: a == b,
        ),
        (
            "sweep's extremes as written, rank-like",
            lambda: _extremes_fast(rank_like),
            lambda: _extremes_plain(rank_like),
            lambda a, b: a == b,
        ),
    ]


def _same_fused(got, want):
    """The fused kernel's accuracy: a relative 1e-12 or 64 eps kappa (tests/test_sweep_drivable.py), inf alike."""
    fin = np.isfinite(want)
    err = np.abs(got[fin] / want[fin] - 1)
    return bool(np.array_equal(np.isinf(got), ~fin) and np.all(err <= 1e-12 + 64 * np.finfo(float).eps * want[fin]))


def _extremes_fast(x):
    """Where the minimum, maximum and smallest magnitude are, as a sweep's reduction finds them."""
    ax = np.abs(x)
    return first_written(x, float(x.min())), first_written(x, float(x.max())), first_written(ax, float(ax.min()))


def _extremes_plain(x):
    """The same from the whole chunk rounded as written (wmr.io.decimals.quantise)."""
    q = quantise(x, 1.0)
    return int(np.argmin(q)), int(np.argmax(q)), int(np.argmin(np.abs(q)))


def main(argv=None, repeat=3):
    """Print one line per fast path: its time, the plain time, the gain and whether the results agree.

    ``argv``: ``[N]``, the number of configurations (default 10**6).  Returns 1 when a fast path disagrees.
    """
    argv = sys.argv[1:] if argv is None else argv
    n, disagree = int(float(argv[0])) if argv else 10**6, 0
    print(f"{n} configurations, best of {repeat}")
    for name, fast, plain, same in rows(n):
        t_fast, a = best_of(fast, repeat)
        t_plain, b = best_of(plain, repeat)
        agree = bool(same(a, b))
        disagree += not agree
        print(
            f"{name:42s} fast {t_fast * 1e3:9.1f} ms  plain {t_plain * 1e3:9.1f} ms  "
            f"gain {t_plain / t_fast:6.1f}x  same {agree}"
        )
    return 1 if disagree else 0


if __name__ == "__main__":
    raise SystemExit(main())
