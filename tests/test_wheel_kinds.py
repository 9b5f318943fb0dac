"""Wheel kinds answer for themselves: the contract every registered kind meets, the registry, and a new kind
added as one new module (the only file it needs) that the robot, the analyses, robot files, the drawings
and the command line then take."""

import dataclasses
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import sympy as sp

import wmr
from wmr.errors import InputTypeError, InputValueError
from wmr.io.mechanism import mechanism, root_body
from wmr.io.wheel_tables import FileKey
from wmr.model.wheels import Joint, WheelUnit, wheel_kind, wheel_kinds
from wmr.model.wheels.joints import actuation

from wheel_contract import CHECKS, check_declarations, check_kind, check_mechanism

PACKAGE = Path(wmr.__file__).resolve().parent  # the package under test (the repository's or a wheel's)
KINDS = sorted(wheel_kinds())


def test_the_five_kinds_are_registered():
    assert {"offset", "centred", "dual", "fixed", "swedish"} <= set(KINDS)
    assert wheel_kind("offset") is wmr.OffsetWheel and wheel_kind("swedish") is wmr.SwedishWheel


@pytest.mark.parametrize("check", CHECKS, ids=[c.__name__ for c in CHECKS])
@pytest.mark.parametrize("kind", KINDS)
def test_every_kind_meets_the_contract(kind, check):
    check(wheel_kind(kind))


def test_the_contract_can_fail():
    """A kind that declares what its block does not do is caught: rolls_in_plane on an invertible block."""

    @dataclasses.dataclass(frozen=True)
    class Liar(wmr.OffsetWheel):  # (no kind of its own: not registered)
        rolls_in_plane = True  # an offset wheel (d > 0) moves its mount point every way

    with pytest.raises(AssertionError):
        check_declarations(Liar)
    check_declarations(wmr.OffsetWheel)


def test_the_mechanism_contract_can_fail():
    """A mechanism with its wheel ahead of P, one deaf to the unit's actuation, a refusal without a reason: caught."""

    @dataclasses.dataclass(frozen=True)
    class Ahead(wmr.OffsetWheel):  # H = P + d j: not where points() puts the wheel
        pass

    @root_body.register(Ahead)
    def _ahead(unit, height):
        root = root_body.dispatch(wmr.OffsetWheel)(unit, height)
        arm = root.children[0]
        return dataclasses.replace(root, children=(dataclasses.replace(arm, pos=(0.0, unit.d, arm.pos[2])),))

    @dataclasses.dataclass(frozen=True)
    class Deaf(wmr.OffsetWheel):  # the kind's default actuation, whatever the unit's
        pass

    @root_body.register(Deaf)
    def _deaf(unit, height):
        return root_body(wmr.OffsetWheel(unit.position, unit.r, d=unit.d), height)

    @dataclasses.dataclass(frozen=True)
    class Shrug(wmr.CentredWheel):
        pass

    @root_body.register(Shrug)
    def _shrug(unit, height):
        raise NotImplementedError("no")

    @dataclasses.dataclass(frozen=True)
    class Mute(wmr.CentredWheel):  # no entry of its own: the default, no description
        pass

    root_body.register(Mute)(root_body.dispatch(object))

    for cls in (Ahead, Deaf, Shrug, Mute):
        with pytest.raises(AssertionError):
            check_mechanism(cls)
    check_mechanism(wmr.OffsetWheel)


def test_a_mechanism_takes_a_height_and_numbers():
    unit = wmr.OffsetWheel((0.3, 0.0), r=0.05, d=0.02)
    assert mechanism(unit, 0.05).wheels[0].pos == (0.0, -0.02, 0.0)
    with pytest.raises(InputValueError, match=r"height .* at least the wheel radius r = 0.05, got 0.04"):
        mechanism(unit, 0.04)
    with pytest.raises(InputTypeError, match="height"):
        mechanism(unit, "tall")  # type: ignore[arg-type]
    with pytest.raises(InputValueError, match="free symbols"):
        mechanism(wmr.OffsetWheel((0.3, 0.0), r=0.05, d=sp.Symbol("d")), 0.05)
    exact = mechanism(wmr.OffsetWheel((sp.sqrt(3) / 10, 0), r=sp.Rational(1, 20), d=sp.Rational(1, 50)), 0.05)
    assert exact.root.pos == (float(sp.sqrt(3) / 10), 0.0, 0.0) and exact.wheels[0].pos == (0.0, -0.02, 0.0)


# ------------------------------------------------------------------------------------------ the registry
def test_wheel_kind_names_and_suggests():
    with pytest.raises(InputValueError, match=r"kind must be one of centred, dual, fixed, offset, swedish.*'centred'"):
        wheel_kind("centered")
    with pytest.raises(InputTypeError, match=r"\bkind\b"):
        wheel_kind(3)  # type: ignore[arg-type]


def test_a_kind_name_is_taken_once():
    with pytest.raises(InputValueError, match=r"'offset' is already OffsetWheel"):

        @dataclasses.dataclass(frozen=True)
        class Other(WheelUnit):
            kind = "offset"

    assert wheel_kind("offset") is wmr.OffsetWheel


