r"""Any :class:`wmr.Robot` as a MuJoCo model (MJCF text): :func:`to_mjcf`.

The model: a ground plane; the platform, a free body whose frame is the body frame of wmr
(origin C on the mount plane, x forward, z up); under it each unit's chain of links
(:func:`wmr.sim.chains.unit_chain`, one description per wheel kind); an actuator for every servoed
hinge; a lock for every drive hinge (a joint equality ``<name>_lock``, inactive: the drive locked,
as the paper's Section 4.2 locks it, when switched on); and a keyframe ``start`` with the steering
angles :math:`\boldsymbol\beta_0`.  Names follow
the paper's numbering: unit ``i`` (from 1) has bodies, joints and actuators ``u<i>_<name>`` (e.g.
``u2_steer``, ``u2_drive``), and the geom by which a wheel touches the ground is named after its
link (``u2_wheel``; ``u3_wheel1``, ``u3_wheel2`` for a dual wheel).

Nothing here imports MuJoCo: the text is written from the chains, deterministically (the same
robot and parameters give the same bytes).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model import validation as V
from ..model.wheels import OffsetWheel
from .chains import POSITION, VELOCITY, height_of, unit_chain
from .params import GRAVITY, Params

__all__ = ["Export", "default_passive", "export", "to_mjcf"]


@dataclass(frozen=True)
class Export:
    """An exported robot: the MJCF text and how its names map to wmr's units.

    Attributes
    ----------
    xml : str
    robot : Robot
    params : Params
    chains : tuple of Chain
        One per unit, in the robot's order.
    passive : tuple of bool
        Per unit: True when its hinges carry no servo (a castor).
    height : float
        Height of the mount plane, i.e. of C, above the ground at rest.
    beta0 : numpy.ndarray (w,)
        The steering angles of the keyframe ``start``.
    weight : float
        :math:`W = m g`, N.
    """

    xml: str
    robot: object
    params: Params
    chains: tuple
    passive: tuple
    height: float
    beta0: np.ndarray
    weight: float

    @staticmethod
    def name(i, part):
        """The MuJoCo name of part ``part`` of unit ``i`` (0-based index): ``u<i+1>_<part>``."""
        return f"u{i + 1}_{part}"

    @property
    def drive_names(self):
        """Every drive hinge (driven or not), each with its lock ``<name>_lock``: tuple of str."""
        return tuple(self.name(i, j.name) for i, ch in enumerate(self.chains) for j in ch.joints if j.servo == VELOCITY)

    @property
    def servo_names(self):
        """The servos (MuJoCo actuators) in the model's order: one per servoed hinge of each active unit (tuple of str)."""
        return tuple(self.name(i, j.name) for i, ch in enumerate(self.chains) if not self.passive[i]
                     for j in ch.joints if j.servo is not None)



def default_passive(robot):
    """Which units are passive castors when nothing says so: the offset wheels of a robot that has other units.

    A robot of offset wheels only (the paper's Section 4) drives and steers them all; in a robot with
    other units (a differential drive with a castor, a steered wheel and two castors) its offset wheels
    are castors.  (wmr's model does not record which joints are driven; say it with ``passive``.)

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    tuple of bool
    """
    offset = [isinstance(u, OffsetWheel) for u in robot.wheels]
    return tuple(offset) if not all(offset) else (False,) * robot.w


def _f(x):
    """A float as MJCF text, 12 significant digits (no negative zero)."""
    return format(float(x) + 0.0, ".12g")


def _v(*xs):
    return " ".join(_f(x) for x in xs)


def _quat_z(angle):
    return _v(np.cos(angle / 2), 0.0, 0.0, np.sin(angle / 2))


def _geom(shape, name, r_wheel, params, pad):
    if shape.contact:
        mu_t, mu_r = params.torsional * r_wheel, params.rolling * r_wheel
        return (f'{pad}<geom name="{name}" type="sphere" size="{_f(shape.radius)}" condim="6" '
                f'friction="{_v(params.sliding, mu_t, mu_r)}" solref="{_v(params.contact_time, 1.0)}" '
                f'contype="1" conaffinity="0" group="3"/>')
    where = f' fromto="{_v(*shape.fromto)}"' if shape.fromto is not None else ""
    return f'{pad}<geom type="{shape.kind}" size="{_f(shape.radius)}"{where} contype="0" conaffinity="0" group="1"/>'


