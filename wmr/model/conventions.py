r"""Conventions used everywhere in :mod:`wmr` (stated once, here).

The drawing is ``figures/conventions.svg`` (made by :func:`edition.figures.conventions`).

Frames
    :math:`\mathcal F` is fixed, :math:`\mathcal B` is attached to the platform with origin at the
    operation point C; :math:`\psi` is the angle from :math:`\mathbf i_{\mathcal F}` to :math:`\mathbf i`,
    counter-clockwise positive seen from above (:math:`\mathbf k` points up).  All angles are in
    radians and counter-clockwise positive.
Twist
    :math:`\mathbf t = [\dot\psi\ \dot x\ \dot y]^T` with :math:`\dot{\mathbf c} = [\dot x\ \dot y]^T`
    in **body-frame** components (25); the fixed-frame velocity is :math:`[\dot X\ \dot Y]^T =
    \mathbf R(\psi)\dot{\mathbf c}`.  :math:`\mathbf t_L = [L\dot\psi\ \dot{\mathbf c}^T]^T` (33).  A
    :class:`Twist` names them (``Twist(omega=..., vx=..., vy=...)``) and is taken wherever a twist is;
    another library's twist object is read by its fields, never by its order.
Mount points
    :math:`\mathbf d_i = \overrightarrow{CP_i}` in the body frame; :math:`P_i` lies on the steering axis.
Wheel frame
    :math:`\beta_i` is the angle of the intermediate body relative to the platform,
    :math:`\mathbf R_{bwi} = \mathbf R(\beta_i)` (11); :math:`\mathbf i_i = \mathbf R_{bwi}[1\ 0]^T` is
    the axle (axis of rolling), :math:`\mathbf j_i = \mathbf R_{bwi}[0\ 1]^T` the rolling direction in
    the wheel plane.  The absolute steering angle is :math:`\phi_i = \psi + \beta_i` (8).
Rolling
    :math:`\dot\theta_i` is the wheel's spin about :math:`\mathbf i_i` (right-hand rule); no slip
    gives :math:`\dot{\mathbf h}_i = -r\dot\theta_i\mathbf j_i` (6).
Offset
    The wheel centre of an offset wheel is :math:`H_i = P_i - d\,\mathbf j_i` (:math:`d \ge 0`), which
    gives (9) with the printed signs.
Dual wheel
    Wheel 1 at :math:`H_i + b\,\mathbf i_i`, wheel 2 at :math:`H_i - b\,\mathbf i_i`, :math:`H_i = P_i`.
Fixed and Swedish wheels
    No steering joint: :math:`\beta_i` is the unit's constant ``angle`` (0: axle along the body x
    axis), and the robot's configuration entry for the unit is ignored
    (:meth:`wmr.Robot.effective_beta`).  A Swedish wheel's rollers are at ``roller`` =
    :math:`\gamma` from the axle, counter-clockwise (:math:`\pi/2` omni, :math:`\pm\pi/4` mecanum);
    its second rate :math:`\dot\sigma_i` moves the hub along the rollers' rolling direction
    (:class:`wmr.SwedishWheel`).
Units
    Python takes radians (every signature says so) and, where a name ends in ``_deg`` (a robot
    file's ``angle_deg``, ``roller_deg``, and the same keywords of :class:`wmr.FixedWheel` and
    :class:`wmr.SwedishWheel`), degrees; the command line takes and prints degrees (every option
    says so).  A constant angle beyond :math:`\pm 2\pi` rad is refused (it is almost surely in degrees).
Actuation
    Every joint of a unit is driven (a motor) or passive (:mod:`wmr.model.wheels.joints`), with a
    default per kind: Swedish rollers, castor swivels and dual-wheel swivels passive, steering and
    wheel drives driven (``driven=`` and a robot file's ``driven`` table change it).  A motion that
    needs a passive joint to move by itself is not admissible for the motors (:mod:`wmr.analysis.actuation`).
Numbering
    Wheels are numbered in the order given to :class:`wmr.Robot`.  The paper's three-wheel robot
    (:func:`wmr.paper_robot`) has :math:`\mathbf d_1 = L(-1,0)`, :math:`\mathbf d_2 = L(\tfrac12,
    \tfrac{\sqrt3}2)`, :math:`\mathbf d_3 = L(\tfrac12,-\tfrac{\sqrt3}2)`: numbered clockwise from
    the negative x-axis, the one placement under which the printed (59) holds.
Tolerance
    One numerical zero, :data:`wmr.model.tolerance.TOL`, always relative: every decision is the same
    in every unit of length and time (how: :mod:`wmr.model.tolerance`).
Errors
    Bad input raises :class:`~wmr.errors.InputTypeError` (the wrong kind of argument, a
    ``TypeError``) or :class:`~wmr.errors.InputValueError` (a bad value, a ``ValueError``); the
    message names the argument and shows the value (:mod:`wmr.model.validation`).  A malformed
    robot file raises :class:`~wmr.errors.RobotFileError`.  Any other exception is a bug.

Other libraries' conventions (:data:`CONVENTIONS`)
--------------------------------------------------
The frames agree: WPILib's robot frame and ROS's ``base_link`` (REP-103) are x forward, y left,
counter-clockwise positive, as wmr's body frame; mount points are WPILib's module ``Translation2d``.
Two things differ, and are translated at the edges only, by this module (``--convention`` on the
command line; :func:`angle_to`, :func:`angle_from`, :func:`twist_to`, :func:`twist_from`, by
:data:`TWIST_ORDER`; twist objects are read by field by :func:`wmr.model.checks.twist_array`, which
the array checks below this module need, and WPILib's are made by :mod:`wmr.io.wpilib`):

``wmr``
    Angles are the axle's, :math:`\beta_i` (0: axle along x, the wheel rolls along y); twists
    :math:`[\dot\psi, \dot x, \dot y]` (the paper's order).
``wpilib``
    A module's angle is its direction of travel at positive speed: no slip gives the wheel-centre
    velocity :math:`r\dot\theta_i(\sin\beta_i, -\cos\beta_i)` (6), WPILib's is
    :math:`s_i(\cos\alpha_i, \sin\alpha_i)`, so :math:`\alpha_i = \beta_i - \pi/2` (0: rolls forward)
    and the speed :math:`s_i = r_i\dot\theta_i`; twists ``ChassisSpeeds(vx, vy, omega)``.
``ros``
    REP-103: a wheel's steering angle is its heading from x (as WPILib), twists
    ``geometry_msgs/Twist`` ``(linear.x, linear.y, angular.z)``, in SI units (the command line still
    writes angles in degrees).

Where things live
-----------------
``wmr/`` is the library, in layers, each importing only from the ones before it (``tests/test_structure.py``):
:mod:`wmr.errors` and :mod:`wmr.model` (what a robot *is*: the backends, the tolerance, the input checks,
the platform, the wheel units, :class:`wmr.Robot`, ready-made robots, the limits, these conventions);
:mod:`wmr.analysis` (what can be computed for *any* robot); :mod:`wmr.io`, :mod:`wmr.swerve` and
:mod:`wmr.odometry` (robots in and out, swerve-drive practice, wheel odometry); :mod:`wmr.sim`,
:mod:`wmr.words` and :mod:`wmr.plot` (MuJoCo and matplotlib imported only there); :mod:`wmr.cli`, the
``wmr`` command line.  ``import wmr`` loads the first two layers.  Beside it, ``edition/`` (the paper's
edition) imports :mod:`wmr`, never the other way, and ``tools/build`` builds the report from both;
the README's *Layout* lists every folder.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..errors import InputValueError
from .checks import finite_array, kind_error, twist_array, twist_kind
from .platform import wrap_angle
from .types import ArrayLike, FloatArray, TwistLike

__all__ = ["CONVENTIONS", "TWIST_ORDER", "Twist", "angle_to", "angle_from", "twist_to", "twist_from"]

#: the conventions a user can bring, in one line each (see the module notes)
CONVENTIONS = {
    "wmr": "angles of the axles (0: the wheel rolls along y), twist (omega, vx, vy)",
    "wpilib": "module angles = direction of travel (0: forward), twist ChassisSpeeds(vx, vy, omega)",
    "ros": "REP-103: wheel headings from x (0: forward), twist (linear.x, linear.y, angular.z)",
}
#: the order a convention writes a twist in, by wmr's names of its components
TWIST_ORDER = {"wmr": ("omega", "vx", "vy"), "wpilib": ("vx", "vy", "omega"), "ros": ("vx", "vy", "omega")}
#: what a convention's angle is, added to wmr's axle angle beta (radians)
_OFFSET = {"wmr": 0.0, "wpilib": -np.pi / 2, "ros": -np.pi / 2}


def checked(convention: object) -> str:
    """``convention`` checked: one of :data:`CONVENTIONS`."""
    if not isinstance(convention, str) or convention not in CONVENTIONS:
        raise kind_error("convention", convention, f"one of {', '.join(CONVENTIONS)}")
    return convention


def angle_to(beta: ArrayLike, convention: str) -> FloatArray:
    r"""wmr's steering angles :math:`\beta` (radians) in the ``convention`` (radians, in :math:`(-\pi, \pi]`).

    Parameters
    ----------
    beta : array (...)
    convention : str
        A key of :data:`CONVENTIONS`.

    Returns
    -------
    numpy.ndarray (...)

    Examples
    --------
    >>> float(np.degrees(angle_to(np.pi / 2, "wpilib")))       # axle along y: the module rolls forward
    0.0
    """
    return wrap_angle(finite_array("beta", beta) + _OFFSET[checked(convention)])


def angle_from(angle: ArrayLike, convention: str, argument: str = "angle") -> FloatArray:
    r"""wmr's steering angles :math:`\beta` (radians) from angles in the ``convention`` (radians).

    Parameters
    ----------
    angle : array (...)
    convention : str
    argument : str, optional
        The name of ``angle`` in messages (the caller's argument).

    Returns
    -------
    numpy.ndarray (...)

    Examples
    --------
    >>> float(np.degrees(angle_from(0.0, "ros")))
    90.0
    """
    return wrap_angle(finite_array(argument, angle) - _OFFSET[checked(convention)])


def _order(convention: str) -> list[int]:
    """Where each of a convention's components is in wmr's twist (indices into ``[omega, vx, vy]``)."""
    return [TWIST_ORDER["wmr"].index(name) for name in TWIST_ORDER[checked(convention)]]


def twist_to(twist: TwistLike, convention: str) -> FloatArray:
    r"""Twists in the order the ``convention`` writes them (:data:`TWIST_ORDER`): WPILib's and ROS's :math:`(v_x, v_y, \omega)`.

    Parameters
    ----------
    twist : array (..., 3), Twist, or twist objects
        wmr's :math:`[\dot\psi, \dot x, \dot y]`; objects are read by their fields (:func:`wmr.model.checks.twist_array`).
    convention : str
        A key of :data:`CONVENTIONS`.

    Returns
    -------
    numpy.ndarray (..., 3)

    Examples
    --------
    >>> twist_to([3.0, 1.0, 2.0], "wpilib").tolist()
    [1.0, 2.0, 3.0]
    """
    return twist_array("twist", twist)[..., _order(convention)]


def twist_from(values: TwistLike, convention: str, argument: str = "twist") -> FloatArray:
    r"""wmr's twists :math:`[\dot\psi, \dot x, \dot y]` of numbers in the ``convention``'s order, or of twist objects.

    Parameters
    ----------
    values : array (..., 3), or twist objects (a WPILib ``ChassisSpeeds``, a list of them, ...)
        Numbers in the order of :data:`TWIST_ORDER` ``[convention]``; a :class:`Twist` and objects are
        read by their names, whatever the convention (:func:`wmr.model.checks.twist_array`).
    convention : str
        A key of :data:`CONVENTIONS`.
    argument : str, optional
        The name of ``values`` in messages (the caller's argument).

    Returns
    -------
    numpy.ndarray (..., 3)

    Examples
    --------
    >>> twist_from([1.0, 2.0, 3.0], "wpilib").tolist()
    [3.0, 1.0, 2.0]
    """
    order = _order(convention)
    first = values[0] if type(values) in (list, tuple) and values else values
    if isinstance(first, Twist) or twist_kind(first) is not None:  # its components named: read by name
        return twist_array(argument, values)
    return finite_array(argument, values, last=3)[..., np.argsort(order)]


class Twist(NamedTuple):
    r"""One twist with its components by name, in wmr's order :math:`[\dot\psi, \dot x, \dot y]`.

    Wherever wmr takes a twist it takes a :class:`Twist`: it is a tuple in wmr's order, so it is read as
    the numbers ``[omega, vx, vy]`` are, and a list of them as an array (n, 3).  A bare list is easy to
    write in another library's order (WPILib's and ROS's are ``(vx, vy, omega)``); the names are not.

    Parameters
    ----------
    omega : float
        The turning rate :math:`\dot\psi`, rad/s, counter-clockwise positive.
    vx, vy : float
        The velocity of C in the body frame, :math:`\dot x` (forward) and :math:`\dot y` (left), in the
        robot's unit of length per second.

    Examples
    --------
    >>> import wmr
    >>> t = wmr.Twist(omega=0.5, vx=1.0, vy=0.0)
    >>> wmr.inverse(wmr.paper_robot("centred"), [0.0, 0.0, 0.0], t).value.shape
    (3,)
    >>> t.in_convention("wpilib"), Twist.of([0.5, 1.0, 0.0]) == t
    ((1.0, 0.0, 0.5), True)
    """

    omega: float
    vx: float
    vy: float

    @classmethod
    def of(cls, twist: TwistLike) -> Twist:
        """The :class:`Twist` of one twist in any form wmr takes: numbers in wmr's order, or a twist object.

        Parameters
        ----------
        twist : array (3,), Twist, or a WPILib ``ChassisSpeeds``, ``Twist2d`` or ROS ``geometry_msgs/Twist``
            Objects are read by their fields (:func:`wmr.model.checks.twist_array`).

        Returns
        -------
        Twist
        """
        t = twist_array("twist", twist)
        if t.size != 3:
            raise InputValueError(f"twist must be one twist (3,), got shape {t.shape}")
        return cls(*(float(v) for v in t.reshape(3)))

    def in_convention(self, convention: str) -> tuple[float, float, float]:
        """The components in the order a convention writes them (:data:`TWIST_ORDER`).

        Parameters
        ----------
        convention : str
            A key of :data:`CONVENTIONS`.

        Returns
        -------
        tuple of 3 float
        """
        return tuple(float(self[k]) for k in _order(convention))  # type: ignore[return-value]
