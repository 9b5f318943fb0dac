"""The chapters as lessons: committed without outputs, thin, anchored, with exercises whose checks can say no,
a student edition without solutions that still runs, and output paths that follow the notebook, not the package."""

from __future__ import annotations

import csv
import re
from pathlib import Path

import nbformat
import numpy as np
import pytest
import sympy as sp

import wmr
from edition import display as DP
from edition import exercises as X
from edition import notebook as NB
from edition.algebra import mod_pi

ROOT = Path(__file__).resolve().parents[2]
CHAPTERS = sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
PAPER_CHAPTERS = [p for p in CHAPTERS if p.name[:2] in {"01", "02", "03", "04", "05", "06"}]
#: every chapter but the interactive robot (07), whose "Things to try" are for the sliders
EXERCISE_CHAPTERS = [p for p in CHAPTERS if p.name[:2] != "07"]
MAX_CELL_LINES = 12


def cells(path, kind=None):
    nb = nbformat.read(path, as_version=4)
    return [c for c in nb.cells if kind is None or c.cell_type == kind]


def tags(cell):
    return set(cell.get("metadata", {}).get("tags", []))


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_committed_notebook_has_no_outputs(path):
    for i, c in enumerate(cells(path, "code")):
        assert not c.outputs and c.execution_count is None, f"{path.name}: cell {i} carries outputs (commit it cleared)"


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_chapter_is_thin_and_prints_nothing(path):
    for c in cells(path, "code"):
        n = len(c.source.splitlines())
        assert n <= MAX_CELL_LINES, f"{path.name}: a code cell of {n} lines:\n{c.source}"
        raw = re.search(r"\bprint\(|\bdisplay\(|DataFrame|\.to_frame\(", c.source)
        assert not raw, f"{path.name}: raw output in\n{c.source}"
        assert "def " not in c.source or "widget" in tags(c), (
            f"{path.name}: a helper defined in the chapter:\n{c.source}"
        )


