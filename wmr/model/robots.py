r"""Ready-made robots, including the three-wheel robots of the paper.

The paper's numbering (the only one under which its printed :math:`\det\mathbf J` (59) holds
exactly): the three mount points are the vertices of an equilateral triangle centred at C, wheel
1 on the negative body x-axis and the others numbered clockwise,

.. math:: \mathbf d_1 = L(-1, 0),\quad \mathbf d_2 = L(\tfrac12, \tfrac{\sqrt3}2),\quad
          \mathbf d_3 = L(\tfrac12, -\tfrac{\sqrt3}2).
"""

from __future__ import annotations

import dataclasses
from typing import TypedDict

from ..errors import InputValueError
from . import validation
from .lazysympy import is_sympy, sp
from .robot import Robot
from .types import Numbers
from .wheels import wheel_kind

__all__ = ["Dimensions", "equilateral_mounts", "paper_robot"]

#: The wheel kinds of the paper's three robots (sections 3, 5 and 6).
PAPER_KINDS = ("centred", "offset", "dual")

#: Angles of the paper's mount points, wheel 1 first (clockwise from the negative x-axis).
PAPER_MOUNT_ANGLES_DEG = (180.0, 60.0, -60.0)


class Dimensions(TypedDict, total=False):
    """The lengths of :func:`paper_robot` by keyword (``paper_robot("offset", **dims)``): L, r, d, b."""

    L: float
    r: float
    d: float
    b: float


def equilateral_mounts(
    L: Numbers = 1.0, first_deg: float = 180.0, clockwise: bool = True, exact: bool = False
) -> list[tuple[Numbers, Numbers]]:
    r"""Mount points at the vertices of an equilateral triangle with centroid C and circumradius L.

    Parameters
    ----------
    L : float or sympy.Expr
        Distance of each mount point from C, > 0.
    first_deg : float
        Polar angle of wheel 1 in degrees.
    clockwise : bool
        Number the other wheels clockwise (the paper's numbering) or counter-clockwise.
    exact : bool
        Return SymPy expressions (exact for multiples of 30 degrees).

    Returns
    -------
    list of 3 pairs

    Examples
    --------
    >>> equilateral_mounts(2.0, exact=True)
    [(-2, 0), (1, sqrt(3)), (1, -sqrt(3))]
    """
    L = validation.positive("L", L)
    first_deg = validation.real("first_deg", first_deg)
    clockwise = validation.flag("clockwise", clockwise)
    exact = validation.flag("exact", exact)
    step = -120 if clockwise else 120
    # the angle exactly (a float is a rational), reduced modulo 360 before anything is added:
    # first_deg = 1e300 must still give three distinct vertices
    first = sp.nsimplify(first_deg) if is_sympy(first_deg) else sp.Rational(first_deg)
    first = first % 360
    if first.is_Rational:
        first = first.limit_denominator(10**6) if first.q > 10**6 else first
    out = []
    for k in range(3):
        ang = sp.pi * (first + k * step) / 180
        if exact or is_sympy(L) or is_sympy(first_deg):
            out.append((sp.nsimplify(L * sp.cos(ang)), sp.nsimplify(L * sp.sin(ang))))
        else:  # exact, then float:
            out.append((float(L * sp.cos(ang)), float(L * sp.sin(ang))))  # no 1e-17 residue
    return out


def paper_robot(
    kind: str = "centred",
    L: Numbers = 1.0,
    r: Numbers = 1.0,
    d: Numbers | None = None,
    b: Numbers | None = None,
    exact: bool = False,
) -> Robot:
    """The paper's three-wheel robot with its wheel numbering (see module docstring).

    Parameters
    ----------
    kind : {"centred", "offset", "dual"}
    L : float or sympy.Expr
        Distance of the mount points from C.
    r : float or sympy.Expr
        Wheel radius.
    d : float, optional
        Offset of offset wheels (default ``r``, the isotropic choice (46)); checked, unused by the others.
    b : float, optional
        Half separation of dual wheels (default ``r``); checked, unused by the others.
    exact : bool
        Use exact (SymPy) mount coordinates.

    Returns
    -------
    Robot

    Examples
    --------
    >>> paper_robot("offset", L=0.5, r=0.1)
    Robot('paper-offset': offset@(-0.5, 0.0), offset@(0.25, 0.4330127018922193), offset@(0.25, -0.4330127018922193))
    """
    if not isinstance(kind, str):
        raise validation.kind_error("kind", kind, "'centred', 'offset' or 'dual'")
    if kind not in PAPER_KINDS:
        raise InputValueError(f"kind must be 'centred', 'offset' or 'dual', got {kind!r}")
    lengths = {
        "d": None if d is None else validation.nonnegative("d (offset)", d),  # checked even where unused
        "b": None if b is None else validation.positive("b (half wheel separation)", b),
    }
    pts = equilateral_mounts(L, exact=validation.flag("exact", exact))
    cls = wheel_kind(kind)
    fields = {f.name for f in dataclasses.fields(cls)}
    own = {f: (r if v is None else v) for f, v in lengths.items() if f in fields}  # default r, as (46)
    units = [cls(p, r=r, **own) for p in pts]
    return Robot(units, name=f"paper-{kind}")
