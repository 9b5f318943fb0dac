"""wmr.sim's export: every example robot loads and steps in MuJoCo or is refused with a reason; the model's
geometry is wmr's (checked against the units' own points); servos on the joints the units drive and on no
other; a kind wmr.sim has never seen exported from its own description; MuJoCo only where asked for."""

from __future__ import annotations

import dataclasses
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.errors import InputTypeError, InputValueError
from wmr.io.mechanism import VERTICAL, Body, mount, root_body, wheel
from wmr.model.backend import NUMERIC
from wmr.model.wheels import Joint, WheelUnit
from wmr.sim import VELOCITY, Params, Schedule, Simulation, export, run, servo, start_angles, to_mjcf

mujoco = pytest.importorskip("mujoco")

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))


def _model(xml):
    return mujoco.MjModel.from_xml_string(xml)


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_every_example_loads_and_steps_or_is_refused(path):
    robot = wmr.load(path)
    if any(isinstance(u, wmr.SwedishWheel) for u in robot.wheels):
        with pytest.raises(NotImplementedError, match="Swedish wheel at .*rollers"):
            to_mjcf(robot)
        return
    # offset arms along the spin about C: the paper's offset robot (d = L) tips over at beta = 0, when C lies
    # outside the triangle of its contact points
    m = _model(to_mjcf(robot, beta=start_angles(robot, [1.0, 0.0, 0.0])))
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, 0)
    mujoco.mj_step(m, d, nstep=500)
    assert np.isfinite(d.qpos).all()
    wheels = sum(len(m.wheels) for m in export(robot).mechanisms)
    assert d.ncon == wheels  # every wheel on the ground, nothing else touching
    assert abs(d.qpos[2] - max(u.r for u in robot.wheels)) < 0.01 * max(u.r for u in robot.wheels)


def _mixed():
    return wmr.Robot(
        [
            wmr.OffsetWheel((0.3, 0.1), r=0.05, d=0.03),
            wmr.CentredWheel((-0.2, 0.25), r=0.04),
            wmr.DualWheel((-0.2, -0.25), r=0.03, b=0.06),
            wmr.FixedWheel((0.25, -0.3), r=0.05, angle=0.4),
        ]
    )


def test_geometry_is_wmrs():
    """At any steering angles, every wheel centre of the model is where the unit's points() put it, at height r."""
    robot = _mixed()
    rng = np.random.default_rng(1)
    for _ in range(3):
        beta = robot.effective_beta(rng.uniform(-np.pi, np.pi, robot.w))
        ex = export(robot, beta)
        m = _model(ex.xml)
        d = mujoco.MjData(m)
        mujoco.mj_resetDataKeyframe(m, d, 0)
        mujoco.mj_forward(m, d)
        for i, (u, mech) in enumerate(zip(robot.wheels, ex.mechanisms)):
            want = u.points(beta[i])["wheels"]
            for k, body in enumerate(mech.wheels):
                b = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, ex.name(i, body.name))
                assert np.allclose(d.xpos[b][:2], want[k], atol=1e-9) and d.xpos[b][2] == pytest.approx(u.r)
                axle = d.xmat[b].reshape(3, 3)[:, 0]
                assert np.allclose(axle[:2], u.points(beta[i])["i"], atol=1e-9)  # drive hinge about i_i


def test_each_kind_has_its_servos_and_rates():
    robot = _mixed()  # every joint as its kind drives it
    xml = to_mjcf(robot)
    assert xml.count("<position ") == 2 and xml.count("<velocity ") == 5  # offset, centred; 1 + 1 + 2 + 1 drives
    ex = export(robot)
    cols = [col for _, _, col in ex.hinges() if col is not None]
    assert sorted(cols) == list(range(robot.n_rates))  # every rate measured by one encoder
    for i, (u, mech) in enumerate(zip(robot.wheels, ex.mechanisms)):
        assert sorted(j.name for j in mech.joints) == sorted(j.name for j in u.joints)
        assert sum(j.steering for j in mech.joints) == (1 if u.steered else 0)
        assert all(
            robot.rate_slices[i].start <= c < robot.rate_slices[i].stop
            for k, _, c in ex.hinges()
            if k == i and c is not None
        )
    dual = ex.mechanisms[2]
    assert [(j.name, servo(j)) for j in dual.joints] == [("swivel", None), ("drive1", VELOCITY), ("drive2", VELOCITY)]
    offset = ex.mechanisms[0]
    assert [(j.name, j.absolute) for j in offset.joints] == [("steer", True), ("drive", False)]  # phi = psi + beta (7)


