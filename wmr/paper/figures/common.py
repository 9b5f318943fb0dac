r"""What the figures share, without matplotlib: robots, exact det J, circle fit, snapping, JSON, singular configurations.

The robots drawn (:func:`centred_robot`), exact :math:`\det\mathbf J` (:func:`exact_det_J`), circle
fitting, where the axles meet (:func:`axles_meet`), the numbers of a singular configuration
(:func:`singular_config`) and how a figure's data becomes JSON (:func:`numbers`).

The data classes of the figures mark each field with how it is written to ``<key>.json``
(:func:`numbers`): a :func:`residual` (round-off, printed as a bound by
:func:`wmr.paper.text.bound`), a :func:`small` value (an integration error: two significant
digits), an ordinary value (rounded by :func:`wmr.paper.text.rounded`), or a :func:`drawing`
field (arrays for the picture, not written).  Arrays for the picture are :func:`snap`-ped, so
that round-off differences between machines do not reach the coordinates in the SVG and PDF files.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from ...analysis import lines as ln
from ...analysis import singularities as sg
from ...analysis.linalg import condition_number
from ...analysis.mobility import rank_F
from ...model.robots import paper_robot
from ..text import bound, degrees, residual as residual_text, rounded

__all__ = ["L_PAPER", "R_CENTRED", "R_OFFSET", "DEG", "SNAP_DECIMALS", "ABS_DET_J", "MAX_PSI", "centred_robot",
           "exact_det_J", "fit_circle", "snap", "residual", "small", "drawing", "numbers", "AxleMeet", "axles_meet", "SingularConfig",
           "singular_config", "beta_text", "config_lines"]

L_PAPER = 1.0      #: distance of the mount points from C in the figures (the unit of length)
R_CENTRED = 0.25   #: wheel radius of the centred-wheel robot in the figures
R_OFFSET = 0.3     #: wheel radius (= offset d) of the offset-wheel robot in Fig. 7
DEG = np.pi / 180
#: Decimal places (in units of L, or radians) of the coordinates handed to matplotlib: 1e-7 L is
#: far below a pixel and far above round-off, so every machine draws the same file.
SNAP_DECIMALS = 7
#: LaTeX of quantities the captions bound.
ABS_DET_J = r"|\det\mathbf{J}|"
MAX_PSI = r"\max|\psi|"


def centred_robot():
    """The paper's three-centred-wheel robot as drawn here (L = 1, r = 0.25).

    Returns
    -------
    wmr.Robot
        :func:`wmr.paper_robot` ``("centred", L=L_PAPER, r=R_CENTRED)``.
    """
    return paper_robot("centred", L=L_PAPER, r=R_CENTRED)


@lru_cache(maxsize=None)
def _exact_poly():
    return sg.det_J_polynomial(sg.exact_robot(paper_robot("centred", L=L_PAPER, r=1.0)))


def exact_det_J(beta_deg, r=R_CENTRED):
    r"""Exact :math:`\det\mathbf J` of the paper's robot at angles given in (integer or rational) degrees.

    Parameters
    ----------
    beta_deg : sequence of 3 numbers
        Degrees; converted exactly (:func:`sympy.nsimplify`).
    r : float
        Wheel radius.

    Returns
    -------
    sympy.Expr
        Simplified; :math:`r^3` times the value for r = 1.

    Examples
    --------
    >>> exact_det_J([30, 30, 30]), exact_det_J([0, 0, 90], r=1)
    (0, 3/2)
    """
    import sympy as sp
    poly, c, s = _exact_poly()
    ang = [sp.nsimplify(b) * sp.pi / 180 for b in beta_deg]
    v = poly.subs({**{c[i]: sp.cos(a) for i, a in enumerate(ang)}, **{s[i]: sp.sin(a) for i, a in enumerate(ang)}})
    return sp.nsimplify(sp.radsimp(sp.expand(v))) * sp.nsimplify(r) ** 3


def fit_circle(xy):
    r"""Least-squares (Kåsa) circle through points.

    Solves :math:`x^2+y^2 = a x + b y + c` in the least-squares sense: centre :math:`(a/2, b/2)`,
    radius :math:`\sqrt{c + a^2/4 + b^2/4}`.

    Parameters
    ----------
    xy : array_like (n, 2)
        At least three points, not all on a line.

    Returns
    -------
    centre : numpy.ndarray (2,)
    radius : float

    Examples
    --------
    >>> t = np.linspace(0, 6, 50)
    >>> c, R = fit_circle(np.stack([1 + 2 * np.cos(t), -1 + 2 * np.sin(t)], axis=1))
    >>> np.round(c, 9).tolist(), round(R, 9)
    ([1.0, -1.0], 2.0)
    """
    xy = np.asarray(xy, dtype=float)
    A = np.column_stack([xy[:, 0], xy[:, 1], np.ones(len(xy))])
    rhs = np.sum(xy ** 2, axis=1)
    (a, b, c), *_ = np.linalg.lstsq(A, rhs, rcond=None)
    centre = np.array([a / 2, b / 2])
    return centre, float(np.sqrt(c + centre @ centre))


def snap(a):
    """Coordinates for drawing: rounded to :data:`SNAP_DECIMALS` places (no ``-0.0``), as a float array.

    Parameters
    ----------
    a : array_like (...)

    Returns
    -------
    numpy.ndarray (...)

    Examples
    --------
    >>> snap([1e-12, -1e-12, 0.123456789]).tolist()
    [0.0, 0.0, 0.1234568]
    """
    return np.round(np.asarray(a, dtype=float), SNAP_DECIMALS) + 0.0


# --------------------------------------------------------------------------- fields and JSON
def residual(**kw):
    """A field holding a value that is zero up to round-off (JSON: :func:`wmr.paper.text.bound` of its magnitude).

    Parameters
    ----------
    **kw
        Passed to :func:`dataclasses.field` (e.g. ``default``).

    Returns
    -------
    dataclasses.Field
    """
    return field(metadata={"json": "residual"}, **kw)


def small(**kw):
    """A field holding a small but meaningful value, e.g. an integration error (JSON: 2 significant digits).

    Parameters
    ----------
    **kw
        Passed to :func:`dataclasses.field`.

    Returns
    -------
    dataclasses.Field
    """
    return field(metadata={"json": "small"}, **kw)


def drawing(**kw):
    """A field holding arrays or objects for the picture only (not in JSON, not in repr or comparisons).

    Parameters
    ----------
    **kw
        Passed to :func:`dataclasses.field`.

    Returns
    -------
    dataclasses.Field
    """
    return field(repr=False, compare=False, metadata={"json": None}, **kw)


def _json(value, how):
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return numbers(value)
    if isinstance(value, dict):
        return {str(k): _json(v, how) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_json(v, how) for v in value]
    if value is None:
        return None
    if how == "residual":
        return bound(abs(value))
    if how == "small":
        return float(f"{float(value):.2g}")
    return rounded(value)


def numbers(data):
    """The numbers of a figure's data object for ``<key>.json``: identical on every machine.

    Parameters
    ----------
    data : dataclass instance
        Fields marked with :func:`residual`, :func:`small`, :func:`drawing` or none (a value).

    Returns
    -------
    dict
        Field name -> JSON value (nested data classes become nested dicts).
    """
    out = {}
    for f in dataclasses.fields(data):
        how = f.metadata.get("json", "value")
        if how is not None:
            out[f.name] = _json(getattr(data, f.name), how)
    return out


# --------------------------------------------------------------------------- where the axles meet
@dataclass(frozen=True)
class AxleMeet:
    r"""Where the axles of a configuration meet, compared with the instantaneous centre asked for.

    Attributes
    ----------
    kind : str
        A :class:`wmr.analysis.lines.Meet` name, lower case (``"finite"`` when they meet at a point).
    point : tuple (2,) or None
        The computed meeting point (body frame).
    error : float
        Its distance from the target (:math:`\infty` when the axles do not meet at a point).
    """

    kind: str
    point: tuple
    error: float = residual()


def axles_meet(robot, beta, target):
    """Where the axles meet at ``beta`` and how far that is from ``target``.

    Parameters
    ----------
    robot : wmr.Robot
    beta : array_like (w,)
        Steering angles (radians).
    target : array_like (2,)
        The instantaneous centre asked for (body frame).

    Returns
    -------
    AxleMeet
    """
    meet = ln.axles_concurrency(robot, beta)
    if meet.point is None:
        return AxleMeet(meet.kind.name.lower(), None, float("inf"))
    return AxleMeet(meet.kind.name.lower(), tuple(map(float, meet.point)),
                    float(np.linalg.norm(meet.point - np.asarray(target, dtype=float))))


# --------------------------------------------------------------------------- singular configurations
@dataclass(frozen=True)
class SingularConfig:
    r"""A configuration of the centred-wheel robot with what Figs. 10-12 state about it.

    Attributes
    ----------
    beta_deg : tuple of 3 floats
        Steering angles, degrees.
    det_J : float
        :math:`\det\mathbf J` in floating point (:func:`wmr.analysis.singularities.det_J`).
    det_J_exact : str
        Exact :math:`\det\mathbf J` (:func:`exact_det_J`) when the angles are exact, else ``""``.
    rank_F : int
        :math:`\operatorname{rank}\mathbf F` (24).
    mobility : int
        :math:`\nu = 3 + n - \operatorname{rank}\mathbf F` (27).
    kappa_J : float
        :math:`\kappa(\mathbf J)`, :math:`\infty` when J is rank deficient.
    singular : bool
        :func:`wmr.analysis.singularities.is_singular`.
    planes_meet : str
        Where the wheel-plane lines meet (a :class:`wmr.analysis.lines.Meet` name, lower case).
    axles_meet : str
        Where the axles meet (likewise).
    D_P : tuple (2,) or None
        The point where the wheel-plane lines meet.
    axle_crossings : tuple of (2,)
        Finite pairwise crossings of the axles within ``reach`` of C.
    coincident : tuple of (i, j)
        Pairs of wheels (1-based) whose planes coincide.
    family : str
        :func:`wmr.analysis.singularities.classify`.
    beta : numpy.ndarray (3,)
        Radians, snapped (drawing).
    plane_reach : tuple of 3 arrays (k, 2)
        Points each wheel-plane line must reach in the drawing.
    axle_reach : tuple of 3 arrays (k, 2)
        Points each axle must reach in the drawing.
    """

    beta_deg: tuple
    det_J: float = residual()
    det_J_exact: str = ""
    rank_F: int = 0
    mobility: int = 0
    kappa_J: float = float("inf")
    singular: bool = True
    planes_meet: str = ""
    D_P: tuple = None
    axles_meet: str = ""
    axle_crossings: tuple = ()
    coincident: tuple = ()
    family: str = ""
    beta: np.ndarray = drawing(default=None)
    plane_reach: tuple = drawing(default=())
    axle_reach: tuple = drawing(default=())


def singular_config(robot, beta, exact_deg=None, reach=3.2):
    r"""The numbers and construction points of one configuration (see :class:`SingularConfig`).

    Parameters
    ----------
    robot : Robot
        Three centred wheels.
    beta : array (3,)
        Radians.
    exact_deg : sequence of 3 numbers, optional
        The same angles in exact degrees: then :math:`\det\mathbf J` is also computed exactly.
    reach : float
        Axle crossings farther than this from C are left out.

    Returns
    -------
    SingularConfig
    """
    b = np.asarray(beta, dtype=float)
    P, u = ln.wheel_plane_lines(robot, b)
    H, iv = ln.axle_lines(robot, b)
    conc = ln.concurrency_point(robot, b)
    planes = ln.pair_intersections(P, u)
    axles = ln.pair_intersections(H, iv)
    plane_reach = [[conc.point] if conc.kind == ln.FINITE else [] for _ in range(3)]
    for (i, j), (kind, _) in planes.items():
        if kind == ln.COINCIDENT:                       # a coincident pair: each line reaches the other's P
            plane_reach[i - 1].append(P[j - 1])
            plane_reach[j - 1].append(P[i - 1])
    axle_reach = [[] for _ in range(3)]
    crossings = []
    for (i, j), (kind, pt) in axles.items():
        if kind == ln.FINITE and np.linalg.norm(pt) < reach:
            crossings.append(pt)
            axle_reach[i - 1].append(pt)
            axle_reach[j - 1].append(pt)
    rk = int(rank_F(robot, b))
    exact = "" if exact_deg is None else str(exact_det_J(exact_deg, r=robot.wheels[0].r))
    return SingularConfig(
        beta_deg=tuple(float(v) for v in (np.degrees(b) if exact_deg is None else exact_deg)),
        det_J=float(sg.det_J(robot, b)), det_J_exact=exact, rank_F=rk, mobility=3 + robot.n_rates - rk,
        kappa_J=float(condition_number(robot.J(b, L=L_PAPER))), singular=bool(sg.is_singular(robot, b)),
        planes_meet=conc.kind.name.lower(), D_P=None if conc.point is None else tuple(map(float, conc.point)),
        axles_meet=ln.axles_concurrency(robot, b).kind.name.lower(),
        axle_crossings=tuple(tuple(map(float, p)) for p in crossings),
        coincident=tuple(k for k, v in planes.items() if v[0] == ln.COINCIDENT),
        family=sg.classify(robot, b).family, beta=snap(b),
        plane_reach=tuple(snap(np.reshape(r_, (-1, 2))) for r_ in plane_reach),
        axle_reach=tuple(snap(np.reshape(r_, (-1, 2))) for r_ in axle_reach))


def beta_text(beta_deg, digits=6):
    r"""``$\beta_1 = 60^\circ$, $\beta_2 = ...$`` for angles in degrees.

    Parameters
    ----------
    beta_deg : sequence of float
        Steering angles (degrees).
    digits : int, optional
        Significant digits (:func:`wmr.paper.text.degrees`).

    Returns
    -------
    str
        Markdown with ``$...$`` math.

    Examples
    --------
    >>> beta_text([60, -120])
    '$\\beta_1 = 60^\\circ$, $\\beta_2 = -120^\\circ$'
    """
    return ", ".join(rf"$\beta_{k + 1} = {degrees(np.radians(b), digits)}^\circ$" for k, b in enumerate(beta_deg))


def config_lines(cfg, kappa=True):
    r"""Lines of text stating :math:`\det\mathbf J` (58) (exact and float), rank F, mobility and :math:`\kappa(\mathbf J)` (30).

    Parameters
    ----------
    cfg : SingularConfig
    kappa : bool, optional
        Include the line on :math:`\kappa(\mathbf J)`.

    Returns
    -------
    list of str
        Markdown with ``$...$`` math, one line each.
    """
    det = residual_text(ABS_DET_J, abs(cfg.det_J))
    lines = [rf"$\det\mathbf{{J}} = {cfg.det_J_exact}$ (exact), ${det}$ (float)" if cfg.det_J_exact
             else rf"${det}$ (float)",
             rf"rank $\mathbf{{F}}$ = {cfg.rank_F}, mobility {cfg.mobility}"]
    if kappa:
        k = cfg.kappa_J
        lines.append(r"$\kappa(\mathbf{J}) = \infty$" if not np.isfinite(k) else rf"$\kappa(\mathbf{{J}}) = {k:.3g}$")
    return lines
