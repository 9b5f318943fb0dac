r"""Two motions of Chapter 6 integrated with :func:`wmr.integrate`: a 90-degree corner (centred, dual and offset
wheels) and a curvilinear translation with the wheels re-steered while moving (the paper's Fig. 8b).
"""

from __future__ import annotations

import numpy as np

from wmr.analysis.integration import integrate
from wmr.analysis.kinematics import inverse
from wmr.analysis.steering import steering_angles

from ...algebra import mod_pi
from .robots import robots

__all__ = ["corner", "curved_translation"]


def corner(v=0.2, w_max=np.pi / 2, dt=0.01):
    r"""A 90-degree corner, exactly: drive along x for 1 s, re-steer, drive along y.  Centred, dual and offset wheels.

    Parameters
    ----------
    v : float
        Speed (m/s).
    w_max : float
        Steering rate limit of the centred wheels (rad/s).
    dt : float

    Returns
    -------
    dict
        ``Ts`` (re-steering time), ``centred`` (motion during re-steering, slip, final pose, slip if
        the new twist is commanded at once), ``dual`` (slip, motion while re-steering, final angle
        error), ``offset`` (slip, final pose, largest joint rate).
    """
    cen, dual, off = robots()
    tw_x, tw_y = np.array([0.0, v, 0.0]), np.array([0.0, 0.0, v])
    bx, by = steering_angles(cen, tw_x), steering_angles(cen, tw_y)
    Ts = float(np.max(np.abs(mod_pi(by - bx)))) / w_max
    rx, ry = inverse(cen, bx, tw_x).value, inverse(cen, by, tw_y).value
    run = integrate(
        cen,
        lambda t, s: rx if t < 1 else (np.zeros(3) if t < 1 + Ts else ry),
        bx,
        t_end=2 + Ts,
        dt=dt,
        steer=lambda t, s: (by - bx) / Ts if 1 <= t < 1 + Ts else np.zeros(3),
    )
    inside = (run.t > 1 + 1e-9) & (run.t < 1 + Ts - 1e-9)
    at_once = inverse(cen, bx, tw_y)

    def dual_rates(t, s):
        if t < 1:
            return inverse(dual, s[1], tw_x).value
        if t < 1 + Ts:
            return inverse(dual, s[1], np.zeros(3), beta_dot=(by - bx) / Ts).value
        return inverse(dual, s[1], tw_y).value

    run_d = integrate(dual, dual_rates, bx, t_end=2 + Ts, dt=dt)
    inside_d = (run_d.t > 1 + 1e-9) & (run_d.t < 1 + Ts - 1e-9)

    def off_rates(t, s):
        return inverse(off, s[1], tw_x if t < 1 else tw_y).value

    run_o = integrate(off, off_rates, np.zeros(3), t_end=2.0, dt=dt)
    top = float(np.abs([off_rates(t, (p, b)) for t, p, b in zip(run_o.t, run_o.pose, run_o.beta, strict=True)]).max())
    return {
        "Ts": Ts,
        "v": v,
        "centred": {
            "moved": float(np.ptp(run.pose[inside], axis=0).max()),
            "slip": float(run.slip.max()),
            "final": run.pose[-1],
            "at_once": float(np.abs(at_once.residual).max()),
            "admissible_at_once": bool(at_once.admissible),
        },
        "dual": {
            "slip": float(run_d.slip.max()),
            "moved": float(np.ptp(run_d.pose[inside_d], axis=0).max()),
            "angle_error": float(np.abs(mod_pi(run_d.beta[-1] - by)).max()),
        },
        "offset": {"slip": float(run_o.slip.max()), "final": run_o.pose[-1], "top_rate": top},
    }


def curved_translation(v=0.2, omega=0.5, t_end=np.pi, dt=0.01):
    r"""Steering while moving: a curvilinear translation (the paper's Fig. 8b) of three centred wheels.

    The velocity direction turns at ``omega`` while the platform does not rotate; the wheels are
    re-steered together at :math:`\dot\beta_i = \omega` and stay parallel, and the rolling rates come
    from the inverse kinematics at the current angles.

    Parameters
    ----------
    v, omega : float
        Speed (m/s) and turning rate of the velocity direction (rad/s).
    t_end, dt : float

    Returns
    -------
    dict
        ``slip`` (largest), ``miss`` (largest difference between the twist executed and the one commanded),
        ``psi`` (largest platform rotation), ``turned`` (direction change, rad),
        ``parallel`` (largest spread of the steering angles).
    """
    cen, _, _ = robots()

    def twist(t):
        return np.array([0.0, v * np.cos(omega * t), v * np.sin(omega * t)])

    beta0 = steering_angles(cen, twist(0.0))
    run = integrate(
        cen, lambda t, s: inverse(cen, s[1], twist(t)).value, beta0, t_end=t_end, dt=dt, steer=np.full(3, omega)
    )
    vel = np.diff(run.pose[:, 1:], axis=0)
    heading = np.unwrap(np.arctan2(vel[:, 1], vel[:, 0]))
    miss = float(np.max(np.abs(run.twist - np.array([twist(t) for t in run.t]))))
    return {
        "slip": float(run.slip.max()),
        "miss": miss,
        "psi": float(np.abs(run.pose[:, 0]).max()),
        "turned": float(heading[-1] - heading[0]),
        "parallel": float(np.ptp(mod_pi(run.beta - run.beta[:, :1]), axis=0).max()),
        "omega": omega,
        "t_end": t_end,
    }