def test_subclasses_without_a_kind_are_not_registered():
    @dataclasses.dataclass(frozen=True)
    class Variant(wmr.CentredWheel):
        """A centred wheel under another class: not a kind of its own."""

    assert Variant not in wheel_kinds().values() and Variant.kind == "centred"
    assert wheel_kind("centred") is wmr.CentredWheel


# ------------------------------------------------------------------------------------------ declarations
def test_joints_and_file_keys_check_themselves():
    with pytest.raises(InputValueError, match="kind must be one of steer, swivel, drive, roller"):
        Joint("x", "motor", True)
    with pytest.raises(InputTypeError, match="driven"):
        Joint("x", "drive", 1)  # type: ignore[arg-type]
    with pytest.raises(InputTypeError, match="name"):
        Joint("two words", "drive", True)
    with pytest.raises(InputValueError, match="check"):
        FileKey("k", "f", "meaning", check="even")
    with pytest.raises(InputValueError, match="distinct names"):

        @dataclasses.dataclass(frozen=True)
        class Twice(WheelUnit):
            JOINTS = (Joint("a", "drive", True), Joint("a", "drive", True))


def test_actuation_overrides_the_defaults():
    joints = wmr.DualWheel.JOINTS
    assert actuation(joints, None) == (False, True, True)
    assert actuation(joints, {"swivel": True}) == (True, True, True)
    assert actuation(joints, [False, False, True]) == (False, False, True)
    with pytest.raises(InputValueError, match=r"driven names a joint 'steer' that DualWheel does not have"):
        wmr.DualWheel((0, 0), r=0.1, b=0.1, driven={"steer": True})
    with pytest.raises(InputTypeError, match=r"driven\['drive1'\]"):
        wmr.DualWheel((0, 0), r=0.1, b=0.1, driven={"drive1": 1})
    with pytest.raises(InputValueError, match="one bool per joint"):
        wmr.DualWheel((0, 0), r=0.1, b=0.1, driven=(True,))
    castor = wmr.OffsetWheel((0, 0), r=0.1, d=0.05, driven={"steer": False, "drive": False})
    assert [j.driven for j in castor.joints] == [False, False] and castor != wmr.OffsetWheel((0, 0), r=0.1, d=0.05)


def test_rate_columns_and_the_kinds_table():
    from wmr.model.wheels import kinds_table
    from wmr.model.wheels.joints import rate_columns

    swivel = Joint("swivel", "swivel", driven=False)
    drives = [Joint(f"drive{k}", "drive", driven=True, rate=("theta", r"\theta", str(k))) for k in (1, 2)]
    assert rate_columns((swivel, *drives)) == {"drive1": 0, "drive2": 1}
    rows = kinds_table().splitlines()
    assert [line.split()[0] for line in rows[3:8]] == [
        "``centred``",
        "``dual``",
        "``fixed``",
        "``offset``",
        "``swedish``",
    ]
    assert rows[4].split("  ")[-1] == r":math:`\dot\theta_{i1},\ \dot\theta_{i2}`"  # a dual wheel's rates


# ------------------------------------------------------------------------------------------ a new kind
BALL = '''\
r"""A ball caster: a ball held in a socket at :math:`P_i`, free to roll every way (two passive rates).

Spinning at :math:`\\dot\\theta_i` about :math:`\\mathbf i_i` moves the ball's centre by
:math:`-r\\dot\\theta_i\\mathbf j_i`, at :math:`\\dot\\sigma_i` about :math:`\\mathbf j_i` by
:math:`+r\\dot\\sigma_i\\mathbf i_i`; the block is invertible, so a ball caster puts no constraint on the
platform.  In a robot file it takes ``position`` and ``radius`` only.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..backend import NUMERIC
from .joints import Joint
from .unsteered import UnsteeredUnit

__all__ = ["BallCaster"]


@dataclass(frozen=True)
class BallCaster(UnsteeredUnit):
    """A ball caster at ``position`` of radius ``r``: no steering joint, both rolling rates passive.

    Parameters
    ----------
    position : pair
    r : float
    angle : float, optional
        The frame of its two rates (default 0).
    driven : mapping or sequence of bool, optional
    """

    angle: float = 0.0
    kind = "ball"
    JOINTS = (Joint("roll_i", "roller", driven=False, rate=("theta", r"\\theta", "")),
              Joint("roll_j", "roller", driven=False, rate=("sigma", r"\\sigma", "")))

    def local_block(self, backend=NUMERIC):
        """The block: the centre moves by -r theta_dot j + r sigma_dot i.

        Parameters
        ----------
        backend : NUMERIC or SYMBOLIC, optional

        Returns
        -------
        numpy.ndarray (2, 2) or sympy.Matrix (2, 2)
        """
        return backend.matrix([[0, self.r], [-self.r, 0]])
'''

DIFFERENTIAL_WITH_BALL = """\
name = "differential drive on a ball caster"

[[wheel]]
type = "fixed"
position = [0.0, 0.2]
radius = 0.05
angle_deg = 90.0

[[wheel]]
type = "fixed"
position = [0.0, -0.2]
radius = 0.05
angle_deg = 90.0

[[wheel]]
type = "ball"
position = [-0.3, 0.0]
radius = 0.02
"""

