r"""The interactive chapter (``notebooks/07_interactive_robot``): a robot to steer, and mount points to place.

Computing, drawing and the widgets are apart, as in :mod:`wmr.paper.figures`:

* :func:`steering_state` -- the numbers of one configuration of a three-centred-wheel robot: the
  steering angles (given, or set by :func:`wmr.steering_angles` for a commanded twist), where the
  axle lines and the wheel-plane lines meet, :math:`\det\mathbf J`, :math:`\operatorname{rank}\mathbf F`,
  :math:`\kappa(\mathbf J)` and the admissible twist.  :func:`mount_state` does the same for a
  placement of three mount points and :math:`\kappa(\mathbf J_{L1})`.  No matplotlib, no widgets.
* :func:`draw_steering`, :func:`draw_mounts` -- one :class:`matplotlib.figure.Figure` of a state;
  :func:`describe_steering`, :func:`describe_mounts` -- its numbers as Markdown.
* :class:`SteeringExplorer`, :class:`MountExplorer` -- ipywidgets around them.  ``show()`` displays
  the controls and then the picture and the numbers as ordinary image and Markdown outputs, which
  the controls update in place (``display_id``).  Run headless (nbconvert, the report), the saved
  outputs are one representative state that needs no widget JavaScript.
"""
from __future__ import annotations

import io
from dataclasses import dataclass

import numpy as np

from ..analysis.isotropy import characteristic_length
from ..analysis.lines import AT_INFINITY, FINITE, axles_concurrency, concurrency_point
from ..analysis.linalg import condition_number
from ..analysis.mobility import admissible_twists, rank_F
from ..analysis.steering import steering_angles
from ..model import validation as V
from ..model.robot import Robot
from ..model.robots import paper_robot
from ..model.wheels import CentredWheel, OffsetWheel
from .text import number

__all__ = ["SteeringState", "MountState", "steering_state", "mount_state", "draw_steering", "draw_mounts",
           "describe_steering", "describe_mounts", "SteeringExplorer", "MountExplorer", "png"]


# ----------------------------------------------------------------------------------------------- data
@dataclass(frozen=True)
class SteeringState:
    r"""One configuration of a three-centred-wheel robot and what it means.

    Attributes
    ----------
    robot : wmr.Robot
    beta : numpy.ndarray (3,)
        Steering angles (radians).
    twist : numpy.ndarray (3,) or None
        The commanded twist, if the angles were set for one.
    det_J : float
        :math:`\det\mathbf J` with :math:`L` the characteristic length (:func:`wmr.characteristic_length`).
    rank_F : int
    kappa_J : float
        :math:`\kappa(\mathbf J)` (``inf`` when singular).
    axles : wmr.analysis.lines.Concurrency
        Where the axle lines meet: the instantaneous centre when the robot can move.
    planes : wmr.analysis.lines.Concurrency
        Where the wheel-plane lines meet (:math:`D_P`).
    motion : numpy.ndarray (3,) or None
        A unit basis vector of the admissible twists (rank F = 5), else None.
    """

    robot: Robot
    beta: np.ndarray
    twist: object
    det_J: float
    rank_F: int
    kappa_J: float
    axles: object
    planes: object
    motion: object

    @property
    def mobility(self):
        """Dimension of the admissible twists (0 or 1 for three centred wheels)."""
        return 3 + self.robot.n_rates - self.rank_F


def steering_state(robot=None, beta=None, twist=None):
    r"""The numbers of one configuration: steering angles ``beta``, or those that make ``twist`` executable.

    Parameters
    ----------
    robot : wmr.Robot, optional
        Three centred wheels (default: the paper's robot, L = 1 m, r = 0.2 m).
    beta : array (3,), optional
        Steering angles (radians); ignored when ``twist`` is given.
    twist : array (3,), optional
        :math:`(\dot\psi, \dot x, \dot y)`; the angles come from :func:`wmr.steering_angles`.

    Returns
    -------
    SteeringState

    Examples
    --------
    >>> s = steering_state(twist=[1.0, 0.0, 0.0])          # spin about C
    >>> s.rank_F, round(s.kappa_J, 6), s.axles.kind.name
    (5, 1.414214, 'FINITE')
    """
    robot = robot or paper_robot("centred", L=1.0, r=0.2)
    if robot.n_rates != 3 or any(u.kind != "centred" for u in robot.wheels):
        raise ValueError(f"robot must have three centred wheels, got {robot!r}")
    if twist is not None:
        twist = V.finite_array("twist", twist, last=3)
        beta = steering_angles(robot, twist, current=None if beta is None else beta)
    beta = V.finite_array("beta", np.zeros(3) if beta is None else beta, last=3)
    L = characteristic_length(robot)
    J = robot.J(beta, L=L)
    rk = int(rank_F(robot, beta))
    basis = admissible_twists(robot, beta)
    motion = None
    if basis.shape[1] == 1:
        m = basis[:, 0]
        motion = m / np.linalg.norm(m) * (1.0 if (m[0] if abs(m[0]) > 1e-12 else m[np.argmax(np.abs(m))]) > 0 else -1.0)
    return SteeringState(robot, beta, twist, float(np.linalg.det(J)), rk, float(condition_number(J)),
                         axles_concurrency(robot, beta), concurrency_point(robot, beta), motion)


