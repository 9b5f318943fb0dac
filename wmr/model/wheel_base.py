r"""The wheel unit in general: what every unit of :mod:`wmr.model.wheels` and :mod:`wmr.model.wheels_fixed` shares.

A unit mounted at :math:`P_i` (``position`` = :math:`\mathbf d_i`) contributes the block
:math:`\mathbf B_i(\beta_i) = \mathbf R_{bwi}\mathbf L_i` of :math:`\mathbf J_2` (21), where
:math:`\mathbf L_i` (2 x ``n_rates``) is its constant local block and :math:`\mathbf R_{bwi}` the
rotation (11) by the angle :math:`\beta_i` of its wheel frame.  Steered units (offset, centred,
dual) take :math:`\beta_i` from the robot's configuration; units without a steering joint
(fixed and Swedish wheels, ``steered = False``) have a constant angle of their own.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
import sympy as sp

from . import validation as V
from .backend import NUMERIC, choose
from .platform import E, rotated

__all__ = []


@dataclass(frozen=True)
class _Unit:
    position: tuple
    r: float

    kind = "unit"
    #: the unit's rate variables, in the order of its columns of J2: (plain name, TeX letter, suffix
    #: after the wheel number), e.g. ``("theta", r"\theta", "1")`` for the first wheel of a dual unit
    RATES = ()
    n_rates = 0                     # len(RATES), set for every subclass
    #: True when the unit has a steering joint (its angle is an entry of the robot's configuration)
    steered = True

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        cls.n_rates = len(cls.RATES)

    def __post_init__(self):
        object.__setattr__(self, "position", V.point("position", self.position))
        object.__setattr__(self, "r", V.positive("r (wheel radius)", self.r))

    # --- rate variables ----------------------------------------------------------------------
    def rate_names(self, i):
        """Plain names of this unit's rate variables when it is wheel ``i``.

        Parameters
        ----------
        i : int
            The unit's number in the robot (1-based, the paper's numbering).

        Returns
        -------
        tuple of str
            ``n_rates`` names, in the order of the unit's columns of :math:`\\mathbf J_2`.

        Examples
        --------
        >>> from wmr import OffsetWheel, DualWheel, CentredWheel
        >>> OffsetWheel((0, 0), r=1, d=0.5).rate_names(2)
        ('phi_dot_2', 'theta_dot_2')
        >>> DualWheel((0, 0), r=1, b=0.5).rate_names(3)
        ('theta_dot_31', 'theta_dot_32')
        """
        i = self._number(i)
        return tuple(f"{name}_dot_{i}{suffix}" for name, _, suffix in self.RATES)

    def rate_symbols(self, i):
        """SymPy symbols of the rate variables of wheel ``i``, typeset as in the paper.

        Parameters
        ----------
        i : int
            The unit's number in the robot (1-based).

        Returns
        -------
        tuple of sympy.Symbol
            ``n_rates`` real symbols, in the order of :meth:`rate_names`.

        Examples
        --------
        >>> from wmr import CentredWheel
        >>> CentredWheel((0, 0), r=1).rate_symbols(1)
        (\\dot{\\theta}_{1},)
        """
        i = self._number(i)
        return tuple(sp.Symbol(rf"\dot{{{tex}}}_{{{i}{suffix}}}", real=True) for _, tex, suffix in self.RATES)

    def beta_rate(self, psi_dot, rates, steer=None):
        """Steering rate :math:`\\dot\\beta_i` of the unit on the platform (used by the simulation).

        Parameters
        ----------
        psi_dot : float or array (...)
            Platform turning rate.
        rates : array (..., n_rates)
            The unit's joint rates.
        steer : float or array (...), optional
            Steering-rate input (used by centred wheels only).

        Returns
        -------
        float or numpy.ndarray (...)
        """
        raise NotImplementedError

    @staticmethod
    def _number(i):
        """The unit's number in the robot, checked (1-based)."""
        return V.integer("i", i, minimum=1)

    def _rates_in(self, psi_dot, rates, steer):
        """``psi_dot`` (...), ``rates`` (..., n_rates) and ``steer`` (... or None), checked."""
        psi_dot = V.finite_array("psi_dot", psi_dot)
        rates = V.finite_array("rates", rates, last=self.n_rates)
        steer = None if steer is None else V.finite_array("steer", steer)
        V.batch_shape({"psi_dot": psi_dot, "rates": rates[..., 0], "steer": steer}, core=0)
        return psi_dot, rates, steer

    @staticmethod
    def _finite_rate(out, rates):
        if not np.isfinite(out).all():
            raise ValueError(f"rates or psi_dot are too large: the steering rate overflows "
                             f"(largest |rates| = {np.abs(rates).max():.3g})")
        return out

    @property
    def is_symbolic(self):
        """True when the position or a length of the unit is a SymPy expression."""
        from .backend import is_symbolic
        return is_symbolic(*self._values())

    def _values(self):
        """The unit's parameters as a flat tuple (position coordinates, lengths, angles)."""
        return (*self.position, *[getattr(self, f.name) for f in dataclasses.fields(self) if f.name != "position"])

    def block(self, beta, backend=None):
        r"""This unit's block :math:`\mathbf B_i(\beta_i) = \mathbf R_{bwi}\mathbf L_i` of :math:`\mathbf J_2`.

        Evaluated as :math:`\cos\beta_i\,\mathbf L_i + \sin\beta_i\,\mathbf E\mathbf L_i` by
        :func:`wmr.model.platform.rotated` (the same matrix, since :math:`\mathbf R(\beta) =
        \cos\beta\,\mathbf 1 + \sin\beta\,\mathbf E` (11)); see :meth:`block_terms`.

        Parameters
        ----------
        beta : float, array (...) or sympy.Expr
            Steering angle :math:`\beta_i` of the intermediate body.
        backend : NUMERIC or SYMBOLIC, optional
            Default: SymPy if ``beta`` or the unit's parameters are symbolic, else NumPy.

        Returns
        -------
        numpy.ndarray (..., 2, n_rates) or sympy.Matrix (2, n_rates)

        Examples
        --------
        >>> from wmr import CentredWheel
        >>> CentredWheel((0.0, 0.0), r=2.0).block(0.0).tolist()     # (51): R(0) [0, -r]^T
        [[0.0], [-2.0]]
        """
        bk = choose(beta, *self._values(), backend=backend)
        if bk is NUMERIC:
            beta = V.finite_array("beta", beta)
        return rotated(beta, *self.block_terms(bk), backend=bk)      # (11): R(beta) L = cos L + sin E L

    def block_terms(self, backend=NUMERIC):
        r"""The constant pair :math:`(\mathbf L_i, \mathbf E\mathbf L_i)` with
        :math:`\mathbf B_i(\beta) = \cos\beta\,\mathbf L_i + \sin\beta\,\mathbf E\mathbf L_i`.

        :math:`\mathbf L_i` is the unit's local block (the block at :math:`\beta_i = 0`): every
        batched kernel of the package (J2, F, J, the mobility constraints, forward and inverse
        kinematics) is assembled from this pair, so the model is still written once.

        Parameters
        ----------
        backend : NUMERIC or SYMBOLIC, optional

        Returns
        -------
        tuple of two numpy.ndarray (2, n_rates) or sympy.Matrix (2, n_rates)
        """
        L = self._local_block(backend)
        return L, E(backend) @ L

    def _local_block(self, bk):
        raise NotImplementedError

    def points(self, beta):
        r"""Points of the unit in the body frame (for drawing and for checks).

        Parameters
        ----------
        beta : float or array (...)
            Steering angle(s) :math:`\beta_i`.

        Returns
        -------
        dict of numpy.ndarray
            ``"P"`` (steering axis, (..., 2)), ``"H"`` (centre of the wheel, or of the pair,
            (..., 2)), ``"wheels"`` ((..., k, 2): wheel centres = ground contact points seen from
            above), ``"i"`` and ``"j"`` (unit axle and rolling directions, (..., 2)).

        Examples
        --------
        >>> from wmr import OffsetWheel
        >>> OffsetWheel((1.0, 0.0), r=0.1, d=0.2).points(0.0)["H"].tolist()    # H = P - d j
        [1.0, -0.2]
        """
        beta = V.finite_array("beta", beta)
        c, s = np.cos(beta), np.sin(beta)
        i_dir = np.stack([c, s], axis=-1)
        j_dir = np.stack([-s, c], axis=-1)
        P = np.broadcast_to(np.asarray(self.position, dtype=float), i_dir.shape)
        return self._points(P, i_dir, j_dir)

    def _points(self, P, i_dir, j_dir):
        return {"P": P, "H": P, "wheels": P[..., None, :], "i": i_dir, "j": j_dir}
