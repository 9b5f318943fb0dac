r"""Section 4.3 as printed: condition number and kinetostatic isotropy of a WMR with three offset wheels, (30)-(50).

Conventions of the transcription
--------------------------------
* Matrix identities are stored as ``Eq(lhs, rhs)`` whose left side names the model objects with
  :class:`sympy.MatrixSymbol` (:data:`JL1`, :data:`J2`, :data:`tL`, :data:`theta_dot`); a notebook
  substitutes the matrices *derived* by :mod:`wmr` and compares with the printed right side.
* The general mount points of (32)-(38) are the symbols :data:`D` = ((d_1x, d_1y), ..., (d_3x, d_3y)).
* Equations (41)-(45) hold "for i = 1, 2, 3"; they are transcribed for one wheel with the generic
  steering angle :data:`beta_i`.

Nothing here is derived: these are the statements under test (see ``notebooks/03_kinetostatic_isotropy``).
"""
from __future__ import annotations

import sympy as sp

from . import symbols as S
from . import register, register_claim

SECTION = "4.3"

#: condition number and extreme singular values of (30)
kappa, sigma_l, sigma_s = sp.symbols(r"\kappa \sigma_l \sigma_s", positive=True)
#: general mount points d_i = CP_i, body frame (i = 1, 2, 3)
D = tuple(sp.symbols(f"d_{{{i}x}} d_{{{i}y}}", real=True) for i in (1, 2, 3))
#: generic steering angle of "wheel i" in (41)-(45)
beta_i = sp.Symbol(r"\beta_i", real=True)

#: model objects named as in the paper (three offset wheels: J2 is 6 x 6)
JL1 = sp.MatrixSymbol(r"\mathbf{J}_{L1}", 6, 3)
J2 = sp.MatrixSymbol(r"\mathbf{J}_{2}", 6, 6)
tL = sp.MatrixSymbol(r"\mathbf{t}_{L}", 3, 1)
theta_dot = sp.MatrixSymbol(r"\dot{\boldsymbol{\theta}}", 6, 1)
Upsilon = tuple(sp.MatrixSymbol(rf"\Upsilon_{{{i}}}", 2, 2) for i in (1, 2, 3))
ptilde2 = sp.MatrixSymbol(r"\tilde{\mathbf{p}}^{2}", 2, 2)

_E = sp.Matrix([[0, -1], [1, 0]])                       # (3), as printed
_I2 = sp.eye(2)
_L, _r, _d = S.L, S.r, S.d
_dv = [sp.Matrix(p) for p in D]
_sum_d = _dv[0] + _dv[1] + _dv[2]
_sum_dd = sum((v.T * v)[0] for v in _dv)


def _R(angle):
    # (11) as printed: [[cos, -sin], [sin, cos]]
    return sp.Matrix([[sp.cos(angle), -sp.sin(angle)], [sp.sin(angle), sp.cos(angle)]])


register(
    "30", SECTION, r"\kappa \equiv \frac{\sigma_l}{\sigma_s}",
    sp.Eq(kappa, sigma_l / sigma_s),
    garbled=r"the extraction prints $\sigma_1$; the text and the nomenclature call it the largest singular value $\sigma_l$",
    note="definition of the condition number of an m x n matrix")

register(
    "31", SECTION, r"1 \leqslant \kappa \leqslant \infty",
    sp.Tuple(sp.Integer(1), sp.oo),
    note="range of kappa: (lower, upper) bounds, both attained (isotropic / rank-deficient matrices)")

register(
    "32", SECTION,
    r"\mathbf{J}_{L1} \equiv \begin{bmatrix} \frac{1}{L}\mathbf{E}\mathbf{d}_1 & \mathbf{1}\\ "
    r"\frac{1}{L}\mathbf{E}\mathbf{d}_2 & \mathbf{1}\\ \vdots & \vdots\\ \frac{1}{L}\mathbf{E}\mathbf{d}_w & \mathbf{1}\end{bmatrix}",
    sp.Eq(JL1, sp.Matrix.vstack(*[sp.Matrix.hstack(_E * v / _L, _I2) for v in _dv]), evaluate=False),
    note="definition; transcribed for w = 3 with general mount points D")

register(
    "33", SECTION, r"\mathbf{t}_L \equiv \begin{bmatrix} \dot\psi L & \dot{\mathbf{c}}^{\mathrm{T}}\end{bmatrix}^{\mathrm{T}}",
    sp.Eq(tL, sp.Matrix([S.psi_dot * _L, S.x_dot, S.y_dot]), evaluate=False),
    note="definition of the dimensionally homogeneous twist")

