"""Benchmark of wmr's batched kernels against plain-NumPy floors, a peer library and targets.

Usage: ``make bench`` or ``python tools/bench.py [--n N] [--repeat R] [--sweep N] [--no-dask]``.

Each row times one kernel on N configurations (default 10**6, fixed seed) as the best of R
wall-clock runs, and compares it with

* a **target** (issue 13: rank F and det J at most 0.1 s, kappa(J) at most 0.15 s), or
* a **floor**: the same arithmetic written as plain NumPy over the whole batch, with what is
  constant per robot computed once (e.g. :math:`\\mathbf J_1^+`); goal: ``wmr`` within 2x of it, or
* a **peer**: WPILib's ``SwerveDrive4Kinematics.toSwerveModuleStates`` (robotpy-wpimath) called
  once per twist, and ``SwerveDrive4Odometry.update`` once per sample (:func:`wmr.wheel_odometry`
  takes the whole run at once), timed in the same run; goal: ``wmr`` at least 5x faster per item.

The ratio column is wmr / (target or floor) -- smaller is better -- and peer / wmr for the peer
(larger is better); both use wall-clock times.  The cpu column is the smallest process CPU time
of the runs (all threads together): on a loaded machine it is what the kernel costs when it has
the cores to itself.  The check column compares a slice of every result with the dense reference
definitions of :mod:`wmr.analysis.reference` (full matrices, SVD, pseudo-inverse), with the floor
and with WPILib, so a fast kernel that returned wrong numbers would say FAIL here.  The sweep rows
time :func:`wmr.sweep` in this process and on a local Dask cluster of 2 single-thread workers, and
measure the peak resident memory of an in-process sweep in a fresh child process; the last rows time
the default sweep of issue 24, kappa(J) of the four-module swerve over its drivable configurations
(goal: 5 M configurations per second in process), beside the same over random angles.  The load
average is printed before and after: timings on a shared machine are only as quiet as it was.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import wmr
from wmr.analysis import reference as R
from wmr.analysis.linalg import det
from wmr.model.backend import NUMERIC

SEED = 20020101
EPS = np.finfo(float).eps


def best_of(fn, repeat, cpu=None):
    """Best wall-clock time of ``repeat`` calls of ``fn`` and the last result.

    If ``cpu`` is a list, the smallest process CPU time of the calls (all threads) is appended
    to it: on a loaded machine it says what the kernel costs when it has the cores to itself.
    """
    times, cpus, out = [], [], None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        times.append(time.perf_counter() - t0)
        cpus.append(time.process_time() - c0)
    if cpu is not None:
        cpu.append(min(cpus))
    return min(times), out


def load():
    try:
        return "load average " + " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:
        return "load average unknown"


def swerve_robot(half=0.3, r=0.05):
    """A 4-module swerve: centred wheels at (+-half, +-half), WPILib's order FL, FR, BL, BR."""
    pts = [(half, half), (half, -half), (-half, half), (-half, -half)]
    return wmr.Robot([wmr.CentredWheel(p, r=r) for p in pts], name="swerve-4")


# ----------------------------------------------------------------------------------- floors
def floor_forward(robot, pinvJ1):
    """Plain NumPy: t = J1^+ J2(beta) theta_dot, unit by unit, J1^+ given (constant per robot)."""
    blocks = [u.block_terms(NUMERIC) for u in robot.wheels]

    def run(beta, rates):
        c, s = np.cos(beta), np.sin(beta)
        rhs = np.empty(beta.shape[:-1] + (2 * robot.w,))
        for i, ((Lb, ELb), sl) in enumerate(zip(blocks, robot.rate_slices)):
            rhs[:, 2 * i : 2 * i + 2] = c[:, i : i + 1] * (rates[:, sl] @ Lb.T) + s[:, i : i + 1] * (
                rates[:, sl] @ ELb.T
            )
        return rhs @ pinvJ1.T

    return run


