"""What every wheel kind must answer, checked on any kind: :func:`check_kind` (used by tests/test_wheel_kinds.py
for every registered kind, and by a kind's own test file).

A unit of the kind is built *from its robot-file keys* (:func:`example`), so a new kind is checked without
a line written for it here.  The checks compare the kind's declarations with each other and with its
block of J2: its rates with its joints, ``steered`` with its joints and its constant angle,
``rolls_in_plane`` with the left null space of its block, a steering row with the null space, the block
with the rotation (11), SymPy with NumPy; then files, drawing, kinematics and the analyses of a robot
on three such units; and the unit's mechanism for a physics engine (its own joints, its wheels where its
points put them) or a refusal that says why.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

import wmr
from wmr.analysis.linalg import left_null_space, singular_values
from wmr.analysis.overview import overview
from wmr.analysis.unit_design import ChangeKind, dead_zone, isotropic_change
from wmr.io import mechanism as M
from wmr.io import wheel_tables as K
from wmr.model.backend import NUMERIC
from wmr.plot import parts as P

#: a valid value of each kind of file key (lengths in metres, angles in degrees)
VALUES = {"pair": [0.3, -0.2], "positive": 0.04, "nonnegative": 0.03, "number": 30.0}


def table(cls, position=(0.3, -0.2), radius=0.05):
    """The ``[[wheel]]`` table of a unit of kind ``cls``, every key given a valid value."""
    lines = [
        "[[wheel]]",
        f'type = "{cls.kind}"',
        f"position = [{position[0]!r}, {position[1]!r}]",
        f"radius = {radius!r}",
    ]
    lines += [f"{key.name} = {VALUES[key.check]!r}" for key in K.file_keys(cls)[2:]]
    return "\n".join(lines) + "\n"


def example(cls, position=(0.3, -0.2), radius=0.05):
    """A unit of kind ``cls`` built from the values of its declared file keys (read as a file would be)."""
    values = {"position": list(position), "radius": radius, **{k.name: VALUES[k.check] for k in K.file_keys(cls)[2:]}}
    return cls(**{k.field: k.read(values[k.name]) for k in K.file_keys(cls)})


def trio(cls, L=0.3):
    """A robot on three units of kind ``cls`` at the paper's mount points."""
    text = 'name = "trio"\n\n' + "\n".join(table(cls, p) for p in wmr.equilateral_mounts(L))
    return wmr.io.loads(text)


def _rotation(b):
    c, s = np.cos(b), np.sin(b)
    return np.array([[c, -s], [s, c]])


# ------------------------------------------------------------------------------------------ the checks
def check_registered(cls):
    """The kind is registered under its name, and robot files know its keys (its entry in wmr.io.wheel_tables)."""
    assert K.has_file_keys(cls), f"{cls.__name__} has no entry in wmr.io.wheel_tables"
    assert wmr.model.wheels.wheel_kind(cls.kind) is cls and cls.kind in wmr.io.wheel_keys()
    assert type(wmr.io.loads(table(cls)).wheels[0]) is cls


def check_declarations(cls):
    """Joints, rates, steering, the constant angle and ``rolls_in_plane`` agree with each other and the block."""
    unit = example(cls)
    L = np.asarray(unit.local_block(NUMERIC), dtype=float)
    assert L.shape == (2, cls.n_rates) and cls.n_rates == len(cls.RATES) >= 1
    assert cls.RATES == tuple(j.rate for j in cls.JOINTS if j.rate is not None)
    assert cls.steered == any(j.kind in ("steer", "swivel") for j in cls.JOINTS)
    assert (unit.constant_angle is None) == cls.steered
    assert unit.driven == tuple(j.driven for j in cls.JOINTS) and unit.joints == cls.JOINTS
    # rolls_in_plane: no slip holds P_i to the wheel plane, i.e. the axle i = (1, 0) annihilates the block
    N = left_null_space(L)
    holds_to_plane = N.shape[1] == 1 and np.allclose(np.abs(N[:, 0]), [1.0, 0.0], atol=1e-12)
    assert cls.rolls_in_plane == holds_to_plane, (cls.kind, N)
    keys = K.file_keys(cls)
    assert [k.name for k in keys[:2]] == [k.name for k in K.COMMON_KEYS] and len({k.name for k in keys}) == len(keys)
    assert set(cls.ANGLES) <= set(unit.parameters()) and {k.field for k in keys if k.degrees} <= set(cls.ANGLES)


