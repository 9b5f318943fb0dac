r"""The exercises of the design study (``notebooks/08_design_study``): one check function each.

As in :mod:`edition.exercises`: the student writes an answer and calls the check, which returns a
:class:`~edition.exercises.feedback.Result` computed from the model (never compared with a typed-in
answer), made fair by :func:`edition.exercises.framework.exercise`; ``None`` gives "no answer yet".

==================================  ========================================================================
check                               the exercise
==================================  ========================================================================
:func:`offset_for_worst_case`       the offset that gives a prescribed worst-case :math:`\kappa(\mathbf J)`
:func:`scalene_optimum`             a scalene triangle of offset wheels with worst-case :math:`\kappa = 1`
:func:`singular_rotation`           a centre of rotation at which the swerve's :math:`\mathbf J` is singular
==================================  ========================================================================

:func:`describe_design` summarises a robot of the reader's own ("your own robot" cells).
"""

from __future__ import annotations

import numpy as np

from wmr.analysis.design import WheelDesign, equilateral_design, worst_kappa
from wmr.analysis.motion_kappa import motion_kappa, motion_map, mount_circle, rotation_twists
from wmr.model import validation as V
from wmr.model.robot import Robot
from wmr.model.wheels import CentredWheel

from .exercises import answers
from .exercises.feedback import right, wrong
from .exercises.framework import exercise
from .exercises.tolerance import decimals, sig_figs, within
from .text import number

__all__ = [
    "TOL_8_1",
    "TOL_8_2",
    "TOL_8_3",
    "swerve",
    "design_row",
    "offset_for_worst_case",
    "scalene_optimum",
    "singular_rotation",
    "describe_design",
]


def swerve(length=0.6, width=0.4, r=0.05):
    """A swerve drive: four centred wheels (modules) at the corners of a ``length`` x ``width`` rectangle centred at C.

    Parameters
    ----------
    length : float
        Side along body x, > 0.
    width : float
        Side along body y, > 0.
    r : float
        Wheel radius, > 0.

    Returns
    -------
    Robot
    """
    a = V.number("length", V.positive("length", length)) / 2
    b = V.number("width", V.positive("width", width)) / 2
    corners = [(a, b), (-a, b), (-a, -b), (a, -b)]
    return Robot([CentredWheel(p, r=r) for p in corners], name=f"swerve {length:g} x {width:g}")


def design_row(name, design, kappa):
    r"""One row of a table of designs: offset ratio, sides, centroid offset, worst case.

    Parameters
    ----------
    name : str
    design : WheelDesign
    kappa : float
        Its worst-case :math:`\bar\kappa`.

    Returns
    -------
    dict
    """
    return {
        "design": name,
        "$d/r$": design.ratio,
        "sides": design.sides(),
        "C to centroid / RMS radius": design.centroid_offset(),
        r"$\bar\kappa$": kappa,
        r"$\bar\kappa - 1$": kappa - 1,
    }


#: exercise 8.1: the offset to 3 significant figures; 8.2: the worst case equal to 1 to 2 decimal places;
#: 8.3: the centre to the millimetre
TOL_8_1 = sig_figs(3)
TOL_8_2 = decimals(2)
TOL_8_3 = within("to the millimetre", abs=1e-3)


@exercise("8.1", answer="an offset in metres", tolerance=TOL_8_1)
def offset_for_worst_case(d, r=0.05, kappa=1.25, radius=0.3):
    r"""Exercise 8.1: the offset :math:`d \le r` that gives the paper's placement a worst-case :math:`\kappa(\mathbf J)`
    of ``kappa``.

    The worst case of the student's offset is computed (:func:`wmr.analysis.design.worst_kappa`) and
    compared with ``kappa`` to the relative tolerance of 3 significant figures of ``d``
    (:math:`\bar\kappa = r/d` for :math:`d \le r`, so the relative errors are the same).

    Parameters
    ----------
    d : float
        The student's offset (m).
    r : float, optional
        Wheel radius (m).
    kappa : float, optional
        The prescribed worst case.
    radius : float, optional
        Mount radius :math:`|\mathbf d_i|` (m).

    Returns
    -------
    Result
    """
    d = answers.number(d, "an offset in metres")
    if d < 0:
        return wrong("An offset is a distance: it cannot be negative.")
    if d == 0:
        return wrong(
            r"With $d = 0$ the units are centred wheels: $\mathbf J_2$ and $\mathbf J$ are singular in every "
            r"configuration ($\kappa = \infty$)."
        )
    design = equilateral_design(d / r).scaled(radius)
    got = worst_kappa(WheelDesign(design.mounts, d, r).robot()).kappa
    if not TOL_8_1.accepts(got, kappa):
        return wrong(
            f"With $d = {number(d, 4)}$ m the worst case is $\\bar\\kappa = {number(got, 4)}$, not ${number(kappa)}$."
        )
    if d > r:
        return wrong(
            f"$d = {number(d, 4)}$ m gives $\\bar\\kappa = {number(got, 4)}$ too, but it is larger than $r$: "
            "find the smaller offset (a smaller dead zone)."
        )
    return right(f"$d = {number(d, 4)}$ m: $\\bar\\kappa = {number(got, 4)} = r/d$, whatever the mount radius.")


