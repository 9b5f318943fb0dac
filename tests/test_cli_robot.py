"""`wmr analyze`, `wmr ik`, `wmr fk`: tables, JSON that matches the library, one-line errors (exit 2)."""

import importlib
import json
import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.analysis.overview import overview
from wmr.cli import COMMANDS, main

from conftest import WRITTEN

ROOT = Path(__file__).resolve().parent.parent
SWERVE = str(ROOT / "examples" / "swerve4.toml")
OFFSET = str(ROOT / "examples" / "paper_offset.toml")


def _run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_console_script_and_commands():
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert meta["project"]["scripts"]["wmr"] == "wmr.cli:main"
    assert {"analyze", "ik", "fk", "sweep"} <= set(COMMANDS)


def test_the_parser_imports_no_command():
    """``wmr --version`` and ``wmr --help`` build every command's parser without importing a command's module;
    a command's module is imported when it runs, and provides ``run`` (issue 34)."""
    code = (
        "import sys, contextlib, io\nfrom wmr.cli import main\nfor argv in (['--version'], ['--help']):\n"
        "    with contextlib.redirect_stdout(io.StringIO()), contextlib.suppress(SystemExit):\n        main(argv)\n"
        "print(sorted(m for m in sys.modules if m.startswith('wmr.cli.')))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    assert out.stdout.strip() == "[]"
    for module in COMMANDS.values():
        assert callable(importlib.import_module(f"wmr.cli.{module}").run)


# ------------------------------------------------------------------------------------- analyze
def test_analyze_json_matches_the_library(capsys):
    code, out, err = _run(capsys, "analyze", SWERVE, "--json", "--grid", "500", "--twists", "50")
    assert code == 0 and err == ""
    data = json.loads(out)
    ov = overview(wmr.load(SWERVE), grid=500, twists=50)
    assert data["rank_F"] == {"generic": 7, "min": 6, "max": 7}
    assert data["nullity"] == {"generic": 0, "min": 0, "max": 1}
    assert data["configurations"] == ov.configurations and data["L"] == pytest.approx(ov.L, rel=WRITTEN)
    assert data["kappa_J_L1"] == pytest.approx(1.0) and data["kappa_J2"] == 1.0 and data["kappa_J"]["max"] == "inf"
    assert [f["family"] for f in data["singular"]] == [f["family"] for f in ov.singular]
    assert np.allclose(data["singular"][1]["angles_deg"], [-45, 45, 45, -45])
    assert (data["delta_m"], data["delta_s"], data["class"]) == (1, 2, "(1,2)")


def test_analyze_table(capsys):
    code, out, _ = _run(capsys, "analyze", OFFSET, "--grid", "200", "--twists", "20", "--brief")
    assert code == 0
    rows = dict((line[:11].strip(), line[13:]) for line in out.splitlines() if line[:11].strip())
    assert rows["rank F"].startswith("6 generic, 6..6 over 152 configurations")
    assert rows["nullity F"] == "3 generic, 3..3" and rows["kappa(J2)"].startswith("1 isotropic")
    assert rows["dead zone"].startswith("radius 1:") and rows["singular"].startswith("none found")
    starts = {len(line) - len(line[13:]) for line in out.splitlines()}
    assert starts == {13}  # one aligned column


# ------------------------------------------------------------------------------------- ik / fk
def test_ik_json_matches_the_library(capsys):
    code, out, _ = _run(capsys, "ik", SWERVE, "--vx", "1.0", "--vy", "0.5", "--omega", "0.8", "--json")
    assert code == 0
    data = json.loads(out)
    bot = wmr.load(SWERVE)
    twist = [0.8, 1.0, 0.5]  # wmr's order: psi_dot, x_dot, y_dot
    beta = wmr.steering_angles(bot, twist)  # rates >= 0; nearer the current 0: beta - 180, rates < 0
    assert np.allclose(data["angles_deg"], np.degrees(beta) - 180.0)
    assert np.allclose(list(data["rates"].values()), -wmr.inverse(bot, beta, twist).value)
    assert list(data["rates"]) == list(bot.rate_names)
    assert data["admissible"] and not data["admissible_without_resteering"] and data["slip_without_resteering"] > 0.1


def test_ik_without_resteering(capsys):
    # driving along body y with every wheel at 0 deg (axles along x): admissible as they stand
    code, out, _ = _run(capsys, "ik", SWERVE, "--vy", "0.5", "--current-angles", "0,0", "0", "0", "--json")
    data = json.loads(out)
    assert code == 0 and data["admissible_without_resteering"] and np.allclose(data["resteer_deg"], 0)
    assert np.allclose(list(data["rates"].values()), -0.5 / 0.0508)  # h_dot = -r theta_dot j
    code, out, _ = _run(capsys, "ik", SWERVE, "--vx", "0.5", "--current-angles", "0", "0", "0", "0")
    assert code == 0 and "without re-steering: no" in out and "admissible: yes" in out


def test_fk_json_matches_the_library(capsys):
    bot = wmr.load(OFFSET)
    beta = np.radians([10, 20, 30])
    rates = wmr.inverse(bot, beta, [0.3, -1.0, 0.5]).value  # compatible rates
    code, out, _ = _run(
        capsys, "fk", OFFSET, "--angles", "10", "20", "30", "--rates=" + ",".join(map(repr, rates.tolist())), "--json"
    )
    data = json.loads(out)
    assert code == 0 and np.allclose([data["omega"], data["vx"], data["vy"]], [0.3, -1.0, 0.5]) and data["admissible"]
    code, out, _ = _run(capsys, "fk", OFFSET, "--angles", "10", "20", "30", "--rates", "1,2,1,2,1,2", "--json")
    data = json.loads(out)
    sol = wmr.forward(bot, beta, [1, 2, 1, 2, 1, 2])
    assert np.allclose([data["omega"], data["vx"], data["vy"]], sol.value) and not data["admissible"]
    assert np.allclose(data["residual"], sol.residual) and data["slip"] == pytest.approx(np.linalg.norm(sol.residual))


def test_fk_slip(capsys):
    code, out, _ = _run(
        capsys, "fk", SWERVE, "--angles", "0", "0", "0", "90", "--rates", "-10", "-10", "-10", "-10", "--json"
    )
    data = json.loads(out)
    assert code == 0 and not data["admissible"] and data["slip"] == pytest.approx(0.622, abs=1e-3)
    code, out, _ = _run(capsys, "fk", SWERVE, "--angles", "0", "0", "0", "0", "--rates", "-10", "-10", "-10", "-10")
    rows = dict(line.split(None, 1) for line in out.splitlines() if not line.startswith("residual"))
    assert rows["vy"] == "0.508 m/s" and rows["vx"] == "0 m/s" and rows["admissible"].startswith("yes")


# ------------------------------------------------------------------------------------ bad input
@pytest.fixture
def bad_file(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text('[[wheel]]\ntype = "centred"\nposition = [0, 0]\nradius = -1\n')
    return str(path)


@pytest.mark.parametrize(
    "argv, words",
    [
        (["analyze", "nowhere.toml"], "nowhere.toml"),
        (["analyze", "BAD"], "bad.toml:4: wheel[1].radius: must be positive"),
        (["analyze", SWERVE, "--grid", "0"], "grid"),
        (["ik", "BAD", "--vx", "1"], "bad.toml:4: wheel[1].radius"),
        (["ik", SWERVE, "--vx", "fast"], "--vx must be a number"),
        (["ik", SWERVE, "--omega", "nan"], "--omega must be a finite number"),
        (["ik", SWERVE, "--current-angles", "0", "0"], "--current-angles needs 4 values"),
        (["ik", SWERVE, "--current-angles", "0", "0", "0", "x"], "--current-angles must be a number"),
        (["fk", SWERVE, "--angles", "0", "0", "0", "0", "--rates", "1"], "--rates needs 4 values"),
        (["fk", OFFSET, "--angles", "0", "0", "0", "--rates", "1", "2", "3"], "phi_dot_1 theta_dot_1"),
        (["fk", SWERVE, "--angles", "0", "0", "0", "inf", "--rates", "1", "1", "1", "1"], "--angles must be a finite"),
        (["fk", "BAD", "--angles", "0", "--rates", "1"], "bad.toml:4"),
    ],
)
def test_bad_input_is_one_line(capsys, bad_file, argv, words):
    argv = [bad_file if a == "BAD" else a for a in argv]
    code, out, err = _run(capsys, *argv)
    assert code == 2 and out == ""
    assert err.startswith(f"wmr {argv[0]}: ") and words in err and err.count("\n") == 1, err


@pytest.mark.parametrize("error", [ValueError("a bug"), TypeError("another bug"), IndexError("and another")])
def test_a_library_bug_is_not_called_bad_input(capsys, monkeypatch, error):
    """A builtin exception from inside wmr (here a planted one) is a bug: traceback, a request to report, exit 1."""

    def broken(*args, **kwargs):
        raise error

    monkeypatch.setattr(wmr, "steering_angles", broken)
    code, out, err = _run(capsys, "ik", SWERVE, "--vx", "1")
    assert code == 1 and out == ""
    assert "Traceback (most recent call last)" in err and f"{type(error).__name__}: {error}" in err
    assert err.rstrip().splitlines()[-1].startswith("wmr ik: internal error: this is a bug in wmr") and "report" in err


def test_input_errors_are_the_package_s_own(capsys, monkeypatch):
    """What the command line reports as bad input is an InputError (which is also a ValueError or TypeError)."""
    from wmr.errors import InputError

    with pytest.raises(InputError) as info:
        wmr.load(ROOT / "examples" / "swerve4.toml").J1(L=-1.0)
    assert isinstance(info.value, ValueError)

    def bad(*args, **kwargs):
        raise info.value

    monkeypatch.setattr(wmr, "steering_angles", bad)
    code, _, err = _run(capsys, "ik", SWERVE, "--vx", "1")
    assert code == 2 and err == f"wmr ik: {info.value}\n"


def test_ik_fixed_wheels(capsys):
    diff = str(ROOT / "examples" / "differential.toml")
    code, out, _ = _run(capsys, "ik", diff, "--vx", "0.5", "--omega", "1", "--json")
    data = json.loads(out)
    assert code == 0 and data["admissible"] and data["admissible_without_resteering"]
    assert data["angles_deg"][:2] == [90.0, 90.0] and data["resteer_deg"][:2] == [0.0, 0.0]
    assert np.allclose(
        [data["rates"]["theta_dot_1"], data["rates"]["theta_dot_2"]], [(0.5 - 0.2) / 0.08, (0.5 + 0.2) / 0.08]
    )
    code, out, _ = _run(capsys, "ik", diff, "--vy", "0.5")  # sideways: impossible
    assert code == 0 and "admissible: no" in out and "without re-steering: no" in out
