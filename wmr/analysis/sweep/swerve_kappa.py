r"""The fused kernel of a drivable sweep of :math:`\kappa(\mathbf J)`: swerve-like robots, straight from the twists.

For a robot whose every unit is steered, rolls in its plane and has one rate (3 to 6 centred wheels:
a swerve drive), the coordinated steering angles of a twist :math:`\mathbf t = (\dot\psi, \dot x, \dot y)`
(:func:`wmr.steering_angles`) set each wheel plane along its mount point's velocity
:math:`\dot{\mathbf p}_i = \dot{\mathbf c} + \dot\psi\mathbf E\mathbf d_i` (2).  Column i of
:math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` (56) is then

.. math:: \mathbf h_i = \cos\beta_i\,\mathbf a_i + \sin\beta_i\,\mathbf b_i
          = \frac{C_i\,\mathbf a_i + S_i\,\mathbf b_i}{\sqrt{C_i^2 + S_i^2}},\qquad
          S_i = \dot p_{ix} = \dot x - \dot\psi d_{iy},\quad C_i = -\dot p_{iy} = -\dot y - \dot\psi d_{ix},

with the constant vectors :math:`\mathbf a_i = \mathbf J_{L1,i}^T\mathbf L_i`,
:math:`\mathbf b_i = \mathbf J_{L1,i}^T\mathbf E\mathbf L_i` (3,) of the unit's block terms, so no angle is
ever formed.  The condition number (30) comes from :math:`\mathbf G = \mathbf J\mathbf J^T` (3 x 3):

* :math:`\mathbf G = \sum_i c_i^2\,(\mathbf a_i\mathbf a_i^T - \mathbf b_i\mathbf b_i^T)
  + c_is_i\,(\mathbf a_i\mathbf b_i^T + \mathbf b_i\mathbf a_i^T) + \mathbf b_i\mathbf b_i^T` with
  :math:`c_i^2 = \cos^2\beta_i = C_i^2/n_i`, :math:`c_is_i = C_iS_i/n_i`, :math:`n_i = C_i^2 + S_i^2`:
  a (6 x (2w + 1)) matrix times :math:`(c^2, cs, 1)`; its two largest eigenvalues
  :math:`\lambda_1\ge\lambda_2` by the trigonometric solution of the cubic
  (:mod:`~wmr.analysis.gram_kappa`, as :func:`wmr.analysis._closed.condition_number_3x3`), or by
  LAPACK where two of them nearly meet (the cubic's solution amplifies rounding there);
* :math:`\det\mathbf G = \sum_S(\det\mathbf J_S)^2` over the 3-column subsets S (Cauchy-Binet), and
  :math:`\det[C_i\mathbf a_i + S_i\mathbf b_i]_{i\in S}` is a cubic form in the twist that vanishes
  in translation (:math:`\dot\psi = 0`: every wheel parallel, the last two rows of
  :math:`\mathbf J` proportional), so it is :math:`\dot\psi\,Q_S(\mathbf t)` with a quadratic form
  :math:`Q_S` whose six coefficients are computed once per robot.  Hence

  .. math:: \det\mathbf G = \dot\psi^2\sum_S Q_S(\mathbf t)^2\prod_{i\notin S} n_i \Big/ \prod_i n_i,
            \qquad \kappa = \sqrt{\lambda_1/\lambda_3} = \lambda_1\sqrt{\lambda_2/\det\mathbf G},

  exact to full relative accuracy however close the twist is to a translation (where
  :math:`\kappa\to\infty` like :math:`1/\dot\psi`).

Everything is made dimensionless first (lengths divided by the largest mount coordinate
:math:`\ell`, the twist by :math:`s = \max(|\dot x|, |\dot y|) + |\dot\psi|\ell`, the columns by
their largest size: :math:`\kappa` changes under none of these), so the kernel takes the same
decisions in every unit.  Each member carries a first-order bound of its relative error (the
rounding of :math:`\mathbf G`, amplified where two eigenvalues nearly meet, and of the
:math:`Q_S`); a member is **accepted** when that bound is within ``KAPPA_ERROR eps kappa`` or
:data:`~wmr.analysis.gram_kappa.ACCURACY`, :math:`\kappa < 1/(2\,\mathrm{TOL})` (so the SVD rule would
not call it singular) and no wheel is still (:math:`\|\dot{\mathbf p}_i\| \le 2\,\mathrm{TOL}\,s`:
its angle is the caller's).  The others are left to the general kernels, so every decision is
theirs.
"""

from __future__ import annotations

