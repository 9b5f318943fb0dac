r"""Any :class:`wmr.Robot` as a MuJoCo model (MJCF text): :func:`to_mjcf`.

A ground plane; the platform, a free body whose frame is wmr's body frame (origin C on the mount plane, x forward,
z up); under it each unit's bodies and joints (:mod:`wmr.sim.bodies`); a lock ``<name>_lock`` for every drive hinge
(an inactive joint equality: the paper's locked drive, when switched on); a keyframe ``start`` with the steering
angles :math:`\boldsymbol\beta_0` and the servo targets that hold them.  Unit ``i`` (from 1) has bodies, joints and
actuators ``u<i>_<name>`` (``u2_steer``, ``u3_swivel``); a wheel's contact geom is named after its body
(``u2_wheel``; ``u3_wheel1``).  The same bytes for the same robot and parameters on every CPU
(:func:`~wmr.sim.bodies.num`).
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..errors import InputTypeError, InputValueError
from ..io.mechanism import Mechanism
from ..model import validation
from ..model.robot import Robot
from ..model.types import ArrayLike
from ..model.wheels.joints import Joint, rate_columns
from .bodies import POSITION, body_xml, height_of, mechanisms, num, nums, servo
from .params import GRAVITY, Params

__all__ = ["Export", "export", "to_mjcf"]


@dataclass(frozen=True)
class Export:
    """An exported robot: the MJCF text and how its names map to wmr's units.

    Attributes
    ----------
    xml : str
    robot : Robot
    params : Params
    mechanisms : tuple of Mechanism
        One per unit, in the robot's order (:func:`wmr.io.mechanism.mechanism`); their
        joints carry the units' actuation.
    height : float
        Height of the mount plane, i.e. of C, above the ground at rest.
    beta0 : numpy.ndarray (w,)
        The steering angles of the keyframe ``start``.
    weight : float
        :math:`W = m g`, N.
    """

    xml: str
    robot: Robot
    params: Params
    mechanisms: tuple[Mechanism, ...]
    height: float
    beta0: np.ndarray
    weight: float

    @staticmethod
    def name(i: int, part: str) -> str:
        """The MuJoCo name of part ``part`` of unit ``i`` (0-based index): ``u<i+1>_<part>``.

        Parameters
        ----------
        i : int
        part : str

        Returns
        -------
        str
        """
        return f"u{i + 1}_{part}"

    @property
    def drive_names(self) -> tuple[str, ...]:
        """Every drive hinge (driven or not), each with its lock ``<name>_lock``: tuple of str."""
        return drive_names(self.mechanisms)

    @property
    def servo_names(self) -> tuple[str, ...]:
        """The servos (MuJoCo actuators) in the model's order: one per driven joint (tuple of str)."""
        return tuple(self.name(i, j.name) for i, m in enumerate(self.mechanisms) for j in m.joints if servo(j))

    def hinges(self) -> list[tuple[int, Joint, int | None]]:
        """Every joint of every unit, in MuJoCo's order, with what wmr's variables make of it.

        Returns
        -------
        list of tuple (int, Joint, int or None)
            ``(unit, joint, column)``: the unit's index (0-based), its joint (with the unit's
            actuation) and the column of the robot's rate vector that the joint's encoder gives
            (None: it gives none).
        """
        out = []
        for i, (u, m, sl) in enumerate(zip(self.robot.wheels, self.mechanisms, self.robot.rate_slices)):
            cols = rate_columns(u.joints)
            out += [(i, j, None if j.name not in cols else sl.start + cols[j.name]) for j in m.joints]
        return out


def drive_names(mechs: Sequence[Mechanism]) -> tuple[str, ...]:
    """The MuJoCo names of the drive hinges of the units' mechanisms (each has a lock)."""
    return tuple(Export.name(i, j.name) for i, m in enumerate(mechs) for j in m.joints if j.kind == "drive")


def _platform(robot, params, height):
    """Inertial and drawn plate of the platform: a uniform plate over the mount points' bounding box."""
    P = robot.mount_points
    lo, hi = P.min(axis=0), P.max(axis=0)
    size = np.maximum(hi - lo, 0.2 * max(float(np.abs(P).max()), height))  # a pair of wheels: still a plate
    t = 0.1 * float(size.min())
    a, b = size
    m = params.platform_mass
    inertia = (m * (b * b + t * t) / 12, m * (a * a + t * t) / 12, m * (a * a + b * b) / 12)
    com = P.mean(axis=0)
    centre = (lo + hi) / 2
    return (
        f'    <inertial pos="{nums(com[0], com[1], 0.0, scale=1.0)}" mass="{num(m)}" diaginertia="{nums(*inertia)}"/>\n'
        f'    <geom type="box" pos="{nums(centre[0], centre[1], t, scale=1.0)}" size="{nums(a / 2, b / 2, t / 2, scale=1.0)}" '
        f'contype="0" conaffinity="0" group="1" rgba="0.6 0.6 0.7 0.5"/>'
    )


