r"""The dead zone: the circle C traces when every unit turns with the drives locked.

Chapter 2's checks live in :mod:`edition.checks.assembly`; this module holds one group of them.
"""

from __future__ import annotations

import numpy as np

from wmr.analysis.integration import integrate
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL

from .. import Derivation, claim, require
from .matrices import PAPER

__all__ = ["dead_zone", "dead_zone_claim"]


def dead_zone(robot, beta0=0.4, T=2 * np.pi, steps=200):
    r"""Steer every unit one full turn with the drives locked; fit a circle to the path of C.

    Parameters
    ----------
    robot : wmr.Robot
        Offset wheels.
    beta0 : float
        The common initial steering angle.
    T : float
        Duration of the turn (s).
    steps : int

    Returns
    -------
    dict
        ``radius`` of the fitted circle, ``circle_fit`` (largest distance from it), ``contact_drift``
        (largest motion of a contact point), ``centre_minus_Cf`` (distance of the circle's centre from
        the centroid of the contacts), ``CCf_min``, ``CCf_max`` (range of :math:`|CC_f|`),
        ``psi_drift``, ``max_slip``.
    """
    rates = np.zeros(2 * robot.w)
    rates[0::2] = 2 * np.pi / T
    run = integrate(robot, rates, np.full(robot.w, beta0), t_end=T, dt=T / steps)
    C = run.pose[:, 1:]
    a, b, c = np.linalg.lstsq(np.c_[2 * C, np.ones(len(C))], (C**2).sum(1), rcond=None)[0]
    centre, radius = np.array([a, b]), float(np.sqrt(c + a * a + b * b))
    G = np.stack([run.unit_points(i, "H") for i in range(robot.w)], axis=1)
    Cf = G.mean(axis=1)
    return {
        "radius": radius,
        "circle_fit": float(np.abs(np.linalg.norm(C - centre, axis=1) - radius).max()),
        "contact_drift": float(np.ptp(G, axis=0).max()),
        "centre_minus_Cf": float(np.linalg.norm(centre - Cf[0])),
        "CCf_min": float(np.linalg.norm(C - Cf, axis=1).min()),
        "CCf_max": float(np.linalg.norm(C - Cf, axis=1).max()),
        "psi_drift": float(np.ptp(run.pose[:, 0])),
        "max_slip": float(run.slip.max()),
    }


def dead_zone_claim(origin=(0.06, -0.04), steps=200):
    r"""Claim ``dead-zone``: C traces a circle of radius :math:`|CC_f| = d` about the fixed centroid of the contacts.

    Holds for the paper's robot (C at the centroid of the mount points); with C elsewhere the
    radius is still d but the centre is :math:`C_f + (C - \bar P)` and :math:`|CC_f|` varies.

    Parameters
    ----------
    origin : pair
        Where C is moved for the comparison.
    steps : int
        Integration steps of the turn.

    Returns
    -------
    Derivation
        ``on``, ``off`` (the two :func:`dead_zone` results), ``shift``, finding ``dead-zone``.
    """
    paper = paper_robot("offset", **PAPER)
    moved = paper.moved(origin=origin)
    d = PAPER["d"]
    on, off = dead_zone(paper, steps=steps), dead_zone(moved, steps=steps)
    shift = float(np.linalg.norm(moved.mount_points.mean(0)))
    holds = (
        abs(on["radius"] - d) < TOL
        and on["contact_drift"] < TOL
        and on["centre_minus_Cf"] < TOL
        and abs(on["CCf_max"] - d) < TOL
        and abs(on["CCf_min"] - d) < TOL
        and on["max_slip"] < TOL
        and on["psi_drift"] < TOL
        and on["circle_fit"] < TOL
    )
    require(
        abs(off["radius"] - d) < TOL
        and off["contact_drift"] < TOL
        and abs(off["centre_minus_Cf"] - shift) < TOL
        and abs(off["CCf_min"] - abs(shift - d)) < 1e-3
        and abs(off["CCf_max"] - (shift + d)) < 1e-3,
        "with C off the centroid: radius d, centre shifted by |C - centroid|",
    )
    res = max(abs(on["radius"] - d), on["centre_minus_Cf"], on["contact_drift"])
    return Derivation(
        on=on,
        off=off,
        shift=shift,
        findings=[
            claim(
                "dead-zone",
                holds,
                f"`wmr.integrate` ({steps} RK4 steps), all units steered one full turn with the drives "
                "locked: the contact points stay fixed, the platform does not turn, and C runs once "
                "around a circle of radius $d$ about their centroid $C_f$, so $|CC_f| = d$ "
                "throughout",
                res,
                convention=r"all $\beta_i$ equal (parallel arms), C at the centroid of the $P_i$",
                note=rf"with C moved off the centroid by ${shift:.3f}$ the radius is still $d$, but the centre is "
                r"$C_f + (C - \bar P)$ and $|CC_f|$ runs from "
                rf"${off['CCf_min']:.3f}$ to ${off['CCf_max']:.3f}$",
            )
        ],
    )
