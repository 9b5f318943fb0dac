r"""Design by conditioning: the worst-case :math:`\kappa(\mathbf J)` of a wheel layout and a search over layouts.

The measure (Section 4.3 of the paper, (30)-(33) and (56))
-----------------------------------------------------------
The kinematic model (21) is :math:`\mathbf J_{L1}\mathbf t_L = \mathbf J_2\dot{\boldsymbol\theta}` with the
homogeneous platform Jacobian :math:`\mathbf J_{L1}` (32) (rows :math:`[\tfrac1L\mathbf E\mathbf d_i\ \ \mathbf 1]`)
and the homogeneous twist :math:`\mathbf t_L = [L\dot\psi\ \dot{\mathbf c}^T]^T` (33).  The map of the
forward kinematics is :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` (56) (:meth:`wmr.Robot.J`), and a
design is judged by its condition number :math:`\kappa(\mathbf J) = \sigma_l/\sigma_s` (30) in the
**worst** steering configuration,

.. math:: \bar\kappa = \sup_{\boldsymbol\beta}\ \kappa\big(\mathbf J(\boldsymbol\beta, L)\big),

with the characteristic length :math:`L` the root-mean-square distance of the mount points from C
(:func:`wmr.characteristic_length`: the :math:`L` of (36) that makes :math:`\mathbf J_{L1}` isotropic when
C is the centroid).  :math:`\kappa(\mathbf J)` has period :math:`\pi` in every :math:`\beta_i`:
:math:`\mathbf R(\beta_i + \pi) = -\mathbf R(\beta_i)` only changes the sign of unit i's columns, so the
configurations are taken in :math:`[0, \pi)^w`.

Two facts frame the search.  :math:`\kappa\ge 1` (31).  And for offset wheels :math:`\mathbf J_2` is square
and invertible (:math:`d > 0`), so :math:`\sigma_s(\mathbf J)\ge\sigma_s(\mathbf J_{L1})\sigma_s(\mathbf J_2)`
and :math:`\kappa(\mathbf J)\le\kappa(\mathbf J_{L1})\,\kappa(\mathbf J_2)` with
:math:`\kappa(\mathbf J_2) = \max(d/r,\ r/d)` at every :math:`\boldsymbol\beta` (the blocks are
:math:`\mathbf R(\beta_i)\,\mathrm{diag}(-d, -r)`, (21)).

The design space of three offset wheels
---------------------------------------
:math:`\kappa(\mathbf J)` does not change when every length is scaled (:math:`\mathbf J_{L1}` depends on
:math:`\mathbf d_i/L`, :math:`\kappa(\mathbf J_2)` on :math:`d/r`) nor when the body frame is rotated.  So
wheel 1 is put at :math:`\mathbf d_1 = (-1, 0)` (the paper's wheel 1) and the radius at :math:`r = 1`; a
design is the vector :math:`\mathbf p = (x_2, y_2, x_3, y_3, \log_2(d/r))`.  :func:`search` screens a
seeded random sample of designs on a coarse grid of configurations, refines the best few by a
compass (pattern) search, and evaluates the winner and the paper's answer -- the equilateral
triangle centred at C with :math:`d = r` ((37), (38), (46)) -- with :func:`worst_kappa` on a fine grid.
"""

from .space import DesignSearch, Landscape, landscape, search
from .worst_case import (
    COARSE_STEPS,
    FINE_STEPS,
    WheelDesign,
    WorstCase,
    equilateral_design,
    worst_kappa,
    worst_kappa_designs,
)

__all__ = [
    "WorstCase",
    "worst_kappa",
    "WheelDesign",
    "equilateral_design",
    "worst_kappa_designs",
    "DesignSearch",
    "search",
    "Landscape",
    "landscape",
    "COARSE_STEPS",
    "FINE_STEPS",
]
