r"""Figure E7 of the design study: :func:`wmr.swerve.plot.transient_figure`, with every strategy told apart.

Two strategies can produce the same motion (``plain`` and ``robot`` do when no module needs a flip), and the
library draws the first run wide so that others may run on it.  A reader still cannot see a curve that lies
exactly under another, so this drawing adds a marker of its own to every run, at staggered samples, and names
in the legend a run that coincides with an earlier one.
"""

from __future__ import annotations

import numpy as np

from wmr.model.tolerance import TOL
from wmr.swerve.plot import transient_figure

__all__ = ["MARKERS", "coincident_runs", "distinguished_transient_figure"]

#: one marker per strategy, in the order of the study's runs
MARKERS = ("o", "s", "^", "D", "v", "P", "X")


def coincident_runs(study):
    r"""For each run, the label of the first earlier run with the same motion (pose, slip, path error), or ``None``.

    Parameters
    ----------
    study : wmr.swerve.transient.TransientStudy

    Returns
    -------
    list of (str or None)
        One entry per run of ``study.runs``.
    """

    def same(a, b):
        scale = max(1.0, float(np.max(np.abs(a.pose))))
        return (
            a.pose.shape == b.pose.shape
            and float(np.max(np.abs(a.pose - b.pose))) <= TOL * scale
            and float(np.max(np.abs(a.slip - b.slip), initial=0.0)) <= TOL * scale
            and float(np.max(np.abs(a.path_error - b.path_error), initial=0.0)) <= TOL * scale
        )

    out = []
    for k, run in enumerate(study.runs):
        out.append(next((prev.label for prev in study.runs[:k] if same(run, prev)), None))
    return out


def distinguished_transient_figure(study, every=10):
    """Figure E7: the library's three panels, each run with its own marker, coincident runs named in the legend.

    Parameters
    ----------
    study : wmr.swerve.transient.TransientStudy
    every : int, optional
        A marker every ``every`` samples; run k starts at sample ``k * every // len(runs)`` so that the
        markers of coincident runs do not cover one another.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig = transient_figure(study)
    runs = list(study.runs)
    same_as = coincident_runs(study)
    for ax in fig.axes:
        by_label = {ln.get_label(): ln for ln in ax.get_lines()}
        for k, run in enumerate(runs):
            line = by_label.get(run.label)
            if line is None:
                continue
            line.set_marker(MARKERS[k % len(MARKERS)])
            line.set_markevery((k * every // len(runs), every))
            line.set_markersize(4.5)
            line.set_markerfacecolor("white")
            if same_as[k]:
                line.set_label(f"{run.label} (same motion as {same_as[k]})")
    legend = fig.axes[0].get_legend()
    if legend is not None:  # below the panels: no curve under it
        size = legend.get_texts()[0].get_fontsize()
        legend.remove()
        handles, labels = fig.axes[0].get_legend_handles_labels()
        fig.set_figheight(fig.get_figheight() + 0.5)
        fig.legend(handles, labels, loc="outside lower center", ncol=6, fontsize=size, frameon=False)
    return fig
