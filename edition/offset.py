r"""Sections 4.1-4.2 as printed: the WMR with offset wheels, its kinematics and mobility, (20)-(29).

Conventions of the transcription
--------------------------------
* As in :mod:`edition.platform_wheels`: identities are ``Eq(lhs, rhs)``, model objects on the left are
  :class:`sympy.MatrixSymbol` objects (:data:`J1`, :data:`J2`, :data:`F`, ...), right sides use the
  printed symbols.
* (20) holds "for i = 1, ..., w"; it is transcribed for one unit with the generic symbols of
  :mod:`edition.platform_wheels` (:data:`~edition.platform_wheels.beta_i`, ...).
* The matrices of (21)-(25) are printed for a general number w of wheels; they are transcribed for
  w = 3 (the robot of Section 4.2) with general mount points :data:`D` = ((d_1x, d_1y), ..., (d_3x, d_3y)),
  steering angles :data:`edition.symbols.beta` and rates :data:`edition.symbols.phi_dot`,
  :data:`edition.symbols.theta_dot`.  :func:`J1_printed` and friends build the printed pattern for any w.
* (29) divides a vector by a vector, which is not an operation; it is stored term by term in ``extra``
  (``expr`` is ``None``).

Nothing here is derived: these are the statements under test (see
``notebooks/02_offset_wheels_and_mobility``).
"""
from __future__ import annotations

import sympy as sp

from . import symbols as S
from . import register, register_claim
from .platform_wheels import E, ONE, R, beta_i, d_i, phi_dot_i, theta_dot_i

SECTION_KIN = "4.1"
SECTION_MOB = "4.2"

#: general mount points d_k = CP_k, body frame (k = 1, 2, 3)
D = tuple(sp.symbols(f"d_{{{k}x}} d_{{{k}y}}", real=True) for k in (1, 2, 3))
#: a symbol for the number of wheels, used in the printed dimensions
w_sym = sp.Symbol("w", positive=True, integer=True)

J1 = sp.MatrixSymbol(r"\mathbf{J}_1", 6, 3)
J2 = sp.MatrixSymbol(r"\mathbf{J}_2", 6, 6)
F = sp.MatrixSymbol(r"\mathbf{F}", 6, 9)
t = sp.MatrixSymbol(r"\mathbf{t}", 3, 1)
theta_dot = sp.MatrixSymbol(r"\dot{\boldsymbol{\theta}}", 6, 1)
q_dot = sp.MatrixSymbol(r"\dot{\mathbf{q}}", 9, 1)
nu = sp.Symbol(r"\nu", integer=True, nonnegative=True)

T_EXPLICIT = sp.Matrix([S.psi_dot, S.x_dot, S.y_dot])        # t = [psi_dot, c_dot^T]^T, c_dot = [x_dot, y_dot]
p_tilde = sp.diag(-S.d, -S.r)                                # p~ of (21) as printed


def J1_printed(points):
    r"""Printed :math:`\mathbf J_1` of (21): block rows :math:`[\mathbf E\mathbf d_k\ \ \mathbf 1]` for the given mount points.

    Parameters
    ----------
    points : sequence of w pairs
        Mount points :math:`\mathbf d_k` (numbers or SymPy expressions).

    Returns
    -------
    sympy.Matrix (2w, 3)

    Examples
    --------
    >>> J1_printed([(1, 0)])
    Matrix([
    [0, 1, 0],
    [1, 0, 1]])
    """
    return sp.Matrix.vstack(*[sp.Matrix.hstack(E * sp.Matrix(p), ONE) for p in points])


def J2_printed(betas):
    r"""Printed :math:`\mathbf J_2` of (21): :math:`\operatorname{blockdiag}(\mathbf R_{bwk}\tilde{\mathbf p})`, with the printed :math:`\tilde{\mathbf p}`.

    Parameters
    ----------
    betas : sequence of w angles
        Steering angles :math:`\beta_k` (SymPy symbols or numbers).

    Returns
    -------
    sympy.Matrix (2w, 2w)
    """
    return sp.diag(*[R(b) * p_tilde for b in betas])


