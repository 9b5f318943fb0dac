"""What ``import wmr`` pulls in: the core needs NumPy and SymPy only (matplotlib belongs to the plots,
the optional extra ``wmr-kinematics[plot]``; IPython to the edition, the extra ``edition``)."""

import subprocess
import sys

import pytest

from conftest import ROOT

HEAVY = ("matplotlib", "pandas", "IPython")


def _imported_after(statement):
    code = (
        f"import sys; {statement}; print(' '.join(sorted({{m.split('.')[0] for m in sys.modules}} & {set(HEAVY)!r})))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return out.stdout.split()


@pytest.mark.parametrize(
    "statement",
    [
        "import wmr",
        "import wmr.model, wmr.analysis",
        "import wmr; wmr.paper_robot(); wmr.mobility(wmr.paper_robot(), [0.0] * 3)",
    ],
)
def test_core_import_does_not_import_the_edition_libraries(statement):
    assert _imported_after(statement) == []


def test_the_check_sees_a_heavy_import():
    """The test above can fail: importing the plots does import matplotlib."""
    assert "matplotlib" in _imported_after("import wmr.plot.robot")


def test_dependencies_declared():
    """pyproject: numpy and sympy at run time; matplotlib in the extra ``plot``, IPython in ``edition``."""
    import tomllib
    from pathlib import Path

    meta = tomllib.loads((Path(__file__).parent.parent / "pyproject.toml").read_text())["project"]

    def names(reqs):
        return {d.split(">")[0].split("=")[0].split("<")[0].split("[")[0].strip().lower() for d in reqs}

    extras = meta["optional-dependencies"]
    assert names(meta["dependencies"]) == {"numpy", "sympy"}
    assert "matplotlib" in names(extras["plot"]) and "ipython" in names(extras["edition"])


@pytest.mark.parametrize(
    "statement",
    [
        "import wmr",
        "import wmr.cli.analyze, wmr.sim, wmr.io",
        "from wmr.cli import main; main(['analyze', 'examples/swerve4.toml', '--json'])",
        "import wmr; b = wmr.load('examples/mecanum4.toml'); wmr.inverse(b, [0.0] * 4, [0.0, 1.0, 0.0])",
    ],
)
def test_numeric_work_does_not_import_sympy(statement):
    """SymPy (0.2 s to import) comes in with the first symbolic value, not before (wmr.model.lazysympy)."""
    quiet = "import sys, contextlib, io\nwith contextlib.redirect_stdout(io.StringIO()):\n    "
    code = f"{quiet}{statement}\nprint('sympy' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    assert out.stdout.split()[-1] == "False", out.stdout


def test_the_sympy_check_sees_a_symbolic_use():
    """The test above can fail: an exact robot does import SymPy."""
    code = "import sys, wmr; wmr.paper_robot(exact=True); print('sympy' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split()[-1] == "True"
