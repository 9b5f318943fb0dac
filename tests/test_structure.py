"""The shape of the code, read from its syntax trees: no import cycles, no private names across modules,
the package's own exceptions, no dispatch on a wheel's kind, modules of at most 800 lines.

Every import counts, also one inside a function (a lazy import is still a dependency); ``from .x import y``
is an import of the module ``x.y`` when that is a module, else of ``x``.  The checks run on the ``wmr``
that is imported (the repository's, or an installed wheel's: this test ships in the sdist).  The same
reader checks the repository's ``edition/`` and ``tools/`` (``tools/build/`` too) beside it, when they are
there: no cycles and no private names imported across modules of the three together, imports one way
(wmr imports neither, the edition never imports the build), and at most 800 lines a module.  The rules of
the library's own error types and of wheel kinds answering for themselves are the library's, checked on
``wmr`` only.
"""

import ast
from pathlib import Path

import pytest

import wmr

#: the folder that holds the package ``wmr`` being tested (the repository, or site-packages)
ROOT = Path(wmr.__file__).resolve().parent.parent
#: a guard against a module that grew a second job, not a shape to fill: modules are split by what they are
#: responsible for (issue 29: a 400-line cap had cut modules by length)
MAX_LINES = 800


# ------------------------------------------------------------------------------------------ the reader
def modules(*packages, root=ROOT):
    """``{dotted name: path}`` of every module of the packages (a package is its ``__init__``)."""
    out = {}
    for pkg in packages:
        for path in sorted((root / pkg).rglob("*.py")):
            parts = list(path.relative_to(root).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts = parts[:-1]
            out[".".join(parts)] = path
    return out


def imports(name, path, known):
    """``[(module imported, name imported from it or None, line)]`` of one module, every import in it."""
    is_package = path.name == "__init__.py"
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out += [(a.name, None, node.lineno) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = name.split(".") if is_package else name.split(".")[:-1]
                base = base[: len(base) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            for a in node.names:
                sub = f"{target}.{a.name}"
                out.append((sub, None, node.lineno) if sub in known else (target, a.name, node.lineno))  # type: ignore[arg-type]
    return out


def nearest(module, known):
    """The module itself, or the package it is in, among the known modules (None: outside them)."""
    while module and module not in known:
        module = module.rpartition(".")[0]
    return module or None


def graph(known):
    """``{module: {modules it imports}}`` among the known modules."""
    return {
        m: {t for t in (nearest(i, known) for i, _, _ in imports(m, p, known)) if t and t != m}
        for m, p in known.items()
    }


def cycles(edges):
    """The strongly connected components of more than one module (Tarjan), each sorted."""
    index: dict = {}
    low: dict = {}
    stack: list = []
    on: set = set()
    out: list = []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(edges[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return sorted(out)


def private_imports(known):
    """``{(importer, module, name)}``: a name starting with ``_`` imported from another module."""
    return {
        (m, nearest(t, known), n)
        for m, p in known.items()
        for t, n, _ in imports(m, p, known)
        if n and n.startswith("_") and not n.startswith("__") and nearest(t, known) not in (None, m)
    }


WMR = modules("wmr")
#: the repository holding this test; its edition and build, when this is a checkout (not an sdist)
REPO = Path(__file__).resolve().parent.parent
EDITION = modules("edition", root=REPO) if (REPO / "edition" / "__init__.py").is_file() else {}
TOOLS = modules("tools", root=REPO) if (REPO / "tools" / "__init__.py").is_file() else {}
#: every module the checks read
EVERY = {**WMR, **EDITION, **TOOLS}
needs_checkout = pytest.mark.skipif(not (EDITION and TOOLS), reason="edition/ and tools/ are in a checkout only")


# ------------------------------------------------------------------------------------------ the checks
def test_the_reader_sees_a_cycle_and_a_private_import(tmp_path):
    """The checks can fail: a lazy import back, and ``from .b import _c``, are found."""
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "a.py").write_text("from .b import _c\n")
    (pkg / "b.py").write_text("def f():\n    from . import a\n_c = 1\n")
    known = modules("pkg", root=tmp_path)
    assert cycles(graph(known)) == [["pkg.a", "pkg.b"]]
    assert private_imports(known) == {("pkg.a", "pkg.b", "_c")}


def test_the_reader_knows_the_package():
    assert {"wmr.model.wheels.unit", "wmr.model.wheels.offset", "wmr.analysis.sweep.execute"} <= set(WMR)
    edges = graph(WMR)
    assert "wmr.model.wheels.unit" in edges["wmr.model.wheels.offset"]
    assert "wmr.analysis.det_exact" in edges["wmr.analysis.singularities"]


def test_no_import_cycles_in_wmr():
    assert cycles(graph(WMR)) == []


def test_no_private_names_imported_across_modules_of_wmr():
    assert private_imports(WMR) == set()


@needs_checkout
def test_the_reader_knows_the_edition_and_the_build():
    assert {"edition.transcription", "edition.ledger", "tools.build"} <= set(EVERY)
    assert any(m.startswith("tools.build.") for m in EVERY)  # tools/build/*.py
    edges = graph(EVERY)
    assert {"wmr", "wmr.sim"} <= edges["edition.physics.common"]  # edges into the library are seen
    assert any(t.startswith("tools.build.") for m, e in edges.items() if m.startswith("tools.build.") for t in e)


@needs_checkout
def test_no_import_cycles_in_the_edition_and_the_build():
    assert cycles(graph(EVERY)) == []


@needs_checkout
def test_no_private_names_imported_across_modules_of_the_edition_and_the_build():
    assert private_imports(EVERY) == set()


@pytest.mark.parametrize(
    "package, forbidden", [("wmr", ("edition", "tools")), pytest.param("edition", ("tools",), marks=needs_checkout)]
)
def test_imports_go_one_way(package, forbidden):
    """The library never imports the edition or the build; the edition never imports the build."""
    known = {m: p for m, p in EVERY.items() if m.split(".")[0] == package}
    wrong = [
        (m, i, line) for m, p in known.items() for i, _, line in imports(m, p, EVERY) if i.split(".")[0] in forbidden
    ]
    assert known and wrong == []


@pytest.mark.parametrize("name", sorted(EVERY))
def test_module_size(name):
    n = len(EVERY[name].read_text(encoding="utf-8").splitlines())
    assert n <= MAX_LINES, f"{name} has {n} lines (at most {MAX_LINES}: split it by responsibility)"


def test_bad_input_raises_the_package_s_own_errors():
    """No ``raise ValueError(...)`` or ``raise TypeError(...)`` in wmr: input errors come from :mod:`wmr.errors`."""
    wrong = []
    for name, path in WMR.items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            value = node.exc if isinstance(node, ast.Raise) else node.value if isinstance(node, ast.Return) else None
            call = value.func if isinstance(value, ast.Call) else value
            if isinstance(call, ast.Name) and call.id in ("ValueError", "TypeError"):
                wrong.append(f"{name}:{getattr(node, 'lineno', '?')}")
    assert wrong == []


def test_no_dispatch_on_the_kind_of_a_wheel():
    """Outside the wheel kinds' own package, nothing compares ``something.kind`` with a kind's name."""
    from wmr.model.wheels import wheel_kinds

    names = set(wheel_kinds())
    wrong = []
    for name, path in WMR.items():
        if name.startswith("wmr.model.wheels"):
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            left = getattr(node, "left", None)
            if not (isinstance(node, ast.Compare) and isinstance(left, ast.Attribute) and left.attr == "kind"):
                continue
            consts = [c for c in ast.walk(node) if isinstance(c, ast.Constant) and c.value in names]
            if consts:
                wrong.append(f"{name}:{node.lineno}")
    assert wrong == []


#: the layers of wmr, inner first: a module may import from its own layer and the ones before it
LAYERS = (
    ("errors", "_version", "model"),
    ("analysis",),
    ("io", "swerve", "odometry"),
    ("sim", "words", "plot"),
    ("cli", "deprecated", "__main__", "__init__"),  # the package itself: what ``import wmr`` gives
)


#: the imports outwards that stay, and why (issue 29 leaves them)
OUTWARD = {
    # the rule of written numbers breaks ties as a file would show them; it belongs with the model's numbers
    ("wmr.analysis.actuation", "wmr.io.decimals"),
    ("wmr.analysis.sweep.reduction", "wmr.io.decimals"),
    ("wmr.swerve.plot", "wmr.plot.style"),  # swerve's own drawings, in the house style
}


def _layer(module):
    """The index in :data:`LAYERS` of a module of wmr (the package ``wmr`` itself: ``__init__``)."""
    parts = module.split(".")
    top = parts[1] if len(parts) > 1 else "__init__"
    return next((k for k, names in enumerate(LAYERS) if top in names), len(LAYERS))


def test_the_layers_import_inwards():
    """The model knows no analysis, file format, drawing or engine; the analyses no words, drawing or engine
    (each kind's drawing, robot-file keys and mechanism are the outer layers' entries, not the kind's)."""
    edges = graph(WMR)
    wrong = sorted(
        (m, t) for m, targets in edges.items() for t in targets if _layer(t) > _layer(m) and (m, t) not in OUTWARD
    )
    assert wrong == []
    assert _layer("wmr.model.wheels.offset") == 0 and _layer("wmr.plot.parts") == 3  # the reader knows the layers
