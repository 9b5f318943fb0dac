"""The build cannot be broken (issue 11, part 3): every fault below was injected into the old
``tools/build.py`` and broke it; each test injects it again.

- a failing notebook leaves no report that looks current;
- outputs are written atomically (SIGKILL in the middle of a write leaves the old or the new file);
- stamps record the hashes of what a step produced: a truncated report, a garbage stamp, a
  truncated executed notebook are rebuilt, never "up to date", never a ``NotJSONError``;
- stopping a build (SIGTERM to make, SIGKILL to make, SIGINT to a background build, a stop during
  the PDF export) leaves no process and no temporary directory behind;
- two builds of one tree at once: the second waits and then finds nothing to do;
- ``make test`` fails when a build modifies tracked files (issue 11, part 4).
"""
from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import textwrap
import time
import uuid
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))
from tools import build  # noqa: E402
from tools.build import files, procs  # noqa: E402
from tools.build.stamps import Stamp  # noqa: E402
from test_notebooks import write_nb  # noqa: E402

PY = sys.executable
LINUX = sys.platform.startswith("linux")


# ----------------------------------------------------------------------------- helpers
def marked_processes(marker: str) -> list[tuple[int, str]]:
    """(pid, command line) of every live process whose environment holds ``marker``."""
    out = []
    for e in os.listdir("/proc"):
        if not e.isdigit() or int(e) == os.getpid():
            continue
        try:
            env = Path(f"/proc/{e}/environ").read_bytes()
            stat = Path(f"/proc/{e}/stat").read_text()
            cmd = Path(f"/proc/{e}/cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            continue
        if stat.rsplit(")", 1)[-1].split()[0] == "Z":
            continue
        if f"WMR_TEST_MARKER={marker}".encode() in env:
            out.append((int(e), cmd.strip()))
    return out


def wait_for(pred, timeout=90.0, step=0.1):
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout:
        v = pred()
        if v:
            return v
        time.sleep(step)
    return pred()


def slow_tree(tmp_path: Path, seconds: int = 120) -> Path:
    """A tree with one notebook that sleeps (so that a build can be stopped while it runs)."""
    write_nb(tmp_path / "notebooks" / "01_slow.ipynb", [f"import time\ntime.sleep({seconds})"])
    return tmp_path


def quick_tree(tmp_path: Path) -> Path:
    """A tree with one notebook of Markdown only (executing it starts no kernel)."""
    write_nb(tmp_path / "notebooks" / "01_quick.ipynb", [], markdown="# 1. A chapter\n\nSome prose with $x^2$.")
    return tmp_path


def env_with(marker: str, **extra) -> dict:
    env = dict(os.environ, WMR_TEST_MARKER=marker, PYTHONPATH=str(ROOT))
    env.update(extra)
    return env


def kernel_running(marker):
    return [p for p in marked_processes(marker) if "ipykernel" in p[1]]


# ----------------------------------------------------------------------------- atomic writes
def test_atomic_write_survives_sigkill(tmp_path):
    """A writer killed at random moments: the file is always complete, old or new."""
    target = tmp_path / "out.bin"
    files.atomic_write(target, b"a" * 2_000_000)
    code = textwrap.dedent(f"""
        import sys; sys.path.insert(0, {str(ROOT)!r})
        from tools.build.files import atomic_write
        i = 0
        while True:
            atomic_write({str(target)!r}, (b"ab"[i % 2:i % 2 + 1]) * 2_000_000)
            i += 1
    """)
    for delay in (0.05, 0.13, 0.21, 0.34, 0.55):
        p = subprocess.Popen([PY, "-c", code])
        time.sleep(delay)
        p.kill()
        p.wait()
        data = target.read_bytes()
        assert len(data) == 2_000_000 and data in (b"a" * 2_000_000, b"b" * 2_000_000), \
            f"killed after {delay} s: the file is {len(data)} bytes, mixed or truncated"
    leftovers = [p.name for p in tmp_path.iterdir() if p.name != "out.bin"]
    # at most the temp file of each killed write: hidden, ignored by git (*.tmp)
    assert len(leftovers) <= 5 and all(re.fullmatch(r"\.out\.bin\..+\.tmp", n) for n in leftovers), leftovers


def test_atomic_path_keeps_old_file_on_error(tmp_path):
    target = tmp_path / "f.txt"
    target.write_text("old")
    with pytest.raises(ZeroDivisionError):
        with files.atomic_path(target) as tmp:
            tmp.write_text("half")
            1 / 0
    assert target.read_text() == "old" and sorted(p.name for p in tmp_path.iterdir()) == ["f.txt"]


# ----------------------------------------------------------------------------- stamps
def test_damaged_outputs_are_rebuilt_and_a_failure_leaves_no_report(tmp_path, capsys):
    """A truncated report, a garbage stamp, a truncated executed notebook: never "up to date";
    then a failing notebook: a loud error and no report left that looks current."""
    import nbformat
    tree = build.Tree(quick_tree(tmp_path))
    nb = tmp_path / "notebooks" / "01_quick.ipynb"
    build.report(tree, html_only=True)
    good = tree.report_html.read_bytes()
    capsys.readouterr()
    build.report(tree, html_only=True)
    assert "up to date" in capsys.readouterr().out
    tree.report_html.write_bytes(good[: len(good) // 3])               # truncated report
    build.report(tree, html_only=True)
    assert "assembled" in capsys.readouterr().out
    assert tree.report_html.read_bytes() == good
    tree.report_stamp.write_text("garbage{")                           # garbage report stamp
    build.report(tree, html_only=True)
    assert "assembled" in capsys.readouterr().out
    out = tree.executed_notebook(nb)
    out.write_bytes(out.read_bytes()[:200])                            # truncated: not JSON any more
    tree.notebook_stamp(nb).write_text("\x00\x01 not a stamp")         # and a garbage notebook stamp
    build.report(tree, html_only=True)                                 # re-executed, no NotJSONError
    assert "01_quick.ipynb (" in capsys.readouterr().out
    assert nbformat.read(out, as_version=4).cells
    assert tree.report_html.exists() and tree.report_stamp.exists()

    write_nb(nb, ["x = 41", "def f(y):\n    raise ValueError(f'deliberate failure {y}')\nf(x + 1)"])
    with pytest.raises(build.BuildError) as ei:
        build.report(tree, html_only=True)
    msg = str(ei.value)
    assert "01_quick.ipynb" in msg                                     # which notebook
    assert "raise ValueError(f'deliberate failure {y}')" in msg        # the failing cell's source
    assert "ValueError: deliberate failure 42" in msg                  # the traceback
    assert "\x1b[" not in msg                                          # readable, no ANSI colours
    left = [p.name for p in (tree.report_html, tree.report_pdf, tree.report_stamp, tree.report_notebook,
                             tree.executed_notebook(nb), tree.notebook_stamp(nb)) if p.exists()]
    assert not left, f"a failed build left {left} behind"
    assert not [p for p in tree.executed.iterdir() if p.name.endswith(".tmp")]


def test_stamp_rejects_changed_outputs(tmp_path):
    a, b = tmp_path / "a", tmp_path / "b"
    a.write_text("1")
    b.write_text("2")
    s = Stamp(tmp_path / "s.stamp")
    s.write("k", [a, b])
    assert s.valid("k", [a, b]) and not s.valid("k2", [a, b]) and not s.valid("k", [a])
    b.unlink()
    assert not s.valid("k", [a, b])


def test_damaged_output_reexecutes_the_notebook_and_the_build_publishes(tmp_path):
    tree = build.Tree(tmp_path)
    nb = write_nb(tmp_path / "notebooks" / "01_fig.ipynb", [
        "import os, pathlib\np = pathlib.Path(os.environ['WMR_OUT']) / 'f.svg'\n"
        "p.parent.mkdir(parents=True, exist_ok=True)\np.write_text('<svg>complete</svg>')"])
    (tmp_path / "figures").mkdir()
    assert build.execute(tree, merge=False) == ["01_fig.ipynb"]
    assert not (tmp_path / "figures" / "f.svg").exists()               # the chapter writes under build/ only
    assert build.execute(tree, merge=False) == []
    (tree.chapter_out(nb) / "f.svg").write_text("<svg>tru")             # truncated by a crash
    assert build.execute(tree, merge=False) == ["01_fig.ipynb"]
    assert build.publish(tree, [nb]) == [tmp_path / "figures" / "f.svg"]
    assert (tmp_path / "figures" / "f.svg").read_text() == "<svg>complete</svg>"
    assert build.publish(tree, [nb]) == []                              # same bytes: nothing written


# ----------------------------------------------------------------------------- signals
pytestmark_linux = pytest.mark.skipif(not LINUX, reason="process checks read /proc (Linux)")


def _make(tree: Path, marker: str, target: str = "report", **env):
    return subprocess.Popen(["make", "--no-print-directory", "-C", str(ROOT), target],
                            env=env_with(marker, WMR_ROOT=str(tree), **env),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)


@pytestmark_linux
@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGKILL], ids=["SIGTERM", "SIGKILL"])
def test_killing_make_leaves_no_process(tmp_path, sig):
    marker = uuid.uuid4().hex
    tree = slow_tree(tmp_path)
    p = _make(tree, marker)
    assert wait_for(lambda: kernel_running(marker)), f"no kernel started:\n{p.stdout.read() if p.poll() is not None else ''}"
    os.kill(p.pid, sig)                                                # make itself, not its group
    p.wait(timeout=60)
    left = wait_for(lambda: not marked_processes(marker), timeout=20) or marked_processes(marker)
    assert left is True, f"processes left after {sig.name} to make: {left}"
    assert not list((tmp_path / "build" / "tmp").glob("*")) if (tmp_path / "build" / "tmp").exists() else True


@pytestmark_linux
def test_sigint_stops_a_background_build(tmp_path):
    """A background job of a non-interactive shell starts with SIGINT ignored; kill -INT still works."""
    marker = uuid.uuid4().hex
    tree = slow_tree(tmp_path)
    p = subprocess.Popen([PY, "-m", "tools.build", "--root", str(tree), "report"], cwd=ROOT,
                         env=env_with(marker), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_IGN))
    assert wait_for(lambda: kernel_running(marker))
    t0 = time.monotonic()
    os.kill(p.pid, signal.SIGINT)
    rc = p.wait(timeout=30)
    assert rc == 128 + signal.SIGINT, p.stdout.read()
    assert time.monotonic() - t0 < 15
    assert wait_for(lambda: not marked_processes(marker), timeout=10), marked_processes(marker)


