r"""Chapter 10's exercises: Campion's classes and the motors of real robots.

======  =======================  ====================================================================
number  check                    the exercise
======  =======================  ====================================================================
10.1    :func:`check_10_1`       :math:`(\delta_m, \delta_s)` of an AGV described in words
10.2    :func:`check_10_2`       a twist the motors of the one-handed mecanum robot cannot produce
10.3    :func:`check_10_3`       the four swerve angles (degrees) for a spin about C
======  =======================  ====================================================================

The robots are built here once (the chapter shows them); every expected value is computed with
``wmr`` (:func:`wmr.campion_class`, :func:`wmr.inverse`, :func:`wmr.steering_angles`).
"""

from __future__ import annotations

import itertools

import numpy as np

import wmr
from wmr.io import layouts

from . import answers
from .feedback import right, wrong
from .framework import exercise
from .tolerance import angle_gap, decimals, within

__all__ = [
    "AGV",
    "ONE_HANDED",
    "SWERVE",
    "motor_rates",
    "check_10_1",
    "check_10_2",
    "check_10_3",
    "ORDER_10_3",
    "TOL_10_2",
    "TOL_10_3",
]

#: 10.1: two steered drive wheels on the centre line, 0.6 m ahead of and behind C, and four castors
AGV = wmr.Robot(
    [wmr.CentredWheel((0.6, 0.0), r=0.1), wmr.CentredWheel((-0.6, 0.0), r=0.1)]
    + [wmr.OffsetWheel((x, y), r=0.05, d=0.04) for x in (0.5, -0.5) for y in (0.35, -0.35)],
    name="AGV with two steered drive wheels and four castors",
)

#: 10.2: four mecanum wheels on a 0.5 m x 0.4 m rectangle, every roller at +45 degrees (all of one hand)
ONE_HANDED = wmr.Robot(
    [wmr.SwedishWheel(tuple(p), r=0.05, angle=np.pi / 2, roller=np.pi / 4) for p in layouts.rectangle(0.5, 0.4)],
    name="mecanum, all rollers of one hand",
)

#: 10.3: a four-module swerve drive on a 0.6 m x 0.5 m rectangle
SWERVE = layouts.swerve(layouts.rectangle(0.6, 0.5), 0.05)
#: 10.3: the order of the modules the answer is given in (that of :func:`wmr.io.layouts.rectangle`)
ORDER_10_3 = (
    ", ".join(f"{n} $({x:g}, {y:g})$" for n, (x, y) in zip(("FL", "FR", "RL", "RR"), SWERVE.mount_points))
    + " (metres, body frame)"
)

#: the motor rates, in units of the wheel rate of the twist's speed (speed / wheel radius), must be below 1e-3
TOL_10_2 = within("every motor rate below $10^{-3}$ of the wheel rate of the same speed", abs=1e-3)
TOL_10_3 = decimals(1, "degrees")
_SPIN = np.array([1.0, 0.0, 0.0])


def motor_rates(robot, beta, twist):
    r"""The rates of the driven joints (motors) that realise ``twist`` at ``beta``: the driven rows of (30).

    Parameters
    ----------
    robot : wmr.Robot
    beta : array (w,)
    twist : array (3,)
        :math:`[\dot\psi, \dot x, \dot y]`.

    Returns
    -------
    numpy.ndarray (k,)
        One entry per driven rate joint (steering motors excluded: a centred wheel's steering rate is
        not a column of :math:`\mathbf J_2`).
    """
    driven = [j.driven for u in robot.wheels for j in u.joints if j.rate is not None]
    rates = wmr.inverse(robot, beta, twist).value
    return np.asarray(rates)[np.array(driven, dtype=bool)]


