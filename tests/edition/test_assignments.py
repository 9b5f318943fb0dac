"""``make assignments`` (tools/assignments.py): nbgrader source notebooks from the chapters' exercise cells, and the
round trip through nbgrader itself -- generate_assignment, then autograde a solved copy (full marks) and the released
blank copy (zero).

The round trip is a build step (``make grades``, tools/grades.py; ``make test`` runs it before pytest): a few minutes
of kernels per run, cached by the build's content hash like an executed chapter.  The tests here read its results,
``build/assignments/grades/<chapter>.json`` (the fixture runs ``make``, which does nothing when they are current),
check that the files are the current ones (their stamp holds the key of the chapter as it is now), and that the key
changes with each thing the round trip reads (a small tree)."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import nbformat
import pytest

from edition.exercises.framework import by_name
from tools import assignments as A
from tools import grades as G
from tools.build import execute as X

ROOT = Path(__file__).resolve().parents[2]
TREE = Path(os.environ.get("WMR_ROOT") or ROOT)  # WMR_ROOT: test another tree (as test_report does)
BUILD = Path(os.environ.get("WMR_BUILD") or TREE / "build")
LESSONS = sorted((TREE / "notebooks").glob("[0-9][0-9]_*.ipynb"))


def _nb(*cells):
    nb = nbformat.v4.new_notebook()
    for kind, src, tags in cells:
        c = nbformat.v4.new_markdown_cell(src) if kind == "md" else nbformat.v4.new_code_cell(src)
        if tags:
            c.metadata["tags"] = tags
        nb.cells.append(c)
    return nb


GOOD = [
    ("code", "import numpy as np", None),
    ("md", "Exercise: give x.", ["exercise"]),
    ("code", "x = None  # a number", ["answer"]),
    ("code", "x = 2.0", ["solution"]),
    ("code", "check_x(x)", ["check"]),
    ("md", "The end.", None),
]


def test_the_four_cells_become_a_solution_region_and_a_graded_test():
    nb = A.assignment(_nb(*GOOD), "demo", lambda name: {"check_x": 3}[name])
    assert nb is not None
    kinds = [
        (c.cell_type, c.metadata.get("nbgrader", {}).get("solution"), c.metadata.get("nbgrader", {}).get("grade"))
        for c in nb.cells
    ]
    assert kinds == [
        ("code", None, None),
        ("markdown", False, False),
        ("code", True, False),
        ("code", False, True),
        ("markdown", None, None),
    ]
    sol, test = nb.cells[2], nb.cells[3]
    assert sol.source == "x = None  # a number\n### BEGIN SOLUTION\nx = 2.0\n### END SOLUTION"
    # the visible check shows the verdict and never raises; the hidden test (put back when nbgrader grades) fails
    assert test.source == "check_x(x)\n### BEGIN HIDDEN TESTS\ncheck_x(x).require();\n### END HIDDEN TESTS"
    assert test.metadata.nbgrader["points"] == 3.0
    assert test.metadata.nbgrader["locked"] and not sol.metadata.nbgrader["locked"]
    assert len({c.metadata.get("nbgrader", {}).get("grade_id") for c in nb.cells[1:4]}) == 3
    nbformat.validate(nb)


@pytest.mark.parametrize(
    "cells,message",
    [
        ([c for c in GOOD if c[2] != ["check"]], "no check cell"),
        ([c for c in GOOD if c[2] != ["solution"]], "has no solution cell"),
        ([c for c in GOOD if c[2] != ["answer"]], "without an answer cell"),
        ([*GOOD[:4], ("code", "check_x(x)\ncheck_x(x)", ["check"])], "one call"),
        ([*GOOD[:4], ("code", "print(check_x(x))", ["check"])], "one call"),
        ([GOOD[0], ("code", "x = None", ["answer", "check"])], "a cell tagged"),
        ([GOOD[0], ("md", "x = None", ["answer"]), *GOOD[3:]], "expected a code cell"),
    ],
    ids=["no check", "no solution", "no answer", "two calls", "not a check call", "two roles", "markdown answer"],
)
def test_a_broken_convention_is_named(cells, message):
    with pytest.raises(A.AssignmentError, match=message):
        A.assignment(_nb(*cells), "demo", lambda name: 1)


def test_a_written_answer_and_its_rubric_become_one_manually_graded_cell():
    cells = [*GOOD[:5], ("md", "*Your answer:* write it here.", ["written"]), ("md", "Model answer: x.", ["rubric"])]
    nb = A.assignment(_nb(*cells), "demo", lambda name: 1)
    assert nb is not None
    manual = nb.cells[-1]
    assert manual.cell_type == "markdown" and manual.source == "Model answer: x."  # the instructor's copy
    meta = manual.metadata.nbgrader
    assert meta["solution"] and meta["grade"] and not meta["locked"] and meta["points"] == A.WRITTEN_POINTS
    assert meta["grade_id"] == "demo-check_x-written"
    with pytest.raises(A.AssignmentError, match="rubric"):
        A.assignment(_nb(*cells[:-1]), "demo", lambda name: 1)
    with pytest.raises(A.AssignmentError, match="written answer"):
        A.assignment(_nb(*cells[:5], ("md", "Model answer: x.", ["rubric"])), "demo", lambda name: 1)


def test_a_chapter_without_gradable_exercises_gives_none():
    assert A.assignment(_nb(GOOD[0], ("code", "x = 1", ["solution"])), "demo", lambda n: 1) is None


def test_make_assignments_writes_each_chapter_with_exercises_once(tmp_path):
    assert A.main(["--no-feedback", str(tmp_path), *map(str, LESSONS)]) == 0
    written = sorted(p.relative_to(tmp_path).as_posix() for p in tmp_path.rglob("*.ipynb"))
    expected = []
    for p in LESSONS:
        nb = nbformat.read(p, as_version=4)
        checks = [c for c in nb.cells if "check" in c.metadata.get("tags", [])]
        if checks:
            expected.append(f"source/{p.stem}/{p.name}")
            out = nbformat.read(tmp_path / "source" / p.stem / p.name, as_version=4)
            graded = [c for c in out.cells if c.metadata.get("nbgrader", {}).get("grade")]
            tests = [c for c in graded if c.cell_type == "code"]
            assert len(tests) == len(checks)
            in_words = [c for c in nb.cells if "written" in c.metadata.get("tags", [])]
            assert len(graded) - len(tests) == len(in_words)  # one manually graded cell per question in words
            for t in tests:
                visible, hidden = t.source.split("\n### BEGIN HIDDEN TESTS\n")
                assert hidden == f"{visible}.require();\n### END HIDDEN TESTS"  # the hidden test recomputes the check
                name = A.check_call(visible, p.name)
                assert t.metadata.nbgrader["points"] == by_name(name).points
            assert not any({"solution", "rubric"} & set(c.metadata.get("tags", [])) for c in out.cells)
    assert written == expected and "source/10_robot_classes/10_robot_classes.ipynb" in written
    before = {p: p.stat().st_mtime_ns for p in tmp_path.rglob("*")}
    assert A.main(["--no-feedback", str(tmp_path), *map(str, LESSONS)]) == 0
    assert {p: p.stat().st_mtime_ns for p in tmp_path.rglob("*")} == before  # nothing rewritten


def checks_of(chapter):
    """The checks a chapter's cells tagged ``check`` call, in order: its own list of exercises."""
    cells = nbformat.read(chapter, as_version=4).cells
    return [A.check_call(c.source, chapter.name) for c in cells if "check" in c.metadata.get("tags", [])]


