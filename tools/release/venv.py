"""The fresh venv: install the wheel offline outside the repository and check it there as a user would."""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
import time
import zipfile
from pathlib import Path

from .common import OUT, ROOT, ReleaseError, python_version, run, say

__all__ = ["EXTRAS", "constraints", "clean_env", "wheelhouse", "python_blocks", "missing_modules", "in_venv"]

#: extras installed in the fresh venv: the library's tests, and what they test beyond numpy and sympy (Dask
#: sweeps, wmr.sim in MuJoCo, the URDF, ROS 2 and WPILib bridges), so that none of them is skipped
EXTRAS = "test,dask,sim,urdf,ros,wpilib"


def constraints(lock: str) -> str:
    """The pins of ``environment.lock`` (``name==version ; marker``) without hashes, for ``pip -c``.

    Examples
    --------
    >>> lock = ("numpy==2.4.6 \\\\\\n    --hash=sha256:ab \\\\\\n    # via x\\n"
    ...         "sphinx==9 ; python_version < '3.12' \\\\\\n")
    >>> print(constraints(lock), end="")
    numpy==2.4.6
    sphinx==9 ; python_version < '3.12'
    """
    pins = []
    for line in lock.splitlines():
        line = line.strip().removesuffix("\\").strip()
        if line and not line.startswith(("#", "--")) and "==" in line:
            pins.append(line)
    return "\n".join(pins) + "\n"


def clean_env(tmp: Path) -> dict[str, str]:
    """The environment of the fresh venv's processes: nothing that points back into the repository."""
    env = {
        k: v
        for k, v in os.environ.items()
        if not k.startswith(("PYTHON", "VIRTUAL_ENV", "WMR_", "PIP_REQUIRE", "CONDA"))
    }
    env.update(
        HOME=env.get("HOME", str(tmp)),
        PYTHONNOUSERSITE="1",
        MPLBACKEND="Agg",
        PYTHONDONTWRITEBYTECODE="1",
        PIP_DISABLE_PIP_VERSION_CHECK="1",
    )
    return env


def wheelhouse(vpy: Path, wheel: Path, env: dict[str, str], cwd: Path) -> Path:
    """The folder of wheels the fresh venv installs from offline; filled once per key."""
    lock = (ROOT / "environment.lock").read_text(encoding="utf-8")
    with zipfile.ZipFile(wheel) as zf:
        meta = next(zf.read(n) for n in zf.namelist() if n.endswith(".dist-info/METADATA"))
    reqs = "\n".join(sorted(ln for ln in meta.decode().splitlines() if ln.startswith("Requires-Dist")))
    key = hashlib.sha256("\0".join([lock, reqs, EXTRAS, python_version(str(vpy))]).encode()).hexdigest()[:16]
    house = OUT / "wheelhouse" / key
    if (house / ".complete").exists():
        return house
    say(f"wheelhouse {house.relative_to(ROOT)}: downloading the pinned dependencies once")
    tmp = house.with_name(house.name + f".tmp{os.getpid()}")
    shutil.rmtree(tmp, ignore_errors=True)
    tmp.mkdir(parents=True)
    (tmp / "constraints.txt").write_text(constraints(lock), encoding="utf-8")
    run(
        [
            vpy,
            "-m",
            "pip",
            "download",
            "--quiet",
            "--only-binary=:all:",
            "--dest",
            tmp,
            "--constraint",
            tmp / "constraints.txt",
            f"{wheel}[{EXTRAS}]",
        ],
        cwd,
        env,
        "pip download",
    )
    (tmp / wheel.name).unlink(missing_ok=True)  # the wheel itself comes from build/release
    (tmp / ".complete").write_text("", encoding="utf-8")
    shutil.rmtree(house, ignore_errors=True)
    os.replace(tmp, house)
    return house


def python_blocks(markdown: str) -> list[str]:
    """The fenced ```python blocks of a Markdown text, in order.

    Examples
    --------
    >>> python_blocks("a\\n```python\\nx = 1\\n```\\n```console\\n$ wmr\\n```\\n```python\\nprint(x)\\n```\\n")
    ['x = 1\\n', 'print(x)\\n']
    """
    return [m.group(1) for m in re.finditer(r"^```python\n(.*?)^```\s*$", markdown, flags=re.MULTILINE | re.DOTALL)]


def missing_modules(pytest_output: str) -> list[str]:
    """The skip reasons of a ``pytest -rs`` run that say a module could not be imported.

    Examples
    --------
    >>> missing_modules("SKIPPED [1] tests/test_a.py:3: could not import 'yaml': No module named 'yaml'\\n"
    ...                 "SKIPPED [2] tests/test_b.py:9: chromium not installed\\n")
    ["tests/test_a.py:3: could not import 'yaml'"]
    """
    return [
        m.group(1)
        for m in re.finditer(r"^SKIPPED \[\d+\] (\S+: could not import '[^']+')", pytest_output, re.MULTILINE)
    ]


