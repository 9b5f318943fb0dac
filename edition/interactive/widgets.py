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

__all__ = ["SteeringExplorer", "MountExplorer"]


class _Explorer:
    """What both explorers share: the state drawn and described, shown below the controls and redrawn in place."""

    _draw: Callable[[Any], Any]       # state -> Figure (set by each explorer)
    state: Callable[[], Any]          # the current state (set by each explorer)
    controls: Any                     # the ipywidgets box shown above the picture
    _describe: Callable[[Any], str]   # state -> Markdown text (set by each explorer)
    _width = 500                      # width of the picture (pixels)

    def _render(self):
        from IPython.display import Image, Markdown
        s = self.state()
        return Image(png(self._draw(s)), width=self._width), Markdown(self._describe(s))

    def _sync(self):
        """Set the controls that follow the others (none here)."""

    def _changed(self, change=None):
        self._sync()
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

    def __init__(self, robot=None, beta_deg=(30.0, -50.0, 75.0), twist=(0.5, 0.2, 0.1), mode="steering angles"):
        import ipywidgets as W
        self.robot = robot or paper_robot("centred", L=1.0, r=0.2)
        lay = W.Layout(width="340px")
        self.mode = W.ToggleButtons(options=["steering angles", "commanded twist"], value=mode)
        self.betas = [W.FloatSlider(value=b, min=-180, max=180, step=1, description=f"β{k} (deg)", layout=lay,
                                    continuous_update=False) for k, b in enumerate(beta_deg, 1)]
        names = ("ψ̇ (rad/s)", "ẋ (m/s)", "ẏ (m/s)")
        self.twist = [W.FloatSlider(value=v, min=-1, max=1, step=0.05, description=n, layout=lay,
                                    continuous_update=False) for n, v in zip(names, twist, strict=True)]
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

    _draw, _describe, _width = staticmethod(draw_steering), staticmethod(describe_steering), 520

    def _sync(self):
        if self.mode.value == "commanded twist":           # show the angles the twist needs
            s = self.state()
            for b, v in zip(self.betas, np.degrees(s.beta), strict=True):
                b.unobserve(self._changed, names="value")
                b.value = float(np.round(v))
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

    _draw, _describe, _width = staticmethod(draw_mounts), staticmethod(describe_mounts), 420

    def _sync(self):
        if self.auto.value:
            self.L.unobserve(self._changed, names="value")
            self.L.value = round(self.state().L_rms, 2)
            self.L.observe(self._changed, names="value")
