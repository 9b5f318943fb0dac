r"""The paper's symbols, defined once for the derivations (SymPy).

Names follow the paper's nomenclature; every symbol is real, lengths are positive.
The steering angles are the same symbols as :attr:`wmr.Robot.beta_symbols`.
"""
import sympy as sp

from wmr.model.backend import SYMBOLIC
from wmr.model.platform import E as _E

psi = sp.Symbol(r"\psi", real=True)                          #: platform orientation
psi_dot, x_dot, y_dot = sp.symbols(r"\dot{\psi} \dot{x} \dot{y}", real=True)   #: twist (4), body frame
X_dot, Y_dot = sp.symbols(r"\dot{X} \dot{Y}", real=True)      #: velocity of C, fixed frame
r, d, b, L = sp.symbols("r d b L", positive=True)             #: radius, offset, half-separation, char. length
beta = sp.symbols("beta1:4", real=True)                       #: beta_1..beta_3 (same symbols as Robot.beta_symbols)
beta_dot = sp.symbols(r"\dot{\beta}_1:4", real=True)
phi = sp.symbols(r"\phi_1:4", real=True)
phi_dot = sp.symbols(r"\dot{\phi}_{1} \dot{\phi}_{2} \dot{\phi}_{3}", real=True)
theta_dot = sp.symbols(r"\dot{\theta}_{1} \dot{\theta}_{2} \dot{\theta}_{3}", real=True)
dx, dy = sp.symbols("d_x d_y", real=True)                     #: components of a mount vector d_i
E = _E(SYMBOLIC)                                              #: (3), the model's E
