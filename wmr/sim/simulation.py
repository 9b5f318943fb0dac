r"""A robot in MuJoCo, commanded and measured in wmr's variables: :class:`Simulation`.

Commands are steering angles :math:`\boldsymbol\beta` and joint rates :math:`\dot{\boldsymbol\theta}` (the rate vector
of :attr:`wmr.Robot.rate_names`); each servo gets its target through the unit's joints (:meth:`wmr.sim.Export.hinges`).
MuJoCo is imported here only; ``import wmr`` does not import it.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from .._version import DISTRIBUTION
from ..errors import InputValueError, MissingDependencyError
from ..model import validation
from ..model.robot import Robot
from ..model.types import ArrayLike, FloatArray
from .bodies import POSITION, VELOCITY, servo
from .measure import Probe
from .mjcf import Export, export
from .params import Params
from .recording import Reading
from .validity import Monitor, Validity

__all__ = ["Simulation"]

#: the most integration steps a run may take (a run of 10^7 steps takes minutes)
MAX_STEPS = 5_000_000


def _mujoco():
    """The ``mujoco`` module, or the error that says how to install it."""
    try:
        import mujoco
    except ImportError as e:  # pragma: no cover - the edition's venv has it
        raise MissingDependencyError(
            f"wmr.sim needs MuJoCo: pip install '{DISTRIBUTION}[sim]' (or pip install mujoco)"
        ) from e
    return mujoco


class Simulation:
    """A robot in MuJoCo, commanded and measured in wmr's variables.

    Parameters
    ----------
    robot : Robot or Export
        The robot (exported here with the other arguments), or an :class:`~wmr.sim.mjcf.Export`.
    beta : array (w,), optional
        Initial steering angles (default 0), also the first target of the steering servos.
    params : Params, optional
    settle : float, optional
        Seconds to let the robot settle on its wheels, every servo holding still, before time 0 (the clock
        then restarts at 0 with C at the origin).
    **changes
        Parameters to change by name.

    Attributes
    ----------
    export : Export
    model, data : mujoco.MjModel, mujoco.MjData
    servo_names : tuple of str
    joint_names : tuple of str
        Every hinge of the units (``u<i>_<name>``), in MuJoCo's order.
    wheel_names : tuple of str
        The contact geoms, one per wheel (``u<i>_wheel``...).
    wheel_unit : numpy.ndarray of int (n_wheels,)
        The unit (0-based) of each wheel.
    """

    def __init__(
        self,
        robot: Robot | Export,
        beta: ArrayLike | None = None,
        params: Params | None = None,
        settle: float = 0.2,
        **changes: float,
    ) -> None:
        mj = _mujoco()
        self._mj = mj
        self.export = robot if isinstance(robot, Export) else export(robot, beta, params, **changes)
        ex = self.export
        self.model = mj.MjModel.from_xml_string(ex.xml)
        self.data = mj.MjData(self.model)
        self.robot = ex.robot
        m = self.model
        self._id = lambda kind, name: mj.mj_name2id(m, kind, name)
        # every hinge: (unit, joint, rate column or None, qpos address, dof address), in MuJoCo's order
        self._hinges = []
        for i, j, col in ex.hinges():
            jid = self._id(mj.mjtObj.mjOBJ_JOINT, ex.name(i, j.name))
            self._hinges.append((i, j, col, int(m.jnt_qposadr[jid]), int(m.jnt_dofadr[jid])))
        self.servo_names = tuple(m.actuator(a).name for a in range(m.nu))
        self.joint_names = tuple(ex.name(i, j.name) for i, j, *_ in self._hinges)
        self._servo = {n: a for a, n in enumerate(self.servo_names)}
        wheels = [(i, ex.name(i, b.name)) for i, mech in enumerate(ex.mechanisms) for b in mech.wheels]
        self.wheel_names = tuple(n for _, n in wheels)
        self.wheel_unit = np.array([i for i, _ in wheels], dtype=int)
        self._platform = self._id(mj.mjtObj.mjOBJ_BODY, "platform")
        geoms = [self._id(mj.mjtObj.mjOBJ_GEOM, n) for _, n in wheels]
        self._probe = Probe(mj, m, self.robot, self._hinges, geoms, self._platform)
        scale = ex.weight * max(float(u.r) for u in self.robot.wheels)
        self._monitor = Monitor(mj, m, self.servo_names, geoms, self._platform, scale)
        self._gains = (m.actuator_gainprm.copy(), m.actuator_biasprm.copy())
        # each servo's target as a linear map of (beta, rates): a steering servo takes beta_i, a drive servo its rate
        self._from_beta, self._from_rates = np.zeros((m.nu, self.robot.w)), np.zeros((m.nu, self.robot.n_rates))
        for i, j, col, _, _ in self._hinges:
            a, kind = self._servo.get(ex.name(i, j.name)), servo(j)
            if a is not None and kind == POSITION:  # a driven steering joint
                self._from_beta[a, i] = 1.0
            elif a is not None and kind == VELOCITY and col is not None:
                self._from_rates[a, col] = 1.0
        # a position servo pushes kp (target - q) - kv q_dot: fed target + (kv / kp) target_dot, it is a PD law
        # on the error and follows a turning target without lag
        kp, kv = m.actuator_gainprm[:, 0], -m.actuator_biasprm[:, 2]
        self._lead = np.where(self._from_beta.any(axis=1) & (kp > 0), kv / np.where(kp > 0, kp, 1.0), 0.0)
        mj.mj_resetDataKeyframe(m, self.data, 0)
        self._beta: FloatArray = np.array(ex.beta0, dtype=float)
        self._rates: FloatArray = np.zeros(self.robot.n_rates)
        self.command(self._beta, self._rates)
        settle = validation.number("settle", validation.nonnegative("settle", settle))
        if settle > 0:
            self.advance(settle)
            self.data.time = 0.0
            self.data.qpos[0:2] = 0.0  # C back at the origin, heading kept
        mj.mj_forward(m, self.data)
        self._monitor.reset(self.data)  # validity is judged from time 0

    # --- commands --------------------------------------------------------------------------
    def command(
        self, beta: ArrayLike | None = None, rates: ArrayLike | None = None, beta_rate: ArrayLike | None = None
    ) -> None:
        """Set the servos' targets from steering angles and joint rates (:meth:`targets`); None keeps the last.

        Parameters
        ----------
        beta : array (w,), optional
            Targets of the steering servos (entries of unsteered or passive units are ignored).
        rates : array (n_rates,), optional
            Joint rates; each drive servo takes the rate its hinge measures.
        beta_rate : array (w,), optional
            The rate at which the steering targets turn (default 0).

        Returns
        -------
        None
        """
        if beta is not None:
            self._beta = validation.finite_array("beta", beta, last=self.robot.w).reshape(self.robot.w).copy()
        if rates is not None:
            self._rates = (
                validation.finite_array("rates", rates, last=self.robot.n_rates).reshape(self.robot.n_rates).copy()
            )
        self.data.ctrl[:] = self.targets(self._beta, self._rates, beta_rate)

    def targets(self, beta: ArrayLike, rates: ArrayLike, beta_rate: ArrayLike | None = None) -> FloatArray:
        r"""The servos' targets for commands in wmr's variables (batched), in the order of :attr:`servo_names`.

        A steering servo takes :math:`\beta_i + (k_v/k_p)\dot\beta_i`, so that it follows a turning target without lag
        (a PD law on the error); a drive servo the rate its hinge measures.

        Parameters
        ----------
        beta : array (..., w)
        rates : array (..., n_rates)
        beta_rate : array (..., w), optional
            Default 0.

        Returns
        -------
        numpy.ndarray (..., n_servos)
        """
        beta = validation.finite_array("beta", beta, last=self.robot.w)
        rates = validation.finite_array("rates", rates, last=self.robot.n_rates)
        out = beta @ self._from_beta.T + rates @ self._from_rates.T
        if beta_rate is not None:
            out = out + self._lead * (
                validation.finite_array("beta_rate", beta_rate, last=self.robot.w) @ self._from_beta.T
            )
        return out

    def release(self, names: Iterable[str]) -> None:
        """Switch servos off (their hinges turn freely), e.g. ``["u1_drive"]``; :meth:`engage` switches them on.

        Parameters
        ----------
        names : iterable of str

        Returns
        -------
        None
        """
        for n in names:
            a = self._servo_index(n)
            self.model.actuator_gainprm[a] = 0.0
            self.model.actuator_biasprm[a] = 0.0

    def engage(self, names: Iterable[str]) -> None:
        """Switch servos back on (undo :meth:`release`).

        Parameters
        ----------
        names : iterable of str

        Returns
        -------
        None
        """
        for n in names:
            a = self._servo_index(n)
            self.model.actuator_gainprm[a] = self._gains[0][a]
            self.model.actuator_biasprm[a] = self._gains[1][a]

    def lock(self, names: Iterable[str]) -> None:
        """Lock drive hinges (e.g. ``["u1_drive"]``) where they are, their servos off: the paper's locked drives.

        A lock is a joint equality of the model (``<name>_lock``), as stiff as MuJoCo's constraints, with no torque
        limit; :meth:`unlock` frees the hinges and switches their servos back on.

        Parameters
        ----------
        names : iterable of str

        Returns
        -------
        None
        """
        mj, m, d = self._mj, self.model, self.data
        for n in names:
            eq = self._id(mj.mjtObj.mjOBJ_EQUALITY, f"{n}_lock")
            if eq < 0:
                raise InputValueError(
                    f"no lockable drive hinge named {validation.show(n)}; drives: {list(self.export.drive_names)}"
                )
            m.eq_data[eq, 0] = d.qpos[m.jnt_qposadr[m.eq_obj1id[eq]]]
            d.eq_active[eq] = 1
            if n in self._servo:
                self.release([n])

    def unlock(self, names: Iterable[str]) -> None:
        """Undo :meth:`lock`.

        Parameters
        ----------
        names : iterable of str

        Returns
        -------
        None
        """
        mj = self._mj
        for n in names:
            eq = self._id(mj.mjtObj.mjOBJ_EQUALITY, f"{n}_lock")
            if eq < 0:
                raise InputValueError(f"no lockable drive hinge named {validation.show(n)}")
            self.data.eq_active[eq] = 0
            if n in self._servo:
                self.engage([n])

    def _servo_index(self, name):
        """The actuator index of a servo name (checked)."""
        if name not in self._servo:
            raise InputValueError(f"no servo named {validation.show(name)}; servos: {list(self.servo_names)}")
        return self._servo[name]

    def push(self, force: ArrayLike = (0.0, 0.0), torque: float = 0.0) -> None:
        """Apply a horizontal force (N, fixed frame) at C and a torque (N m) about the vertical to the platform, until changed.

        Parameters
        ----------
        force : pair
        torque : float

        Returns
        -------
        None
        """
        f = np.asarray(force, dtype=float) if isinstance(force, np.ndarray) else None
        if f is None or f.shape != (2,) or not np.isfinite(f).all():  # the checks of bad input, off the fast path
            f = validation.finite_array("force", force, last=2).reshape(2)
        tau = torque if type(torque) is float and np.isfinite(torque) else validation.number("torque", torque)
        self.data.xfrc_applied[:] = 0.0
        # xfrc_applied acts at the body's centre of mass: move the force to C by adding its moment
        com = self.data.xipos[self._platform]
        C = self.data.xpos[self._platform]
        arm = C[:2] - com[:2]
        self.data.xfrc_applied[self._platform, 0:2] = f
        self.data.xfrc_applied[self._platform, 5] = tau + arm[0] * f[1] - arm[1] * f[0]

    # --- time ------------------------------------------------------------------------------
    def advance(self, seconds: float) -> None:
        """Integrate ``seconds`` (>= 0, rounded to whole steps) with the present commands.

        Parameters
        ----------
        seconds : float

        Returns
        -------
        None
        """
        seconds = validation.number("seconds", validation.nonnegative("seconds", seconds))
        n = round(seconds / self.model.opt.timestep)
        if n > MAX_STEPS:
            raise InputValueError(f"seconds = {seconds!r} needs {n} steps, more than {MAX_STEPS}")
        if n:
            self.step(n)

    def step(self, n: int = 1, check: bool = True) -> None:
        """Integrate ``n`` steps with the present servo targets (``data.ctrl``), as fast as MuJoCo goes.

        Parameters
        ----------
        n : int
        check : bool
            Raise ``FloatingPointError`` if the state is no longer finite (:func:`wmr.sim.run` checks at each sample
            instead).

        Returns
        -------
        None
        """
        self._mj.mj_step(self.model, self.data, n)
        if check:
            self._check_finite()

    def _check_finite(self):
        """Raise ``FloatingPointError`` if the state is no longer finite."""
        if not np.isfinite(self.data.qpos).all():
            raise FloatingPointError(f"the simulation diverged at t = {self.data.time:.6g} s")

    @property
    def t(self) -> float:
        """Simulated time, s."""
        return float(self.data.time)

    # --- measurements ----------------------------------------------------------------------
    def sample(self) -> Reading:
        """Measure the present state in wmr's variables (:mod:`wmr.sim.measure`); ``FloatingPointError`` if it diverged.

        Returns
        -------
        Reading
        """
        self._check_finite()
        self._mj.mj_forward(self.model, self.data)  # positions, contacts and forces of this state
        self._monitor.update(self.data)
        return self._probe.sample(self.data)

    def watch(self) -> None:
        """Let the validity monitor see the present state without taking a sample (a loop that steps by itself).

        Returns
        -------
        None
        """
        self._monitor.update(self.data)

    def validity(self) -> Validity:
        """What the validity monitor saw since time 0, at every sample and watch.

        Returns
        -------
        Validity
        """
        return self._monitor.validity()