def test_passive_joints_get_no_servo():
    """The units say which joints are driven: a castor (both joints passive) gets none, one passive joint none."""
    diff = wmr.load(ROOT / "examples" / "differential.toml")  # its castor: driven = {steer, drive: false}
    xml = to_mjcf(diff)
    assert "u3_steer" in xml and 'joint="u3_' not in xml  # a castor: its hinges, no servo
    m = _model(xml)
    assert export(diff).servo_names == tuple(m.actuator(a).name for a in range(m.nu)) == ("u1_drive", "u2_drive")
    motor = dataclasses.replace(diff.wheels[2], driven=None)  # the kind's default: both driven
    assert to_mjcf(wmr.Robot([*diff.wheels[:2], motor])).count('joint="u3_') == 2
    free_steer = dataclasses.replace(diff.wheels[2], driven={"steer": False})
    assert export(wmr.Robot([*diff.wheels[:2], free_steer])).servo_names == ("u1_drive", "u2_drive", "u3_drive")
    steered_swivel = wmr.DualWheel((0.0, 0.0), r=0.05, b=0.1, driven={"swivel": True})
    assert '<position name="u1_swivel"' in to_mjcf(wmr.Robot([steered_swivel]))


def test_start_angles_trail_where_the_steering_is_free():
    """Offset wheels (steering free for any twist) start trailing, j along p_dot; centred wheels as steering_angles."""
    robot = _mixed()
    twist = np.array([0.0, 1.0, 0.0])  # forward: p_dot = (1, 0) everywhere
    beta = start_angles(robot, twist)
    assert beta[0] == pytest.approx(-np.pi / 2)  # j = (-sin, cos) = (1, 0): arm behind P
    assert np.allclose(beta[1:3], wmr.steering_angles(robot, twist)[1:3]) and beta[3] == pytest.approx(0.4)


def test_parameters_reach_the_model():
    robot = wmr.paper_robot("centred", L=0.3, r=0.05)
    m = _model(to_mjcf(robot, sliding=0.6, torsional=0.1, rolling=0.02, timestep=0.002))
    g = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, "u1_wheel")
    assert np.allclose(m.geom_friction[g], [0.6, 0.1 * 0.05, 0.02 * 0.05]) and m.opt.timestep == 0.002
    ex = export(robot)
    mass = float(sum(_model(ex.xml).body_mass))
    assert ex.weight == pytest.approx(mass * 9.81)
    limit = _model(ex.xml).actuator_forcerange
    assert limit[0, 1] == pytest.approx(Params().steer_torque * ex.weight * 0.05)
    assert limit[1, 1] == pytest.approx(Params().drive_torque * ex.weight * 0.05)


def test_export_is_deterministic_and_carries_the_start_angles():
    robot = wmr.paper_robot("offset", L=0.3, r=0.05)
    a, b = to_mjcf(robot, beta=[0.1, 0.2, 0.3]), to_mjcf(robot, beta=[0.1, 0.2, 0.3])
    assert a == b
    m = _model(a)
    assert np.allclose(m.key_qpos[0][[7, 9, 11]], [0.1, 0.2, 0.3])


@dataclasses.dataclass(frozen=True)
class TwinCastor(WheelUnit):
    r"""An office chair's castor, a kind wmr.sim has never seen (not registered).

    Two wheels at :math:`H \pm b\,\mathbf i` on an arm, :math:`H = P - d\,\mathbf j`, on a free swivel; every joint
    passive.

    The wheels roll :math:`H` at :math:`-\tfrac r2(\dot\theta_1 + \dot\theta_2)\mathbf j` and turn the arm at
    :math:`\dot\phi = -\tfrac{r}{2b}(\dot\theta_1 - \dot\theta_2)`, so :math:`P = H + d\,\mathbf j` moves at
    :math:`-\tfrac r2(\dot\theta_1 + \dot\theta_2)\mathbf j + \tfrac{dr}{2b}(\dot\theta_1 - \dot\theta_2)\mathbf i`.
    """

    d: float = 0.03
    b: float = 0.02
    JOINTS = (
        Joint("swivel", "swivel", driven=False),
        Joint("drive1", "drive", driven=False, rate=("theta", r"\theta", "1")),
        Joint("drive2", "drive", driven=False, rate=("theta", r"\theta", "2")),
    )

    def local_block(self, backend=NUMERIC):
        k = self.d * self.r / (2 * self.b)
        return backend.matrix([[k, -k], [-self.r / 2, -self.r / 2]])

    def _points(self, P, i_dir, j_dir):
        H = P - self.d * j_dir
        return {
            "P": P,
            "H": H,
            "wheels": np.stack([H + self.b * i_dir, H - self.b * i_dir], axis=-2),
            "i": i_dir,
            "j": j_dir,
        }