import itertools
import math
from fractions import Fraction

import numpy as np

from ...errors import InputValueError
from ...model.backend import NUMERIC
from ...model.tolerance import TOL
from ..gram_kappa import SCRATCH, kappa_by_lapack, kappa_from_gram
from ..gram_kappa import UPPER as _UPPER

__all__ = ["SwerveKappa"]

#: Twists per chunk of the kernel (each of its about 130 NumPy calls costs a microsecond besides its work).
CHUNK = 8192
_EPS = np.finfo(float).eps
_SERIAL = 1 << 17  # multiply-adds of one BLAS call (see _product)


def _product(A, B, out):
    """``out = A @ B`` for a small ``A`` and a long ``B``, in column blocks that keep OpenBLAS on one thread.

    OpenBLAS starts threads above about ``4 * 65536`` multiply-adds: on a thread of the sweep's pool that is
    5 times slower (measured), so every call here stays below ``_SERIAL``.
    """
    step = max(1, _SERIAL // (A.shape[0] * A.shape[1]))
    k = B.shape[1]
    for a in range(0, k, step):
        np.matmul(A, B[:, a : a + step], out=out[:, a : a + step])


def swerve_like(robot) -> bool:
    """True when :class:`SwerveKappa` applies: 3 to 6 units, each steered, rolling in its plane, with one rate."""
    return 3 <= robot.w <= 6 and all(
        u.steered and u.rolls_in_plane and u.n_rates == 1 and u.steering_row() is None for u in robot.wheels
    )


def _cubic_form(K3):
    r"""The cubic form :math:`\det[\mathbf K_1\mathbf t, \mathbf K_2\mathbf t, \mathbf K_3\mathbf t]` by monomial, exactly.

    Each of the 27 terms :math:`t_x t_y t_z \det[\mathbf K_1\mathbf e_x, \mathbf K_2\mathbf e_y,
    \mathbf K_3\mathbf e_z]` is computed in rational arithmetic from the floating-point entries,
    so the coefficients are exact (rounded once) and those that vanish in exact arithmetic are 0.
    Returns sorted exponent triple ``(x, y, z)`` -> :class:`fractions.Fraction`.
    """
    F = [[[Fraction(float(v)) for v in row] for row in Ki] for Ki in K3]
    out: dict[tuple[int, ...], Fraction] = {}
    for x, y, z in itertools.product(range(3), repeat=3):
        c = [[F[0][r][x], F[1][r][y], F[2][r][z]] for r in range(3)]
        det = (
            c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1])
            - c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0])
            + c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0])
        )
        key = tuple(sorted((x, y, z)))
        out[key] = out.get(key, Fraction(0)) + det
    return out