def _body(link, i, params, lines, depth):
    pad = "  " * depth
    quat = f' quat="{_quat_z(link.angle)}"' if link.angle else ""
    lines.append(f'{pad}<body name="{Export.name(i, link.name)}" pos="{_v(*link.pos)}"{quat}>')
    if link.joint is not None:
        lines.append(f'{pad}  <joint name="{Export.name(i, link.joint.name)}" type="hinge" axis="{_v(*link.joint.axis)}"/>')
    lines.append(f'{pad}  <inertial pos="0 0 0" mass="{_f(link.mass)}" diaginertia="{_v(*link.inertia)}"/>')
    radius = max((s.radius for s in link.shapes if s.contact), default=0.0)
    for s in link.shapes:
        lines.append(_geom(s, Export.name(i, link.name), radius, params, pad + "  "))
    for c in link.children:
        _body(c, i, params, lines, depth + 1)
    lines.append(f"{pad}</body>")


def _platform(robot, params, height):
    """Inertial and drawn plate of the platform: a uniform plate over the mount points' bounding box."""
    P = robot.mount_points
    lo, hi = P.min(axis=0), P.max(axis=0)
    size = np.maximum(hi - lo, 0.2 * max(float(np.abs(P).max()), height))          # a pair of wheels: still a plate
    t = 0.1 * float(size.min())
    a, b = size
    m = params.platform_mass
    inertia = (m * (b * b + t * t) / 12, m * (a * a + t * t) / 12, m * (a * a + b * b) / 12)
    com = P.mean(axis=0)
    centre = (lo + hi) / 2
    return (f'    <inertial pos="{_v(com[0], com[1], 0.0)}" mass="{_f(m)}" diaginertia="{_v(*inertia)}"/>\n'
            f'    <geom type="box" pos="{_v(centre[0], centre[1], t)}" size="{_v(a / 2, b / 2, t / 2)}" '
            f'contype="0" conaffinity="0" group="1" rgba="0.6 0.6 0.7 0.5"/>')


def export(robot, beta=None, passive=None, params=None, **changes):
    r"""Export a robot: the MJCF text and the map from its names to wmr's units.

    Parameters
    ----------
    robot : Robot
    beta : array (w,), optional
        Steering angles of the keyframe ``start`` (default 0; unsteered units: their own angle).
    passive : sequence of bool, optional
        Per unit, True for a passive unit (no servo on its hinges); default
        :func:`default_passive`.
    params : Params, optional
    **changes
        Parameters to change (names of :class:`Params`), e.g. ``torsional=0``.

    Returns
    -------
    Export

    Raises
    ------
    NotImplementedError
        If a unit cannot be represented faithfully (Swedish wheels).
    """
    robot = V.numeric_robot(robot)
    if params is not None and not isinstance(params, Params):
        raise TypeError(f"params must be a wmr.sim.Params, got {V.show(params)}")
    params = (params or Params()).replace(**changes) if changes else (params or Params())
    beta0 = robot.effective_beta(np.zeros(robot.w) if beta is None else beta)
    if beta0.shape != (robot.w,):
        raise ValueError(f"beta must be one vector of {robot.w} steering angles, got shape {beta0.shape}")
    if passive is None:
        passive = default_passive(robot)
    passive = tuple(V.flag(f"passive[{k}]", p) for k, p in enumerate(passive))
    if len(passive) != robot.w:
        raise ValueError(f"passive must have one flag per unit ({robot.w}), got {len(passive)}")
    height = height_of(robot)
    chains = tuple(unit_chain(u, height, params) for u in robot.wheels)
    n_bodies = sum(len(c.links) - len(c.wheels) for c in chains)
    n_wheels = sum(len(c.wheels) for c in chains)
    weight = params.total_mass(n_bodies, n_wheels) * GRAVITY
    xml = _write(robot, params, chains, passive, height, beta0, weight)
    return Export(xml, robot, params, chains, passive, height, beta0, weight)


