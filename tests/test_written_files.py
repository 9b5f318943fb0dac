"""Every file wmr writes is the same on every CPU: the writers write floats by one rule (:mod:`wmr.io.decimals`).

Another CPU computes the same numbers with arithmetic that differs in the last bits.  Each writer here (URDF, ROS 2
YAML, TOML, MJCF, ``wmr analyze/fk/ik/sweep/simulate --json``; the edition's CSV tables in
``tests/edition/test_reproducible.py``) writes the project's example
robots (``examples/*.toml``, ``examples/engineers/*.toml``) with every input moved by one ulp and NumPy's
transcendental functions one ulp off, both ways (``tests/perturb.py``), and must write the same bytes as without, and
those of the committed file where there is one.  The rule makes a changed byte improbable, not impossible (a value
within ~1e-16 relative of a rounding boundary would still flip): these are the files the project commits and ships
examples of, checked.  :func:`test_the_perturbation_changes_what_repr_writes` shows the check is not vacuous, and
:func:`test_the_writers_write_floats_by_the_rule` that no writer goes around the rule.
"""

from __future__ import annotations

import contextlib
import io
import re
from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.cli import main
from wmr.errors import InputValueError
from wmr.io import dump, to_ros2, to_urdf
from wmr.sim import to_mjcf

from conftest import ROOT
from perturb import another_cpu, nudge

EXAMPLES = sorted((ROOT / "examples").glob("*.toml")) + sorted((ROOT / "examples" / "engineers").glob("*.toml"))
NAMES = [p.relative_to(ROOT / "examples").as_posix() for p in EXAMPLES]
DIRECTIONS = [pytest.param(np.inf, id="up"), pytest.param(-np.inf, id="down")]
#: committed files a writer writes: (writer, example robot) -> file
COMMITTED = {
    ("urdf", "mecanum4.toml"): ROOT / "examples" / "urdf" / "mecanum4.urdf",
    ("urdf", "tricycle.toml"): ROOT / "examples" / "urdf" / "tricycle.urdf",
    ("ros2", "swerve4.toml"): ROOT / "examples" / "ros2" / "swerve_drive.yaml",
    ("ros2", "omni3.toml"): ROOT / "examples" / "ros2" / "omni_drive.yaml",
}


def _text_or_refusal(write, robot):
    """What a writer writes for ``robot``, or the kind of its refusal (a format that cannot express the robot)."""
    try:
        return write(robot)
    except (InputValueError, NotImplementedError) as e:
        return f"refused: {type(e).__name__}"


LIBRARY = {"urdf": to_urdf, "ros2": to_ros2, "toml": dump, "mjcf": lambda robot: to_mjcf(robot)}


