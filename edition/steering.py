r"""Equations (60)-(65) as printed: steering of a WMR with three centred wheels (Section 5.4).

Symbols not in :mod:`edition.symbols` are defined here: the absolute steering angle
:math:`\phi_i` of a generic wheel, the position vectors :math:`\mathbf u` (of the instantaneous
centre U) and :math:`\mathbf c` (of the operation point C), :math:`\mathbf u_c =
\overrightarrow{CU}`, :math:`\mathbf u_i = \overrightarrow{P_iU}` and a generic mount vector
:math:`\mathbf d_i = (d_x, d_y)`.  Vectors are 2 x 1 SymPy matrices.

Equations (61)-(64) are vector identities; their ``expr`` is the printed right-hand side and
``extra["lhs"]`` the printed left-hand side.  (60) and (65) are scalar equations (``sympy.Eq``).
"""
import sympy as sp

from . import symbols as S
from . import register

#: Absolute steering angle of a generic wheel i (8): phi_i = psi + beta_i.
phi_i = sp.Symbol(r"\phi_i", real=True)
#: Steering angle of the intermediate body of a generic wheel i.
beta_i = sp.Symbol(r"\beta_i", real=True)
#: Position vectors of U and C in the fixed frame.
u = sp.Matrix(sp.symbols("u_X u_Y", real=True))
c = sp.Matrix(sp.symbols("c_X c_Y", real=True))
#: u_c = CU and u_i = P_i U (components in one frame).
u_c = sp.Matrix(sp.symbols("u_{cx} u_{cy}", real=True))
u_i = sp.Matrix(sp.symbols("u_{ix} u_{iy}", real=True))
#: Velocity of C and generic mount vector d_i (same frame as u_c).
c_dot = sp.Matrix([S.x_dot, S.y_dot])
d_i = sp.Matrix([S.dx, S.dy])
#: Velocity of U (the printed left-hand side of (62)).
u_dot = sp.Matrix(sp.symbols(r"\dot{u}_x \dot{u}_y", real=True))

register(
    "60", "5.4.1",
    r"\phi_i = \tan^{-1}\left(\frac{\dot Y}{\dot X}\right), \quad i = 1, 2, 3",
    sp.Eq(phi_i, sp.atan(S.Y_dot / S.X_dot)),
    note="Steering angles in translation; Xdot, Ydot are the fixed-frame components of c_dot (1).",
)

register(
    "61", "5.4.2",
    r"\mathbf u - \mathbf c = \mathbf u_c",
    u - c,
    note="Definition of u_c = CU; expr is the left-hand side u - c, extra['lhs'] the defined symbol u_c.",
    lhs=u_c,
)

register(
    "62", "5.4.2",
    r"\dot{\mathbf u} = \dot{\mathbf c} + \dot\psi\,\mathbf E\,\mathbf u_c",
    c_dot + S.psi_dot * S.E * u_c,
    note="'The velocity of U'; expr is the right-hand side.",
    lhs=u_dot,
)

register(
    "63", "5.4.2",
    r"\mathbf u_c = \frac{1}{\dot\psi}\,\mathbf E\,\dot{\mathbf c}",
    S.E * c_dot / S.psi_dot,
    note="Instantaneous centre from u_dot = 0; expr is the right-hand side.",
    lhs=u_c,
)

register(
    "64", "5.4.2",
    r"\mathbf u_i = \frac{1}{\dot\psi}\,\mathbf E\,\dot{\mathbf c} - \mathbf d_i",
    S.E * c_dot / S.psi_dot - d_i,
    note="Vector P_i U for psi_dot != 0; expr is the right-hand side.",
    lhs=u_i,
)

register(
    "65", "5.4.2",
    r"\cos\beta_i = \frac{\mathbf u_c^{\mathrm T}\mathbf u_i}{\|\mathbf u_c\|\,\|\mathbf u_i\|}",
    sp.Eq(sp.cos(beta_i), (u_c.T * u_i)[0] / (u_c.norm() * u_i.norm())),
    note="Steering angle of wheel i in rotation about U.",
)