def in_venv(vdir: Path, src: Path, env: dict[str, str], version: str, dist: str) -> dict[str, str]:
    """Check the installed wheel from the unpacked sdist ``src`` (its ``wmr/`` removed); return facts."""
    vpy, wmr_cmd = vdir / "bin" / "python", vdir / "bin" / "wmr"
    facts: dict[str, str] = {}
    run([vpy, "-m", "pip", "check"], src, env, "pip check")
    facts["pip show"] = run([vpy, "-m", "pip", "show", dist], src, env, "pip show").strip()
    probe = (
        "import wmr, importlib.metadata as m, sysconfig; "
        f"print(wmr.__file__); print(m.version({dist!r})); print(sysconfig.get_path('purelib'))"
    )
    where = run([vpy, "-P", "-c", probe], src, env, "import wmr").split("\n")
    if not Path(where[0]).is_relative_to(Path(where[2])):
        raise ReleaseError(f"import wmr found {where[0]}, not the installed wheel in {where[2]}")
    if where[1] != version:
        raise ReleaseError(f"installed metadata says {dist} {where[1]}, wmr/_version.py says {version}")
    out = run([wmr_cmd, "--version"], src, env, "wmr --version").strip()
    if not out.startswith(f"wmr {version} ({dist}, {Path(where[0]).parent}"):
        raise ReleaseError(f"wmr --version printed {out!r}")
    facts["wmr --version"] = out
    # the README's examples, in one namespace, as a user would paste them
    code = "\n".join(python_blocks((src / "README.md").read_text(encoding="utf-8")))
    if not code:
        raise ReleaseError("the README has no ```python example")
    facts["README example"] = run([vpy, "-P", "-c", code], src, env, "the README's Python examples").strip()
    # the command line on the shipped example robots
    analyzed = json.loads(run([wmr_cmd, "analyze", "examples/swerve4.toml", "--json"], src, env, "wmr analyze"))
    if (analyzed["delta_m"], analyzed["delta_s"]) != (1, 2):
        raise ReleaseError(
            f"wmr analyze examples/swerve4.toml: class ({analyzed['delta_m']},{analyzed['delta_s']}), "
            "expected (1,2) (tests/test_cli_robot.py has the same robot)"
        )
    run(
        [wmr_cmd, "ik", "examples/swerve4.toml", "--vx", "1", "--vy", "0.5", "--omega", "0.8", "--json"],
        src,
        env,
        "wmr ik",
    )
    run(
        [wmr_cmd, "fk", "examples/paper_centred.toml", "--angles", "0", "0", "0", "--rates", "1", "1", "1", "--json"],
        src,
        env,
        "wmr fk",
    )
    run([wmr_cmd, "sweep", "examples/paper_centred.toml", "kappa_J", "--grid", "12", "--json"], src, env, "wmr sweep")
    bad = subprocess.run(
        [str(wmr_cmd), "analyze", "no-such-robot.toml"], cwd=src, env=env, capture_output=True, text=True, check=False
    )
    if bad.returncode != 2 or len(bad.stderr.strip().splitlines()) != 1 or "no-such-robot.toml" not in bad.stderr:
        raise ReleaseError(
            f"wmr analyze on a missing file: exit {bad.returncode}, stderr {bad.stderr!r} "
            "(expected exit 2 and one line naming the file)"
        )
    ros2 = run([wmr_cmd, "convert", "examples/urdf/diffbot.urdf", "--to", "ros2"], src, env, "wmr convert")
    if "diff_drive_controller" not in ros2:
        raise ReleaseError(f"wmr convert examples/urdf/diffbot.urdf --to ros2: no diff_drive_controller in\n{ros2}")
    facts["wmr commands"] = (
        "analyze, ik, fk, sweep, convert (URDF -> ROS 2) on examples/; a missing file: exit 2, one line"
    )
    # the library's tests, as shipped
    log = vdir.parent / "pytest.log"
    t0 = time.monotonic()
    with open(log, "w", encoding="utf-8") as fh:
        proc = subprocess.run(
            [str(vpy), "-P", "-m", "pytest", "-q", "-rs", "-p", "no:cacheprovider", "tests"],
            cwd=src,
            env=env,
            stdout=fh,
            stderr=subprocess.STDOUT,
            check=False,
        )
    text = log.read_text(encoding="utf-8", errors="replace")
    summary = next((ln.strip("= ") for ln in reversed(text.splitlines()) if re.search(r"\d+ (passed|failed)", ln)), "")
    if proc.returncode != 0 or "passed" not in summary:
        raise ReleaseError(f"the library's tests failed in the fresh venv (exit {proc.returncode}):\n{text[-6000:]}")
    unimported = missing_modules(text)
    if unimported:
        raise ReleaseError(
            "library tests were skipped in the fresh venv for want of a module (an extra missing "
            f"from EXTRAS, or from pyproject's extras): {'; '.join(unimported)}"
        )
    facts["library tests"] = f"{summary} ({time.monotonic() - t0:.0f} s)"
    return facts
