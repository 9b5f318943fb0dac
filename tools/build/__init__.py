"""The build of the wmr edition: glue between the Makefile and the tools that do the work.

The Makefile is the task runner: it knows every file and what it is made from, runs two steps at
once, and calls one command of this package per step (``python -m tools.build``). What each hands on:

- :mod:`~tools.build.execute`: a notebook to **nbclient** (a fresh kernel), cached by content hash;
  what the chapters wrote into ``figures/`` (the ledger rows to ``python -m edition.ledger``);
- :mod:`~tools.build.assemble` (+ :mod:`~tools.build.chapters`): Part I and Part II into one notebook;
- :mod:`~tools.build.markup`: all Markdown of the report to **pandoc**, in one call per format;
- :mod:`~tools.build.html`: the page to **nbconvert** (template ``wmr_html``), MathJax inlined;
- :mod:`~tools.build.pdf`: the document to **nbconvert** (template ``wmr_latex``) and **xelatex**,
  the PDF's ``/ID`` fixed and its date the commit's (byte-identical builds);
- :mod:`~tools.build.typeset`: figures and part headings, the two cells Markdown cannot say.

Only the standard library is imported up front; nbformat, nbclient, nbconvert when a step needs them.
"""

from __future__ import annotations

import time
from pathlib import Path

__all__ = ["BuildError", "atomic_write", "say"]


class BuildError(RuntimeError):
    """A build step failed; the message says which and why (for a notebook: the failing cell and its traceback)."""


def say(step: str, msg: str, t0: float | None = None) -> None:
    """Print ``[step] msg``, and the seconds since ``t0`` when given: a build log reads as a timeline."""
    print(f"[{step}] {msg}" + (f" ({time.perf_counter() - t0:.1f} s)" if t0 is not None else ""), flush=True)


def atomic_write(path: Path, data: str | bytes) -> None:
    """:func:`edition.files.atomic_write`, imported when a step writes (``edition`` is not a light import)."""
    from edition.files import atomic_write as write

    write(path, data)
