"""The package's metadata: one version, one distribution name, the licence, the changelog, ``wmr --version``.

These read the files of the source tree (pyproject.toml, CHANGELOG.md, CITATION.cff, LICENSE), which the
sdist carries too; what the installed wheel says about itself is checked by tools/release/.
"""

import re
import sys
import tomllib
from pathlib import Path

import pytest

import wmr
from wmr import _version
from wmr.cli import main

ROOT = Path(__file__).resolve().parent.parent
META = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))


def test_distribution_name_is_written_once_in_code():
    """pyproject's ``name`` (which cannot be dynamic) is the name the code uses in its hints."""
    assert META["project"]["name"] == _version.DISTRIBUTION == "wmr-kinematics"


def test_version_has_one_source():
    assert "version" not in META["project"] and "version" in META["project"]["dynamic"]
    assert META["tool"]["setuptools"]["dynamic"]["version"] == {"attr": "wmr._version.__version__"}
    assert wmr.__version__ is _version.__version__
    assert re.fullmatch(r"\d+\.\d+\.\d+((a|b|rc)\d+)?(\.post\d+)?(\.dev\d+)?", wmr.__version__)


def test_the_newest_changelog_entry_is_this_version():
    heads = re.findall(r"^## (\S+)", (ROOT / "CHANGELOG.md").read_text(encoding="utf-8"), flags=re.MULTILINE)
    assert heads and heads[0] == wmr.__version__, heads


def test_licence_is_mit_everywhere():
    assert META["project"]["license"] == "MIT" and META["project"]["license-files"] == ["LICENSE"]
    text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("MIT License") and "the wmr-kinematics contributors" in text
    cff = (ROOT / "CITATION.cff").read_text(encoding="utf-8")
    assert re.search(r"^license: MIT$", cff, flags=re.MULTILINE) and "wmr-kinematics" in cff


def test_build_requirement_is_capped():
    (req,) = META["build-system"]["requires"]
    assert re.fullmatch(r"setuptools>=(\d+),<(\d+)", req)
    low, high = map(int, re.findall(r"\d+", req))
    assert low >= 77 and high > low  # SPDX license + license-files need setuptools >= 77


def test_package_is_typed():
    assert (Path(wmr.__file__).parent / "py.typed").is_file()


def test_version_option(capsys):
    with pytest.raises(SystemExit) as exit_:
        main(["--version"])
    assert exit_.value.code == 0
    out = capsys.readouterr().out
    assert out.startswith(f"wmr {wmr.__version__} ({_version.DISTRIBUTION}, ")
    assert str(Path(wmr.__file__).parent) in out  # which copy of wmr answers


def test_missing_extra_hint_names_this_distribution(capsys, monkeypatch):
    """Without dask, ``wmr sweep --dask`` says which extra to install, of this distribution (not 'wmr')."""
    monkeypatch.setitem(sys.modules, "dask.distributed", None)  # import fails as if not installed
    code = main(["sweep", str(ROOT / "examples" / "paper_centred.toml"), "rank_F", "--grid", "2", "--dask", "local:1"])
    err = capsys.readouterr().err
    assert code == 2 and f"pip install '{_version.DISTRIBUTION}[dask]'" in err, err
