r"""Section 5 as printed: WMR with centred wheels, (51)-(59), and the list of singular configurations.

Conventions of the transcription are those of :mod:`edition.isotropy`: matrix identities are
``Eq(lhs, rhs)`` with the model objects named by :class:`sympy.MatrixSymbol`; general mount points
are the symbols :data:`D`; (51) is transcribed for one wheel with generic symbols.  The steering
angles :math:`\beta_1..\beta_3` are :data:`edition.symbols.beta` (the same symbols as
:attr:`wmr.Robot.beta_symbols`).

Nothing here is derived: these are the statements under test (see
``notebooks/04_centred_wheels_and_singularities``).
"""
from __future__ import annotations

import sympy as sp

from . import symbols as S
from . import register, register_claim
from .isotropy import D

SECTION_KIN, SECTION_MOB, SECTION_ISO = "5.1", "5.2", "5.3"

#: generic wheel i of (51)
d_i = sp.symbols(r"d_{ix} d_{iy}", real=True)
beta_i = sp.Symbol(r"\beta_i", real=True)
theta_dot_i = sp.Symbol(r"\dot{\theta}_i", real=True)

#: model objects named as in the paper (three centred wheels: J2 is 6 x 3, J is 3 x 3)
JL1 = sp.MatrixSymbol(r"\mathbf{J}_{L1}", 6, 3)
J2 = sp.MatrixSymbol(r"\mathbf{J}_{2}", 6, 3)
J = sp.MatrixSymbol(r"\mathbf{J}", 3, 3)
tL = sp.MatrixSymbol(r"\mathbf{t}_{L}", 3, 1)
theta_dot = sp.MatrixSymbol(r"\dot{\boldsymbol{\theta}}", 3, 1)
F = sp.MatrixSymbol(r"\mathbf{F}", 6, 6)
q_dot = sp.MatrixSymbol(r"\dot{\mathbf{q}}", 6, 1)
det_J = sp.Symbol(r"\det(\mathbf{J})")

_E = sp.Matrix([[0, -1], [1, 0]])
_I2 = sp.eye(2)
_r = S.r
b1, b2, b3 = S.beta


def _R(angle):
    # (11) as printed
    return sp.Matrix([[sp.cos(angle), -sp.sin(angle)], [sp.sin(angle), sp.cos(angle)]])


register(
    "51", SECTION_KIN,
    r"[\mathbf{E}\mathbf{d}_i\quad \mathbf{1}]\begin{bmatrix}\dot\psi\\ \dot{\mathbf{c}}\end{bmatrix} = "
    r"[\mathbf{R}_{bwi}]\begin{bmatrix}0\\ -r\dot\theta_i\end{bmatrix}",
    sp.Eq(sp.Matrix.hstack(_E * sp.Matrix(d_i), _I2) * sp.Matrix([S.psi_dot, S.x_dot, S.y_dot]),
          _R(beta_i) * sp.Matrix([0, -_r * theta_dot_i]), evaluate=False),
    note="one wheel, generic symbols; followed (unnumbered) by J1 (as in (21)) and the block-diagonal J2 with "
         "blocks R_bwi [0, -r]^T, stored in extra['J2'] for w = 3",
    J2=sp.diag(*[_R(b) * sp.Matrix([0, -_r]) for b in S.beta]))

register(
    "52", SECTION_MOB,
    r"\mathbf{F} \equiv \begin{bmatrix} \mathbf{E}\mathbf{d}_1 & \mathbf{1} & [\mathbf{R}_{bw1}]\begin{bmatrix}0\\ r\end{bmatrix} & \mathbf{0} & \mathbf{0}\\ "
    r"\mathbf{E}\mathbf{d}_2 & \mathbf{1} & \mathbf{0} & [\mathbf{R}_{bw2}]\begin{bmatrix}0\\ r\end{bmatrix} & \mathbf{0}\\ "
    r"\mathbf{E}\mathbf{d}_3 & \mathbf{1} & \mathbf{0} & \mathbf{0} & [\mathbf{R}_{bw3}]\begin{bmatrix}0\\ r\end{bmatrix}\end{bmatrix}",
    sp.Eq(F, sp.Matrix.hstack(
        sp.Matrix.vstack(*[sp.Matrix.hstack(_E * sp.Matrix(p), _I2) for p in D]),
        sp.diag(*[_R(b) * sp.Matrix([0, _r]) for b in S.beta])), evaluate=False),
    garbled=r"the third block row prints a plain $1$ for the $2\times2$ identity $\mathbf 1$",
    note="three centred wheels, general mount points D; note the sign +r")

register(
    "53", SECTION_MOB,
    r"\dot{\mathbf{q}} \equiv \begin{bmatrix}\dot\psi & \dot x & \dot y & \dot\theta_1 & \dot\theta_2 & \dot\theta_3\end{bmatrix}^{\mathrm{T}}",
    sp.Eq(q_dot, sp.Matrix([S.psi_dot, S.x_dot, S.y_dot, *S.theta_dot]), evaluate=False),
    garbled=r"the text before it says $\mathbf q$ for $\dot{\mathbf q}$",
    note="definition: the column order of F in (52)")

register(
    "54", SECTION_ISO, r"\mathbf{J}_2^{\mathrm{T}}\mathbf{J}_2 = r^2\begin{bmatrix}1&0&0\\0&1&0\\0&0&1\end{bmatrix}",
    sp.Eq(J2.T * J2, _r**2 * sp.eye(3), evaluate=False))

