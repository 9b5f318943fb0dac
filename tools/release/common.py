"""What the release check's steps share: the paths, the error, the progress line, running a command."""

from __future__ import annotations

import subprocess
from collections.abc import Sequence
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "build" / "release"


class ReleaseError(RuntimeError):
    """The release is not what it should be; the message says what."""


def say(msg: str) -> None:
    """Print one progress line, ``[release] msg``."""
    print(f"[release] {msg}", flush=True)


def python_version(python: str) -> str:
    """``implementation version machine`` of the interpreter ``python``, e.g. ``CPython 3.11.2 x86_64``."""
    code = "import sys, platform; print(platform.python_implementation(), sys.version.split()[0], platform.machine())"
    out = subprocess.run([python, "-c", code], capture_output=True, text=True, check=True)
    return out.stdout.strip()


def run(cmd: Sequence[str | Path], cwd: Path, env: dict[str, str], what: str, timeout: float = 1800) -> str:
    """Run ``cmd``; its stdout, or :class:`ReleaseError` with the end of its output if it fails."""
    proc = subprocess.run(
        [str(c) for c in cmd], cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout, check=False
    )
    if proc.returncode != 0:
        raise ReleaseError(
            f"{what} failed (exit {proc.returncode}): {' '.join(map(str, cmd))}\n{(proc.stdout + proc.stderr)[-4000:]}"
        )
    return proc.stdout