def check_block(cls):
    """B(beta) = R(beta) L (11) at the unit's angle, batched; SymPy gives the same matrix."""
    unit = example(cls)
    L = np.asarray(unit.local_block(NUMERIC), dtype=float)
    betas = np.random.default_rng(0).uniform(-np.pi, np.pi, (2, 3))
    B = unit.block(betas)
    assert B.shape == (2, 3, 2, cls.n_rates)
    own = unit.constant_angle
    for b, Bk in zip(betas.ravel(), B.reshape(-1, 2, cls.n_rates)):
        assert np.allclose(Bk, _rotation(b if own is None else float(own)) @ L, atol=1e-15)
    beta = sp.Symbol("beta", real=True)
    S = unit.block(beta)
    assert isinstance(S, sp.MatrixBase) and S.shape == (2, cls.n_rates)
    f = sp.lambdify(beta, S, "numpy")
    assert np.allclose(np.array(f(0.7), dtype=float), unit.block(0.7), atol=1e-14)
    names = unit.rate_names(3)
    assert len(names) == len(set(names)) == len(unit.rate_symbols(3)) == cls.n_rates
    assert all("_dot_3" in n for n in names)


def check_geometry_and_drawing(cls):
    """Points in the body frame (batched); the kind's drawing entry (wmr.plot.parts): parts as data (one disc per
    wheel, a pivot iff steered), drawn."""
    unit = example(cls)
    pts = unit.points(np.zeros((4,)))
    assert pts["P"].shape == pts["H"].shape == pts["i"].shape == pts["j"].shape == (4, 2)
    assert pts["wheels"].shape[0] == 4 and pts["wheels"].shape[-1] == 2
    assert np.allclose(pts["P"], unit.position) and np.allclose(np.einsum("...k,...k", pts["i"], pts["j"]), 0)
    assert P.has_parts(cls), f"{cls.__name__} has no entry in wmr.plot.parts.unit_parts"
    parts = P.unit_parts(unit, 0.4)
    assert all(isinstance(p, (P.Disc, P.Link, P.Rollers, P.Pivot)) for p in parts)
    assert sum(isinstance(p, P.Disc) for p in parts) == pts["wheels"].shape[1]
    assert any(isinstance(p, P.Pivot) for p in parts) == cls.steered
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from wmr.plot.robot import draw_unit

    fig, ax = plt.subplots()
    try:
        P_w, H_w = draw_unit(ax, unit, 0.4, pose=(0.3, 1.0, 2.0))
        assert len(ax.patches) + len(ax.lines) >= len(parts)
        assert np.allclose(P_w, np.array([1.0, 2.0]) + _rotation(0.3) @ np.asarray(unit.position, float))
    finally:
        plt.close(fig)


def check_files(cls):
    """A unit written to a robot file reads back the same; an actuation override too; each key is required."""
    unit = example(cls)
    bot = wmr.Robot([unit], name="one")
    back = wmr.io.loads(wmr.dump(bot)).wheels[0]
    assert type(back) is cls and back.driven == unit.driven
    for (k, v), (k2, v2) in zip(unit.parameters().items(), back.parameters().items()):
        assert k == k2 and np.isclose(float(v), float(v2), rtol=1e-14, atol=1e-15), (k, v, v2)
    flipped = {cls.JOINTS[0].name: not cls.JOINTS[0].driven}
    other = wmr.io.loads(wmr.dump(wmr.Robot([cls(**{**_fields(unit), "driven": flipped})]))).wheels[0]
    assert other.driven[0] is (not cls.JOINTS[0].driven) and other.driven[1:] == unit.driven[1:]
    for key in K.file_keys(cls):
        text = "\n".join(line for line in table(cls).splitlines() if not line.startswith(key.name + " "))
        try:
            wmr.io.loads(text, "f.toml")
        except wmr.errors.RobotFileError as exc:
            assert exc.key == f"wheel[1].{key.name}" and "missing" in str(exc) and key.meaning in str(exc)
        else:
            raise AssertionError(f"{cls.kind}: a table without {key.name} was read")


def _fields(unit):
    return {"position": unit.position, **unit.parameters()}


def check_steering(cls):
    """beta_rate has the batch shape; a steering row lies in the block's null space and steers as wanted."""
    unit = example(cls)
    rates = np.random.default_rng(1).normal(size=(5, cls.n_rates))
    assert np.shape(unit.beta_rate(np.zeros(5), rates)) == (5,)
    c = unit.steering_row()
    if c is None:
        return
    L = np.asarray(unit.local_block(NUMERIC), dtype=float)
    assert c.shape == (cls.n_rates,) and np.allclose(L @ c, 0, atol=1e-15) and np.any(c != 0)
    bot = trio(cls)
    twist, beta_dot = np.array([0.4, 0.1, -0.2]), np.array([0.3, -0.5, 0.2])
    beta = wmr.steering_angles(bot, twist)
    sol = wmr.inverse(bot, beta, twist, beta_dot=beta_dot)
    got = [u.beta_rate(twist[0], sol.value[sl]) for u, sl in zip(bot.wheels, bot.rate_slices)]
    assert np.allclose(got, beta_dot, atol=1e-12)


