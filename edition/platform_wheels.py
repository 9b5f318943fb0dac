r"""Section 3 as printed: platform kinematics and wheel kinematics, (2)-(19).

Conventions of the transcription
--------------------------------
* Vector identities are stored as ``Eq(lhs, rhs)``.  The left side names the object with a
  :class:`sympy.MatrixSymbol` (e.g. :data:`p_dot_i`); the right side is written with the printed
  symbols.  A notebook derives the left side from the model and compares it with the right side.
* Frame-free vectors of the paper (the wheel axes :math:`\mathbf i_i, \mathbf j_i`) stay
  :class:`~sympy.MatrixSymbol` objects (:data:`i_i`, :data:`j_i`); the notebook substitutes their
  components in whatever frame it derives in.
* Vectors the paper writes in the body frame :math:`\mathcal B` are written in components:
  :math:`\dot{\mathbf c} = [\dot x\ \dot y]^T` (1), :math:`\mathbf d_i = [d_{ix}\ d_{iy}]^T`.
* Every equation "for wheel unit i" is transcribed with generic symbols carrying the index i
  (:data:`beta_i`, :data:`phi_dot_i`, :data:`theta_dot_i`, ...).

Nothing here is derived: these are the statements under test (see
``notebooks/01_platform_and_wheels``).
"""
from __future__ import annotations

import sympy as sp

from . import symbols as S
from . import register

SECTION_PLATFORM = "3.1"
SECTION_WHEEL = "3.2"

# --- generic symbols of wheel unit i ------------------------------------------------------------
#: components of d_i = CP_i in the body frame
d_i = sp.symbols("d_{ix} d_{iy}", real=True)
#: steering angle of the intermediate body relative to the platform, absolute steering angle
beta_i, phi_i = sp.symbols(r"\beta_i \phi_i", real=True)
#: rates of unit i: steering (absolute), rolling, intermediate body relative to the platform
phi_dot_i, theta_dot_i, beta_dot_i = sp.symbols(r"\dot{\phi}_i \dot{\theta}_i \dot{\beta}_i", real=True)
#: dual wheel: rolling rates and angles of wheels i1 and i2, average rolling angle
theta_dot_i1, theta_dot_i2 = sp.symbols(r"\dot{\theta}_{i1} \dot{\theta}_{i2}", real=True)
theta_i, theta_i1, theta_i2 = sp.symbols(r"\theta_i \theta_{i1} \theta_{i2}", real=True)

# --- named objects (left sides) -----------------------------------------------------------------
p_dot_i = sp.MatrixSymbol(r"\dot{\mathbf{p}}_i", 2, 1)             #: velocity of P_i
p_dot_i_B = sp.MatrixSymbol(r"[\dot{\mathbf{p}}_i]_{\mathcal{B}}", 2, 1)  #: the same in body components
h_dot_i = sp.MatrixSymbol(r"\dot{\mathbf{h}}_i", 2, 1)             #: velocity of the wheel centre H_i
h_dot_i1 = sp.MatrixSymbol(r"\dot{\mathbf{h}}_{i1}", 2, 1)         #: dual wheel: velocity of H_i1
h_dot_i2 = sp.MatrixSymbol(r"\dot{\mathbf{h}}_{i2}", 2, 1)         #: dual wheel: velocity of H_i2
i_i = sp.MatrixSymbol(r"\mathbf{i}_i", 2, 1)                       #: axle direction of unit i
j_i = sp.MatrixSymbol(r"\mathbf{j}_i", 2, 1)                       #: rolling direction of unit i
E_sym = sp.MatrixSymbol(r"\mathbf{E}", 2, 2)
R_bwi = sp.MatrixSymbol(r"\mathbf{R}_{bwi}", 2, 2)
t_sym = sp.MatrixSymbol(r"\mathbf{t}", 3, 1)

# --- printed building blocks --------------------------------------------------------------------
E = sp.Matrix([[0, -1], [1, 0]])                                     # (3) as printed
c_dot = sp.Matrix([S.x_dot, S.y_dot])                                # (1): c_dot = x_dot i + y_dot j
d_vec = sp.Matrix(d_i)
ONE = sp.eye(2)


def R(angle):
    r"""The rotation of (11) as printed, :math:`\begin{bmatrix}\cos & -\sin\\ \sin & \cos\end{bmatrix}`.

    Parameters
    ----------
    angle : sympy.Expr or number
        Radians.

    Returns
    -------
    sympy.Matrix (2, 2)

    Examples
    --------
    >>> R(sp.pi / 2)
    Matrix([
    [0, -1],
    [1,  0]])
    """
    return sp.Matrix([[sp.cos(angle), -sp.sin(angle)], [sp.sin(angle), sp.cos(angle)]])