@root_body.register(TwinCastor)
def _twin_castor(unit, height):
    """Its own entry: the swivel at P, the arm to H = P - d j, the two wheels at H +- b i."""
    r, d, b = float(unit.r), float(unit.d), float(unit.b)
    z = r - height
    swivel, drive1, drive2 = unit.joints
    wheels = (wheel("wheel1", (b, -d, z), r, drive1), wheel("wheel2", (-b, -d, z), r, drive2))
    return Body(
        "swivel",
        mount(unit.position),
        0.0,
        swivel,
        VERTICAL,
        size=d,
        rods=(((0.0, 0.0, 0.0), (0.0, -d, z)), ((b, -d, z), (-b, -d, z))),
        children=wheels,
    )


def test_a_kind_wmr_sim_has_never_seen_is_exported_from_its_own_description():
    """A differential drive on the twin castor above: its wheels where its points() put them, no servo on it, and
    driven forward from a sideways start the castor swings round to trail (j along the motion)."""
    diff = wmr.load(ROOT / "examples" / "differential.toml")
    robot = wmr.Robot([*diff.wheels[:2], TwinCastor((-0.3, 0.0), r=0.03)])
    for beta in (0.0, 1.1, -2.5):
        ex = export(robot, [0.0, 0.0, beta])
        m = _model(ex.xml)
        d = mujoco.MjData(m)
        mujoco.mj_resetDataKeyframe(m, d, 0)
        mujoco.mj_forward(m, d)
        for k, name in enumerate(("u3_wheel1", "u3_wheel2")):
            got = d.xpos[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, name)]
            assert np.allclose(got[:2], robot.wheels[2].points(beta)["wheels"][k], atol=1e-9)
    assert ex.servo_names == ("u1_drive", "u2_drive") and ex.drive_names[2:] == ("u3_drive1", "u3_drive2")
    sim = Simulation(robot, beta=[0.0, 0.0, 0.0])  # arm across the motion
    rec = run(sim, Schedule.constant(np.zeros(3), [5.0, 5.0, 0.0, 0.0]), 3.0)
    assert rec.twist[-1, 1] == pytest.approx(0.08 * 5.0, rel=0.05)  # v = r omega forward
    # and straight on average: the castor drags not (at the wheels' own contact stiffness, 0.005 s, its two wheels
    # shimmy a little, the turning rate swinging by a few mrad/s about zero)
    assert abs(rec.twist[rec.t >= 2.0, 0].mean()) < 1e-3
    trail = -np.pi / 2  # j = (-sin, cos) = (1, 0)
    assert abs(np.angle(np.exp(1j * (rec.beta[-1, 2] - trail)))) < 0.01  # (held by a servo at 0: 0.036 off)


def test_bad_input_is_named():
    robot = wmr.paper_robot("centred", L=0.3, r=0.05)
    with pytest.raises(InputValueError, match="sliding"):
        to_mjcf(robot, sliding=-1.0)
    with pytest.raises(InputTypeError, match="unknown parameter"):
        to_mjcf(robot, slidng=1.0)
    with pytest.raises(InputTypeError, match="params"):
        to_mjcf(robot, params={"sliding": 1.0})  # type: ignore[arg-type]
    with pytest.raises(InputValueError, match="beta"):
        to_mjcf(robot, beta=[0.0, 0.0])


def test_a_unit_without_a_mechanism_is_refused():
    """A kind that does not describe its bodies and joints is refused, naming the wheel, not guessed at."""

    @dataclasses.dataclass(frozen=True)
    class Mute(wmr.CentredWheel):  # (no kind of its own: not registered)
        pass

    root_body.register(Mute)(root_body.dispatch(object))  # the default: no description

    robot = wmr.Robot([wmr.CentredWheel((0.3, 0.0), r=0.05), Mute((-0.3, 0.0), r=0.05)])
    with pytest.raises(NotImplementedError, match=r"wheel 2 \(Mute\): Mute does not describe its mechanism"):
        to_mjcf(robot)


def test_import_wmr_does_not_import_mujoco():
    for statement in ("import wmr", "import wmr.sim; wmr.sim.to_mjcf(wmr.paper_robot())"):
        out = subprocess.run(
            [sys.executable, "-c", f"import sys; {statement}; print('mujoco' in sys.modules)"],
            capture_output=True,
            text=True,
            check=True,
        ).stdout.strip()
        assert out == "False", statement
    make = "wmr.sim.Simulation(wmr.paper_robot('centred', L=0.3, r=0.05), settle=0)"
    out = subprocess.run(
        [sys.executable, "-c", f"import sys, wmr.sim; {make}; print('mujoco' in sys.modules)"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.strip()
    assert out == "True"  # the check above can see an import


def test_sim_is_an_optional_extra():
    import tomllib

    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert any(d.startswith("mujoco") for d in meta["optional-dependencies"]["sim"])
    assert not any(d.startswith("mujoco") for d in meta["dependencies"])


def test_yaw_of_a_quaternion():
    from wmr.sim.measure import yaw

    assert round(yaw([np.cos(0.25), 0.0, 0.0, np.sin(0.25)]), 12) == 0.5
