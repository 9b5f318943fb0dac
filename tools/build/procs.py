"""Child processes, signals and the build lock: a killed build leaves nothing running.

- :func:`run` starts every child in its own process group, registered until it ends; external
  tools get a parent-death signal (``setpriv --pdeathsig``), Python children set their own
  (:func:`die_with_parent`), so that no child outlives a build killed with SIGKILL.
- :func:`handle_signals` (the CLI calls it) turns SIGINT, SIGTERM and SIGHUP into
  :class:`~tools.build.log.Interrupted` after sending SIGTERM to every child's group. SIGINT is
  handled even when inherited as ignored (a background job of a non-interactive shell), so that
  ``kill -INT`` stops a background build. The build makes itself a child subreaper (Linux): a
  process orphaned below it (a kernel whose worker died) is re-parented to it and
  :func:`terminate_all` finds it.
- :class:`BuildLock` serialises builds of one tree: the second says so and waits.
"""
from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import errno
import fcntl
import os
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

from .log import Interrupted, say

__all__ = ["run", "call", "terminate_all", "handle_signals", "die_with_parent", "become_subreaper",
           "descendants", "stopping", "BuildLock"]

_children: set[subprocess.Popen] = set()
_lock = threading.Lock()
_stopping = False
_SETPRIV = shutil.which("setpriv") if sys.platform.startswith("linux") else None


def _prctl(option: int, arg: int) -> bool:
    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
        return libc.prctl(option, arg, 0, 0, 0) == 0
    except (OSError, AttributeError):
        return False


def die_with_parent(sig: int = signal.SIGTERM) -> None:
    """Ask the kernel to send ``sig`` to this process when its parent dies (Linux); if the
    parent is already gone, act on it now."""
    ppid = os.getppid()
    if _prctl(1, int(sig)) and os.getppid() != ppid:   # PR_SET_PDEATHSIG; parent died meanwhile
        os.kill(os.getpid(), sig)


def become_subreaper() -> bool:
    """Make this process the reaper of orphaned descendants (Linux ``PR_SET_CHILD_SUBREAPER``)."""
    return _prctl(36, 1)


