r"""Driving a :class:`~wmr.sim.Simulation` along a :class:`~wmr.sim.Schedule`: :func:`run`, and what it records."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np

from ..errors import InputTypeError, InputValueError
from ..model import validation
from .recording import Reading, Recording, Schedule
from .simulation import MAX_STEPS, Simulation

__all__ = ["run"]


def run(
    sim: Simulation,
    schedule: Schedule | None,
    seconds: float,
    control_dt: float = 0.001,
    every: int = 10,
    on_step: Callable[[Simulation], object] | None = None,
) -> Recording:
    """Drive a simulation along a schedule and record it.

    Each control period the servos get the schedule's command at the period's start (as :meth:`Simulation.command`
    gives it), then the physics advances one period.  A sample is taken at the start of every ``every``-th period,
    after its commands are set (the torques sampled are those applied), and one at the end.

    Parameters
    ----------
    sim : Simulation
    schedule : Schedule or None
        None: keep the present commands.
    seconds : float
        Duration, > 0.
    control_dt : float
        Control period, s (whole integration steps, at least one; default 0.001, a 1 kHz controller).
    every : int
        Record every ``every``-th period (and the end).
    on_step : callable, optional
        ``on_step(sim)`` called at each period before the command (e.g. to push).

    Returns
    -------
    Recording
    """
    seconds = validation.number("seconds", validation.positive("seconds", seconds))
    control_dt = validation.number("control_dt", validation.positive("control_dt", control_dt))
    every = validation.integer("every", every, minimum=1)
    if not isinstance(sim, Simulation):
        raise InputTypeError(f"sim must be a wmr.sim.Simulation, got {validation.show(sim)}")
    if schedule is not None and not isinstance(schedule, Schedule):
        raise InputTypeError(f"schedule must be a wmr.sim.Schedule or None, got {validation.show(schedule)}")
    steps = max(1, round(control_dt / sim.model.opt.timestep))  # a period of at least one step
    n = int(np.ceil(seconds / (steps * sim.model.opt.timestep) - 1e-9))
    if n * steps > MAX_STEPS:
        raise InputValueError(f"seconds = {seconds!r} needs more than {MAX_STEPS} steps")
    times = np.arange(n) * steps * sim.model.opt.timestep
    if schedule is not None:
        beta, rates = schedule.at(times)
        turning = schedule.beta_rate(times)
        ctrl = sim.targets(beta, rates, turning)  # every servo's target, every period
    samples = []
    data, step = sim.data, sim.step
    for k in range(n):
        if on_step is not None:
            on_step(sim)
        if schedule is not None:
            data.ctrl[:] = ctrl[k]
        if k % every == 0:
            samples.append(sim.sample())  # the state at the period's start, with its commands (checked finite)
        step(steps, False)
    if schedule is not None:
        sim.command(beta[-1], rates[-1], turning[-1])  # the last command stays (as command() would have set it)
    samples.append(sim.sample())
    return _stack(sim.export, samples, sim.validity())


def _stack(ex, samples, validity):
    """The readings of a run stacked into a :class:`~wmr.sim.recording.Recording` (a time axis first)."""
    stacked = {f.name: np.array([getattr(s, f.name) for s in samples]) for f in dataclasses.fields(Reading)}
    return Recording(ex, **stacked, validity=validity)