def floor_inverse(robot):
    """Plain NumPy: theta_dot_i = L_i^+ R(beta_i)^T [E d_i 1] t, unit by unit (no residual)."""
    d = robot.mount_points
    pinvs = [np.linalg.pinv(u.block_terms(NUMERIC)[0]) for u in robot.wheels]

    def run(beta, twist):
        c, s = np.cos(beta), np.sin(beta)
        vx = twist[:, 1:2] - twist[:, 0:1] * d[:, 1]
        vy = twist[:, 2:3] + twist[:, 0:1] * d[:, 0]
        lx, ly = c * vx + s * vy, c * vy - s * vx  # R^T v
        return np.concatenate(
            [lx[:, i : i + 1] * P[:, 0] + ly[:, i : i + 1] * P[:, 1] for i, P in enumerate(pinvs)], axis=1
        )

    return run


def floor_swerve(robot):
    """Plain NumPy swerve inverse kinematics: v_i = c_dot + psi_dot E d_i, then atan2 and hypot."""
    d = robot.mount_points
    r = np.array([u.r for u in robot.wheels])

    def run(twist):
        px = twist[:, 1:2] - twist[:, 0:1] * d[:, 1]
        py = twist[:, 2:3] + twist[:, 0:1] * d[:, 0]
        return np.arctan2(px, -py), np.hypot(px, py) / r

    return run


def wpilib_swerve(robot):
    """WPILib's inverse kinematics, one call per twist (a Python loop, as a robot program does)."""
    from wpimath.geometry import Translation2d
    from wpimath.kinematics import ChassisSpeeds, SwerveDrive4Kinematics

    kin = SwerveDrive4Kinematics(*[Translation2d(float(x), float(y)) for x, y in robot.mount_points])

    def run(twist, keep=False):
        out = []
        for om, vx, vy in twist.tolist():
            states = kin.toSwerveModuleStates(ChassisSpeeds(vx, vy, om))
            if keep:
                out.append(states)
        return out

    return run


def wmr_swerve(robot):
    def run(twist):
        beta = wmr.steering_angles(robot, twist)
        return beta, wmr.inverse(robot, beta, twist)

    return run


def odometry_run(robot, n):
    """Module angles and travels of a noisy (slipping) swerve run of ``n`` samples."""
    rng = np.random.default_rng(SEED)
    twist = np.cumsum(rng.normal(0, 0.05, (n, 3)), axis=0)
    beta = wmr.steering_angles(robot, twist) + rng.normal(0, 0.01, (n, robot.w))
    travel = np.cumsum(rng.normal(0.01, 0.005, (n, robot.w)), axis=0)
    return beta, travel


def wpilib_odometry(robot, beta, travel, m):
    """WPILib's SwerveDrive4Odometry, one update per sample; the module positions of the first ``m`` samples are
    built here, untimed (a robot program gets them from its encoders)."""
    from wpimath.geometry import Pose2d, Rotation2d
    from wpimath.kinematics import SwerveDrive4Odometry

    from wmr.io import to_wpilib
    from wmr.io.wpilib import module_positions

    kin = to_wpilib(robot)
    cache = [tuple(module_positions(b, t)) for b, t in zip(beta[:m], travel[:m])]

    def run(twist):
        odo = SwerveDrive4Odometry(kin, Rotation2d(0.0), cache[0], Pose2d())
        for p in cache[1 : len(twist)]:
            odo.update(Rotation2d(0.0), p)

    run.label = "WPILib, one update per sample"  # type: ignore[attr-defined]
    return run


# ----------------------------------------------------------------------------------- checks
def same_kappa(got, want):
    fin = np.isfinite(want)
    return bool(
        np.array_equal(np.isinf(got), ~fin) and np.all(np.abs(got[fin] / want[fin] - 1) <= 32 * EPS * want[fin])
    )


def angle_gap(a, b):
    return np.abs((a - b + np.pi) % (2 * np.pi) - np.pi)