class SwerveKappa:
    r""":math:`\kappa(\mathbf J)` at the coordinated steering angles of twists, for one swerve-like robot and L.

    See the module notes.  The constants (the vectors :math:`\mathbf a_i, \mathbf b_i`, the map from
    :math:`(\gamma, \sigma)` to :math:`\mathbf G`, the coefficients of the :math:`Q_S`) are computed
    here, once.

    Parameters
    ----------
    robot : Robot
        A numeric swerve-like robot (:func:`~wmr.analysis.sweep.motions.swerve_like`).
    L : float
        Characteristic length of :math:`\mathbf J_{L1}`.

    Raises
    ------
    wmr.errors.InputValueError
        If the robot's :math:`\det\mathbf J_S` do not vanish in translation
        (then no fused kernel applies).
    """

    def __init__(self, robot, L):
        w = robot.w
        JL1 = robot.J1(L=L)
        d = np.asarray(robot.mount_points, dtype=float)
        ell = float(np.abs(d).max())
        a, b = np.empty((w, 3)), np.empty((w, 3))
        for i, u in enumerate(robot.wheels):
            Li, ELi = u.block_terms(NUMERIC)
            a[i] = JL1[2 * i : 2 * i + 2].T @ np.asarray(Li, dtype=float)[:, 0]
            b[i] = JL1[2 * i : 2 * i + 2].T @ np.asarray(ELi, dtype=float)[:, 0]
        size = max(float(np.abs(a).max()), float(np.abs(b).max()))
        a, b = a / size, b / size  # kappa does not change when J is scaled
        e = d / ell if ell > 0 else d
        # C_i and S_i as linear forms in the dimensionless twist (psi ell, x_dot, y_dot) / s
        lin = np.zeros((2 * w, 3))
        lin[:w, 0], lin[:w, 2] = -e[:, 0], -1.0  # C_i = -y_dot - psi d_ix
        lin[w:, 0], lin[w:, 1] = -e[:, 1], 1.0  # S_i = x_dot - psi d_iy
        # G (upper entries) = sum_i c_i^2 a_i a_i^T + c_i s_i (a_i b_i^T + b_i a_i^T) + (1 - c_i^2) b_i b_i^T
        # = coef @ (c^2; c s; 1), c_i = cos beta_i, s_i = sin beta_i
        coef = np.zeros((6, 2 * w + 1))
        for m, (j, k) in enumerate(_UPPER):
            coef[m, :w] = a[:, j] * a[:, k] - b[:, j] * b[:, k]
            coef[m, w : 2 * w] = a[:, j] * b[:, k] + b[:, j] * a[:, k]
            coef[m, 2 * w] = float(np.sum(b[:, j] * b[:, k]))
        # K_i t = C_i a_i + S_i b_i: K_i = a_i lin_C,i^T + b_i lin_S,i^T (3 x 3)
        K = a[:, :, None] * lin[:w, None, :] + b[:, :, None] * lin[w:, None, :]
        subsets = list(itertools.combinations(range(w), 3))
        qcoef = np.zeros((len(subsets), 6))
        for s, S in enumerate(subsets):
            cubic = _cubic_form([K[i] for i in S])
            # in translation J is singular: the coefficients of the monomials without psi vanish
            if any(cubic[m] for m in cubic if m[0] != 0):
                raise InputValueError(
                    f"robot must have det J = 0 in translation for the fused kappa(J) kernel, got {robot!r}"
                )
            for m, (j, k) in enumerate(_UPPER):
                qcoef[s, m] = float(cubic.get((0, j, k), 0))
        comp = [tuple(i for i in range(w) if i not in S) for S in subsets]
        self.w, self.ell, self.lin, self.L = w, ell, lin, L
        self.coef = coef
        self.qcoef, self.qabs = qcoef, np.abs(qcoef)
        self.comp = comp
        # rounding of G: entry m is a sum of 2w + 1 terms of at most sum_j |coef_mj| (c^2 and c s lie in
        # [-1, 1], with a few eps of error), so |dG_m| <= (2w + 6) eps size_m and the eigenvalues move by at
        # most ||dG||_F
        size = np.abs(coef).sum(axis=1)
        size[[1, 2, 4]] *= math.sqrt(2.0)  # the off-diagonal entries count twice in ||.||_F
        self.g_error = (2 * w + 6) * _EPS * float(np.linalg.norm(size))

    def __call__(self, twist, out, redo):
        r"""Evaluate the kernel on ``twist (k, 3)``: :math:`\kappa` into ``out (k,)``, ``redo (k,)`` True where not accepted."""
        N = twist.shape[0]
        m = min(CHUNK, N)
        # one workspace for every chunk of the call (no allocation per chunk: large temporaries would be
        # mapped and faulted in afresh each time)
        w, nS = self.w, self.qcoef.shape[0]
        ws = _Workspace(np.empty((5 * w + 16 + 2 * nS + _SCRATCH, m)), np.empty((2, m), dtype=bool), w, nS)
        ws.gs[2 * w] = 1.0  # the constant term of G
        again: list = []  # (rows, G, det G, its relative error) of members for LAPACK's eigenvalues
        with np.errstate(all="ignore"):
            for lo in range(0, N, m):
                hi = min(lo + m, N)
                rows = self._chunk(twist[lo:hi], out[lo:hi], redo[lo:hi], ws.view(hi - lo))
                if rows.size:
                    again.append((lo + rows, ws.G[:, rows], ws.scratch[6, rows], ws.scratch[4, rows]))
        if again:  # one call for all of them (LAPACK's call costs far more than these few members)
            rows, G, detG, det_rel = (np.concatenate(x, axis=-1) for x in zip(*again))
            out[rows], ok = kappa_by_lapack(G, detG, det_rel, self.g_error)
            redo[rows] = ~ok

    def _chunk(self, tw, out, redo, ws):
        w = self.w
        T, CS, n, gs, G, M, Q, Qa = ws.T, ws.CS, ws.n, ws.gs, ws.G, ws.M, ws.Q, ws.Qa
        v = ws.scratch  # vectors v[0], v[1], ...
        # the dimensionless twist t / s, s = max(|x_dot|, |y_dot|) + |psi| ell (the scale of steering_angles)
        s = v[0]
        np.abs(tw.T, out=T)
        np.maximum(T[1], T[2], out=s)
        T[0] *= self.ell
        s += T[0]
        np.divide(1.0, s, out=s)
        np.multiply(tw.T, s, out=T)
        T[0] *= self.ell
        _product(self.lin, T, CS)  # (2w, k): C_i then S_i
        C, S = CS[:w], CS[w:]
        cc, cs = gs[:w], gs[w : 2 * w]  # (row 2w is 1)
        np.multiply(C, C, out=cc)
        np.multiply(S, S, out=n)
        n += cc  # n_i = C_i^2 + S_i^2 = |p_i|^2 / s^2
        np.multiply(C, S, out=cs)
        cc /= n  # cos^2 beta_i
        cs /= n  # cos beta_i sin beta_i
        moving = ws.moving  # no wheel (nearly) at the centre, a non-zero finite twist
        lo = v[1]
        np.minimum(n[0], n[1], out=lo)
        for i in range(2, w):
            np.minimum(lo, n[i], out=lo)
        np.greater(lo, (2 * TOL) ** 2, out=moving)
        _product(self.coef, gs, G)  # the upper entries of G = J J^T
        # det G = psi^2 sum_S Q_S^2 prod_{i not in S} n_i / prod_i n_i
        x, y, z = T
        np.multiply(x, x, out=M[0])
        np.multiply(x, y, out=M[1])
        np.multiply(x, z, out=M[2])
        np.multiply(y, y, out=M[3])
        np.multiply(y, z, out=M[4])
        np.multiply(z, z, out=M[5])
        _product(self.qcoef, M, Q)
        for j in (1, 2, 4):
            np.abs(M[j], out=M[j])
        _product(self.qabs, M, Qa)
        np.abs(Q, out=Q)
        Qa *= Q
        Q *= Q
        if w == 4:  # the complement of subset k (in the order of itertools.combinations) is wheel 3 - k
            Q *= n[::-1]
            Qa *= n[::-1]
        elif w > 4:
            f = v[2]
            for k, rest in enumerate(self.comp):
                np.multiply(n[rest[0]], n[rest[1]], out=f)
                for i in rest[2:]:
                    f *= n[i]
                Q[k] *= f
                Qa[k] *= f
        R, Ra, prod = v[3], v[4], v[5]
        for acc, rows, op in ((R, Q, np.add), (Ra, Qa, np.add), (prod, n, np.multiply)):
            np.copyto(acc, rows[0])  # row by row: faster than a reduction over the first axis
            for row in rows[1:]:
                op(acc, row, out=acc)
        # relative error of det G: 2 * 8 eps sum_S |Q_S| (|q_S| . |M|) ... / R (each Q_S a 6-term dot
        # product of exact coefficients and rounded monomials), plus the products and quotients
        det_rel = Ra
        det_rel /= R
        det_rel *= 16 * _EPS
        det_rel += (2 * w + 8) * _EPS
        detG = v[6]
        np.multiply(M[0], R, out=detG)
        detG /= prod
        ok = redo
        lam2 = kappa_from_gram(G, detG, det_rel, self.g_error, v[7:], out, ok, ws.bad)
        ok &= moving  # (with the wheels' speeds above 2 TOL s, nothing above under- or overflows)
        np.logical_not(ok, out=redo)
        # where two eigenvalues nearly meet, the cubic's solution amplifies the rounding of G: those members
        # get LAPACK's eigenvalues before the general kernels
        again = np.flatnonzero(redo)
        return again[moving[again] & (lam2[again] > 0)]


_SCRATCH = 7 + SCRATCH


class _Workspace:
    """The preallocated temporaries of :meth:`SwerveKappa._chunk`: named rows of ``V`` and ``B``, for ``k`` twists.

    ``V`` (5 w + 16 + 2 nS + _SCRATCH, >= k) floats, ``B`` (2, >= k) bools; ``nS`` 3-subsets of the ``w`` units.
    """

    def __init__(self, V, B, w, nS, k=None):
        k = V.shape[1] if k is None else k
        self.V, self.B, self.w, self.nS = V, B, w, nS
        a = np.cumsum([0, 3, 2 * w, w, 2 * w + 1, 6, 6, nS, nS, _SCRATCH]).tolist()
        self.T, self.CS, self.n, self.gs, self.G, self.M, self.Q, self.Qa, self.scratch = (
            V[a[j] : a[j + 1], :k] for j in range(9)
        )
        self.moving, self.bad = B[0, :k], B[1, :k]

    def view(self, k):
        """The workspace for a chunk of ``k`` twists (views of the first ``k`` columns)."""
        return _Workspace(self.V, self.B, self.w, self.nS, k)
