"""The public API is annotated (issue 22): every function and method reachable from ``wmr.__all__``, and
every class of wmr that one of them returns, states the types of its parameters and of its result.

"Reachable": the functions and classes in ``wmr.__all__``, the members of the modules in it (``wmr.swerve``,
``wmr.errors``, ...), the public methods and properties of those classes, and, followed from the return
annotations, the classes of wmr they return (a :class:`~wmr.analysis.classes.CampionClass`, a
:class:`~wmr.analysis.sweep.result.Sweep`, ...) with their own methods.  mypy (``make test``) checks that
the annotations agree with the code; this test checks that they are there, so that the count cannot fall.

``python tests/test_annotations.py`` prints how many of the public API's callables, and of all the
public callables of wmr's public modules, are annotated.
"""

from __future__ import annotations

import ast
import importlib
import inspect
import pkgutil
import sys
import types
import typing
from collections.abc import Callable, Iterator

import wmr


def _functions_of(cls: type) -> Iterator[tuple[str, Callable]]:
    """The public methods and properties a class defines itself (and ``__init__``), by qualified name."""
    for name, attr in vars(cls).items():
        if name.startswith("_") and name != "__init__":
            continue
        if isinstance(attr, (staticmethod, classmethod)):
            attr = attr.__func__
        elif isinstance(attr, property):
            attr = attr.fget
        if inspect.isfunction(attr):
            yield f"{cls.__module__}.{cls.__qualname__}.{name}", attr


def _returned_classes(func: Callable) -> list[type]:
    """The classes of wmr named in ``func``'s return annotation (looked up in its module)."""
    ret = inspect.signature(func).return_annotation
    if ret is inspect.Signature.empty:
        return []
    if isinstance(ret, str):  # from __future__ import annotations: look the names up
        names = {n.id for n in ast.walk(ast.parse(ret, mode="eval")) if isinstance(n, ast.Name)}
        scope = dict(vars(sys.modules[func.__module__]))
        if "." in func.__qualname__:  # a method: its own class (typing.Self)
            scope.setdefault("Self", scope.get(func.__qualname__.split(".")[0]))
        found = [scope.get(n) for n in names]
    else:  # the objects themselves (X, tuple[X, ...], X | None)
        found, todo = [], [ret]
        while todo:
            t = todo.pop()
            found.append(t)
            todo += typing.get_args(t)
    return [c for c in found if inspect.isclass(c) and c.__module__.split(".")[0] == "wmr"]


def api() -> dict[str, Callable]:
    """Every callable of the public API, by qualified name (each function once)."""
    out: dict[str, Callable] = {}
    classes: list[type] = []
    todo: list[object] = [getattr(wmr, n) for n in wmr.__all__]
    while todo:
        obj = todo.pop()
        if isinstance(obj, types.ModuleType):
            todo += [getattr(obj, n) for n in getattr(obj, "__all__", ())]
        elif inspect.isclass(obj) and obj.__module__.split(".")[0] == "wmr" and obj not in classes:
            classes.append(obj)
            for base in obj.__mro__[1:]:
                if base.__module__.split(".")[0] == "wmr":
                    todo.append(base)  # inherited methods are part of the class's API
            for name, f in _functions_of(obj):
                if name not in out:
                    out[name] = f
                    todo += _returned_classes(f)
        elif inspect.isfunction(obj) and obj.__module__.split(".")[0] == "wmr":
            name = f"{obj.__module__}.{obj.__qualname__}"
            if name not in out:
                out[name] = obj
                todo += _returned_classes(obj)
    return out


def everything() -> dict[str, Callable]:
    """Every public function and method of wmr's public modules (no part of the name starting with ``_``)."""
    out: dict[str, Callable] = {}
    names = ["wmr"] + [
        m.name
        for m in pkgutil.walk_packages(wmr.__path__, "wmr.")
        if not any(p.startswith("_") for p in m.name.split(".")[1:])
    ]
    for modname in sorted(names):
        try:
            module = importlib.import_module(modname)
        except ImportError:  # a module that needs an extra that is not installed
            continue
        for name, obj in vars(module).items():
            if name.startswith("_") or getattr(obj, "__module__", None) != modname:
                continue
            if inspect.isfunction(obj):
                out[f"{modname}.{obj.__qualname__}"] = obj
            elif inspect.isclass(obj):
                out.update(_functions_of(obj))
    return out


def missing(func: Callable) -> list[str]:
    """The parameters of ``func`` without an annotation, and ``return`` when its result has none.

    ``self`` and ``cls`` need none; ``__init__`` needs no return annotation when a parameter has one.
    """
    sig = inspect.signature(func)
    params = [p for k, p in enumerate(sig.parameters.values()) if not (k == 0 and p.name in ("self", "cls"))]
    out = [p.name for p in params if p.annotation is inspect.Parameter.empty]
    if sig.return_annotation is inspect.Signature.empty and not (func.__name__ == "__init__" and params):
        out.append("return")
    return out


# ------------------------------------------------------------------------------------------ the checks
def test_the_api_is_what_wmr_exports_and_what_it_returns():
    names = api()
    assert "wmr.analysis.linalg.rank" in names and "wmr.model.robot.Robot.J2" in names
    assert "wmr.swerve.modules.module_commands" in names  # a module in wmr.__all__
    assert "wmr.analysis.sweep.result.Sweep.summary" in names  # a class wmr.sweep returns
    assert "wmr.model.wheels.unit.WheelUnit.block" in names  # a base class of OffsetWheel
    assert not any(n.split(".")[-1].startswith("_") and not n.endswith("__init__") for n in names)


def test_every_callable_of_the_public_api_is_annotated():
    unannotated = {name: m for name, f in api().items() if (m := missing(f))}
    assert unannotated == {}


def test_the_check_sees_a_missing_annotation():
    def half(x: float, y) -> float:
        return x

    def whole(x: float):
        return x

    class Thing:
        def __init__(self, x: float):
            self.x = x

        def bare(self):
            return self.x

    assert missing(half) == ["y"] and missing(whole) == ["return"] and missing(Thing.__init__) == []
    assert missing(Thing.bare) == ["return"]


if __name__ == "__main__":
    for label, found in (
        ("public API (wmr.__all__ and what it returns)", api()),
        ("public modules of wmr", everything()),
    ):
        done = sum(not missing(f) for f in found.values())
        print(f"{label}: {done} of {len(found)} callables annotated")
