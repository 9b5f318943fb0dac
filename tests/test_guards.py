"""Issue 24, point 5: limits checked before work starts, Ctrl-C leaves a partial result, hostile robot files
get one line naming file, line and key.  Run from outside, as a user would (subprocesses, a real SIGINT)."""

import json
import math
import os
import re
import resource
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.errors import LimitError, RobotFileError

ROOT = Path(__file__).resolve().parent.parent
SWERVE = ROOT / "examples" / "swerve4.toml"
PEAK = "print([l for l in open('/proc/self/status') if l.startswith('VmHWM')][0].split()[1], file=sys.stderr)"


def _wheels(n, kind="centred"):
    out = [f'name = "{n} wheels"']
    for k in range(n):
        a = 2 * math.pi * k / n
        out += [
            "",
            "[[wheel]]",
            f'type = "{kind}"',
            f"position = [{math.cos(a):.6f}, {math.sin(a):.6f}]",
            "radius = 0.05",
        ]
    return "\n".join(out) + "\n"


def _cli(*argv, env=None):
    """``wmr argv`` in a fresh interpreter: (exit status, stdout, stderr, CPU seconds, peak resident memory in MB).

    CPU time (user + system, from wait4) rather than wall-clock time: the machine is shared.
    """
    code = (
        "import sys\nfrom wmr.cli import main\ntry:\n    rc = main(sys.argv[1:])\nfinally:\n    "
        + PEAK
        + "\nsys.exit(rc)\n"
    )
    p = subprocess.Popen(
        [sys.executable, "-c", code, *map(str, argv)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=dict(os.environ, **(env or {})),
    )
    out, err = p.communicate(timeout=120)
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)  # (children waited for so far)
    *lines, peak = err.rstrip("\n").split("\n")
    return p.returncode, out, "\n".join(lines), usage.ru_utime + usage.ru_stime, int(peak) / 1024


@pytest.mark.parametrize("command", [["analyze"], ["ik", "--vx", "1"], ["sweep", "kappa_J"]])
def test_ten_thousand_wheels_are_refused_at_once(tmp_path, command):
    path = tmp_path / "w10000.toml"
    path.write_text(_wheels(10_000))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    code, out, err, cpu, mb = _cli(command[0], path, *command[1:])
    sec = cpu - before.ru_utime - before.ru_stime
    assert code == 2 and out == "" and err.count("\n") == 0
    assert f"{path}:" in err and ": wheel: the file has 10,000 wheel units, more than the limit of 100" in err
    assert "WMR_MAX_WHEELS" in err
    assert sec < 5 and mb < 500, (sec, mb)


def test_the_wheel_limit_is_raised_by_its_variable(tmp_path, monkeypatch):
    text = _wheels(120)
    with pytest.raises(RobotFileError, match="limit of 100") as refused:
        wmr.io.loads(text)
    suggested = re.search(r"e\.g\. WMR_MAX_WHEELS=(\d+)\)", str(refused.value))
    assert suggested and suggested.group(1) == "120"  # exactly enough
    monkeypatch.setenv("WMR_MAX_WHEELS", suggested.group(1))
    assert wmr.io.loads(text).w == 120
    monkeypatch.setenv("WMR_MAX_WHEELS", "50")
    with pytest.raises(LimitError, match="WMR_MAX_WHEELS"):
        wmr.Robot([wmr.CentredWheel((k, 0.0), r=0.1) for k in range(60)])


@pytest.mark.parametrize("argv", [["--sample", "1e30"], ["--angles", "any", "--grid", "2000"]])
def test_huge_sweeps_are_refused_before_they_start(argv):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    code, out, err, cpu, mb = _cli("sweep", SWERVE, "kappa_J", *argv)
    sec = cpu - before.ru_utime - before.ru_stime
    assert code == 2 and out == "" and "more than the limit of 1,000,000,000" in err
    assert "WMR_MAX_CONFIGURATIONS" in err and sec < 5 and mb < 300


def test_memory_limit(monkeypatch):
    from wmr.analysis.sweep import Drivable

    bot = wmr.io.loads(_wheels(100))
    monkeypatch.setenv("WMR_MAX_MEMORY_MB", "1")
    with pytest.raises(LimitError, match="WMR_MAX_MEMORY_MB"):
        wmr.sweep(bot, "kappa_J", Drivable(1000))
    monkeypatch.setenv("WMR_MAX_MEMORY_MB", "64")  # fits, in smaller chunks
    assert wmr.sweep(bot, "kappa_J", Drivable(3000)).count == 3000
    with pytest.raises(LimitError, match="keep=True"):
        wmr.sweep(bot, "rank_F", Drivable(10**8), keep=True)


def test_memory_is_checked_before_the_robot_is_worked_on(monkeypatch):
    """With the wheel limit raised, the memory limit still refuses before any work on the robot."""
    from wmr.analysis.sweep import Drivable, motions

    monkeypatch.setenv("WMR_MAX_WHEELS", "400")
    bot = wmr.io.loads(_wheels(400))
    monkeypatch.setenv("WMR_MAX_MEMORY_MB", "1")
    monkeypatch.setattr(motions, "twist_constraints", None)  # binding would fail here
    fixed = wmr.io.loads(_wheels(400, "fixed").replace("radius = 0.05", "radius = 0.05\nangle_deg = 0"))
    for robot in (bot, fixed):  # steered; fixed (binding works)
        with pytest.raises(LimitError, match=r"a sweep of kappa_J .* WMR_MAX_MEMORY_MB"):
            wmr.sweep(robot, "kappa_J", Drivable(1000))
    with pytest.raises(LimitError, match=r"the kinematics of this robot \(400 wheel units, 400 rates\) needs 7 MB"):
        wmr.inverse(bot, np.zeros(400), [0.0, 1.0, 0.0])


