r"""3D lifting, the vertical axis, time, and the printed symbols of the wheel axes, shared by the checks.

Chapter 1's checks live in :mod:`edition.checks.wheels`; this module holds one group of them.  The
derivations themselves (the rolling disk, the offset wheel, ...) are in the chapter's notebook.
"""

from __future__ import annotations

import sympy as sp

from ... import symbols as S
from .. import require

__all__ = ["k", "time", "lift", "planar", "unit_axes"]


#: the vertical unit vector (3D)
k = sp.Matrix([0, 0, 1])
#: time, the variable of the angle histories whose derivatives are the rates
time = sp.Symbol("t", real=True)


def lift(v):
    """A planar vector as a 3D vector with zero vertical component.

    Parameters
    ----------
    v : sequence of 2

    Returns
    -------
    sympy.Matrix (3, 1)
    """
    return sp.Matrix([v[0], v[1], 0])


def planar(v):
    """The planar part of a 3D vector (which must have no vertical component).

    Parameters
    ----------
    v : sympy.Matrix (3, 1)

    Returns
    -------
    sympy.Matrix (2, 1)
    """
    require(sp.simplify(v[2]) == 0, "a planar velocity has no vertical component")
    return sp.Matrix(v[:2])


def unit_axes(i3, j3):
    r"""The printed symbols :math:`\mathbf i_i, \mathbf j_i` mapped onto the chapter's axes (for the printed forms).

    Parameters
    ----------
    i3, j3 : sympy.Matrix (3, 1)
        The axle and the rolling direction in fixed components, functions of :math:`\phi_i`.

    Returns
    -------
    dict
        ``{S.i_i: Matrix (2, 1), S.j_i: Matrix (2, 1)}``.
    """
    return {S.i_i: planar(i3), S.j_i: planar(j3)}
