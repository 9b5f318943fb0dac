"""The build cannot be broken (issue 11) and stays glue (issue 23): the Makefile runs the steps, each
step is one call of ``tools/build``; every fault below breaks a build that lacks the guard against it.

- outputs are written atomically (SIGKILL in the middle of a write leaves the old or the new file);
- a notebook's stamp records its key and the hashes of what it produced: a truncated executed
  notebook or a garbage stamp runs it again, never "up to date", never a ``NotJSONError``;
- a failing notebook: its name, cell and traceback, and no report left that looks current;
- stopping a build (SIGTERM or SIGKILL to make, SIGINT to a background build, a stop during the PDF
  export) leaves no process and no temporary directory behind;
- two builds of one tree at once: the second waits and then finds nothing to do;
- ``make test`` fails when a build modifies tracked files.

Each test builds a small tree of its own (``make -C <repository> WMR_ROOT=<tree>``): notebooks of a
line or two, Markdown only where no kernel is needed.
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

import nbformat
import pytest

from edition.files import atomic_path, atomic_write
from tools.build import execute as X

ROOT = Path(__file__).resolve().parents[2]

PY = sys.executable
LINUX = sys.platform.startswith("linux")
linux_only = pytest.mark.skipif(not LINUX, reason="process checks read /proc (Linux)")


# ----------------------------------------------------------------------------- trees
def write_nb(
    path: Path, code: tuple[str, ...] | list[str] = (), markdown: str | None = None, tags: tuple[str, ...] = ()
) -> Path:
    nb = nbformat.v4.new_notebook()
    if markdown:
        nb.cells.append(nbformat.v4.new_markdown_cell(markdown, metadata={"tags": list(tags)} if tags else {}))
    nb.cells += [nbformat.v4.new_code_cell(s) for s in code]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    path.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, path)
    return path


def tree(tmp_path: Path, *chapters: tuple[str, list[str]]) -> Path:
    """A project with the given chapters (name, code cells) and a findings chapter of Markdown only."""
    nb = tmp_path / "notebooks"
    write_nb(nb / "findings.ipynb", markdown="# A tiny edition\n\n*of nothing*", tags=("title",))
    for name, code in chapters:
        write_nb(nb / name, code, markdown=f"# {name}\n\nSome prose with $x^2$.")
    (tmp_path / "figures").mkdir(exist_ok=True)
    return tmp_path


def make(root: Path, *targets: str, marker: str = "", **kw) -> subprocess.Popen:
    env = dict(os.environ, WMR_TEST_MARKER=marker, **kw.pop("env", {}))
    env.pop("WMR_BUILD", None)
    return subprocess.Popen(
        ["make", "--no-print-directory", "-C", str(ROOT), f"WMR_ROOT={root}", *targets],
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        **kw,
    )


def run_make(root: Path, *targets: str, **kw) -> tuple[int, str]:
    p = make(root, *targets, **kw)
    out = p.communicate(timeout=600)[0]
    return p.returncode, out


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
        if stat.rsplit(")", 1)[-1].split()[0] != "Z" and f"WMR_TEST_MARKER={marker}".encode() in env:
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


def kernel_running(marker):
    return [p for p in marked_processes(marker) if "ipykernel" in p[1]]


# ----------------------------------------------------------------------------- atomic writes
def test_atomic_write_survives_sigkill(tmp_path):
    """A writer killed at random moments: the file is always complete, old or new."""
    target = tmp_path / "out.bin"
    atomic_write(target, b"a" * 2_000_000)
    code = textwrap.dedent(f"""
        from edition.files import atomic_write
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
        assert len(data) == 2_000_000 and data in (b"a" * 2_000_000, b"b" * 2_000_000), (
            f"killed after {delay} s: the file is {len(data)} bytes, mixed or truncated"
        )
    leftovers = [p.name for p in tmp_path.iterdir() if p.name != "out.bin"]
    # at most the temp file of each killed write: hidden, ignored by git (*.tmp)
    assert len(leftovers) <= 5 and all(re.fullmatch(r"\.out\.bin\..+\.tmp", n) for n in leftovers), leftovers


def test_atomic_path_keeps_old_file_on_error(tmp_path):
    target = tmp_path / "f.txt"
    target.write_text("old")
    with pytest.raises(RuntimeError), atomic_path(target) as tmp:
        tmp.write_text("half")
        raise RuntimeError("the writer fails half-way")
    assert target.read_text() == "old" and sorted(p.name for p in tmp_path.iterdir()) == ["f.txt"]