def grades_file(chapter):
    return BUILD / "assignments" / "grades" / f"{chapter.stem}.json"


def current(chapter):
    """True when the chapter's grades file is the one its key asks for (the stamp is the build's)."""
    out = grades_file(chapter)
    return X.up_to_date(out.with_suffix(".stamp"), G.key(chapter, TREE), out)


@pytest.fixture(scope="module")
def grades():
    """The grades of every lesson; ``make`` builds those that are not current (after ``make test``'s build: none)."""
    stale = [str(grades_file(p)) for p in LESSONS if not current(p)]
    if stale:
        make = ["make", "-s", "--no-print-directory", "-j2", "-C", str(ROOT), f"WMR_ROOT={TREE}", f"WMR_BUILD={BUILD}"]
        p = subprocess.run([*make, *stale], capture_output=True, text=True, check=False)
        if p.returncode != 0:
            pytest.fail(p.stdout + p.stderr, pytrace=False)
    return {c.stem: json.loads(grades_file(c).read_text(encoding="utf-8")) for c in LESSONS}


@pytest.mark.parametrize("chapter", LESSONS, ids=lambda p: p.stem)
def test_nbgrader_round_trip_full_marks_for_the_solution_and_zero_for_the_blank(grades, chapter):
    assert current(chapter), f"{grades_file(chapter)} is not the current one: make did not rebuild it"
    g, checks = grades[chapter.stem], checks_of(chapter)
    if not checks:  # "Your own robot" cells only, or none: nothing to grade, nbgrader not started
        assert g == {"chapter": chapter.stem, "exercises": []}
        return
    assert g["chapter"] == chapter.stem
    assert [e["check"] for e in g["exercises"]] == checks  # every exercise graded by nbgrader, once, in order
    for e in g["exercises"]:
        assert e["grade_id"] == f"{chapter.stem}-{e['check']}"
        assert e["max"] == by_name(e["check"]).points > 0, e
        assert (e["solved"], e["blank"]) == (e["max"], 0.0), e
    # the questions answered in words: each a manually graded cell; the model answer waits for a grader, the
    # untouched blank is scored 0 by nbgrader itself
    cells = nbformat.read(chapter, as_version=4).cells
    n_written = sum("written" in c.metadata.get("tags", []) for c in cells)
    assert len(g["written"]) == n_written
    for w in g["written"]:
        assert w["max"] == A.WRITTEN_POINTS and w["solved_needs_manual_grade"], w
        assert (w["blank"], w["blank_needs_manual_grade"]) == (0.0, False), w
    auto = sum(e["max"] for e in g["exercises"])
    by_hand = sum(w["max"] for w in g["written"])
    assert g["total"] == {"max": auto + by_hand, "solved": auto, "blank": 0.0}  # nbgrader's own sums per submission
    # Run All on the released notebook (hidden tests removed, answers blank) runs to the end: a student is never
    # stopped by a traceback before the first exercise is answered
    assert g["released_runs_to_the_end"] is True, g["released_runs_to_the_end"]


