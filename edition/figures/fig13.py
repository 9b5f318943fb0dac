r"""Fig. 13: steering angles that make a commanded rotation about U admissible.

:math:`\mathbf u_c` (63), :math:`\mathbf u_i = \mathbf u_c - \mathbf d_i` (64), the angles from
:func:`wmr.steering_angles` (axles through U) and, for comparison, the printed (65)
:math:`\arccos(\mathbf u_c^T\mathbf u_i/\|\mathbf u_c\|\|\mathbf u_i\|)`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr.analysis.kinematics import inverse
from wmr.analysis.mobility import rank_F
from wmr.analysis.steering import centre_to_wheels, instantaneous_centre, steering_angles

from ..text import bound, degrees
from .common import L_PAPER, centred_robot, drawing, residual, snap
from .configs import AxleMeet, axles_meet

__all__ = ["NUMBER", "TITLE", "PAPER_CAPTION", "Fig13Data", "data", "draw", "caption"]

NUMBER = "13"
TITLE = "Steering angles of the wheels"
PAPER_CAPTION = "Steering angles of the wheels."


@dataclass(frozen=True)
class Fig13Data:
    r"""The numbers of Fig. 13.

    Attributes
    ----------
    twist : tuple (3,)
        :math:`(\dot\psi, \dot{\mathbf c})` of the rotation about U at :math:`\dot\psi = 1` (63).
    u_c : tuple (2,)
        U from :func:`wmr.instantaneous_centre`.
    u_i : tuple of 3 (2,)
        :math:`\mathbf u_i = \mathbf u_c - \mathbf d_i` from :func:`wmr.centre_to_wheels` (64).
    beta_deg : tuple (3,)
        :func:`wmr.steering_angles`, degrees.
    printed65_deg : tuple (3,)
        The printed (65), degrees.
    axles : AxleMeet
        Where the axles meet, and the distance of that point from U.
    rank_F : int
        :math:`\operatorname{rank}\mathbf F` (24) at the steering angles.
    mobility : int
        :math:`\nu` (27).
    slip : float
        Largest residual of the inverse kinematics (:func:`wmr.inverse`).
    admissible : bool
        The twist is executable without slip at ``beta_deg``.
    robot : wmr.Robot
        Drawing only: the robot drawn (:func:`~edition.figures.common.centred_robot`).
    beta : numpy.ndarray (3,)
        Drawing only: the steering angles (radians).
    """

    twist: tuple
    u_c: tuple
    u_i: tuple
    beta_deg: tuple
    printed65_deg: tuple
    axles: AxleMeet
    rank_F: int = 0
    mobility: int = 0
    slip: float = residual(default=0.0)
    admissible: bool = False
    robot: object = drawing(default=None)
    beta: np.ndarray = drawing(default=None)


def data(uc=(1.7, 1.1)):
    """Steer the wheels for a rotation about the body point ``uc``: (63)-(65).

    Parameters
    ----------
    uc : tuple (2,), optional
        The instantaneous centre U in the body frame (units of L).

    Returns
    -------
    Fig13Data
    """
    bot = centred_robot()
    uc = np.asarray(uc, dtype=float)
    twist = np.array([1.0, uc[1], -uc[0]])  # (63): c_dot = -psi_dot E u_c
    U = instantaneous_centre(twist).point
    ui = centre_to_wheels(twist, bot.mount_points)
    beta = steering_angles(bot, twist)
    p65 = np.degrees(np.arccos(ui @ U / (np.linalg.norm(ui, axis=1) * np.linalg.norm(U))))
    sol = inverse(bot, beta, twist)
    rk = int(rank_F(bot, beta))
    return Fig13Data(
        twist=tuple(twist.tolist()),
        u_c=tuple(U.tolist()),
        u_i=tuple(map(tuple, ui.tolist())),
        beta_deg=tuple(np.degrees(beta).tolist()),
        printed65_deg=tuple(p65.tolist()),
        axles=axles_meet(bot, beta, U),
        rank_F=rk,
        mobility=3 + bot.n_rates - rk,
        slip=float(np.abs(sol.residual).max()),
        admissible=bool(sol.admissible),
        robot=bot,
        beta=snap(beta),
    )


def _angles(values, symbol=r"\beta"):
    return ", ".join(rf"${symbol}_{k + 1} = {degrees(np.radians(v), 4)}^\circ$" for k, v in enumerate(values))


def draw(data, fig=None):
    """Draw Fig. 13 from its data.

    Parameters
    ----------
    data : Fig13Data
        The numbers (:func:`data`).
    fig : matplotlib.figure.Figure, optional
        Draw into this figure (cleared) instead of a new one.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from wmr.plot import annotate as an
    from wmr.plot import robot as rd
    from wmr.plot.style import PALETTE, ROLE, fit_view, new_figure, style

    bot = data.robot
    U = snap(data.u_c)
    ui = snap(data.u_i)
    with style():
        fig, (ax,) = new_figure(1, 1, width=5.6, height=4.9, fig=fig)
        g = rd.draw_robot(ax, bot, data.beta, arrows="j")
        rd.draw_axles(ax, g, include=[[U]] * bot.w, margin=0.3)
        an.draw_point(ax, U, "$U$", marker="*", color=ROLE["ic"], size=11, offset=(0, 9), ha="center", zorder=9.5)
        an.draw_arrow(ax, g.C, U, color=PALETTE["dark"], lw=1.3, head=9, zorder=8)
        an.label(ax, 0.42 * U, r"$\mathbf{u}_c$", offset=(4, -4), ha="left", va="top")
        for k in range(bot.w):
            an.draw_arrow(ax, g.P[k], ui[k], color=PALETTE["green"], lw=1.0, head=7, zorder=7.5)
            nrm = np.array([-ui[k][1], ui[k][0]]) / np.linalg.norm(ui[k])  # left normal of u_i
            an.label(
                ax,
                g.P[k] + 0.45 * ui[k],
                rf"$\mathbf{{u}}_{k + 1}$",
                offset=(7 * nrm[0], 7 * nrm[1]),
                ha="center",
                va="center",
                color=PALETTE["green"],
            )
            # beta_i: from the body x-direction to the axle i_i
            ax.plot(
                *np.stack([g.P[k], g.P[k] + [0.6, 0.0]]).T, color=PALETTE["grey"], lw=0.6, ls=(0, (1.5, 1.5)), zorder=6
            )
            an.draw_angle(
                ax,
                g.P[k],
                0.48,
                0.0,
                float(data.beta[k]),
                rf"$\beta_{k + 1}$",
                color=PALETTE["purple"],
                text_radius=1.3,
            )
        fit_view(ax, np.vstack([rd.robot_extent(g, rd.platform_radius(bot)), U[None] + 0.3]), pad=0.04)
        an.scale_bar(ax, L_PAPER, "$L$", loc=(0.03, 0.03))
    return fig


def caption(data):
    """Our caption of Fig. 13 (Markdown with ``$...$``).

    Parameters
    ----------
    data : Fig13Data
        The numbers (:func:`data`).

    Returns
    -------
    str
        Markdown with ``$...$`` math.
    """
    uc = data.u_c
    return (
        rf"Steering angles of the wheels for a rotation about $U$, $\mathbf{{u}}_c = ({uc[0]:g}, {uc[1]:g})L$ "
        r"(63); $\mathbf{u}_i = \mathbf{u}_c - \mathbf{d}_i$ (64) in green. The angles computed by "
        rf"`wmr.steering_angles`, {_angles(data.beta_deg)} (from the body $x$-axis to the axle $\mathbf{{i}}_i$), "
        r"put every axle through $U$ (distance of the computed intersection from $U$: "
        rf"${bound(data.axles.error, latex=True)}$; rank $\mathbf{{F}} = {data.rank_F}$, inverse kinematics "
        rf"residual ${bound(data.slip, latex=True)}$). The printed (65) would give "
        + ", ".join(rf"${degrees(np.radians(v), 4)}^\circ$" for v in data.printed65_deg)
        + r", the angles between $\mathbf{u}_c$ and $\mathbf{u}_i$, which are not the steering angles."
    )