def run(cmd: list[str], *, cwd=None, env=None, timeout: float | None = None, pdeathsig: bool = True,
        input: str | None = None) -> subprocess.CompletedProcess:
    """Run ``cmd`` to completion in its own process group, capturing text output.

    Parameters
    ----------
    cmd : list of str
    cwd, env : optional
        As for :class:`subprocess.Popen`.
    timeout : float, optional
        Seconds; on expiry the whole group is killed and ``subprocess.TimeoutExpired`` raised.
    pdeathsig : bool
        Prefix ``setpriv --pdeathsig KILL`` (when available) so the child dies with the build.
        Python children of the build call :func:`die_with_parent` themselves instead.
    input : str, optional
        Sent to the child's stdin.

    Raises
    ------
    Interrupted
        If the build is stopping (a signal arrived): no new child is started.
    """
    if _stopping:
        raise Interrupted(signal.SIGTERM)
    full = ([_SETPRIV, "--pdeathsig", "KILL", "--"] if pdeathsig and _SETPRIV else []) + list(cmd)
    with _lock:
        p = subprocess.Popen(full, cwd=cwd, env=env, stdin=subprocess.PIPE if input is not None else subprocess.DEVNULL,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
        _children.add(p)
    try:
        out, err = p.communicate(input=input, timeout=timeout)
    except subprocess.TimeoutExpired:
        _kill_group(p, signal.SIGKILL)
        p.communicate()
        raise
    finally:
        with _lock:
            _children.discard(p)
        if p.poll() is None:                       # interrupted while waiting: take it down
            _kill_group(p, signal.SIGKILL)
            p.wait()
    return subprocess.CompletedProcess(full, p.returncode, out, err)


def call(cmd: list[str], *, cwd=None, env=None) -> int:
    """Run ``cmd`` with the build's own stdin/stdout/stderr (a test run the user watches), in its
    own process group, registered like :func:`run`; return its exit status."""
    if _stopping:
        raise Interrupted(signal.SIGTERM)
    with _lock:
        p = subprocess.Popen(list(cmd), cwd=cwd, env=env, start_new_session=True)
        _children.add(p)
    try:
        return p.wait()
    finally:
        with _lock:
            _children.discard(p)
        if p.poll() is None:
            _kill_group(p, signal.SIGKILL)
            p.wait()


def _kill_group(p: subprocess.Popen, sig: int) -> None:
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.killpg(p.pid, sig)


def descendants(pid: int | None = None) -> list[int]:
    """Every live descendant of ``pid`` (default: this process), from ``/proc`` (Linux; else [])."""
    pid = os.getpid() if pid is None else pid
    kids: dict[int, list[int]] = {}
    try:
        entries = os.listdir("/proc")
    except OSError:
        return []
    for e in entries:
        if not e.isdigit():
            continue
        try:
            with open(f"/proc/{e}/stat", "rb") as f:
                stat = f.read().decode(errors="replace")
        except OSError:
            continue
        # "pid (comm) state ppid ...": comm may hold spaces and parentheses
        rest = stat.rsplit(")", 1)[-1].split()
        if len(rest) >= 2 and rest[0] != "Z":
            kids.setdefault(int(rest[1]), []).append(int(e))
    out, todo = [], [pid]
    while todo:
        for c in kids.get(todo.pop(), []):
            out.append(c)
            todo.append(c)
    return out


def terminate_all(grace: float = 5.0) -> None:
    """SIGTERM every child's group, wait up to ``grace`` seconds, SIGKILL what is left, then
    SIGKILL every remaining descendant (orphans re-parented to this subreaper) and reap them."""
    with _lock:
        procs = list(_children)
    for p in procs:
        _kill_group(p, signal.SIGTERM)
    deadline = time.monotonic() + grace
    for p in procs:
        with contextlib.suppress(subprocess.TimeoutExpired):
            p.wait(timeout=max(0.0, deadline - time.monotonic()))
    for p in procs:
        if p.poll() is None:
            _kill_group(p, signal.SIGKILL)
    # whatever is still below us (kernels of killed workers, their helpers)
    for _ in range(3):
        rest = descendants()
        if not rest:
            break
        for pid in rest:
            with contextlib.suppress(ProcessLookupError, PermissionError):
                os.kill(pid, signal.SIGKILL)
        time.sleep(0.1)
        _reap()
    _reap()


def _reap() -> None:
    while True:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return


def handle_signals() -> None:
    """Install the build's handlers (main thread only): SIGINT, SIGTERM and SIGHUP (unless
    ignored, as under ``nohup``) stop every child and raise :class:`Interrupted`."""

    def on_signal(signum, frame):
        global _stopping
        if _stopping:
            return                                 # already stopping: the cleanup is bounded
        _stopping = True
        with _lock:
            procs = list(_children)
        for p in procs:                            # unblock the threads that wait on children
            _kill_group(p, signal.SIGTERM)
        raise Interrupted(signum)

    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        if sig == signal.SIGHUP and signal.getsignal(sig) == signal.SIG_IGN:
            continue
        signal.signal(sig, on_signal)


def stopping() -> bool:
    """True once a signal has arrived."""
    return _stopping


class BuildLock:
    """An exclusive ``flock`` on ``path`` for the duration of a build; re-entrant in one process.

    A second build of the same tree prints who holds the lock and waits for it; with
    ``wait=False`` it does not wait and :attr:`acquired` says whether it got the lock.
    """

    _held: dict[str, list] = {}

    def __init__(self, path: Path, wait: bool = True):
        self.path = Path(path)
        self.wait = wait
        self.acquired = False

    def __enter__(self):
        key = str(self.path)
        held = BuildLock._held.get(key)
        if held:
            held[1] += 1
            self.acquired = True
            return self
        self.path.parent.mkdir(parents=True, exist_ok=True)
        fd = os.open(self.path, os.O_RDWR | os.O_CREAT, 0o644)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as e:
            if e.errno not in (errno.EAGAIN, errno.EACCES):
                os.close(fd)
                raise
            if not self.wait:                      # held by another build: do nothing
                os.close(fd)
                return self
            try:
                owner = os.pread(fd, 64, 0).decode(errors="replace").strip() or "?"
            except OSError:
                owner = "?"
            say("lock", f"another build of this tree is running (pid {owner}, lock {self.path}): waiting for it")
            t0 = time.perf_counter()
            try:
                fcntl.flock(fd, fcntl.LOCK_EX)
            except BaseException:
                os.close(fd)
                raise
            say("lock", "the other build finished", t0)
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"{os.getpid()}\n".encode(), 0)
        BuildLock._held[key] = [fd, 1]
        self.acquired = True
        return self

    def __exit__(self, *exc):
        key = str(self.path)
        held = BuildLock._held.get(key)
        if held is None:                          # not acquired (wait=False and busy)
            return False
        held[1] -= 1
        if held[1] == 0:
            del BuildLock._held[key]
            with contextlib.suppress(OSError):
                os.ftruncate(held[0], 0)
            fcntl.flock(held[0], fcntl.LOCK_UN)
            os.close(held[0])
        return False
