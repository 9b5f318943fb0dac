"""One notebook, executed in a fresh kernel: ``python -m tools.build.worker NB OUT CWD``.

Run by :mod:`tools.build.execute` as a child process (nbclient's event loop and kernel stay out of
the build's own process). The worker dies with its parent, and on SIGTERM, SIGINT or SIGHUP it
kills its kernel's process group before exiting, so that no kernel outlives a stopped build.
Exit status: 0 and ``OUT`` written atomically; 3 and the failing cell's source and traceback on
stderr when a cell raised; anything else for other failures.
"""
from __future__ import annotations

import contextlib
import os
import signal
import sys
from pathlib import Path

from .files import atomic_path
from .log import strip_ansi
from .procs import die_with_parent

__all__ = ["main", "skip_slow_imports", "CELL_TIMEOUT"]

CELL_TIMEOUT = 600  # seconds per notebook cell


def skip_slow_imports() -> None:
    """``import nbformat`` imports jsonschema, which imports ``rfc3987_syntax`` if installed: a
    grammar compiled at import, about 1 s, used only to check the "iri" string format, which no
    notebook schema uses. Blocking it makes every worker (and the build) start 1 s sooner."""
    sys.modules.setdefault("rfc3987_syntax", None)


def main(argv: list[str]) -> int:
    nb_path, out_path, cwd = argv
    die_with_parent(signal.SIGTERM)
    skip_slow_imports()
    import nbformat
    from jupyter_client.manager import AsyncKernelManager
    from jupyter_core.utils import run_sync
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError

    nb = nbformat.read(nb_path, as_version=4)
    if not any(c.cell_type == "code" and c.source.strip() for c in nb.cells):
        with atomic_path(Path(out_path)) as tmp:          # nothing to run: no kernel to start
            nbformat.write(nb, str(tmp))
        return 0
    km = AsyncKernelManager(kernel_name="python3")

    def kill_kernel() -> None:
        proc = getattr(getattr(km, "provisioner", None), "process", None)
        if proc is not None and proc.poll() is None:
            with contextlib.suppress(ProcessLookupError, PermissionError):
                os.killpg(proc.pid, signal.SIGKILL)   # jupyter_client starts it in its own session
        with contextlib.suppress(Exception):
            km.cleanup_connection_file()

    def on_signal(signum, frame):
        kill_kernel()
        os._exit(128 + signum)

    for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        signal.signal(sig, on_signal)

    client = NotebookClient(nb, km=km, timeout=CELL_TIMEOUT, kernel_name="python3", record_timing=False,
                            resources={"metadata": {"path": cwd}})
    try:
        client.execute(cwd=cwd)
    except CellExecutionError as e:  # message = the failing cell's source + traceback
        sys.stderr.write(strip_ansi(str(e)) + "\n")
        return 3
    finally:
        if km.has_kernel:
            try:
                run_sync(km.shutdown_kernel)(now=True)
            except Exception:   # noqa: BLE001 - a kernel that will not stop is killed
                kill_kernel()
    with atomic_path(Path(out_path)) as tmp:
        nbformat.write(nb, str(tmp))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
