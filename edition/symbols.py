r"""The paper's symbols, defined once: the names the printed forms (``edition/printed.toml``) are written in.

Names follow the paper's nomenclature; every symbol is real, lengths are positive.  The steering
angles :data:`beta` are the same symbols as :attr:`wmr.Robot.beta_symbols`.  The SymPy form of each
printed equation is a string parsed against the public names of this module
(:mod:`edition.transcription`), so a name here is a name there.

* Platform and twist: :data:`psi`, :data:`psi_dot`, :data:`x_dot`, :data:`y_dot` (body frame),
  :data:`X_dot`, :data:`Y_dot` (fixed frame), :data:`c_dot` (1) in body components.
* Dimensions: wheel radius :data:`r`, offset :data:`d`, half-separation of a dual wheel :data:`b`,
  characteristic length :data:`L`, number of wheels :data:`w`.
* A generic wheel unit *i* ("for i = 1 to w"): :data:`d_i`, :data:`beta_i`, :data:`phi_i`, their
  rates, and the two wheels *i1*, *i2* of a dual wheel.
* Three units (Sections 4-5): mount points :data:`D`, angles :data:`beta`, rates :data:`phi_dot`,
  :data:`theta_dot`.
* Named objects (:class:`sympy.MatrixSymbol`), the left sides of identities: a check substitutes
  the matrices it derives from :mod:`wmr` for them.  Where the paper uses one letter for matrices of
  different sizes (three offset or three centred wheels), the name says which.
* Section 5.4: the instantaneous centre :data:`u`, :data:`u_c`, :data:`u_i`.
"""

import sympy as sp

# --- platform and twist ------------------------------------------------------------------------------
psi = sp.Symbol(r"\psi", real=True)  #: platform orientation
psi_dot, x_dot, y_dot = sp.symbols(r"\dot{\psi} \dot{x} \dot{y}", real=True)  #: twist (4), body frame
X_dot, Y_dot = sp.symbols(r"\dot{X} \dot{Y}", real=True)  #: velocity of C, fixed frame
c_dot = sp.Matrix([x_dot, y_dot])  #: (1): c_dot = x_dot i + y_dot j, body components

# --- dimensions ------------------------------------------------------------------------------------------
r, d, b, L = sp.symbols("r d b L", positive=True)  #: radius, offset, half-separation, char. length
w = sp.Symbol("w", positive=True, integer=True)  #: number of wheels, in printed sizes

# --- three wheel units ------------------------------------------------------------------------------------
beta = sp.symbols("beta1:4", real=True)  #: beta_1..beta_3 (same symbols as Robot.beta_symbols)
beta1, beta2, beta3 = beta
beta_dot = sp.symbols(r"\dot{\beta}_1:4", real=True)
phi = sp.symbols(r"\phi_1:4", real=True)
phi_dot = sp.symbols(r"\dot{\phi}_{1} \dot{\phi}_{2} \dot{\phi}_{3}", real=True)
phi_dot1, phi_dot2, phi_dot3 = phi_dot
theta_dot = sp.symbols(r"\dot{\theta}_{1} \dot{\theta}_{2} \dot{\theta}_{3}", real=True)
theta_dot1, theta_dot2, theta_dot3 = theta_dot
#: general mount points d_k = CP_k, body frame (k = 1, 2, 3)
D = tuple(sp.symbols(f"d_{{{k}x}} d_{{{k}y}}", real=True) for k in (1, 2, 3))
#: the mount vectors d_1, d_2, d_3 of :data:`D` as columns
d1, d2, d3 = (sp.Matrix(p) for p in D)

# --- a generic wheel unit i ---------------------------------------------------------------------------------
d_i = sp.symbols("d_{ix} d_{iy}", real=True)  #: components of d_i = CP_i, body frame
dx, dy = sp.symbols("d_x d_y", real=True)  #: components of a mount vector d_i (Section 5.4)
#: steering angle of the intermediate body relative to the platform, absolute steering angle
beta_i, phi_i = sp.symbols(r"\beta_i \phi_i", real=True)
#: rates of unit i: steering (absolute), rolling, intermediate body relative to the platform
phi_dot_i, theta_dot_i, beta_dot_i = sp.symbols(r"\dot{\phi}_i \dot{\theta}_i \dot{\beta}_i", real=True)
#: dual wheel: rolling rates and angles of wheels i1 and i2, average rolling angle
theta_dot_i1, theta_dot_i2 = sp.symbols(r"\dot{\theta}_{i1} \dot{\theta}_{i2}", real=True)
theta_i, theta_i1, theta_i2 = sp.symbols(r"\theta_i \theta_{i1} \theta_{i2}", real=True)