def theta_dot_printed(w):
    r"""The joint-rate vector of (21) as reconstructed: :math:`[\dot\phi_1\ \dot\theta_1\ \dots\ \dot\phi_w\ \dot\theta_w]^T`.

    Parameters
    ----------
    w : int
        Number of wheel units.

    Returns
    -------
    sympy.Matrix (2w, 1)
    """
    syms = []
    for k in range(1, w + 1):
        syms += sp.symbols(rf"\dot{{\phi}}_{{{k}}} \dot{{\theta}}_{{{k}}}", real=True)
    return sp.Matrix(syms)


def F_printed(points, betas):
    r"""Printed :math:`\mathbf F` of (24): :math:`[\mathbf J_1\ \ -\mathbf J_2]` for the given mount points and steering angles.

    Parameters
    ----------
    points : sequence of w pairs
        Mount points (as for :func:`J1_printed`).
    betas : sequence of w angles
        Steering angles (as for :func:`J2_printed`).

    Returns
    -------
    sympy.Matrix (2w, 3 + 2w)
    """
    return sp.Matrix.hstack(J1_printed(points), -J2_printed(betas))


def q_dot_printed(w):
    r"""Printed :math:`\dot{\mathbf q}` of (25): :math:`[\dot\psi\ \dot x\ \dot y\ \dot\phi_1\ \dot\theta_1\ \dots\ \dot\phi_w\ \dot\theta_w]^T`.

    Parameters
    ----------
    w : int
        Number of wheel units.

    Returns
    -------
    sympy.Matrix (3 + 2w, 1)
    """
    return sp.Matrix.vstack(T_EXPLICIT, theta_dot_printed(w))


_J1_3 = J1_printed(D)
_J2_3 = J2_printed(S.beta)
_th_3 = theta_dot_printed(3)

register(
    "20", SECTION_KIN,
    r"[\mathbf{E}\mathbf{d}_i \quad \mathbf{1}]\begin{bmatrix}\dot\psi\\ \dot{\mathbf{c}}\end{bmatrix} = "
    r"[\dot{\mathbf{p}}_i]_{\mathcal{B}} = [\mathbf{R}_{bwi}][\dot{\mathbf{p}}_i] = "
    r"[\mathbf{R}_{bwi}]\begin{bmatrix}-d\dot\phi_i\\ -r\dot\theta_i\end{bmatrix}",
    sp.Eq(sp.Matrix.hstack(E * sp.Matrix(d_i), ONE) * T_EXPLICIT,
          R(beta_i) * sp.Matrix([-S.d * phi_dot_i, -S.r * theta_dot_i]), evaluate=False),
    note="(5) equated with (10) for one unit; the middle terms are (10)'s")

