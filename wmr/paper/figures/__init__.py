r"""The paper's Figures 7-13, a map of :math:`\det\mathbf J`, and a drawing of the conventions, regenerated from the model.

Every figure function returns a :class:`matplotlib.figure.Figure` with three attributes:

``wmr_numbers``
    dict of the numbers the figure shows or asserts (a fitted radius, :math:`\det\mathbf J`,
    :math:`\operatorname{rank}\mathbf F`, ...), all computed here from :mod:`wmr`, never typed in;
    the tests check them.
``wmr_title``, ``wmr_caption``
    Title and caption (with the computed numbers; ``$...$`` is LaTeX).

``python -m wmr.paper.figures OUTDIR`` writes ``OUTDIR/<key>.svg|.pdf|.png`` for every key of
:data:`FIGURES`, ``OUTDIR/captions.json`` and ``OUTDIR/singularities.csv``.  The files are
byte-for-byte reproducible (Agg backend, fixed SVG hash salt, no dates) and record the function
that made them and the git commit of the tree.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from functools import lru_cache
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from ...plot import robot as dr
from ...plot.robot import PALETTE, ROLE, style
from ...analysis.isotropy import condition_number
from ...analysis.kinematics import inverse
from ...analysis.mobility import admissible_twists, rank_F, twist_constraints
from ...model.robots import paper_robot
from ...analysis.simulation import simulate
from ...analysis.steering import steering_angles
from ...analysis import lines as ln
from ...analysis import singularities as sg
from ...model.platform import wrap_angle
from .. import families as fams

L_PAPER = 1.0      #: distance of the mount points from C in the figures
R_CENTRED = 0.25   #: wheel radius of the centred-wheel robot in the figures
R_OFFSET = 0.3     #: wheel radius (= offset d) of the offset-wheel robot in Fig. 7
DEG = np.pi / 180


# ------------------------------------------------------------------------------ helpers
def centred_robot():
    """The paper's three-centred-wheel robot as drawn here (L = 1, r = 0.25)."""
    return paper_robot("centred", L=L_PAPER, r=R_CENTRED)


@lru_cache(maxsize=None)
def _exact_poly():
    return sg.det_J_polynomial(sg.exact_robot(paper_robot("centred", L=L_PAPER, r=1.0)))


def exact_det_J(beta_deg, r=R_CENTRED):
    r"""Exact :math:`\det\mathbf J` of the paper's robot at angles given in (integer or rational) degrees.

    Returns
    -------
    sympy.Expr
        Simplified; :math:`r^3` times the value for r = 1.
    """
    import sympy as sp
    poly, c, s = _exact_poly()
    ang = [sp.nsimplify(b) * sp.pi / 180 for b in beta_deg]
    v = poly.subs({**{c[i]: sp.cos(a) for i, a in enumerate(ang)}, **{s[i]: sp.sin(a) for i, a in enumerate(ang)}})
    return sp.nsimplify(sp.radsimp(sp.expand(v))) * sp.nsimplify(r) ** 3


def fit_circle(xy):
    r"""Least-squares (Kåsa) circle through points (n, 2): returns (centre (2,), radius).

    Solves :math:`x^2+y^2 = a x + b y + c` in the least-squares sense.
    """
    xy = np.asarray(xy, dtype=float)
    A = np.column_stack([xy[:, 0], xy[:, 1], np.ones(len(xy))])
    rhs = np.sum(xy ** 2, axis=1)
    (a, b, c), *_ = np.linalg.lstsq(A, rhs, rcond=None)
    centre = np.array([a / 2, b / 2])
    return centre, float(np.sqrt(c + centre @ centre))


def _fmt(x, digits=3):
    """Short scientific/decimal formatting for labels."""
    x = float(x)
    if x == 0:
        return "0"
    if abs(x) < 1e-3 or abs(x) >= 1e4:
        m, e = f"{x:.{digits - 1}e}".split("e")
        return rf"{m}\times10^{{{int(e)}}}"
    return f"{x:.{digits}g}"


def _deg(x):
    v = float(np.degrees(x))
    v = round(v, 6) + 0.0
    return f"{v:.4g}" if abs(v - round(v)) > 1e-6 else f"{int(round(v))}"


def _det_lines(robot, beta_deg, exact=True):
    """Computed det J (exact and float), rank F, mobility, kappa for the info boxes."""
    b = np.asarray(beta_deg, dtype=float) * DEG
    dj = float(sg.det_J(robot, b))
    rk = int(rank_F(robot, b))
    kap = float(condition_number(robot.J(b, L=L_PAPER)))
    out = {"beta_deg": [float(v) for v in beta_deg], "det_J": dj, "rank_F": rk, "mobility": 3 + robot.n_rates - rk,
           "kappa_J": kap, "singular": bool(sg.is_singular(robot, b))}
    if exact:
        e = exact_det_J(beta_deg, r=robot.wheels[0].r)
        out["det_J_exact"] = str(e)
    return out


def _info_lines(n):
    lines = []
    if "det_J_exact" in n:
        ex = "0" if n["det_J_exact"] == "0" else n["det_J_exact"]
        lines.append(rf"$\det\mathbf{{J}} = {ex}$ (exact), ${_fmt(n['det_J'])}$ (float)")
    lines.append(rf"rank $\mathbf{{F}}$ = {n['rank_F']}, mobility {n['mobility']}")
    k = n["kappa_J"]
    lines.append(r"$\kappa(\mathbf{J}) = \infty$" if not np.isfinite(k) else rf"$\kappa(\mathbf{{J}}) = {_fmt(k)}$")
    return lines


def _beta_text(beta_deg):
    return ", ".join(rf"$\beta_{k + 1} = {_deg(b * DEG)}^\circ$" for k, b in enumerate(beta_deg))


def _finish(fig, title, caption, numbers):
    fig.wmr_title = title
    fig.wmr_caption = caption
    fig.wmr_numbers = numbers
    return fig