def test_the_grades_key_changes_with_everything_the_round_trip_reads(tmp_path):
    """A stale cache would report the grades of another edition: the key must change when the chapter, what a
    chapter derived for later ones (``figures/*.derived.json``), ``wmr/``, ``edition/``, the tools that make and grade
    the assignment or the pinned environment change, and only then (a new mtime, another chapter's notebook or
    another published file is no change)."""
    files = {
        "notebooks/01_a.ipynb": "{}",
        "figures/00_z.derived.json": "{}",
        "wmr/__init__.py": "",
        "edition/exercises/framework.py": "",
        "tools/assignments.py": "",
        "tools/grades.py": "",
        "environment.lock": "nbgrader==0.9.6",
    }
    for name, text in files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text)
    chapter = tmp_path / "notebooks" / "01_a.ipynb"
    k = G.key(chapter, tmp_path)
    os.utime(chapter, (0, 0))
    assert G.key(chapter, tmp_path) == k
    (tmp_path / "tools" / "bench.py").write_text("# not read by the round trip")
    (tmp_path / "notebooks" / "02_b.ipynb").write_text("{}")  # another chapter: read through its derived file only
    (tmp_path / "figures" / "fig01.json").write_text("{}")
    assert G.key(chapter, tmp_path) == k
    seen = {k}
    for name in files:
        (tmp_path / name).write_text(files[name] + " ")
        new = G.key(chapter, tmp_path)
        assert new not in seen, f"the key did not change with {name}"
        seen.add(new)
    (tmp_path / "edition" / "exercises" / "ch9.py").write_text("")  # a new file
    assert G.key(chapter, tmp_path) not in seen


def test_a_current_stamp_runs_nothing_and_a_damaged_result_runs_again(tmp_path):
    """The cache of :func:`tools.grades.grade` is the build's: a chapter without exercises (no nbgrader) on a small tree."""
    chapter = tmp_path / "notebooks" / "01_a.ipynb"
    chapter.parent.mkdir()
    nbformat.write(_nb(*GOOD[:1]), chapter)
    out = tmp_path / "build" / "assignments" / "grades" / "01_a.json"
    assert G.grade(chapter, out, root=tmp_path)
    assert json.loads(out.read_text()) == {"chapter": "01_a", "exercises": []}
    assert not G.grade(chapter, out, root=tmp_path)  # current: nothing runs
    out.write_text(out.read_text()[:10])  # truncated
    assert G.grade(chapter, out, root=tmp_path) and json.loads(out.read_text())["chapter"] == "01_a"
    (tmp_path / "environment.lock").write_text("nbgrader==0.9.7")
    assert G.grade(chapter, out, root=tmp_path)