# --- 3.1 platform ---------------------------------------------------------------------------------
register(
    "2", SECTION_PLATFORM,
    r"\dot{\mathbf{p}}_i = \dot{\mathbf{c}} + \dot\psi\,\mathbf{E}\mathbf{d}_i \quad\text{as}\quad "
    r"\dot{\boldsymbol\psi}\times\mathbf{d}_i = \dot\psi\,\mathbf{E}\mathbf{d}_i, \quad i = 1 \text{ to } w",
    sp.Eq(p_dot_i, c_dot + S.psi_dot * E * d_vec, evaluate=False),
    garbled=r"the extraction reads $\dot{\mathbf p}_i = \dot{\mathbf c}_w = \dot{\mathbf c} + \dot\psi\mathbf E\mathbf d_i$ as "
            r"$\dot\psi\times\mathbf d_i = \dots$; $\dot{\mathbf c}_w$ is defined nowhere in the paper and is dropped (a "
            r"mangled middle term); $\dot\psi\times\mathbf d_i$ is read as the angular velocity vector $\dot\psi\mathbf k$ "
            r"crossed with $\mathbf d_i$",
    note="vector identity; transcribed in body-frame components, c_dot = [x_dot, y_dot] by (1)")

register(
    "3", SECTION_PLATFORM, r"\mathbf{E} \equiv \begin{bmatrix} 0 & -1 \\ 1 & 0 \end{bmatrix}",
    sp.Eq(E_sym, E, evaluate=False),
    note="definition: 'a 2 x 2 skew-symmetric matrix rotating vectors in the plane through 90 degrees "
         "counter-clockwise'")

register(
    "4", SECTION_PLATFORM, r"\mathbf{t} = \begin{bmatrix} \dot\psi & \dot{\mathbf{c}}^{\mathrm{T}}\end{bmatrix}^{\mathrm{T}}",
    sp.Eq(t_sym, sp.Matrix([S.psi_dot, S.x_dot, S.y_dot]), evaluate=False),
    note="definition of the planar twist: rotation first, then the 2D velocity of C")

register(
    "5", SECTION_PLATFORM,
    r"[\dot{\mathbf{p}}_i] = [\mathbf{E}\mathbf{d}_i \quad \mathbf{1}]\begin{bmatrix}\dot\psi\\ \dot{\mathbf{c}}\end{bmatrix}",
    sp.Eq(p_dot_i, sp.Matrix.hstack(E * d_vec, ONE) * sp.Matrix([S.psi_dot, S.x_dot, S.y_dot]), evaluate=False),
    note="(2) rearranged; 1 is the 2 x 2 identity",
    matrix=sp.Matrix.hstack(E * d_vec, ONE))

# --- 3.2 wheel kinematics -------------------------------------------------------------------------
register(
    "6", SECTION_WHEEL, r"\dot{\mathbf{h}}_i = -r\dot\theta_i\,\mathbf{j}_i",
    sp.Eq(h_dot_i, -S.r * theta_dot_i * j_i, evaluate=False),
    note="no-slip condition of a thin disk of radius r rolling on a plane (disk plane vertical); "
         "i_i along the axle, j_i normal to i_i in the disk plane, k upward")

register(
    "7", SECTION_WHEEL, r"\dot\phi_i = \dot\psi + \dot\beta_i",
    sp.Eq(phi_dot_i, S.psi_dot + beta_dot_i),
    note="beta_dot_i is the angular velocity of the intermediate body relative to the platform")

register(
    "8", SECTION_WHEEL, r"\phi_i = \psi + \beta_i",
    sp.Eq(phi_i, S.psi + beta_i),
    note="(7) integrated; the paper adds 'in which psi and beta_i are both zero if phi_i = 0' "
         "(meant: the integration constant is zero, phi_i = 0 when psi = beta_i = 0)")

register(
    "9", SECTION_WHEEL, r"\dot{\mathbf{p}}_i = -r\dot\theta_i\,\mathbf{j}_i - d\dot\phi_i\,\mathbf{i}_i",
    sp.Eq(p_dot_i, -S.r * theta_dot_i * j_i - S.d * phi_dot_i * i_i, evaluate=False),
    note="velocity of the steering-axis point P_i of an offset wheel (wheel centre at distance d from the "
         "steering axis); the side of the offset is not stated in the text (Fig. 4 is missing)")

