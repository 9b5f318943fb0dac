r"""The square :math:`\mathbf J` (56) of a robot on three single-rate units (three centred wheels).

What the numeric side of :math:`\det\mathbf J` (:mod:`wmr.analysis.singularities`) and its exact side
(:mod:`wmr.analysis.det_exact`) share: the check that :math:`\mathbf J` is square, the characteristic
length used by default, and the exact (SymPy) counterpart of a numeric robot.
"""

from __future__ import annotations

import dataclasses

from ..errors import InputValueError
from ..model import validation
from ..model.lazysympy import sp
from ..model.robot import Robot
from ..model.types import Numbers
from .isotropy import characteristic_length

__all__ = ["exact_robot"]


def require_square(robot: Robot) -> None:
    r"""Check that ``robot`` has a square :math:`\mathbf J` (56): three units of one rate each (three centred wheels)."""
    validation.robot(robot)
    if robot.n_rates != 3 or robot.w != 3:
        raise InputValueError(
            f"det J needs a square J (three centred wheels, n_rates = 3); got a robot with w = {robot.w}, "
            f"n_rates = {robot.n_rates} (for dual wheels analyse the kinematically equivalent centred robot)"
        )


def default_L(robot: Robot, L: Numbers | None, numeric: bool = True) -> Numbers:
    """``L`` checked, or the characteristic length of ``robot`` (:func:`wmr.characteristic_length`) when None.

    ``numeric``: return a float (else a given SymPy ``L`` is kept).
    """
    validation.robot(robot)
    if L is not None:
        L = validation.positive("L", L)
        return validation.number("L", L) if numeric else L
    if validation.robot(robot).free_symbols:
        raise InputValueError(
            f"L must be given explicitly for a robot with symbolic mount points, got L = None for {validation.show(robot)}"
        )
    return characteristic_length(robot)


def exact_robot(robot: Robot) -> Robot:
    r"""The same robot with exact (SymPy) mount coordinates and radii, for symbolic checks.

    Parameters
    ----------
    robot : Robot
        Numeric (floats are made exact with ``nsimplify`` over :math:`\sqrt2, \sqrt3`) or symbolic (returned as is).

    Returns
    -------
    Robot
    """
    if validation.robot(robot).is_symbolic:
        return robot
    ns = [sp.sqrt(2), sp.sqrt(3)]
    units = [
        dataclasses.replace(u, position=tuple(sp.nsimplify(v, ns) for v in u.position), r=sp.nsimplify(u.r, ns))
        for u in robot.wheels
    ]
    return Robot(units, name=robot.name)
