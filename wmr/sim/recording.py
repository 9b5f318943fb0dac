r"""What goes into a simulation (:class:`Schedule`) and what comes out (:class:`Reading`, :class:`Recording`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputValueError
from ..model import validation
from ..model.types import ArrayLike, FloatArray
from .mjcf import Export
from .validity import Validity

__all__ = ["Recording", "Reading", "Schedule"]


@dataclass(frozen=True)
class Reading:
    r"""What :meth:`wmr.sim.Simulation.sample` measures at one instant.

    Attributes
    ----------
    t : float
    pose : numpy.ndarray (3,)
        :math:`(\psi, X, Y)`: heading and position of C, fixed frame.
    twist : numpy.ndarray (3,)
        :math:`[\dot\psi, \dot x, \dot y]`, body frame.
    beta : numpy.ndarray (w,)
        Steering angles (unwrapped; unsteered units: their own angle).
    rates : numpy.ndarray (n_rates,)
        The encoders' joint rates in wmr's order.
    torque : numpy.ndarray (n_servos,)
        Servo torques, in the order of :attr:`Simulation.servo_names`.
    joint_pos : numpy.ndarray (n_hinges,)
        Angle of every hinge of the units (servoed or passive), in the order of
        :attr:`Simulation.joint_names`, radians.
    joint_vel : numpy.ndarray (n_hinges,)
        Their rates, rad/s.
    point : numpy.ndarray (n_wheels, 3)
        Contact points, fixed frame (NaN for a wheel off the ground).
    force : numpy.ndarray (n_wheels, 3)
        Contact force on each wheel, fixed frame.
    moment : numpy.ndarray (n_wheels, 3)
        Contact torque on each wheel (torsional and rolling friction), fixed frame.
    slip : numpy.ndarray (n_wheels, 2)
        Horizontal velocity of each wheel's material point at its contact, fixed frame.
    dissipation : numpy.ndarray (n_wheels,)
        Power the contact takes from each wheel, W: :math:`-(\mathbf f\cdot\mathbf v +
        \boldsymbol\tau\cdot\boldsymbol\omega)`, :math:`\mathbf v` the velocity of the wheel's point at the
        contact, :math:`\boldsymbol\omega` the wheel's angular velocity (all friction together).
    """

    t: float
    pose: np.ndarray
    twist: np.ndarray
    beta: np.ndarray
    rates: np.ndarray
    torque: np.ndarray
    joint_pos: np.ndarray
    joint_vel: np.ndarray
    point: np.ndarray
    force: np.ndarray
    moment: np.ndarray
    slip: np.ndarray
    dissipation: np.ndarray


@dataclass(frozen=True)
class Recording:
    """Samples of a run, stacked: each attribute of :class:`Reading` with a leading time axis (N, ...).

    Attributes
    ----------
    export : Export
        The exported robot (names, mechanisms, parameters).
    t : numpy.ndarray (N,)
    pose : numpy.ndarray (N, 3)
    twist : numpy.ndarray (N, 3)
    beta : numpy.ndarray (N, w)
    rates : numpy.ndarray (N, n_rates)
    torque : numpy.ndarray (N, n_servos)
    joint_pos : numpy.ndarray (N, n_hinges)
    joint_vel : numpy.ndarray (N, n_hinges)
    point : numpy.ndarray (N, n_wheels, 3)
    force : numpy.ndarray (N, n_wheels, 3)
    moment : numpy.ndarray (N, n_wheels, 3)
    slip : numpy.ndarray (N, n_wheels, 2)
    dissipation : numpy.ndarray (N, n_wheels)
    validity : Validity, optional
        What the simulation's validity monitor saw up to the end of the run (:mod:`wmr.sim.validity`).
    """

    export: Export
    t: np.ndarray
    pose: np.ndarray
    twist: np.ndarray
    beta: np.ndarray
    rates: np.ndarray
    torque: np.ndarray
    joint_pos: np.ndarray
    joint_vel: np.ndarray
    point: np.ndarray
    force: np.ndarray
    moment: np.ndarray
    slip: np.ndarray
    dissipation: np.ndarray
    validity: Validity | None = None

    @property
    def slip_speed(self) -> FloatArray:
        """Slip speed of each wheel, m/s: (N, n_wheels)."""
        return np.hypot(self.slip[..., 0], self.slip[..., 1])

    def kinematic_slip(self) -> tuple[FloatArray, FloatArray]:
        r"""wmr's view of the encoders: the residual of (21) of the least-squares twist, per sample.

        :func:`wmr.forward` from the measured steering angles and joint rates; the residual
        :math:`\mathbf J_1\mathbf t - \mathbf J_2\dot{\boldsymbol\theta}` is zero exactly when the rates are
        compatible.

        Returns
        -------
        tuple of numpy.ndarray
            The twist from the encoders (N, 3) and the residual's norm (N,).
        """
        from ..analysis.kinematics import forward

        sol = forward(self.export.robot, self.beta, self.rates)
        return sol.value, np.linalg.norm(sol.residual, axis=-1)


@dataclass(frozen=True)
class Schedule:
    r"""Commands in wmr's variables over time, interpolated linearly between knots.

    Attributes
    ----------
    t : numpy.ndarray (K,)
        Knot times, increasing; before the first and after the last the end values hold.
    beta : numpy.ndarray (K, w)
        Steering angles for the steering servos.
    rates : numpy.ndarray (K, n_rates)
        Joint rates for the drive servos.
    """

    t: np.ndarray
    beta: np.ndarray
    rates: np.ndarray

    def __post_init__(self):
        t = validation.finite_array("t", self.t)
        if t.ndim != 1 or len(t) == 0 or (len(t) > 1 and not np.all(np.diff(t) > 0)):
            raise InputValueError(f"t must be a non-empty increasing vector, got {validation.show(self.t)}")
        beta = validation.finite_array("beta", self.beta)
        rates = validation.finite_array("rates", self.rates)
        if beta.ndim != 2 or rates.ndim != 2 or len(beta) != len(t) or len(rates) != len(t):
            raise InputValueError(
                f"beta and rates must have one row per knot ({len(t)}), got shapes {beta.shape} and {rates.shape}"
            )
        object.__setattr__(self, "t", t)
        object.__setattr__(self, "beta", beta)
        object.__setattr__(self, "rates", rates)

    @classmethod
    def constant(cls, beta: ArrayLike, rates: ArrayLike) -> Schedule:
        """The same command at every time.

        Parameters
        ----------
        beta : array (w,)
        rates : array (n_rates,)

        Returns
        -------
        Schedule
        """
        return cls(
            np.zeros(1), np.atleast_2d(np.asarray(beta, dtype=float)), np.atleast_2d(np.asarray(rates, dtype=float))
        )

    def at(self, t: ArrayLike) -> tuple[FloatArray, FloatArray]:
        """The commands at times ``t``.

        Parameters
        ----------
        t : float or array (n,)

        Returns
        -------
        tuple of numpy.ndarray
            beta (w,) and rates (n_rates,), or (n, w) and (n, n_rates) for an array of times.
        """
        tt = np.atleast_1d(np.asarray(t, dtype=float))
        out = []
        for values in (self.beta, self.rates):
            if len(self.t) == 1:
                out.append(np.repeat(values, len(tt), axis=0))
            else:
                out.append(np.stack([np.interp(tt, self.t, col) for col in values.T], axis=-1))
        return (out[0], out[1]) if np.ndim(t) else (out[0][0], out[1][0])

    def beta_rate(self, t: ArrayLike) -> FloatArray:
        """The rate of the steering targets at times ``t`` (the slope of the segment; 0 outside the knots).

        Parameters
        ----------
        t : array (n,)

        Returns
        -------
        numpy.ndarray (n, w)
        """
        tt = np.atleast_1d(np.asarray(t, dtype=float))
        out = np.zeros((len(tt), self.beta.shape[1]))
        if len(self.t) > 1:
            slope = np.diff(self.beta, axis=0) / np.diff(self.t)[:, None]
            k = np.searchsorted(self.t, tt, side="right") - 1
            inside = (k >= 0) & (k < len(self.t) - 1)
            out[inside] = slope[k[inside]]
        return out


def __getattr__(name: str) -> object:
    """``wmr.sim.recording.Sample``, the name :class:`Reading` had: deprecated."""
    if name == "Sample":
        import warnings

        warnings.warn("wmr.sim.recording.Sample is deprecated: use wmr.sim.recording.Reading", DeprecationWarning, 2)
        return Reading
    raise AttributeError(f"module 'wmr.sim.recording' has no attribute {name!r}")