@dataclass(frozen=True)
class MountState:
    r"""A placement of three mount points and the isotropy of :math:`\mathbf J_{L1}`.

    Attributes
    ----------
    points : numpy.ndarray (3, 2)
    L : float
        The characteristic length used.
    L_rms : float
        The root-mean-square distance of the mount points from C (the best L when the centroid is at C).
    centroid : numpy.ndarray (2,)
        :math:`\tfrac13\sum_i\mathbf d_i`.
    kappa : float
        :math:`\kappa(\mathbf J_{L1})`.
    kappa_best : float
        :math:`\kappa(\mathbf J_{L1})` at ``L_rms``.
    """

    points: np.ndarray
    L: float
    L_rms: float
    centroid: np.ndarray
    kappa: float
    kappa_best: float


def mount_state(points, L=None):
    r"""The isotropy of :math:`\mathbf J_{L1}` for three mount points and a characteristic length.

    Parameters
    ----------
    points : array (3, 2)
        Mount points :math:`\mathbf d_i` (body frame).
    L : float, optional
        Default: the RMS distance.

    Returns
    -------
    MountState

    Examples
    --------
    >>> s = mount_state([(2, 0), (-1, 1), (-1, -1)])       # isosceles, centroid at C
    >>> round(s.kappa, 9), round(s.L_rms ** 2, 9)
    (1.0, 2.666666667)
    """
    pts = V.finite_array("points", points, last=2)
    if pts.shape != (3, 2):
        raise ValueError(f"points must have shape (3, 2), got {pts.shape}")
    L_rms = float(np.sqrt(np.mean(np.sum(pts**2, axis=1))))
    if L_rms == 0:
        raise ValueError("points must not all be at C")
    L = L_rms if L is None else V.positive("L", L)
    bot = Robot([OffsetWheel(tuple(p), r=1.0, d=1.0) for p in pts])
    return MountState(pts, float(L), L_rms, pts.mean(axis=0), float(condition_number(bot.J1(L))),
                      float(condition_number(bot.J1(L_rms))))


# ----------------------------------------------------------------------------------------------- drawing
def _deg(x):
    return f"{np.degrees(x):.0f}^\\circ"


