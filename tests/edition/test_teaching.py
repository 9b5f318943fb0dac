"""TEACHING.md, followed as an instructor would: its set-up and its script run as written (nbgrader from the
clone's environment, not activated and activated), two students (one with every answer right, one blank),
the answers in words graded through nbgrader's gradebook (what the formgrader does), then the feedback pages
(offline math) and the exported gradebook."""

from __future__ import annotations

import csv
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
GUIDE = ROOT / "TEACHING.md"


def _blocks() -> list[str]:
    return re.findall(r"^```bash\n(.*?)^```", GUIDE.read_text(encoding="utf-8"), re.MULTILINE | re.DOTALL)


def _script() -> tuple[str, str, str]:
    """The guide's script, cut at its steps: the preamble (variables, nbgrader, cd), step 1, steps 2 to 6."""
    (script,) = [b for b in _blocks() if "nbgrader generate_assignment" in b]
    head, rest = script.split("# 1. release", 1)
    step1, rest = rest.split("# 2. collect", 1)
    return head, "# 1. release" + step1, "# 2. collect" + rest


def _bash(source: str, home: Path, cwd: Path) -> subprocess.CompletedProcess:
    venv_bin = str(ROOT / ".venv" / "bin")
    path = os.pathsep.join(p for p in os.environ.get("PATH", "").split(os.pathsep) if p != venv_bin)
    env = {"HOME": str(home), "PATH": path, "LANG": "C.UTF-8"}  # not activated: nbgrader by its path
    return subprocess.run(
        ["bash", "-euo", "pipefail", "-c", source], cwd=cwd, env=env, capture_output=True, text=True, timeout=900
    )


def _ok(p: subprocess.CompletedProcess) -> None:
    assert p.returncode == 0, f"exit {p.returncode}\n{p.stdout[-3000:]}\n{p.stderr[-6000:]}"


def _formgrader_page(course: Path, path: str) -> str:
    """A page of nbgrader's formgrader, served by a Jupyter server started in ``course`` (nbgrader's extensions on)."""
    import socket
    import time
    import urllib.error
    import urllib.request

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    cmd = [str(ROOT / ".venv" / "bin" / "jupyter"), "server", "--no-browser", f"--port={port}", "--ip=127.0.0.1"]
    cmd += ["--IdentityProvider.token=t", f"--ServerApp.root_dir={course}", "--allow-root"]
    server = subprocess.Popen(cmd, cwd=course, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        for _ in range(120):
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/{path}?token=t", timeout=30) as r:
                    return r.read().decode("utf-8")
            except urllib.error.HTTPError as e:
                raise AssertionError(f"the formgrader answered {e.code} for {path}") from None
            except (urllib.error.URLError, ConnectionError):
                time.sleep(0.5)
        raise AssertionError("the Jupyter server did not start")
    finally:
        server.terminate()
        server.wait(30)


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    """The set-up block run in this clone (its `git clone` line left out: the clone is this one), HOME a
    temporary folder holding a link `wmr` to the clone."""
    home = tmp_path_factory.mktemp("home")
    (home / "wmr").symlink_to(ROOT)
    (setup,) = [b for b in _blocks() if "make assignments" in b]
    lines = [line for line in setup.splitlines() if not line.startswith("git clone")]
    _ok(_bash("\n".join(lines), home, ROOT))
    return home


def test_the_guide_names_every_step_an_instructor_expects():
    text = GUIDE.read_text(encoding="utf-8")
    for step in ("generate_assignment", "autograde", "generate_feedback", "nbgrader export", "Formgrader", "collect"):
        assert step in text, step
    head, step1, rest = _script()
    assert 'source "$WMR/.venv/bin/activate"' in head  # the activated form is offered beside the other


def test_the_guide_runs_as_written_release_collect_autograde_grade_feedback_export(course):
    home = course
    head, step1, rest = _script()
    _ok(_bash(head + step1, home, home))
    cdir, ch = home / "wmr-course", "05_steering_and_instant_centre"
    assert f"CH={ch}" in head
    released = cdir / "release" / ch / f"{ch}.ipynb"
    text = released.read_text(encoding="utf-8")
    assert "BEGIN SOLUTION" not in text and "BEGIN HIDDEN TESTS" not in text and "YOUR ANSWER HERE" in text
    downloads = home / "downloads" / ch
    downloads.mkdir(parents=True)
    shutil.copy(cdir / "source" / ch / f"{ch}.ipynb", downloads / "alice.ipynb")  # every answer right
    shutil.copy(released, downloads / "bob.ipynb")  # blank
    collect, grade = rest.split("# 5. feedback", 1)
    _ok(_bash(head + collect, home, home))
    # step 4, as the formgrader does it: each answer in words gets its score (alice the model answer: full marks)
    from nbgrader.api import Gradebook  # type: ignore[import-untyped]

    with Gradebook(f"sqlite:///{cdir / 'gradebook.db'}") as gb:
        for student, score in (("alice", 1.0), ("bob", 0.0)):
            (nb,) = gb.find_submission(ch, student).notebooks
            manual = [g for g in nb.grades if g.cell_type == "markdown" and g.max_score]
            assert manual, "the chapter has a question answered in words"
            for g in manual:
                g.manual_score = score * g.max_score
        gb.db.commit()
        alice = gb.find_submission_notebook(ch, ch, "alice").id
    page = _formgrader_page(cdir, f"formgrader/submissions/{alice}/")  # where the guide sends the grader
    assert "YOUR ANSWER HERE" not in page and page.count('class="score') >= 1
    _ok(_bash(head + "# 5. feedback" + grade, home, home))
    rows = {r["student_id"]: r for r in csv.DictReader((cdir / "grades.csv").open(encoding="utf-8"))}
    assert set(rows) == {"alice", "bob"}
    assert float(rows["alice"]["score"]) == float(rows["alice"]["max_score"]) > 0
    assert float(rows["bob"]["score"]) == 0.0
    for student in ("alice", "bob"):
        page = (cdir / "feedback" / student / ch / f"{ch}.html").read_text(encoding="utf-8")
        assert 'id="wmr-mathjax-gz"' in page  # math typeset offline
        assert not re.search(r"<(script|link)[^>]+(src|href)=\"https?:", page)  # nothing fetched


def test_the_guide_works_with_the_environment_activated(course, tmp_path):
    """Step 1 (nbgrader's first database in a new course: where `alembic` was once not found) with the
    clone's environment activated, in a course of its own."""
    head, step1, _ = _script()
    shutil.copytree(course / "wmr-course" / "source", tmp_path / "c" / "source")
    shutil.copy(course / "wmr-course" / "nbgrader_config.py", tmp_path / "c")
    activated = re.sub(r"^nbgrader\(\).*$", 'source "$WMR/.venv/bin/activate"', head, flags=re.MULTILINE)
    activated = re.sub(r"^COURSE=.*$", f"COURSE={tmp_path / 'c'}", activated, flags=re.MULTILINE)
    assert activated != head
    _ok(_bash(activated + step1, course, tmp_path))
    assert (tmp_path / "c" / "release" / "05_steering_and_instant_centre").is_dir()
