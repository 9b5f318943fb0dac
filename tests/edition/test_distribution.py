"""The tools of the release and the docs (tools/release/, tools/mathjax.py, tools/docs.py,
docs/_ext): their checks catch what they are for, without building anything or using the network.
(`make test` then runs them for real: `make release`, `make docs`.)"""

import doctest
import importlib
import io
import re
import sys
import tarfile

import pytest

import wmr
from tools import docs, mathjax
from tools.release import artifacts, venv
from tools.release import check as release

from conftest import ROOT

sys.path.insert(0, str(ROOT / "docs" / "_ext"))  # the Sphinx extensions, imported by name below

EXT = ("wmr_markdown", "wmr_aliases")


@pytest.mark.parametrize("module", [artifacts, venv, mathjax, docs, *EXT])
def test_examples_in_the_docstrings(module):
    mod = importlib.import_module(module) if isinstance(module, str) else module
    result = doctest.testmod(mod, optionflags=doctest.ELLIPSIS)
    assert result.attempted > 0 and result.failed == 0


# ------------------------------------------------------------------------------- the release check
def test_the_shipped_tests_need_nothing_of_the_repository():
    """What the release check refuses, checked here too (fast): a test in tests/ that imports the edition."""
    for f in sorted((ROOT / "tests").glob("*.py")):
        assert artifacts.repo_only_imports(f.read_text(encoding="utf-8")) == [], (
            f"{f.name} imports the edition or the build: move it to tests/edition/"
        )


def test_version_and_name_read_without_importing():
    assert release.version_of(ROOT) == (wmr.__version__, "wmr-kinematics")


def test_sdist_check_sees_what_is_missing_or_extra():
    tree = {
        *artifacts.SDIST_FILES,
        *(f"tests/{p.name}" for p in (ROOT / "tests").glob("*.py")),
        *(p.relative_to(ROOT).as_posix() for p in (ROOT / "examples").rglob("*") if p.is_file()),
    }
    assert artifacts.check_sdist(sorted(tree)) == []
    missing = artifacts.check_sdist(
        sorted(tree - {"tests/conftest.py", "examples/swerve4.toml", "examples/urdf/swerve.urdf", "LICENSE"})
    )
    assert missing == [
        "missing from the sdist: LICENSE",
        "missing from the sdist: tests/conftest.py",
        "missing from the sdist: examples/swerve4.toml",
        "missing from the sdist: examples/urdf/swerve.urdf",
    ]
    extra = artifacts.check_sdist(
        sorted(tree | {"tests/edition/test_x.py", "notebooks/01.ipynb", "tests/__pycache__/a.pyc"})
    )
    assert any("tests/edition/" in p for p in extra) and any("notebooks/" in p for p in extra)
    assert any("compiled files" in p for p in extra)


GOOD_METADATA = """Metadata-Version: 2.4
Name: wmr-kinematics
Version: 0.1.0
License-Expression: MIT
License-File: LICENSE
Requires-Dist: numpy>=1.26
Requires-Dist: sympy>=1.12
Requires-Dist: dask>=2024.1; extra == "dask"
"""
GOOD_NAMES = [
    "wmr/__init__.py",
    "wmr/py.typed",
    "wmr/_version.py",
    "wmr_kinematics-0.1.0.dist-info/METADATA",
    "wmr_kinematics-0.1.0.dist-info/licenses/LICENSE",
]
ENTRY = "[console_scripts]\nwmr = wmr.cli:main\n"


def test_wheel_check_accepts_a_good_wheel():
    assert artifacts.check_wheel(GOOD_NAMES, GOOD_METADATA, ENTRY, "0.1.0", "wmr-kinematics") == []