# ----------------------------------------------------------------------------- the cache
def test_stamp_records_the_key_and_every_output(tmp_path):
    out = tmp_path / "build" / "notebooks" / "01_a.ipynb"
    chapter = tmp_path / "build" / "out" / "01_a"
    chapter.mkdir(parents=True)
    out.parent.mkdir(parents=True)
    out.write_text("{}")
    (chapter / "f.svg").write_text("<svg/>")
    stamp = out.with_suffix(".stamp")
    stamp.write_text(
        f'{{"key": "k", "outputs": {{"notebooks/01_a.ipynb": "{X._sha(out)}", '
        f'"out/01_a/f.svg": "{X._sha(chapter / "f.svg")}"}}}}'
    )
    assert X.up_to_date(stamp, "k", out) and not X.up_to_date(stamp, "k2", out)
    (chapter / "g.svg").write_text("<svg/>")  # a file it did not write
    assert not X.up_to_date(stamp, "k", out)
    (chapter / "g.svg").unlink()
    (chapter / "f.svg").write_text("<sv")  # truncated
    assert not X.up_to_date(stamp, "k", out)
    (chapter / "f.svg").unlink()  # deleted
    assert not X.up_to_date(stamp, "k", out)
    stamp.write_text("garbage{")
    assert not X.up_to_date(stamp, "k", out)


def test_cache_reexecutes_only_what_changed_and_the_build_publishes(tmp_path):
    """Content hashes, not timestamps: a new mtime runs nothing, an edit runs that notebook, a change
    in wmr/ runs every one; a damaged output runs it again; the chapter writes under build/ only,
    and publishing copies into figures/ only the bytes that changed."""
    nb = tmp_path / "notebooks"
    a = write_nb(
        nb / "01_a.ipynb",
        [
            "import os\nos.getcwd()",
            "import sys\nsys.executable",
            (
                "import pathlib\np = pathlib.Path(os.environ['WMR_OUT']) / 'f.svg'\n"
                "p.parent.mkdir(parents=True, exist_ok=True)\n"
                "p.write_text('<svg>complete</svg>')\nstr(p)"
            ),
        ],
    )
    b = write_nb(nb / "02_b.ipynb", markdown="Markdown only: executed without a kernel.")
    out = {n: tmp_path / "build" / "notebooks" / n.name for n in (a, b)}

    def run(n):
        return X.execute(n, out[n], root=tmp_path)

    (tmp_path / "figures").mkdir()
    assert run(a) and run(b)
    cells = nbformat.read(out[a], as_version=4).cells
    assert cells[0].outputs[0]["data"]["text/plain"].strip("'\"") == str(nb)  # its own folder
    assert Path(cells[1].outputs[0]["data"]["text/plain"].strip("'\"")).parent == Path(sys.executable).parent
    svg = tmp_path / "build" / "out" / "01_a" / "f.svg"
    assert cells[2].outputs[0]["data"]["text/plain"].strip("'\"") == str(svg)  # WMR_OUT
    assert not (tmp_path / "figures" / "f.svg").exists()
    assert not run(a) and not run(b)  # nothing changed: nothing runs
    os.utime(b)
    assert not run(b)  # a new mtime, same bytes
    write_nb(b, markdown="Edited.")
    assert not run(a) and run(b)
    svg.write_text("<svg>tru")  # truncated by a crash
    assert run(a) and svg.read_text() == "<svg>complete</svg>"
    out[a].write_bytes(out[a].read_bytes()[:200])  # not JSON any more
    out[a].with_suffix(".stamp").write_text("\x00\x01 not a stamp")
    assert run(a) and nbformat.read(out[a], as_version=4).cells
    (tmp_path / "wmr").mkdir()
    (tmp_path / "wmr" / "__init__.py").write_text("# package changed\n")
    assert not X.up_to_date(out[a].with_suffix(".stamp"), X.key(a, tmp_path), out[a])  # wmr/ changed: every one
    assert run(b)
    executed = list(out.values())
    assert X.publish(tmp_path / "figures", executed) == [tmp_path / "figures" / "f.svg"]
    assert (tmp_path / "figures" / "f.svg").read_text() == "<svg>complete</svg>"
    assert X.publish(tmp_path / "figures", executed) == []  # same bytes: nothing written


