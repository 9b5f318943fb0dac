r"""Fig. 8: rectilinear and curvilinear translation of the centred-wheel robot (simulated).

(a) All wheels parallel at a constant :math:`\beta`; (b) all wheels steered together,
:math:`\beta(t) = 90^\circ + A\sin(2\pi t/T)`.  The platform does not turn and every point moves
along a congruent curve: the congruence error is
:math:`\max_{k,t}\|\mathbf p_k(t) - \mathbf c(t) - \mathbf d_k\|`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr.analysis.integration import integrate
from wmr.analysis.mobility import rank_F

from ..text import bound
from ..text import residual as residual_text
from .common import DEG, L_PAPER, MAX_PSI, centred_robot, drawing, residual, snap

__all__ = ["NUMBER", "TITLE", "PAPER_CAPTION", "TranslationRun", "Fig08Data", "data", "draw", "caption"]

NUMBER = "8"
TITLE = "Rectilinear and curvilinear translations"
PAPER_CAPTION = "Rectilinear and curvilinear translations."


@dataclass(frozen=True)
class TranslationRun:
    r"""One simulated translation.

    Attributes
    ----------
    psi_max : float
        Largest :math:`|\psi|` along the run.
    congruence_error : float
        :math:`\max_{k,t}\|\mathbf p_k(t) - \mathbf c(t) - \mathbf d_k\|` over the paths of the :math:`P_k`.
    slip_max : float
        Largest residual of (21).
    rank_F : tuple of int
        The ranks of :math:`\mathbf F` found along the run.
    distance : float
        :math:`\|\mathbf c(T) - \mathbf c(0)\|`.
    straightness : float or None
        Largest distance of the path of C from the chord (rectilinear run only).
    beta : numpy.ndarray (N, 3)
        Drawing only: steering angles along the run (radians).
    pose : numpy.ndarray (N, 3)
        Drawing only: :math:`(\psi, X, Y)` along the run.
    pivots : numpy.ndarray (N, 3, 2)
        Drawing only: the paths of the :math:`P_i`.
    """

    psi_max: float = residual()
    congruence_error: float = residual()
    slip_max: float = residual()
    rank_F: tuple = ()
    distance: float = 0.0
    straightness: float | None = residual(default=None)
    beta: np.ndarray = drawing(default=None)  # (N, 3)
    pose: np.ndarray = drawing(default=None)  # (N, 3)
    pivots: np.ndarray = drawing(default=None)  # (N, 3, 2)


@dataclass(frozen=True)
class Fig08Data:
    r"""The numbers of Fig. 8: the parameters (angles in degrees) and the two runs.

    Attributes
    ----------
    speed : float
        Speed of C (units of L per unit of time).
    t_end : float
        Duration of each run.
    dt : float
        Time step.
    beta_rect : float
        Steering angle of the rectilinear run (degrees).
    amplitude : float
        Amplitude of the steering angle of the curvilinear run (degrees).
    rectilinear : TranslationRun
    curvilinear : TranslationRun
    robot : wmr.Robot
        Drawing only: the robot simulated.
    """

    speed: float
    t_end: float
    dt: float
    beta_rect: float
    amplitude: float
    rectilinear: TranslationRun
    curvilinear: TranslationRun
    robot: object = drawing(default=None)


def _run(bot, beta0, steer, speed, t_end, dt, straight):
    rates = np.full(bot.w, speed / bot.wheels[0].r)
    tr = integrate(bot, rates, np.full(bot.w, beta0), t_end, dt, steer=steer)
    C = tr.pose[:, 1:]
    P = np.stack([tr.unit_points(k, "P") for k in range(bot.w)], axis=1)  # (N, w, 2)
    dev = float(np.max(np.linalg.norm(P - C[:, None, :] - bot.mount_points, axis=-1)))
    st = None
    if straight:
        xy = C - C[0]
        u = xy[-1] / np.linalg.norm(xy[-1])
        st = float(np.max(np.abs(xy[:, 0] * u[1] - xy[:, 1] * u[0])))
    return TranslationRun(
        psi_max=float(np.abs(tr.pose[:, 0]).max()),
        congruence_error=dev,
        slip_max=float(tr.slip.max()),
        rank_F=tuple(sorted(set(int(v) for v in rank_F(bot, tr.beta)))),
        distance=float(np.linalg.norm(C[-1] - C[0])),
        straightness=st,
        beta=snap(tr.beta),
        pose=snap(tr.pose),
        pivots=snap(P),
    )


def data(speed=1.0, t_end=6.0, dt=0.02, beta_rect=100.0, amplitude=45.0):
    r"""Simulate the two translations.

    Parameters
    ----------
    speed : float
        :math:`r\dot\theta_i` (units of L per second).
    t_end, dt : float
        Duration T and RK4 step.
    beta_rect : float
        Steering angle of the rectilinear run, degrees.
    amplitude : float
        A of the curvilinear run, degrees.

    Returns
    -------
    Fig08Data
    """
    bot = centred_robot()
    amp = amplitude * DEG

    def steer(t, state):
        return np.full(bot.w, amp * 2 * np.pi / t_end * np.cos(2 * np.pi * t / t_end))

    return Fig08Data(
        speed=speed,
        t_end=t_end,
        dt=dt,
        beta_rect=beta_rect,
        amplitude=amplitude,
        rectilinear=_run(bot, beta_rect * DEG, None, speed, t_end, dt, True),
        curvilinear=_run(bot, 90 * DEG, steer, speed, t_end, dt, False),
        robot=bot,
    )


def draw(data, fig=None):
    """Draw Fig. 8 from its data.

    Parameters
    ----------
    data : Fig08Data
        The numbers (:func:`data`).
    fig : matplotlib.figure.Figure, optional
        Draw into this figure (cleared) instead of a new one.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from wmr.plot import annotate as an
    from wmr.plot import robot as rd
    from wmr.plot.style import ROLE, common_view, new_figure, panel_title, style

    bot = data.robot
    cols = ROLE["path"][:4]
    R = rd.platform_radius(bot)
    runs = {"a": data.rectilinear, "b": data.curvilinear}
    with style():
        fig, axes = new_figure(2, 1, width=7.0, height=6.0, fig=fig)
        views = []
        for ax, (letter, run) in zip(axes, runs.items(), strict=True):
            n = len(run.pose)
            idx = [0, n // 3, 2 * n // 3, n - 1]
            ext = []
            for q, kk in enumerate(idx):
                g = rd.draw_robot(
                    ax,
                    bot,
                    run.beta[kk],
                    run.pose[kk],
                    ghost=0 < q < len(idx) - 1,
                    labels=q == 0,
                    frame=q in (0, len(idx) - 1),
                    label_offsets={2: (-16, 4)} if letter == "b" else None,
                    arrows="j",
                )
                ext.append(rd.robot_extent(g, R))
            for xy, col in zip([run.pose[:, 1:]] + [run.pivots[:, k] for k in range(bot.w)], cols, strict=False):
                an.draw_path(ax, xy, color=col, lw=1.5, zorder=7)
            views.append(np.vstack(ext))
            title = (
                rf"rectilinear: constant $\beta_i = {data.beta_rect:g}^\circ$"
                if letter == "a"
                else rf"curvilinear: $\beta_i(t) = 90^\circ + {data.amplitude:g}^\circ\sin(2\pi t/T)$"
            )
            panel_title(ax, letter, title)
        common_view(axes, [np.vstack([v, v.min(axis=0) - [0, 0.45]]) for v in views], pad=0.02)
        for ax in axes:
            an.scale_bar(ax, L_PAPER, "$L$", loc=(0.02, 0.04))
        fig.legend(
            handles=an.legend_handles(
                [("path of $C$", f"path:{cols[0]}")] + [(f"$P_{k + 1}$", f"path:{cols[k + 1]}") for k in range(bot.w)]
            ),
            loc="outside lower center",
            ncols=4,
        )
    return fig


def caption(data):
    """Our caption of Fig. 8 (Markdown with ``$...$``).

    Parameters
    ----------
    data : Fig08Data
        The numbers (:func:`data`).

    Returns
    -------
    str
        Markdown with ``$...$`` math.
    """
    a, b = data.rectilinear, data.curvilinear
    ranks = sorted(set(a.rank_F) | set(b.rank_F))
    return (
        r"Rectilinear (a) and curvilinear (b) translation of the WMR with three centred wheels, simulated: all "
        rf"wheels parallel and driven at $r\dot\theta_i = {data.speed:g}\,L/\mathrm{{s}}$ for $T = {data.t_end:g}$ "
        r"s; in (b) they are steered together. Paths of $C$ and the $P_i$; platform at the start and end (solid) "
        r"and two intermediate poses (dashed). The platform does not turn "
        rf"(${residual_text(MAX_PSI, max(a.psi_max, b.psi_max))}$), the paths are congruent (translates of one "
        rf"another: largest deviation ${bound(max(a.congruence_error, b.congruence_error), latex=True)}$), rank "
        rf"$\mathbf{{F}} = {', '.join(map(str, ranks))}$ (mobility 1) throughout, and no slip is needed (residual "
        rf"of (21): ${bound(max(a.slip_max, b.slip_max), latex=True)}$)."
    )
