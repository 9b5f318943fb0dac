r"""Fig. 7: the dead zone of three offset wheels steered one full turn without driving (simulated).

All wheels start at the same :math:`\beta` (parallel arms, the configuration in which steering
without driving is possible) and are steered with :math:`\dot\phi_i = 2\pi/T`,
:math:`\dot\theta_i = 0` (:func:`wmr.integrate`).  The path of C is fitted with a circle
(:func:`~edition.figures.common.fit_circle`); its radius is compared with the offset d.  RK4 on
this smooth periodic motion has a global error of order :math:`d\,(\omega\Delta t)^4`
(:math:`\omega = 2\pi/T`), recorded as ``tolerance``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr.analysis.integration import integrate
from wmr.model.robots import paper_robot

from ..text import degrees, number
from ..text import residual as residual_text
from .common import DEG, L_PAPER, MAX_PSI, R_OFFSET, drawing, fit_circle, residual, small, snap

__all__ = ["NUMBER", "TITLE", "PAPER_CAPTION", "Fig07Data", "data", "draw", "caption"]

NUMBER = "7"
TITLE = "Dead zone of a WMR with offset wheels"
PAPER_CAPTION = "Dead zone of a WMR with offset wheels. Insert: Enlarged view of pivoting point of offset wheel."


@dataclass(frozen=True)
class Fig07Data:
    r"""The numbers of Fig. 7.

    Attributes
    ----------
    r : float
        Wheel radius (units of L).
    d : float
        Offset (units of L).
    beta0 : float
        Initial steering angle of every wheel, degrees.
    T : float
        Time of one turn; :math:`\dot\phi_i = 2\pi/T`.
    steps : int
        RK4 steps per turn.
    dt : float
        Time step, ``T / steps``.
    later : float
        Fraction of the turn at which the dashed (later) pose is drawn.
    radius : float
        Fitted radius of the path of C.
    radius_error : float
        :math:`|R - d|`.
    tolerance : float
        :math:`d(\omega\Delta t)^4`, the order of the RK4 global error.
    centre : tuple (2,)
        Centre of the fitted circle.
    C_f : tuple (2,)
        Centroid of the contact points :math:`G_i` at the start.
    centre_error : float
        :math:`\|\text{centre} - C_\mathrm{f}\|`.
    contact_drift : float
        Largest displacement of a contact point :math:`G_i` during the turn.
    psi_max : float
        Largest :math:`|\psi|` along the run.
    slip_max : float
        Largest residual of (21) along the run.
    rank_M_equal, rank_M_generic : int
        Rank of the locked-drive matrix :math:`\mathbf M(\boldsymbol\beta)` (6 x 6,
        :func:`edition.checks.assembly.locked.locked_system`) with all :math:`\beta_i` equal and at ``generic_deg``.
    generic_deg : tuple (3,)
        Steering angles (degrees) at which the arm lines are neither concurrent nor parallel.
    robot : wmr.Robot
        Drawing only: the robot simulated.
    beta : numpy.ndarray (N, 3)
        Drawing only: steering angles along the run (radians).
    pose : numpy.ndarray (N, 3)
        Drawing only: :math:`(\psi, X, Y)` along the run.
    pivots : numpy.ndarray (N, 3, 2)
        Drawing only: the paths of the :math:`P_i`.
    contacts : numpy.ndarray (3, 2)
        Drawing only: the contact points :math:`G_i` at the start.
    later_index : int
        Drawing only: the time step of the dashed (later) pose.
    """

    r: float
    d: float
    beta0: float
    T: float
    steps: int
    later: float
    dt: float
    radius: float
    radius_error: float = small()
    tolerance: float = small()
    centre: tuple = ()
    C_f: tuple = ()
    centre_error: float = small(default=0.0)
    contact_drift: float = small(default=0.0)
    psi_max: float = residual(default=0.0)
    slip_max: float = residual(default=0.0)
    rank_M_equal: int = 0
    rank_M_generic: int = 0
    generic_deg: tuple = ()
    robot: object = drawing(default=None)
    beta: np.ndarray = drawing(default=None)  # (N, 3) radians
    pose: np.ndarray = drawing(default=None)  # (N, 3)
    pivots: np.ndarray = drawing(default=None)  # (N, 3, 2) paths of the P_i
    contacts: np.ndarray = drawing(default=None)  # (3, 2) the G_i at the start
    later_index: int = drawing(default=0)


def data(r=R_OFFSET, d=None, beta0=0.0, T=1.0, steps=240, later=3 / 8, generic=(20.0, 75.0, 140.0)):
    r"""Simulate one full turn of steering without driving and fit the path of C.

    Parameters
    ----------
    r : float
        Wheel radius (units of L).
    d : float, optional
        Offset (default r, the isotropic design of section 4.3).
    beta0 : float
        Initial steering angle of every wheel, degrees.
    T : float
        Duration of the turn.
    steps : int
        RK4 steps.
    later : float
        Fraction of the turn for the dashed pose.
    generic : tuple (3,)
        Steering angles (degrees) where the locked-drive matrix is evaluated for comparison.

    Returns
    -------
    Fig07Data
    """
    from wmr.analysis.linalg import rank

    from ..checks.assembly.locked import locked_system

    d = r if d is None else d
    bot = paper_robot("offset", L=L_PAPER, r=r, d=d)
    dt = T / steps
    omega = 2 * np.pi / T
    rates = np.tile([omega, 0.0], bot.w)  # phi_dot_i, theta_dot_i
    tr = integrate(bot, rates, np.full(bot.w, beta0 * DEG), T, dt)
    C = tr.pose[:, 1:]
    centre, R = fit_circle(C)
    G = np.stack([tr.unit_points(k, "H") for k in range(bot.w)], axis=1)  # (N, w, 2) contact points
    Cf = G[0].mean(axis=0)
    return Fig07Data(
        r=r,
        d=d,
        beta0=beta0,
        T=T,
        steps=steps,
        later=later,
        dt=dt,
        radius=R,
        radius_error=abs(R - d),
        tolerance=d * (omega * dt) ** 4,
        centre=tuple(centre.tolist()),
        C_f=tuple(Cf.tolist()),
        centre_error=float(np.linalg.norm(centre - Cf)),
        contact_drift=float(np.max(np.linalg.norm(G - G[0], axis=-1))),
        psi_max=float(np.abs(tr.pose[:, 0]).max()),
        slip_max=float(tr.slip.max()),
        rank_M_equal=int(rank(locked_system(bot, np.full(bot.w, beta0 * DEG)))),
        rank_M_generic=int(rank(locked_system(bot, np.asarray(generic) * DEG))),
        generic_deg=tuple(generic),
        robot=bot,
        beta=snap(tr.beta),
        pose=snap(tr.pose),
        pivots=snap(np.stack([tr.unit_points(k, "P") for k in range(bot.w)], axis=1)),
        contacts=snap(G[0]),
        later_index=int(round(later * steps)),
    )


def draw(data, fig=None):
    """Draw Fig. 7 from its data.

    Parameters
    ----------
    data : Fig07Data
        The numbers (:func:`data`).
    fig : matplotlib.figure.Figure, optional
        Draw into this figure (cleared) instead of a new one.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from wmr.plot import annotate as an
    from wmr.plot import robot as rd
    from wmr.plot.style import FONT_SMALL, PALETTE, ROLE, new_figure, plain_axes, style

    bot, k1 = data.robot, data.later_index
    G, Cf = data.contacts, snap(data.C_f)
    with style():
        fig, (ax,) = new_figure(1, 1, width=7.0, height=3.9, fig=fig)
        g0 = rd.draw_robot(
            ax, bot, data.beta[0], data.pose[0], wheel_labels=False, label_offsets={"C": (-6, 6)}, arrows="j"
        )
        g1 = rd.draw_robot(ax, bot, data.beta[k1], data.pose[k1], ghost=True, labels=False, arrows="j")
        an.label(ax, g1.C, "$C'$", offset=(-7, -3), ha="right", va="top")
        an.label(ax, g0.P[0], "$P$", offset=(-9, 0), ha="right", va="center")
        an.label(ax, g1.P[0], "$P'$", offset=(-8, -5), ha="right", va="top")
        for k in range(bot.w):
            an.draw_path(ax, data.pivots[:, k], color=ROLE["path"][1], lw=0.8, zorder=2.6)
        an.draw_path(ax, data.pose[:, 1:], color=ROLE["path"][0], lw=1.8, zorder=7)
        ax.plot(*np.vstack([G, G[:1]]).T, color=PALETTE["grey"], lw=0.6, ls=(0, (2, 2)), zorder=2.4)
        for k in range(bot.w):
            an.draw_point(
                ax,
                G[k],
                f"$G_{{{k + 1}}}$",
                marker="D",
                color=PALETTE["green"],
                size=4.2,
                offset=(8, -3),
                ha="left",
                va="top",
                zorder=8.5,
            )
        an.draw_point(
            ax,
            Cf,
            r"$C_\mathrm{f}$",
            marker="P",
            color=PALETTE["vermillion"],
            size=6.5,
            offset=(-6, -4),
            ha="right",
            va="top",
            zorder=8.5,
        )
        e = snap(float(snap(data.radius)) * np.array([np.cos(-np.pi / 9), np.sin(-np.pi / 9)]))
        ax.plot(*np.stack([Cf, Cf + e]).T, color=PALETTE["orange"], lw=0.9, zorder=7.5)  # a radius of the dead zone
        an.label(ax, Cf + 0.55 * e, "$d$", offset=(0, 4), ha="center", va="bottom")
        pr = rd.platform_radius(bot)
        ax.set_xlim(-pr - 0.45, pr + 3.35)
        ax.set_ylim(-pr - 0.75, pr + 0.3)
        # inset: the pivot of wheel 1, enlarged
        axi = ax.inset_axes([0.615, 0.30, 0.37, 0.68])
        plain_axes(axi)
        Pp = data.pivots[:, 0]
        for kk, ghost in ((0, False), (k1, True)):
            rd.draw_unit(axi, bot.wheels[0], data.beta[kk, 0], data.pose[kk], ghost=ghost, light=True, arrows="j")
        an.draw_path(axi, Pp, color=ROLE["path"][1], lw=1.1)
        an.draw_point(
            axi,
            G[0],
            "$G$",
            marker="D",
            color=PALETTE["green"],
            size=5,
            offset=(8, -2),
            ha="left",
            va="center",
            zorder=9,
        )
        an.label(axi, Pp[0], "$P$", offset=(-8, 5), ha="right", va="bottom")
        an.label(axi, Pp[k1], "$P'$", offset=(-6, -6), ha="right", va="top")
        for kk in (0, k1):
            axi.plot(*np.stack([G[0], Pp[kk]]).T, color=PALETTE["vermillion"], lw=1.4, zorder=8)
        an.label(axi, 0.5 * (G[0] + Pp[0]), "$d$", offset=(-7, 0), ha="right", va="center", color=PALETTE["vermillion"])
        h = 1.25 * max(data.r, data.d)
        axi.set_xlim(G[0, 0] - h, G[0, 0] + h)
        axi.set_ylim(G[0, 1] - h, G[0, 1] + h)
        for sp_ in axi.spines.values():
            sp_.set_visible(True)
            sp_.set_color("#999999")
            sp_.set_linewidth(0.6)
        axi.set_title("pivot of wheel 1, enlarged", fontsize=FONT_SMALL, pad=2)
        zoom = ax.indicate_inset_zoom(axi, edgecolor="#999999", linewidth=0.6, alpha=1.0)
        for line in zoom.connectors:  # they would cross the drawing; the box and title say it
            line.set_visible(False)
        an.scale_bar(ax, L_PAPER, "$L$", loc=(0.03, 0.04))
    return fig