def _cli(argv):
    """What ``wmr ARGV`` prints (stdout)."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main([str(a) for a in argv]) == 0
    return out.getvalue()


def _cli_runs(robot):
    """The --json commands run on one robot file: name -> argv after the file."""
    angles = [str(10.0 * (k + 1)) for k in range(robot.w)]  # generic steering angles, degrees
    rates = [str(1.0 + 0.1 * k) for k in range(robot.n_rates)]
    return {
        "analyze": ["analyze", "--json", "--grid", "100", "--twists", "10"],
        "fk": ["fk", "--angles", *angles, "--rates", *rates, "--json"],
        "ik": ["ik", "--vx", "0.3", "--vy", "0.1", "--omega", "0.7", "--current-angles", *angles, "--json"],
        "sweep": ["sweep", "kappa_J", "--angles", "any", "--sample", "200", "--seed", "1", "--json", "--no-progress"],
    }


@contextlib.contextmanager
def _loaded_nudged(monkeypatch, direction):
    """The command line loads every robot file nudged by one ulp (``wmr.load`` as the commands call it)."""
    load = wmr.load
    with monkeypatch.context() as m:
        m.setattr(wmr, "load", lambda *a, **k: nudge(load(*a, **k), direction))
        yield


# ------------------------------------------------------------------------------------------ the rule holds
@pytest.mark.parametrize("direction", DIRECTIONS)
@pytest.mark.parametrize("writer", list(LIBRARY))
def test_library_writers_do_not_depend_on_the_last_bits(writer, direction):
    write, written = LIBRARY[writer], 0
    for path, name in zip(EXAMPLES, NAMES):
        robot = wmr.load(path)
        want = _text_or_refusal(write, robot)
        with another_cpu(direction):
            got = _text_or_refusal(write, nudge(robot, direction))
        assert got == want, f"{writer} of examples/{name} changes when its inputs move by one ulp"
        written += not want.startswith("refused")
        if (writer, name) in COMMITTED:
            assert COMMITTED[writer, name].read_text(encoding="utf-8") == want, f"regenerate {COMMITTED[writer, name]}"
    assert written >= 5, f"{writer} wrote {written} example robots only"


@pytest.mark.parametrize("direction", DIRECTIONS)
@pytest.mark.parametrize("command", ["analyze", "fk", "ik", "sweep"])
def test_command_line_json_does_not_depend_on_the_last_bits(monkeypatch, command, direction):
    for path, name in zip(EXAMPLES, NAMES):
        argv = _cli_runs(wmr.load(path))[command]
        argv = [argv[0], path, *argv[1:]]
        want = _cli(argv)
        with _loaded_nudged(monkeypatch, direction), another_cpu(direction):
            got = _cli(argv)
        assert got == want, f"wmr {command} --json on examples/{name} changes when its inputs move by one ulp"


@pytest.mark.parametrize("direction", DIRECTIONS)
def test_simulate_json_does_not_depend_on_the_last_bits(monkeypatch, direction):
    """MuJoCo's measurements (at wmr.cli.simulate.SIM_DIGITS) and the model it is given."""
    pytest.importorskip("mujoco")
    argv = ["simulate", ROOT / "examples" / "differential.toml", "--vx", "0.5", "--omega", "1", "--seconds", "0.3"]
    want = _cli([*argv, "--json"])
    with _loaded_nudged(monkeypatch, direction), another_cpu(direction):
        got = _cli([*argv, "--json"])
    assert got == want


# ------------------------------------------------------------------------------------------ not vacuous
def test_the_perturbation_changes_what_repr_writes(monkeypatch):
    """Without the rule (floats written with ``repr``), the perturbation changes the files: the test above can fail."""
    from wmr.io import urdf_write

    robot = wmr.load(ROOT / "examples" / "mecanum4.toml")
    monkeypatch.setattr(urdf_write, "float_text", lambda x, scale=None: repr(float(x) + 0.0))
    before = to_urdf(robot)
    changed = []
    for direction in (np.inf, -np.inf):
        with another_cpu(direction):
            changed.append(to_urdf(nudge(robot, direction)) != before)
    assert all(changed), "the perturbation would not change a URDF written with repr"
    assert repr(nudge(1.0471975511965976, np.inf)) != repr(1.0471975511965976)


#: the modules that write files or --json, and what would go around the rule in them: a float's ``repr`` or
#: ``%g`` text anywhere, ``json.dumps`` in a command (``wmr.cli._numbers.json_text`` writes JSON)
REPR = r"repr\(float|format\(float|\"\.\d+g\"|:\.\d+g\}"
WRITERS = {
    "wmr/io/urdf_write.py": REPR,
    "wmr/io/ros2.py": REPR,
    "wmr/io/toml.py": REPR,
    "wmr/sim/bodies.py": REPR,
    "wmr/sim/mjcf.py": REPR,
    "wmr/cli/analyze.py": r"repr\(float|json\.dumps\(",  # %g: the table, not the JSON
    "wmr/cli/fk.py": r"repr\(float|json\.dumps\(",
    "wmr/cli/ik.py": r"repr\(float|json\.dumps\(",
    "wmr/cli/sweep.py": r"repr\(float|json\.dumps\(",
    "wmr/cli/simulate.py": r"repr\(float|json\.dumps\(",
}


@pytest.mark.parametrize("module", WRITERS)
def test_the_writers_write_floats_by_the_rule(module):
    """No writer formats a written number itself: ``float_text`` (wmr.io.decimals) and ``json_text`` (wmr.cli._numbers) do."""
    bypass = re.compile(WRITERS[module])
    source = Path(wmr.__file__).parent / module.removeprefix("wmr/")  # the installed package (also from an sdist)
    found = [line.strip() for line in source.read_text(encoding="utf-8").splitlines() if bypass.search(line)]
    assert not found, f"{module} writes numbers around wmr.io.decimals: {found}"