# ------------------------------------------------------------------------------ Fig. 7
def fig07(r=R_OFFSET, d=None, beta0=0.0, T=1.0, steps=240, later=3 / 8):
    r"""Fig. 7: dead zone of three offset wheels steered one full turn without driving (simulated).

    All wheels start at the same :math:`\beta` (parallel arms, the configuration in which steering
    without driving is possible) and are steered with :math:`\dot\phi_i = 2\pi/T`,
    :math:`\dot\theta_i = 0` (:func:`wmr.simulate`).  The path of C is fitted with a circle
    (:func:`fit_circle`); its radius is compared with the offset d.  RK4 on this smooth periodic
    motion has a global error of order :math:`d\,(\omega\Delta t)^4` (:math:`\omega = 2\pi/T`),
    recorded as ``tolerance``.

    Returns
    -------
    Figure
        ``wmr_numbers``: radius, d, radius_error, tolerance, centre, C_f, centre_error,
        contact_drift, psi_max, slip_max, dt.
    """
    d = r if d is None else d
    bot = paper_robot("offset", L=L_PAPER, r=r, d=d)
    dt = T / steps
    omega = 2 * np.pi / T
    rates = np.tile([omega, 0.0], bot.w)                               # phi_dot_i, theta_dot_i
    tr = simulate(bot, rates, np.full(bot.w, beta0), T, dt)
    C = tr.pose[:, 1:]
    centre, R = fit_circle(C)
    G = np.stack([tr.unit_points(k, "H") for k in range(bot.w)], axis=1)     # (N, w, 2) contact points
    Cf = G[0].mean(axis=0)
    drift = float(np.max(np.linalg.norm(G - G[0], axis=-1)))
    tol = d * (omega * dt) ** 4
    k1 = int(round(later * steps))
    Pp = tr.unit_points(0, "P")
    psi_max = float(np.abs(tr.pose[:, 0]).max())

    with style():
        fig, (ax,) = dr.new_figure(1, 1, width=7.0, height=3.9)
        g0 = dr.draw_robot(ax, bot, tr.beta[0], tr.pose[0], wheel_labels=False, label_offsets={"C": (-6, 6)})
        g1 = dr.draw_robot(ax, bot, tr.beta[k1], tr.pose[k1], ghost=True, labels=False)
        dr.label(ax, g1.C, "$C'$", offset=(-7, -3), ha="right", va="top")
        dr.label(ax, g0.P[0], "$P$", offset=(-9, 0), ha="right", va="center")
        dr.label(ax, g1.P[0], "$P'$", offset=(-8, -5), ha="right", va="top")
        for k in range(bot.w):
            dr.draw_path(ax, tr.unit_points(k, "P"), color=ROLE["path"][1], lw=0.8, zorder=2.6)
        dr.draw_path(ax, C, color=ROLE["path"][0], lw=1.8, zorder=7)
        tri = np.vstack([G[0], G[0][:1]])
        ax.plot(*tri.T, color=PALETTE["grey"], lw=0.6, ls=(0, (2, 2)), zorder=2.4)
        for k in range(bot.w):
            dr.draw_point(ax, G[0, k], f"$G_{{{k + 1}}}$", marker="D", color=PALETTE["green"], size=4.2,
                          offset=(8, -3), ha="left", va="top", zorder=8.5)
        dr.draw_point(ax, Cf, r"$C_\mathrm{f}$", marker="P", color=PALETTE["vermillion"], size=6.5,
                      offset=(-6, -4), ha="right", va="top", zorder=8.5)
        e = np.array([np.cos(-np.pi / 9), np.sin(-np.pi / 9)])          # a radius of the dead zone
        ax.plot(*np.stack([Cf, Cf + R * e]).T, color=PALETTE["orange"], lw=0.9, zorder=7.5)
        dr.label(ax, Cf + 0.55 * R * e, "$d$", offset=(0, 4), ha="center", va="bottom")
        pr = dr.platform_radius(bot)
        ax.set_xlim(-pr - 0.45, pr + 3.35)
        ax.set_ylim(-pr - 0.75, pr + 0.3)
        # inset: the pivot of wheel 1, enlarged
        axi = ax.inset_axes([0.615, 0.30, 0.37, 0.68])
        dr.plain_axes(axi)
        for kk, ghost in ((0, False), (k1, True)):
            dr.draw_unit(axi, bot.wheels[0], tr.beta[kk, 0], tr.pose[kk], ghost=ghost, light=True)
        dr.draw_path(axi, Pp, color=ROLE["path"][1], lw=1.1)
        dr.draw_point(axi, G[0, 0], "$G$", marker="D", color=PALETTE["green"], size=5, offset=(8, -2),
                      ha="left", va="center", zorder=9)
        dr.label(axi, Pp[0], "$P$", offset=(-8, 5), ha="right", va="bottom")
        dr.label(axi, Pp[k1], "$P'$", offset=(-6, -6), ha="right", va="top")
        for kk in (0, k1):
            arm = np.stack([G[0, 0], Pp[kk]])
            axi.plot(*arm.T, color=PALETTE["vermillion"], lw=1.4, zorder=8)
        dr.label(axi, 0.5 * (G[0, 0] + Pp[0]), "$d$", offset=(-7, 0), ha="right", va="center",
                 color=PALETTE["vermillion"])
        c0 = G[0, 0]
        h = 1.25 * max(r, d)
        axi.set_xlim(c0[0] - h, c0[0] + h)
        axi.set_ylim(c0[1] - h, c0[1] + h)
        for sp_ in axi.spines.values():
            sp_.set_visible(True)
            sp_.set_color("#999999")
            sp_.set_linewidth(0.6)
        axi.set_title("pivot of wheel 1, enlarged", fontsize=dr.FONT_SMALL, pad=2)
        ax.indicate_inset_zoom(axi, edgecolor="#999999", linewidth=0.6, alpha=1.0)
        dr.info_box(ax, [rf"fitted radius of the path of $C$: $R = {R:.9f}$",
                         rf"offset $d = {d:g}$:  $|R-d| = {_fmt(abs(R - d), 2)}$ $\leq d(\omega\Delta t)^4 = {_fmt(tol, 2)}$",
                         rf"contact points $G_i$ moved $\leq {_fmt(drift, 2)}$;  $\max|\psi| = {_fmt(psi_max, 2)}$"],
                    loc=(0.985, 0.015), ha="right", va="bottom")
        dr.scale_bar(ax, L_PAPER, "$L$", loc=(0.03, 0.04))
    numbers = {"radius": R, "d": d, "r": r, "radius_error": abs(R - d), "tolerance": tol,
               "centre": centre.tolist(), "C_f": Cf.tolist(), "centre_error": float(np.linalg.norm(centre - Cf)),
               "contact_drift": drift, "psi_max": psi_max, "slip_max": float(tr.slip.max()), "dt": dt, "T": T,
               "steps": steps}
    cap = (rf"Dead zone of the WMR with three offset wheels ($d = r = {d:g}L$), simulated (RK4, "
           rf"$\Delta t = T/{steps}$): the wheels, all at $\beta_i = {_deg(beta0)}^\circ$, are steered one full turn "
           r"($\dot\phi_i = 2\pi/T$) without driving ($\dot\theta_i = 0$). "
           r"$C$ traces a circle about $C_\mathrm{f}$, the centroid of the contact points $G_i$, of fitted radius "
           rf"$R = {R:.9f}$: the offset $d = {d:g}$ to within ${_fmt(abs(R - d), 2)}$ (integration error bound "
           rf"${_fmt(tol, 2)}$). The $G_i$ do not move (at most ${_fmt(drift, 2)}$) and the platform does not "
           rf"turn. Solid: start; dashed: after {later:g} of the turn ($C'$, $P'$). Blue: paths of the pivots $P_i$, "
           r"circles of radius $d$ about the $G_i$. Inset: the pivot $P$ of wheel 1 circles its fixed contact point "
           r"$G$ at distance $d$.")
    return _finish(fig, "Dead zone of a WMR with offset wheels", cap, numbers)


# ------------------------------------------------------------------------------ Fig. 8
def _translation_run(bot, beta0, steer, speed, t_end, dt):
    rates = np.full(bot.w, speed / bot.wheels[0].r)
    return simulate(bot, rates, np.full(bot.w, beta0), t_end, dt, steer=steer)