def check_robot(cls):
    """A robot on three such units: the kinematics close on themselves, the analyses run."""
    bot = trio(cls)
    rng = np.random.default_rng(2)
    for twist in rng.normal(size=(4, 3)):
        beta = wmr.steering_angles(bot, twist, current=rng.uniform(-np.pi, np.pi, bot.w))
        inv = wmr.inverse(bot, beta, twist)
        fwd = wmr.forward(bot, beta, inv.value)
        if bool(inv.admissible):
            assert bool(fwd.admissible) and np.allclose(fwd.value, twist, atol=1e-9)
        assert np.allclose(bot.J2(beta) @ inv.value - bot.J1() @ twist, -inv.residual, atol=1e-12)
    c = wmr.campion_class(bot)
    assert 0 <= c.delta_m <= 3 and 0 <= c.delta_s <= 3
    ov = overview(bot, grid=64, twists=8)
    assert ov.kinds == (cls.kind,) * 3 and ov.steered == (cls.steered,) * 3
    for u in bot.wheels:
        s = singular_values(np.asarray(u.local_block(NUMERIC), dtype=float))
        change = isotropic_change(u)
        assert change is None or (isinstance(change.kind, ChangeKind) and not np.allclose(s, s[0])), (
            cls.kind,
            change,
            s,
        )
        if change is not None:  # the changed unit's block is isotropic
            t = singular_values(np.asarray(change.unit.local_block(NUMERIC), dtype=float))
            assert np.allclose(t, t[0], rtol=1e-12), (cls.kind, change, t)
        zone = dead_zone(u)
        assert zone is None or zone >= 0


def _turn(axis, angle):
    """Rotation by ``angle`` about the unit ``axis`` (Rodrigues)."""
    k = np.asarray(axis, dtype=float)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K


def _wheel_frames(body, beta, R=None, o=None):
    """(centre, axle) of every wheel body of a mechanism, platform frame, its steering joints at ``beta``."""
    R, o = (np.eye(3), np.zeros(3)) if R is None else (R, o)
    o = o + R @ np.asarray(body.pos, dtype=float)
    R = R @ _turn((0.0, 0.0, 1.0), body.angle)
    if body.joint is not None:
        R = R @ _turn(body.axis, beta if body.joint.steering else 0.0)
    out = [(o, R[:, 0])] if body.wheel is not None else []
    for c in body.children:
        out += _wheel_frames(c, beta, R, o)
    return out


def check_mechanism(cls):
    """Its bodies and joints for a physics engine: the unit's own joints (with its actuation), each once, a wheel body
    per wheel at any steering angle where points() puts it, its axle i, at height r; or a refusal that says why."""
    assert M.has_mechanism(cls), f"{cls.__name__} has no entry in wmr.io.mechanism.root_body"
    unit = example(cls)
    height = 1.5 * float(unit.r)
    try:
        mech = M.mechanism(unit, height)
    except NotImplementedError as exc:
        assert len(str(exc).split()) >= 8, f"{cls.kind}: a refusal must say why, got {exc}"
        return
    assert sorted(mech.joints, key=lambda j: j.name) == sorted(unit.joints, key=lambda j: j.name)
    flipped = cls(**{**_fields(unit), "driven": {cls.JOINTS[0].name: not cls.JOINTS[0].driven}})
    assert {j.name: j.driven for j in M.mechanism(flipped, height).joints} == {j.name: j.driven for j in flipped.joints}
    assert sum(j.steering for j in mech.joints) == (1 if cls.steered else 0)
    for beta in (0.0, 0.7, -2.2):
        pts = unit.points(beta)
        frames = _wheel_frames(mech.root, beta)
        assert len(frames) == pts["wheels"].shape[0] == len(mech.wheels)
        for (centre, axle), want, body in zip(frames, pts["wheels"], mech.wheels):
            assert np.allclose(centre[:2], want, atol=1e-12) and np.isclose(centre[2] + height, float(unit.r))
            assert np.allclose(axle, [*pts["i"], 0.0], atol=1e-12) and body.wheel == float(unit.r)


CHECKS = (
    check_registered,
    check_declarations,
    check_block,
    check_geometry_and_drawing,
    check_files,
    check_steering,
    check_robot,
    check_mechanism,
)


def check_kind(cls):
    """Every check of this module on the wheel kind ``cls`` (an AssertionError names the one that failed)."""
    for check in CHECKS:
        check(cls)
