r"""What a chapter derived, for a later chapter and the tests: read from the file the chapter wrote.

A chapter derives each equation in its own cells (a few lines of SymPy, shown to the reader) and passes
the derived objects to a check of :mod:`edition.checks`.  A chapter whose derived objects are used later
(Chapter 2 builds on Chapter 1's rows, Chapter 3 on Chapter 2's :math:`\mathbf J_1` and :math:`\mathbf J_2`,
the tests re-grade the checks with them) writes them, when it runs, into ``<chapter>.derived.json`` beside
its figures (:meth:`edition.notebook.Chapter.save_derived`, which calls :func:`write`); the build publishes
the file into ``figures/`` with the other outputs.  :func:`derived` reads it back: no cell of the earlier
chapter runs again.

The file is a JSON object with sorted keys: the chapter, the format and, per name, the object's
:func:`sympy.srepr`, which is exact (integers, rationals, symbols with their assumptions, matrices).
Reading it never calls :func:`eval`: the text of each object is parsed (:mod:`ast`) and only calls of SymPy's
own classes are rebuilt, with numbers, ``True``/``False`` and, as a symbol's or a function's name, strings as
their arguments (:func:`loads`); anything else (an attribute, another name, a string where SymPy would
parse it) refuses the file.  :func:`dumps` writes a name only when it reads back equal to the object.
"""

from __future__ import annotations

import ast
import json
import os
import re
from functools import cache
from pathlib import Path
from types import MappingProxyType
from typing import Any

import sympy as sp
from sympy.core.function import UndefinedFunction

from .files import atomic_write

__all__ = ["FORMAT", "SOURCES", "derived", "dumps", "filename", "loads", "read", "source", "write"]

#: what the file says it holds (a reader refuses another format)
FORMAT = "wmr derived objects 1: sympy.srepr per name"
#: where :func:`derived` looks after the build's own output (see :func:`source`): the checkout's published
#: ``figures/``, then ``edition/_derived/`` (the course package, ``make course``, ships the files there)
SOURCES = (Path(__file__).resolve().parents[1] / "figures", Path(__file__).resolve().parent / "_derived")
_OUT = "WMR_OUT"  # edition.notebook.OUT_VARIABLE: the folder the build gives the running chapter
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")
_FLOAT = re.compile(r"[+-]?[0-9]+(\.[0-9]*)?([eE][+-]?[0-9]+)?\Z")
#: SymPy's classes and constants (``pi``, ``I``, ``oo``, ...) a file may name; Dummy and Wild are not exact
#: the SymPy classes a file may call: the algebra of the chapters' objects (a class that computes, such as
#: factorial, could be asked for an unbounded amount of work); :func:`dumps` refuses an object needing another
_CALLABLE = {
    n: getattr(sp, n)
    for n in (
        "Symbol", "Function", "Integer", "Rational", "Float", "Add", "Mul", "Pow", "sin", "cos", "tan", "atan2",
        "Abs", "sign", "Eq", "Derivative", "Tuple", "MutableDenseMatrix", "ImmutableDenseMatrix",
    )
}  # fmt: skip
_CONSTANT = {n: v for n, v in vars(sp).items() if isinstance(v, sp.Basic) and not isinstance(v, type)}
#: bounds on what a file may ask SymPy to build: its size, an integer's size and an integer exponent's
MAX_BYTES, MAX_INTEGER, MAX_EXPONENT = 1 << 20, 10**6, 64
_NAMED = {"Symbol", "Function"}  # the classes whose first argument is a name (a string SymPy does not parse)


def filename(chapter: str) -> str:
    """The file a chapter writes: ``<chapter>.derived.json``.

    >>> filename("01_platform_and_wheels")
    '01_platform_and_wheels.derived.json'
    """
    return f"{chapter}.derived.json"


def _same(a: Any, b: Any) -> bool:
    """Equal and of one type, containers element by element (a Python ``2`` is not SymPy's ``Integer(2)``)."""
    if type(a) is not type(b):
        return False
    if isinstance(a, (list, tuple)):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(_same(a[k], b[k]) for k in a)
    return bool(a == b)


