r"""What a MuJoCo state says in wmr's variables: :class:`Probe` reads a :class:`~wmr.sim.recording.Reading`.

An offset wheel's encoder rate is :math:`\dot\phi_i = \dot\psi + \dot\beta_i` (7); a wheel's **slip** is the
velocity of its material point at the contact relative to the ground (zero for rolling without slipping, (6)).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ..model.robot import Robot
from .recording import Reading

__all__: list[str] = []


def yaw(q):
    """Heading (radians) of a quaternion ``(w, x, y, z)`` about the vertical."""
    w, x, y, z = q
    return float(np.arctan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)))


class Probe:
    """Reads the state of one compiled model in wmr's variables (:meth:`Probe.sample`).

    ``hinges`` lists every hinge of the units as ``(unit, joint, rate column or None, qpos address, dof address)`` in
    MuJoCo's order, ``wheel_geoms`` the contact geom of each wheel (MuJoCo ids), ``platform`` the platform's body id.
    """

    def __init__(
        self, mj: Any, model: Any, robot: Robot, hinges: Sequence[tuple], wheel_geoms: Sequence[int], platform: int
    ) -> None:
        self.mj, self.model, self.robot = mj, model, robot
        self.hinges = list(hinges)
        self.qa = np.array([h[3] for h in self.hinges], dtype=int)
        self.da = np.array([h[4] for h in self.hinges], dtype=int)
        self.n_wheels = len(wheel_geoms)
        self.geom = {g: k for k, g in enumerate(wheel_geoms)}
        self.wheel_body = [int(model.geom_bodyid[g]) for g in sorted(self.geom, key=lambda g: self.geom[g])]
        self.platform = platform
        self.jacp, self.jacr = np.zeros((3, model.nv)), np.zeros((3, model.nv))
        self.f6 = np.zeros(6)

    def sample(self, d: Any) -> Reading:
        """Measure the state ``d`` (a ``mujoco.MjData`` of this probe's model, after ``mj_forward``)."""
        mj, m = self.mj, self.model
        q = d.qpos
        psi = yaw(q[3:7])
        c, s = np.cos(psi), np.sin(psi)
        v = d.qvel[0:3]  # world-frame velocity of C
        wz = float(d.xmat[self.platform].reshape(3, 3)[:, 2] @ d.qvel[3:6])  # turning rate (body -> world z)
        twist = np.array([wz, c * v[0] + s * v[1], -s * v[0] + c * v[1]])
        beta = np.array(self.robot.effective_beta(np.zeros(self.robot.w)), dtype=float)
        rates = np.zeros(self.robot.n_rates)
        for i, j, col, qa, da in self.hinges:
            if j.steering:
                beta[i] = q[qa]
            if col is not None:
                rates[col] = d.qvel[da] + (wz if j.absolute else 0.0)
        nw = self.n_wheels
        point = np.full((nw, 3), np.nan)
        force, moment = np.zeros((nw, 3)), np.zeros((nw, 3))
        slip, power = np.zeros((nw, 2)), np.zeros(nw)
        for k in range(d.ncon):
            con = d.contact[k]
            g1, g2 = int(con.geom[0]), int(con.geom[1])
            w = self.geom.get(g2, self.geom.get(g1))
            if w is None:
                continue
            mj.mj_contactForce(m, d, k, self.f6)
            frame = con.frame.reshape(3, 3)  # rows: normal (geom1 -> geom2), tangents
            sign = 1.0 if g2 in self.geom else -1.0  # the force on geom2 is +, on geom1 -
            f = sign * (frame.T @ self.f6[:3])
            tq = sign * (frame.T @ self.f6[3:6])
            p = np.array(con.pos)
            mj.mj_jac(m, d, self.jacp, self.jacr, p, self.wheel_body[w])
            u, om = self.jacp @ d.qvel, self.jacr @ d.qvel  # the wheel's point at p, the wheel's spin
            force[w] += f
            moment[w] += tq
            point[w] = p
            slip[w] = u[:2]
            power[w] -= f @ u + tq @ om
        torque = np.array(d.actuator_force, dtype=float)
        return Reading(
            float(d.time),
            np.array([psi, q[0], q[1]]),
            twist,
            beta,
            rates,
            torque,
            q[self.qa].copy(),
            d.qvel[self.da].copy(),
            point,
            force,
            moment,
            slip,
            power,
        )