def draw_steering(state, fig=None):
    """The robot at ``state``: wheels, axle lines (blue), wheel-plane lines (vermillion), the centre U and :math:`D_P`.

    Parameters
    ----------
    state : SteeringState
    fig : matplotlib.figure.Figure, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    from ..plot.annotate import draw_line, draw_point, label
    from ..plot.robot import draw_robot, platform_radius, robot_geometry
    from matplotlib.lines import Line2D
    from ..plot.style import DASHES, ROLE, fit_view, new_figure, style
    with style():
        fig, (ax,) = new_figure(1, 1, width=5.6, height=5.0, fig=fig)
        g = robot_geometry(state.robot, state.beta)
        R = platform_radius(state.robot)
        view = 2.6 * R
        include = [() for _ in range(3)]
        U = state.axles.point if state.axles.kind == FINITE and np.linalg.norm(state.axles.point) < view else None
        D = state.planes.point if state.planes.kind == FINITE and np.linalg.norm(state.planes.point) < view else None
        for k in range(3):
            pts = [p for p in (U,) if p is not None]
            draw_line(ax, g.P[k], g.i[k], pts, kind="axle", margin=0.35 * R, min_half=1.2 * R)
            pts = [p for p in (D,) if p is not None]
            draw_line(ax, g.P[k], g.j[k], pts, kind="plane", margin=0.35 * R, min_half=1.2 * R)
        draw_robot(ax, state.robot, state.beta)
        if U is not None and state.mobility > 0:
            draw_point(ax, U, None, color=ROLE["ic"], size=6, zorder=9)
            label(ax, U, "$U$", offset=(6, 6), color=ROLE["ic"])
        if D is not None:
            draw_point(ax, D, None, marker="s", color=ROLE["dp"], size=5, zorder=9)
            label(ax, D, "$D_P$", offset=(6, -10), color=ROLE["dp"])
        if state.motion is not None and state.axles.kind == AT_INFINITY:
            v = state.motion[1:] / max(np.linalg.norm(state.motion[1:]), 1e-12)
            ax.annotate("", xy=tuple(0.9 * R * v), xytext=(0, 0),
                        arrowprops=dict(arrowstyle="-|>", color=ROLE["ic"], lw=1.6), zorder=9)
        fit_view(ax, np.array([[-view, -view], [view, view]]) * 0.62, pad=0.02)
        handles = [Line2D([], [], color=DASHES["axle"][0], ls=DASHES["axle"][1], lw=1.2, label="axle lines"),
                   Line2D([], [], color=DASHES["plane"][0], ls=DASHES["plane"][1], lw=1.2, label="wheel-plane lines"),
                   Line2D([], [], color=ROLE["ic"], marker="o", ls="none", label="$U$: centre of rotation"),
                   Line2D([], [], color=ROLE["dp"], marker="s", ls="none", label="$D_P$: planes meet")]
        ax.legend(handles=handles, loc="lower left", fontsize=7.5, frameon=True, framealpha=0.9)
        verdict = ("can move" if state.mobility > 0 else "cannot move")
        ax.set_title(rf"$\beta = ({', '.join(_deg(b) for b in state.beta)})$: the robot {verdict}", fontsize=9)
    return fig


def draw_mounts(state, fig=None):
    r"""Three mount points, their centroid, the circle of radius L about C and the triangle.

    Parameters
    ----------
    state : MountState
    fig : matplotlib.figure.Figure, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, Polygon
    from ..plot.annotate import draw_point, label
    from ..plot.style import PALETTE, fit_view, new_figure, style
    with style():
        fig, (ax,) = new_figure(1, 1, width=4.6, height=4.4, fig=fig)
        p = state.points
        ax.add_patch(Polygon(p, closed=True, facecolor=PALETTE["light"], edgecolor=PALETTE["grey"], lw=0.9))
        ax.add_patch(Circle((0, 0), state.L, facecolor="none", edgecolor=PALETTE["blue"], lw=0.9, ls=(0, (5, 3))))
        ax.add_patch(Circle((0, 0), state.L_rms, facecolor="none", edgecolor=PALETTE["green"], lw=0.8, ls=(0, (1, 2))))
        draw_point(ax, (0, 0), None, size=5)
        label(ax, (0, 0), "$C$", offset=(-6, 6), ha="right", va="bottom")
        draw_point(ax, state.centroid, None, marker="x", color=PALETTE["vermillion"], size=7, zorder=8)
        label(ax, state.centroid, r"$\bar P$", offset=(6, -6), ha="left", va="top", color=PALETTE["vermillion"])
        handles = [Line2D([], [], color=PALETTE["blue"], ls=(0, (5, 3)), label=f"radius $L = {state.L:.3g}$"),
                   Line2D([], [], color=PALETTE["green"], ls=(0, (1, 2)), label=f"RMS distance ${state.L_rms:.3g}$"),
                   Line2D([], [], color=PALETTE["vermillion"], marker="x", ls="none", label=r"centroid $\bar P$")]
        ax.legend(handles=handles, loc="lower left", fontsize=7.5, frameon=True, framealpha=0.9)
        for k, q in enumerate(p, 1):
            draw_point(ax, q, None, size=5, color=PALETTE["dark"])
            label(ax, q, f"$P_{k}$", offset=(6, 6))
        m = max(float(np.abs(p).max()), state.L, state.L_rms) * 1.25
        fit_view(ax, np.array([[-m, -m], [m, m]]), pad=0.02)
        ax.set_title(rf"$\kappa(\mathbf{{J}}_{{L1}}) = {number(state.kappa, 4)}$ at $L = {state.L:.3g}$", fontsize=9)
    return fig