@pytest.mark.parametrize(
    "names, metadata, entry, words",
    [
        (GOOD_NAMES + ["edition/__init__.py"], GOOD_METADATA, ENTRY, "more than wmr/"),
        ([n for n in GOOD_NAMES if "py.typed" not in n], GOOD_METADATA, ENTRY, "wmr/py.typed"),
        ([n for n in GOOD_NAMES if "LICENSE" not in n], GOOD_METADATA, ENTRY, "licenses/LICENSE"),
        (GOOD_NAMES, GOOD_METADATA.replace("License-Expression: MIT\n", ""), ENTRY, "License-Expression"),
        (GOOD_NAMES, GOOD_METADATA + "License: MIT\n", ENTRY, "deprecated License field"),
        (GOOD_NAMES, GOOD_METADATA.replace("Name: wmr-kinematics", "Name: wmr"), ENTRY, "Name"),
        (GOOD_NAMES, GOOD_METADATA.replace("Version: 0.1.0", "Version: 0.2.0"), ENTRY, "Version"),
        (GOOD_NAMES, GOOD_METADATA + "Requires-Dist: pandas>=2\n", ENTRY, "pandas"),
        (GOOD_NAMES, GOOD_METADATA, "[console_scripts]\nwmr = wmr.cli:run\n", "console script"),
    ],
)
def test_wheel_check_sees_each_defect(names, metadata, entry, words):
    problems = artifacts.check_wheel(names, metadata, entry, "0.1.0", "wmr-kinematics")
    assert len(problems) == 1 and words in problems[0], problems


def test_constraints_keep_every_pin_of_the_lock():
    lock = (ROOT / "environment.lock").read_text(encoding="utf-8")
    pins = venv.constraints(lock).splitlines()
    assert len(pins) == len(re.findall(r"^[A-Za-z0-9_.\-]+==", lock, re.MULTILINE)) > 50
    assert any(p.startswith("numpy==") for p in pins) and not any("--hash" in p or "\\" in p for p in pins)


def test_the_readme_has_python_examples_for_the_release_to_run():
    blocks = venv.python_blocks((ROOT / "README.md").read_text(encoding="utf-8"))
    assert len(blocks) >= 2 and all("import wmr" in b for b in blocks)  # each one pastes on its own


def test_inputs_hash_follows_the_sdist_contents(tmp_path):
    for name in ("pyproject.toml", "README.md"):
        (tmp_path / name).write_text("a", encoding="utf-8")
    (tmp_path / "wmr").mkdir()
    (tmp_path / "wmr" / "x.py").write_text("x = 1", encoding="utf-8")
    h1 = release.inputs_hash(tmp_path)
    (tmp_path / "wmr" / "__pycache__").mkdir()
    (tmp_path / "wmr" / "__pycache__" / "x.pyc").write_bytes(b"\0")  # not an input
    assert release.inputs_hash(tmp_path) == h1
    (tmp_path / "tests" / "edition").mkdir(parents=True)
    (tmp_path / "tests" / "edition" / "test_x.py").write_text("", encoding="utf-8")  # not in the sdist
    assert release.inputs_hash(tmp_path) == h1
    (tmp_path / "wmr" / "x.py").write_text("x = 2", encoding="utf-8")
    assert release.inputs_hash(tmp_path) != h1


# ------------------------------------------------------------------------------------------ MathJax
def _tgz(files):
    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w:gz") as tar:
        for name, data in files.items():
            info = tarfile.TarInfo(name)
            info.size = len(data)
            tar.addfile(info, io.BytesIO(data))
    return buf.getvalue()


def test_a_tarball_that_is_not_the_release_is_refused(tmp_path, monkeypatch):
    fake = _tgz({"package/es5/tex-svg-full.js": b"alert('not mathjax')"})

    def pack(dest):  # what npm would have fetched
        out = dest / ".download"
        out.write_bytes(fake)
        return out

    monkeypatch.setattr(mathjax, "_npm_pack", pack)
    with pytest.raises(mathjax.MathJaxError, match="integrity mismatch"):
        mathjax.bundle("tex-svg-full.js", cache=tmp_path)
    assert not (tmp_path / f"mathjax-{mathjax.VERSION}.tgz").exists()  # never kept under its name
    assert not list(tmp_path.rglob("tex-svg-full.js"))


