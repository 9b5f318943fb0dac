r"""The derivations of a chapter, run outside the notebook: its cells tagged ``derivation``.

A chapter derives each equation in its own cells (a few lines of SymPy, shown to the reader) and passes
the derived objects to a check of :mod:`edition.checks`, which compares them with the printed form and
records the verdict.  The derivation is written once, in the notebook; the tests and the exercise checks
that need a derived object run the same cells through :func:`derived` instead of keeping a copy.

Only the chapter's first code cell (its imports, tagged ``imports``) and the cells tagged ``derivation``
run, in that order, in a fresh namespace; what they display is dropped.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path
from types import MappingProxyType

__all__ = ["NOTEBOOKS", "derived"]

#: the chapters of this checkout; in the course package (``make course``), which ships no chapter with its
#: solutions, their ``imports`` and ``derivation`` cells in ``edition/_chapters``
NOTEBOOKS = next(
    (
        p
        for p in (Path(__file__).resolve().parents[1] / "notebooks", Path(__file__).resolve().parent / "_chapters")
        if p.is_dir()
    ),
    Path(__file__).resolve().parents[1] / "notebooks",
)


def _quiet(*args, **kwargs):
    """What ``show``, ``say``, ``table`` and ``quote`` become outside the notebook: nothing is displayed."""
    return None


@cache
def derived(chapter):
    """Run the cells tagged ``imports`` and ``derivation`` of a chapter and return what they defined.

    Parameters
    ----------
    chapter : str
        The notebook's stem, e.g. ``"01_platform_and_wheels"``.

    Returns
    -------
    mappingproxy
        The namespace after the last derivation cell (read only; cached per chapter).

    Raises
    ------
    FileNotFoundError
        When ``notebooks/<chapter>.ipynb`` does not exist.
    """
    import json

    path = NOTEBOOKS / f"{chapter}.ipynb"
    if not path.is_file():
        raise FileNotFoundError(f"chapter {chapter!r}: no notebook {path}")
    # plain JSON (nbformat 4 stores a cell's source as a string or a list of lines): importing nbformat costs
    # its schema validator, over a second, in every kernel that calls this
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    namespace: dict = {"__name__": f"derived_{chapter}"}
    for cell in cells:
        tags = set(cell.get("metadata", {}).get("tags", []))
        if cell.get("cell_type") == "code" and ("imports" in tags or "derivation" in tags):
            source = cell["source"] if isinstance(cell["source"], str) else "".join(cell["source"])
            exec(compile(source, f"{path.name}", "exec"), namespace)
            namespace.update(show=_quiet, say=_quiet, table=_quiet, quote=_quiet)
    return MappingProxyType(namespace)
