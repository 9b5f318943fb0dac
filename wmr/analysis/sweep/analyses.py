r"""The analyses a sweep evaluates, by name (:data:`ANALYSES`; the table is in :mod:`wmr.analysis.sweep`).

Each one maps a robot, a chunk of configurations :math:`\boldsymbol\beta` (shape ``(k, w)``) and the
characteristic length to one value per configuration (shape ``(k,)``) with the batched kernels.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..actuation import actuated_mobility
from ..linalg import condition_number, det
from ..mobility import mobility, rank_F

__all__ = ["ANALYSES"]


@dataclass(frozen=True)
class _Analysis:
    """One analysis: its title, its batched evaluation ``(robot, beta (k, w), L) -> (k,)`` and its worst end."""

    title: str
    evaluate: Callable[..., Any]
    integer: bool
    worst: str  # "min", "max" or "min_abs"
    uses_L: bool = False
    square: bool = False
    fused: bool = False  # a fused kernel over Drivable configurations for swerve-like robots (sweep.motions)


#: The analyses :func:`sweep` knows, by name.
ANALYSES = {
    "rank_F": _Analysis("rank F", lambda robot, beta, L: rank_F(robot, beta), True, "min"),
    "mobility": _Analysis("mobility", lambda robot, beta, L: mobility(robot, beta), True, "min"),
    "actuated_mobility": _Analysis(
        "actuated mobility", lambda robot, beta, L: actuated_mobility(robot, beta), True, "min"
    ),
    "det_J": _Analysis(
        "det J", lambda robot, beta, L: det(robot.J(beta, L=L)), False, "min_abs", uses_L=True, square=True
    ),
    "kappa_J": _Analysis(
        "kappa(J)", lambda robot, beta, L: condition_number(robot.J(beta, L=L)), False, "max", uses_L=True, fused=True
    ),
    "kappa_JL1": _Analysis(
        "kappa(J_L1)",
        lambda robot, beta, L: np.full(beta.shape[:-1], float(condition_number(robot.J1(L)))),
        False,
        "max",
        uses_L=True,
    ),
}
