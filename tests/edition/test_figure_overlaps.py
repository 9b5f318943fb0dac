"""No label or legend of the edition's figures covers the figure's data, and none covers another (issue 30).

The rule is generic, in display coordinates after the figure is drawn (Agg): inside each axes, the box of
every text and of the legend (shrunk by a point, so a box that only touches a line passes; the part inside
the axes, where the data is drawn) must not cross a line of two or more points, an arrow, the outline of a
patch (a platform's rim, a wheel) or a marked point of that axes; across the figure, no two such boxes
overlap.  It is run on every figure the edition draws from data it can compute here: the paper's Figures
7-13 with the det J map and the conventions (edition.figures), chapter 7's two pictures, chapter 8's three
figures and chapter 9's four.  The first test shows the rule failing on figures made to break it."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Circle, FancyArrowPatch
from matplotlib.path import Path
from matplotlib.transforms import Bbox


def _shrunk(bb: Bbox, by: float = 1.0) -> Bbox:
    return Bbox.from_extents(bb.x0 + by, bb.y0 + by, bb.x1 - by, bb.y1 - by)


def _data(ax) -> list[tuple[str, Path]]:
    """The axes' data in display coordinates: lines, arrows and marked points (each a small square)."""
    out = []
    for line in ax.get_lines():
        if not line.get_visible():
            continue
        xy = line.get_transform().transform(np.asarray(line.get_xydata(), dtype=float))
        xy = xy[np.all(np.isfinite(xy), axis=1)]
        drawn = line.get_linestyle() not in ("None", "none", "", " ")
        if drawn and len(xy) >= 2:
            out.append((f"line {line.get_label()!r}", Path(xy)))
        if line.get_marker() not in (None, "None", "none", "", " "):
            out += [(f"marker of {line.get_label()!r}", Path(p + [[-1, -1], [1, 1]])) for p in xy]
    for patch in ax.patches:
        edged = patch.get_linewidth() > 0 and patch.get_edgecolor()[3] > 0
        if patch.get_visible() and (isinstance(patch, FancyArrowPatch) or edged):
            what = "arrow" if isinstance(patch, FancyArrowPatch) else f"outline of a {type(patch).__name__}"
            out.append((what, patch.get_transform().transform_path(patch.get_path())))
    for c in ax.collections:
        offsets = np.asarray(c.get_offsets(), dtype=float)
        if c.get_visible() and offsets.ndim == 2 and 0 < len(offsets) <= 5000:
            pts = c.get_offset_transform().transform(offsets)
            out += [("point", Path(p + [[-1, -1], [1, 1]])) for p in pts if np.all(np.isfinite(p))]
    return out


def overlaps(fig: Figure) -> list[str]:
    """Every text or legend of ``fig`` that covers data of its axes or another text or legend."""
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    r = canvas.get_renderer()
    found, boxes = [], []
    for k, ax in enumerate(fig.axes):
        mine = [
            (f"axes {k}: text {t.get_text()!r}", t.get_window_extent(r))
            for t in ax.texts
            if t.get_visible() and t.get_text().strip()
        ]
        legend = ax.get_legend()
        if legend is not None and legend.get_visible():
            mine.append((f"axes {k}: legend", legend.get_window_extent(r)))
        data, inside = _data(ax), ax.get_window_extent(r)
        for name, bb in mine:
            seen = Bbox.intersection(_shrunk(bb), inside)  # data is drawn only inside its axes (clipped)
            hit = seen and next((what for what, p in data if p.intersects_bbox(seen, filled=False)), None)
            if hit:
                found.append(f"{name} covers the {hit}")
        boxes += mine
    boxes += [(f"figure legend {i}", lg.get_window_extent(r)) for i, lg in enumerate(fig.legends)]
    for i, (a, ba) in enumerate(boxes):
        for b, bb in boxes[i + 1 :]:
            if _shrunk(ba).overlaps(_shrunk(bb)):
                found.append(f"{a} overlaps {b}")
    return found


