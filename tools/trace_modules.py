"""Which modules of wmr one command passes through, and how often it comes back to each (issue 29).

``python -m tools.trace_modules [ARGS ...]`` runs ``wmr ARGS`` (default ``analyze examples/swerve4.toml``) in
this process under :func:`sys.setprofile` and prints two readings of the path through the code:

* **as a reader follows it**: each function of wmr counted once, at its first call, in the order of first
  calls; a *visit* is a run of consecutive first calls in one module.  A module visited more than twice is
  one the reader has to leave and come back to (the measure of issue 29: at most twice each).  A
  comprehension or generator expression is read as part of the function that holds it (Python 3.12 inlines
  comprehensions, PEP 709, and the reader never leaves the function for one); a lambda counts, as it may be
  called far from where it is written;
* **as the interpreter runs it**: every call into a function of wmr and every return to one; a visit is a
  run of consecutive events in one module (loops over wheels and configurations count every pass).

Only modules of the imported ``wmr`` count; the standard library, NumPy and SymPy are transparent.
"""

from __future__ import annotations

import contextlib
import io
import sys
from collections import Counter
from pathlib import Path
from types import FrameType
from typing import Any

import wmr.cli

ROOT = Path(wmr.__file__).resolve().parent
#: code objects a reader reads inside the function that holds them
INLINE = frozenset({"<listcomp>", "<dictcomp>", "<setcomp>", "<genexpr>"})


def module_of(frame: FrameType | None) -> str | None:
    """The dotted name of the wmr module a frame runs in, or None outside wmr.

    Parameters
    ----------
    frame : frame or None

    Returns
    -------
    str or None
    """
    if frame is None:
        return None
    path = Path(frame.f_code.co_filename)
    if ROOT not in path.parents:
        return None
    parts = ("wmr",) + path.relative_to(ROOT).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def trace(argv: list[str]) -> tuple[list[str], list[str]]:
    """The modules of the first calls and of every call and return, while ``wmr argv`` runs.

    Parameters
    ----------
    argv : list of str

    Returns
    -------
    first, every : list of str
    """
    first: list[str] = []
    every: list[str] = []
    seen: set[tuple[str, int]] = set()

    def profile(frame: FrameType, event: str, arg: Any) -> None:
        here = module_of(frame)
        if here is None:
            return
        if event == "call":
            every.append(here)
            key = (frame.f_code.co_filename, frame.f_code.co_firstlineno)
            if key not in seen and frame.f_code.co_name not in INLINE:
                seen.add(key)
                first.append(here)
        elif event == "return" and (back := module_of(frame.f_back)) is not None:
            every.append(back)

    sys.setprofile(profile)
    try:
        with contextlib.redirect_stdout(io.StringIO()), contextlib.suppress(SystemExit):
            wmr.cli.main(argv)
    finally:
        sys.setprofile(None)
    return first, every


def visits(sequence: list[str]) -> Counter[str]:
    """How many runs of consecutive equal entries each module has in ``sequence``.

    Parameters
    ----------
    sequence : list of str

    Returns
    -------
    collections.Counter
    """
    return Counter(m for k, m in enumerate(sequence) if k == 0 or sequence[k - 1] != m)


def main(argv: list[str] | None = None) -> int:
    """Print both readings for ``wmr argv``.

    Parameters
    ----------
    argv : list of str, optional

    Returns
    -------
    int
        0.
    """
    args = list(sys.argv[1:] if argv is None else argv) or ["analyze", "examples/swerve4.toml"]
    first, every = trace(args)
    print(f"wmr {' '.join(args)}")
    for reading, sequence in (("as a reader follows it", first), ("as the interpreter runs it", every)):
        count = visits(sequence)
        over = sorted((m for m, v in count.items() if v > 2), key=lambda m: -count[m])
        print(f"{reading}: {sum(count.values())} visits to {len(count)} modules, {len(over)} visited more than twice")
        print("  " + ", ".join(f"{m} {count[m]}" for m in over[:12]))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
