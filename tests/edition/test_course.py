"""The student package (``make course``, issue 32): a wheel with no worked solution, no rubric and no hidden
test in it, whose notebooks run to the end in a fresh venv with their answers blank."""

from __future__ import annotations

import json
import subprocess
import zipfile

import nbformat
import pytest

from tools import course as K

ROOT = K.ROOT
OUT = ROOT / "build" / "course"


def test_the_leak_rule_can_fail():
    solutions = K.solution_texts()
    assert solutions, "the lessons have worked solutions to look for"
    some = solutions[0]
    assert K.leaks({"edition/x.py": f"# {some}\n".encode()}, solutions)  # a solution line anywhere
    cell = {"cells": [{"source": ["x = 1\n", "### BEGIN HIDDEN TESTS\n"]}]}
    assert K.leaks({"n.ipynb": json.dumps(cell).encode()}, [])  # nbgrader's markers
    assert K.leaks({"n.ipynb": json.dumps({"cells": [{"source": ["**Model answer (1.1).** x"]}]}).encode()}, [])
    assert K.leaks({"n.ipynb": json.dumps({"cells": [{"source": ["# YOUR CODE HERE"]}]}).encode()}, solutions) == []


@pytest.fixture(scope="module")
def built():
    """``make course`` (cached by its stamp: after ``make test``'s build, nothing runs)."""
    p = subprocess.run(
        ["make", "-s", "--no-print-directory", "-C", str(ROOT), "course"], capture_output=True, text=True, check=False
    )
    if p.returncode != 0:
        pytest.fail(p.stdout + p.stderr, pytrace=False)
    (wheel,) = OUT.glob("wmr_course-*-py3-none-any.whl")
    with zipfile.ZipFile(wheel) as zf:
        members = {n: zf.read(n) for n in zf.namelist()}
    return members, json.loads((OUT / "check.json").read_text(encoding="utf-8"))


def test_the_package_holds_every_lesson_and_no_solution(built):
    members, _ = built
    for p in K.LESSONS:
        assert f"wmr_course/notebooks/{p.name}" in members, p.name
    # what a lesson derived for a later one: the published files, read by edition.derivations.derived; no cell
    derived = sorted((ROOT / "figures").glob("*.derived.json"))
    assert derived and all(members[f"edition/_derived/{p.name}"] == p.read_bytes() for p in derived)
    assert not [n for n in members if n.startswith("edition/_chapters/")]
    assert "wmr_course/__main__.py" in members and any(n.endswith(".dist-info/RECORD") for n in members)
    found = K.leaks(members, K.solution_texts())
    assert not found, f"solutions in the student package: {found[:10]}"


def test_every_notebook_runs_to_the_end_in_a_fresh_venv_with_blank_answers(built):
    _, check = built
    ran = check["notebooks"]
    assert sorted(ran) == sorted(p.name for p in K.LESSONS)
    for p in K.LESSONS:
        checks = sum("check" in c.metadata.get("tags", []) for c in nbformat.read(p, as_version=4).cells)
        assert ran[p.name] == {"runs_to_the_end": True, "unanswered_shown": checks}, (p.name, ran[p.name])