def png(fig, dpi=100):
    """The figure as PNG bytes (Agg), without registering it anywhere.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    dpi : int

    Returns
    -------
    bytes
    """
    from ..plot.style import style
    buf = io.BytesIO()
    with style():
        fig.savefig(buf, format="png", dpi=dpi)
    return buf.getvalue()


def describe_steering(state):
    r"""The numbers of a :class:`SteeringState` as Markdown.

    Parameters
    ----------
    state : SteeringState

    Returns
    -------
    str
    """
    kind = {FINITE: "meet at one point", AT_INFINITY: "are all parallel"}
    axles = kind.get(state.axles.kind, "do not meet in one point")
    planes = kind.get(state.planes.kind, "do not meet in one point")
    k = "\\infty" if not np.isfinite(state.kappa_J) else number(state.kappa_J, 4)
    lines = [f"| $\\det\\mathbf J$ | $\\operatorname{{rank}}\\mathbf F$ | mobility | $\\kappa(\\mathbf J)$ |",
             "|---|---|---|---|",
             f"| ${number(state.det_J, 3) if abs(state.det_J) > 1e-12 else '0'}$ | {state.rank_F} | {state.mobility} | ${k}$ |",
             "", f"The axle lines {axles}; the wheel-plane lines {planes}."]
    if state.mobility:
        m = state.motion
        u = np.round(state.axles.point, 2) + 0.0 if state.axles.kind == FINITE else None
        what = "a translation" if abs(m[0]) < 1e-9 or u is None else f"a rotation about $U = ({u[0]:.2f}, {u[1]:.2f})$"
        lines.append(f"The robot can move: {what}, the only admissible motion.")
    else:
        lines.append("The robot cannot move: the steering angles jam it (the axles must meet in one point).")
    if abs(state.det_J) < 1e-9:
        lines.append(r"$\mathbf J$ is singular: the wheel-plane lines are concurrent or parallel.")
    return "\n".join(lines)


def describe_mounts(state):
    r"""The numbers of a :class:`MountState` as Markdown.

    Parameters
    ----------
    state : MountState

    Returns
    -------
    str
    """
    c = state.centroid
    iso = abs(state.kappa - 1) < 1e-9
    text = (rf"$\kappa(\mathbf J_{{L1}}) = {number(state.kappa, 4)}$ at $L = {state.L:.3g}$; centroid of the "
            rf"$P_i$ at $({c[0]:.3f}, {c[1]:.3f})$; RMS distance ${state.L_rms:.3f}$, where "
            rf"$\kappa = {number(state.kappa_best, 4)}$.")
    if iso:
        text += r" **Isotropic.**"
    elif np.abs(c).max() > 1e-9:
        text += r" The centroid must be at C (37)."
    else:
        text += r" The centroid is at C: choose $L$ = the RMS distance (36)."
    return text