register(
    "34", SECTION,
    r"\mathbf{J}_{L1}^{\mathrm{T}}\mathbf{J}_{L1} = \begin{bmatrix} \frac{1}{L^2}\sum_{i=1}^{3}\mathbf{d}_i^{\mathrm{T}}\mathbf{d}_i & "
    r"\frac{1}{L}\left(\sum_{i=1}^{3}\mathbf{d}_i^{\mathrm{T}}\right)\mathbf{E}^{\mathrm{T}}\\ "
    r"\frac{1}{L}\mathbf{E}\left(\sum_{i=1}^{3}\mathbf{d}_i\right) & (3)\mathbf{1}\end{bmatrix}",
    sp.Eq(JL1.T * JL1, sp.Matrix(sp.BlockMatrix([
        [sp.Matrix([[_sum_dd / _L**2]]), _sum_d.T * _E.T / _L],
        [_E * _sum_d / _L, 3 * _I2]])), evaluate=False),
    note="three wheels, general mount points D")

register(
    "35", SECTION,
    r"\frac{1}{L}\left(\sum_{i=1}^{3}\mathbf{d}_i^{\mathrm{T}}\right)\mathbf{E}^{\mathrm{T}} = \mathbf{0} \;\Rightarrow\; "
    r"\frac{1}{L}\mathbf{E}\left(\sum_{i=1}^{3}\mathbf{d}_i\right) = \mathbf{0}",
    sp.Eq(_E * _sum_d / _L, sp.zeros(2, 1), evaluate=False),
    note="isotropy condition (off-diagonal blocks of (34)); stored as the column form after the implication",
    row_form=sp.Eq(_sum_d.T * _E.T / _L, sp.zeros(1, 2), evaluate=False))

register(
    "36", SECTION, r"\frac{1}{L^2}\sum_{i=1}^{3}\mathbf{d}_i^{\mathrm{T}}\mathbf{d}_i = 3",
    sp.Eq(_sum_dd / _L**2, 3),
    note="isotropy condition (corner entry of (34) equal to the diagonal 3 of its lower block)")

register(
    "37", SECTION, r"\sum_{i=1}^{3}\mathbf{d}_i = \mathbf{0}",
    sp.Eq(_sum_d, sp.zeros(2, 1), evaluate=False),
    note="stated as what (35)-(36) require, together with (38): 'the three offset wheels must be mounted at "
         "the vertices of an equilateral triangle'")

register(
    "38", SECTION, r"\mathbf{d}_i^{\mathrm{T}}\mathbf{d}_i = L^2, \quad i = 1, 2, 3",
    tuple(sp.Eq((v.T * v)[0], _L**2) for v in _dv),
    note="stated as necessary ('must be mounted at the vertices of an equilateral triangle ... the magnitudes "
         "of the vectors d_i must be identical'); L is 'naturally selected' as that common magnitude")

register(
    "39", SECTION, r"\mathbf{J}_{L1}^{\mathbf{T}}\mathbf{J}_{L1} = 3\begin{bmatrix}1&0&0\\0&1&0\\0&0&1\end{bmatrix}",
    sp.Eq(JL1.T * JL1, 3 * sp.eye(3), evaluate=False),
    note="under (37)-(38)")

register(
    "40", SECTION,
    r"\mathbf{J}_2\mathbf{J}_2^{\mathrm{T}} = \begin{bmatrix} \Upsilon_1 & \mathbf{0}_{2\times2} & \mathbf{0}_{2\times2}\\ "
    r"\mathbf{0}_{2\times2} & \Upsilon_2 & \mathbf{0}_{2\times2}\\ \mathbf{0}_{2\times2} & \mathbf{0}_{2\times2} & \Upsilon_3\end{bmatrix}",
    sp.Eq(J2 * J2.T, sp.BlockDiagMatrix(*Upsilon), evaluate=False),
    note="three offset wheels; Upsilon_i defined by (41)")

register(
    "41", SECTION,
    r"\Upsilon_i \equiv [\mathbf{R}_{bwi}]\,[\tilde{\mathbf{p}}^2]\,[\mathbf{R}_{bwi}]^{\mathrm{T}}",
    sp.Eq(sp.MatrixSymbol(r"\Upsilon_i", 2, 2), _R(beta_i) * ptilde2 * _R(beta_i).T, evaluate=False),
    note="R_bwi transcribed from (11) with the generic angle beta_i; p~^2 is the square of p~ = diag(-d, -r) of (21)")

register(
    "42", SECTION, r"[\tilde{\mathbf{p}}^2] = \begin{bmatrix} -d^2 & 0\\ 0 & -r^2\end{bmatrix}",
    sp.Eq(ptilde2, sp.diag(-_d**2, -_r**2), evaluate=False))

