r"""Singular configurations of a WMR with three centred wheels: the zero set of :math:`\det\mathbf J` (58)-(59).

For centred wheels the i-th column of :math:`\mathbf J = \mathbf J_{L1}^T\mathbf J_2` (56) is
:math:`-r_i[\tfrac1L\mathbf d_i^T\mathbf E^T\mathbf j_i,\ \mathbf j_i^T]^T`, and
:math:`(\mathbf E\mathbf d_i)^T\mathbf j_i = \mathbf d_i\times\mathbf j_i = \mathbf d_i^T\mathbf i_i`.  So the
column is (up to the factor :math:`-r_i`) the Plücker vector
:math:`\mathbf w_i = [\,m_i/L,\ \mathbf j_i^T]^T`, :math:`m_i = \mathbf d_i^T\mathbf i_i`, of the
**wheel-plane line** :math:`\ell_i` (the trace of the wheel plane on the floor: through :math:`P_i`
along :math:`\mathbf j_i`), and

.. math::

    \det\mathbf J = -\frac{r_1r_2r_3}{L}\Big[m_1\sin(\beta_3-\beta_2) + m_2\sin(\beta_1-\beta_3)
                    + m_3\sin(\beta_2-\beta_1)\Big] = -\frac{r_1r_2r_3}{L}\det\mathbf W ,

an identity checked exactly by :func:`characterisation` for symbolic mount points.  A point
:math:`D` lies on :math:`\ell_i` iff :math:`[-1,\ -D_y,\ D_x]\,\mathbf W_{L=1}\mathbf e_i = 0`; hence
:math:`\det\mathbf J = 0` **iff the three wheel-plane lines are concurrent at a point**
:math:`D_P` **or all parallel** (concurrent at infinity), and :math:`D_P` is read off the left null
vector of :math:`\mathbf W` (:func:`concurrency_point`).  The zero set is one irreducible surface
in the torus of :math:`(\beta_1,\beta_2,\beta_3)` (for the paper's robot :math:`\det\mathbf J` is an
irreducible trilinear form in :math:`(\cos\beta_i,\sin\beta_i)`), swept by :math:`D_P` over the
projective plane with the 8 choices :math:`\beta_i` or :math:`\beta_i+\pi`; the paper's items
(i)-(v) are pieces of it.

A different matrix decides mobility: :math:`\operatorname{rank}\mathbf F = 5` (mobility 1) iff
the three **axle** lines (through :math:`P_i` along :math:`\mathbf i_i`) are concurrent, at the
instantaneous centre U; otherwise 6.  Both happen at once iff every :math:`P_i` sees
:math:`U` and :math:`D_P` at a right angle, i.e. (Thales) :math:`U` and :math:`D_P` are antipodal
on the circle through :math:`P_1,P_2,P_3`, or both are at infinity: a rotation about any point
of that circle passes through a singular :math:`\mathbf J`, a family the paper does not list
(:func:`families`).

Everything here is computed from :meth:`wmr.Robot.J` and :func:`wmr.mobility.rank_F`; nothing is
copied from the paper.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from . import _validate as V
from .backend import NUMERIC, SYMBOLIC
from .mobility import rank_F
from .tolerance import TOL, near_zero

FINITE, AT_INFINITY, NONE = "finite", "infinity", "none"

#: The paper's items of section 5.3 for its wheel numbering (wheels 1-based).
PAPER_PAIR_ITEMS = {(1, 3): "(ii)", (1, 2): "(iii)", (2, 3): "(iv)"}


def _require_square(robot):
    if robot.n_rates != 3 or robot.w != 3:
        raise ValueError(
            f"det J needs a square J (three centred wheels, n_rates = 3); got a robot with w = {robot.w}, "
            f"n_rates = {robot.n_rates} (for dual wheels analyse the kinematically equivalent centred robot)")


def _default_L(robot, L):
    if L is not None:
        return V.positive("L", L)
    from .isotropy import characteristic_length
    try:
        return characteristic_length(robot)
    except TypeError:
        raise ValueError("give L explicitly for a robot with symbolic mount points") from None


def exact_robot(robot):
    """The same robot with exact (SymPy) mount coordinates and radii, for symbolic checks."""
    import dataclasses
    from .robot import Robot
    if robot.is_symbolic:
        return robot
    ns = [sp.sqrt(2), sp.sqrt(3)]
    units = [dataclasses.replace(u, position=tuple(sp.nsimplify(v, ns) for v in u.position),
                                 r=sp.nsimplify(u.r, ns)) for u in robot.wheels]
    return Robot(units, name=robot.name)


def numeric_robot(robot):
    """The same robot with float coordinates (from an exact one)."""
    import dataclasses
    from .robot import Robot
    units = [dataclasses.replace(u, position=tuple(float(v) for v in u.position), r=float(u.r))
             for u in robot.wheels]
    return Robot(units, name=robot.name)


# ------------------------------------------------------------------------------------- det J
def det_J(robot, beta, L=None):
    r""":math:`\det\mathbf J(\boldsymbol\beta)` (58) for a batch of configurations.

    Parameters
    ----------
    robot : Robot
        Three centred wheels (``n_rates == 3``).
    beta : array (..., 3)
    L : float, optional
        Characteristic length of :math:`\mathbf J_{L1}` (default: :func:`wmr.characteristic_length`,
        which is the paper's L for its robot).

    Returns
    -------
    numpy.ndarray (...)

    Examples
    --------
    >>> import wmr
    >>> bot = wmr.paper_robot("centred")
    >>> abs(float(det_J(bot, [0.3, 0.3, 0.3]))) < 1e-15      # item (i)
    True
    """
    _require_square(robot)
    return np.linalg.det(robot.J(beta, L=_default_L(robot, L)))


def det_J_scale(robot, beta, L=None):
    r"""Hadamard bound :math:`\prod_i\|\mathbf J\mathbf e_i\|`: the size against which :math:`\det\mathbf J` is zero.

    Returns
    -------
    numpy.ndarray (...)
    """
    J = robot.J(beta, L=_default_L(robot, L))
    return np.prod(np.linalg.norm(J, axis=-2), axis=-1)


def is_singular(robot, beta, L=None):
    r"""True where :math:`|\det\mathbf J| \le` ``TOL`` times the Hadamard bound (batched)."""
    return near_zero(det_J(robot, beta, L), det_J_scale(robot, beta, L))


def det_J_symbolic(robot, L=None):
    r"""Exact :math:`\det\mathbf J` as a SymPy expression in the robot's :math:`\beta_i` symbols.

    Derived from :meth:`wmr.Robot.J`, expanded into a polynomial in :math:`\cos\beta_i,\sin\beta_i`
    (of degree one in each wheel's pair) and factored.

    Parameters
    ----------
    robot : Robot
        Numeric (use ``paper_robot(..., exact=True)`` for exact coefficients) or symbolic.
    L : float or sympy.Expr, optional

    Returns
    -------
    sympy.Expr
    """
    _require_square(robot)
    robot = exact_robot(robot)
    L = _default_L(robot, L)
    if isinstance(L, float):
        L = sp.nsimplify(L, [sp.sqrt(2), sp.sqrt(3)])
    J = robot.J(None, L=L)
    return sp.factor(sp.expand(sp.expand_trig(J.det())))


def plane_line_matrix(robot, beta, L=1, backend=None):
    r"""The matrix :math:`\mathbf W` whose columns are the Plücker vectors :math:`[m_i/L,\ \mathbf j_i^T]^T` of the wheel-plane lines.

    :math:`m_i = \mathbf d_i^T\mathbf i_i = \mathbf d_i\times\mathbf j_i` is the moment of the line
    about C.  For three centred wheels :math:`\mathbf J = -\mathbf W\,\mathrm{diag}(r_i)`.

    Parameters
    ----------
    robot : Robot
    beta : array (..., w) or sequence of SymPy expressions (None: the symbols)
    L : float or sympy.Expr

    Returns
    -------
    numpy.ndarray (..., 3, w) or sympy.Matrix (3, w)
    """
    symbolic = beta is None or robot.is_symbolic or any(
        isinstance(b, sp.Basic) for b in np.ravel(np.asarray(beta, dtype=object)))
    bk = SYMBOLIC if symbolic else NUMERIC
    if symbolic:
        b = list(robot.beta_symbols) if beta is None else list(beta)
    else:
        beta = V.finite_array("beta", beta, last=robot.w)
        b = [beta[..., i] for i in range(robot.w)]
    columns = []
    for u, bi in zip(robot.wheels, b):
        jx, jy = -bk.sin(bi), bk.cos(bi)                       # j_i = R_bwi [0 1]^T, (11)
        px, py = u.position
        columns.append([(px * jy - py * jx) / L, jx, jy])      # [m_i / L, j_i], m_i = d_i x j_i
    return bk.matrix([list(row) for row in zip(*columns)])


def characterisation(robot=None):
    r"""Exact statements about the zero set of :math:`\det\mathbf J`, derived from the model.

    Parameters
    ----------
    robot : Robot, optional
        Default: the paper's robot with symbolic ``L`` and ``r`` (:mod:`wmr.symbols`).

    Returns
    -------
    dict
        ``"det_J"``: the factored :math:`\det\mathbf J` of ``robot``;
        ``"lines_form"``: :math:`-(r_1r_2r_3/L)\sum_{\rm cyc} m_i\sin(\beta_k-\beta_j)`;
        ``"identity_general"``: True when :math:`\det\mathbf J = -(r_1r_2r_3/L)\det\mathbf W`
        holds exactly for three centred wheels at **symbolic** mount points;
        ``"identity_robot"``: the same identity for ``robot``;
        ``"independent_of_L"``: True when ``det_J`` does not contain the symbol L;
        ``"irreducible"``: True when the trilinear form has no factor other than constants.
    """
    from . import symbols as S
    from .robot import Robot
    from .robots import paper_robot
    from .wheels import CentredWheel
    if robot is None:
        robot = paper_robot("centred", L=S.L, r=S.r, exact=True)
        L = S.L
    else:
        L = S.L if robot.is_symbolic else _default_L(robot, None)

    def lines_form(bot, L):
        b = bot.beta_symbols
        m = [u.position[0] * sp.cos(bi) + u.position[1] * sp.sin(bi) for u, bi in zip(bot.wheels, b)]
        rr = sp.Mul(*[u.r for u in bot.wheels])
        return -(rr / L) * (m[0] * sp.sin(b[2] - b[1]) + m[1] * sp.sin(b[0] - b[2]) + m[2] * sp.sin(b[1] - b[0]))

    xs, ys = sp.symbols("x1:4", real=True), sp.symbols("y1:4", real=True)
    rs = sp.symbols("r1:4", positive=True)
    gen = Robot([CentredWheel((x, y), r=ri) for x, y, ri in zip(xs, ys, rs)])
    gdet = gen.J(None, L=S.L).det()
    ident_general = sp.expand(sp.expand_trig(gdet - lines_form(gen, S.L))) == 0
    ident_w = sp.expand(sp.expand_trig(gdet + sp.Mul(*rs) * plane_line_matrix(gen, None, S.L).det())) == 0
    det = det_J_symbolic(robot, L)
    lf = lines_form(robot, L)
    ident_robot = sp.expand(sp.expand_trig(det - lf)) == 0
    # irreducibility: write det J as a polynomial in c_i, s_i and factor over Q(sqrt 3)
    cs = sp.symbols("c1:4 s1:4", real=True)
    b = robot.beta_symbols
    poly = sp.expand(sp.expand_trig(det)).subs({**{sp.cos(bi): cs[i] for i, bi in enumerate(b)},
                                                **{sp.sin(bi): cs[3 + i] for i, bi in enumerate(b)}})
    fl = sp.factor_list(sp.expand(poly), extension=sp.sqrt(3))
    nontrivial = [f for f, _ in fl[1] if f.free_symbols & set(cs)]
    return {"det_J": det, "lines_form": lf, "identity_general": bool(ident_general and ident_w),
            "identity_robot": bool(ident_robot), "independent_of_L": S.L not in det.free_symbols,
            "irreducible": len(nontrivial) == 1, "polynomial": poly}


# ------------------------------------------------------------------------------------ lines
def wheel_plane_lines(robot, beta):
    r"""Wheel-plane lines :math:`\ell_i`: through :math:`P_i` along :math:`\mathbf j_i`.

    (For an offset wheel the line also passes through :math:`H_i = P_i - d\mathbf j_i`; for a dual
    wheel it is the unit's mid-plane.)

    Returns
    -------
    points : numpy.ndarray (..., w, 2)
    directions : numpy.ndarray (..., w, 2)
        Unit vectors :math:`\mathbf j_i`.
    """
    pts = _unit_points(robot, beta)
    return np.stack([p["P"] for p in pts], axis=-2), np.stack([p["j"] for p in pts], axis=-2)


def axle_lines(robot, beta):
    r"""Axle lines: through each wheel centre along :math:`\mathbf i_i` (centred: through :math:`P_i`).

    Returns
    -------
    points : numpy.ndarray (..., w, 2)
        Wheel centres :math:`H_i` (body frame).
    directions : numpy.ndarray (..., w, 2)
    """
    pts = _unit_points(robot, beta)
    return np.stack([p["H"] for p in pts], axis=-2), np.stack([p["i"] for p in pts], axis=-2)


def _unit_points(robot, beta):
    """Each unit's points and axes (``unit.points``) at the steering angles ``beta (..., w)``."""
    beta = V.finite_array("beta", beta, last=robot.w)
    return [u.points(beta[..., i]) for i, u in enumerate(robot.wheels)]


def line_intersection(p1, u1, p2, u2):
    r"""Intersection of the lines :math:`p_1 + s u_1` and :math:`p_2 + t u_2` (one pair).

    Returns
    -------
    (kind, point)
        ``kind`` is ``"finite"`` (point (2,)), ``"parallel"`` (point None) or ``"coincident"``
        (point None).
    """
    p1, u1, p2, u2 = (np.asarray(a, dtype=float) for a in (p1, u1, p2, u2))
    cross = u1[0] * u2[1] - u1[1] * u2[0]
    w = p2 - p1
    scale = max(1.0, float(np.abs(w).max()))
    if near_zero(cross):
        off = u1[0] * w[1] - u1[1] * w[0]
        return ("coincident", None) if near_zero(off, scale) else ("parallel", None)
    s = (w[0] * u2[1] - w[1] * u2[0]) / cross
    return "finite", p1 + s * u1


def pair_intersections(points, directions):
    r"""All pairwise intersections :math:`D_{ij}` of lines (one configuration).

    Parameters
    ----------
    points, directions : array (w, 2)

    Returns
    -------
    dict (i, j) -> (kind, point), 1-based wheel numbers, i < j
    """
    out = {}
    n = len(points)
    for i in range(n):
        for j in range(i + 1, n):
            out[(i + 1, j + 1)] = line_intersection(points[i], directions[i], points[j], directions[j])
    return out


@dataclass(frozen=True)
class Concurrency:
    """Where a set of lines meet (one configuration).

    Attributes
    ----------
    kind : str
        ``"finite"`` (all meet at ``point``), ``"infinity"`` (all parallel to ``direction``) or
        ``"none"``.
    point : numpy.ndarray (2,) or None
    direction : numpy.ndarray (2,) or None
    residual : float
        Smallest singular value of the normalised Plücker matrix (0 when concurrent).
    """

    kind: str
    point: object
    direction: object
    residual: float


def lines_concurrency(points, directions):
    r"""Common point of lines :math:`p_k + s\,u_k` (one configuration), via the Plücker matrix.

    A point D lies on every line iff :math:`[-1, -D_y, D_x]\,[p_k\times u_k,\ u_k]^T = 0`; the
    left null vector of the :math:`3\times n` Plücker matrix gives D in homogeneous coordinates.

    Parameters
    ----------
    points, directions : array (n, 2), n >= 2

    Returns
    -------
    Concurrency
    """
    p = np.asarray(points, dtype=float)
    u = np.asarray(directions, dtype=float)
    u = u / np.linalg.norm(u, axis=-1, keepdims=True)
    scale = max(1.0, float(np.abs(p).max()))
    m = (p[:, 0] * u[:, 1] - p[:, 1] * u[:, 0]) / scale
    W = np.stack([m, u[:, 0], u[:, 1]])                 # (3, n)
    U, s, _ = np.linalg.svd(W)
    res = float(s[-1]) if W.shape[1] >= 3 else 0.0
    if W.shape[1] >= 3 and not near_zero(res):
        return Concurrency(NONE, None, None, res)
    n = U[:, -1]
    if near_zero(n[0], np.abs(n[1:]).max()):
        dirn = np.array([-n[2], n[1]])
        return Concurrency(AT_INFINITY, None, dirn / np.linalg.norm(dirn), res)
    return Concurrency(FINITE, np.array([-n[2] / n[0], n[1] / n[0]]) * scale, None, res)


def concurrency_point(robot, beta):
    r"""The point :math:`D_P` where the wheel-plane lines meet (one configuration).

    Returns
    -------
    Concurrency
        ``kind == "none"`` exactly when :math:`\det\mathbf J \ne 0` (three wheels).
    """
    beta = V.finite_array("beta", beta, last=robot.w)
    if beta.ndim != 1:
        raise ValueError(f"concurrency_point takes one configuration (w,), got shape {beta.shape}")
    return lines_concurrency(*wheel_plane_lines(robot, beta))


def instantaneous_centre_of_axles(robot, beta):
    """Where the axle lines meet (one configuration): the IC when ``rank F = 5``.  See :func:`lines_concurrency`."""
    beta = V.finite_array("beta", beta, last=robot.w)
    return lines_concurrency(*axle_lines(robot, beta))


# ------------------------------------------------------------------------------- steering to
def planes_through(robot, D):
    r"""Steering angles whose wheel-plane lines all pass through the point D (body frame).

    :math:`\mathbf j_i \parallel D - P_i`, choosing :math:`\beta_i\in(-\pi/2, \pi/2]`... (the
    other choice, :math:`\beta_i + \pi`, gives the same line).  Where :math:`D = P_i` the angle is
    free and 0 is returned.

    Parameters
    ----------
    robot : Robot
    D : array (..., 2)

    Returns
    -------
    numpy.ndarray (..., w)
    """
    D = V.finite_array("D", D, last=2)
    v = D[..., None, :] - robot.mount_points                        # (..., w, 2)
    beta = np.arctan2(-v[..., 0], v[..., 1])                       # j = (-sin b, cos b) || v
    beta = np.where(np.linalg.norm(v, axis=-1) <= TOL, 0.0, beta)
    return _half_turn(beta)


def axles_through(robot, U):
    r"""Steering angles whose axles all pass through U (body frame): rotation about U is admissible.

    Returns
    -------
    numpy.ndarray (..., w), in :math:`(-\pi/2, \pi/2]`
    """
    U = V.finite_array("U", U, last=2)
    v = U[..., None, :] - robot.mount_points
    beta = np.arctan2(v[..., 1], v[..., 0])                        # i = (cos b, sin b) || v
    beta = np.where(np.linalg.norm(v, axis=-1) <= TOL, 0.0, beta)
    return _half_turn(beta)


def _half_turn(beta):
    """Map angles to (-pi/2, pi/2] (same line)."""
    b = np.mod(beta + np.pi / 2, np.pi) - np.pi / 2
    return np.where(np.isclose(b, -np.pi / 2, atol=TOL, rtol=0), np.pi / 2, b)


def circumcircle(robot):
    """Centre (2,) and radius of the circle through the first three mount points."""
    (ax, ay), (bx, by), (cx, cy) = robot.mount_points[:3]
    dd = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    if near_zero(dd):
        raise ValueError("the mount points are collinear: no circumcircle")
    ux = ((ax**2 + ay**2) * (by - cy) + (bx**2 + by**2) * (cy - ay) + (cx**2 + cy**2) * (ay - by)) / dd
    uy = ((ax**2 + ay**2) * (cx - bx) + (bx**2 + by**2) * (ax - cx) + (cx**2 + cy**2) * (bx - ax)) / dd
    centre = np.array([ux, uy])
    return centre, float(np.linalg.norm(robot.mount_points[0] - centre))


def pair_line_angle(robot, i, j):
    r"""The steering angle (in :math:`(-\pi/2,\pi/2]`) that puts the plane of wheel i on the line :math:`P_iP_j` (1-based)."""
    return float(planes_through(robot, robot.mount_points[j - 1])[i - 1])


# -------------------------------------------------------------------------------- classify
@dataclass(frozen=True)
class Classification:
    """What a configuration is (see :func:`classify`).

    Attributes
    ----------
    beta : numpy.ndarray (3,)
    det_J : float
    singular : bool
    rank_F : int
    mobility : int
    planes : Concurrency
        Where the wheel-plane lines meet (:math:`D_P`).
    axles : Concurrency
        Where the axles meet (the IC).
    coincident : tuple of (i, j)
        Pairs of wheels whose planes coincide.
    family : str
        Key of the row of :func:`families` the configuration belongs to ("regular" if none).
    paper_item : str
        The paper's item (i)-(v) that states this configuration literally, or "" if none.
    """

    beta: np.ndarray
    det_J: float
    singular: bool
    rank_F: int
    mobility: int
    planes: Concurrency
    axles: Concurrency
    coincident: tuple = field(default_factory=tuple)
    family: str = "regular"
    paper_item: str = ""


def _same_angle(a, b, period=2 * np.pi):
    """True when a = b modulo ``period`` (within TOL)."""
    x = np.mod(a - b + period / 2, period) - period / 2
    return bool(near_zero(x))


def classify(robot, beta, L=None):
    r"""Classify one configuration of a three-centred-wheel robot.

    Families (keys of :func:`families`): ``"i"`` (all wheel planes parallel, equal angles),
    ``"i'"`` (parallel, some wheel turned by :math:`\pi`), ``"pair-ij"`` / ``"pair-ij'"`` (planes of
    wheels i, j on the line :math:`P_iP_j`, with equal / half-turn-apart angles), ``"v-C"``
    (:math:`D_P = C`), ``"v-P"`` (:math:`D_P` at a mount point), ``"v-circle"`` (axles also
    concurrent: rotation about a point of the circle through the :math:`P_i`), ``"v"`` (any other
    finite :math:`D_P`).

    Parameters
    ----------
    robot : Robot
    beta : array (3,)

    Returns
    -------
    Classification
    """
    beta = V.finite_array("beta", beta, last=robot.w)
    if beta.ndim != 1:
        raise ValueError(f"classify takes one configuration (3,), got shape {beta.shape}")
    dj = float(det_J(robot, beta, L))
    sing = bool(is_singular(robot, beta, L))
    rk = int(rank_F(robot, beta))
    mob = 3 + robot.n_rates - rk
    planes = concurrency_point(robot, beta)
    axles = instantaneous_centre_of_axles(robot, beta)
    P, u = wheel_plane_lines(robot, beta)
    pairs = tuple(k for k, (kind, _) in pair_intersections(P, u).items() if kind == "coincident")
    fam, item = "regular", ""
    if sing:
        scale = float(np.abs(robot.mount_points).max())
        if planes.kind == AT_INFINITY:
            equal = all(_same_angle(beta[k], beta[0]) for k in range(1, robot.w))
            fam, item = ("i", "(i)") if equal else ("i'", "")
        elif pairs:
            i, j = pairs[0]
            equal = _same_angle(beta[i - 1], beta[j - 1])
            fam = f"pair-{i}{j}" + ("" if equal else "'")
            item = PAPER_PAIR_ITEMS.get((i, j), "") if equal else ""
        elif axles.kind != NONE:
            fam, item = "v-circle", "(v)"
        elif planes.kind == FINITE and near_zero(np.linalg.norm(planes.point), scale):
            fam, item = "v-C", "(v)"
        elif planes.kind == FINITE and np.min(np.linalg.norm(robot.mount_points - planes.point, axis=1)) <= TOL * max(1.0, scale):
            fam, item = "v-P", "(v)"
        else:
            fam, item = "v", "(v)"
    return Classification(beta, dj, sing, rk, mob, planes, axles, pairs, fam, item)


# -------------------------------------------------------------------------------- families
@dataclass
class Family:
    """One family of singular configurations, with computed evidence (a row of ``singularities.csv``).

    ``samples`` is an array (n, 3) of representative configurations; ``exact`` a callable
    returning the list of (cos, sin) pairs (unnormalised directions of :math:`\\mathbf i_i`, SymPy)
    parameterising the family by free symbols, used for the exact check.
    """

    key: str
    family: str
    configuration: str
    geometric_meaning: str
    listed_in_paper: str
    paper_item: str
    note: str
    samples: np.ndarray = None
    exact: object = None
    # computed
    det_J_max: float = float("nan")
    det_J_exact_zero: bool | None = None
    rank_F: str = ""
    classified_as: str = ""

    def row(self):
        return {
            "family": self.family, "configuration": self.configuration,
            "geometric_meaning": self.geometric_meaning,
            "det_J": f"{self.det_J_max:.1e}",
            "det_J_exact": ("0 identically" if self.det_J_exact_zero else
                            ("NOT zero" if self.det_J_exact_zero is False else "not checked")),
            "rank_F": self.rank_F, "samples": len(self.samples),
            "listed_in_paper": self.listed_in_paper, "paper_item": self.paper_item, "note": self.note,
        }


COLUMNS = ("family", "configuration", "geometric_meaning", "det_J", "det_J_exact", "rank_F", "samples",
           "listed_in_paper", "paper_item", "note")


def _deg(x):
    v = float(np.degrees(x))
    v = round(v, 9)
    return f"{v:g}"


def _exact_dirs_angles(angles):
    """(cos, sin) of exact angles (SymPy) as unnormalised axle directions."""
    return [(sp.cos(a), sp.sin(a)) for a in angles]


def _poly_det(robot, L=None):
    """det J as a polynomial in c_i = cos(beta_i), s_i = sin(beta_i) (degree 1 in each pair)."""
    det = sp.expand(sp.expand_trig(det_J_symbolic(robot, L)))
    c = sp.symbols("c1:4", real=True)
    s = sp.symbols("s1:4", real=True)
    b = robot.beta_symbols
    poly = det.subs({**{sp.cos(bi): c[i] for i, bi in enumerate(b)}, **{sp.sin(bi): s[i] for i, bi in enumerate(b)}})
    return sp.expand(poly), c, s


def exact_zero(poly, c, s, dirs):
    r"""True when the polynomial form of :math:`\det\mathbf J` vanishes identically on a parameterised family.

    :math:`\det\mathbf J` is homogeneous of degree one in each wheel's :math:`(\cos\beta_i,\sin\beta_i)`,
    so substituting unnormalised axle directions multiplies it by a non-zero factor: the zero test
    is exact without square roots.

    Parameters
    ----------
    poly, c, s : from the internal ``_poly_det``
    dirs : list of 3 pairs of SymPy expressions (axle direction of each wheel)
    """
    e = poly.subs({**{c[i]: dirs[i][0] for i in range(3)}, **{s[i]: dirs[i][1] for i in range(3)}},
                  simultaneous=True)
    e = sp.expand(sp.expand_trig(e))
    if e == 0:
        return True
    num, _ = sp.fraction(sp.cancel(sp.together(e)))
    return sp.expand(num) == 0 or sp.simplify(e) == 0


def families(robot=None, n=72, exact=True):
    r"""The singular families of the paper's robot, each checked exactly and at samples.

    Parameters
    ----------
    robot : Robot, optional
        The paper's three-centred-wheel robot (default ``paper_robot("centred", exact=True)``,
        L = r = 1; the zero set does not depend on L or r).
    n : int
        Samples per free angle.
    exact : bool
        Run the symbolic checks.

    Returns
    -------
    list of Family
        With ``det_J_max`` (max :math:`|\det\mathbf J|` over the samples), ``det_J_exact_zero``,
        ``rank_F`` (the ranks found, with counts) and ``classified_as`` filled in.
    """
    from .robots import paper_robot
    if robot is None:
        robot = paper_robot("centred")
    _require_square(robot)
    num = numeric_robot(robot)
    exact_bot = exact_robot(robot)
    P = num.mount_points
    t = np.linspace(-np.pi, np.pi, n, endpoint=False)
    tau = sp.Symbol("tau", real=True)
    th = sp.Symbol("t", real=True)
    x, y = sp.symbols("x y", real=True)
    Pex = [tuple(u.position) for u in exact_bot.wheels]
    out = []

    # (i) and (i'): all wheel-plane lines parallel
    out.append(Family(
        "i", "(i)", r"$\beta_1=\beta_2=\beta_3=\beta$, $\beta$ free",
        r"all wheel planes parallel ($D_P$ and the IC at infinity): translation",
        "yes", "(i)", "Fig. 10; the only singular family in which the robot still translates.",
        samples=np.stack([t, t, t], axis=-1),
        exact=lambda: _exact_dirs_angles([tau, tau, tau])))
    rev = []
    for k in range(3):
        b = np.stack([t, t, t], axis=-1)
        b[:, k] += np.pi
        rev.append(b)
    out.append(Family(
        "i'", "(i') parallel, one wheel turned by 180 deg",
        r"$\beta_j=\beta_k=\beta$, $\beta_i=\beta+180^\circ$ (3 choices of i), $\beta$ free",
        r"the same parallel planes as (i): $\beta$ and $\beta+\pi$ give the same wheel plane",
        "no", "(i)", "The printed (i) requires equal angles; a wheel turned half a turn has the same plane "
        "(its column of J only changes sign). Translation is still possible (rank F = 5).",
        samples=np.concatenate(rev),
        exact=lambda: _exact_dirs_angles([tau + sp.pi, tau, tau])))

    # (ii)-(iv): two wheel planes on the line P_i P_j, third free
    for (i, j), item in PAPER_PAIR_ITEMS.items():
        k = ({1, 2, 3} - {i, j}).pop()
        a = pair_line_angle(num, i, j)
        ai = sp.nsimplify(sp.Rational(round(np.degrees(a) * 1e6), 10**6)) * sp.pi / 180
        for prime in (False, True):
            rows = []
            combos = [(0.0, 0.0), (np.pi, np.pi)] if not prime else [(0.0, np.pi), (np.pi, 0.0)]
            for oi, oj in combos:
                b = np.zeros((n, 3))
                b[:, i - 1], b[:, j - 1], b[:, k - 1] = a + oi, a + oj, t
                rows.append(b)
            a1, a2 = _deg(_wrap(a)), _deg(_wrap(a + np.pi))
            if not prime:
                conf = rf"$\beta_{i}=\beta_{j}={a1}^\circ$ or $\beta_{i}=\beta_{j}={a2}^\circ$, $\beta_{k}$ free"
                fam = f"{item} planes {i},{j} coincident"
                listed, note = "yes", (f"Fig. 11; line $P_{i}P_{j}$ carries both planes; axles {i} and {j} parallel, so "
                                       "rank F = 6 unless the third plane is parallel too (then it is (i) or (i')).")
            else:
                conf = rf"$\beta_{i}={a1}^\circ,\ \beta_{j}={a2}^\circ$ or $\beta_{i}={a2}^\circ,\ \beta_{j}={a1}^\circ$, $\beta_{k}$ free"
                fam = f"{item}' planes {i},{j} coincident, half-turn apart"
                listed = "no"
                note = (f"The printed {item} gives equal angles; one wheel of the pair turned by 180 deg has the "
                        "same plane, so these are singular too.")
            out.append(Family(
                f"pair-{i}{j}" + ("'" if prime else ""), fam, conf,
                rf"planes of wheels {i} and {j} coincide with the line $P_{i}P_{j}$; $D_P$ = where plane {k} "
                "crosses it", listed, item, note, samples=np.concatenate(rows),
                exact=(lambda i=i, j=j, k=k, ai=ai, prime=prime: _exact_dirs_angles(
                    [ai if w == i else (ai + (sp.pi if prime else 0) if w == j else th) for w in (1, 2, 3)]))))

    # (v): concurrent at a finite point D_P
    grid = np.linspace(-2.5, 2.5, 11) * np.abs(P).max()
    D = np.array([(gx, gy) for gx in grid for gy in grid])
    D = D[np.min(np.linalg.norm(D[:, None, :] - P[None], axis=-1), axis=1) > 1e-6]
    base = planes_through(num, D)
    flips = np.array([[a, b_, c] for a in (0, 1) for b_ in (0, 1) for c in (0, 1)]) * np.pi
    samples_v = (base[:, None, :] + flips[None]).reshape(-1, 3)

    def dirs_through(Dx, Dy, turn=(0, 0, 0)):
        # axle i_i = -E (D - P_i) direction: wheel plane along D - P_i, i = (v_y, -v_x)
        out_ = []
        for (px, py), f in zip(Pex, turn):
            vx, vy = Dx - px, Dy - py
            sgn = -1 if f else 1
            out_.append((sgn * vy, -sgn * vx))
        return out_

    out.append(Family(
        "v", "(v) planes concurrent", r"$\ell_1,\ell_2,\ell_3$ concurrent at a finite $D_P$ (2 free parameters; "
        r"each $\beta_i$ or $\beta_i+180^\circ$)",
        r"the three wheel-plane lines meet at one point $D_P$; generically the axles meet pairwise at three points",
        "yes", "(v)", "Fig. 12b. Contains (ii)-(iv) (two planes on a side line) and the rows v-a, v-b, v-c; "
        "rank F = 5 only where $D_P$ is on the circle through the $P_i$ (row v-c).",
        samples=samples_v, exact=lambda: dirs_through(x, y, (0, 1, 0))))
    bC = planes_through(num, [0.0, 0.0])
    out.append(Family(
        "v-C", "(v-a) planes through C",
        rf"$\beta=({_deg(bC[0])}^\circ, {_deg(bC[1])}^\circ, {_deg(bC[2])}^\circ)$, each $+180^\circ$ optional",
        r"$D_P=C$: every wheel plane contains the operation point; no twist is admissible",
        "yes", "(v)", "Fig. 12a (braking at rest). Isolated points (8 of them).",
        samples=bC[None, :] + flips, exact=lambda: dirs_through(0, 0)))
    rows = []
    for kk in range(3):
        b = np.zeros((4 * n, 3))
        base_k = planes_through(num, P[kk])
        for q, (f1, f2) in enumerate([(0, 0), (0, 1), (1, 0), (1, 1)]):
            blk = b[q * n:(q + 1) * n]
            others = [w for w in range(3) if w != kk]
            blk[:, others[0]] = base_k[others[0]] + f1 * np.pi
            blk[:, others[1]] = base_k[others[1]] + f2 * np.pi
            blk[:, kk] = t
        rows.append(b)
    a13 = _deg(pair_line_angle(num, 1, 3))
    a23 = _deg(pair_line_angle(num, 2, 3))
    out.append(Family(
        "v-P", "(v-b) planes through a mount point",
        rf"e.g. $\beta_1\equiv{a13}^\circ,\ \beta_2\equiv{a23}^\circ \pmod{{180^\circ}}$, $\beta_3$ free ($D_P=P_3$); likewise at $P_1$, $P_2$",
        r"$D_P=P_k$: the other two planes lie on the sides through $P_k$; wheel k may take any angle",
        "partly", "(v)", "Implied by (v) but, unlike (ii)-(iv), not identified as a family with a free angle.",
        samples=np.concatenate(rows),
        exact=lambda: [(sp.cos(th), sp.sin(th)) if w == 2 else dirs_through(*Pex[2])[w] for w in range(3)]))

    # rotation about a point U on the circumcircle: axles through U and planes through the antipode
    cc, R = circumcircle(num)
    U = cc + R * np.stack([np.cos(t + np.pi / n), np.sin(t + np.pi / n)], axis=-1)   # half a step: U != P_k
    bU = axles_through(num, U)
    samples_c = (bU[:, None, :] + flips[None]).reshape(-1, 3)
    (ax, ay), (bx, by), (qx, qy) = Pex                       # exact circumcircle
    dd = 2 * (ax * (by - qy) + bx * (qy - ay) + qx * (ay - by))
    ccx = sp.radsimp(((ax**2 + ay**2) * (by - qy) + (bx**2 + by**2) * (qy - ay) + (qx**2 + qy**2) * (ay - by)) / dd)
    ccy = sp.radsimp(((ax**2 + ay**2) * (qx - bx) + (bx**2 + by**2) * (ax - qx) + (qx**2 + qy**2) * (bx - ax)) / dd)
    Rex = sp.sqrt(sp.radsimp((ax - ccx)**2 + (ay - ccy)**2))

    def circle_dirs():
        ux = ccx + Rex * (1 - th**2) / (1 + th**2)
        uy = ccy + Rex * 2 * th / (1 + th**2)
        return [(ux - px, uy - py) for px, py in Pex]            # i_i || U - P_i
    out.append(Family(
        "v-circle", "(v-c) rotation about a point of the circle through P1, P2, P3",
        r"axles through U on the circle through $P_1,P_2,P_3$ (radius L about C), U free",
        r"$U$ and $D_P$ antipodal on the circumcircle: each $P_i$ sees them at a right angle (Thales)",
        "no", "(v)", "det J = 0 while rank F = 5: the robot CAN rotate about U, contradicting the statement "
        "that in (v) it has lost all mobility; every rotation about a point at distance L from C is J-singular.",
        samples=samples_c, exact=circle_dirs))

    poly, c, s = _poly_det(exact_bot)
    for f in out:
        dj = np.abs(det_J(num, f.samples))
        f.det_J_max = float(dj.max())
        ranks = rank_F(num, f.samples)
        vals, counts = np.unique(ranks, return_counts=True)
        order = np.argsort(-counts)
        f.rank_F = ", ".join(f"{int(vals[o])} ({int(counts[o])}/{len(ranks)})" for o in order)
        kinds = {}
        for b in f.samples[:: max(1, len(f.samples) // 24)]:
            k = classify(num, b).family
            kinds[k] = kinds.get(k, 0) + 1
        f.classified_as = ", ".join(f"{k} ({v})" for k, v in sorted(kinds.items()))
        if exact and f.exact is not None:
            f.det_J_exact_zero = exact_zero(poly, c, s, f.exact())
    return out


def _wrap(a):
    """Angle in (-pi, pi]."""
    w = np.mod(a + np.pi, 2 * np.pi) - np.pi
    return np.pi if np.isclose(w, -np.pi, atol=TOL, rtol=0) else float(w)


def check_paper_items(robot=None, L=None):
    r"""Check the printed list (i)-(v) literally, for every value of the free angle (exact).

    Parameters
    ----------
    robot : Robot, optional
        Default: the paper's robot (exact coordinates).

    Returns
    -------
    dict item -> bool
        ``"(i)"``: :math:`\beta_1=\beta_2=\beta_3=\tau`; ``"(ii) 60"``, ``"(ii) -120"``:
        :math:`\beta_1=\beta_3=60^\circ` (resp. :math:`-120^\circ`), :math:`\beta_2` free; likewise (iii),
        (iv); ``"(v)"``: planes concurrent at a symbolic point D; each True when :math:`\det\mathbf J`
        vanishes identically.
    """
    from .robots import paper_robot
    if robot is None:
        robot = paper_robot("centred")
    robot = exact_robot(robot)
    poly, c, s = _poly_det(robot, L)
    tau = sp.Symbol("tau", real=True)
    deg = sp.pi / 180
    out = {"(i)": exact_zero(poly, c, s, _exact_dirs_angles([tau, tau, tau]))}
    printed = {"(ii)": ((1, 3), (60, -120)), "(iii)": ((1, 2), (-60, 120)), "(iv)": ((2, 3), (0, 180))}
    for item, ((i, j), vals) in printed.items():
        for v in vals:
            ang = [v * deg if w in (i, j) else tau for w in (1, 2, 3)]
            out[f"{item} {v}"] = exact_zero(poly, c, s, _exact_dirs_angles(ang))
    x, y = sp.symbols("x y", real=True)
    dirs = []
    for u in robot.wheels:
        px, py = (sp.nsimplify(v) for v in u.position)
        dirs.append((y - py, -(x - px)))                          # plane through D = (x, y)
    out["(v)"] = exact_zero(poly, c, s, dirs)
    return out


def table(robot=None, n=72, exact=True):
    """The families as a list of dict rows (columns :data:`COLUMNS`)."""
    return [f.row() for f in families(robot, n=n, exact=exact)]


def write_csv(path, robot=None, n=72, exact=True):
    """Write ``singularities.csv`` (columns :data:`COLUMNS`); returns the rows."""
    import csv
    rows = table(robot, n=n, exact=exact)
    with open(path, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    return rows


def singular_motions(robot, beta1):
    r"""Configurations with :math:`\beta_1` fixed where :math:`\det\mathbf J = 0` **and** rank F = 5.

    These are the points where a slice :math:`\beta_1 = {\rm const}` of the singular surface meets
    the set of configurations that admit motion: all planes parallel (families (i), (i')) and
    rotations about the second point :math:`U^*` where the axle of wheel 1 meets the circle through
    the :math:`P_i` (family v-circle; none when the axle is tangent to the circle).

    Parameters
    ----------
    robot : Robot
        Three centred wheels.
    beta1 : float
        Radians.

    Returns
    -------
    beta : numpy.ndarray (n, 3)
        In :math:`(-\pi, \pi]`.
    family : list of str
        From :func:`classify`.
    """
    _require_square(robot)
    rows = []
    for a in (0.0, np.pi):
        for b in (0.0, np.pi):
            rows.append([beta1, beta1 + a, beta1 + b])
    c, R = circumcircle(robot)
    p = robot.mount_points[0]
    i1 = np.array([np.cos(beta1), np.sin(beta1)])
    t = -2.0 * float(i1 @ (p - c))
    if not near_zero(t, R):
        U = p + t * i1
        base = axles_through(robot, U)
        for a in (0.0, np.pi):
            for b in (0.0, np.pi):
                rows.append([beta1, base[1] + a, base[2] + b])
    beta = np.array([[_wrap(v) for v in row] for row in rows])
    return beta, [classify(robot, b_).family for b_ in beta]
