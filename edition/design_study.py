r"""The exercises of the design study (``notebooks/08_design_study``): one check function each.

As in :mod:`edition.exercises`: the student writes an answer and calls the check, which returns a
:class:`~edition.exercises.Feedback` computed from the model (never compared with a typed-in
answer); ``None`` gives "no answer yet" without failing.

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

from .exercises import Feedback

__all__ = ["swerve", "design_row", "offset_for_worst_case", "scalene_optimum", "singular_rotation", "describe_design"]


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
    return {"design": name, "$d/r$": design.ratio, "sides": design.sides(),
            "C to centroid / RMS radius": design.centroid_offset(), r"$\bar\kappa$": kappa,
            r"$\bar\kappa - 1$": kappa - 1}


def _none(answer, what):
    return Feedback(False, f"No answer yet: replace `None` by {what}.") if answer is None else None


def offset_for_worst_case(d, r=0.05, kappa=1.25, radius=0.3):
    r"""Exercise 8.1: the offset :math:`d \le r` that gives the paper's placement a worst-case :math:`\kappa(\mathbf J)`
    of ``kappa``.

    Parameters
    ----------
    d : float or None
        The student's offset (m).
    r : float, optional
        Wheel radius (m).
    kappa : float, optional
        The prescribed worst case.
    radius : float, optional
        Mount radius :math:`|\mathbf d_i|` (m).

    Returns
    -------
    Feedback
    """
    fb = _none(d, "an offset in metres")
    if fb is not None:
        return fb
    try:
        d = float(V.number("d", V.nonnegative("d", d)))
    except (TypeError, ValueError) as e:
        return Feedback(False, f"The offset must be a number >= 0: {e}.")
    if d == 0:
        return Feedback(False, r"With $d = 0$ the units are centred wheels: $\mathbf J_2$ and $\mathbf J$ are singular "
                               r"in every configuration ($\kappa = \infty$).")
    design = equilateral_design(d / r).scaled(radius)
    got = worst_kappa(WheelDesign(design.mounts, d, r).robot()).kappa
    if abs(got - kappa) > 1e-3 * kappa:
        return Feedback(False, f"With $d = {d:g}$ m the worst case is $\\bar\\kappa = {got:.4f}$, not ${kappa:g}$.")
    if d > r:
        return Feedback(False, f"$d = {d:g}$ m gives $\\bar\\kappa = {got:.4f}$ too, but it is larger than $r$: "
                               "find the smaller offset (a smaller dead zone).")
    return Feedback(True, f"$d = {d:g}$ m: $\\bar\\kappa = {got:.4f} = r/d$, whatever the mount radius.")


def scalene_optimum(points):
    r"""Exercise 8.2: three mount points, no two sides equal, with worst-case :math:`\kappa(\mathbf J) = 1` at
    :math:`d = r`.

    Parameters
    ----------
    points : array_like (3, 2) or None

    Returns
    -------
    Feedback
    """
    fb = _none(points, "three mount points, e.g. `[(x1, y1), (x2, y2), (x3, y3)]`")
    if fb is not None:
        return fb
    try:
        design = WheelDesign(np.asarray(points, dtype=float), 1.0, 1.0)
    except (TypeError, ValueError) as e:
        return Feedback(False, f"The points must be three pairs of numbers: {e}.")
    if design.mounts.shape != (3, 2):
        return Feedback(False, f"Give exactly three points, got {design.mounts.shape[0]}.")
    scale = float(np.abs(design.mounts).max()) or 1.0
    design = design.scaled(1.0 / scale)                             # any unit: r = 1 on the points' scale
    s = np.sort(design.sides())
    if np.min(np.diff(s)) <= 1e-3 * s[-1]:
        return Feedback(False, "Two sides of your triangle are equal: make it scalene.")
    got = worst_kappa(design.robot()).kappa
    if got > 1 + 1e-6:
        return Feedback(False, f"Worst case $\\bar\\kappa = {got:.4f}$: the centroid of your points is "
                               f"{design.centroid_offset():.3g} RMS radii away from C.")
    return Feedback(True, f"Sides {', '.join(f'{x:.3g}' for x in s)}: $\\bar\\kappa = {got:.4g}$. Only the centroid "
                          "matters (37); the equal distances of (38) are not needed.")


def singular_rotation(U, length=0.6, width=0.4):
    r"""Exercise 8.3: a centre of rotation U (not a module, not at infinity) at which the swerve's :math:`\mathbf J` is
    singular.

    Parameters
    ----------
    U : pair or None
        The centre, body frame (m).
    length : float, optional
        The swerve's side along body x (m).
    width : float, optional
        Its side along body y (m).

    Returns
    -------
    Feedback
    """
    fb = _none(U, "a point `(x, y)` in metres")
    if fb is not None:
        return fb
    try:
        U = np.array(V.point("U", U), dtype=float)
    except (TypeError, ValueError) as e:
        return Feedback(False, f"U must be a pair of numbers: {e}.")
    bot = swerve(length, width)
    size = float(np.abs(bot.mount_points).max())
    if np.min(np.linalg.norm(bot.mount_points - U, axis=1)) <= 1e-6 * size:
        return Feedback(False, "U is a module's mount point: that module does not roll. Choose another point.")
    k = float(motion_kappa(bot, rotation_twists(U)))
    if np.isfinite(k):
        return Feedback(False, f"About U = ({U[0]:g}, {U[1]:g}) the robot is well defined: "
                               f"$\\kappa(\\mathbf J) = {k:.3g}$.")
    circle = mount_circle(bot)
    assert circle is not None                      # kappa = inf about U: the mount points are concyclic
    c, R = circle
    return Feedback(True, f"$\\kappa(\\mathbf J) = \\infty$ about U: U is {np.linalg.norm(U - c):.4g} m from the "
                          f"centre, on the circle of radius {R:.4g} m through the four modules.")


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
        text += (f"; along its motions: smallest ${mm.kappa_min:.4g}$ (rotation about ({mm.argmin[0]:.3g}, "
                 f"{mm.argmin[1]:.3g})), translation ${_k(mm.kappa_translation)}$, "
                 + ("singular on the circle through the mount points" if mm.circle else "mount points not concyclic"))
    return text + "."


def _k(x):
    return r"\infty" if np.isinf(x) else f"{x:.4g}"
