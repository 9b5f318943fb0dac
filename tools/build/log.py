"""Messages and the build's one error type.

Every step prints one line ``[step] message (seconds)`` so that a log reads as a timeline;
:class:`BuildError` carries a message that says which step failed and why (the failing cell's
source and traceback for a notebook).
"""
from __future__ import annotations

import re
import sys
import threading
import time

__all__ = ["BuildError", "Interrupted", "say", "strip_ansi"]

_lock = threading.Lock()
_ANSI = re.compile(r"\x1b\[[0-9;]*[A-Za-z]")


class BuildError(RuntimeError):
    """A build step failed; the message says which and why."""


class Interrupted(BaseException):
    """The build received a signal (SIGINT, SIGTERM, SIGHUP); ``signum`` says which.

    A ``BaseException`` (like ``KeyboardInterrupt``) so that no ``except Exception`` swallows it.
    """

    def __init__(self, signum: int):
        super().__init__(f"interrupted by signal {signum}")
        self.signum = signum


def say(step: str, msg: str, t0: float | None = None) -> None:
    """Print ``[step] msg`` (and the seconds since ``t0``), one line at a time across threads."""
    el = f" ({time.perf_counter() - t0:.1f} s)" if t0 is not None else ""
    with _lock:
        print(f"[{step}] {msg}{el}", file=sys.stdout, flush=True)


def strip_ansi(s: str) -> str:
    """``s`` without terminal colour codes (nbclient's tracebacks carry them)."""
    return _ANSI.sub("", s)
