r"""The physical parameters of an exported robot: masses, friction, actuators, time step.

wmr's model (the paper's) has no mass, no force and no friction; a physics engine needs all three.
:class:`Params` holds them, each with a stated default, and every default is written so that it
means the same thing for a robot of any size: masses in kilograms, but torques and friction
lengths **relative to the robot**, so that a robot described in units of :math:`L` (the paper's
examples, with :math:`r = L = 1`) and one in metres behave alike.

Friction (MuJoCo's soft contact model, one point contact per wheel)
--------------------------------------------------------------------
Each wheel touches the ground at one point, the paper's thin disk, with three coefficients:

* ``sliding`` :math:`\mu`: Coulomb friction, the tangential force :math:`\|\mathbf f_t\| \le \mu N`
  (elliptic cone);
* ``torsional`` :math:`\mu_t`: the largest torque about the contact normal, :math:`|\tau_n| \le \mu_t N`.
  It stands for the contact patch that a real tyre has (the paper's "dry-friction torque stemming
  from the unavoidable deformation of the wheel"); given as a fraction of the wheel radius
  (:math:`\mu_t = \text{torsional}\cdot r`; a patch of radius :math:`a` under uniform pressure gives
  :math:`\tfrac23\mu a`);
* ``rolling`` :math:`c_{rr}`: rolling resistance, the largest torque about the tangent axes
  :math:`c_{rr} r N`, i.e. a resisting force :math:`c_{rr}N` (rubber on concrete: about 0.01).

The contact is soft (MuJoCo's ``solref``/``solimp`` defaults, ``impratio`` below): a wheel held by
static friction still creeps slowly, so "no motion" is always decided against a stated threshold.

Actuators
---------
Torque limits are fractions of :math:`W r_i`, with :math:`W` the robot's weight and :math:`r_i` the
wheel's radius (``drive_torque = 1`` lets one drive push the whole robot up a 45 degree slope).  A
steering hinge is under a position servo (gain ``steer_kp`` per radian of error, damping at the ratio
``steer_damping`` of critical for the hinge's inertia), a drive hinge under a velocity servo (gain
``drive_kv`` per rad/s of error); gains are given per unit of the torque limit, so that a servo
saturates at an error of ``1 / gain``.  The runner feeds a steering servo its target angle plus
``kv / kp`` times the target's rate, so that it tracks a turning target without lag (a PD law on the
error).
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
        The wheel's contact geom has the higher ``priority``, so that this time constant is the one used
        (MuJoCo would otherwise average it with the ground's default 0.02).
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