# ----------------------------------------------------------------------------------------------- widgets
class SteeringExplorer:
    r"""Sliders for the three steering angles, or for a commanded twist; the robot and its numbers redrawn live.

    Parameters
    ----------
    robot : wmr.Robot, optional
        Three centred wheels (default: the paper's robot).
    beta_deg : sequence of 3 floats
        Initial steering angles (degrees).
    twist : sequence of 3 floats
        Initial commanded twist (for the twist mode).
    mode : {"steering angles", "commanded twist"}
        Initial mode.
    """

    def __init__(self, robot=None, beta_deg=(30.0, -50.0, 75.0), twist=(0.5, 0.2, 0.1), mode="steering angles"):
        import ipywidgets as W
        self.robot = robot or paper_robot("centred", L=1.0, r=0.2)
        lay = W.Layout(width="340px")
        self.mode = W.ToggleButtons(options=["steering angles", "commanded twist"], value=mode)
        self.betas = [W.FloatSlider(value=b, min=-180, max=180, step=1, description=f"β{k} (deg)", layout=lay,
                                    continuous_update=False) for k, b in enumerate(beta_deg, 1)]
        names = ("ψ̇ (rad/s)", "ẋ (m/s)", "ẏ (m/s)")
        self.twist = [W.FloatSlider(value=v, min=-1, max=1, step=0.05, description=n, layout=lay,
                                    continuous_update=False) for n, v in zip(names, twist)]
        for w in self.betas + self.twist + [self.mode]:
            w.observe(self._changed, names="value")
        self.controls = W.VBox([self.mode, W.HBox([W.VBox(self.betas), W.VBox(self.twist)])])
        self._image = self._text = None
        self._changed()                                     # the angle sliders show the angles of the twist mode

    def state(self):
        """The :class:`SteeringState` the controls describe.

        Returns
        -------
        SteeringState
        """
        if self.mode.value == "commanded twist":
            return steering_state(self.robot, np.radians([b.value for b in self.betas]), [t.value for t in self.twist])
        return steering_state(self.robot, np.radians([b.value for b in self.betas]))

    def _render(self):
        from IPython.display import Image, Markdown
        s = self.state()
        return Image(png(draw_steering(s)), width=520), Markdown(describe_steering(s))

    def _changed(self, change=None):
        if self.mode.value == "commanded twist":           # show the angles the twist needs
            s = self.state()
            for b, v in zip(self.betas, np.degrees(s.beta)):
                b.unobserve(self._changed, names="value")
                b.value = float(np.round(v))
                b.observe(self._changed, names="value")
        if self._image is not None:
            img, md = self._render()
            self._image.update(img)
            self._text.update(md)

    def show(self):
        """Display the controls, then the picture and the numbers (updated in place by the controls).

        Returns
        -------
        None
        """
        from IPython.display import display
        display(self.controls)
        img, md = self._render()
        self._image = display(img, display_id=True)
        self._text = display(md, display_id=True)


class MountExplorer:
    r"""Sliders for the polar coordinates of three mount points and for L; :math:`\kappa(\mathbf J_{L1})` live.

    Parameters
    ----------
    radii : sequence of 3 floats
        Initial distances of the mount points from C.
    angles_deg : sequence of 3 floats
        Initial polar angles (degrees).
    L : float or None
        Initial characteristic length (None: the RMS distance, kept in step with the points).
    """

    def __init__(self, radii=(1.0, 1.0, 1.0), angles_deg=(180.0, 60.0, -60.0), L=None):
        import ipywidgets as W
        lay = W.Layout(width="320px")
        self.radii = [W.FloatSlider(value=r, min=0.2, max=2.0, step=0.05, description=f"|CP{k}|", layout=lay,
                                    continuous_update=False) for k, r in enumerate(radii, 1)]
        self.angles = [W.FloatSlider(value=a, min=-180, max=180, step=1, description=f"∠P{k} (deg)", layout=lay,
                                     continuous_update=False) for k, a in enumerate(angles_deg, 1)]
        self.auto = W.Checkbox(value=L is None, description="L = RMS distance")
        self.L = W.FloatSlider(value=1.0 if L is None else L, min=0.2, max=2.0, step=0.01, description="L",
                               layout=lay, continuous_update=False)
        for w in self.radii + self.angles + [self.auto, self.L]:
            w.observe(self._changed, names="value")
        self.controls = W.VBox([W.HBox([W.VBox(self.radii), W.VBox(self.angles)]), W.HBox([self.auto, self.L])])
        self._image = self._text = None

    def points(self):
        """The mount points the sliders describe, array (3, 2).

        Returns
        -------
        numpy.ndarray
        """
        a = np.radians([s.value for s in self.angles])
        r = np.array([s.value for s in self.radii])
        return np.stack([r * np.cos(a), r * np.sin(a)], axis=-1)

    def state(self):
        """The :class:`MountState` the controls describe.

        Returns
        -------
        MountState
        """
        return mount_state(self.points(), None if self.auto.value else self.L.value)

    def _render(self):
        from IPython.display import Image, Markdown
        s = self.state()
        return Image(png(draw_mounts(s)), width=420), Markdown(describe_mounts(s))

    def _changed(self, change=None):
        if self.auto.value:
            self.L.unobserve(self._changed, names="value")
            self.L.value = round(self.state().L_rms, 2)
            self.L.observe(self._changed, names="value")
        if self._image is not None:
            img, md = self._render()
            self._image.update(img)
            self._text.update(md)

    def show(self):
        """Display the controls, then the picture and the numbers (updated in place by the controls).

        Returns
        -------
        None
        """
        from IPython.display import display
        display(self.controls)
        img, md = self._render()
        self._image = display(img, display_id=True)
        self._text = display(md, display_id=True)
