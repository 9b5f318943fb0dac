r"""The physical parameters of an exported robot: masses, friction, actuators, time step (:class:`Params`).

wmr's model has no mass, force or friction; a physics engine needs all three.  Masses are in kilograms, but
torques and friction lengths are **relative to the robot**, so that a robot in units of :math:`L` (the paper's
examples) and one in metres behave alike.

Each wheel touches the ground at one point (MuJoCo's soft contact, elliptic cone) with Coulomb friction
:math:`\|\mathbf f_t\| \le \mu N`, a torque about the normal :math:`|\tau_n| \le \mu_t N` standing for a tyre's
contact patch (:math:`\mu_t = \text{torsional}\cdot r`; a patch of radius :math:`a` under uniform pressure gives
:math:`\tfrac23\mu a`), and rolling resistance :math:`c_{rr} r N`.  The contact is soft: a wheel held by static
friction still creeps, so "no motion" is always decided against a stated threshold.

Torque limits are fractions of :math:`W r_i` (:math:`W` the weight; ``drive_torque = 1`` lets one drive push the
robot up a 45 degree slope); servo gains are per unit of that limit, so that a servo saturates at an error of
``1 / gain``.  The runner feeds a steering servo its target plus ``kv / kp`` times the target's rate (a PD law on
the error: no lag on a turning target).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from ..errors import InputTypeError, InputValueError
from ..model import validation

__all__ = ["CONES", "GRAVITY", "INTEGRATORS", "Params"]

#: standard gravity, m/s^2 (lengths are read as metres)
GRAVITY = 9.81
#: MuJoCo's integrators (``<option integrator=...>``)
INTEGRATORS = ("implicitfast", "implicit", "Euler", "RK4")
#: MuJoCo's friction cones (``<option cone=...>``)
CONES = ("elliptic", "pyramidal")


@dataclass(frozen=True)
class Params:
    r"""Physical parameters of :func:`wmr.sim.to_mjcf` (all have defaults; see the module docstring).

    Attributes
    ----------
    platform_mass : float
        kg (default 10); a uniform plate over the mount points, its centre of mass at their centroid.
    body_mass : float
        kg (default 0.2): each intermediate body (steering link, dual-wheel axle).
    wheel_mass : float
        kg (default 0.5): each wheel, a thin disk.
    sliding : float
        Coulomb coefficient :math:`\mu` (default 1.0).
    torsional : float
        :math:`\mu_t / r` (default 0.05).  0 switches torsional friction off.
    rolling : float
        :math:`c_{rr}` (default 0.01).  0 switches rolling resistance off.
    steer_torque : float
        Torque limit of a steering servo, as a fraction of :math:`W r_i` (default 0.1).
    drive_torque : float
        Torque limit of a drive servo, as a fraction of :math:`W r_i` (default 0.5).
    steer_kp : float
        Position gain, in torque limits per radian (default 20: saturates at 2.9 degrees of error).
    steer_damping : float
        Damping ratio of the steering servo (default 1: critical).
    drive_kv : float
        Velocity gain, in torque limits per rad/s (default 2: saturates at 0.5 rad/s of error; stiffer servos
        fight each other through the soft contacts and make the wheels chatter).
    timestep : float
        Integration step, s (default 0.001); MuJoCo's Newton solver.
    contact_time : float
        Time constant of the soft wheel contacts, s (MuJoCo's ``solref``, critically damped; default
        0.005, five steps: stiffer than MuJoCo's 0.02, so that creep under static friction stays small).
    impratio : float
        Ratio of frictional to normal contact stiffness (default 100: little creep under static friction).
    integrator : str
        MuJoCo's integrator, one of :data:`INTEGRATORS` (default ``"implicitfast"``).
    cone : str
        MuJoCo's friction cone, ``"elliptic"`` (default) or ``"pyramidal"``.
    """

    platform_mass: float = 10.0
    body_mass: float = 0.2
    wheel_mass: float = 0.5
    sliding: float = 1.0
    torsional: float = 0.05
    rolling: float = 0.01
    steer_torque: float = 0.1
    drive_torque: float = 0.5
    steer_kp: float = 20.0
    steer_damping: float = 1.0
    drive_kv: float = 2.0
    timestep: float = 0.001
    contact_time: float = 0.005
    impratio: float = 100.0
    integrator: str = "implicitfast"
    cone: str = "elliptic"

    def __post_init__(self):
        for name, allowed in (("integrator", INTEGRATORS), ("cone", CONES)):
            if getattr(self, name) not in allowed:
                raise InputValueError(
                    f"{name} must be one of {list(allowed)}, got {validation.show(getattr(self, name))}"
                )
        for f in dataclasses.fields(self):
            if f.name in ("integrator", "cone"):
                continue
            check = (
                validation.nonnegative if f.name in ("torsional", "rolling", "steer_damping") else validation.positive
            )
            object.__setattr__(self, f.name, validation.number(f.name, check(f.name, getattr(self, f.name))))

    def replace(self, **changes: float | str) -> Params:
        """A copy with some parameters changed (each checked).

        Parameters
        ----------
        **changes
            Attribute names and new values.

        Returns
        -------
        Params
        """
        unknown = sorted(set(changes) - {f.name for f in dataclasses.fields(self)})
        if unknown:
            raise InputTypeError(f"unknown parameter(s) {unknown}; known: {[f.name for f in dataclasses.fields(self)]}")
        return dataclasses.replace(self, **changes)  # type: ignore[arg-type]

    def total_mass(self, n_bodies: int, n_wheels: int) -> float:
        """Mass of the robot, kg.

        Parameters
        ----------
        n_bodies, n_wheels : int
            Intermediate bodies and wheels.

        Returns
        -------
        float
        """
        return self.platform_mass + n_bodies * self.body_mass + n_wheels * self.wheel_mass