@exercise("8.2", answer="three mount points, e.g. `[(x1, y1), (x2, y2), (x3, y3)]`", tolerance=TOL_8_2)
def scalene_optimum(points):
    r"""Exercise 8.2: three mount points, no two sides equal, with worst-case :math:`\kappa(\mathbf J) = 1` at
    :math:`d = r` (to 2 decimal places).

    Parameters
    ----------
    points : array_like (3, 2)

    Returns
    -------
    Result
    """
    pts = answers.array(points, (3, 2), "three mount points, an array of shape (3, 2)")
    scale = float(np.abs(pts).max())
    if scale == 0:
        return wrong("All three points are C itself: there is no triangle.")
    pts = pts / scale  # any unit: r = 1 on the points' scale
    e1, e2 = pts[1] - pts[0], pts[2] - pts[0]
    if abs(e1[0] * e2[1] - e1[1] * e2[0]) <= 1e-6:
        return wrong(
            "The three points are collinear: the wheels cannot steer the platform's rotation well. Make a triangle."
        )
    design = WheelDesign(pts, 1.0, 1.0)
    s = np.sort(design.sides())
    if np.min(np.diff(s)) <= 1e-3 * s[-1]:
        return wrong("Two sides of your triangle are equal: make it scalene.")
    got = worst_kappa(design.robot()).kappa
    if not TOL_8_2.accepts(got, 1.0):
        return wrong(
            f"Worst case $\\bar\\kappa = {number(got, 4)}$: the centroid of your points is "
            f"${number(design.centroid_offset())}$ RMS radii away from C."
        )
    return right(
        f"Sides ${', '.join(number(x) for x in s * scale)}$: $\\bar\\kappa = {number(got, 4)}$. Only the "
        "centroid matters (37); the equal distances of (38) are not needed."
    )


@exercise("8.3", answer="a point `(x, y)` in metres", tolerance=TOL_8_3)
def singular_rotation(U, length=0.6, width=0.4):
    r"""Exercise 8.3: a centre of rotation U (not a module, not at infinity) at which the swerve's :math:`\mathbf J` is
    singular, to the millimetre.

    :math:`\kappa(\mathbf J) = \infty` exactly on the circle through the four modules and grows without bound
    towards it, so the check measures the distance of U from that circle
    (:func:`wmr.analysis.motion_kappa.mount_circle`), and gives :math:`\kappa(\mathbf J)` only for a
    point outside the tolerance.

    Parameters
    ----------
    U : array_like (2,)
        The centre, body frame (m).
    length : float, optional
        The swerve's side along body x (m).
    width : float, optional
        Its side along body y (m).

    Returns
    -------
    Result
    """
    U = answers.vector(U, 2, "a point `(x, y)` in metres")
    bot = swerve(length, width)
    if np.min(np.linalg.norm(bot.mount_points - U, axis=1)) <= TOL_8_3.abs:
        return wrong("U is a module's mount point: that module does not roll. Choose another point.")
    circle = mount_circle(bot)
    assert circle is not None  # four modules on a rectangle: concyclic
    c, R = circle
    gap = abs(float(np.linalg.norm(U - c)) - R)
    if gap <= TOL_8_3.allowed(R):
        return right(
            r"U lies on the circle through the four modules (to the millimetre), where "
            r"$\kappa(\mathbf J) = \infty$: the robot turns about U, yet $\mathbf J$ is singular."
        )
    k = float(motion_kappa(bot, rotation_twists(U)))
    return wrong(f"About this U, $\\kappa(\\mathbf J) = {number(k)}$: $\\mathbf J$ is not singular here.")


def describe_design(robot):
    r"""A short Markdown summary of a robot's conditioning: worst case over configurations, and along its motions.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    str
    """
    robot = V.numeric_robot(robot)
    wc = worst_kappa(robot, refine=False)
    text = f"{robot.w} units: worst-case $\\kappa(\\mathbf J) = {_k(wc.kappa)}$ over {wc.count:,} configurations"
    if all(u.kind in ("centred", "dual") for u in robot.wheels):
        mm = motion_map(robot, n=61)
        text += (
            f"; along its motions: smallest ${mm.kappa_min:.4g}$ (rotation about ({mm.argmin[0]:.3g}, "
            f"{mm.argmin[1]:.3g})), translation ${_k(mm.kappa_translation)}$, "
            + ("singular on the circle through the mount points" if mm.circle else "mount points not concyclic")
        )
    return text + "."


def _k(x):
    return r"\infty" if np.isinf(x) else f"{x:.4g}"