def export(robot: Robot, beta: ArrayLike | None = None, params: Params | None = None, **changes: float) -> Export:
    r"""Export a robot: the MJCF text and the map from its names to wmr's units.

    Parameters
    ----------
    robot : Robot
        Its units' joints say which are driven (``driven=``; a castor is an offset wheel with both
        joints passive): a driven joint gets a servo, a passive one none.
    beta : array (w,), optional
        Steering angles of the keyframe ``start`` (default 0; unsteered units: their own angle).
    params : Params, optional
        Physical parameters (default :class:`Params`).
    **changes
        Parameters to change by name, e.g. ``sliding=0.6, torsional=0``.

    Returns
    -------
    Export

    Raises
    ------
    NotImplementedError
        If a unit cannot be represented faithfully (Swedish wheels: the unit says why).
    wmr.errors.InputError
        For bad input, naming the argument.
    """
    robot = validation.numeric_robot(robot)
    if params is not None and not isinstance(params, Params):
        raise InputTypeError(f"params must be a wmr.sim.Params, got {validation.show(params)}")
    params = (params or Params()).replace(**changes) if changes else (params or Params())
    beta0 = robot.effective_beta(np.zeros(robot.w) if beta is None else beta)
    if beta0.shape != (robot.w,):
        raise InputValueError(f"beta must be one vector of {robot.w} steering angles, got shape {beta0.shape}")
    height = height_of(robot)
    mechs = mechanisms(robot, height)
    n_bodies = sum(len(m.bodies) - len(m.wheels) for m in mechs)
    n_wheels = sum(len(m.wheels) for m in mechs)
    weight = params.total_mass(n_bodies, n_wheels) * GRAVITY
    xml = _write(robot, params, mechs, height, beta0, weight)
    return Export(xml, robot, params, mechs, height, beta0, weight)


def to_mjcf(robot: Robot, beta: ArrayLike | None = None, params: Params | None = None, **changes: float) -> str:
    """A MuJoCo model (MJCF text) of any :class:`wmr.Robot`: the ``xml`` of :func:`export`.

    Parameters
    ----------
    robot : Robot
    beta : array (w,), optional
    params : Params, optional
    **changes
        As for :func:`export`.

    Returns
    -------
    str
        MJCF; ``mujoco.MjModel.from_xml_string`` loads it.
    """
    return export(robot, beta, params, **changes).xml


def _actuator(name, kind, r, params, weight):
    """A servo: its torque limit a fraction of W r, its gain per unit of that limit (:mod:`wmr.sim.params`)."""
    if kind == POSITION:
        tau = params.steer_torque * weight * r
        return (
            f'    <position name="{name}" joint="{name}" kp="{num(params.steer_kp * tau)}" '
            f'dampratio="{num(params.steer_damping)}" forcerange="{nums(-tau, tau)}"/>'
        )
    tau = params.drive_torque * weight * r
    return (
        f'    <velocity name="{name}" joint="{name}" kv="{num(params.drive_kv * tau)}" forcerange="{nums(-tau, tau)}"/>'
    )


def _write(robot, params, mechs, height, beta0, weight):
    lines = [
        f'<mujoco model="{_escape(robot.name)}">',
        '  <compiler angle="radian" autolimits="true"/>',
        (
            f'  <option timestep="{num(params.timestep)}" integrator="{params.integrator}" cone="{params.cone}" '
            f'impratio="{num(params.impratio)}" jacobian="dense" gravity="0 0 {num(-GRAVITY)}">\n'
            '    <flag energy="enable"/>\n'
            "  </option>"
        ),
        "  <worldbody>",
        ('    <geom name="ground" type="plane" size="0 0 1" friction="0 0 0" contype="0" conaffinity="1" condim="6"/>'),
        f'    <body name="platform" pos="0 0 {num(height, 1.0)}">',
        '      <freejoint name="platform"/>',
        "  " + _platform(robot, params, height).replace("\n", "\n  "),
    ]
    for i, (u, m) in enumerate(zip(robot.wheels, mechs)):
        lines += body_xml(m.root, functools.partial(Export.name, i), float(u.r), params, 3)
    lines += ["    </body>", "  </worldbody>", "  <actuator>"]
    for i, (u, m) in enumerate(zip(robot.wheels, mechs)):
        lines += [_actuator(Export.name(i, j.name), servo(j), float(u.r), params, weight) for j in m.joints if servo(j)]
    lines.append("  </actuator>")
    drives = drive_names(mechs)
    if drives:  # a lock per drive hinge, off until Simulation.lock switches it on (a brake)
        lines += (
            ["  <equality>"]
            + [f'    <joint name="{n}_lock" joint1="{n}" polycoef="0 0 0 0 0" active="false"/>' for n in drives]
            + ["  </equality>"]
        )
    qpos = [0.0, 0.0, height, 1.0, 0.0, 0.0, 0.0]
    ctrl = []  # the servos' targets at the start: each steering servo holds its angle, each drive servo rate 0
    for i, m in enumerate(mechs):
        qpos += [float(beta0[i]) if j.steering else 0.0 for j in m.joints]
        ctrl += [float(beta0[i]) if servo(j) == POSITION else 0.0 for j in m.joints if servo(j)]
    key = f'    <key name="start" qpos="{nums(*qpos, scale=1.0)}"' + (
        f' ctrl="{nums(*ctrl, scale=1.0)}"' if ctrl else ""
    )
    lines += ["  <keyframe>", key + "/>", "  </keyframe>", "</mujoco>", ""]
    return "\n".join(lines)


def _escape(text):
    """``text`` escaped for an XML attribute."""
    return str(text).replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;").replace(">", "&gt;")