def fig08(speed=1.0, t_end=6.0, dt=0.02, beta_rect=100.0, amplitude=45.0):
    r"""Fig. 8: rectilinear and curvilinear translation of the centred-wheel robot (simulated).

    (a) All wheels parallel at a constant :math:`\beta`; (b) all wheels steered together,
    :math:`\beta(t) = 90^\circ + A\sin(2\pi t/T)`.  The platform does not turn and every point moves
    along a congruent curve: ``congruence_error`` is
    :math:`\max_{k,t}\|\mathbf p_k(t) - \mathbf c(t) - \mathbf d_k\|`.

    Returns
    -------
    Figure
        ``wmr_numbers``: for "rectilinear" and "curvilinear": psi_max, congruence_error,
        slip_max, rank_F (values along the run), straightness (rectilinear only).
    """
    bot = centred_robot()
    amp = amplitude * DEG
    runs = {"rectilinear": _translation_run(bot, beta_rect * DEG, None, speed, t_end, dt)}

    def steer(t, state):
        return np.full(bot.w, amp * 2 * np.pi / t_end * np.cos(2 * np.pi * t / t_end))
    runs["curvilinear"] = _translation_run(bot, 90 * DEG, steer, speed, t_end, dt)
    numbers, views = {}, []
    cols = [ROLE["path"][0], ROLE["path"][1], ROLE["path"][2], ROLE["path"][3]]
    R = dr.platform_radius(bot)
    with style():
        fig, axes = dr.new_figure(2, 1, width=7.0, height=6.0)
        for ax, (name, tr), letter in zip(axes, runs.items(), "ab"):
            pts = {"C": tr.pose[:, 1:]}
            for k in range(bot.w):
                pts[f"P{k + 1}"] = tr.unit_points(k, "P")
            idx = [0, len(tr.t) // 3, 2 * len(tr.t) // 3, len(tr.t) - 1]
            ext = []
            for q, kk in enumerate(idx):
                g = dr.draw_robot(ax, bot, tr.beta[kk], tr.pose[kk], ghost=0 < q < len(idx) - 1,
                                  labels=q == 0, frame=q in (0, len(idx) - 1))
                ext.append(dr.robot_extent(g, R))
            for (nm, xy), col in zip(pts.items(), cols):
                dr.draw_path(ax, xy, color=col, lw=1.5, zorder=7)
            views.append(np.vstack(ext))
            dev = max(float(np.max(np.linalg.norm(pts[f"P{k + 1}"] - pts["C"] - bot.mount_points[k], axis=1)))
                      for k in range(bot.w))
            rk = sorted(set(int(v) for v in rank_F(bot, tr.beta)))
            n = {"psi_max": float(np.abs(tr.pose[:, 0]).max()), "congruence_error": dev,
                 "slip_max": float(tr.slip.max()), "rank_F": rk, "distance": float(np.linalg.norm(pts["C"][-1]))}
            if name == "rectilinear":
                xy = pts["C"] - pts["C"][0]
                dirn = xy[-1] / np.linalg.norm(xy[-1])
                n["straightness"] = float(np.max(np.abs(xy[:, 0] * dirn[1] - xy[:, 1] * dirn[0])))
            numbers[name] = n
            title = (rf"rectilinear: constant $\beta_i = {beta_rect:g}^\circ$" if name == "rectilinear" else
                     rf"curvilinear: $\beta_i(t) = 90^\circ + {amplitude:g}^\circ\sin(2\pi t/T)$")
            dr.panel_title(ax, letter, title)
            dr.info_box(ax, [rf"$\max|\psi| = {_fmt(n['psi_max'], 2)}$;  paths congruent within "
                             rf"${_fmt(dev, 2)}$;  rank $\mathbf{{F}}$ = {', '.join(map(str, rk))} along the run"],
                        loc=(0.99, 0.015), ha="right", va="bottom")
        dr.common_view(axes, [np.vstack([v, v.min(axis=0) - [0, 0.45]]) for v in views], pad=0.02)
        for ax in axes:
            dr.scale_bar(ax, L_PAPER, "$L$", loc=(0.02, 0.04))
        fig.legend(handles=dr.legend_handles([("path of $C$", f"path:{cols[0]}"), ("$P_1$", f"path:{cols[1]}"),
                                              ("$P_2$", f"path:{cols[2]}"), ("$P_3$", f"path:{cols[3]}")]),
                   loc="outside lower center", ncols=4)
    r_, c_ = numbers["rectilinear"], numbers["curvilinear"]
    cap = (r"Rectilinear (a) and curvilinear (b) translation of the WMR with three centred wheels, simulated: all wheels "
           rf"parallel and driven at $r\dot\theta_i = {speed:g}\,L/\mathrm{{s}}$ for $T = {t_end:g}$ s; in (b) they are "
           r"steered together. Paths of $C$ and the $P_i$; platform at the start and end (solid) and two intermediate "
           rf"poses (dashed). The platform does not turn ($\max|\psi| = {_fmt(max(r_['psi_max'], c_['psi_max']), 2)}$), "
           r"the paths are congruent (translates of one another within "
           rf"${_fmt(max(r_['congruence_error'], c_['congruence_error']), 2)}$), rank $\mathbf{{F}} = {r_['rank_F'][0]}$ "
           rf"(mobility 1) throughout, and no slip is needed (largest residual of (21): "
           rf"${_fmt(max(r_['slip_max'], c_['slip_max']), 2)}$).")
    return _finish(fig, "Rectilinear and curvilinear translations", cap, numbers)


# ------------------------------------------------------------------------------ Fig. 9
def _rotation_run(bot, uc, turn, steps=120):
    """Rotation about the body point uc (psi_dot = 1): steering angles, rates, simulation."""
    uc = np.asarray(uc, dtype=float)
    twist = np.array([1.0, uc[1], -uc[0]])                 # (63): c_dot = -psi_dot E u_c
    beta = steering_angles(bot, twist)
    rates = inverse(bot, beta, twist).value
    tr = simulate(bot, rates, beta, turn, turn / steps)
    return twist, beta, rates, tr


def fig09(uc_U=(-0.7, 1.8), turn=60 * DEG):
    r"""Fig. 9: rotation with the IC at C and at an arbitrary point U (simulated).

    Steering angles from :func:`wmr.steering_angles` (axles through the IC), joint rates from
    :func:`wmr.inverse`, motion from :func:`wmr.simulate` with :math:`\dot\psi = 1`.

    Returns
    -------
    Figure
        ``wmr_numbers``: for "C" and "U": u_c, beta_deg, rank_F, mobility, axle_meet (where the
        axles meet, from their Plücker matrix), axle_meet_error, radius (fitted radius of the
        path of C, 0 when the IC is C), radius_expected, psi_rate, turn_deg, slip_max.
    """
    bot = centred_robot()
    numbers, views = {}, []
    R = dr.platform_radius(bot)
    with style():
        fig, axes = dr.new_figure(1, 2, width=7.2, height=3.9)
        for ax, (name, uc), letter in zip(axes, (("C", (0.0, 0.0)), ("U", uc_U)), "ab"):
            twist, beta, rates, tr = _rotation_run(bot, uc, turn)
            meet = ln.axles_concurrency(bot, beta)
            rk = int(rank_F(bot, beta))
            Cpath = tr.pose[:, 1:]
            if name == "U":
                cen, rad = fit_circle(Cpath)
            else:
                rad = float(np.max(np.linalg.norm(Cpath, axis=1)))
            n = {"u_c": list(map(float, uc)), "beta_deg": np.degrees(beta).tolist(), "rank_F": rk,
                 "mobility": 3 + bot.n_rates - rk, "axle_meet_kind": meet.kind.name.lower(),
                 "axle_meet": None if meet.point is None else meet.point.tolist(),
                 "axle_meet_error": float(np.linalg.norm(meet.point - uc)) if meet.point is not None else float("inf"),
                 "radius": rad, "radius_expected": float(np.linalg.norm(uc)), "psi_rate": float(np.mean(tr.twist[:, 0])),
                 "turn_deg": float(np.degrees(tr.pose[-1, 0])), "slip_max": float(tr.slip.max())}
            numbers[name] = n
            g0 = dr.draw_robot(ax, bot, tr.beta[0], tr.pose[0], zorder=4)
            g1 = dr.draw_robot(ax, bot, tr.beta[-1], tr.pose[-1], ghost=True, labels=False)
            U = np.asarray(uc, dtype=float)
            dr.draw_axles(ax, g0, include=[[U]] * 3, margin=0.25)
            for k in range(bot.w):
                dr.draw_path(ax, tr.unit_points(k, "P"), color=ROLE["path"][1], lw=1.1, zorder=2.7)
            if name == "U":
                dr.draw_path(ax, Cpath, color=ROLE["path"][0], lw=1.6, zorder=7)
                dr.draw_point(ax, U, "$U$ (IC)", marker="*", color=ROLE["ic"], size=10, offset=(8, 2), zorder=9)
                dr.label(ax, g1.C, "$C'$", offset=(6, -4), ha="left", va="top")
                dr.draw_arrow(ax, g0.C, U - g0.C, color=PALETTE["dark"], lw=0.8, zorder=6.5)
                dr.label(ax, 0.5 * (g0.C + U), r"$\mathbf{u}_c$", offset=(5, 0), ha="left", va="center")
            else:
                dr.draw_point(ax, U, None, marker="*", color=ROLE["ic"], size=10, zorder=9)
                dr.label(ax, U, "IC", offset=(-10, -12), ha="right", va="top", color=ROLE["ic"])
                dr.draw_angle(ax, g0.C, 0.62, 0.0, tr.pose[-1, 0], r"$\psi$", text_radius=1.22, color=PALETTE["grey"])
            views.append(np.vstack([dr.robot_extent(g0, R), dr.robot_extent(g1, R), U[None]]))
            psi_name = r"\dot\psi_\mathrm{c}" if name == "C" else r"\dot\psi_\mathrm{u}"
            dr.panel_title(ax, letter, "IC at the operation point $C$" if name == "C" else "IC at a point $U$")
            dr.info_box(ax, [rf"${psi_name} = {n['psi_rate']:.3g}$, turned ${n['turn_deg']:.4g}^\circ$;  "
                             f"rank $\\mathbf{{F}}$ = {rk}, mobility {n['mobility']}",
                             rf"axles meet at the IC (computed, error ${_fmt(n['axle_meet_error'], 2)}$)"], below=True)
        dr.common_view(axes, views, pad=0.03)
        dr.scale_bar(axes[0], L_PAPER, "$L$", loc=(0.03, 0.03))
        fig.legend(handles=dr.legend_handles([("axle", "axle"), ("paths of the $P_i$", f"path:{ROLE['path'][1]}"),
                                              ("path of $C$", f"path:{ROLE['path'][0]}")]),
                   loc="outside upper center", ncols=3)
    a, b = numbers["C"], numbers["U"]
    cap = (r"Rotation of the WMR with three centred wheels (simulated, $\dot\psi = 1$, turned "
           rf"{a['turn_deg']:.4g}$^\circ$; dashed: final pose): (a) IC at the operation point $C$, which stays fixed; "
           rf"(b) IC at $U$, $\mathbf{{u}}_c = ({uc_U[0]:g}, {uc_U[1]:g})L$, about which $C$ moves on a circle of "
           rf"fitted radius {b['radius']:.6f} ($\|\mathbf{{u}}_c\| = {b['radius_expected']:.6f}$). Steering angles from "
           r"`wmr.steering_angles`: the axles (dashed) all pass through the IC (computed intersection within "
           rf"${_fmt(max(a['axle_meet_error'], b['axle_meet_error']), 2)}$); rank $\mathbf{{F}} = {a['rank_F']}$ "
           r"(mobility 1) in both cases.")
    return _finish(fig, "WMR in rotation about C and about U", cap, numbers)


# ------------------------------------------------------------------------------ singular drawings
def _draw_singular(ax, bot, beta, *, dp_label=None, dp_offset=(7, 3), exact_deg=None, frame=True, reach=3.2,
                   wheel_label_offsets=None):
    """Robot + wheel-plane lines + axles; marks D_P and the pairwise axle crossings. Returns (g, numbers, extent)."""
    b = np.asarray(beta, dtype=float)
    g = dr.draw_robot(ax, bot, b, frame=frame, label_offsets=wheel_label_offsets)
    P, u = ln.wheel_plane_lines(bot, b)
    H, iv = ln.axle_lines(bot, b)
    conc = ln.concurrency_point(bot, b)
    ax_pairs = ln.pair_intersections(H, iv)
    pl_pairs = ln.pair_intersections(P, u)
    axle_pts = [v[1] for v in ax_pairs.values() if v[0] == ln.FINITE and np.linalg.norm(v[1]) < reach]
    inc_planes = [[conc.point] if conc.kind == ln.FINITE else [] for _ in range(3)]
    for (i, j), (kind, pt) in pl_pairs.items():
        if kind == ln.COINCIDENT:
            inc_planes[i - 1].append(P[j - 1])
            inc_planes[j - 1].append(P[i - 1])
    inc_axles = [[] for _ in range(3)]
    for (i, j), (kind, pt) in ax_pairs.items():
        if kind == ln.FINITE and np.linalg.norm(pt) < reach:
            inc_axles[i - 1].append(pt)
            inc_axles[j - 1].append(pt)
    dr.draw_planes(ax, g, include=inc_planes, margin=0.3, min_half=0.6)
    dr.draw_axles(ax, g, include=inc_axles, margin=0.3, min_half=0.6)
    for pt in axle_pts:
        dr.draw_point(ax, pt, None, marker="o", color=ROLE["axle"], size=4.5, face="white", zorder=8)
    if conc.kind == ln.FINITE:
        dr.draw_point(ax, conc.point, dp_label, marker="D", color=ROLE["dp"], size=5.5, offset=dp_offset, zorder=8.6)
    ext = [dr.robot_extent(g, dr.platform_radius(bot))] + [np.atleast_2d(p) for p in axle_pts]
    if conc.kind == ln.FINITE:
        ext.append(conc.point[None])
    n = _det_lines(bot, np.degrees(b) if exact_deg is None else exact_deg, exact=exact_deg is not None)
    n.update({"planes_meet": conc.kind.name.lower(), "D_P": None if conc.point is None else conc.point.tolist(),
              "axle_crossings": [p.tolist() for p in axle_pts],
              "coincident": [list(k) for k, v in pl_pairs.items() if v[0] == ln.COINCIDENT],
              "axles_meet": ln.axles_concurrency(bot, b).kind.name.lower(),
              "family": sg.classify(bot, b).family})
    return g, n, np.vstack(ext)


# ------------------------------------------------------------------------------ Fig. 10
def fig10(beta=30.0):
    r"""Fig. 10: the singular configuration :math:`\beta_1=\beta_2=\beta_3` (IC at infinity), with computed det J and rank F.

    Returns
    -------
    Figure
        ``wmr_numbers``: det_J, det_J_exact, rank_F, mobility, kappa_J, planes_meet, axles_meet,
        admissible (basis of the admissible twists), family.
    """
    bot = centred_robot()
    bdeg = [beta] * 3
    with style():
        fig, (ax,) = dr.new_figure(1, 1, width=5.0, height=4.6)
        g, n, ext = _draw_singular(ax, bot, np.asarray(bdeg) * DEG, exact_deg=bdeg)
        A = admissible_twists(bot, np.asarray(bdeg) * DEG)
        n["admissible"] = A.tolist()
        t = A[:, 0]
        v = t[1:] / np.linalg.norm(t[1:])
        v = v if v[1] >= 0 else -v
        for sgn in (1, -1):
            dr.draw_arrow(ax, g.C + sgn * 0.06 * v, sgn * 0.5 * v, color=PALETTE["green"], lw=2.0, head=11, zorder=9)
        dr.label(ax, g.C + 0.5 * v, r"$\dot{\mathbf{c}}$", offset=(-7, 0), ha="right", va="center",
                 color=PALETTE["green"])
        dr.fit_view(ax, ext, pad=0.06)
        dr.info_box(ax, [_beta_text(bdeg) + ": wheel planes and axles parallel, IC at infinity"] + _info_lines(n),
                    below=True)
        fig.legend(handles=dr.legend_handles([("wheel plane", "plane"), ("axle", "axle"),
                                              ("admissible motion", f"path:{PALETTE['green']}")]),
                   loc="outside upper center", ncols=3)
        dr.scale_bar(ax, L_PAPER, "$L$", loc=(0.03, 0.03))
    cap = (rf"Singular configuration with the IC at infinity, $\beta_1 = \beta_2 = \beta_3 = {beta:g}^\circ$ (item (i)). "
           rf"Computed: $\det\mathbf{{J}} = {n['det_J_exact']}$ exactly (${_fmt(n['det_J'])}$ in floating point), "
           rf"rank $\mathbf{{F}} = {n['rank_F']}$ (mobility {n['mobility']}): the wheel planes (dash-dotted) and the "
           r"axles (dashed) are parallel, and the only admissible motion is the translation along the wheel planes (green).")
    return _finish(fig, "Singular configuration with IC at infinity", cap, n)


# ------------------------------------------------------------------------------ Fig. 11
FIG11_CONFIGS = {"a": (60.0, 140.0, 60.0), "b": (-60.0, -60.0, 20.0), "c": (80.0, 0.0, 0.0)}


def fig11(configs=None):
    r"""Fig. 11: the three configurations with two wheel planes coincident (paper's (a)-(c)), with D_ij, det J, rank F.

    Defaults: (a) :math:`\beta_1=\beta_3=60^\circ`, :math:`\beta_2=140^\circ`; (b)
    :math:`\beta_1=\beta_2=-60^\circ`, :math:`\beta_3=20^\circ`; (c) :math:`\beta_2=\beta_3=0^\circ`,
    :math:`\beta_1=80^\circ` (the same picture turned by 120 degrees each time, up to a half turn
    of wheel 1 in (c)).

    Returns
    -------
    Figure
        ``wmr_numbers``: per panel "a", "b", "c": det_J, det_J_exact, rank_F, mobility,
        coincident (pair), D_P, axle_crossings, family.
    """
    bot = centred_robot()
    configs = configs or FIG11_CONFIGS
    numbers, views = {}, []
    with style():
        fig, axes = dr.new_figure(1, 3, width=7.4, height=3.5)
        for ax, (letter, bdeg) in zip(axes, configs.items()):
            b = np.asarray(bdeg) * DEG
            P, u = ln.wheel_plane_lines(bot, b)
            co = [k for k, v in ln.pair_intersections(P, u).items() if v[0] == ln.COINCIDENT]
            i, j = co[0]
            k3 = ({1, 2, 3} - {i, j}).pop()
            lab = rf"$D_{{{min(i, k3)}{max(i, k3)}}} = D_{{{min(j, k3)}{max(j, k3)}}}$"
            conc = ln.concurrency_point(bot, b)
            off = dr._outward_offset(conc.point - (P[i - 1] + P[j - 1]) / 2 + 1e-9, 1)
            off = (-9 if off[0] < 0 else 9, 0)
            g, n, ext = _draw_singular(ax, bot, b, dp_label=lab, exact_deg=bdeg, frame=False,
                                       dp_offset=(0, -9))
            numbers[letter] = n
            views.append(ext)
            dr.panel_title(ax, letter, rf"$\beta_{i} = \beta_{j} = {bdeg[i - 1]:g}^\circ$, "
                                       rf"$\beta_{k3} = {bdeg[k3 - 1]:g}^\circ$")
            dr.info_box(ax, _info_lines(n)[:2], below=True)
        dr.common_view(axes, views, pad=0.08)
        fig.legend(handles=dr.legend_handles([("wheel plane", "plane"), ("axle", "axle"),
                                              ("axles cross", f"marker:o:{ROLE['axle']}"),
                                              ("planes meet", f"marker:D:{ROLE['dp']}")]),
                   loc="outside lower center", ncols=4)
    ranks = sorted(set(v["rank_F"] for v in numbers.values()))
    cap = ("Singular configurations with two wheel planes coincident (items (ii)-(iv)): "
           + "; ".join(rf"({k}) {_beta_text(c)}" for k, c in configs.items())
           + r". The planes of two wheels lie on one side $P_iP_j$ of the mount triangle and the third plane crosses it at "
           r"$D_{ik} = D_{jk}$. Computed for each: $\det\mathbf{J} = 0$ exactly (float $\leq "
           + _fmt(max(abs(v['det_J']) for v in numbers.values()), 2) + r"$), rank $\mathbf{F} = "
           + ", ".join(map(str, ranks)) + r"$ (mobility 0): the two coincident wheels have parallel axles, which the "
           r"third axle crosses at two different points (open circles), so there is no IC.")
    return _finish(fig, "Singular configurations with two wheel planes coincident", cap, numbers)


# ------------------------------------------------------------------------------ Fig. 12
def fig12(D_arbitrary=(-0.5, 1.8)):
    r"""Fig. 12: all three wheel planes through one point, (a) the operation point C, (b) an arbitrary point D_P.

    Angles from :func:`wmr.analysis.lines.planes_through`.

    Returns
    -------
    Figure
        ``wmr_numbers``: per panel "a", "b": beta_deg, det_J (exact too for (a)), rank_F,
        mobility, D_P (the computed concurrency point), D_P_error, axle_crossings, family.
    """
    bot = centred_robot()
    numbers, views = {}, []
    with style():
        fig, axes = dr.new_figure(1, 2, width=7.2, height=4.1)
        for ax, (letter, D) in zip(axes, (("a", (0.0, 0.0)), ("b", tuple(D_arbitrary)))):
            b = ln.planes_through(bot, D)
            bdeg = np.degrees(b)
            exact = [int(round(v)) for v in bdeg] if letter == "a" else None
            g, n, ext = _draw_singular(ax, bot, b, dp_label="$D_P = C$" if letter == "a" else "$D_P$",
                                       exact_deg=exact, dp_offset=(8, 6) if letter == "a" else (8, 2),
                                       frame=letter == "b")
            n["D_P_target"] = list(map(float, D))
            n["D_P_error"] = float(np.linalg.norm(np.asarray(n["D_P"]) - np.asarray(D)))
            numbers[letter] = n
            views.append(ext)
            dr.panel_title(ax, letter, "planes meet at the operation point $C$" if letter == "a"
                           else "planes meet at an arbitrary point $D_P$")
            lines = [", ".join(rf"$\beta_{k + 1} = {v:.4g}^\circ$" for k, v in enumerate(bdeg))]
            if exact:
                lines += _info_lines(n)[:2]
            else:
                lines += [rf"$\det\mathbf{{J}} = {_fmt(n['det_J'])}$ (float)",
                          f"rank $\\mathbf{{F}}$ = {n['rank_F']}, mobility {n['mobility']}"]
            dr.info_box(ax, lines, below=True)
        dr.common_view(axes, views, pad=0.1)
        fig.legend(handles=dr.legend_handles([("wheel plane", "plane"), ("axle", "axle"),
                                              ("axles cross", f"marker:o:{ROLE['axle']}"),
                                              ("$D_P$", f"marker:D:{ROLE['dp']}")]),
                   loc="outside lower center", ncols=4)
    a, b = numbers["a"], numbers["b"]
    cap = (r"Singular configurations with the planes of all three wheels through one point $D_P$ (item (v)): (a) the "
           rf"operation point $C$ ({_beta_text(a['beta_deg'])}; $\det\mathbf{{J}} = {a['det_J_exact']}$ exactly), "
           rf"(b) an arbitrary point $D_P = ({D_arbitrary[0]:g}, {D_arbitrary[1]:g})L$ (angles from "
           rf"`planes_through`; computed $\det\mathbf{{J}} = {_fmt(b['det_J'])}$, and the computed concurrency point "
           rf"is $D_P$ within ${_fmt(b['D_P_error'], 2)}$). The axles cross pairwise at three different points (open "
           rf"circles), so rank $\mathbf{{F}} = {a['rank_F']}$ and {b['rank_F']}: mobility 0, the robot cannot move; "
           r"(a) can serve as a brake.")
    return _finish(fig, "Singular configurations: all wheel planes through one point", cap, numbers)


# ------------------------------------------------------------------------------ Fig. 13
def fig13(uc=(1.7, 1.1)):
    r"""Fig. 13: steering angles that make a commanded rotation about U admissible.

    :math:`\mathbf u_c` (63), :math:`\mathbf u_i = \mathbf u_c - \mathbf d_i` (64), the angles from
    :func:`wmr.steering_angles` (axles through U) and, for comparison, the printed (65)
    :math:`\arccos(\mathbf u_c^T\mathbf u_i/\|\mathbf u_c\|\|\mathbf u_i\|)`.

    Returns
    -------
    Figure
        ``wmr_numbers``: twist, u_c, u_i, beta_deg, printed65_deg, axle_meet, axle_meet_error,
        rank_F, mobility, slip (residual of the inverse kinematics), admissible.
    """
    from ...analysis.steering import centre_to_wheels, instantaneous_centre
    bot = centred_robot()
    uc = np.asarray(uc, dtype=float)
    twist = np.array([1.0, uc[1], -uc[0]])                 # (63): c_dot = -psi_dot E u_c
    U = instantaneous_centre(twist).point
    ui = centre_to_wheels(twist, bot.mount_points)
    beta = steering_angles(bot, twist)
    meet = ln.axles_concurrency(bot, beta)
    p65 = np.degrees(np.arccos(ui @ U / (np.linalg.norm(ui, axis=1) * np.linalg.norm(U))))
    sol = inverse(bot, beta, twist)
    rk = int(rank_F(bot, beta))
    n = {"twist": twist.tolist(), "u_c": U.tolist(), "u_i": ui.tolist(), "beta_deg": np.degrees(beta).tolist(),
         "printed65_deg": p65.tolist(), "axle_meet_kind": meet.kind.name.lower(),
         "axle_meet": None if meet.point is None else meet.point.tolist(),
         "axle_meet_error": float(np.linalg.norm(meet.point - U)), "rank_F": rk, "mobility": 3 + bot.n_rates - rk,
         "slip": float(np.abs(sol.residual).max()), "admissible": bool(sol.admissible)}
    p65_txt = "^\\circ, ".join(f"{v:.1f}" for v in p65) + "^\\circ"
    with style():
        fig, (ax,) = dr.new_figure(1, 1, width=5.6, height=4.9)
        g = dr.draw_robot(ax, bot, beta, label_offsets={2: (-13, 4), 3: (-13, -4)})
        dr.draw_axles(ax, g, include=[[U]] * 3, margin=0.3)
        dr.draw_point(ax, U, "$U$", marker="*", color=ROLE["ic"], size=11, offset=(0, 9), ha="center", zorder=9.5)
        dr.draw_arrow(ax, g.C, U, color=PALETTE["dark"], lw=1.3, head=9, zorder=8)
        dr.label(ax, 0.42 * U, r"$\mathbf{u}_c$", offset=(4, -4), ha="left", va="top")
        for k in range(bot.w):
            dr.draw_arrow(ax, g.P[k], ui[k], color=PALETTE["green"], lw=1.0, head=7, zorder=7.5)
            nrm = np.array([-ui[k][1], ui[k][0]]) / np.linalg.norm(ui[k])      # left normal of u_i
            dr.label(ax, g.P[k] + 0.45 * ui[k], rf"$\mathbf{{u}}_{k + 1}$", offset=(7 * nrm[0], 7 * nrm[1]),
                     ha="center", va="center", color=PALETTE["green"])
            ref = np.array([1.0, 0.0])                       # beta_i: from the body x-direction to the axle i_i
            ax.plot(*np.stack([g.P[k], g.P[k] + 0.6 * ref]).T, color=PALETTE["grey"], lw=0.6, ls=(0, (1.5, 1.5)),
                    zorder=6)
            dr.draw_angle(ax, g.P[k], 0.48, 0.0, float(beta[k]), rf"$\beta_{k + 1}$", color=PALETTE["purple"],
                          text_radius=1.3)
        R = dr.platform_radius(bot)
        dr.fit_view(ax, np.vstack([dr.robot_extent(g, R), U[None] + 0.3]), pad=0.04)
        dr.info_box(ax, [", ".join(rf"$\beta_{k + 1} = {v:.1f}^\circ$" for k, v in enumerate(n["beta_deg"]))
                         + ";  printed (65): $" + p65_txt + "$",
                         rf"axles meet at $U$ (computed, error ${_fmt(n['axle_meet_error'], 2)}$);  "
                         f"rank $\\mathbf{{F}}$ = {rk}, mobility {n['mobility']}"], below=True)
        dr.scale_bar(ax, L_PAPER, "$L$", loc=(0.03, 0.03))
    cap = (rf"Steering angles of the wheels for a rotation about $U$, $\mathbf{{u}}_c = ({uc[0]:g}, {uc[1]:g})L$ (63); "
           r"$\mathbf{u}_i = \mathbf{u}_c - \mathbf{d}_i$ (64) in green. The angles computed by `wmr.steering_angles`, "
           + ", ".join(rf"$\beta_{k + 1} = {v:.2f}^\circ$" for k, v in enumerate(n["beta_deg"]))
           + rf" (from the body $x$-axis to the axle $\mathbf{{i}}_i$), put every axle through $U$ (computed "
           rf"intersection within ${_fmt(n['axle_meet_error'], 2)}$; rank $\mathbf{{F}} = {rk}$, inverse kinematics "
           rf"residual ${_fmt(n['slip'], 2)}$). The printed (65) would give "
           + ", ".join(f"{v:.2f}" for v in p65)
           + r" degrees, the angles between $\mathbf{u}_c$ and $\mathbf{u}_i$, which are not the steering angles.")
    return _finish(fig, "Steering angles of the wheels", cap, n)


# ------------------------------------------------------------------------------ det J map
def _slice(bot, beta1, g):
    B2, B3 = np.meshgrid(g, g, indexing="xy")
    beta = np.stack([np.full_like(B2, beta1), B2, B3], axis=-1) * DEG
    J = bot.J(beta, L=L_PAPER)
    r3 = float(np.prod([u.r for u in bot.wheels]))
    D = np.linalg.det(J) / r3
    kap = condition_number(J)
    A, _ = twist_constraints(bot, beta)
    return D, kap, np.linalg.det(A)


def det_map(beta1s=(60.0, 20.0), n=400):
    r""":math:`\det\mathbf J` and :math:`\kappa(\mathbf J)` over :math:`(\beta_2,\beta_3)` for fixed :math:`\beta_1` (batched).

    For each :math:`\beta_1` in ``beta1s`` (a column of panels) an ``n`` x ``n`` grid is evaluated in
    one batch.  Solid black: the singular curves (zero contour of :math:`\det\mathbf J`); dashed:
    configurations with concurrent axles (zero contour of :math:`\det\mathbf A`, the twist-constraint
    matrix of :func:`wmr.analysis.mobility.twist_constraints`: rank F = 5, the robot can move); markers:
    where both hold (:func:`wmr.analysis.singularities.singular_motions`).

    Returns
    -------
    Figure
        ``wmr_numbers``: per beta1 (key ``"beta1=<deg>"``): det_min, det_max (of det J / r^3),
        kappa_min, singular_fraction, singular_motions (list of [beta2, beta3, family]),
        singular_motion_det_max; and n, time_s (evaluation time of all grids).
    """
    from matplotlib import colormaps as cmaps
    from matplotlib.lines import Line2D
    bot = centred_robot()
    g = -180.0 + (np.arange(n) + 0.5) * 360.0 / n          # cell centres: no sample sits exactly on a zero
    t0 = time.perf_counter()
    data = {b1: _slice(bot, b1, g) for b1 in beta1s}
    elapsed = time.perf_counter() - t0
    numbers = {"n": n, "time_s": elapsed}
    lim = max(float(np.abs(D).max()) for D, _, _ in data.values())
    fam_style = {"i": ("o", PALETTE["vermillion"]), "i'": ("s", PALETTE["vermillion"]),
                 "v-circle": ("^", PALETTE["yellow"])}
    with style():
        fig = Figure(figsize=(7.2, 6.6), layout="constrained")
        axes = fig.subplots(2, len(beta1s), squeeze=False)
        for col, b1 in enumerate(beta1s):
            D, kap, dA = data[b1]
            lk = np.log10(np.clip(np.where(np.isfinite(kap), kap, 1e16), 1, 1e16))
            mb, fams = sg.singular_motions(bot, b1 * DEG)
            mdeg = np.degrees(mb)
            finite = kap[np.isfinite(kap)]
            numbers[f"beta1={b1:g}"] = {
                "det_min": float(D.min()), "det_max": float(D.max()), "kappa_min": float(finite.min()),
                "singular_fraction": float(np.mean(~np.isfinite(kap))),
                "singular_motions": [[float(a), float(b), f] for (_, a, b), f in zip(mdeg, fams)],
                "singular_motion_det_max": float(np.abs(sg.det_J(bot, mb)).max()),
                "singular_motion_ranks": sorted(set(int(v) for v in rank_F(bot, mb)))}
            for row, (Z, kw) in enumerate(((D, dict(cmap=cmaps["PuOr"].resampled(64), vmin=-lim, vmax=lim)),
                                           (lk, dict(cmap=cmaps["cividis"].resampled(64), vmin=0, vmax=2)))):
                ax = axes[row, col]
                m = ax.imshow(Z, extent=(-180, 180, -180, 180), origin="lower", interpolation="nearest",
                              aspect="equal", **kw)
                ax.contour(g, g, D, levels=[0.0], colors=[PALETTE["black"]], linewidths=1.2)
                ax.contour(g, g, dA, levels=[0.0], colors=[PALETTE["sky"]], linewidths=1.0,
                           linestyles=[(0, (4, 2))])
                for (a, b, f) in numbers[f"beta1={b1:g}"]["singular_motions"]:
                    mk, c = fam_style.get(f, ("x", PALETTE["black"]))
                    ax.plot([a], [b], marker=mk, color=c, markersize=6, markeredgecolor=PALETTE["black"],
                            markeredgewidth=0.7, linestyle="none", zorder=5, clip_on=False)
                ax.set_aspect("equal")
                ax.set_xlim(-180, 180)
                ax.set_ylim(-180, 180)
                ax.set_xticks(np.arange(-180, 181, 90))
                ax.set_yticks(np.arange(-180, 181, 90))
                ax.tick_params(labelsize=dr.FONT_SMALL)
                ax.set_xlabel(r"$\beta_2$ (deg)")
                if col == 0:
                    ax.set_ylabel(r"$\beta_3$ (deg)")
                what = r"$\det\mathbf{J}/r^3$" if row == 0 else r"$\log_{10}\kappa(\mathbf{J})$"
                ax.set_title(f"({'abcd'[row * len(beta1s) + col]}) {what}, $\\beta_1 = {b1:g}^\\circ$", loc="left")
                if col == len(beta1s) - 1:
                    fig.colorbar(m, ax=axes[row, :].tolist(), shrink=0.9,
                                 label=r"$\det\mathbf{J}/r^3$" if row == 0 else r"$\log_{10}\kappa(\mathbf{J})$",
                                 extend="neither" if row == 0 else "max")
        handles = [Line2D([], [], color=PALETTE["black"], lw=1.2, label=r"$\det\mathbf{J} = 0$"),
                   Line2D([], [], color=PALETTE["sky"], lw=1.0, ls=(0, (4, 2)), label=r"axles concurrent (rank $\mathbf{F}=5$)")]
        for f, lab in (("i", "(i)"), ("i'", "(i')"), ("v-circle", "IC on the circle through the $P_i$")):
            mk, c = fam_style[f]
            handles.append(Line2D([], [], marker=mk, color=c, markeredgecolor=PALETTE["black"], markeredgewidth=0.7,
                                  linestyle="none", markersize=6, label=lab))
        fig.legend(handles=handles, loc="outside lower center", ncols=3)
    alpha = np.arctan2(bot.mount_points[:, 1], bot.mount_points[:, 0])      # polar angles of the P_i
    vortex = {sgn: float(condition_number(bot.J(alpha + sgn * 45 * DEG, L=L_PAPER))) for sgn in (1, -1)}
    numbers["kappa_vortex"] = vortex[1]
    numbers["kappa_vortex_minus"] = vortex[-1]
    numbers["vortex_beta_deg"] = [float(_deg(wrap_angle(a))) for a in alpha + 45 * DEG]
    k0 = numbers[f"beta1={beta1s[0]:g}"]
    a13 = _deg(ln.pair_line_angle(bot, 1, 3))
    a23 = _deg(ln.pair_line_angle(bot, 2, 3))
    kmin = min(numbers[f"beta1={b:g}"]["kappa_min"] for b in beta1s)
    cap = (rf"$\det\mathbf{{J}}/r^3$ (top) and $\log_{{10}}\kappa(\mathbf{{J}})$ (bottom, clipped at 2) of the WMR with three "
           rf"centred wheels over $(\beta_2, \beta_3)$ for $\beta_1 = {beta1s[0]:g}^\circ$ (left) and "
           rf"${beta1s[1]:g}^\circ$ (right), each on a {n}$\times${n} grid evaluated in one batch. Black: the singular "
           r"curves $\det\mathbf{J} = 0$. For $\beta_1 = "
           rf"{beta1s[0]:g}^\circ$ plane 1 lies on the side $P_1P_3$, and the singular set is the straight lines "
           rf"$\beta_3 \equiv {a13}^\circ$ (item (ii) and its half-turn variant) and $\beta_2 \equiv {a23}^\circ$ "
           r"(mod $180^\circ$; planes 1 and 2 through $P_3$, $\beta_3$ free); for a generic $\beta_1$ it is a "
           r"curve. Dashed: configurations with concurrent axles, the only ones in which the robot can move "
           r"(rank $\mathbf{F} = 5$). Markers: where the robot can move although $\mathbf{J}$ is singular (computed "
           rf"$|\det\mathbf{{J}}| \leq {_fmt(max(numbers[f'beta1={b:g}']['singular_motion_det_max'] for b in beta1s), 2)}$, "
           r"rank $\mathbf{F} = 5$): all planes parallel ((i), (i')) and rotations about a point of the circle through "
           rf"the $P_i$. On these slices $\kappa(\mathbf{{J}}) \geq {kmin:.3f}$: although $\mathbf{{J}}_{{L1}}$ and "
           r"$\mathbf{J}_2$ are isotropic, $\mathbf{J}$ is isotropic only at special configurations, e.g. with every "
           r"wheel turned by the same $45^\circ$ from its radial line $CP_i$ (computed $\kappa(\mathbf{J}) = "
           + f"{numbers['kappa_vortex']:.12f}" + r"$ at $\beta = ("
           + ", ".join(f"{_deg(_b * DEG)}" for _b in numbers["vortex_beta_deg"]) + r")^\circ$).")
    del k0
    return _finish(fig, "Singular configurations and conditioning of J", cap, numbers)


# ------------------------------------------------------------------------------ conventions
def conventions(psi=25 * DEG, beta=35 * DEG):
    r"""A drawing of the package's conventions (:mod:`wmr.conventions`).

    (a) Fixed frame :math:`\mathcal F`, body frame :math:`\mathcal B` at C, :math:`\psi`,
    :math:`\mathbf c`, :math:`\mathbf d_i = \overrightarrow{CP_i}`; (b) an offset wheel:
    :math:`\beta_i` from :math:`\mathbf i` to :math:`\mathbf i_i`, :math:`\mathbf j_i`,
    :math:`H_i = P_i - d\,\mathbf j_i`; (c) a dual wheel: wheels at :math:`P_i \pm b\,\mathbf i_i`.

    Returns
    -------
    Figure
        ``wmr_numbers``: psi_deg, beta_deg, H_minus_P (offset wheel, body frame), i, j,
        dual_wheels (body frame), mount_points (paper numbering).
    """
    from ...model.wheels import DualWheel, OffsetWheel
    bot = paper_robot("centred", L=L_PAPER, r=R_CENTRED)
    pose = (psi, 1.55, 1.1)
    r_ = 0.3
    ow = OffsetWheel((0.0, 0.0), r=r_, d=r_)
    dw = DualWheel((0.0, 0.0), r=r_, b=0.45)
    po = ow.points(beta)
    pd = dw.points(beta)
    numbers = {"psi_deg": float(np.degrees(psi)), "beta_deg": float(np.degrees(beta)),
               "H_minus_P": (po["H"] - po["P"]).tolist(), "j": po["j"].tolist(), "i": po["i"].tolist(),
               "dual_wheels": pd["wheels"].tolist(), "mount_points": bot.mount_points.tolist()}
    P = po["P"]
    with style():
        fig, axes = dr.new_figure(1, 3, width=7.4, height=2.7)
        # (a) frames
        ax = axes[0]
        dr.draw_frame(ax, (0, 0), 0.0, 0.5, labels=(r"$\mathbf{i}_\mathcal{F}$", r"$\mathbf{j}_\mathcal{F}$"),
                      color=ROLE["fixed_frame"])
        dr.label(ax, (0, 0), r"$\mathcal{F}$", offset=(-4, -4), ha="right", va="top", color=ROLE["fixed_frame"])
        g = dr.draw_robot(ax, bot, np.zeros(3), pose, frame=False, label_offsets={"C": (-2, -7), 2: (-12, 6),
                                                                                  1: (-13, 0), 3: (13, 0)})
        dr.draw_frame(ax, g.C, psi, 0.6, zorder=8)
        ax.plot(*np.stack([g.C, g.C + np.array([0.9, 0.0])]).T, color=PALETTE["grey"], lw=0.6, ls=(0, (2, 2)))
        dr.draw_angle(ax, g.C, 0.82, 0.0, psi, r"$\psi$", text_radius=1.2)
        dr.draw_arrow(ax, g.C, g.P[1] - g.C, color=PALETTE["blue"], lw=1.1, head=7, zorder=8)
        dr.label(ax, g.C + 0.62 * (g.P[1] - g.C), r"$\mathbf{d}_2$", offset=(7, -2), ha="left", va="center",
                 color=PALETTE["blue"])
        dr.draw_arrow(ax, (0, 0), g.C, color=PALETTE["grey"], lw=0.8, head=6, zorder=3)
        dr.label(ax, 0.35 * g.C, r"$\mathbf{c}$", offset=(4, -4), ha="left", va="top", color=PALETTE["grey"])
        dr.fit_view(ax, np.vstack([dr.robot_extent(g, dr.platform_radius(bot)), [[-0.35, -0.35]]]), pad=0.02)
        dr.panel_title(ax, "a", r"frames $\mathcal{F}$ and $\mathcal{B}$")
        # (b) offset wheel, (c) dual wheel
        for ax, unit, letter in ((axes[1], ow, "b"), (axes[2], dw, "c")):
            ax.plot(*np.stack([P, P + np.array([0.8, 0.0])]).T, color=PALETTE["grey"], lw=0.6, ls=(0, (2, 2)))
            dr.label(ax, P + np.array([0.8, 0.0]), r"$\mathbf{i}$", offset=(3, 0), ha="left", va="center",
                     color=PALETTE["grey"], fontsize=dr.FONT_SMALL)
            dr.draw_unit(ax, unit, beta, light=True, zorder=3)
            dr.draw_frame(ax, P, beta, 0.62, labels=(r"$\mathbf{i}_i$", r"$\mathbf{j}_i$"), color=PALETTE["blue"],
                          zorder=7)
            dr.draw_angle(ax, P, 0.42, 0.0, beta, r"$\beta_i$", text_radius=1.35, color=PALETTE["purple"], zorder=7)
            dr.label(ax, P, "$P_i$", offset=(-7, 4), ha="right", va="bottom")
            dr.fit_view(ax, np.array([[-0.72, -0.78], [0.9, 0.72]]), pad=0.0)
        ax = axes[1]
        dr.draw_line(ax, po["H"], po["i"], kind="axle", min_half=0.5, margin=0.05)
        dr.draw_point(ax, po["H"], None, size=3.5, color=PALETTE["dark"], zorder=9)
        dr.label(ax, po["H"], "$H_i$", offset=(8, -3), ha="left", va="top")
        dr.label(ax, 0.5 * (P + po["H"]), "$d$", offset=(-7, -2), ha="right", va="center", color=PALETTE["vermillion"])
        ax.plot(*np.stack([P, po["H"]]).T, color=PALETTE["vermillion"], lw=1.6, zorder=8)
        dr.panel_title(ax, "b", r"offset wheel: $H_i = P_i - d\,\mathbf{j}_i$")
        ax = axes[2]
        for k, w_ in enumerate(pd["wheels"]):
            dr.label(ax, w_ + (r_ + 0.1) * po["j"], f"wheel {k + 1}", offset=(0, 0), ha="center", va="center",
                     fontsize=dr.FONT_SMALL)
        dr.panel_title(ax, "c", r"dual wheel: wheels at $P_i \pm b\,\mathbf{i}_i$")
    cap = (r"Conventions of the package. (a) Fixed frame $\mathcal{F}$ and body frame $\mathcal{B}$ "
           r"($\mathbf{i}$, $\mathbf{j}$) at the operation point $C$, turned by $\psi$ (counter-clockwise positive, here "
           rf"{np.degrees(psi):g}$^\circ$); $\mathbf{{c}}$ locates $C$ in $\mathcal{{F}}$ and "
           r"$\mathbf{d}_i = \overrightarrow{CP_i}$ is resolved in $\mathcal{B}$; the paper's numbering "
           r"$\mathbf{d}_1 = L(-1, 0)$, $\mathbf{d}_2 = L(\frac12, \frac{\sqrt3}2)$, $\mathbf{d}_3 = L(\frac12, -\frac{\sqrt3}2)$. "
           rf"(b) Offset wheel: the intermediate body turns by $\beta_i$ (here {np.degrees(beta):g}$^\circ$) from $\mathbf{{i}}$ "
           r"to the axle $\mathbf{i}_i$; $\mathbf{j}_i$ is the rolling direction (arrows on the wheels) and the wheel "
           r"centre is $H_i = P_i - d\,\mathbf{j}_i$ (a centred wheel has $d = 0$). (c) Dual wheel: wheel 1 at "
           r"$P_i + b\,\mathbf{i}_i$, wheel 2 at $P_i - b\,\mathbf{i}_i$. No slip: "
           r"$\dot{\mathbf{h}}_i = -r\dot\theta_i\mathbf{j}_i$.")
    return _finish(fig, "Conventions", cap, numbers)


# ------------------------------------------------------------------------------ writer
#: key -> (function, paper figure number or "")
def show(fig, dpi=110):
    """Display a figure in a notebook as a PNG with its caption; returns its computed numbers.

    Parameters
    ----------
    fig : matplotlib.figure.Figure or str
        A figure made by this module, or its key in :data:`FIGURES` (e.g. ``"fig07"``).
    dpi : int
        Resolution of the PNG.

    Returns
    -------
    dict
        ``fig.wmr_numbers``: the numbers the figure asserts.
    """
    import io

    from IPython.display import Image, Markdown, display

    label = ""
    if isinstance(fig, str):
        if fig not in FIGURES:
            raise ValueError(f"unknown figure {fig!r}; expected one of {sorted(FIGURES)}")
        func, number = FIGURES[fig]
        label = f"Figure {number} (regenerated): " if number else ""
        fig = func()
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi)
    title = getattr(fig, "wmr_title", "")
    display(Image(buf.getvalue()), Markdown(f"*{label}{title}.* {getattr(fig, 'wmr_caption', '')}"))
    return getattr(fig, "wmr_numbers", {})