USE = """\
import json, sys
import numpy as np
import wmr
from wmr.cli import main
from wmr.model.wheels import kinds_table, wheel_kinds
sys.path.insert(0, sys.argv[2])
from wheel_contract import check_kind

ball = wheel_kinds()["ball"]
from wmr.io import wheel_tables
from wmr.io.mechanism import root_body
from wmr.plot.parts import Disc, has_parts, unit_parts


def refused(why):                                          # the contract names the outer layer's missing entry
    try:
        check_kind(ball)
    except AssertionError as exc:
        assert why in str(exc), exc
    else:
        raise AssertionError(f"a kind met the contract without {why}")


assert [k.name for k in wheel_tables.file_keys(ball)][2:] == ["angle_deg"]  # an unsteered unit's, inherited
wheel_tables.register(ball, ())                            # its own: position and radius only
assert not has_parts(ball)                                 # the drawing layer holds no entry for it yet
refused("BallCaster has no entry in wmr.plot.parts.unit_parts")


@unit_parts.register(ball)                                 # its drawing, registered where drawings live
def _ball(unit, beta):
    return (Disc(np.asarray(unit.position, dtype=float), 0.0, float(unit.r), arrow=False),)


refused("BallCaster has no entry in wmr.io.mechanism.root_body")


@root_body.register(ball)                                  # a refusal that says why is an entry
def _no_ball(unit, height):
    raise NotImplementedError("a ball caster turns about every axis in its socket: two hinges in series would "
                              "lock when the outer one turns a quarter turn, and a mechanism has hinges only")


check_kind(ball)                                           # the contract every kind meets
bot = wmr.load(sys.argv[1])
assert type(bot.wheels[2]) is ball and bot.rate_names[-2:] == ("theta_dot_3", "sigma_dot_3")
assert wmr.dump(bot).rstrip().endswith('type = "ball"\\nposition = [-0.3, 0.0]\\nradius = 0.02')
sol = wmr.inverse(bot, [0.0, 0.0, 0.0], [0.5, 1.0, 0.0])   # turn and drive: admissible
side = wmr.inverse(bot, [0.0, 0.0, 0.0], [0.0, 0.0, 1.0])  # sideways: the fixed wheels slip
assert bool(sol.admissible) and not bool(side.admissible)
assert int(wmr.mobility(bot, [0.0, 0.0, 0.0])) == 2         # 3 + 4 rates - rank F (5): turn and drive
assert wmr.campion_class(bot).label == "(2,0)"
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from wmr.plot.robot import draw_robot
fig, ax = plt.subplots()
draw_robot(ax, bot, np.zeros(3))
assert main(["analyze", sys.argv[1], "--json", "--grid", "50", "--twists", "5"]) == 0
import wmr.sim
try:
    wmr.sim.to_mjcf(bot)                                   # a physics engine: refused, with the kind's reason
except NotImplementedError as exc:
    assert "wheel 3 (BallCaster): a ball caster turns about every axis" in str(exc), exc
else:
    raise AssertionError("a ball caster was exported")
assert main(["simulate", sys.argv[1], "--seconds", "0"]) == 2
print("``ball``" in kinds_table() and "``ball``" in wmr.model.wheels.__doc__)
"""


def test_a_new_kind_is_one_new_module(tmp_path):
    """Copy the package, add ``wmr/model/wheels/ball.py`` and nothing else in wmr: every part of wmr takes the new
    kind once its drawing entry is registered (wmr.plot.parts; the contract fails without it), and wmr.sim refuses it
    with the reason its module gives."""
    shutil.copytree(PACKAGE, tmp_path / "wmr", ignore=shutil.ignore_patterns("__pycache__"))
    (tmp_path / "wmr" / "model" / "wheels" / "ball.py").write_text(BALL)
    changed = sorted(
        str(p.relative_to(tmp_path / "wmr"))
        for p in (tmp_path / "wmr").rglob("*.py")
        if not (PACKAGE / p.relative_to(tmp_path / "wmr")).exists()
        or (PACKAGE / p.relative_to(tmp_path / "wmr")).read_bytes() != p.read_bytes()
    )
    assert changed == ["model/wheels/ball.py"]
    robot = tmp_path / "ball.toml"
    robot.write_text(DIFFERENTIAL_WITH_BALL)
    env = {**os.environ, "PYTHONPATH": str(tmp_path), "MPLBACKEND": "Agg"}
    out = subprocess.run(
        [sys.executable, "-c", USE, str(robot), str(Path(__file__).parent)],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert out.returncode == 0, out.stderr[-3000:]
    assert out.stdout.strip().splitlines()[-1] == "True", out.stdout[-2000:]
    assert '"wheels": [\n    "fixed",\n    "fixed",\n    "ball"\n  ]' in out.stdout


def test_the_new_kind_is_not_in_this_package():
    """(The module above was added to a copy: this process has not seen it.)"""
    assert "ball" not in wheel_kinds()
    check_kind(wmr.CentredWheel)