def caption(data):
    """Our caption of Fig. 7 (Markdown with ``$...$``).

    Parameters
    ----------
    data : Fig07Data
        The numbers (:func:`data`).

    Returns
    -------
    str
        Markdown with ``$...$`` math.
    """
    return (
        rf"Dead zone of the WMR with three offset wheels ($d = r = {data.d:g}L$), simulated (RK4, "
        rf"$\Delta t = T/{data.steps}$): the wheels, all at $\beta_i = {degrees(data.beta0 * DEG)}^\circ$, are "
        r"steered one full turn ($\dot\phi_i = 2\pi/T$) without driving ($\dot\theta_i = 0$). "
        r"$C$ traces a circle about $C_\mathrm{f}$, the centroid of the contact points $G_i$, of fitted radius "
        rf"$R$, the offset $d = {data.d:g}$ to within $|R - d| = {number(data.radius_error, 2)}$ "
        rf"(integration error bound ${number(data.tolerance, 2)}$). The $G_i$ do not move (at most "
        rf"${number(data.contact_drift, 2)}$) and the platform does not turn "
        rf"(${residual_text(MAX_PSI, data.psi_max)}$). Solid: start; dashed: after {data.later:g} of the "
        r"turn ($C'$, $P'$). Blue: paths of the pivots $P_i$, circles of radius $d$ about the $G_i$. Inset: the "
        r"pivot $P$ of wheel 1 circles its fixed contact point $G$ at distance $d$. The dead zone needs all "
        r"$\beta_i$ equal: with the drives locked the wheels can be steered only while their arm lines (through "
        r"$P_i$ along $\mathbf j_i$) are parallel, or concurrent for an instant; the $6\times6$ locked-drive "
        rf"matrix $\mathbf M(\boldsymbol\beta)$ has rank {data.rank_M_equal} here, but rank "
        rf"{data.rank_M_generic} at $\boldsymbol\beta = ({', '.join(f'{b:g}' for b in data.generic_deg)})^\circ$, "
        r"where the wheels cannot be steered at all without driving."
    )
