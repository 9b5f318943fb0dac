r"""What the figures share, without matplotlib: robots, exact det J, circle fit, snapping, JSON, singular
configurations.

The robots drawn (:func:`centred_robot`), exact :math:`\det\mathbf J` (:func:`exact_det_J`), circle
fitting and how a figure's data becomes JSON (:func:`numbers`).  The numbers of one configuration
(where the axles meet, a singular configuration) are in :mod:`edition.figures.configs`.

The data classes of the figures mark each field with how it is written to ``<key>.json``
(:func:`numbers`): a :func:`residual` (round-off, printed as a bound by
:func:`edition.text.bound`), a :func:`small` value (an integration error: two significant
digits), an ordinary value (rounded by :func:`edition.text.rounded`), or a :func:`drawing`
field (arrays for the picture, not written).  Arrays for the picture are :func:`snap`-ped, so
that round-off differences between machines do not reach the coordinates in the SVG and PDF files.
"""

from __future__ import annotations

import dataclasses
from dataclasses import field
from functools import cache

import numpy as np

from wmr.analysis import singularities as sg
from wmr.model.robots import paper_robot
from wmr.plot.snapping import snap

from ..text import bound, rounded

__all__ = [
    "L_PAPER",
    "R_CENTRED",
    "R_OFFSET",
    "DEG",
    "ABS_DET_J",
    "MAX_PSI",
    "centred_robot",
    "exact_det_J",
    "fit_circle",
    "snap",
    "snapped",
    "residual",
    "small",
    "drawing",
    "numbers",
]

L_PAPER = 1.0  #: distance of the mount points from C in the figures (the unit of length)
R_CENTRED = 0.25  #: wheel radius of the centred-wheel robot in the figures
R_OFFSET = 0.3  #: wheel radius (= offset d) of the offset-wheel robot in Fig. 7
DEG = np.pi / 180
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


@cache
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
    rhs = np.sum(xy**2, axis=1)
    (a, b, c), *_ = np.linalg.lstsq(A, rhs, rcond=None)
    centre = np.array([a / 2, b / 2])
    return centre, float(np.sqrt(c + centre @ centre))


def snapped(data):
    """A figure's data with every value it draws from :func:`~wmr.plot.snapping.snap`-ped.

    Walks the data class, and the data classes, tuples, lists and dicts inside it, and snaps the
    floats and float arrays of its value and drawing fields.  Residual and small fields are left
    alone: their text is already a bound or two digits (:func:`numbers`).  Objects that are not
    data of a figure (a robot) are kept as they are.

    Parameters
    ----------
    data : dataclass instance
        ``FIGURES[key].data()``.

    Returns
    -------
    dataclass instance
        Of the same class.

    Examples
    --------
    >>> from edition.figures import fig13
    >>> snapped(fig13.data()).beta.tolist() == snap(fig13.data().beta).tolist()
    True
    """
    return _snapped(data)


def _snapped(x):
    if dataclasses.is_dataclass(x) and not isinstance(x, type):
        if not type(x).__module__.startswith(__package__):
            return x
        kept = ("residual", "small")
        return dataclasses.replace(
            x,
            **{
                f.name: getattr(x, f.name) if f.metadata.get("json") in kept else _snapped(getattr(x, f.name))
                for f in dataclasses.fields(x)
                if f.init
            },
        )
    if isinstance(x, (float, np.floating)):
        return float(snap(x))
    if isinstance(x, np.ndarray):
        return snap(x) if x.dtype.kind == "f" else x
    if isinstance(x, (tuple, list)):
        return type(x)(_snapped(v) for v in x)
    if isinstance(x, dict):
        return {k: _snapped(v) for k, v in x.items()}
    return x


# --------------------------------------------------------------------------- fields and JSON
def residual(**kw):
    """A field holding a value that is zero up to round-off (JSON: :func:`edition.text.bound` of its magnitude).

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
