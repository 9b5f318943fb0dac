r"""Is a run valid? A physics engine returns numbers even when its integration has gone wrong.

:class:`Monitor` watches a :class:`~wmr.sim.Simulation` at every sample and :class:`Validity` states what it saw:

* **finite**: the state stayed finite (a run that diverges raises ``FloatingPointError`` at once);
* **warnings**: MuJoCo raised none of its warnings of a bad state (:data:`BAD_STATE`);
* **energy**: the mechanical energy never grew by more than the work the servos and pushes can have done,
  :math:`\int\sum_a|\tau_a\dot q_a| + |\mathbf f\cdot\mathbf v|\,dt`, by more than :data:`ENERGY` of :math:`W r`
  (:math:`W` the weight, :math:`r` the largest wheel radius): energy from nowhere is a numerical instability;
* **penetration**: no wheel sank into the ground by more than :data:`PENETRATION` of its radius;
* **saturation**: no servo sat at its torque limit for more than :data:`SATURATION` of the samples, unless the
  experiment expects it to (a stalled servo is the measurement of a jam);
* **chatter**: no servo's torque jumped between samples by more than :data:`CHATTER` of its limit on average (an
  unstable servo swings from limit to limit).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

__all__ = ["Monitor", "Validity"]

#: largest energy gain beyond the work done on the robot, as a fraction of W r
ENERGY = 0.05
#: largest penetration of a wheel into the ground, as a fraction of its radius
PENETRATION = 0.05
#: largest fraction of the samples a servo may spend at its torque limit (unless expected to)
SATURATION = 0.5
#: largest mean jump of a servo's torque between samples, as a fraction of its limit
CHATTER = 0.4
#: MuJoCo's warnings of a bad state, by the names of ``mujoco.mjtWarning``
BAD_STATE = ("mjWARN_INERTIA", "mjWARN_CONTACTFULL", "mjWARN_CNSTRFULL", "mjWARN_BADQPOS", "mjWARN_BADQVEL",
             "mjWARN_BADQACC", "mjWARN_BADCTRL")  # fmt: skip


@dataclass(frozen=True)
class Validity:
    """What a :class:`Monitor` saw during a run (module docstring), and the problems it makes.

    Attributes
    ----------
    finite : bool
        The state stayed finite.
    warnings : int
        MuJoCo's warnings of a bad state raised during the run.
    energy : float
        The largest gain of mechanical energy beyond the work done on the robot, as a fraction of
        :math:`W r` (0 or below: none).
    penetration : float
        The deepest a wheel sank into the ground, as a fraction of its radius.
    saturation : dict
        Servo name -> fraction of the samples at its torque limit.
    chatter : dict
        Servo name -> mean jump of its torque from one sample to the next, as a fraction of its limit.
    samples : int
        Samples watched.
    """

    finite: bool = True
    warnings: int = 0
    energy: float = 0.0
    penetration: float = 0.0
    saturation: dict[str, float] = field(default_factory=dict)
    chatter: dict[str, float] = field(default_factory=dict)
    samples: int = 0

    def problems(self, saturating: Iterable[str] = ()) -> tuple[str, ...]:
        """Why the run is not valid, in words (empty: it is).

        Parameters
        ----------
        saturating : iterable of str
            Servos expected to sit at their limit (a stall that is the measurement): not counted.

        Returns
        -------
        tuple of str

        Examples
        --------
        >>> Validity(penetration=0.2, saturation={"u1_drive": 0.9, "u1_steer": 0.9}).problems(["u1_steer"])
        ('a wheel sank 20% of its radius into the ground', 'u1_drive at its torque limit 90% of the time')
        """
        out = []
        if not self.finite:
            out.append("the state diverged")
        if self.warnings:
            out.append(f"MuJoCo warned of a bad state {self.warnings} times")
        if self.energy > ENERGY:
            out.append(f"energy grew by {self.energy:.2g} W r more than the work done on the robot")
        if self.penetration > PENETRATION:
            out.append(f"a wheel sank {100 * self.penetration:.2g}% of its radius into the ground")
        skip = set(saturating)
        out += [
            f"{n} at its torque limit {100 * f:.2g}% of the time"
            for n, f in self.saturation.items()
            if f > SATURATION and n not in skip
        ]
        out += [
            f"{n} chattered (torque jumps {100 * f:.2g}% of its limit per sample)"
            for n, f in self.chatter.items()
            if f > CHATTER
        ]
        return tuple(out)

    def valid(self, saturating: Iterable[str] = ()) -> bool:
        """True when :meth:`Validity.problems` finds none.

        Parameters
        ----------
        saturating : iterable of str

        Returns
        -------
        bool
        """
        return not self.problems(saturating)

    @classmethod
    def diverged(cls) -> Validity:
        """The validity of a run whose state diverged.

        Returns
        -------
        Validity
        """
        return cls(finite=False)


class Monitor:
    """Watches one simulation's state at each sample (module docstring); :meth:`Monitor.validity` says what it saw.

    Parameters
    ----------
    mj : module
        ``mujoco``.
    model : mujoco.MjModel
    servo_names : sequence of str
        The actuators' names, in MuJoCo's order.
    wheel_geoms : sequence of int
        The wheels' contact geoms.
    platform : int
        The platform's body id (pushes act on it).
    scale : float
        :math:`W r`, J: the unit of the energy check.
    """

    def __init__(self, mj: Any, model: Any, servo_names, wheel_geoms, platform: int, scale: float) -> None:
        self.mj, self.model = mj, model
        self.names = tuple(servo_names)
        self.limit = np.abs(model.actuator_forcerange).max(axis=1) if model.nu else np.zeros(0)
        self.radius = np.zeros(len(model.geom_size))  # the wheels' radii by geom id, 0 for other geoms
        for g in wheel_geoms:
            self.radius[int(g)] = float(model.geom_size[g, 0])
        self.platform, self.scale = platform, float(scale)
        self.bad = [int(getattr(mj.mjtWarning, n)) for n in BAD_STATE]
        self.reset(None)

    def reset(self, d: Any) -> None:
        """Forget what was seen (the clock restarts): the next sample is the first.

        Parameters
        ----------
        d : mujoco.MjData or None

        Returns
        -------
        None
        """
        self.n, self.sat, self.jumps = 0, np.zeros(len(self.names)), np.zeros(len(self.names))
        self.tau: np.ndarray | None = None
        self.t: float | None = None
        self.e0 = self.p = 0.0
        self.work, self.excess, self.depth = 0.0, -np.inf, 0.0
        self.data: Any = d
        self.warn0 = 0 if d is None else self._warnings(d)

    def _warnings(self, d):
        """MuJoCo's count of bad-state warnings in ``d``."""
        return int(sum(d.warning[k].number for k in self.bad))

    def update(self, d: Any) -> None:
        """Watch the present state (positions, forces and energy of the last step or forward pass).

        Parameters
        ----------
        d : mujoco.MjData

        Returns
        -------
        None
        """
        tau = np.asarray(d.actuator_force)
        f = d.xfrc_applied[self.platform]
        p = float(np.abs(tau * d.actuator_velocity).sum() + abs(f[:3] @ d.qvel[0:3]) + abs(f[5] * d.qvel[5]))
        e = float(d.energy[0] + d.energy[1])
        if self.t is None:
            self.e0 = e
        else:
            self.work += 0.5 * (p + self.p) * (d.time - self.t)
        self.t, self.p = float(d.time), p
        self.excess = max(self.excess, e - self.e0 - self.work)
        self.n += 1
        self.sat += (np.abs(tau) >= (1 - 1e-6) * self.limit) & (self.limit > 0)
        if self.tau is not None:
            self.jumps += np.abs(tau - self.tau) / np.where(self.limit > 0, self.limit, 1.0)
        self.tau = tau.copy()
        if d.ncon:
            c = d.contact
            r = np.maximum(self.radius[c.geom[:, 0]], self.radius[c.geom[:, 1]])  # the wheel's, of a wheel's contact
            wheel = r > 0
            if wheel.any():
                self.depth = max(self.depth, float((-c.dist[wheel] / r[wheel]).max()))
        self.data = d

    def validity(self) -> Validity:
        """What was seen since the last :meth:`Monitor.reset`.

        Returns
        -------
        Validity
        """
        n = max(self.n, 1)
        return Validity(
            finite=True,
            warnings=0 if self.data is None else self._warnings(self.data) - self.warn0,
            energy=max(0.0, float(self.excess) / self.scale) if self.n else 0.0,
            penetration=self.depth,
            saturation={name: float(s / n) for name, s in zip(self.names, self.sat)},
            chatter={name: float(j / max(self.n - 1, 1)) for name, j in zip(self.names, self.jumps)},
            samples=self.n,
        )