register(
    "55", SECTION_ISO, r"\mathbf{t}_L = \frac{1}{3}\mathbf{J}\dot{\boldsymbol{\theta}}",
    sp.Eq(tL, J * theta_dot / 3, evaluate=False),
    note="forward kinematics with both Jacobians isotropic ('robustness of the kinematic control is ensured')")

register(
    "56", SECTION_ISO, r"\mathbf{J} \equiv \mathbf{J}_{L1}^{\mathrm{T}}\mathbf{J}_2",
    sp.Eq(J, JL1.T * J2, evaluate=False), note="definition (3 x 3 for three centred wheels)")

register(
    "57", SECTION_ISO, r"\dot{\boldsymbol{\theta}} = \frac{1}{r^2}\mathbf{J}^{\mathrm{T}}\mathbf{t}_L",
    sp.Eq(theta_dot, J.T * tL / _r**2, evaluate=False), note="inverse kinematics")

register(
    "58", SECTION_ISO, r"\det(\mathbf{J}) = 0",
    sp.Eq(sp.Determinant(J), 0),
    note="definition of the singular configurations: the angles beta_i that solve it")

_s3 = sp.sqrt(3)
#: the printed (59) as terms (coefficient, function, signs of beta_1, beta_2, beta_3): the SymPy form and its
#: LaTeX are both built from this one list (:func:`det_J_59`, :func:`det_J_59_latex`)
TERMS_59 = ((-_s3 / 2, sp.cos, (1, -1, -1)), (sp.Rational(3, 4), sp.sin, (1, -1, 1)),
            (-sp.Rational(3, 4), sp.sin, (1, 1, -1)), (_s3 / 4, sp.cos, (1, 1, -1)), (_s3 / 4, sp.cos, (1, -1, 1)))


def det_J_59(terms=TERMS_59):
    """The right side of (59) as printed, from its terms.

    Parameters
    ----------
    terms : sequence of (coefficient, function, signs)
        Default :data:`TERMS_59`.

    Returns
    -------
    sympy.Expr
        In :data:`edition.symbols.beta`.
    """
    return sum(c * f(sum(sg * b for sg, b in zip(signs, S.beta))) for c, f, signs in terms)


def det_J_59_latex(lhs=r"\det(\mathbf{J})", factor="", per_line=3, terms=TERMS_59):
    r"""LaTeX of (59) from its terms, broken by hand into lines of ``per_line`` terms (``aligned``).

    Parameters
    ----------
    lhs : str
        LaTeX of the left side.
    factor : str, optional
        A factor of the whole right side, e.g. ``"r^3"`` (then the terms are in ``\Big( \Big)``).
    per_line : int
        Terms per line.
    terms : sequence of (coefficient, function, signs)
        Default :data:`TERMS_59`.

    Returns
    -------
    str
        A LaTeX body (no ``$``).
    """
    parts = []
    for k, (c, f, signs) in enumerate(terms):
        arg = "".join(("" if j == 0 and sg > 0 else ("+" if sg > 0 else "-")) + rf"\beta_{j + 1}" for j, sg in enumerate(signs))
        sign = "-" if c < 0 else ("+" if k else "")
        parts.append(rf"{sign} {sp.latex(abs(c))}\{f.__name__}({arg})".strip())
    lines = [" ".join(parts[i:i + per_line]) for i in range(0, len(parts), per_line)]
    open_, close = (rf"{factor}\Big(", r"\Big)") if factor else ("", "")
    return (r"\begin{aligned}" + lhs + " = " + open_ + "&" + r"\\ &".join(lines) + close + r"\end{aligned}")


register(
    "59", SECTION_ISO,
    det_J_59_latex(),
    sp.Eq(det_J, det_J_59()),
    note="computed with Maple in the paper, for the three-wheel robot of Section 5 (placement and numbering not "
         "stated). Followed by the list of zeros in extra['singular']; (v) is a geometric statement (None)",
    singular={
        "i": r"\beta_1 = \beta_2 = \beta_3",
        "ii": r"\beta_1 = \beta_3 = 60^\circ \text{ or } -120^\circ",
        "iii": r"\beta_1 = \beta_2 = -60^\circ \text{ or } 120^\circ",
        "iv": r"\beta_2 = \beta_3 = 0^\circ \text{ or } 180^\circ",
        "v": r"\text{planes of all three wheels intersect}",
    },
    singular_sets={                       # (pair of equal angles, the printed values in degrees)
        "ii": ((1, 3), (60, -120)),
        "iii": ((1, 2), (-60, 120)),
        "iv": ((2, 3), (0, 180)),
    })


# --- claims of Sections 5.2-5.3 -----------------------------------------------------------------
register_claim(
    "mobility-centred", SECTION_MOB,
    r"The rank of the functional matrix $\mathbf F$ is 5 when the WMR is in translation or in rotation. The "
    r"resulting mobility of this WMR is unity [...] provided these angles satisfy the coordination condition "
    r"[the wheel axes converge to a single point, possibly at infinity].")

register_claim(
    "singular-list-complete", SECTION_ISO,
    r"$\det(\mathbf J)$ vanishes for the following configurations: (i) $\beta_1 = \beta_2 = \beta_3$; "
    r"(ii) $\beta_1 = \beta_3 = 60^\circ$ or $-120^\circ$; (iii) $\beta_1 = \beta_2 = -60^\circ$ or $120^\circ$; "
    r"(iv) $\beta_2 = \beta_3 = 0^\circ$ or $180^\circ$; and (v) planes of all three wheels intersect.")

register_claim(
    "singular-v-immobile", SECTION_ISO,
    r"[In (v)] the planes of all three wheels intersect at a single point $D_P$ [...] The axles of the three wheels "
    r"intersect at three different locations. Under this condition, the WMR has lost all its mobility.")
