r"""3D lifting, the vertical axis and the rolling disk (the derivation of (6)), shared by the checks.

Chapter 1's checks live in :mod:`edition.checks.wheels`; this module holds one group of them.
"""
from __future__ import annotations

from functools import cache

import sympy as sp

from ... import symbols as S
from .. import Derivation, require

__all__ = ["k", "time", "lift", "planar", "disk_velocity", "unit_axes"]


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


@cache
def disk_velocity(theta_dot, phi=S.phi_i, phi_dot=S.phi_dot_i, r=S.r):
    r"""Velocity of the centre of a thin disk rolling without slip, and its axes (derivation of (6)).

    The disk spins about its axle :math:`\mathbf i_i` at ``theta_dot`` and is steered about
    :math:`\mathbf k` at ``phi_dot``, :math:`\boldsymbol\Omega = \dot\theta\,\mathbf i_i + \dot\phi\,\mathbf k`;
    no slip: the material point at the contact :math:`H - r\mathbf k` is at rest,
    :math:`\dot{\mathbf h} + \boldsymbol\Omega\times(-r\mathbf k) = \mathbf 0`.

    Parameters
    ----------
    theta_dot, phi, phi_dot, r : SymPy symbols
        Rolling rate, absolute steering angle and rate, radius.

    Returns
    -------
    Derivation
        ``h_dot`` (3, 1) fixed-frame velocity of the centre, ``Omega``, the axle ``i3`` and rolling
        direction ``j3 = k x i3`` (3, 1).
    """
    i3 = sp.Matrix([sp.cos(phi), sp.sin(phi), 0])
    j3 = k.cross(i3)
    Omega = theta_dot * i3 + phi_dot * k
    v = sp.Matrix(sp.symbols("v_x v_y v_z", real=True))
    sol = sp.solve(list(v + Omega.cross(-r * k)), list(v), dict=True)[0]
    return Derivation(h_dot=v.subs(sol), Omega=Omega, i3=i3, j3=j3)


def unit_axes():
    r"""The axes :math:`\mathbf i_i, \mathbf j_i` of unit *i* in the fixed frame, from the rolling disk
    (:func:`disk_velocity`).

    Returns
    -------
    dict
        ``{S.i_i: Matrix (2, 1), S.j_i: Matrix (2, 1)}``: the named axes of the printed forms and
        their components, functions of the absolute steering angle :math:`\phi_i`.
    """
    d = disk_velocity(S.theta_dot_i)
    return {S.i_i: planar(d.i3), S.j_i: planar(d.j3)}