@pytestmark_linux
def test_stop_during_pdf_export_removes_latex_dir(tmp_path):
    """The PDF's LaTeX directory is removed when the build is stopped while xelatex runs."""
    marker = uuid.uuid4().hex
    tree = quick_tree(tmp_path)
    fake = tmp_path / "bin"
    fake.mkdir()
    (fake / "xelatex").write_text("#!/bin/sh\nsleep 300\n")
    (fake / "xelatex").chmod(0o755)
    env = env_with(marker, PATH=f"{fake}{os.pathsep}{os.environ['PATH']}")
    p = subprocess.Popen([PY, "-m", "tools.build", "--root", str(tree), "report"], cwd=ROOT, env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
    assert wait_for(lambda: [q for q in marked_processes(marker) if "sleep 300" in q[1] or "xelatex" in q[1]])
    assert list((tmp_path / "build" / "tmp").iterdir()), "the LaTeX directory should exist while xelatex runs"
    os.kill(p.pid, signal.SIGTERM)
    assert p.wait(timeout=30) == 128 + signal.SIGTERM
    assert wait_for(lambda: not marked_processes(marker), timeout=10), marked_processes(marker)
    assert not list((tmp_path / "build" / "tmp").iterdir()), "LaTeX directory left behind"
    assert not tree.joinpath("build", "report.html").exists() or not tree.joinpath("build", "report.stamp").exists()


# ----------------------------------------------------------------------------- lock
def test_two_builds_of_one_tree_run_one_after_the_other(tmp_path):
    write_nb(tmp_path / "notebooks" / "01_a.ipynb", ["import time\ntime.sleep(1.5)"])
    cmd = [PY, "-m", "tools.build", "--root", str(tmp_path), "execute"]
    kw = dict(cwd=ROOT, env=dict(os.environ, PYTHONPATH=str(ROOT)), stdout=subprocess.PIPE,
              stderr=subprocess.STDOUT, text=True)
    first = subprocess.Popen(cmd, **kw)
    assert wait_for(lambda: (tmp_path / "build" / ".lock").exists() and
                    (tmp_path / "build" / ".lock").read_text().strip() == str(first.pid), timeout=30)
    second = subprocess.Popen(cmd, **kw)
    out1, out2 = first.communicate(timeout=120)[0], second.communicate(timeout=120)[0]
    assert first.returncode == 0 and second.returncode == 0, out1 + out2
    assert "waiting" in out2, out2
    runs = len(re.findall(r"^\[execute\] 01_a\.ipynb \(", out1 + out2, re.M))
    assert runs == 1, f"the notebook ran {runs} times:\n{out1}\n{out2}"


# ----------------------------------------------------------------------------- git status
def _git(tree: Path, *args):
    subprocess.run(["git", "-C", str(tree), *args], check=True, capture_output=True)


def test_make_test_fails_when_the_build_modifies_tracked_files(tmp_path):
    nb = tmp_path / "notebooks" / "01_w.ipynb"

    def writes(value):
        write_nb(nb, ["import os, pathlib\np = pathlib.Path(os.environ['WMR_OUT']) / 'data.txt'\n"
                      f"p.parent.mkdir(parents=True, exist_ok=True)\np.write_text({value})"])
    writes("'fixed'")
    (tmp_path / "figures").mkdir()
    (tmp_path / "figures" / "data.txt").write_text("fixed")
    (tmp_path / "tests").mkdir()
    (tmp_path / "tests" / "test_ok.py").write_text("def test_ok():\n    assert 1 + 1 == 2\n")
    (tmp_path / ".gitignore").write_text("build/\n__pycache__/\n.pytest_cache/\n")
    (tmp_path / "notes.txt").write_text("an edit of my own\n")
    _git(tmp_path, "init", "-q")
    _git(tmp_path, "add", "-A")
    _git(tmp_path, "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qm", "init")
    (tmp_path / "notes.txt").write_text("an uncommitted edit: not the build's doing\n")

    def make_test():
        p = subprocess.run([PY, "-m", "tools.build", "--root", str(tmp_path), "test", "--", "-q", "-p", "no:cacheprovider"],
                           cwd=ROOT, env=dict(os.environ, PYTHONPATH=str(ROOT), PYTEST_DISABLE_PLUGIN_AUTOLOAD="1"),
                           capture_output=True, text=True)
        return p.returncode, p.stdout + p.stderr
    rc, out = make_test()                         # the notebook rewrites the same bytes: clean
    assert rc == 0 and "left git status as it found it" in out, out
    writes("str(__import__('time').time_ns())")   # now it writes new bytes into a tracked file
    _git(tmp_path, "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qam", "nondeterministic")
    rc, out = make_test()
    assert rc == 2, out
    assert "figures/data.txt" in out and "notes.txt" not in out.split("FAILED", 1)[1]


def test_ci_runs_the_readme_test_command():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert re.search(r"^make test +#", readme, re.M) and re.search(r"^make report +#", readme, re.M)
    assert re.search(r"^make test$", (ROOT / ".ci" / "run").read_text(), re.M)
    assert re.search(r"^test:.*\n\t@\$\(BUILD\) test$", (ROOT / "Makefile").read_text(), re.M)


# ----------------------------------------------------------------------------- the tool itself
BUILD_MODULES = sorted(p.stem for p in (ROOT / "tools" / "build").glob("*.py") if p.stem != "__main__")


@pytest.mark.parametrize("name", BUILD_MODULES)
def test_build_modules_are_small_documented_and_doctested(name):
    import doctest
    import importlib
    mod = importlib.import_module(f"tools.build.{name}" if name != "__init__" else "tools.build")
    path = Path(mod.__file__)
    n = len(path.read_text().splitlines())
    assert n <= 400, f"{path.name} has {n} lines: split it (one responsibility per module)"
    assert (mod.__doc__ or "").strip(), f"{path.name} has no module docstring"
    assert name == "__init__" or hasattr(mod, "__all__") or name in ("worker",), f"{path.name} has no __all__"
    res = doctest.testmod(mod, optionflags=doctest.ELLIPSIS)
    assert res.failed == 0