# ------------------------------------------------------------------------------------ rows
def kernel_rows(n, repeat, k, peer=200_000):
    rng = np.random.default_rng(SEED)
    centred, dual, swerve = wmr.paper_robot("centred"), wmr.paper_robot("dual"), swerve_robot()
    L = wmr.characteristic_length(centred)
    beta = rng.uniform(-np.pi, np.pi, (n, 3))
    rates = rng.normal(size=(n, centred.n_rates))
    twist = rng.normal(size=(n, 3))
    pinvJ1 = np.linalg.pinv(centred.J1())
    fwd_floor, inv_floor = floor_forward(centred, pinvJ1), floor_inverse(centred)
    sw_floor, sw_wmr = floor_swerve(swerve), wmr_swerve(swerve)
    b, th, tw = beta[:k], rates[:k], twist[:k]

    def check_forward(sol):
        t, res, adm = R.forward(centred, b, th)
        return (
            np.allclose(sol.value[:k], t, rtol=1e-12, atol=1e-12)
            and np.allclose(sol.residual[:k], res, atol=1e-12)
            and np.array_equal(sol.admissible[:k], adm)
        )

    def check_inverse(sol):
        th_ref, res, adm = R.inverse(centred, b, tw)
        return (
            np.allclose(sol.value[:k], th_ref, rtol=1e-12, atol=1e-12)
            and np.allclose(sol.residual[:k], res, atol=1e-12)
            and np.array_equal(sol.admissible[:k], adm)
        )

    def check_swerve(out):
        beta_s, sol = out
        fl_beta, fl_rate = sw_floor(tw)
        states = wpilib_swerve(swerve)(tw[:1000], keep=True)
        ang = np.array([[m.angle.radians() for m in s] for s in states])
        spd = np.array([[m.speed for m in s] for s in states])
        r = np.array([u.r for u in swerve.wheels])
        return (
            np.all(angle_gap(beta_s[:k], fl_beta) < 1e-12)
            and np.allclose(sol.value[:k], fl_rate, rtol=1e-12)
            and np.all(sol.admissible[:k])
            and np.all(angle_gap(beta_s[:1000] - np.pi / 2, ang) < 1e-9)
            and np.allclose(sol.value[:1000] * r, spd, rtol=1e-9)
        )

    from wmr.odometry import wheel_odometry

    o_beta, o_travel = odometry_run(swerve, n)
    radii = np.array([u.r for u in swerve.wheels])
    wp_odometry = wpilib_odometry(swerve, o_beta, o_travel, min(n, peer))

    def check_odometry(odo):  # WPILib with the wheels' heading as its gyro
        from wpimath.geometry import Pose2d, Rotation2d
        from wpimath.kinematics import SwerveDrive4Odometry

        from wmr.io import to_wpilib
        from wmr.io.wpilib import module_positions

        m = min(k, 2000)
        ref = SwerveDrive4Odometry(
            to_wpilib(swerve), Rotation2d(0.0), tuple(module_positions(o_beta[0], o_travel[0])), Pose2d()
        )
        poses = (
            ref.update(Rotation2d(float(odo.pose[j, 0])), tuple(module_positions(o_beta[j], o_travel[j])))
            for j in range(1, m)
        )
        xy = [(0.0, 0.0)] + [(p.X(), p.Y()) for p in poses]
        return np.abs(np.array(xy) - odo.pose[:m, 1:]).max() <= 1e-12 * max(1.0, np.abs(odo.pose[:m, 1:]).max())

    J_ref = R.J(centred, b, L)
    return [
        # name, function, (kind, reference time or function), check
        (
            "rank F, 3 centred (6x6)",
            lambda: wmr.rank_F(centred, beta),
            ("target", 0.1),
            lambda x: np.array_equal(x[:k], R.rank_F(centred, b)),
        ),
        (
            "det J, 3 centred (3x3)",
            lambda: det(centred.J(beta, L=L)),
            ("target", 0.1),
            lambda x: np.allclose(x[:k], R.det(J_ref), rtol=1e-12, atol=1e-14),
        ),
        (
            "kappa(J), 3 centred (3x3)",
            lambda: wmr.condition_number(centred.J(beta, L=L)),
            ("target", 0.15),
            lambda x: same_kappa(x[:k], R.condition_number(J_ref)),
        ),
        (
            "mobility, 3 dual (6x9)",
            lambda: wmr.mobility(dual, beta),
            ("target", 0.1),
            lambda x: np.array_equal(x[:k], 3 + dual.n_rates - R.rank_F(dual, b)),
        ),
        (
            "forward kinematics, 3 centred",
            lambda: wmr.forward(centred, beta, rates),
            ("floor", lambda: fwd_floor(beta, rates)),
            check_forward,
        ),
        (
            "inverse kinematics, 3 centred",
            lambda: wmr.inverse(centred, beta, twist),
            ("floor", lambda: inv_floor(beta, twist)),
            check_inverse,
        ),
        ("swerve IK + steering, 4 modules", lambda: sw_wmr(twist), ("floor", lambda: sw_floor(twist)), check_swerve),
        ("swerve IK + steering, 4 modules", lambda: sw_wmr(twist), ("peer", wpilib_swerve(swerve)), check_swerve),
        (
            "swerve odometry, 4 modules",
            lambda: wheel_odometry(swerve, o_beta, o_travel / radii),
            ("peer", wp_odometry),
            check_odometry,
        ),
    ], twist