register(
    "21", SECTION_KIN,
    # one line of print, three here: the display is broken by hand so that it keeps its size
    r"\begin{aligned}&\mathbf{J}_1\mathbf{t} = \mathbf{J}_2\dot{\boldsymbol\theta},\quad "
    r"\mathbf{J}_1 = \begin{bmatrix}\mathbf{E}\mathbf{d}_1 & \mathbf{1}\\ \mathbf{E}\mathbf{d}_2 & \mathbf{1}\\ "
    r"\vdots & \vdots\\ \mathbf{E}\mathbf{d}_w & \mathbf{1}\end{bmatrix},\quad "
    r"\mathbf{t} = \begin{bmatrix}\dot\psi\\ \dot{\mathbf{c}}\end{bmatrix},\\[4pt] "
    r"&\dot{\boldsymbol\theta} = \begin{bmatrix}\dot\phi_1 & \dot\theta_1 & \dot\phi_2 & \dot\theta_2 & \dots & "
    r"\dot\phi_w & \dot\theta_w\end{bmatrix}^{\mathrm{T}},\\[4pt] "
    r"&\mathbf{J}_2 = \begin{bmatrix}\mathbf{R}_{bw1}\tilde{\mathbf{p}} & \mathbf{0} & \dots & \mathbf{0}\\ "
    r"\mathbf{0} & \mathbf{R}_{bw2}\tilde{\mathbf{p}} & \dots & \mathbf{0}\\ \vdots & \vdots & \ddots & \vdots\\ "
    r"\mathbf{0} & \mathbf{0} & \dots & \mathbf{R}_{bww}\tilde{\mathbf{p}}\end{bmatrix},\quad "
    r"\tilde{\mathbf{p}} = \begin{bmatrix}-d & 0\\ 0 & -r\end{bmatrix}\end{aligned}",
    sp.Eq(_J1_3 * T_EXPLICIT, _J2_3 * _th_3, evaluate=False),
    garbled=r"the rate vector is extracted as $[\dot\phi_1\ \dot\phi_2\ \dot\phi_2 \dots \dot\phi_w\ \dot\theta_w]^{\mathrm T}$; "
            r"reconstructed as $[\dot\phi_1\ \dot\theta_1\ \dot\phi_2\ \dot\theta_2 \dots \dot\phi_w\ \dot\theta_w]^{\mathrm T}$, "
            r"the layout of (25) and the only one that matches the blocks $\mathbf R_{bwi}\tilde{\mathbf p}$ acting on "
            r"$[\dot\phi_i\ \dot\theta_i]^{\mathrm T}$ in (20); the vertical dots of $\mathbf J_1$ are extracted as 'drawnowsigned'",
    note="transcribed for w = 3 with general mount points D; the text adds: J1 is 2w x 3, J2 is 2w x 2w, "
         "t and theta_dot are 3D and 2w-D",
    J1=_J1_3, J2=_J2_3, t=T_EXPLICIT, theta_dot=_th_3,
    dims={"J1": (2 * w_sym, 3), "J2": (2 * w_sym, 2 * w_sym), "t": 3, "theta_dot": 2 * w_sym})

register(
    "22", SECTION_MOB,
    r"[\mathbf{J}_1 \quad -\mathbf{J}_2]\begin{bmatrix}\mathbf{t}\\ \dot{\boldsymbol\theta}\end{bmatrix} = \mathbf{0}"
    r"\quad\text{where } \mathbf{0} \text{ denotes the } (3+2w)\text{-D zero vector}",
    sp.Eq(sp.Matrix.hstack(_J1_3, -_J2_3) * sp.Matrix.vstack(T_EXPLICIT, _th_3), sp.zeros(6, 1), evaluate=False),
    note="transcribed for w = 3; the printed size of the zero vector is in extra['zero_dim']",
    zero_dim=3 + 2 * w_sym)

register(
    "23", SECTION_MOB, r"\mathbf{F}\dot{\mathbf{q}} = \mathbf{0}",
    sp.Eq(F * q_dot, sp.ZeroMatrix(6, 1), evaluate=False),
    note="(22) in compact form (shapes for w = 3)")

register(
    "24", SECTION_MOB,
    r"\mathbf{F} = \begin{bmatrix}\mathbf{E}\mathbf{d}_1 & \mathbf{1} & -\mathbf{R}_{bw1}\tilde{\mathbf{p}} & "
    r"\mathbf{0} & \dots & \mathbf{0}\\ \mathbf{E}\mathbf{d}_2 & \mathbf{1} & \mathbf{0} & "
    r"-\mathbf{R}_{bw2}\tilde{\mathbf{p}} & \dots & \mathbf{0}\\ \vdots & \vdots & \vdots & \vdots & \ddots & \vdots\\ "
    r"\mathbf{E}\mathbf{d}_w & \mathbf{1} & \mathbf{0} & \mathbf{0} & \dots & -\mathbf{R}_{bww}\tilde{\mathbf{p}}"
    r"\end{bmatrix}",
    sp.Eq(F, F_printed(D, S.beta), evaluate=False),
    note="'the 2w x (3+2w) functional matrix'; transcribed for w = 3",
    dims=(2 * w_sym, 3 + 2 * w_sym))

