r"""The numbers of one configuration in the figures: where the axles meet, and a singular configuration.

:class:`AxleMeet` (:func:`axles_meet`) compares where the axles meet with the instantaneous centre
asked for (Figs. 9 and 13); :class:`SingularConfig` (:func:`singular_config`) holds what Figs. 10-12
state about a configuration of the three-centred-wheel robot, and :func:`beta_text`,
:func:`config_lines` say it in Markdown.  No matplotlib.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr.analysis import lines as ln
from wmr.analysis import singularities as sg
from wmr.analysis.linalg import condition_number
from wmr.analysis.mobility import rank_F

from ..text import degrees
from ..text import residual as residual_text
from .common import ABS_DET_J, L_PAPER, drawing, exact_det_J, residual, snap

__all__ = ["AxleMeet", "axles_meet", "SingularConfig", "singular_config", "beta_text", "config_lines"]


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
    point: tuple | None
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
    return AxleMeet(
        meet.kind.name.lower(),
        tuple(map(float, meet.point)),
        float(np.linalg.norm(meet.point - np.asarray(target, dtype=float))),
    )


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
    D_P: tuple | None = None
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
        if kind == ln.COINCIDENT:  # a coincident pair: each line reaches the other's P
            plane_reach[i - 1].append(P[j - 1])
            plane_reach[j - 1].append(P[i - 1])
    axle_reach: list[list] = [[] for _ in range(3)]
    crossings = []
    for (i, j), (kind, pt) in axles.items():
        if kind == ln.FINITE and pt is not None and np.linalg.norm(pt) < reach:
            crossings.append(pt)
            axle_reach[i - 1].append(pt)
            axle_reach[j - 1].append(pt)
    rk = int(rank_F(robot, b))
    exact = "" if exact_deg is None else str(exact_det_J(exact_deg, r=robot.wheels[0].r))
    return SingularConfig(
        beta_deg=tuple(float(v) for v in (np.degrees(b) if exact_deg is None else exact_deg)),
        det_J=float(sg.det_J(robot, b)),
        det_J_exact=exact,
        rank_F=rk,
        mobility=3 + robot.n_rates - rk,
        kappa_J=float(condition_number(robot.J(b, L=L_PAPER))),
        singular=bool(sg.is_singular(robot, b)),
        planes_meet=conc.kind.name.lower(),
        D_P=None if conc.point is None else tuple(map(float, conc.point)),
        axles_meet=ln.axles_concurrency(robot, b).kind.name.lower(),
        axle_crossings=tuple(tuple(map(float, p)) for p in crossings),
        coincident=tuple(k for k, v in planes.items() if v[0] == ln.COINCIDENT),
        family=sg.classify(robot, b).family,
        beta=snap(b),
        plane_reach=tuple(snap(np.reshape(r_, (-1, 2))) for r_ in plane_reach),
        axle_reach=tuple(snap(np.reshape(r_, (-1, 2))) for r_ in axle_reach),
    )


def beta_text(beta_deg, digits=6):
    r"""``$\beta_1 = 60^\circ$, $\beta_2 = ...$`` for angles in degrees.

    Parameters
    ----------
    beta_deg : sequence of float
        Steering angles (degrees).
    digits : int, optional
        Significant digits (:func:`edition.text.degrees`).

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
    r"""Lines of text stating :math:`\det\mathbf J` (58) (exact and float), rank F, mobility and
    :math:`\kappa(\mathbf J)` (30).

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
    lines = [
        rf"$\det\mathbf{{J}} = {cfg.det_J_exact}$ (exact), ${det}$ (float)" if cfg.det_J_exact else rf"${det}$ (float)",
        rf"rank $\mathbf{{F}}$ = {cfg.rank_F}, mobility {cfg.mobility}",
    ]
    if kappa:
        k = cfg.kappa_J
        lines.append(r"$\kappa(\mathbf{J}) = \infty$" if not np.isfinite(k) else rf"$\kappa(\mathbf{{J}}) = {k:.3g}$")
    return lines