def test_a_failing_notebook_says_where_and_leaves_no_report(tmp_path):
    """The tree builds (up to the report notebook; the HTML and PDF exports are tested on their own, so two files stand
    in for them here), then a chapter fails: no report file is left that would look current."""
    root = tree(tmp_path, ("01_quick.ipynb", []))
    rc, log = run_make(root, f"{root}/build/report.ipynb")
    build = root / "build"
    assert rc == 0 and (build / "report.ipynb").exists(), log
    for ext in ("html", "pdf"):
        (build / f"report.{ext}").write_text("a report of the tree before the failing edit")
    write_nb(
        root / "notebooks" / "01_quick.ipynb",
        ["x = 41", "def f(y):\n    raise ValueError(f'deliberate failure {y}')\nf(x + 1)"],
    )
    rc, log = run_make(root, f"{root}/build/report.html")
    assert rc != 0
    assert "01_quick.ipynb" in log  # which notebook
    assert "raise ValueError(f'deliberate failure {y}')" in log  # the failing cell's source
    assert "ValueError: deliberate failure 42" in log  # the traceback
    assert "\x1b[" not in log.split("BUILD FAILED", 1)[1]  # readable, no ANSI colours
    left = [
        p.name
        for p in (
            build / "report.html",
            build / "report.pdf",
            build / "report.ipynb",
            build / "notebooks" / "01_quick.ipynb",
            build / "notebooks" / "01_quick.stamp",
        )
        if p.exists()
    ]
    assert not left, f"a failed build left {left} behind"


# ----------------------------------------------------------------------------- signals
@linux_only
@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGKILL], ids=["SIGTERM", "SIGKILL"])
def test_killing_make_leaves_no_process(tmp_path, sig):
    marker = uuid.uuid4().hex
    root = tree(tmp_path, ("01_slow.ipynb", ["import time\ntime.sleep(120)"]))
    p = make(root, "report", marker=marker, start_new_session=True)
    assert wait_for(lambda: kernel_running(marker)), "no kernel started"
    os.kill(p.pid, sig)  # make itself, not its group
    p.wait(timeout=60)
    left = wait_for(lambda: not marked_processes(marker), timeout=20) or marked_processes(marker)
    assert left is True, f"processes left after {sig.name} to make: {left}"


@linux_only
def test_sigint_stops_a_background_build(tmp_path):
    """A background job of a non-interactive shell starts with SIGINT ignored (make keeps ignoring
    it); ``kill -INT`` to the job still stops the step that runs, and with it the build."""
    marker = uuid.uuid4().hex
    root = tree(tmp_path, ("01_slow.ipynb", ["import time\ntime.sleep(120)"]))
    p = make(
        root,
        "report",
        marker=marker,
        start_new_session=True,
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_IGN),
    )
    assert wait_for(lambda: kernel_running(marker))
    t0 = time.monotonic()
    os.killpg(p.pid, signal.SIGINT)
    assert p.wait(timeout=30) != 0, p.stdout.read() if p.stdout else ""
    assert time.monotonic() - t0 < 15
    assert wait_for(lambda: not marked_processes(marker), timeout=10), marked_processes(marker)


@linux_only
def test_stop_during_pdf_export_removes_latex_dir(tmp_path):
    """The PDF's LaTeX directory is removed when the build is stopped while xelatex runs."""
    marker = uuid.uuid4().hex
    root = tree(tmp_path, ("01_quick.ipynb", []))
    fake = tmp_path / "bin"
    fake.mkdir()
    (fake / "xelatex").write_text("#!/bin/sh\nexec sleep 300\n")  # one process, as xelatex is
    (fake / "xelatex").chmod(0o755)
    p = make(
        root,
        f"{root}/build/report.pdf",
        marker=marker,
        start_new_session=True,
        env={"PATH": f"{fake}{os.pathsep}{os.environ['PATH']}"},
    )
    latex = root / "build" / "tmp" / "pdf"
    assert wait_for(lambda: [q for q in marked_processes(marker) if "sleep 300" in q[1]])
    assert list(latex.iterdir()), "the LaTeX directory should exist while xelatex runs"
    os.kill(p.pid, signal.SIGTERM)
    p.wait(timeout=30)
    assert wait_for(lambda: not marked_processes(marker), timeout=10), marked_processes(marker)
    assert not list(latex.iterdir()), "LaTeX directory left behind"
    assert not (root / "build" / "report.pdf").exists()