register(
    "25", SECTION_MOB,
    r"\dot{\mathbf{q}} \equiv \begin{bmatrix}\dot\psi & \dot x & \dot y & \dot\phi_1 & \dot\theta_1 & "
    r"\dot\phi_2 & \dot\theta_2 & \dots & \dot\phi_w & \dot\theta_w\end{bmatrix}^{\mathrm{T}}",
    sp.Eq(q_dot, q_dot_printed(3), evaluate=False),
    note="definition of the generalised rates; transcribed for w = 3")

register(
    "26", SECTION_MOB, r"\dot{\mathbf{q}} \in \mathcal{N}(\mathbf{F})",
    None,
    note="set membership, equivalent to (23); checked through a basis of the null space")

register(
    "27", SECTION_MOB, r"\nu = \dim(\mathcal{N}(\mathbf{F}))",
    sp.Eq(nu, sp.Symbol(r"\dim\mathcal{N}(\mathbf{F})")),
    note="definition of the nullity (the mobility). The text then claims: for three offset wheels q_dot is 9D, "
         "rank F = 6, nu(F) = 3, full mobility, omnidirectional (extra['claim'])",
    claim={"q_dim": 9, "rank_F": 6, "nullity": 3})

_R3 = [R(b) for b in S.beta]
_drift_terms = [Rk * sp.Matrix([-pd, 0]) for Rk, pd in zip(_R3, S.phi_dot)]

register(
    "28", SECTION_MOB,
    r"\dot{\mathbf{c}} = \frac{d}{3}\sum_{i=1}^{3}\left([\mathbf{R}_{bwi}]\begin{bmatrix}-\dot\phi_i\\ 0\end{bmatrix}\right)",
    sp.Eq(sp.MatrixSymbol(r"\dot{\mathbf{c}}", 2, 1), S.d / 3 * (_drift_terms[0] + _drift_terms[1] + _drift_terms[2]),
          evaluate=False),
    note="'if the driving actuators are locked, i.e. theta_dot_i = 0 for i = 1, 2, 3 ... the summation of (20) "
         "for i = 1, 2, 3 becomes'; c_dot in body components")

register(
    "29", SECTION_MOB,
    r"\dot\psi = \frac{d}{3}\sum_{i=1}^{3}\frac{\left([\mathbf{R}_{bwi}]\begin{bmatrix}-\dot\phi_i\\ 0\end{bmatrix}\right)}"
    r"{\mathbf{d}_i}",
    None,
    note="'Upon multiplying both sides of (20) with c_dot^T E to eliminate theta_dot_i, we obtain'. The right side "
         "divides the 2-vector R_bwi [-phi_dot_i, 0]^T by the 2-vector d_i, which is not defined; stored term by "
         "term: psi_dot = (d/3) sum_i numerators[i] / divisors[i]",
    numerators=tuple(_drift_terms), divisors=tuple(sp.Matrix(p) for p in D))


# --- claims of Section 4.2 ----------------------------------------------------------------------
register_claim(
    "mobility-offset", SECTION_MOB,
    r"For a WMR with three active offset wheels, vector $\dot{\mathbf q}$ is 9D and the rank of matrix "
    r"$\mathbf F$ is 6; thus $\nu(\mathbf F) = 3$ [...] the WMR at hand has full mobility and the WMR is "
    r"omni-directional.")

register_claim(
    "drift", SECTION_MOB,
    r"Equations (28) and (29) reveal a drift whenever the WMR is steered without driving "
    r"[$\dot\theta_i = 0$, $i = 1, 2, 3$].")

register_claim(
    "dead-zone", SECTION_MOB,
    r"When all the wheels are steered one full turn without driving, point $C$ will trace a circle whose radius "
    r"equals the distance between point $C$ and point $C_f$, the centroid of the triangle whose vertices are the "
    r"points of contact [...] $C_f$ remains fixed during steering. This distance $d$ is the offset of the wheel.")