def test_the_pinned_release_is_extracted_and_kept_equal(tmp_path, monkeypatch):
    """With the integrity of a tarball pinned, its bundle is extracted, and a changed copy is replaced."""
    data = _tgz({"package/es5/tex-svg-full.js": b"MathJax = {};", "package/es5/a11y/x.js": b""})
    (tmp_path / f"mathjax-{mathjax.VERSION}.tgz").write_bytes(data)
    monkeypatch.setattr(
        mathjax,
        "INTEGRITY",
        "sha512-" + __import__("base64").b64encode(__import__("hashlib").sha512(data).digest()).decode(),
    )
    monkeypatch.setattr(mathjax, "_npm_pack", lambda dest: pytest.fail("fetched although the cache is good"))
    path = mathjax.bundle("tex-svg-full.js", cache=tmp_path)
    assert path.read_bytes() == b"MathJax = {};"
    path.write_bytes(b"changed")
    assert mathjax.bundle("tex-svg-full.js", cache=tmp_path).read_bytes() == b"MathJax = {};"
    with pytest.raises(mathjax.MathJaxError, match="not in mathjax"):
        mathjax.bundle("tex-mml-svg.js", cache=tmp_path)
    for bad in ("../x.js", "a/b.js", ".hidden"):
        with pytest.raises(mathjax.MathJaxError, match="expected a file name"):
            mathjax.bundle(bad, cache=tmp_path)


# ------------------------------------------------------------------------------------------ the docs
def test_every_guide_page_names_a_readme_section_that_exists():
    wmr_markdown = importlib.import_module("wmr_markdown")  # docs/_ext (on sys.path above)
    pages = sorted((ROOT / "docs").rglob("*.rst"))
    used = 0
    for page in pages:
        text = page.read_text(encoding="utf-8")
        for file, title in re.findall(r"^\.\. markdown:: (\S+)\n(?:   :section: (.+)\n)?", text, re.MULTILINE):
            md = (ROOT / file).read_text(encoding="utf-8")
            if title:
                assert wmr_markdown.section(md, title).strip(), (page.name, title)
            used += 1
    assert used >= 7


def _guide(tmp_path, readme):
    """Build a one-page guide from ``readme`` with the extension; return (exit status, log)."""
    import subprocess

    (tmp_path / "README.md").write_text(readme, encoding="utf-8")
    src = tmp_path / "src"
    src.mkdir()
    (src / "conf.py").write_text(
        f"import sys; sys.path.insert(0, {str(ROOT / 'docs' / '_ext')!r})\n"
        f"extensions = ['wmr_markdown']\nwmr_repository = {str(tmp_path)!r}\n",
        encoding="utf-8",
    )
    (src / "index.rst").write_text("Guide\n=====\n\n.. markdown:: README.md\n   :section: Use\n", encoding="utf-8")
    proc = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "-q", "-b", "html", str(src), str(tmp_path / "out")],
        capture_output=True,
        text=True,
        check=False,
    )
    return proc.returncode, proc.stdout + proc.stderr


README = """# Title

## Use

```console
$ wmr --version
{version}
```

```python
import wmr
print("two:", 1 + 1)   # {claim}
```

## Next
"""


def test_the_guide_proves_its_examples(tmp_path):
    from wmr.cli import _version

    code, log = _guide(tmp_path, README.format(version=_version(), claim="2"))
    assert code == 0, log
    page = (tmp_path / "out" / "index.html").read_text(encoding="utf-8")
    assert "two: 2" in page and "Next" not in page  # the output shown; one section only


def test_a_drifted_console_example_or_a_false_comment_fails_the_build(tmp_path):
    code, log = _guide(tmp_path, README.format(version="wmr 0.0.0 (somewhere)", claim="3"))
    assert code != 0
    assert "`wmr --version` prints something else than shown" in log and "+wmr " in log
    assert "the example's comment says it prints '3'" in log


def test_the_pages_may_load_nothing_from_the_network(tmp_path):
    (tmp_path / "_static").mkdir()
    (tmp_path / "_static" / "m.js").write_text("", encoding="utf-8")
    (tmp_path / "ok.html").write_text(
        '<script src="_static/m.js"></script><a href="ok.html#top">x</a>'
        '<a href="https://example.org/">an outside link is fine</a>',
        encoding="utf-8",
    )
    assert docs.check_pages(tmp_path) == []
    (tmp_path / "bad.html").write_text('<link rel="stylesheet" href="//cdn.example/x.css">', encoding="utf-8")
    assert docs.check_pages(tmp_path) == ["bad.html loads //cdn.example/x.css from the network"]
    (tmp_path / "bad.html").write_text(
        "<p><strong>``wmr-kinematics``</strong></p><pre>``ok in code``</pre>", encoding="utf-8"
    )
    (problem,) = docs.check_pages(tmp_path)
    assert problem.startswith("bad.html shows raw markup")