def test_every_ledger_row_is_anchored_in_its_notebook():
    with open(ROOT / "figures" / "ledger.csv", newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    anchors: dict = {}
    for path in PAPER_CHAPTERS:
        for c in cells(path, "markdown"):
            for a in re.findall(r'<a id="([^"]+)"></a>', c.source):
                assert a not in anchors, f"anchor {a} twice ({anchors[a]}, {path.stem})"
                anchors[a] = path.stem
    for r in rows:
        assert anchors.get(r["anchor"]) == r["notebook"], f"row {r['id']}: anchor {r['anchor']} not in {r['notebook']}"


@pytest.mark.parametrize("path", PAPER_CHAPTERS, ids=lambda p: p.name)
def test_equations_are_quoted_and_verdicts_are_generated(path):
    md = "\n".join(c.source for c in cells(path, "markdown"))
    assert not re.search(r"\*\*Verdict\b[^*\n]*\b(ok|typo|wrong)\b", md), f"{path.name}: a typed verdict in the prose"
    code = "\n".join(c.source for c in cells(path, "code"))
    assert "ch.record(" in code and "ch.close()" in code
    ledger_cells = [c for c in cells(path, "code") if "ledger" in tags(c)]
    assert len(ledger_cells) == 1 and "ch.close()" in ledger_cells[0].source


def test_exercise_chapters_include_the_design_study():
    assert [p.name[:2] for p in EXERCISE_CHAPTERS] == ["01", "02", "03", "04", "05", "06", "08", "09", "10"]


@pytest.mark.parametrize("path", EXERCISE_CHAPTERS, ids=lambda p: p.name)
def test_chapter_has_exercises_with_checks_and_worked_solutions(path):
    if any("check" in tags(c) for c in cells(path)):  # the cell convention (edition.exercises.framework)
        return _exercises_in_four_cells(path)
    # chapters still in the older convention: the check called in a cell tagged "exercise"
    pattern = r"(?:exercises|study)\.(\w+)\("
    named = {"describe_robot", "describe_design"}
    tagged = [c for c in cells(path, "code") if "exercise" in tags(c)]
    sol = [c for c in cells(path, "code") if "solution" in tags(c)]
    checks = {m for c in tagged for m in re.findall(pattern, c.source)} - named
    assert len(checks) >= 2, f"{path.name}: exercises {checks}"
    assert {m for c in sol for m in re.findall(pattern, c.source)} == checks
    assert any(any(o in c.source for o in named) or "my_robot" in c.source for c in tagged), (
        f"{path.name}: no 'your own robot' cell"
    )
    for c in tagged:
        if re.search(pattern, c.source) and "my_robot" not in c.source:
            assert "= None" in c.source, f"{path.name}: an exercise template without a placeholder:\n{c.source}"


def _exercises_in_four_cells(path):
    """The convention of edition.exercises.framework: statement, answer (a None template), solution, check (one
    call of a registered check with the answer's names), in this order; and a "your own robot" cell."""
    from edition.exercises.framework import by_name
    from tools.assignments import assignment, check_call

    nb = nbformat.read(path, as_version=4)
    assert assignment(nb, path.stem, lambda name: by_name(name).points) is not None  # order and roles
    checks = [c for c in nb.cells if "check" in tags(c)]
    assert len(checks) >= 2, f"{path.name}: {len(checks)} exercises"
    for c in checks:
        by_name(check_call(c.source, path.name))
    for c in nb.cells:
        if "answer" in tags(c):
            assert re.fullmatch(r"\w+ = None +# .+", c.source.strip()), f"{path.name}: an answer template:\n{c.source}"
    own = [
        c for c in nb.cells if c.cell_type == "code" and tags(c) & {"explore", "exercise"} and "my_robot" in c.source
    ]
    assert own, f"{path.name}: no 'your own robot' cell"


@pytest.mark.parametrize("path", EXERCISE_CHAPTERS, ids=lambda p: p.name)
def test_exercise_statements_carry_their_number_and_tolerance(path):
    """The statement cell before each answer names its exercise and the tolerance its check applies (the answer
    tables of the checks test that the tolerance is the one applied)."""
    from edition.exercises.framework import by_name
    from tools.assignments import check_call

    cs = cells(path)
    for i, c in enumerate(cs):
        if "check" not in tags(c):
            continue
        statement = next(x for x in reversed(cs[:i]) if "exercise" in tags(x) and x.cell_type == "markdown")
        ex = by_name(check_call(c.source, path.name))
        text = " ".join(statement.source.replace("**", "").split())
        assert re.search(rf"(?<![\d.]){re.escape(ex.number)}(?!\d)", text), f"{path.name}: {ex.number} not named"
        if ex.tolerance is not None and ex.tolerance.statement.startswith(("to ", "within ")):
            stated = ex.tolerance.statement.removeprefix("to ").removeprefix("within ")
            assert stated in text, f"{path.name}: exercise {ex.number} does not state {ex.tolerance.statement!r}"
        symbolic = "SymPy" in ex.answer or "whole numbers" in ex.answer
        if not symbolic:  # a number: its units
            assert re.search(r"\b(rad|rad/s|degrees?|metres|m|m/s)\b", text), f"{path.name}: {ex.number} states no unit"
        if re.search(r"\b(two|three|four|pair|list|points|twist)\b", ex.answer) and not symbolic:  # a list: its order
            order = r"wheel 1 first|in the order|in any order|\(?\\beta_1, \\beta_2|"
            order += r"\(\\dot\\theta_\{i1\}|\(\\dot\\psi|\(u_x|\(x, y\)"
            assert re.search(order, text), f"{path.name}: exercise {ex.number} does not state the order of its list"


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_figures_are_shown_once_in_tagged_cells(path):
    for c in cells(path, "code"):
        shows = re.findall(r"ch\.figure\(\"(\w+)\"\)", c.source)
        if shows:
            assert "figure" in tags(c) and len(shows) == 1, f"{path.name}: {c.source}"


def test_each_figure_is_computed_in_its_chapter():
    where = {}
    for path in CHAPTERS:
        for c in cells(path, "code"):
            for key in re.findall(r"ch\.figure\(\"(\w+)\"\)", c.source):
                assert key not in where, f"{key} computed twice"
                where[key] = path.name[:2]
    assert where == {
        "conventions": "01",
        "fig07": "02",
        "fig08": "04",
        "fig09": "04",
        "fig10": "04",
        "fig11": "04",
        "fig12": "04",
        "detmap": "04",
        "fig13": "05",
    }


# ----------------------------------------------------------------------------------------------- student edition
def test_student_edition_has_no_solutions_and_still_runs():
    """``make student RUN=1`` (nbconvert's TagRemovePreprocessor, then the chapters' cached executor):
    every chapter without its solutions, its exercises kept, and every one still runs."""
    import subprocess

    run = subprocess.run(
        ["make", "-s", "--no-print-directory", "-C", str(ROOT), f"WMR_ROOT={ROOT}", "student", "RUN=1"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert run.returncode == 0, "student notebooks fail:\n" + (run.stdout + run.stderr)[-4000:]
    out = ROOT / "build" / "student"
    paths = sorted(out.glob("*.ipynb"))
    assert [p.name for p in paths] == [p.name for p in CHAPTERS]
    for p, src in zip(paths, CHAPTERS):
        nb = nbformat.read(p, as_version=4)
        assert not [c for c in nb.cells if "solution" in tags(c)]
        assert not [c for c in nb.cells if c.cell_type == "code" and (c.outputs or c.execution_count)]
        n_ex = sum("exercise" in tags(c) for c in cells(src))
        assert sum("exercise" in tags(c) for c in nb.cells) == n_ex
    done = nbformat.read(ROOT / "build" / "student-run" / "notebooks" / paths[0].name, as_version=4)
    assert [c.source for c in done.cells] == [c.source for c in nbformat.read(paths[0], as_version=4).cells]
    text = "\n".join(
        o.get("data", {}).get("text/markdown", "") for c in done.cells if c.cell_type == "code" for o in c.outputs
    )
    assert "No answer yet" in text and "**Right.**" not in text


# ----------------------------------------------------------------------------------------------- where files go
def test_project_from_environment(monkeypatch, tmp_path):
    monkeypatch.setenv("WMR_OUT", str(tmp_path / "out"))
    p = NB.project("/somewhere/else/notebooks")
    assert p.out == p.figures == (tmp_path / "out").resolve() and p.source == "build"


def test_project_from_the_notebook_location(monkeypatch, tmp_path):
    monkeypatch.delenv("WMR_OUT", raising=False)
    for d in ("notebooks", "figures"):
        (tmp_path / "course" / d).mkdir(parents=True)
    course = (tmp_path / "course").resolve()
    p = NB.project(tmp_path / "course" / "notebooks", "04_x")  # a chapter of a project: its build/scratch
    assert (p.root, p.out, p.source) == (course, course / "build" / "scratch" / "04_x", "scratch")
    assert NB.project(tmp_path / "course").root == course
    copy = NB.project(tmp_path / "copy")  # a copy elsewhere: a temporary folder ...
    assert copy.root is None and copy.source == "temporary" and tmp_path not in copy.out.parents
    assert not (tmp_path / "copy" / "figures").exists()
    text = copy.where()  # ... and it says so
    assert str(copy.out) in text and "temporary" in text
    monkeypatch.chdir(tmp_path / "course" / "notebooks")
    assert NB.project().root == course
    (tmp_path / "other" / "notebooks").mkdir(parents=True)  # notebooks/ without figures/: not a project
    assert NB.project(tmp_path / "other" / "notebooks").source == "temporary"


def _shown(monkeypatch):
    """What IPython.display.display shows, collected (the Markdown texts and the images' types)."""
    shown = []
    monkeypatch.setattr("IPython.display.display", lambda *objs, **kw: shown.extend(objs))
    return shown


def test_a_figure_is_saved_only_in_a_project_and_drawn_unless_nbgrader_grades(monkeypatch, tmp_path):
    monkeypatch.delenv("WMR_OUT", raising=False)
    monkeypatch.delenv("NBGRADER_EXECUTION", raising=False)
    for d in ("notebooks", "figures"):
        (tmp_path / "course" / d).mkdir(parents=True)
    shown = _shown(monkeypatch)
    scratch = NB.Chapter("04_x", where=tmp_path / "course" / "notebooks")
    scratch.figure("fig13")
    assert (scratch.project.out / "fig13.json").is_file() and (scratch.project.out / "fig13.svg").is_file()
    copy = NB.Chapter("04_x", where=tmp_path / "copy")  # outside any project: shown, not saved
    copy.figure("fig13")
    assert copy.project.source == "temporary" and not list(copy.project.out.iterdir())
    assert "figures are shown, not saved" in copy.project.where()
    assert sum(isinstance(o, dict) and "image/png" in o for o in shown) == 2  # both drawn
    monkeypatch.setenv("NBGRADER_EXECUTION", "autograde")  # nbgrader grading: computed, not drawn, not saved
    shown.clear()
    graded = NB.Chapter("04_y", where=tmp_path / "course" / "notebooks")
    data = graded.figure("fig13")
    assert data.rank_F == 5 and not graded.project.out.exists()
    assert not any(isinstance(o, dict) and "image/png" in o for o in shown)
    assert any("not drawn in this run" in getattr(o, "data", "") for o in shown)


def test_project_of_this_repository_writes_under_build_and_says_so(monkeypatch):
    monkeypatch.delenv("WMR_OUT", raising=False)
    p = NB.project(ROOT / "notebooks", "01_x")
    assert p.root == ROOT and p.out == ROOT / "build" / "scratch" / "01_x"
    assert "not this project" not in p.where() and "only `make report` or `make test` writes `figures/`" in p.where()
    other = NB.Project(root=Path("/elsewhere"), out=Path("/elsewhere/build/scratch/x"), source="scratch")
    assert "not this project" in other.where() and str(Path(wmr.__file__).parent) in other.where()


def test_the_library_resolves_no_repository_path():
    src = "\n".join(p.read_text() for p in (ROOT / "wmr").rglob("*.py"))
    assert "parents[2]" not in src and "WMR_FIGURES" not in src


# ----------------------------------------------------------------------------------------------- helpers
def test_table_is_markdown_without_index(monkeypatch):
    shown = []
    monkeypatch.setattr(DP, "_display", lambda *o: shown.extend(o))
    DP.table([{"w": 1, "rank": {5, 6}, "ok": True, "x": 0.123456}])
    md = shown[0].data
    assert md.splitlines()[0] == "| w | rank | ok | x |" and "| 1 | 5, 6 | yes | $0.123$ |" in md


def test_long_sums_are_broken_into_lines(monkeypatch):
    shown = []
    monkeypatch.setattr(DP, "_display", lambda *o: shown.extend(o))
    x, y, z = sp.symbols("x y z")
    DP.show("s", x - y + z, per_line=1)
    assert r"\begin{aligned}s = {}& x\\ &- y\\ &+ z\end{aligned}" in shown[0].data
    for bad, kind in ((0, ValueError), (1.5, TypeError), (True, TypeError)):
        with pytest.raises(kind, match="per_line"):
            DP.show("s", x, per_line=bad)


def test_a_quantity_that_does_not_exist_reads_undefined(monkeypatch):
    shown = []
    monkeypatch.setattr(DP, "_display", lambda *o: shown.extend(o))
    DP.table([{"u": np.array([np.nan, np.nan]), "v": np.array([0.8, np.nan]), "x": float("nan")}])
    assert "| undefined | $0.8$, undefined | undefined |" in shown[0].data and "NaN" not in shown[0].data
    DP.show("q", sp.Integer(0) / 0)
    assert r"q = \text{undefined}" in shown[1].data


def test_mod_pi_and_latex():
    assert np.allclose(mod_pi([np.pi + 0.25, -np.pi / 2, np.pi / 2]), [0.25, -np.pi / 2, -np.pi / 2])
    assert DP.latex(sp.Matrix([[1, 2]])) == r"\begin{bmatrix}1 & 2\end{bmatrix}"


# ----------------------------------------------------------------------------------------------- exercise checks
CHECKS = [
    X.offset_other_side,
    X.dual_counterexample,
    X.dual_spin_in_place,
    X.locked_steering,
    X.drift_of_c_general,
    X.isotropic_placement,
    X.dual_upsilon,
    X.offset_for_kappa,
    X.unlisted_singularity,
    X.mobile_and_singular,
    X.translation_angles,
    X.rotation_angles,
    X.printed_65_region,
    X.curved_translation,
    X.reversal,
]


@pytest.mark.parametrize("check", CHECKS, ids=lambda f: f.__name__)
def test_a_missing_answer_is_not_an_error(check):
    import inspect

    n = len([p for p in inspect.signature(check).parameters.values() if p.default is inspect.Parameter.empty])
    fb = check(*([None] * n))
    assert not fb and fb.message.startswith("No answer yet") and fb._repr_markdown_().startswith("**Not yet.**")


def test_describe_robot():
    text = X.describe_robot(wmr.paper_robot("offset", L=0.3, r=0.1, d=0.05), twist=[1, 0, 0])
    assert "rank 6" in text and "3-dimensional" in text and "executable" in text
    with pytest.raises(TypeError, match="robot"):
        X.describe_robot("robot")


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_every_picture_a_chapter_shows_has_alt_text(path):
    """Each PNG an executed chapter shows also comes as an ``<img alt=...>`` with a description (JupyterLab and HTML
    readers get the alt text; a bare PNG output has none). Reads the build's executed copy (``make test`` makes it)."""
    executed = ROOT / "build" / "notebooks" / path.name
    if not executed.is_file():
        pytest.skip(f"{executed} not built: run `make notebooks` (make test does)")
    nb = nbformat.read(executed, as_version=4)
    bare = []
    for k, c in enumerate(nb.cells):
        for o in c.get("outputs", []):
            data = o.get("data", {})
            if "image/png" in data:
                m = re.search(r'<img [^>]*alt="([^"]*)"', data.get("text/html", ""))
                if not m or len(m.group(1).split()) < 3:
                    bare.append(f"cell {k}")
    assert not bare, f"{path.name}: pictures without alt text in {bare}"
