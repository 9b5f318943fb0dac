"""What ``import wmr`` pulls in: the core needs NumPy and SymPy only (matplotlib belongs to the plots,
the optional extra ``wmr-kinematics[plot]``; IPython to the edition, the extra ``edition``)."""

import subprocess
import sys

import pytest

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