register(
    "43", SECTION,
    r"\Upsilon_i = \begin{bmatrix} r^2\sin^2\beta_i + d^2\cos^2\beta_i & (d^2 - r^2)\sin\beta_i\cos\beta_i\\ "
    r"(d^2 - r^2)\sin\beta_i\cos\beta_i & r^2\cos^2\beta_i + d^2\sin^2\beta_i\end{bmatrix}, \quad i = 1, 2, 3",
    sp.Eq(sp.MatrixSymbol(r"\Upsilon_i", 2, 2), sp.Matrix([
        [_r**2 * sp.sin(beta_i)**2 + _d**2 * sp.cos(beta_i)**2, (_d**2 - _r**2) * sp.sin(beta_i) * sp.cos(beta_i)],
        [(_d**2 - _r**2) * sp.sin(beta_i) * sp.cos(beta_i), _r**2 * sp.cos(beta_i)**2 + _d**2 * sp.sin(beta_i)**2]]),
        evaluate=False))

register(
    "44", SECTION, r"(d^2 - r^2)\sin\beta_i\cos\beta_i = 0",
    sp.Eq((_d**2 - _r**2) * sp.sin(beta_i) * sp.cos(beta_i), 0),
    note="isotropy condition on the off-diagonal entry of (43)")

register(
    "45", SECTION, r"r^2\sin^2\beta_i + d^2\cos^2\beta_i = r^2\cos^2\beta_i + d^2\sin^2\beta_i",
    sp.Eq(_r**2 * sp.sin(beta_i)**2 + _d**2 * sp.cos(beta_i)**2, _r**2 * sp.cos(beta_i)**2 + _d**2 * sp.sin(beta_i)**2),
    note="isotropy condition on the diagonal entries of (43)")

register(
    "46", SECTION, r"d = r", sp.Eq(_d, _r),
    note="the solution of (44)-(45) claimed by the paper ('for J2 to be isotropic')")

register(
    "47", SECTION, r"\Upsilon_i = r^2\begin{bmatrix}1&0\\0&1\end{bmatrix}",
    sp.Eq(sp.MatrixSymbol(r"\Upsilon_i", 2, 2), _r**2 * sp.eye(2), evaluate=False),
    note="under (46)")

register(
    "48", SECTION, r"\mathbf{J}_2\mathbf{J}_2^{\mathrm{T}} = r^2\,\mathbf{1}_{6\times 6}",
    sp.Eq(J2 * J2.T, _r**2 * sp.eye(6), evaluate=False),
    note="under (46); printed as r^2 times the explicit 6 x 6 identity. The text adds: J2 J2^T and J2^T J2 are "
         "identical if d = r")

register(
    "49", SECTION, r"\mathbf{t}_L = \frac{1}{3}\mathbf{J}_{L1}^{\mathrm{T}}\mathbf{J}_2\dot{\boldsymbol{\theta}}",
    sp.Eq(tL, JL1.T * J2 * theta_dot / 3, evaluate=False),
    note="forward kinematics ('the computation of the planar twist reduces to') under (39) and (48)")

register(
    "50", SECTION, r"\dot{\boldsymbol{\theta}} = \frac{1}{r^2}\mathbf{J}_2^{\mathrm{T}}\mathbf{J}_{L1}\mathbf{t}_L",
    sp.Eq(theta_dot, J2.T * JL1 * tL / _r**2, evaluate=False),
    note="inverse kinematics under (39) and (48)")


# --- claims of Section 4.3 ----------------------------------------------------------------------
register_claim(
    "isotropy-placement", SECTION,
    r"For (35) and (36) to be true, the three offset wheels must be mounted at the vertices of an equilateral "
    r"triangle, such that $\sum_i\mathbf d_i = \mathbf 0$ and the magnitudes of the vectors $\mathbf d_i$ are identical.")

register_claim(
    "isotropy-L", SECTION,
    r"The value of $L$ is naturally selected to be the identical magnitude of vectors $\mathbf d_i$, to render "
    r"$\mathbf J_{L1}$ isotropic.")

register_claim(
    "isotropy-d-equals-r", SECTION,
    r"For $\mathbf J_2$ to be isotropic, we then have $d = r$ [...] the products $\mathbf J_2\mathbf J_2^{\mathrm T}$ "
    r"and $\mathbf J_2^{\mathrm T}\mathbf J_2$ are identical if $d = r$.")

register_claim(
    "isotropy-d-zero", "4.3.3",
    r"Isotropy [$d = r$] leads to a maximum drift and a maximum dead zone [...] isotropy is achieved at the expense "
    r"of a large drift, if offset wheels are used.")

register_claim(
    "robust-control", "4.3.3, 5.3.2",
    r"Robustness in the kinematic control can then be achieved if the wheel offset $d$ is equal to the radius $r$ "
    r"of the wheel (Section 4.3.3). With both Jacobian matrices [$\mathbf J_{L1}$, $\mathbf J_2$] isotropic, "
    r"robustness of the kinematic control is ensured (Section 5.3.2, centred wheels).")