def sweep_child(analysis, n, chunk, threads=None, robot="paper_centred", source="Sample"):
    """Run one in-process sweep in a fresh interpreter; return (seconds, cpu seconds, peak RSS in MB, count).

    ``robot`` is ``"paper_centred"`` (the paper's three centred wheels) or ``"swerve4"`` (examples/swerve4.toml);
    ``source`` is ``"Sample"`` (random angles) or ``"Drivable"`` (the steering angles of sampled twists).
    """
    # VmHWM, not ru_maxrss: Linux carries the parent's peak over fork + exec into ru_maxrss
    make = (
        "wmr.paper_robot('centred')"
        if robot == "paper_centred"
        else f"wmr.load({str(Path(__file__).resolve().parent.parent / 'examples' / 'swerve4.toml')!r})"
    )
    code = (
        "import sys, time, wmr\n"
        f"from wmr.analysis.sweep import {source}\n"
        f"bot = {make}\n"
        f"t0, c0 = time.perf_counter(), time.process_time(); res = wmr.sweep(bot, {analysis!r}, "
        f"{source}({n}, seed=1), chunk={chunk})\n"
        "dt, dc = time.perf_counter() - t0, time.process_time() - c0\n"
        "hwm = [l for l in open('/proc/self/status') if l.startswith('VmHWM')][0].split()[1]\n"
        "print(dt, dc, int(hwm) / 1024, res.count, res.max)\n"
    )
    env = dict(os.environ, **({} if threads is None else {"WMR_THREADS": str(threads)}))
    out = subprocess.run(
        [sys.executable, "-c", code], check=True, capture_output=True, text=True, env=env
    ).stdout.split()
    return float(out[0]), float(out[1]), float(out[2]), int(out[3])


def sweep_rows(n, dask):
    from wmr.analysis.sweep import CHUNK, Sample

    rows = []
    for analysis in ("rank_F", "kappa_J"):
        for threads in (None, 1):
            sec, cpu, rss, count = sweep_child(analysis, n, CHUNK, threads)
            where = "in process" if threads is None else "in process, 1 thread"
            rows.append((f"sweep {analysis}, {where}", sec, cpu, count, rss))
        if dask:
            from dask.distributed import Client, LocalCluster

            bot = wmr.paper_robot("centred")
            with (
                LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cl,
                Client(cl) as client,
            ):
                wmr.sweep(bot, analysis, Sample(4 * CHUNK, seed=2), client=client)  # warm the workers
                t0 = time.perf_counter()
                res = wmr.sweep(bot, analysis, Sample(n, seed=1), client=client)
                rows.append((f"sweep {analysis}, dask 2 workers", time.perf_counter() - t0, None, res.count, None))
    return rows


