"""``make assignments`` (tools/assignments.py): nbgrader source notebooks from the chapters' exercise cells, and the
round trip through nbgrader itself -- generate_assignment, then autograde a solved copy (full marks) and the released
blank copy (zero)."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

from edition.exercises.framework import by_name
from tools import assignments as A

ROOT = Path(__file__).resolve().parents[2]
LESSONS = sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))


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
    assert test.source == "check_x(x).require();" and test.metadata.nbgrader["points"] == 3.0
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


def test_a_chapter_without_gradable_exercises_gives_none():
    assert A.assignment(_nb(GOOD[0], ("code", "x = 1", ["solution"])), "demo", lambda n: 1) is None


def test_make_assignments_writes_each_chapter_with_exercises_once(tmp_path):
    assert A.main([str(tmp_path), *map(str, LESSONS)]) == 0
    written = sorted(p.relative_to(tmp_path).as_posix() for p in tmp_path.rglob("*.ipynb"))
    expected = []
    for p in LESSONS:
        nb = nbformat.read(p, as_version=4)
        checks = [c for c in nb.cells if "check" in c.metadata.get("tags", [])]
        if checks:
            expected.append(f"source/{p.stem}/{p.name}")
            out = nbformat.read(tmp_path / "source" / p.stem / p.name, as_version=4)
            tests = [c for c in out.cells if c.metadata.get("nbgrader", {}).get("grade")]
            assert len(tests) == len(checks)
            for t in tests:
                name = A.check_call(t.source.rstrip(";").removesuffix(".require()"), p.name)
                assert t.metadata.nbgrader["points"] == by_name(name).points
            assert not any("solution" in c.metadata.get("tags", []) for c in out.cells)
    assert written == expected and "source/10_robot_classes/10_robot_classes.ipynb" in written
    before = {p: p.stat().st_mtime_ns for p in tmp_path.rglob("*")}
    assert A.main([str(tmp_path), *map(str, LESSONS)]) == 0
    assert {p: p.stat().st_mtime_ns for p in tmp_path.rglob("*")} == before  # nothing rewritten


ASSIGNED = [
    p for p in LESSONS if any("check" in c.metadata.get("tags", []) for c in nbformat.read(p, as_version=4).cells)
]


@pytest.mark.parametrize("chapter", ASSIGNED, ids=lambda p: p.stem)
def test_nbgrader_round_trip_full_marks_for_the_solution_and_zero_for_the_blank(tmp_path, chapter):
    course, name = tmp_path / "course", chapter.stem
    assert A.main([str(course), str(chapter)]) == 0
    env = dict(
        os.environ,
        PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
        MPLBACKEND="Agg",
        WMR_OUT=str(tmp_path / "out"),
    )
    nbgrader = [sys.executable, "-m", "nbgrader"]

    def run(*args):
        p = subprocess.run(
            [*nbgrader, *args, "--log-level=WARN"], cwd=course, env=env, capture_output=True, text=True, timeout=900
        )
        assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]

    run("generate_assignment", name)
    for student, src in (("solved", course / "source"), ("blank", course / "release")):
        (course / "submitted" / student / name).mkdir(parents=True)
        shutil.copy(src / name / chapter.name, course / "submitted" / student / name / chapter.name)
    released = nbformat.read(course / "release" / name / chapter.name, as_version=4)
    assert "### BEGIN SOLUTION" not in nbformat.writes(released)
    run("autograde", name)
    from nbgrader.api import Gradebook  # type: ignore[import-untyped]

    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        solved, blank = gb.find_submission(name, "solved"), gb.find_submission(name, "blank")
        assert solved.max_score > 0
        assert (solved.score, blank.score) == (solved.max_score, 0.0), (solved.score, blank.score, solved.max_score)
