"""The kernel rows of tools/bench/batched.py: wmr's batched kernels against targets, plain-NumPy floors and WPILib.

Each row is ``(name, function, (kind, reference), check)``: :func:`kernel_rows` builds them on N
configurations (fixed seed); :func:`best_of` times a call.  The floors are the same arithmetic written
as plain NumPy over the whole batch; the peer is WPILib (robotpy-wpimath) called once per twist or sample;
the checks compare a slice of every result with the dense reference definitions of
:mod:`wmr.analysis.reference`, the floor and WPILib.
"""

from __future__ import annotations

import time

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