def drivable_rows(n):
    """The default sweep of issue 24: kappa(J) of the four-module swerve over drivable configurations (goal 5 M/s)."""
    from wmr.analysis.sweep import CHUNK

    rows = []
    for threads in (None, 1):
        sec, cpu, rss, count = sweep_child("kappa_J", n, CHUNK, threads, robot="swerve4", source="Drivable")
        where = "in process" if threads is None else "in process, 1 thread"
        rows.append((f"swerve4 kappa_J drivable, {where}", sec, cpu, count, rss))
    sec, cpu, rss, count = sweep_child("kappa_J", n, CHUNK, None, robot="swerve4", source="Sample")
    rows.append(("swerve4 kappa_J random angles", sec, cpu, count, rss))
    return rows


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=float, default=1e6, help="configurations per kernel (default 1e6)")
    p.add_argument("--repeat", type=int, default=5, help="runs per kernel; the best counts (default 5)")
    p.add_argument("--peer-n", type=float, default=2e5, help="twists for the per-twist WPILib loop (default 2e5)")
    p.add_argument("--sweep", type=float, default=1e7, help="configurations per sweep row (0: no sweep rows)")
    p.add_argument("--no-dask", action="store_true", help="skip the Dask rows")
    args = p.parse_args(argv)
    n, k = int(args.n), min(int(args.n), 20000)
    print(
        f"wmr {wmr.__version__}, numpy {np.__version__}, Python {platform.python_version()}, "
        f"{os.cpu_count()} cores, WMR_THREADS={os.environ.get('WMR_THREADS', '(all)')}, N = {n:,}, "
        f"best of {args.repeat}, seed {SEED}"
    )
    print(f"before: {load()}")
    rows, twist = kernel_rows(n, args.repeat, k, int(args.peer_n))
    head = (
        f"{'kernel':34s} {'wmr s':>8s} {'cpu s':>7s}  {'compared with':28s} {'its s':>8s} {'ratio':>7s}  "
        f"{'goal':>7s}  check"
    )
    print(head)
    print("-" * len(head))
    fails = 0
    for name, fn, (kind, ref), check in rows:
        cpu: list[float] = []
        sec, out = best_of(fn, args.repeat, cpu)
        ok = bool(check(out))
        if kind == "target":  # the targets are for 10**6 configurations
            other = ref * n / 1e6
            what, ratio, goal, met = "target (issue 13)", sec / other, "<= 1", sec <= other
        elif kind == "floor":
            other, _ = best_of(ref, args.repeat)
            what, ratio, goal = "plain NumPy floor", sec / other, "<= 2"
            met = ratio <= 2
        else:
            m = min(int(args.peer_n), n)
            peer_sec, _ = best_of(lambda ref=ref, m=m: ref(twist[:m]), max(1, args.repeat // 2))
            per_wmr, per_peer = sec / n, peer_sec / m
            what = getattr(ref, "label", "WPILib, one call per twist")
            print(
                f"{name:34s} {per_wmr * 1e6:6.3f}us {cpu[0] / n * 1e6:5.3f}us  {what:28s} "
                f"{per_peer * 1e6:6.3f}us {per_peer / per_wmr:6.1f}x  {'>= 5x':>7s}  "
                f"{'ok' if ok else 'FAIL'}{'' if per_peer / per_wmr >= 5 else ' (goal missed)'}"
            )
            fails += not ok
            continue
        fails += not ok
        print(
            f"{name:34s} {sec:8.4f} {cpu[0]:7.4f}  {what:28s} {other:8.4f} {ratio:7.2f}  {goal:>7s}  "
            f"{'ok' if ok else 'FAIL'}{'' if met else ' (goal missed)'}"
        )
    if args.sweep > 0:
        ns = int(args.sweep)
        print(f"\nsweeps of {ns:,} random configurations of the paper's centred robot ({load()})")
        srows = sweep_rows(ns, dask=not args.no_dask)
        base: dict = {}
        for name, sec, _cpu, count, rss in srows:
            an = name.split(",")[0]
            extra = f"peak RSS {rss:.0f} MB" if rss is not None else f"speed-up {base[an] / sec:.2f}x vs in process"
            base.setdefault(an, sec)
            print(f"{name:34s} {sec:8.2f} s  {count / sec / 1e6:6.2f} M configurations/s  {extra}")
        print(
            f"\nthe default (drivable) sweep of issue 24, {ns:,} configurations; goal >= 5 M/s in process "
            f"({load()}); the cpu rate is per second of CPU time of all threads together"
        )
        for name, sec, cpu, count, rss in drivable_rows(ns):
            goal = (
                ""
                if "random" in name or "1 thread" in name
                else ("  goal met" if count / sec >= 5e6 else "  (goal missed: see the load average)")
            )
            print(
                f"{name:34s} {sec:8.2f} s  {count / sec / 1e6:6.2f} M/s wall  {count / cpu / 1e6:6.2f} M/s cpu  "
                f"peak RSS {rss:.0f} MB{goal}"
            )
    print(f"after: {load()}")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