def to_mjcf(robot, beta=None, passive=None, params=None, **changes):
    r"""A MuJoCo model (MJCF text) of any :class:`wmr.Robot`.

    The platform (a free body, its frame wmr's body frame at C), each unit's real joints
    (:mod:`wmr.sim.chains`): steering hinges under position servos, drive hinges under velocity
    servos, offset arms, the dual wheel's passive pivot, fixed wheels, passive castors; wheels
    touching the ground at one point each, with sliding, torsional and rolling friction
    (:mod:`wmr.sim.params`).

    Parameters
    ----------
    robot : Robot
    beta : array (w,), optional
        Steering angles of the keyframe ``start`` (default 0).
    passive : sequence of bool, optional
        Per unit, True for a passive unit; default :func:`default_passive` (castors).
    params : Params, optional
        Physical parameters (default :class:`Params`).
    **changes
        Parameters to change by name, e.g. ``sliding=0.6, torsional=0``.

    Returns
    -------
    str
        MJCF; ``mujoco.MjModel.from_xml_string`` loads it.

    Raises
    ------
    NotImplementedError
        For Swedish wheels (:data:`wmr.sim.chains.SWEDISH_REFUSAL`).

    Examples
    --------
    >>> import wmr
    >>> from wmr.sim import to_mjcf
    >>> xml = to_mjcf(wmr.paper_robot("centred", L=0.3, r=0.05))
    >>> xml.count('<position '), xml.count('<velocity ')
    (3, 3)
    """
    return export(robot, beta, passive, params, **changes).xml


def _write(robot, params, chains, passive, height, beta0, weight):
    lines = [f'<mujoco model="{_escape(robot.name)}">',
             '  <compiler angle="radian" autolimits="true"/>',
             (f'  <option timestep="{_f(params.timestep)}" integrator="implicitfast" cone="elliptic" '
             f'impratio="{_f(params.impratio)}" jacobian="dense" gravity="0 0 {_f(-GRAVITY)}"/>'),
             "  <worldbody>",
             '    <geom name="ground" type="plane" size="0 0 1" friction="0 0 0" contype="0" conaffinity="1" condim="6"/>',
             f'    <body name="platform" pos="0 0 {_f(height)}">',
             '      <freejoint name="platform"/>',
             "  " + _platform(robot, params, height).replace("\n", "\n  ")]
    for i, ch in enumerate(chains):
        _body(ch.root, i, params, lines, 3)
    lines += ["    </body>", "  </worldbody>", "  <actuator>"]
    for i, (u, ch) in enumerate(zip(robot.wheels, chains)):
        if passive[i]:
            continue
        r = float(u.r)
        for j in ch.joints:
            name = Export.name(i, j.name)
            if j.servo == POSITION:
                tau = params.steer_torque * weight * r
                lines.append(f'    <position name="{name}" joint="{name}" kp="{_f(params.steer_kp * tau)}" '
                             f'dampratio="{_f(params.steer_damping)}" forcerange="{_v(-tau, tau)}"/>')
            elif j.servo == VELOCITY:
                tau = params.drive_torque * weight * r
                lines.append(f'    <velocity name="{name}" joint="{name}" kv="{_f(params.drive_kv * tau)}" '
                             f'forcerange="{_v(-tau, tau)}"/>')
    lines.append("  </actuator>")
    drives = Export(None, robot, params, chains, passive, height, beta0, weight).drive_names
    if drives:                       # a lock per drive hinge, off until Simulation.lock switches it on (a brake)
        lines += (["  <equality>"] + [f'    <joint name="{n}_lock" joint1="{n}" polycoef="0 0 0 0 0" active="false"/>'
                                       for n in drives] + ["  </equality>"])
    qpos = [0.0, 0.0, height, 1.0, 0.0, 0.0, 0.0]
    for i, ch in enumerate(chains):
        qpos += [float(beta0[i]) if j.steering else 0.0 for j in ch.joints]
    lines += ["  <keyframe>", f'    <key name="start" qpos="{_v(*qpos)}"/>', "  </keyframe>", "</mujoco>", ""]
    return "\n".join(lines)


def _escape(text):
    return (str(text).replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;").replace(">", "&gt;"))
