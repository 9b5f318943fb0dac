r"""The numbers of a state as Markdown.

Part of the interactive chapter: :mod:`edition.interactive`.
"""

from __future__ import annotations

import numpy as np

from wmr.analysis.lines import AT_INFINITY, FINITE

from ..text import number

__all__ = ["describe_steering", "describe_mounts"]


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
    lines = [
        "| $\\det\\mathbf J$ | $\\operatorname{rank}\\mathbf F$ | mobility | $\\kappa(\\mathbf J)$ |",
        "|---|---|---|---|",
        f"| ${number(state.det_J, 3) if abs(state.det_J) > 1e-12 else '0'}$ | {state.rank_F} | {state.mobility} | "
        f"${k}$ |",
        "",
        f"The axle lines {axles}; the wheel-plane lines {planes}.",
    ]
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
    c = np.round(state.centroid, 3) + 0.0  # no "-0.000"
    iso = abs(state.kappa - 1) < 1e-9
    text = (
        rf"$\kappa(\mathbf J_{{L1}}) = {number(state.kappa, 4)}$ at $L = {state.L:.3g}$; centroid of the "
        rf"$P_i$ at $({c[0]:.3f}, {c[1]:.3f})$; RMS distance ${state.L_rms:.3f}$, where "
        rf"$\kappa = {number(state.kappa_best, 4)}$."
    )
    if iso:
        text += r" **Isotropic.**"
    elif np.abs(c).max() > 1e-9:
        text += r" The centroid must be at C (37)."
    else:
        text += r" The centroid is at C: choose $L$ = the RMS distance (36)."
    return text
