"""Property-based fuzzing of the whole public API (issue 11, part 2).

For every public function of ``wmr`` (``wmr.__all__`` and the public functions of the modules of
``wmr.model`` and ``wmr.analysis``, listed in ``tests/fuzz_api.py``), Hypothesis draws arguments that
are valid, awkward-but-valid (extreme magnitudes, Fractions, empty batches) or bad (wrong kind,
wrong shape, NaN, infinity, SymPy ``oo``/``nan``/``zoo``/``I``, ``10**400``, ``np.longdouble('1e400')``,
``None`` robots, the class ``Robot``) and checks that

* the only exceptions are ``TypeError`` and ``ValueError``, and their messages name an argument;
* a bad argument is rejected (never silently accepted);
* a result from finite input is finite (except the documented infinities: a singular matrix's
  condition number, an instantaneous centre at infinity or of a platform at rest).

Deterministic (the ``wmr`` Hypothesis profile of ``conftest.py``: derandomized, no database).
"""

import inspect
import warnings

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import wmr
from wmr.errors import InputValueError

import fuzz_api as F

EXAMPLES = 8


def _draw(data, case):
    """Arguments for ``case``, drawn by Hypothesis (the same three kinds of value as fuzz_api.draw)."""
    pool = [F.ROBOTS[i] for i in case.robots] if case.robots else F.ROBOTS
    bot = data.draw(st.sampled_from(pool), label="robot")
    args, bad = {}, []
    for name, role in case.roles:
        good, odd, wrong = F.role_values(role, bot)
        if role == "robot":
            good = [bot]
        kinds = ["good"] + (["odd"] if odd else []) + (["bad"] if wrong else [])
        kind = data.draw(st.sampled_from(kinds), label=f"{name} kind")
        values = {"good": good, "odd": odd, "bad": wrong}[kind]
        args[name] = values[data.draw(st.integers(0, len(values) - 1), label=name)]
        if kind == "bad":
            bad.append(name)
    return args, bad


@pytest.mark.parametrize("case", F.CASES, ids=[c.name for c in F.CASES])
@settings(max_examples=EXAMPLES)
@given(data=st.data())
def test_public_function_under_fuzzing(case, data):
    args, bad = _draw(data, case)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # no overflow warning leaks out either
        what, detail = F.outcome(case, args, bad)
    assert what in ("returned", "rejected"), f"{what}: {case.name}({args}) {detail}"


def _public_functions():
    """Names of every public function and class of wmr, wmr.model.* and wmr.analysis.* (not the packages)."""
    import importlib
    import pkgutil

    names = {n for n in wmr.__all__ if inspect.isfunction(getattr(wmr, n)) or inspect.isclass(getattr(wmr, n))}
    for m in pkgutil.walk_packages(wmr.__path__, "wmr."):
        if not m.name.startswith(("wmr.model.", "wmr.analysis.")) or any(p.startswith("_") for p in m.name.split(".")):
            continue
        mod = importlib.import_module(m.name)
        for n in getattr(mod, "__all__", []):
            obj = getattr(mod, n)
            if (inspect.isfunction(obj) or inspect.isclass(obj)) and obj.__module__ == m.name:
                names.add(n)
    return names


def test_every_public_function_is_fuzzed_or_excused():
    """A new public function must get a fuzz case (or a stated reason in fuzz_api.NOT_FUZZED)."""
    covered = {c.name.split(".")[-1].split("(")[0] for c in F.CASES}
    covered |= {
        "Robot",
        "Solution",
        "Trajectory",
        "InstantCentre",
        "Concurrency",
        "Classification",
        "Meet",
        "NumericBackend",
        "SymbolicBackend",
        "Grid",
        "Sample",
        "Sweep",
    }  # result types, fuzzed via the calls
    covered |= {
        "real",
        "number",
        "positive",
        "nonnegative",
        "point",
        "finite_array",
        "symbolic_vector",  # the checks
        "symbolic_matrix",
        "robot",
        "numeric_robot",
        "batch_shape",
        "flag",
        "integer",
        "show",
    }
    missing = sorted(_public_functions() - covered - set(F.NOT_FUZZED))
    assert not missing, f"public functions without a fuzz case: {missing}"


def test_the_fuzzer_catches_faults(monkeypatch):
    """The classification is not vacuous: a NaN result, a stray exception and an accepted bad value are faults."""
    case = F.Case("f", lambda x: x, (("x", "angle"),))
    assert F.outcome(case, {"x": float("nan")}, [])[0] == "non-finite"
    assert F.outcome(case, {"x": 1.0}, ["x"])[0] == "accepted-bad"
    boom = F.Case("g", lambda x: [][1], (("x", "angle"),))
    assert F.outcome(boom, {"x": 1.0}, [])[0] == "wrong-exception"
    vague = F.Case("h", lambda x: (_ for _ in ()).throw(InputValueError("something is wrong")), (("x", "angle"),))
    assert F.outcome(vague, {"x": 1.0}, [])[0] == "unnamed"
    builtin = F.Case("k", lambda x: (_ for _ in ()).throw(ValueError(f"x = {x} is bad")), (("x", "angle"),))
    assert F.outcome(builtin, {"x": 1.0}, ["x"])[0] == "wrong-exception"  # not the package's own error
    monkeypatch.setattr(wmr.analysis.mobility, "rank_F", lambda robot, beta: float("nan"))
    mobility_case = F.CASES[[c.name for c in F.CASES].index("mobility")]
    assert F.outcome(mobility_case, {"robot": F.ROBOTS[0], "beta": [0.0] * 3}, [])[0] == "non-finite"