FIGURES = {
    "fig07": (fig07, "7"), "fig08": (fig08, "8"), "fig09": (fig09, "9"), "fig10": (fig10, "10"),
    "fig11": (fig11, "11"), "fig12": (fig12, "12"), "fig13": (fig13, "13"),
    "detmap": (det_map, ""), "conventions": (conventions, ""),
}


def git_commit(root=None):
    """The source commit of the figures: the last commit that changed ``wmr/``, or "unknown".

    Figures are functions of the package alone, so they name the commit of its code (with
    ``+dirty`` when ``wmr/`` has uncommitted changes); regenerating them after commits that do
    not touch the package gives identical files.
    """
    root = root or Path(__file__).resolve().parents[3]   # TODO(issue 8): the build passes the root
    try:
        p = subprocess.run(["git", "log", "-1", "--format=%H", "--", "wmr"], cwd=root,
                           capture_output=True, text=True, timeout=10)
        commit = p.stdout.strip() if p.returncode == 0 else ""
        if not commit:
            return "unknown"
        q = subprocess.run(["git", "status", "--porcelain", "--", "wmr"], cwd=root,
                           capture_output=True, text=True, timeout=10)
        return commit + ("+dirty" if q.returncode == 0 and q.stdout.strip() else "")
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def save(fig, outdir, key, function, commit, formats=("svg", "pdf", "png")):
    """Write ``outdir/key.<fmt>`` deterministically, with provenance metadata; returns the paths."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    title = f"{key}: {getattr(fig, 'wmr_title', key)}"
    desc = f"made by {function} (wmr) at git commit {commit}"
    meta = {
        "svg": {"Title": title, "Description": desc, "Date": None, "Creator": f"wmr {function}"},
        "pdf": {"Title": title, "Subject": desc, "Keywords": f"wmr; {function}; commit {commit}",
                "Creator": f"wmr {function}", "CreationDate": None, "ModDate": None},
        "png": {"Title": title, "Description": desc, "Software": f"wmr {function}"},
    }
    paths = []
    order = sorted(formats, key=lambda f: f != "png")       # lay out once (on the first save), then freeze
    with style():
        for k, fmt in enumerate(order):
            p = outdir / f"{key}.{fmt}"
            fig.savefig(p, format=fmt, metadata=meta[fmt])
            paths.append(p)
            if k == 0 and fig.get_layout_engine() is not None:
                fig.set_layout_engine("none")
    return paths


def build(key):
    """Make the figure ``key`` of :data:`FIGURES`."""
    fn, _ = FIGURES[key]
    return fn()


def write_all(outdir, keys=None, formats=("svg", "pdf", "png"), csv=True, commit=None, verbose=False):
    """Write the figures, ``captions.json`` and (``csv=True``) ``singularities.csv`` into ``outdir``.

    With a subset of ``keys``, the other entries of an existing ``captions.json`` are kept.

    Returns
    -------
    dict
        The captions (key -> {number, title, caption, function, commit}).
    """
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    commit = commit or git_commit()
    keys = list(FIGURES) if keys is None else list(keys)
    caps = {}
    for key in keys:
        t0 = time.perf_counter()
        fn, number = FIGURES[key]
        function = f"wmr.paper.figures.{fn.__name__}"
        fig = fn()
        save(fig, outdir, key, function, commit, formats)
        caps[key] = {"number": number, "title": fig.wmr_title, "caption": fig.wmr_caption,
                     "function": function, "commit": commit}
        if verbose:
            print(f"  {key:12s} {time.perf_counter() - t0:5.2f} s", file=sys.stderr)
    path = outdir / "captions.json"
    if set(keys) != set(FIGURES) and path.exists():         # a subset: keep the other entries
        old = json.loads(path.read_text(encoding="utf-8"))
        caps = {k: caps.get(k, old.get(k)) for k in FIGURES if k in caps or k in old}
    path.write_text(json.dumps(caps, indent=2, ensure_ascii=False) + "\n", encoding="utf-8")
    if csv:
        t0 = time.perf_counter()
        fams.write_csv(outdir / "singularities.csv")
        if verbose:
            print(f"  {'singularities':12s} {time.perf_counter() - t0:5.2f} s", file=sys.stderr)
    return caps


def main(argv=None):
    """``python -m wmr.paper.figures OUTDIR [KEY ...]``."""
    import matplotlib
    matplotlib.use("Agg")                                   # headless; PNG is rendered by Agg in any case
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] in ("-h", "--help"):
        print(main.__doc__ + "\nkeys: " + " ".join(FIGURES))
        return 0 if argv else 2
    outdir, keys = argv[0], (argv[1:] or None)
    bad = [k for k in keys or [] if k not in FIGURES]
    if bad:
        print(f"unknown figure keys {bad}; known: {list(FIGURES)}", file=sys.stderr)
        return 2
    t0 = time.perf_counter()
    write_all(outdir, keys, verbose=os.environ.get("WMR_VERBOSE", "1") != "0")
    print(f"wrote {outdir} in {time.perf_counter() - t0:.1f} s", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
