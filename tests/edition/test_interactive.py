"""Chapter 07's explorers (edition.interactive): only the controls of the current mode act, every slider has a typed
box that reaches values between its steps, and the pictures' text stays readable when the notebook is narrow."""

from __future__ import annotations

import numpy as np
import pytest

from edition import interactive as I
from edition.interactive import draw
from edition.interactive.widgets import typed_slider


def _disabled(sliders):
    return [s.disabled for s in sliders]


def test_only_the_controls_of_the_current_mode_are_enabled_and_the_angles_carry_over_exactly():
    ex = I.SteeringExplorer(mode="commanded twist", twist=(0.5, 0.2, 0.1))
    assert _disabled(ex.betas) == [True] * 3 and _disabled(ex.twist) == [False] * 3
    moving = ex.state()
    assert moving.mobility == 1
    ex.mode.value = "steering angles"
    assert _disabled(ex.betas) == [False] * 3 and _disabled(ex.twist) == [True] * 3
    assert ex.state().mobility == 1  # the twist's angles, not rounded ones (which jam)
    ex.betas[0].value += 3.0
    assert ex.state().mobility == 0


def test_a_typed_value_is_kept_between_the_steps():
    slider, box, row = typed_slider("x", 1.0, 0.2, 2.0, 0.05)
    box.value = float(np.sqrt(2))
    assert slider.value == float(np.sqrt(2)) and box in row.children and slider in row.children
    slider.value = 0.5
    assert box.value == 0.5


def test_the_mount_explorer_reaches_an_isotropic_isosceles_triangle_by_typing():
    ex = I.MountExplorer(radii=(1.2, 0.9, 1.0), angles_deg=(180, 50, -70))
    assert ex.L.disabled  # L follows the points while "L = RMS distance" is ticked
    for s, v in zip(ex.radii + ex.angles, (2.0, np.sqrt(2), np.sqrt(2), 180.0, 45.0, -45.0), strict=True):
        s.value = float(v)
    assert abs(ex.state().kappa - 1.0) < 1e-9
    ex.auto.value = False
    assert not ex.L.disabled
    ex.L.value = 1.0
    assert ex.state().kappa > 1.1


@pytest.mark.parametrize("which", ["steering", "mounts"])
def test_the_pictures_text_is_at_least_14_px_at_the_display_width(which):
    if which == "steering":
        fig, shown = draw.draw_steering(I.steering_state(beta=np.radians([-135, 105, -15]))), I.SteeringExplorer._width
    else:
        fig, shown = draw.draw_mounts(I.mount_state([(-2, 0), (1, 1), (1, -1)])), I.MountExplorer._width
    sizes = [
        t.get_fontsize()
        for t in fig.findobj(lambda a: hasattr(a, "get_fontsize") and hasattr(a, "get_text"))
        if t.get_text().strip()
    ]
    png_px = fig.get_figwidth() * draw.DPI
    assert sizes and shown <= png_px * 1.01  # shown at most at its natural size
    # at a notebook column of 480 px (820 px window with the file browser open) the picture is shrunk to fit
    assert min(sizes) * draw.DPI / 72 * min(1.0, 480 / png_px) >= 14.0 - 1e-9, min(sizes)
