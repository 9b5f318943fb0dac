r"""The condition number, (30)-(31): the definition applied exactly to :math:`\mathbf J_{L1}` of the paper's
placement with L free, and compared with :func:`wmr.condition_number`.

Chapter 3's checks live in :mod:`edition.checks.isotropy`; this module holds one group of them.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from wmr.analysis.linalg import condition_number
from wmr.model.robot import Robot
from wmr.model.robots import paper_robot
from wmr.model.tolerance import TOL
from wmr.model.wheels import CentredWheel

from ... import symbols as S
from ...transcription import printed
from ...verify import SEED, symbolic_equal
from .. import Derivation, equation, require

__all__ = ["RHO", "condition_number_def"]


#: the mount radius symbol of the paper's placement with L left free
RHO = sp.Symbol("rho", positive=True)


def condition_number_def(JL1, sv, kappa, n_pairs=50, n_random=2000, seed=SEED):
    r"""(30)-(31): the definition applied exactly to :math:`\mathbf J_{L1}` of the paper's placement with L free.

    :math:`\kappa(\mathbf J_{L1}) = \max(\rho/L, L/\rho)` for mount radius :math:`\rho`; both ends of
    (31) are attained (L = :math:`\rho`; all mount points at C).

    Parameters
    ----------
    JL1 : sympy.Matrix (6, 3)
        The derived :math:`\mathbf J_{L1}` of the paper's placement with mount radius :data:`RHO`, ``S.L`` free.
    sv : list
        Its derived singular values.
    kappa : SymPy expression
        The derived condition number :math:`\max(\sigma)/\min(\sigma)`.
    n_pairs : int
        Random :math:`(\rho, L)` for the comparison with ``wmr.condition_number``.
    n_random : int
        Random 6x3 matrices compared with ``numpy.linalg.cond``.
    seed : int

    Returns
    -------
    Derivation
        ``k_min`` (smallest kappa of the random matrices),
        findings (30) and (31).
    """
    p30, p31 = printed(30), printed(31)
    require(
        symbolic_equal(paper_robot("offset", L=RHO, r=S.r, exact=True).J1(S.L), JL1),
        "wmr's J1(L) of the paper's placement is the derived J_L1",
    )
    require(
        symbolic_equal(p30.expr.rhs.subs({S.sigma_l: sp.Max(*sv), S.sigma_s: sp.Min(*sv)}), kappa),
        "the derived kappa is (30) applied to the derived singular values",
    )
    key = sp.default_sort_key
    holds30 = symbolic_equal(
        sp.Matrix(sorted([s**2 for s in sv], key=key)),
        sp.Matrix(sorted((JL1.T * JL1).eigenvals(multiple=True), key=key)),
    )
    kfun = sp.lambdify((RHO, S.L), kappa, "numpy")
    rng = np.random.default_rng(seed)
    res = 0.0
    for rho, L in rng.uniform(0.2, 2.0, (n_pairs, 2)):
        res = max(res, abs(condition_number(paper_robot("offset", L=rho, r=0.1).J1(L)) - kfun(rho, L)))
    A = rng.normal(size=(n_random, 6, 3))
    k_rand = condition_number(A)
    res = max(res, float(np.max(np.abs(k_rand - np.linalg.cond(A)))))
    sv0 = Robot([CentredWheel((0, 0), r=1)] * 3).J1(sp.Integer(1)).singular_values()
    k_iso = condition_number(paper_robot("offset", L=0.4, r=0.1).J1(0.4))
    lower, upper = p31.expr
    holds31 = (
        min(sv0) == 0
        and upper == sp.oo
        and sp.simplify(kappa.subs(S.L, RHO)) == lower
        and bool(np.all(k_rand >= lower))
        and abs(k_iso - 1) <= TOL
    )
    return Derivation(
        k_min=float(k_rand.min()),
        findings=[
            equation(
                30,
                holds30,
                r"the squared singular values of $\mathbf J_{L1}$ (paper placement, radius $\rho$, $L$ "
                r"free) are the eigenvalues of $\mathbf J_{L1}^{\mathrm T}\mathbf J_{L1}$ (SymPy), "
                r"giving $\kappa = \max(\rho/L, L/\rho)$; `wmr.condition_number` agrees at "
                rf"{n_pairs} random $(\rho, L)$ and with `numpy.linalg.cond` on {n_random} random "
                r"matrices",
                res,
                convention=r"$\sigma_l$, $\sigma_s$ the largest and smallest singular values",
                note=r"`wmr.condition_number` returns $\infty$ when $\sigma_s \le 10^{-9}\sigma_l$",
            ),
            equation(
                31,
                holds31,
                r"$\kappa = 1$ is attained ($\mathbf J_{L1}$ at $L = \rho$) and $\kappa = \infty$ too "
                r"(all mount points at C: $\sigma_s = 0$ exactly); every random matrix has "
                r"$\kappa \geq 1$",
                0.0,
            ),
        ],
    )
