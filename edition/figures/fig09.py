r"""Fig. 9: rotation of the centred-wheel robot with the IC at C and at an arbitrary point U (simulated).

Steering angles from :func:`wmr.steering_angles` (axles through the IC), joint rates from
:func:`wmr.inverse`, motion from :func:`wmr.integrate` with :math:`\dot\psi = 1`; the twist of a
rotation about the body point :math:`\mathbf u_c` is :math:`(\dot\psi, -\dot\psi\mathbf E\mathbf u_c)` (63).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr.analysis.integration import integrate
from wmr.analysis.kinematics import inverse
from wmr.analysis.mobility import rank_F
from wmr.analysis.steering import steering_angles

from ..text import bound
from .common import DEG, L_PAPER, centred_robot, drawing, fit_circle, residual, snap
from .configs import AxleMeet, axles_meet

__all__ = ["NUMBER", "TITLE", "PAPER_CAPTION", "RotationRun", "Fig09Data", "data", "draw", "caption"]

NUMBER = "9"
TITLE = "WMR in rotation about C and about U"
PAPER_CAPTION = "WMR in rotation with IC located at the operating point C and with IC located at an arbitrary point U."


@dataclass(frozen=True)
class RotationRun:
    r"""One simulated rotation about a body point :math:`\mathbf u_c`.

    Attributes
    ----------
    u_c : tuple (2,)
        The IC in the body frame (units of L).
    beta_deg : tuple (3,)
        Steering angles from :func:`wmr.steering_angles`, degrees.
    rank_F : int
        :math:`\operatorname{rank}\mathbf F` (24) at the steering angles.
    mobility : int
        :math:`\nu` (27).
    axles : AxleMeet
        Where the axles meet, and the distance of that point from :math:`\mathbf u_c`.
    radius : float
        Fitted radius of the path of C (the IC at U); the largest distance of C from the IC (the IC at C).
    radius_expected : float
        :math:`\|\mathbf u_c\|`.
    psi_rate : float
        Mean :math:`\dot\psi` along the run.
    turn_deg : float
        :math:`\psi` at the end, degrees.
    slip_max : float
        Largest residual of (21).
    beta : numpy.ndarray (N, 3)
        Drawing only: steering angles along the run (radians).
    pose : numpy.ndarray (N, 3)
        Drawing only: :math:`(\psi, X, Y)` along the run.
    pivots : numpy.ndarray (N, 3, 2)
        Drawing only: the paths of the :math:`P_i`.
    """

    u_c: tuple
    beta_deg: tuple
    rank_F: int
    mobility: int
    axles: AxleMeet
    radius: float = 0.0
    radius_expected: float = 0.0
    psi_rate: float = 0.0
    turn_deg: float = 0.0
    slip_max: float = residual(default=0.0)
    beta: np.ndarray = drawing(default=None)  # (N, 3)
    pose: np.ndarray = drawing(default=None)  # (N, 3)
    pivots: np.ndarray = drawing(default=None)  # (N, 3, 2)


@dataclass(frozen=True)
class Fig09Data:
    r"""The numbers of Fig. 9: U (units of L), the angle turned (degrees) and the two runs ``C`` and ``U``.

    Attributes
    ----------
    uc_U : tuple (2,)
        The point U in the body frame (units of L).
    turn : float
        Angle turned by the platform (degrees).
    C : RotationRun
        The rotation about C.
    U : RotationRun
        The rotation about U.
    robot : wmr.Robot
        Drawing only: the robot simulated.
    """

    uc_U: tuple
    turn: float
    C: RotationRun
    U: RotationRun
    robot: object = drawing(default=None)


def _run(bot, uc, turn, steps=120):
    uc = np.asarray(uc, dtype=float)
    twist = np.array([1.0, uc[1], -uc[0]])  # (63): c_dot = -psi_dot E u_c
    beta = steering_angles(bot, twist)
    rates = inverse(bot, beta, twist).value
    tr = integrate(bot, rates, beta, turn, turn / steps)
    rk = int(rank_F(bot, beta))
    C = tr.pose[:, 1:]
    rad = fit_circle(C)[1] if np.linalg.norm(uc) > 0 else float(np.max(np.linalg.norm(C - uc, axis=1)))
    return RotationRun(
        u_c=tuple(uc.tolist()),
        beta_deg=tuple(np.degrees(beta).tolist()),
        rank_F=rk,
        mobility=3 + bot.n_rates - rk,
        axles=axles_meet(bot, beta, uc),
        radius=rad,
        radius_expected=float(np.linalg.norm(uc)),
        psi_rate=float(np.mean(tr.twist[:, 0])),
        turn_deg=float(np.degrees(tr.pose[-1, 0])),
        slip_max=float(tr.slip.max()),
        beta=snap(tr.beta),
        pose=snap(tr.pose),
        pivots=snap(np.stack([tr.unit_points(k, "P") for k in range(bot.w)], axis=1)),
    )


def data(uc_U=(-0.7, 1.8), turn=60.0):
    """Simulate the rotations about C and about U.

    Parameters
    ----------
    uc_U : (2,)
        U in the body frame, units of L.
    turn : float
        Angle turned, degrees (at :math:`\\dot\\psi = 1`).

    Returns
    -------
    Fig09Data
    """
    bot = centred_robot()
    return Fig09Data(
        uc_U=tuple(map(float, uc_U)),
        turn=turn,
        C=_run(bot, (0.0, 0.0), turn * DEG),
        U=_run(bot, uc_U, turn * DEG),
        robot=bot,
    )


def draw(data, fig=None):
    """Draw Fig. 9 from its data.

    Parameters
    ----------
    data : Fig09Data
        The numbers (:func:`data`).
    fig : matplotlib.figure.Figure, optional
        Draw into this figure (cleared) instead of a new one.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from wmr.plot import annotate as an
    from wmr.plot import robot as rd
    from wmr.plot.style import PALETTE, ROLE, common_view, new_figure, panel_title, style

    bot = data.robot
    R = rd.platform_radius(bot)
    with style():
        fig, axes = new_figure(1, 2, width=7.2, height=3.9, fig=fig)
        views = []
        for ax, name, letter in zip(axes, ("C", "U"), "ab", strict=True):
            run = getattr(data, name)
            U = snap(run.u_c)
            g0 = rd.draw_robot(ax, bot, run.beta[0], run.pose[0], zorder=4, arrows="j")
            g1 = rd.draw_robot(ax, bot, run.beta[-1], run.pose[-1], ghost=True, labels=False, arrows="j")
            rd.draw_axles(ax, g0, include=[[U]] * bot.w, margin=0.25)
            for k in range(bot.w):
                an.draw_path(ax, run.pivots[:, k], color=ROLE["path"][1], lw=1.1, zorder=2.7)
            if name == "U":
                an.draw_path(ax, run.pose[:, 1:], color=ROLE["path"][0], lw=1.6, zorder=7)
                an.draw_point(ax, U, "$U$ (IC)", marker="*", color=ROLE["ic"], size=10, offset=(8, 2), zorder=9)
                an.label(ax, g1.C, "$C'$", offset=(6, -4), ha="left", va="top")
                an.draw_arrow(ax, g0.C, U - g0.C, color=PALETTE["dark"], lw=0.8, zorder=6.5)
                an.label(ax, 0.5 * (g0.C + U), r"$\mathbf{u}_c$", offset=(5, 0), ha="left", va="center")
            else:
                an.draw_point(ax, U, None, marker="*", color=ROLE["ic"], size=10, zorder=9)
                an.label(ax, U, "IC", offset=(-10, -12), ha="right", va="top", color=ROLE["ic"])
                an.draw_angle(
                    ax, g0.C, 0.62, 0.0, float(run.pose[-1, 0]), r"$\psi$", text_radius=1.22, color=PALETTE["grey"]
                )
            views.append(np.vstack([rd.robot_extent(g0, R), rd.robot_extent(g1, R), U[None]]))
            panel_title(ax, letter, "IC at the operation point $C$" if name == "C" else "IC at a point $U$")
        common_view(axes, views, pad=0.03)
        an.scale_bar(axes[0], L_PAPER, "$L$", loc=(0.03, 0.03))
        fig.legend(
            handles=an.legend_handles(
                [
                    ("axle", "axle"),
                    ("paths of the $P_i$", f"path:{ROLE['path'][1]}"),
                    ("path of $C$", f"path:{ROLE['path'][0]}"),
                ]
            ),
            loc="outside upper center",
            ncols=3,
        )
    return fig


def caption(data):
    """Our caption of Fig. 9 (Markdown with ``$...$``).

    Parameters
    ----------
    data : Fig09Data
        The numbers (:func:`data`).

    Returns
    -------
    str
        Markdown with ``$...$`` math.
    """
    a, b = data.C, data.U
    return (
        r"Rotation of the WMR with three centred wheels (simulated, $\dot\psi = 1$, turned "
        rf"{a.turn_deg:.4g}$^\circ$; dashed: final pose): (a) IC at the operation point $C$, which stays fixed; "
        rf"(b) IC at $U$, $\mathbf{{u}}_c = ({data.uc_U[0]:g}, {data.uc_U[1]:g})L$, about which $C$ moves on a "
        rf"circle of radius $\|\mathbf{{u}}_c\| = {b.radius_expected:.4f}$ (the fitted radius differs by "
        rf"${bound(abs(b.radius - b.radius_expected), latex=True)}$). Steering angles from `wmr.steering_angles`: "
        r"the axles (dashed) all pass through the IC (distance of their computed intersection from the IC "
        rf"${bound(max(a.axles.error, b.axles.error), latex=True)}$); rank $\mathbf{{F}} = {a.rank_F}$ (mobility "
        r"1) in both cases."
    )
