r"""Running a Drake model (:mod:`edition.physics.drake.model`): servo targets, samples, and the run's validity.

:func:`simulate` advances a :class:`~edition.physics.drake.model.Plant` step by step, setting the servos' targets
before every step (angle and rate at the end of the step, which Drake's implicit PD control reaches), and samples
it every :data:`SAMPLE` seconds.  Each sample feeds the same checks as :class:`wmr.sim.validity.Monitor` does for
MuJoCo, with the same limits (:class:`wmr.sim.validity.Validity`): the state finite; the mechanical energy never
grown by more than the work the servos and the push can have done (:math:`\int\sum|\tau\dot q| + |\mathbf f\cdot
\mathbf v|\,dt`, trapezoidal over the samples) by more than 5 % of :math:`W r`; no wheel sunk into the ground by
more than 5 % of its radius (its centre's height below its radius); no servo at its effort limit more than half
the samples unless expected; no servo chattering.  (Drake issues no warnings of a bad state: that count is 0.)
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from wmr.sim.validity import Validity

__all__ = ["SAMPLE", "Recording", "simulate"]

#: time between samples, s
SAMPLE = 0.005


@dataclass
class Recording:
    r"""The samples of a run.

    Attributes
    ----------
    t : numpy.ndarray (N,)
    pose : numpy.ndarray (N, 3)
        The platform's heading and position of C, :math:`(\psi, X, Y)`.
    joints : dict
        Joint name -> angle samples (N,).
    rates : dict
        Joint name -> rate samples (N,).
    torque : numpy.ndarray (N, number of servos)
        The servos' torques (Drake's net actuation), in :attr:`Plant.servo_names` order.
    point : numpy.ndarray (N, wheels, 2)
        Each wheel's contact point on the ground (below its centre).
    validity : wmr.sim.Validity
    """

    t: np.ndarray
    pose: np.ndarray
    joints: dict
    rates: dict
    torque: np.ndarray
    point: np.ndarray
    validity: Validity = field(default_factory=Validity)

    def power(self, names):
        """The servos' mechanical power summed over ``names``, per sample (W).

        Parameters
        ----------
        names : iterable of str
            Servo names.

        Returns
        -------
        numpy.ndarray (N,)
        """
        return sum(self.torque[:, self._servo[n]] * self.rates[n] for n in names)

    _servo: dict = field(default_factory=dict, repr=False)


class _Watch:
    """The validity checks of one run (module docstring)."""

    def __init__(self, m):
        self.m, self.n = m, 0
        self.sat = np.zeros(len(m.servo_names))
        self.jumps = np.zeros(len(m.servo_names))
        self.tau = None
        self.t = self.p = self.e0 = 0.0
        self.work, self.excess, self.depth = 0.0, -np.inf, 0.0
        self.scale = m.weight * max(r for _, _, r in m.wheels)

    def update(self, t, tau, qdot, force):
        m, pc = self.m, self.m.plant_context
        v = m.plant.EvalBodySpatialVelocityInWorld(pc, m.platform).translational()
        p = float(np.abs(tau * qdot).sum() + abs(np.r_[force, 0.0] @ v))
        e = float(m.plant.CalcKineticEnergy(pc) + m.plant.CalcPotentialEnergy(pc))
        if self.n == 0:
            self.e0 = e
        else:
            self.work += 0.5 * (p + self.p) * (t - self.t)
        self.t, self.p = t, p
        self.excess = max(self.excess, e - self.e0 - self.work)
        lim = m.limit
        self.sat += (np.abs(tau) >= (1 - 1e-6) * lim) & (lim > 0)
        if self.tau is not None:
            self.jumps += np.abs(tau - self.tau) / np.where(lim > 0, lim, 1.0)
        self.tau = tau.copy()
        for _, b, r in m.wheels:
            self.depth = max(self.depth, (r - m.plant.EvalBodyPoseInWorld(pc, b).translation()[2]) / r)
        self.n += 1

    def validity(self, finite=True):
        if not finite:
            return Validity.diverged()
        n = max(self.n, 1)
        names = self.m.servo_names
        return Validity(
            finite=True,
            energy=max(0.0, float(self.excess) / self.scale) if self.n else 0.0,
            penetration=float(self.depth),
            saturation={k: float(s / n) for k, s in zip(names, self.sat)},
            chatter={k: float(j / max(self.n - 1, 1)) for k, j in zip(names, self.jumps)},
            samples=self.n,
        )


def simulate(m, seconds, target=None, push=None, stop=None):
    """Run a built model for ``seconds``, sampling it every :data:`SAMPLE` s.

    Parameters
    ----------
    m : Plant
    seconds : float
    target : callable, optional
        ``target(t) -> (q, v)``: the servos' target angles and rates at time ``t`` (actuator order).
    push : callable, optional
        ``push(t) -> (fx, fy)``: the force on the platform at C (N, world frame), updated at every sample.
    stop : callable, optional
        ``stop(recording_so_far) -> bool``, asked after every sample: end the run early.

    Returns
    -------
    Recording
    """
    plant, pc, sim = m.plant, m.plant_context, m.simulator
    dt = m.plant.time_step()
    every = max(1, round(SAMPLE / dt))
    net = plant.get_net_actuation_output_port()
    names = list(m.joints)
    servo_index = {n: k for k, n in enumerate(m.servo_names)}
    rows: dict = {"t": [], "pose": [], "q": [], "v": [], "tau": [], "point": []}
    watch = _Watch(m)
    sim.Initialize()
    force = np.zeros(2)
    steps = round(seconds / dt)
    finite = True
    if target is None:  # nothing to do between samples: advance sample by sample
        dt, every, steps = dt * every, 1, round(seconds / (dt * every))
    for k in range(steps + 1):
        t = k * dt
        if k % every == 0:
            X = plant.EvalBodyPoseInWorld(pc, m.platform)
            x = X.translation()
            R = X.rotation().matrix()
            q = np.array([m.joints[n].get_angle(pc) for n in names])
            v = np.array([m.joints[n].get_angular_rate(pc) for n in names])
            if not (np.isfinite(x).all() and np.isfinite(q).all() and np.isfinite(v).all()):
                finite = False
                break
            tau = np.asarray(net.Eval(pc), float).copy()
            qdot = np.array([v[names.index(n)] for n in m.servo_names])
            rows["t"].append(t)
            rows["pose"].append([np.arctan2(R[1, 0], R[0, 0]), x[0], x[1]])
            rows["q"].append(q)
            rows["v"].append(v)
            rows["tau"].append(tau)
            rows["point"].append([plant.EvalBodyPoseInWorld(pc, b).translation()[:2] for _, b, _ in m.wheels])
            watch.update(t, tau, qdot, force)
            if push is not None:
                force = np.asarray(push(t), float)
                m.push(force)
            if stop is not None and stop(rows):
                break
        if k == steps:
            break
        if target is not None:
            m.command(*target(t + dt))
        sim.AdvanceTo(t + dt)
    Q, V = np.array(rows["q"]), np.array(rows["v"])
    rec = Recording(
        t=np.array(rows["t"]),
        pose=np.array(rows["pose"]),
        joints={n: Q[:, j] for j, n in enumerate(names)},
        rates={n: V[:, j] for j, n in enumerate(names)},
        torque=np.array(rows["tau"]).reshape(len(rows["t"]), len(m.servo_names)),
        point=np.array(rows["point"]),
        validity=watch.validity(finite),
    )
    rec._servo = servo_index
    rec.pose[:, 0] = np.unwrap(rec.pose[:, 0])
    return rec