def test_ctrl_c_prints_the_partial_result():
    """A real SIGINT to a running sweep: the result over the chunks done, marked, exit status 130."""
    p = subprocess.Popen(
        [sys.executable, "-m", "wmr", "sweep", str(SWERVE), "kappa_J", "--sample", "1e9", "--json", "--progress"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        seen = ""
        assert p.stderr is not None
        while "[" not in seen:  # the progress bar: it is running
            seen += p.stderr.read(1)
            assert p.poll() is None, seen
        time.sleep(0.5)
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            p.kill()
    assert p.returncode == 130, err
    data = json.loads(out)
    assert not data["complete"] and 0 < data["count"] < 10**9 and data["min"] >= 1.0
    assert "interrupted (Ctrl-C)" in err and "Traceback" not in err


def test_interrupted_sweep_in_python_is_marked():
    from wmr.analysis.sweep import Drivable

    calls = []

    def progress(done, total):
        calls.append(done)
        if len(calls) == 2:
            os.kill(os.getpid(), signal.SIGINT)  # as a user's Ctrl-C

    bot = wmr.load(SWERVE)
    old = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        res = wmr.sweep(bot, "kappa_J", Drivable(1 << 22), chunk=1 << 16, progress=progress, interruptible=True)
    finally:
        signal.signal(signal.SIGINT, old)
    assert not res.complete and res.count == calls[-1] == 2 << 16
    calls.clear()
    old = signal.signal(signal.SIGINT, signal.default_int_handler)  # (a test runner may ignore it)
    try:
        with pytest.raises(KeyboardInterrupt):  # not interruptible: as Python does
            wmr.sweep(bot, "kappa_J", Drivable(1 << 22), chunk=1 << 16, progress=progress)
    finally:
        signal.signal(signal.SIGINT, old)


# -------------------------------------------------------------------------------- hostile files
W2 = '\n[[wheel]]\ntype = "centred"\nposition = [-0.3, 0.0]\nradius = 0.05\n'


@pytest.mark.parametrize(
    "text, where",
    [
        ('[[wheel]]\ntype = "centred"\nposition = [1e308, 0.0]\nradius = 0.05\n' + W2, ":3: wheel[1].position:"),
        ('[[wheel]]\ntype = "centred"\nposition = [0.3, 0.0]\nradius = nan\n' + W2, ":4: wheel[1].radius:"),
        ('[[wheel]]\ntype = "centred"\nposition = [0.3, inf]\nradius = 0.05\n' + W2, ":3: wheel[1].position:"),
        ('[[wheel]]\ntype = "centred"\nposition = "0.3, 0"\nradius = 0.05\n' + W2, ":3: wheel[1].position:"),
        ('[[wheel]]\ntype = "centred"\nposition = [0.3, 0.0]\nradius = true\n' + W2, ":4: wheel[1].radius:"),
        ('[[wheel]]\ntype = "centred"\nposition = [0.3, 0.0]\nradius = 1e-320\n' + W2, ":4: wheel[1].radius:"),
        (
            '[[wheel]]\ntype = "fixed"\nposition = [0.3, 0.0]\nradius = 0.05\nangle_deg = 1e308\n' + W2,
            ":5: wheel[1].angle_deg:",
        ),
        (
            '[[wheel]]\ntype = "centred"\nposition = [0.3, 0.0]\nradius = 0.05\ndriven = {drive = "yes"}\n' + W2,
            ":5: wheel[1].driven:",
        ),
    ],
)
def test_hostile_files_name_file_line_and_key(tmp_path, text, where):
    path = tmp_path / "bot.toml"
    path.write_text(text)
    code, out, err, _, _ = _cli("analyze", path)
    assert code == 2 and out == "" and err == f"wmr analyze: {path}{where}" + err.split(where, 1)[1]
    assert "\n" not in err and "Warning" not in err


def test_a_byte_order_mark_is_accepted(tmp_path):
    text = (ROOT / "examples" / "swerve4.toml").read_text()
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + text.encode())
    a, b = wmr.load(path), wmr.load(SWERVE)
    assert np.array_equal(a.mount_points, b.mount_points) and a.name == b.name


def test_huge_but_finite_robot_runs_without_warnings(tmp_path):
    path = tmp_path / "big.toml"
    path.write_text('[[wheel]]\ntype = "centred"\nposition = [1e300, 0.0]\nradius = 0.05\n' + W2)
    for argv in (["analyze", path, "--grid", "100", "--twists", "50"], ["ik", path, "--vx", "1", "--omega", "1"]):
        p = subprocess.run(
            [sys.executable, "-W", "error", "-m", "wmr", *map(str, argv)], capture_output=True, text=True, timeout=120
        )
        assert p.returncode == 0 and p.stderr == "", p.stderr


@pytest.mark.parametrize(
    "argv, words",
    [(["--grid", "10000000000"], "WMR_MAX_CONFIGURATIONS"), (["--twists", "100000000"], "WMR_MAX_MEMORY_MB")],
)
def test_analyze_is_guarded_too(capsys, argv, words):
    from wmr.cli import main

    t0 = time.perf_counter()
    assert main(["analyze", str(SWERVE), *argv]) == 2
    err = capsys.readouterr().err
    assert err.startswith("wmr analyze: the overview (grid and twists) ") and words in err
    assert time.perf_counter() - t0 < 5
