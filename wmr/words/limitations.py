r"""What a robot cannot do, in plain sentences: the words of :mod:`wmr.analysis.limitations`' records.

Examples
--------
>>> import numpy as np, wmr
>>> skid = wmr.Robot([wmr.FixedWheel((x, y), r=0.1, angle=np.pi / 2) for x in (0.4, 0.0, -0.4) for y in (0.3, -0.3)])
>>> sentences(skid)
['turning requires skidding: it can only drive straight ahead (along x)']
"""

from __future__ import annotations

from ..analysis.actuation import Motion, MotionKind, motion
from ..analysis.limitations import Limitation, LimitationKind, limitations

__all__ = ["where", "describe_twist", "sentence", "sentences"]

_FIXED = {
    LimitationKind.NO_MOTION: "it cannot move at all without skidding: its wheels' constraints admit no motion",
    LimitationKind.CAR_LIKE: "it cannot move sideways or choose its centre of rotation freely: every motion turns "
    "about a point on the line of its fixed wheels' axles (or drives straight along their planes), and steering "
    "picks the point (car-like)",
    LimitationKind.ONE_MOTION: "at any one steering it has a single motion: to change the direction of motion it "
    "must re-steer its wheels first (it cannot change direction instantly)",
}


def where(m: Motion) -> str:
    """Where a motion takes the robot, in plain words to follow "moves": a direction, or a turn and its centre.

    Parameters
    ----------
    m : wmr.analysis.actuation.Motion

    Returns
    -------
    str
    """
    if m.kind is MotionKind.TRANSLATION:
        a = m.heading or 0.0
        if abs(a) < 0.5:
            return "straight ahead (along x)"
        if abs(abs(a) - 90.0) < 0.5:
            return "sideways (along y)"
        return f"diagonally (along {a:.0f} deg from x)"
    if m.kind is MotionKind.STILL:
        return "nowhere (standing still)"
    if m.kind is MotionKind.SPIN:
        return "on the spot (turning about C)"
    x, y = m.centre or (0.0, 0.0)
    return f"in a turn about the point ({x:.3g}, {y:.3g}) m"


def describe_twist(robot, twist) -> str:
    """Where a twist moves the robot, in plain words (:func:`wmr.analysis.actuation.motion`, then :func:`where`).

    Parameters
    ----------
    robot : Robot
        For its size (what counts as a translation and a spin).
    twist : array (3,)
        :math:`[\\dot\\psi, \\dot x, \\dot y]`, body frame; only its direction matters (either sign).

    Returns
    -------
    str

    Examples
    --------
    >>> import wmr
    >>> bot = wmr.paper_robot("centred")
    >>> describe_twist(bot, [0.0, 1.0, 1.0]), describe_twist(bot, [0.0, 0.0, -2.0])
    ('diagonally (along 45 deg from x)', 'sideways (along y)')
    >>> describe_twist(bot, [1.0, 0.0, 0.0]), describe_twist(bot, [1.0, 0.0, -1.0])
    ('on the spot (turning about C)', 'in a turn about the point (1, 0) m')
    """
    return where(motion(robot, twist))


def sentence(x: Limitation) -> str:
    """A limitation in one plain sentence.

    Parameters
    ----------
    x : wmr.analysis.limitations.Limitation

    Returns
    -------
    str
    """
    K = LimitationKind
    what = " or ".join(where(m) for m in x.motions) or "one direction"
    if x.kind in _FIXED:
        return _FIXED[x.kind]
    if x.kind is K.NO_TURNING:
        return f"turning requires skidding: it can only drive {what}"
    if x.kind is K.NO_STRAIGHT:
        return f"driving straight requires skidding: it can only move {what}"
    if x.kind is K.FORBIDDEN:
        return f"it cannot move {what}: no motion may have a part of that (non-holonomic, like a differential drive)"
    if x.kind is K.FORBIDDEN_AT_STEERING:
        return f"at any one steering it cannot move {what}: that needs its steered wheel re-steered first"
    if x.kind is K.UNCONTROLLED:
        return (
            f"the motors cannot move it {what}: it moves that way with every motor stopped (its passive joints roll "
            f"freely), so the motors can neither drive nor stop that motion (actuated mobility {x.actuated_mobility} "
            f"< delta_m = {x.delta_m})"
        )
    return (
        f"wheel {(x.unit or 0) + 1}: its steering joint is passive and nothing turns it (no motor, no offset to trail "
        "behind): its angle is not under control"
    )


def sentences(robot, campion=None) -> list[str]:
    """What the robot cannot do, as plain sentences (:func:`wmr.analysis.limitations.limitations` in words).

    Parameters
    ----------
    robot : Robot
        A numeric robot.
    campion : CampionClass, optional
        Its class (:func:`wmr.campion_class`), when already computed.

    Returns
    -------
    list of str
    """
    return [sentence(x) for x in limitations(robot, campion)]