def _build(node: ast.AST, text: str) -> Any:
    """The object an ``ast`` node of :func:`sympy.srepr`'s text stands for; ValueError for anything else."""
    if isinstance(node, ast.Constant) and type(node.value) in (int, float, bool):
        if type(node.value) is int and abs(node.value) > MAX_INTEGER:
            raise ValueError(f"an integer of {len(str(abs(node.value)))} digits (at most {MAX_INTEGER:,})")
        return node.value
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        value = _build(node.operand, text)
        if type(value) not in (int, float):
            raise ValueError(f"a minus sign before {type(value).__name__}")
        return -value
    if isinstance(node, ast.Name) and node.id in _CONSTANT:
        return _CONSTANT[node.id]
    if isinstance(node, (ast.List, ast.Tuple)):
        items = [_build(e, text) for e in node.elts]
        return items if isinstance(node, ast.List) else tuple(items)
    if isinstance(node, ast.Dict) and None not in node.keys:
        return {_build(k, text): _build(v, text) for k, v in zip(node.keys, node.values)}  # type: ignore[arg-type]
    if isinstance(node, ast.Call):
        if isinstance(node.func, ast.Name) and node.func.id in _CALLABLE:
            cls, name = _CALLABLE[node.func.id], node.func.id
        elif isinstance(node.func, ast.Call):  # an undefined function applied: Function('psi')(Symbol('t'))
            cls, name = _build(node.func, text), "applied"
            if not isinstance(cls, UndefinedFunction):
                raise ValueError(f"a call of {type(cls).__name__}")
        else:
            raise ValueError(f"a call of {ast.get_source_segment(text, node.func)!r}, not a SymPy class")
        args = [_string(a, name, text) if i == 0 else _build(a, text) for i, a in enumerate(node.args)]
        if name == "Pow" and len(args) == 2 and isinstance(args[1], sp.Integer) and abs(args[1]) > MAX_EXPONENT:
            raise ValueError(f"the power {args[1]} (SymPy would expand it; at most {MAX_EXPONENT})")
        kwargs = {}
        for kw in node.keywords:
            if kw.arg is None or not isinstance(kw.value, ast.Constant) or type(kw.value.value) not in (bool, int):
                raise ValueError(f"keyword {kw.arg!r} of {name}: only True, False or an integer")
            kwargs[kw.arg] = kw.value.value
        return cls(*args, **kwargs)
    raise ValueError(f"{ast.get_source_segment(text, node) or type(node).__name__!r} is not SymPy's srepr")


def _string(node: ast.AST, cls: str, text: str) -> Any:
    """The first argument of a call: a name for Symbol and Function, a decimal for Float, else not a string."""
    if not (isinstance(node, ast.Constant) and isinstance(node.value, str)):
        return _build(node, text)
    if cls in _NAMED or (cls == "Float" and _FLOAT.match(node.value)):
        return node.value
    raise ValueError(f"the string {node.value!r} given to {cls} (SymPy would parse it)")


def loads(text: str, chapter: str | None = None) -> dict[str, Any]:
    """The objects of a file :func:`dumps` wrote (``name -> object``), rebuilt without :func:`eval`.

    Parameters
    ----------
    text : str
        The file's text.
    chapter : str, optional
        The chapter the file must be of.

    Raises
    ------
    ValueError
        Not such a file: not JSON, another format or chapter, a name that is no identifier, or an object whose
        text is anything but calls of SymPy's classes (see the module).

    Examples
    --------
    >>> loads(dumps("ch", {"M": sp.Matrix([[1, sp.Symbol("x", real=True) / 2]])}))["M"]
    Matrix([[1, x/2]])
    >>> loads(dumps("ch", {"x": sp.Integer(1)}).replace("Integer(1)", "__import__('os')"))
    Traceback (most recent call last):
    ...
    ValueError: x: a call of '__import__', not a SymPy class
    """
    if len(text) > MAX_BYTES:
        raise ValueError(f"{len(text):,} characters: larger than a file of derived objects ({MAX_BYTES:,})")
    try:
        data = json.loads(text)
    except ValueError as e:
        raise ValueError(f"not JSON: {e}") from None
    if not isinstance(data, dict) or data.get("format") != FORMAT or not isinstance(data.get("objects"), dict):
        raise ValueError(f"not a file of derived objects (format {FORMAT!r})")
    if chapter is not None and data.get("chapter") != chapter:
        raise ValueError(f"the objects of {data.get('chapter')!r}, not of {chapter!r}")
    out = {}
    for name, src in data["objects"].items():
        if not _NAME.match(name) or not isinstance(src, str):
            raise ValueError(f"{name!r}: not a name and the text of an object")
        try:
            out[name] = _build(ast.parse(src, mode="eval").body, src)
        except Exception as e:  # a syntax error, a refused node, a SymPy class refusing its arguments
            raise ValueError(f"{name}: {e}") from None
    return out


