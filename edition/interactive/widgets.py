r"""The explorers: ipywidgets around a state, its figure and its numbers.

Part of the interactive chapter: :mod:`edition.interactive`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from wmr.model.robots import paper_robot

from .describe import describe_mounts, describe_steering
from .draw import draw_mounts, draw_steering, png
from .state import mount_state, steering_state

__all__ = ["SteeringExplorer", "MountExplorer", "typed_slider"]

#: one control row (label, slider, typed box): it shrinks with the notebook and the groups wrap below 820 px
_ROW = {"width": "100%", "max_width": "410px"}
_GROUPS = {"flex_flow": "row wrap", "justify_content": "flex-start", "grid_gap": "0 24px"}


def typed_slider(description, value, lo, hi, step, width="82px"):
    r"""A slider and, beside it, a box to type the value (any value in range, not only multiples of ``step``).

    The two share one value (``ipywidgets.link``): dragging moves in steps of ``step``, typing gives any
    number between ``lo`` and ``hi`` (e.g. :math:`\sqrt2 \approx 1.414214`, which steps of 0.05 miss).

    Parameters
    ----------
    description : str
        The label (left of the slider).
    value, lo, hi, step : float
    width : str, optional
        Width of the typed box (CSS).

    Returns
    -------
    slider : ipywidgets.FloatSlider
        Observe this one; its ``value`` is the control's value.
    box : ipywidgets.BoundedFloatText
    row : ipywidgets.HBox
        Slider and box, for the layout.
    """
    import ipywidgets as W

    slider = W.FloatSlider(
        value=value,
        min=lo,
        max=hi,
        step=step,
        description=description,
        readout=False,
        continuous_update=False,
        style={"description_width": "76px"},
        layout=W.Layout(flex="1 1 auto", min_width="160px", width="auto"),
    )
    box = W.BoundedFloatText(value=value, min=lo, max=hi, step=None, layout=W.Layout(width=width, flex="0 0 auto"))
    W.link((slider, "value"), (box, "value"))
    return slider, box, W.HBox([slider, box], layout=W.Layout(**_ROW))


def _enable(pairs, on):
    """Enable (``on``) or disable the sliders and typed boxes ``pairs``."""
    for slider, box in pairs:
        slider.disabled = box.disabled = not on


class _Picture:
    """A PNG with alt text, displayed (and updated in place) as :func:`wmr.plot.design.picture_bundle`."""

    def __init__(self, data, alt, width):
        self.data, self.alt, self.width = data, alt, width

    def _repr_mimebundle_(self, include=None, exclude=None):
        from wmr.plot.design import picture_bundle

        return picture_bundle(self.data, self.alt, self.width), {"image/png": {"width": self.width}}


class _Explorer:
    """What both explorers share: the state drawn and described, shown below the controls and redrawn in place."""

    _draw: Callable[[Any], Any]  # state -> Figure (set by each explorer)
    state: Callable[[], Any]  # the current state (set by each explorer)
    controls: Any  # the ipywidgets box shown above the picture
    _describe: Callable[[Any], str]  # state -> Markdown text (set by each explorer)
    _width = 500  # width of the picture (pixels)
    _alt = "The robot seen from above."  # what the picture shows, for a reader who cannot see it (each explorer)

    def _render(self):
        from IPython.display import Markdown

        s = self.state()
        return _Picture(png(self._draw(s)), self._alt, self._width), Markdown(self._describe(s))

    def _sync(self):
        """Set the controls that follow the others (none here)."""

    def _changed(self, change=None):
        self._sync()
        if self._image is not None:
            img, md = self._render()
            self._image.update(img)
            self._text.update(md)

    def show(self, caption=None):
        """Display the controls, then the picture, its caption and the numbers (updated in place by the controls).

        Parameters
        ----------
        caption : str, optional
            Markdown shown right below the picture (a figure number and what the picture shows); it stays as the
            picture is redrawn, so it describes what every drawing shows, not one state.

        Returns
        -------
        None
        """
        from IPython.display import Markdown, display

        display(self.controls)
        img, md = self._render()
        self._image = display(img, display_id=True)
        if caption:
            display(Markdown(caption))
        self._text = display(md, display_id=True)


class SteeringExplorer(_Explorer):
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

    _alt = (
        "The robot seen from above at the chosen steering angles: its three wheels, their axle lines and "
        "wheel-plane lines, and the instantaneous centre where the axles meet, when they do."
    )

    def __init__(self, robot=None, beta_deg=(30.0, -50.0, 75.0), twist=(0.5, 0.2, 0.1), mode="steering angles"):
        import ipywidgets as W

        self.robot = robot or paper_robot("centred", L=1.0, r=0.2)
        self.mode = W.ToggleButtons(
            options=["steering angles", "commanded twist"], value=mode, style={"button_width": "150px"}
        )
        angles = [typed_slider(rf"$\beta_{k}$ (deg)", b, -180, 180, 1) for k, b in enumerate(beta_deg, 1)]
        names = (r"$\dot\psi$ (rad/s)", r"$\dot x$ (m/s)", r"$\dot y$ (m/s)")  # typeset by MathJax
        rates = [typed_slider(n, v, -1, 1, 0.05) for n, v in zip(names, twist, strict=True)]
        self.betas, self.twist = [a[0] for a in angles], [r[0] for r in rates]
        self._pairs = {"angles": [a[:2] for a in angles], "twist": [r[:2] for r in rates]}
        for w in self.betas + self.twist + [self.mode]:
            w.observe(self._changed, names="value")
        groups = [
            W.VBox([a[2] for a in angles], layout=W.Layout(width="410px", max_width="100%")),
            W.VBox([r[2] for r in rates], layout=W.Layout(width="410px", max_width="100%")),
        ]
        self.controls = W.VBox([self.mode, W.Box(groups, layout=W.Layout(**_GROUPS))])
        self._image = self._text = None
        self._changed()  # the angle sliders show the angles of the twist mode

    def state(self):
        """The :class:`SteeringState` the controls describe.

        Returns
        -------
        SteeringState
        """
        if self.mode.value == "commanded twist":
            return steering_state(self.robot, np.radians([b.value for b in self.betas]), [t.value for t in self.twist])
        return steering_state(self.robot, np.radians([b.value for b in self.betas]))

    _draw, _describe, _width = staticmethod(draw_steering), staticmethod(describe_steering), 504

    def _sync(self):
        twist = self.mode.value == "commanded twist"
        _enable(self._pairs["angles"], not twist)  # in each mode only its own controls act
        _enable(self._pairs["twist"], twist)
        if twist:  # show the angles the twist needs
            s = self.state()
            for b, v in zip(self.betas, np.degrees(s.beta), strict=True):
                b.unobserve(self._changed, names="value")
                b.value = float(v)  # exact: a rounded angle would jam the robot
                b.observe(self._changed, names="value")


class MountExplorer(_Explorer):
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

    _alt = (
        "The platform seen from above: the centre C, the three mount points placed by the sliders, and the "
        "circle of radius L about C."
    )

    def __init__(self, radii=(1.0, 1.0, 1.0), angles_deg=(180.0, 60.0, -60.0), L=None):
        import ipywidgets as W

        radius = [typed_slider(rf"$|CP_{k}|$", r, 0.2, 2.0, 0.05) for k, r in enumerate(radii, 1)]
        angle = [typed_slider(rf"$\angle P_{k}$ (deg)", a, -180, 180, 1) for k, a in enumerate(angles_deg, 1)]
        self.radii, self.angles = [r[0] for r in radius], [a[0] for a in angle]
        self.auto = W.Checkbox(
            value=L is None, description="$L$ = RMS distance", indent=False, layout=W.Layout(width="auto")
        )
        length = typed_slider("$L$", 1.0 if L is None else L, 0.2, 2.0, 0.01)
        self.L, self._L_pair = length[0], length[:2]
        for w in self.radii + self.angles + [self.auto, self.L]:
            w.observe(self._changed, names="value")
        col = W.Layout(width="410px", max_width="100%")
        self.controls = W.VBox(
            [
                W.Box(
                    [W.VBox([r[2] for r in radius], layout=col), W.VBox([a[2] for a in angle], layout=col)],
                    layout=W.Layout(**_GROUPS),
                ),
                W.Box([W.VBox([length[2]], layout=col), self.auto], layout=W.Layout(**_GROUPS)),
            ]
        )
        self._image = self._text = None
        self._sync()

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

    _draw, _describe, _width = staticmethod(draw_mounts), staticmethod(describe_mounts), 480

    def _sync(self):
        _enable([self._L_pair], not self.auto.value)  # L follows the points while the box is ticked
        if self.auto.value:
            self.L.unobserve(self._changed, names="value")
            self.L.value = round(self.state().L_rms, 4)
            self.L.observe(self._changed, names="value")