register(
    "10", SECTION_WHEEL,
    r"[\dot{\mathbf{p}}_i]_{\mathcal{B}} = [\mathbf{R}_{bwi}][\dot{\mathbf{p}}_i] = "
    r"[\mathbf{R}_{bwi}]\begin{bmatrix} -d\dot\phi_i \\ -r\dot\theta_i\end{bmatrix}",
    sp.Eq(p_dot_i_B, R(beta_i) * sp.Matrix([-S.d * phi_dot_i, -S.r * theta_dot_i]), evaluate=False),
    note="[p_dot_i] without subscript = components in the wheel frame W_i (along i_i, j_i); R_bwi from (11)")

register(
    "11", SECTION_WHEEL,
    r"[\mathbf{R}_{bwi}] \equiv \begin{bmatrix} \cos\beta_i & -\sin\beta_i \\ \sin\beta_i & \cos\beta_i\end{bmatrix}",
    sp.Eq(R_bwi, R(beta_i), evaluate=False),
    note="'the rotation matrix from the wheel frame to the body-attached frame'")

register(
    "12", SECTION_WHEEL,
    r"[\dot{\mathbf{p}}_i]_{\mathcal{B}} = [\mathbf{R}_{bwi}][\dot{\mathbf{p}}_i] = "
    r"[\mathbf{R}_{bwi}]\begin{bmatrix} 0 \\ -r\dot\theta_i\end{bmatrix}",
    sp.Eq(p_dot_i_B, R(beta_i) * sp.Matrix([0, -S.r * theta_dot_i]), evaluate=False),
    note="(10) with offset d = 0: the centred wheel")

register(
    "13", SECTION_WHEEL, r"\dot{\mathbf{h}}_{i1} = -r\dot\theta_{i1}\,\mathbf{j}_i",
    sp.Eq(h_dot_i1, -S.r * theta_dot_i1 * j_i, evaluate=False),
    garbled=r"the extraction prints a dotted $\dot{\mathbf j}_i$; read as the unit vector $\mathbf j_i$, as in "
            r"(14) and (17) (a derivative of $\mathbf j_i$ has no place in a no-slip condition)",
    note="dual wheel, wheel 1")

register(
    "14", SECTION_WHEEL, r"\dot{\mathbf{h}}_{i2} = -r\dot\theta_{i2}\,\mathbf{j}_i",
    sp.Eq(h_dot_i2, -S.r * theta_dot_i2 * j_i, evaluate=False),
    note="dual wheel, wheel 2")

register(
    "15", SECTION_WHEEL, r"\dot\beta_i = -\frac{r}{2b}\left(\dot\theta_{i1} - \dot\theta_{i2}\right)",
    sp.Eq(beta_dot_i, -S.r / (2 * S.b) * (theta_dot_i1 - theta_dot_i2)),
    garbled=r"the extraction prints $2h$ in the denominator; read as $2b$ ($b$ = one-half the wheel separation, "
            r"the nomenclature and (16))",
    note="third no-slip constraint of the dual wheel; wheels 'mounted symmetrically about the center of the "
         "intermediate body at a distance b'")

register(
    "16", SECTION_WHEEL, r"\beta_i = -\frac{r}{2b}\left(\theta_{i1} - \theta_{i2}\right)",
    sp.Eq(beta_i, -S.r / (2 * S.b) * (theta_i1 - theta_i2)),
    note="(15) integrated, 'where theta_i1 and theta_i2 are both zero if beta_i = 0'")

register(
    "17", SECTION_WHEEL,
    r"\dot{\mathbf{h}}_i \equiv \tfrac12(\dot{\mathbf{h}}_{i1} + \dot{\mathbf{h}}_{i2}) = "
    r"-\frac{r}{2}(\dot\theta_{i1} + \dot\theta_{i2})\,\mathbf{j}_i = -r\dot\theta_i\,\mathbf{j}_i",
    sp.Eq(h_dot_i, -S.r / 2 * (theta_dot_i1 + theta_dot_i2) * j_i, evaluate=False),
    note="average velocity of the two wheel centres; expr holds the middle equality, the chain's ends are in "
         "extra (definition, average_form)",
    definition=(h_dot_i1 + h_dot_i2) / 2,
    average_form=-S.r * theta_dot_i * j_i)

register(
    "18", SECTION_WHEEL, r"\dot\theta_i \equiv \tfrac12(\dot\theta_{i1} + \dot\theta_{i2})",
    sp.Eq(theta_dot_i, (theta_dot_i1 + theta_dot_i2) / 2),
    note="definition of the average rolling rate")

register(
    "19", SECTION_WHEEL, r"\theta_i = \tfrac12(\theta_{i1} + \theta_{i2})",
    sp.Eq(theta_i, (theta_i1 + theta_i2) / 2),
    note="(18) integrated, 'in which theta_i1 and theta_i2 are both zero if theta_i = 0'")
