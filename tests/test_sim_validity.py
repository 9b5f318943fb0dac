"""wmr.sim's runs check themselves (wmr.sim.validity), the wheels' contact stiffness is the one asked for, the
exported keyframe holds the module angles, and the MuJoCo options of Params reach the model."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

import wmr
from wmr.errors import InputValueError
from wmr.sim import Params, Schedule, Simulation, Validity, export, run
from wmr.sim.validity import CHATTER, ENERGY, Monitor

mujoco = pytest.importorskip("mujoco")


def _bot(kind="centred"):
    return wmr.paper_robot(kind, L=0.3, r=0.05)


def _drive(params, kind="centred", seconds=1.0):
    sim = Simulation(_bot(kind), params=params)
    return run(sim, Schedule.constant(np.zeros(3), np.full(sim.robot.n_rates, 5.0)), seconds)


@pytest.mark.parametrize("contact_time", [0.005, 0.003])
def test_the_wheels_contact_stiffness_is_the_one_asked_for(contact_time):
    """The wheel's geom has the higher priority: MuJoCo uses its solref, not the mean with the ground's 0.02 s."""
    sim = Simulation(_bot(), params=Params(contact_time=contact_time))
    d = sim.data
    assert d.ncon == 3
    assert all(d.contact[k].solref[0] == pytest.approx(contact_time) for k in range(d.ncon))


def test_the_keyframe_carries_the_servo_targets():
    """A model loaded from the exported text and reset to its keyframe holds its module angles."""
    beta = [0.3, -0.5, 1.1]
    ex = export(_bot("offset"), beta=beta)
    m = mujoco.MjModel.from_xml_string(ex.xml)
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, 0)
    assert np.allclose(d.ctrl, [0.3, 0.0, -0.5, 0.0, 1.1, 0.0])
    mujoco.mj_step(m, d, nstep=1000)
    steer = [m.joint(f"u{i}_steer").qposadr[0] for i in (1, 2, 3)]
    assert np.allclose(d.qpos[steer], beta, atol=1e-3)


def test_mujoco_options_reach_the_model_and_bad_ones_are_refused():
    m = mujoco.MjModel.from_xml_string(export(_bot(), params=Params(integrator="Euler", cone="pyramidal")).xml)
    assert m.opt.integrator == mujoco.mjtIntegrator.mjINT_EULER and m.opt.cone == mujoco.mjtCone.mjCONE_PYRAMIDAL
    with pytest.raises(InputValueError, match="integrator"):
        Params(integrator="leapfrog")
    with pytest.raises(InputValueError, match="cone"):
        Params().replace(cone="round")


def test_a_nominal_run_is_valid_and_lasts_its_time_at_any_step():
    rec = _drive(Params())
    assert rec.validity.valid() and rec.validity.samples == len(rec.t)
    slow = _drive(Params(timestep=0.002))  # a step longer than the control period: one step per period
    assert slow.t[-1] == pytest.approx(1.0) and slow.validity.valid()


def test_an_unstable_or_sinking_run_is_invalid():
    """An explicit integrator with a long step makes the drive servos swing from limit to limit; a very soft contact
    lets the wheels sink: both are refused, with the reason."""
    unstable = _drive(Params(integrator="Euler", timestep=0.004)).validity
    assert not unstable.valid() and any("torque limit" in p or "chattered" in p for p in unstable.problems())
    soft = _drive(Params(contact_time=0.3)).validity
    assert not soft.valid() and any("sank" in p for p in soft.problems())


def test_the_dual_wheel_servos_under_euler_are_caught():
    """The issue's case: under Euler the dual wheel's drive servos go unstable; the run says so."""
    robot = _bot("dual")
    rates = wmr.inverse(robot, np.zeros(3), [0.0, 0.0, 0.0], beta_dot=np.ones(3)).value
    for integrator, ok in (("implicitfast", True), ("Euler", False)):
        sim = Simulation(robot, params=Params(integrator=integrator))
        s = Schedule(np.array([0.0, 2.0]), np.array([np.zeros(3), np.full(3, 2.0)]), np.array([rates, rates]))
        v = run(sim, s, 2.0).validity
        assert v is not None and v.valid() is ok


def test_validity_problems_and_expected_stalls():
    v = Validity(saturation={"u1_steer": 1.0, "u1_drive": 0.1}, chatter={"u1_drive": 2 * CHATTER})
    assert v.problems(["u1_steer"]) == ("u1_drive chattered (torque jumps 80% of its limit per sample)",)
    assert len(v.problems()) == 2 and not Validity.diverged().valid() and Validity().valid()
    assert Validity(energy=2 * ENERGY).problems() and Validity(warnings=1).problems()


def _state(t, energy, tau=0.0, speed=0.0):
    """A MuJoCo state reduced to what the monitor reads: one servo, no contact, no push."""
    return SimpleNamespace(
        time=t,
        energy=np.array([0.0, energy]),
        actuator_force=np.array([tau]),
        actuator_velocity=np.array([speed]),
        xfrc_applied=np.zeros((2, 6)),
        qvel=np.zeros(6),
        ncon=0,
        contact=[],
        warning=[SimpleNamespace(number=0) for _ in range(8)],
    )


def test_energy_from_nowhere_is_caught_and_work_done_is_not():
    model = SimpleNamespace(nu=1, actuator_forcerange=np.array([[-10.0, 10.0]]), geom_size=np.zeros((1, 3)))
    for tau, expected in ((1.0, True), (0.0, False)):  # 1 N m at 1 rad/s for 1 s: 1 J of work, 1 J gained
        mon = Monitor(mujoco, model, ["u1_drive"], [], 1, scale=1.0)
        for k in range(11):
            mon.update(_state(0.1 * k, 0.1 * k, tau=tau, speed=1.0))
        assert mon.validity().valid() is expected
