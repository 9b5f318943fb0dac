r"""The analyses a sweep evaluates, by name (:data:`ANALYSES`; the table is in :mod:`wmr.analysis.sweep`).

Each one maps a robot and a chunk of configurations :math:`\boldsymbol\beta` (shape ``(k, w)``) to
one value per configuration (shape ``(k,)``) with the batched kernels.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ...model import validation
from ...model.robot import Robot

__all__ = ["ANALYSES"]


def J_length(robot: Robot, L: float | None) -> float:
    r"""The length of the analyses of :math:`\mathbf J_{L1}`: ``L`` checked, or :func:`wmr.characteristic_length`."""
    from ..isotropy import characteristic_length

    validation.numeric_robot(robot)
    return characteristic_length(robot) if L is None else validation.number("L", validation.positive("L", L))


def _rank_F(robot, beta, L):
    from ..mobility import rank_F

    return rank_F(robot, beta)


def _mobility(robot, beta, L):
    from ..mobility import mobility

    return mobility(robot, beta)


def _det_J(robot, beta, L):
    from ..linalg import det

    return det(robot.J(beta, L=L))


def _kappa_J(robot, beta, L):
    from ..linalg import condition_number

    return condition_number(robot.J(beta, L=L))


def _kappa_J_drivable(source, start, stop, L, fold):
    from .motions import kappa_J_drivable

    return kappa_J_drivable(source, start, stop, L, fold)


def _kappa_J_fused(robot, L):
    from .motions import fused_kernel
    from .swerve_kappa import swerve_like

    return swerve_like(robot) and fused_kernel(robot, J_length(robot, L)) is not None  # (a small robot: cheap)


def _actuated(robot, beta, L):
    from ..actuation import actuated_mobility

    return actuated_mobility(robot, beta)


def _kappa_JL1(robot, beta, L):
    from ..linalg import condition_number

    return np.full(beta.shape[:-1], float(condition_number(robot.J1(L))))


@dataclass(frozen=True)
class _Analysis:
    title: str
    evaluate: Callable[..., Any]  # (robot, beta (k, w), L) -> (k,)
    integer: bool
    worst: str  # "min", "max" or "min_abs"
    uses_L: bool = False
    square: bool = False
    drivable: Callable[..., Any] | None = None  # (source, start, stop, L, fold) -> bool: a fused kernel
    fused: Callable[..., bool] | None = None  # (robot, L or None) -> whether ``drivable`` applies


#: The analyses :func:`sweep` knows, by name.
ANALYSES = {
    "rank_F": _Analysis("rank F", _rank_F, True, "min"),
    "mobility": _Analysis("mobility", _mobility, True, "min"),
    "actuated_mobility": _Analysis("actuated mobility", _actuated, True, "min"),
    "det_J": _Analysis("det J", _det_J, False, "min_abs", uses_L=True, square=True),
    "kappa_J": _Analysis(
        "kappa(J)", _kappa_J, False, "max", uses_L=True, drivable=_kappa_J_drivable, fused=_kappa_J_fused
    ),
    "kappa_JL1": _Analysis("kappa(J_L1)", _kappa_JL1, False, "max", uses_L=True),
}