@exercise("10.1", answer="two whole numbers $(\\delta_m, \\delta_s)$")
def check_10_1(classes):
    """Exercise 10.1: the degree of mobility and of steerability of :data:`AGV`."""
    v = answers.vector(classes, 2, "two whole numbers $(\\delta_m, \\delta_s)$")
    if np.any(v != np.round(v)) or np.any(v < 0) or np.any(v > 3):
        return wrong("Both degrees are whole numbers from 0 to 3.")
    c = wmr.campion_class(AGV)
    dm, ds = int(v[0]), int(v[1])
    if (dm, ds) == (c.delta_m, c.delta_s):
        return right(f"The AGV is of class ({dm},{ds}): {c.name}, degree of maneuverability {c.maneuverability}.")
    if (ds, dm) == (c.delta_m, c.delta_s):
        return wrong(r"These are the two numbers in the other order: $\delta_m$ comes first.")
    if dm == c.delta_m:
        return wrong(
            r"$\delta_m$ is right; $\delta_s$ counts the steering angles you can choose *independently* "
            r"once the robot moves."
        )
    if ds == c.delta_s:
        return wrong(
            r"$\delta_s$ is right; for $\delta_m$ count the rows of $\mathbf C_1^*$ at a configuration where "
            "the robot moves. Castors add no row."
        )
    return wrong(r"Neither degree is right: write $\mathbf C_1^*$ row by row (castors add none) and take its rank.")


@exercise("10.2", answer="a twist $(\\dot\\psi, \\dot x, \\dot y)$ in rad/s and m/s", tolerance=TOL_10_2)
def check_10_2(twist):
    r"""Exercise 10.2: a non-zero twist of :data:`ONE_HANDED` for which no motor turns."""
    t = answers.vector(twist, 3, r"a twist $(\dot\psi, \dot x, \dot y)$ in rad/s and m/s")
    beta = ONE_HANDED.effective_beta(np.zeros(ONE_HANDED.w))
    L = float(np.sqrt(np.mean(np.sum(ONE_HANDED.mount_points.astype(float) ** 2, axis=1))))
    speed = float(np.hypot(L * t[0], np.hypot(t[1], t[2])))  # metres per second at the wheels
    if speed == 0:
        return wrong("A robot at rest turns no motor: give a motion.")
    m = motor_rates(ONE_HANDED, beta, t)
    scale = speed / 0.05  # the wheel rates of that speed, rad/s
    if TOL_10_2.accepts(m / scale, np.zeros_like(m)):  # an absolute bound on dimensionless rates
        return right(
            "No drive motor turns, yet the platform moves: the rollers alone carry this motion, so the "
            "motors can neither produce it nor stop it."
        )
    turning = max(1, int(np.sum(np.abs(m) > TOL_10_2.abs * scale)))
    return wrong(
        f"For this twist {turning} of the four drive motors must turn. Look for a motion that the rollers "
        "alone can carry, with every wheel's spin zero."
    )


@exercise("10.3", answer="four steering angles in degrees", tolerance=TOL_10_3, units={"beta": "deg"})
def check_10_3(beta):
    """Exercise 10.3: the steering angles of :data:`SWERVE` for a spin about C."""
    b = answers.angles(beta, 4, "deg")
    want = wmr.steering_angles(SWERVE, _SPIN)
    tol = np.radians(TOL_10_3.allowed(0.0))
    if angle_gap(b, want) <= tol:
        return right("Every axle passes through C: the robot spins on the spot.")
    for order in itertools.permutations(range(4)):
        if angle_gap(b, want[list(order)]) <= tol:  # the right angles, given for the modules in another order
            return wrong(
                f"These are the right angles in another order of the modules. Give them in the order {ORDER_10_3}."
            )
    basis = wmr.admissible_twists(SWERVE, b)
    if basis.shape[1] == 0:
        return wrong("The axle lines do not meet in one point: with these angles the robot cannot move at all.")
    t = basis[:, 0]
    if abs(t[0]) < 1e-9 * np.linalg.norm(t):
        return wrong("The axles are parallel: the robot can translate, but not turn about C.")
    return wrong("The axles meet in one point, but not at C: the robot turns about another point.")
