"""Docstrings: numpydoc for everything public, every parameter documented, doctests pass.

Modelled on python-control's ``docstrings_test.py``: the signature is the truth, the
``Parameters`` section must list every argument (and nothing that is not one).
"""

import dataclasses
import doctest
import enum
import importlib
import inspect
import pkgutil
import re
from pathlib import Path

import pytest

import wmr


def _walk():
    """Every module of the package (walked, not listed by hand), except the ``__main__`` scripts."""
    names = ["wmr"] + [m.name for m in pkgutil.walk_packages(wmr.__path__, "wmr.")]
    return sorted(n for n in names if not n.endswith(".__main__"))


ALL_MODULES = _walk()
#: modules whose names have no private part: their public functions and classes are checked as numpydoc
PUBLIC_MODULES = [m for m in ALL_MODULES if not any(part.startswith("_") for part in m.split("."))]


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
    """Public functions and classes (and their public methods) defined in the public modules.

    A module's public names are those its ``__all__`` lists (PEP 8); a package's ``__all__`` names its
    modules.  The other names of a module are its implementation, called by wmr's own modules with values
    already checked: :func:`test_internal_names_say_what_they_are` asks them for a summary line only.
    """
    out: list = []
    for module in PUBLIC_MODULES:
        mod = importlib.import_module(module)
        for name in getattr(mod, "__all__", ()):
            obj = getattr(mod, name, None)
            if getattr(obj, "__module__", None) != module:
                continue
            if inspect.isfunction(obj):
                out.append((f"{module}.{name}", obj))
            elif inspect.isclass(obj) and "Backend" not in name:
                out.append((f"{module}.{name}", obj))
                out += [
                    (f"{module}.{name}.{k}", v)
                    for k, v in vars(obj).items()
                    if inspect.isfunction(v) and not k.startswith("_")
                ]
    return out


PUBLIC = _public_callables()
MODULE_LEVEL = [(n, o) for n, o in _module_callables() if all(o is not p for _, p in PUBLIC)]
PROPERTIES = [
    (f"{n}.{m}", p)
    for n, c in PUBLIC
    if inspect.isclass(c)
    for m, p in inspect.getmembers(c, lambda x: isinstance(x, property))
    if not m.startswith("_")
]


def sections(doc):
    """numpydoc sections: {title: [lines]} (a title is a line followed by a line of dashes)."""
    lines = inspect.cleandoc(doc).splitlines()
    out: dict[str, list] = {"_summary": []}
    current = "_summary"
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
    return [
        p.name
        for p in sig.parameters.values()
        if p.name not in ("self", "cls") and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)
    ]


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


def numpydoc_problems(name, obj):
    """What is missing from the docstring of a module-level function or class (a list of sentences)."""
    doc = inspect.getdoc(obj)
    if not (doc and doc.strip()):
        return [f"{name} has no docstring"]
    if inspect.isclass(obj) and issubclass(obj, enum.Enum):
        return []  # the signature is Enum's machinery
    params = signature_parameters(obj)
    documented = documented_parameters(doc)
    if dataclasses.is_dataclass(obj):
        documented += [
            line.split(" : ")[0].strip()
            for line in sections(doc).get("Attributes", [])
            if line and not line.startswith(" ")
        ]
    out = []
    missing = [p for p in params if p not in documented]
    if missing:
        out.append(f"{name}: parameters not documented: {missing}")
    if inspect.isfunction(obj) and "Returns" not in sections(doc) and "Yields" not in sections(doc):
        out.append(f"{name}: no 'Returns' section")
    return out


@pytest.mark.parametrize("name, obj", MODULE_LEVEL, ids=[n for n, _ in MODULE_LEVEL])
def test_module_level_docstrings(name, obj):
    """The rest of the public API of every public module: documented too (dataclass fields under Attributes)."""
    problems = numpydoc_problems(name, obj)
    assert not problems, problems


def test_checker_catches_missing_sections():
    def f(a):
        """Summary only."""

    assert numpydoc_problems("f", f) == ["f: parameters not documented: ['a']", "f: no 'Returns' section"]


def _internal_callables():
    """Functions and classes of wmr's modules that no ``__all__`` lists: the modules' implementation.

    Names with a leading underscore are a module's own (no other module may import them) and are left out.
    """
    listed = {id(o) for _, o in PUBLIC + _module_callables()}
    out = []
    for module in ALL_MODULES:
        mod = importlib.import_module(module)
        for name, obj in vars(mod).items():
            if name[0] != "_" and getattr(obj, "__module__", None) == module and id(obj) not in listed:
                if inspect.isfunction(obj) or inspect.isclass(obj):
                    out.append((f"{module}.{name}", obj))
    return out


INTERNAL = _internal_callables()


@pytest.mark.parametrize("name, obj", INTERNAL, ids=[n for n, _ in INTERNAL])
def test_internal_names_say_what_they_are(name, obj):
    """Implementation names: a summary line (the formula and shapes where they help), no numpydoc sections asked."""
    doc = inspect.getdoc(obj)
    assert doc and doc.strip().splitlines()[0].strip(), f"{name} has no summary line"


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


def test_the_walk_finds_every_module():
    """The module lists are walked from the package: a new module is checked without editing this file."""
    package = Path(wmr.__file__).parent
    files = {p.relative_to(package.parent).with_suffix("") for p in package.rglob("*.py")}
    names = {".".join(f.parts[:-1] if f.name == "__init__" else f.parts) for f in files}
    assert names - {n for n in names if n.endswith("__main__")} == set(ALL_MODULES)
    assert "wmr.model.validation" in PUBLIC_MODULES and "wmr.analysis._closed" not in PUBLIC_MODULES


@pytest.mark.parametrize("module", ALL_MODULES)
def test_doctests(module):
    mod = importlib.import_module(module)
    result = doctest.testmod(mod, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE, verbose=False)
    assert result.failed == 0, f"{result.failed} doctest(s) failed in {module}"


@pytest.mark.parametrize("module", ALL_MODULES)
def test_module_has_docstring_and_all(module):
    """Every module says what it is; the library's modules state their public names in ``__all__``."""
    mod = importlib.import_module(module)
    assert (mod.__doc__ or "").strip(), f"{module} has no module docstring"
    if module.startswith(("wmr.model", "wmr.analysis")):
        names = getattr(mod, "__all__", None)
        assert names is not None, f"{module} has no __all__"
        missing = [n for n in names if not hasattr(mod, n)]
        assert not missing, f"{module}.__all__ names what it does not define: {missing}"


def test_core_modules_have_examples():
    """Worked examples (which double as doctests) exist across the core."""
    finder = doctest.DocTestFinder()  # counted, not run again: test_doctests runs each one
    n = sum(
        not ex.options.get(doctest.SKIP)
        for module in ALL_MODULES
        for t in finder.find(importlib.import_module(module))
        for ex in t.examples
    )
    assert n >= 30