# ----------------------------------------------------------------------------- lock
def test_two_builds_of_one_tree_run_one_after_the_other(tmp_path):
    root = tree(tmp_path, ("01_a.ipynb", ["import time\ntime.sleep(1.5)"]))
    marker = uuid.uuid4().hex
    first = make(root, "notebooks", marker=marker)
    assert wait_for(lambda: any("tools.build execute" in c for _, c in marked_processes(marker)), timeout=30)
    second = make(root, "notebooks")
    out1, out2 = first.communicate(timeout=120)[0], second.communicate(timeout=120)[0]
    assert first.returncode == 0 and second.returncode == 0, out1 + out2
    assert "waiting" in out2, out2
    runs = len(re.findall(r"^\[execute\] 01_a\.ipynb \(", out1 + out2, re.MULTILINE))
    assert runs == 1, f"the notebook ran {runs} times:\n{out1}\n{out2}"


# ----------------------------------------------------------------------------- git status
def _git(root: Path, *args):
    subprocess.run(
        ["git", "-C", str(root), "-c", "user.name=t", "-c", "user.email=t@t", *args], check=True, capture_output=True
    )


def test_make_test_fails_when_the_build_modifies_tracked_files(tmp_path):
    """The guard of ``make test`` around everything it runs: here a test of the tree that rewrites a
    tracked file, first with the same bytes (clean), then with new ones (the guard names that file,
    and not an uncommitted edit that was there before). No report, student edition or lint here:
    the guard does not depend on what is built."""
    root = tree(tmp_path)
    (root / "figures" / "data.txt").write_text("fixed")
    (root / "tests").mkdir()
    writes = (
        "import pathlib\n\ndef test_writes():\n"
        "    (pathlib.Path(__file__).parents[1] / 'figures' / 'data.txt').write_text(%s)\n"
    )
    (root / "tests" / "test_w.py").write_text(writes % "'fixed'")
    (root / ".gitignore").write_text("build/\n__pycache__/\n.pytest_cache/\n")
    (root / "notes.txt").write_text("an edit of my own\n")
    _git(root, "init", "-q")
    _git(root, "add", "-A")
    _git(root, "commit", "-qm", "init")
    (root / "notes.txt").write_text("an uncommitted edit: not the build's doing\n")
    args = (
        "test",
        f"TEST_BUILD={root}/build/notebooks/findings.ipynb",
        "LINTED=",
        "PYTEST_ARGS=-q -p no:cacheprovider -n 0",
    )
    rc, out = run_make(root, *args)
    assert rc == 0 and "left git status as it found it" in out, out
    (root / "tests" / "test_w.py").write_text(writes % "str(__import__('time').time_ns())")
    _git(root, "commit", "-qam", "nondeterministic")
    rc, out = run_make(root, *args)
    assert rc != 0, out
    failed = out.split("[git] FAILED", 1)[1]
    assert "figures/data.txt" in failed and "notes.txt" not in failed


def test_ci_runs_the_readme_test_command():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert re.search(r"^make test +#", readme, re.MULTILINE) and re.search(r"^make report +#", readme, re.MULTILINE)
    ci = (ROOT / ".ci" / "run").read_text()
    assert re.search(r"^make test$", ci, re.MULTILINE) and "git status --porcelain" in ci
    assert re.search(r"^test: ", (ROOT / "Makefile").read_text(), re.MULTILINE)


# ----------------------------------------------------------------------------- the tool itself
BUILD_MODULES = sorted(p.stem for p in (ROOT / "tools" / "build").glob("*.py") if p.stem != "__main__")


def test_the_build_is_glue():
    """``tools/build`` hands the work to Make, nbclient, nbconvert, pandoc and xelatex: under 1,000 lines."""
    n = sum(len(p.read_text().splitlines()) for p in (ROOT / "tools" / "build").glob("*.py"))
    assert n <= 1000, f"tools/build has {n} lines"


@pytest.mark.parametrize("name", BUILD_MODULES)
def test_build_modules_are_small_documented_and_doctested(name):
    import doctest
    import importlib

    mod = importlib.import_module(f"tools.build.{name}" if name != "__init__" else "tools.build")
    path = Path(str(mod.__file__))
    n = len(path.read_text().splitlines())
    assert n <= 400, f"{path.name} has {n} lines: split it (one responsibility per module)"
    assert (mod.__doc__ or "").strip(), f"{path.name} has no module docstring"
    assert name == "__init__" or hasattr(mod, "__all__"), f"{path.name} has no __all__"
    assert doctest.testmod(mod, optionflags=doctest.ELLIPSIS).failed == 0
