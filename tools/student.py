"""The student edition of the chapters: ``build/student/*.ipynb`` without the worked solutions.

    python tools/student.py            # write build/student/NN_*.ipynb (solution cells and all outputs removed)
    python tools/student.py --run      # ... and execute them (cached), to show that they still run

A cell tagged ``solution`` is dropped; everything else stays, with its outputs cleared, so each
exercise keeps its statement and its answer template (``answer = None`` and the check call, which
answers "no answer yet").  ``--run`` executes each student notebook in a fresh kernel with
``WMR_OUT`` set to a scratch folder under ``build/student/.run`` (a student notebook never
writes into the repository's ``figures/``); a run is skipped when neither the notebook nor any
``wmr/**/*.py`` changed since the last successful one.
"""
from __future__ import annotations

import argparse
import hashlib
import os
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SOLUTION = "solution"
NOTE = ("*Student edition: the worked solutions are removed. Each exercise ends with a check: run it after "
        "writing your answer.*")


def student_cells(nb):
    """The cells of a chapter without its solutions, outputs cleared (new cell objects)."""
    import nbformat
    out = []
    for c in nb.cells:
        if SOLUTION in c.get("metadata", {}).get("tags", []):
            continue
        c = nbformat.from_dict(dict(c))
        if c.cell_type == "code":
            c.outputs, c.execution_count = [], None
        out.append(c)
    return out


def build(src=ROOT / "notebooks", out=ROOT / "build" / "student"):
    """Write the student edition of every chapter ``src/NN_*.ipynb`` into ``out``; returns the paths."""
    import nbformat
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for path in sorted(src.glob("[0-9][0-9]_*.ipynb")):
        nb = nbformat.read(path, as_version=4)
        nb.cells = student_cells(nb)
        note = nbformat.v4.new_markdown_cell(NOTE)
        note["id"] = "student-note"
        nb.cells.insert(1 if nb.cells and nb.cells[0].cell_type == "markdown" else 0, note)
        target = out / path.name
        tmp = target.with_name("." + target.name + ".tmp")
        nbformat.write(nb, tmp)
        os.replace(tmp, target)
        paths.append(target)
    return paths


def _key(nb_path, root=ROOT):
    h = hashlib.sha256(Path(nb_path).read_bytes())
    for p in sorted((root / "wmr").rglob("*.py")):
        if "__pycache__" not in p.parts:
            h.update(str(p.relative_to(root)).encode())
            h.update(p.read_bytes())
    h.update(sys.version.encode())
    return h.hexdigest()


def run(paths, out=ROOT / "build" / "student", timeout=600):
    """Execute student notebooks (cached); returns ``{name: error or None}`` and writes executed copies to ``out/.run``."""
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError
    scratch = out / ".run"
    scratch.mkdir(parents=True, exist_ok=True)
    env_before = os.environ.get("WMR_OUT")
    os.environ["WMR_OUT"] = str(scratch / "out")
    os.environ.setdefault("MPLBACKEND", "Agg")
    results = {}
    try:
        for path in paths:
            stamp, done = scratch / (path.stem + ".stamp"), scratch / path.name
            key = _key(path)
            if done.exists() and stamp.exists() and stamp.read_text() == key:
                results[path.name] = None
                continue
            stamp.unlink(missing_ok=True)
            nb = nbformat.read(path, as_version=4)
            t0 = time.perf_counter()
            try:
                NotebookClient(nb, timeout=timeout, kernel_name="python3").execute(cwd=str(out))
                nbformat.write(nb, done)
                stamp.write_text(key)
                results[path.name] = None
                print(f"[student] {path.name} ran in {time.perf_counter() - t0:.1f} s", file=sys.stderr)
            except CellExecutionError as e:
                results[path.name] = str(e)
    finally:
        if env_before is None:
            os.environ.pop("WMR_OUT", None)
        else:
            os.environ["WMR_OUT"] = env_before
    return results


def main(argv=None):
    """``python tools/student.py [--run] [--out DIR]``; returns the exit status."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--run", action="store_true", help="execute the student notebooks (cached)")
    ap.add_argument("--out", type=Path, default=ROOT / "build" / "student")
    args = ap.parse_args(argv)
    paths = build(out=args.out)
    print(f"[student] {len(paths)} notebooks without solutions in {args.out}")
    if args.run:
        failed = {k: v for k, v in run(paths, out=args.out).items() if v}
        for name, err in failed.items():
            print(f"[student] {name} FAILED:\n{err}", file=sys.stderr)
        return 1 if failed else 0
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
