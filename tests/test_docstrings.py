"""Docstrings: numpydoc for everything public, every parameter documented, doctests pass.

Modelled on python-control's ``docstrings_test.py``: the signature is the truth, the
``Parameters`` section must list every argument (and nothing that is not one).
"""
import dataclasses
import doctest
import importlib
import inspect
import re

import pytest

import wmr

CORE_MODULES = ["wmr", "wmr.model.backend", "wmr.model.conventions", "wmr.model.platform", "wmr.model.wheels", "wmr.model.robot",
                "wmr.model.robots", "wmr.analysis.linalg", "wmr.analysis.mobility", "wmr.analysis.isotropy", "wmr.analysis.kinematics", "wmr.analysis.steering",
                "wmr.analysis.simulation", "wmr.model.tolerance", "wmr.paper.ledger", "wmr.paper.verify", "wmr.paper.symbols",
                "wmr.analysis._batch", "wmr.analysis.sweep", "wmr.analysis.reference", "wmr.analysis._closed",
                "wmr.cli.sweep", "wmr.model.trig"]


def _public_callables():
    out = []
    for name in wmr.__all__:
        obj = getattr(wmr, name)
        if inspect.isfunction(obj) or inspect.isclass(obj):
            out.append((name, obj))
            if inspect.isclass(obj):
                for mname, member in inspect.getmembers(obj):
                    if mname.startswith("_") or getattr(member, "__module__", "").split(".")[0] != "wmr":
                        continue
                    if inspect.isfunction(member):
                        out.append((f"{name}.{mname}", member))
    return out


def _module_callables():
    """Public functions and classes (and their public methods) defined in the public core modules."""
    out = []
    for module in CORE_MODULES:
        if module.split(".")[-1].startswith("_"):
            continue
        mod = importlib.import_module(module)
        for name, obj in vars(mod).items():
            if name.startswith("_") or getattr(obj, "__module__", None) != module:
                continue
            if inspect.isfunction(obj):
                out.append((f"{module}.{name}", obj))
            elif inspect.isclass(obj) and "Backend" not in name:
                out.append((f"{module}.{name}", obj))
                out += [(f"{module}.{name}.{k}", v) for k, v in vars(obj).items()
                        if inspect.isfunction(v) and not k.startswith("_")]
    return out


PUBLIC = _public_callables()
MODULE_LEVEL = [(n, o) for n, o in _module_callables() if all(o is not p for _, p in PUBLIC)]
PROPERTIES = [(f"{n}.{m}", p) for n, c in PUBLIC if inspect.isclass(c)
              for m, p in inspect.getmembers(c, lambda x: isinstance(x, property)) if not m.startswith("_")]


def sections(doc):
    """numpydoc sections: {title: [lines]} (a title is a line followed by a line of dashes)."""
    lines = inspect.cleandoc(doc).splitlines()
    out, current = {"_summary": []}, "_summary"
    i = 0
    while i < len(lines):
        if i + 1 < len(lines) and lines[i].strip() and re.fullmatch(r"-{3,}", lines[i + 1].strip()):
            current = lines[i].strip()
            out[current] = []
            i += 2
            continue
        out[current].append(lines[i])
        i += 1
    return out


def documented_parameters(doc):
    names = []
    for title in ("Parameters", "Other Parameters"):
        for line in sections(doc).get(title, []):
            if line and not line.startswith(" "):
                head = line.split(" : ")[0].strip()
                names += [n.strip().lstrip("*") for n in head.split(",") if n.strip()]
    return names


def signature_parameters(obj):
    try:
        sig = inspect.signature(obj)
    except (TypeError, ValueError):
        return []
    return [p.name for p in sig.parameters.values()
            if p.name not in ("self", "cls") and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]


@pytest.mark.parametrize("name, obj", PUBLIC, ids=[n for n, _ in PUBLIC])
def test_numpydoc_docstring(name, obj):
    doc = inspect.getdoc(obj)
    assert doc and doc.strip(), f"{name} has no docstring"
    summary = sections(doc)["_summary"]
    assert summary and summary[0].strip(), f"{name}: the docstring must start with a summary line"
    params = signature_parameters(obj)
    documented = documented_parameters(doc)
    missing = [p for p in params if p not in documented]
    assert not missing, f"{name}: parameters not documented in 'Parameters': {missing}"
    extra = [p for p in documented if p not in params]
    assert not extra, f"{name}: 'Parameters' documents arguments that do not exist: {extra}"
    if inspect.isfunction(obj):
        secs = sections(doc)
        assert "Returns" in secs or "Yields" in secs, f"{name}: no 'Returns' section"


@pytest.mark.parametrize("name, obj", MODULE_LEVEL, ids=[n for n, _ in MODULE_LEVEL])
def test_module_level_docstrings(name, obj):
    """The rest of the core's public API: documented too (dataclass fields under Attributes)."""
    doc = inspect.getdoc(obj)
    assert doc and doc.strip(), f"{name} has no docstring"
    params = signature_parameters(obj)
    documented = documented_parameters(doc)
    if dataclasses.is_dataclass(obj):
        documented += [line.split(" : ")[0].strip() for line in sections(doc).get("Attributes", [])
                       if line and not line.startswith(" ")]
    missing = [p for p in params if p not in documented]
    assert not missing, f"{name}: parameters not documented: {missing}"
    if inspect.isfunction(obj):
        assert "Returns" in sections(doc), f"{name}: no 'Returns' section"


@pytest.mark.parametrize("name, prop", PROPERTIES, ids=[n for n, _ in PROPERTIES])
def test_properties_documented(name, prop):
    assert prop.__doc__ and prop.__doc__.strip(), f"{name} has no docstring"


def test_all_is_complete_and_importable():
    for name in wmr.__all__:
        assert hasattr(wmr, name), name
    assert len(set(wmr.__all__)) == len(wmr.__all__)


def test_parser_catches_an_undocumented_parameter():
    def f(a, b=1):
        """Summary.

        Parameters
        ----------
        a : int

        Returns
        -------
        int
        """
    assert documented_parameters(inspect.getdoc(f)) == ["a"]
    assert "b" not in documented_parameters(inspect.getdoc(f))


@pytest.mark.parametrize("module", CORE_MODULES)
def test_doctests(module):
    mod = importlib.import_module(module)
    result = doctest.testmod(mod, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE, verbose=False)
    assert result.failed == 0, f"{result.failed} doctest(s) failed in {module}"


def test_core_modules_have_examples():
    """Worked examples (which double as doctests) exist across the core."""
    n = 0
    for module in CORE_MODULES:
        n += doctest.testmod(importlib.import_module(module), optionflags=doctest.ELLIPSIS).attempted
    assert n >= 30