# ----------------------------------------------------------------------------- the rule can fail
def test_the_rule_can_fail():
    fig = Figure(figsize=(4, 3))
    ax = fig.add_subplot()
    ax.plot([0, 1], [0, 1], label="data")
    ax.legend(loc="center")  # on the line
    assert any("legend covers the line" in f for f in overlaps(fig))
    fig = Figure(figsize=(4, 3))
    ax = fig.add_subplot()
    ax.plot([0, 1], [0.5, 0.5])
    ax.annotate("a label on the line", (0.5, 0.5), ha="center", va="center")
    assert any("covers the line" in f for f in overlaps(fig))
    fig = Figure(figsize=(4, 3))
    ax = fig.add_subplot()
    ax.add_patch(Circle((0.5, 0.5), 0.3, facecolor="0.9", edgecolor="0.5"))
    ax.text(0.8, 0.5, "on the rim", ha="center", va="center")
    assert any("covers the outline of a Circle" in f for f in overlaps(fig))
    fig = Figure(figsize=(4, 3))
    ax = fig.add_subplot()
    ax.text(0.2, 0.2, "one")
    ax.text(0.2, 0.2, "two")
    assert any("overlaps" in f for f in overlaps(fig))
    fig = Figure(figsize=(4, 3))
    ax = fig.add_subplot()
    ax.plot([0, 1], [0, 1], label="data")
    ax.legend(loc="upper left")
    assert overlaps(fig) == []


def test_a_clear_label_moves_off_a_line_it_would_cross():
    from wmr.plot.marks import label

    fig = Figure(figsize=(4, 3))
    ax = fig.add_subplot()
    ax.plot([0.5, 0.5], [0, 1])
    label(ax, (0.5, 0.5), "a label", offset=(0, -6), ha="center", va="top")  # straight down the line
    assert overlaps(fig) == []


def test_a_clear_label_moves_off_a_rim_it_would_cross():
    from wmr.plot.marks import label

    fig = Figure(figsize=(4, 3))
    ax = fig.add_subplot()
    ax.add_patch(Circle((0.5, 0.5), 0.3, facecolor="0.9", edgecolor="0.5"))
    label(ax, (0.8, 0.5), "a label", offset=(0, 0), ha="center", va="center")  # centred on the rim
    assert overlaps(fig) == []


# ----------------------------------------------------------------------------- the edition's figures
def _paper_figures():
    from edition.figures import FIGURES

    return {key: (lambda m=m: m.draw(m.data())) for key, m in FIGURES.items()}


def _physics_figures():
    from edition import physics
    from edition.physics import plot

    def run(*names):
        return [getattr(physics, n)() for n in names]

    return {
        "E8 drives locked": lambda: plot.draw_drift(*run("dead_zone_experiment", "jam_experiment")),
        "E9 contacts": lambda: plot.draw_contacts(*run("steering_experiment", "brake_experiment")),
        "E10 friction and noise": lambda: plot.draw_friction_noise(*run("reorient_experiment", "noise_experiment")),
        "E11 re-steering": lambda: plot.draw_resteer(*run("resteer_experiment")),
    }


def _interactive_figures():
    import wmr
    from edition import interactive

    steer = interactive.SteeringExplorer(
        wmr.paper_robot("centred", L=1.0, r=0.2), twist=(0.5, 0.2, 0.1), mode="commanded twist"
    )
    mounts = interactive.MountExplorer(radii=(1.2, 0.9, 1.0), angles_deg=(180, 50, -70))
    return {
        "E3 steering": lambda: interactive.draw_steering(steer.state()),
        "E4 mounts": lambda: interactive.draw_mounts(mounts.state()),
    }


def _design_figures():
    import wmr
    from edition import design_study as study
    from edition.transient_plot import distinguished_transient_figure
    from wmr.analysis import design
    from wmr.analysis import motion_kappa as mk
    from wmr.plot.design import draw_landscape, draw_motion_maps
    from wmr.swerve import direction_change, resteer_study

    swerve = study.swerve(0.6, 0.4, r=0.05)  # as chapter 8 builds them
    kite = wmr.Robot([wmr.CentredWheel(p, r=0.05) for p in [(0.4, 0.0), (0.0, 0.2), (-0.3, 0.0), (0.0, -0.2)]])

    def maps():
        m = [mk.motion_map(swerve, half_width=0.9), mk.motion_map(kite, half_width=0.9)]
        return draw_motion_maps(m, ["swerve, 0.6 m x 0.4 m", "kite"])

    def transient():
        return distinguished_transient_figure(
            resteer_study(swerve, direction_change(spin=0.5, dt=0.02), steer_rate=2 * np.pi)
        )

    return {
        "E5 design landscape": lambda: draw_landscape(design.landscape()),
        "E6 motion maps": maps,
        "E7 swerve transient": transient,
    }


FIGURE_MAKERS = {**_paper_figures(), **_physics_figures(), **_interactive_figures(), **_design_figures()}


@pytest.mark.parametrize("name", list(FIGURE_MAKERS))
def test_no_label_or_legend_covers_data_or_another(name):
    found = overlaps(FIGURE_MAKERS[name]())
    assert not found, f"{name}: {found}"
