"""Sphinx extension: a reference to a name that a package re-exports resolves to the page of the
object where it is defined; ``.. exports:: PACKAGE`` lists what a package re-exports.

The API reference documents each object once, in the module that defines it
(``wmr.model.robot.Robot``), while users and docstrings write the names ``wmr`` offers
(``wmr.Robot``, ``wmr.conventions``) or a short name inside a package that re-exports it
(``spin_and_translate`` in :mod:`wmr.swerve`). When Sphinx finds no target for such a name, this
imports it and retries with the object's own name (``module.qualname``, or the module's name); if
that is documented, the reference links there. Anything else stays unresolved, and ``nitpicky``
reports it.
"""

from __future__ import annotations

import importlib
import inspect
from typing import Any

from docutils import nodes
from sphinx.addnodes import pending_xref
from sphinx.application import Sphinx
from sphinx.environment import BuildEnvironment
from sphinx.util.docutils import SphinxDirective


def imported(dotted: str) -> Any:
    """The object that ``dotted`` names (a module, or attributes of one), or None.

    Examples
    --------
    >>> imported("os.path.join") is __import__("os").path.join
    True
    >>> imported("os.no_such_thing") is None
    True
    """
    parts = dotted.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj: Any = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        try:
            for attr in parts[i:]:
                obj = getattr(obj, attr)
        except AttributeError:
            return None
        return obj
    return None


def own_name(obj: Any) -> str | None:
    """The name under which ``obj`` is defined (and documented); None for data.

    Examples
    --------
    >>> own_name(__import__("os").path.join)
    'posixpath.join'
    >>> own_name(3) is None
    True
    """
    if inspect.ismodule(obj):
        return obj.__name__
    obj = getattr(obj, "fget", None) or getattr(obj, "func", None) or obj  # property, cached_property
    module, qualname = getattr(obj, "__module__", None), getattr(obj, "__qualname__", None)
    if isinstance(module, str) and isinstance(qualname, str) and "<" not in qualname:
        return f"{module}.{qualname}"
    return None


_MISSING = object()


def documented_as(domain: Any, target: str, reftype: str, obj: Any = _MISSING) -> str | None:
    """The one documented name that ends with ``.target`` (or is ``target``), of a type the role
    ``reftype`` may refer to, and that is ``obj`` when ``obj`` is given; None when there is not one."""
    types = set(domain.objtypes_for_role(reftype) or ())
    found = [
        name
        for name, entry in domain.objects.items()
        if (name == target or name.endswith("." + target))
        and (not types or entry.objtype in types)
        and (obj is _MISSING or imported(name) is obj)
    ]
    return found[0] if len(found) == 1 else None


def resolve(app: Sphinx, env: BuildEnvironment, node: pending_xref, contnode: nodes.TextElement) -> Any:
    if node.get("refdomain") != "py":
        return None
    domain = env.get_domain("py")
    target, reftype = node["reftarget"].lstrip(".~"), node["reftype"]
    modname = node.get("py:module")
    names: list[str | None] = []
    parts = target.split(".")
    suffixes = [".".join(parts[i:]) for i in range(len(parts))]  # the longest first
    for candidate in ([f"{modname}.{target}"] if modname else []) + [target]:
        obj = imported(candidate) if "." in candidate else None
        owner, _, attr = candidate.rpartition(".")
        cls = imported(owner) if obj is None and owner else None
        if inspect.isclass(cls) and any(attr in vars(c).get("__annotations__", {}) for c in cls.__mro__):
            names.append(f"{own_name(cls)}.{attr}")  # an instance attribute (a frozen value's, set when made)
        if obj is not None:
            names.append(own_name(obj))
            names += [documented_as(domain, suffix, reftype, obj) for suffix in suffixes]
            names += [documented_as(domain, suffix, "obj", obj) for suffix in suffixes]  # any type
    names.append(documented_as(domain, target, reftype))
    for name in names:
        if name and name != node["reftarget"]:
            ref = domain.resolve_any_xref(env, node["refdoc"], app.builder, name, node, contnode)
            if ref:
                return ref[0][1]
    return None


def reexported(module: Any) -> list[str]:
    """The names of ``module.__all__`` that are defined elsewhere (the package's offer to its users).

    Examples
    --------
    >>> import types; m = types.ModuleType("m"); m.__all__ = ["join", "here"]
    >>> m.join = __import__("os").path.join; m.here = 3
    >>> reexported(m)
    ['join']
    """
    out = []
    for name in getattr(module, "__all__", ()):
        obj = getattr(module, name, None)
        own = own_name(obj)
        if (own is not None and own != f"{module.__name__}.{name}") or (own is None and not _defined_in(module, name)):
            out.append(name)
    return out


def _defined_in(module: Any, name: str) -> bool:
    """Whether ``name`` (data) is assigned in ``module``'s own source, rather than imported."""
    import ast

    try:
        tree = ast.parse(inspect.getsource(module))
    except (OSError, TypeError):
        return True
    for node in tree.body:
        targets = (
            node.targets if isinstance(node, ast.Assign) else [node.target] if isinstance(node, ast.AnnAssign) else []
        )
        for t in targets:
            names = [t] if isinstance(t, ast.Name) else list(t.elts) if isinstance(t, ast.Tuple) else []
            if any(isinstance(n, ast.Name) and n.id == name for n in names):
                return True
    return False


def summary(obj: Any) -> str:
    """The first sentence of ``obj``'s docstring (data: its type).

    Examples
    --------
    >>> summary(summary)
    "The first sentence of ``obj``'s docstring (data: its type)."
    """
    if own_name(obj) is None:
        return f"(a ``{type(obj).__name__}``)"
    doc = (inspect.getdoc(obj) or "").strip().split("\n\n")[0].replace("\n", " ")
    end = doc.find(". ")
    return doc if end < 0 else doc[: end + 1]


class Exports(SphinxDirective):
    """``.. exports:: PACKAGE``: a table of the names PACKAGE re-exports, each linked to its page."""

    required_arguments = 1

    def run(self) -> list[Any]:
        module = importlib.import_module(self.arguments[0])
        names = reexported(module)
        if not names:
            return []
        lines = [
            f".. rubric:: What ``{module.__name__}`` offers",
            "",
            f"The names of ``{module.__name__}.__all__`` that are defined in its modules:",
            "",
            ".. list-table::",
            "   :widths: 30 70",
            "",
        ]
        for name in names:
            lines += [f"   * - :py:obj:`{module.__name__}.{name}`", f"     - {summary(getattr(module, name))}"]
        self.state_machine.insert_input(lines + [""], f"<exports of {module.__name__}>")
        return []


def setup(app: Sphinx) -> dict[str, Any]:
    app.connect("missing-reference", resolve)
    app.add_directive("exports", Exports)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