def dumps(chapter: str, objects: dict[str, Any]) -> str:
    """The text of the file :func:`write` writes: deterministic (sorted keys, one object a line).

    Raises
    ------
    ValueError
        An object that does not read back (:func:`loads`) equal to itself, or a name that is no identifier.
    """
    texts = {}
    for name, value in objects.items():
        text = sp.srepr(value)
        if not _NAME.match(name):
            raise ValueError(f"{name!r} is not a name")
        why = ""
        try:
            same = _same(_build(ast.parse(text, mode="eval").body, text), value)
        except Exception as e:  # what the reader refuses (a Dummy, a function class, ...)
            same, why = False, f" ({e})"
        if not same:
            raise ValueError(f"{name}: {type(value).__name__} does not read back exactly from sympy.srepr{why}")
        texts[name] = text
    return json.dumps({"chapter": chapter, "format": FORMAT, "objects": texts}, indent=1, sort_keys=True) + "\n"


def write(out: Path | str, chapter: str, objects: dict[str, Any]) -> Path:
    """Write ``out/<chapter>.derived.json`` (atomically) and return its path."""
    return atomic_write(Path(out) / filename(chapter), dumps(chapter, objects))


def read(path: Path | str, chapter: str | None = None) -> MappingProxyType:
    """The objects of one file (read only); ValueError when it is not one :func:`dumps` wrote (:func:`loads`)."""
    path = Path(path)
    if not path.is_file() or path.stat().st_size > MAX_BYTES:
        raise ValueError(f"{path}: not a regular file of at most {MAX_BYTES:,} bytes")
    try:
        return MappingProxyType(loads(path.read_text(encoding="utf-8"), chapter))
    except ValueError as e:
        raise ValueError(f"{path}: {e}") from None


def source(chapter: str) -> Path:
    """The file :func:`derived` reads: what the chapter wrote in this build, else the published one.

    In the build (``$WMR_OUT`` is ``<build>/out/<this chapter>``), the file in ``<build>/out/<chapter>/``
    when it is there (the Makefile runs a chapter after the ones it reads); else ``figures/`` of this
    checkout; else the course package's copy (:data:`SOURCES`).

    Raises
    ------
    FileNotFoundError
        No such file in any of them.
    """
    name = filename(chapter)
    out = os.environ.get(_OUT, "").strip()
    places = ([Path(out).resolve().parent / chapter] if out else []) + list(SOURCES)
    for p in (d / name for d in places):
        if p.is_file():
            return p
    raise FileNotFoundError(f"chapter {chapter!r}: no {name} in {', '.join(map(str, places))}")


@cache
def derived(chapter: str) -> MappingProxyType:
    """The objects a chapter derived and wrote for later use: ``name -> SymPy object`` (read only, cached).

    Parameters
    ----------
    chapter : str
        The notebook's stem, e.g. ``"01_platform_and_wheels"``.

    Raises
    ------
    FileNotFoundError
        The chapter's file is nowhere (:func:`source`).
    ValueError
        The file is not one :func:`write` wrote for this chapter (:func:`read`).
    """
    return read(source(chapter), chapter)