# --- named objects of Section 3 -----------------------------------------------------------------------------
p_dot_i = sp.MatrixSymbol(r"\dot{\mathbf{p}}_i", 2, 1)  #: velocity of P_i
p_dot_i_B = sp.MatrixSymbol(r"[\dot{\mathbf{p}}_i]_{\mathcal{B}}", 2, 1)  #: the same in body components
h_dot_i = sp.MatrixSymbol(r"\dot{\mathbf{h}}_i", 2, 1)  #: velocity of the wheel centre H_i
h_dot_i1 = sp.MatrixSymbol(r"\dot{\mathbf{h}}_{i1}", 2, 1)  #: dual wheel: velocity of H_i1
h_dot_i2 = sp.MatrixSymbol(r"\dot{\mathbf{h}}_{i2}", 2, 1)  #: dual wheel: velocity of H_i2
i_i = sp.MatrixSymbol(r"\mathbf{i}_i", 2, 1)  #: axle direction of unit i
j_i = sp.MatrixSymbol(r"\mathbf{j}_i", 2, 1)  #: rolling direction of unit i
E_sym = sp.MatrixSymbol(r"\mathbf{E}", 2, 2)  #: the matrix E of (3), by name
R_bwi = sp.MatrixSymbol(r"\mathbf{R}_{bwi}", 2, 2)  #: the rotation of (11), by name
t_sym = sp.MatrixSymbol(r"\mathbf{t}", 3, 1)  #: the twist of (4), by name
c_dot_sym = sp.MatrixSymbol(r"\dot{\mathbf{c}}", 2, 1)  #: the velocity of C, by name (28)

# --- named objects of Section 4 (three offset wheels) ------------------------------------------------------
F_offset = sp.MatrixSymbol(r"\mathbf{F}", 6, 9)  #: functional matrix (24)
q_dot_offset = sp.MatrixSymbol(r"\dot{\mathbf{q}}", 9, 1)  #: generalised rates (25)
nu = sp.Symbol(r"\nu", integer=True, nonnegative=True)  #: nullity (27)
dim_N_F = sp.Symbol(r"\dim\mathcal{N}(\mathbf{F})")
kappa, sigma_l, sigma_s = sp.symbols(r"\kappa \sigma_l \sigma_s", positive=True)  #: (30)
JL1 = sp.MatrixSymbol(r"\mathbf{J}_{L1}", 6, 3)  #: (32), three wheels
tL = sp.MatrixSymbol(r"\mathbf{t}_{L}", 3, 1)  #: (33)
J2_offset = sp.MatrixSymbol(r"\mathbf{J}_{2}", 6, 6)  #: J2 of (21) for three offset wheels
theta_dot_offset = sp.MatrixSymbol(r"\dot{\boldsymbol{\theta}}", 6, 1)
Upsilon = tuple(sp.MatrixSymbol(rf"\Upsilon_{{{i}}}", 2, 2) for i in (1, 2, 3))  #: (40)
Upsilon_i = sp.MatrixSymbol(r"\Upsilon_i", 2, 2)  #: (41)
ptilde2 = sp.MatrixSymbol(r"\tilde{\mathbf{p}}^{2}", 2, 2)  #: (41)-(42)

# --- named objects of Section 5 (three centred wheels) -----------------------------------------------------
J2_centred = sp.MatrixSymbol(r"\mathbf{J}_{2}", 6, 3)
theta_dot_centred = sp.MatrixSymbol(r"\dot{\boldsymbol{\theta}}", 3, 1)
J = sp.MatrixSymbol(r"\mathbf{J}", 3, 3)  #: (56)
F_centred = sp.MatrixSymbol(r"\mathbf{F}", 6, 6)  #: (52)
q_dot_centred = sp.MatrixSymbol(r"\dot{\mathbf{q}}", 6, 1)  #: (53)
det_J = sp.Symbol(r"\det(\mathbf{J})")  #: (59)

# --- Section 5.4: the instantaneous centre U ------------------------------------------------------------------
u = sp.Matrix(sp.symbols("u_X u_Y", real=True))  #: position of U, fixed frame
c = sp.Matrix(sp.symbols("c_X c_Y", real=True))  #: position of C, fixed frame
u_c = sp.Matrix(sp.symbols("u_{cx} u_{cy}", real=True))  #: CU
u_i = sp.Matrix(sp.symbols("u_{ix} u_{iy}", real=True))  #: P_i U
u_dot = sp.Matrix(sp.symbols(r"\dot{u}_x \dot{u}_y", real=True))  #: velocity of U (62)
