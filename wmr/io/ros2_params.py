"""ROS 2 parameter files as data with line numbers: the controllers in a file, and their parameters read with checks.

A ROS 2 parameter file (YAML) holds one block per node, ``NODE: {ros__parameters: {...}}``, maybe
under namespaces or the wildcard ``/**``; the ``controller_manager`` block gives each controller's
``type`` (``diff_drive_controller/DiffDriveController``).  :func:`parse` reads the file with PyYAML
and keeps the line of every key, so that :class:`Params` can say ``FILE:LINE: node.key: what is wrong``
(:class:`~wmr.errors.RobotFileError`).
"""

from __future__ import annotations

import difflib
import math
from dataclasses import dataclass, field
from typing import Any, NoReturn

from ..errors import RobotFileError
from .extras import require
from .wheel_tables import toml_text

__all__: list[str] = []  # what wmr.io.ros2 reads a parameter file with

_MISSING = object()


@dataclass
class Block:
    """The ``ros__parameters`` of one ``node``: ``params`` nested as in the file, the ``line`` of the key, the ``lines`` of
    every key under it (``{(key, subkey, ...): line}``).
    """

    node: str
    params: dict
    line: int
    lines: dict = field(default_factory=dict)


#: YAML 1.2's floats (``1e-3``, ``2E5`` without a dot): ROS 2's parameter parser reads them as doubles, PyYAML's
#: YAML 1.1 resolver as strings
_FLOAT = r"^[-+]?(?:[0-9][0-9_]*)?(?:\.[0-9_]*)?[eE][-+]?[0-9]+$"


def _loader(yaml):
    """PyYAML's SafeLoader, reading ``1e-3`` as a float as ROS 2 does."""
    import re

    Loader: Any = type("Loader", (yaml.SafeLoader,), {})  # a subclass: SafeLoader itself stays as it is
    Loader.add_implicit_resolver("tag:yaml.org,2002:float", re.compile(_FLOAT), list("-+0123456789."))
    return Loader


def _lines(node, prefix, out):
    """The line of every mapping key below a composed YAML node: ``{key path: line}``."""
    if node.id == "mapping":
        for key, value in node.value:
            path = prefix + (str(key.value),)
            out[path] = key.start_mark.line + 1
            _lines(value, path, out)


def parse(raw: bytes, source: str) -> list[Block]:
    """The node blocks of a ROS 2 parameter file (``raw`` UTF-8, named ``source``), with their lines.

    A file that is not UTF-8, not YAML, or holds no ``ros__parameters`` raises a RobotFileError.
    """
    yaml = require("ros", "reading ROS 2 parameter files")
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise RobotFileError(source, raw[: exc.start].count(b"\n") + 1, "file", "not UTF-8 text") from None
    try:
        loader = _loader(yaml)
        data, tree = yaml.load(text, Loader=loader), yaml.compose(text, Loader=loader)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        line = mark.line + 1 if mark is not None else 1
        what = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        context, at = getattr(exc, "context", None), getattr(exc, "context_mark", None)
        if context and at is not None:
            what += f" ({context} started at line {at.line + 1})"
        raise RobotFileError(source, line, "yaml", f"YAML syntax error: {what}") from None
    lines: dict[tuple, int] = {}
    if tree is not None:
        _lines(tree, (), lines)
    blocks: list[Block] = []

    def walk(value, path):
        if not isinstance(value, dict):
            return
        if "ros__parameters" in value and path:
            params = value["ros__parameters"]
            here = path + ("ros__parameters",)
            sub = {k[len(here) :]: n for k, n in lines.items() if k[: len(here)] == here and len(k) > len(here)}
            if not isinstance(params, dict):
                raise RobotFileError(
                    source,
                    lines.get(here, 1),
                    f"{path[-1]}.ros__parameters",
                    f"must be a mapping of parameters, got {toml_text(params)}",
                )
            blocks.append(Block(str(path[-1]), params, lines.get(here, 1), sub))
            return
        for key, sub in value.items():
            walk(sub, path + (str(key),))

    walk(data, ())
    if not blocks:
        raise RobotFileError(
            source,
            1,
            "ros__parameters",
            "no node parameters in the file (a ROS 2 parameter file holds NODE: {ros__parameters: {...}})",
        )
    return blocks


class Params:
    """The parameters of one controller (``block`` of the file ``source``), read with checks; a problem raises a
    RobotFileError at the key's line.
    """

    def __init__(self, source: str, block: Block):
        self.source, self.block = source, block

    def fail(self, key: str, reason: str) -> NoReturn:
        """Raise the RobotFileError of ``key`` (dotted): at its line, else its parent's, else the node's ``ros__parameters``."""
        path = tuple(key.split("."))
        line = self.block.lines.get(path)
        while line is None and len(path) > 1:
            path = path[:-1]
            line = self.block.lines.get(path)
        raise RobotFileError(self.source, line or self.block.line, f"{self.block.node}.{key}", reason)

    def has(self, key: str) -> bool:
        """True when ``key`` (dotted for nested parameters) is in the block."""
        return self._raw(key) is not _MISSING

    def _raw(self, key):
        value: Any = self.block.params
        for part in key.split("."):
            if not isinstance(value, dict) or part not in value:
                return _MISSING
            value = value[part]
        return value

    def first(self, keys: tuple, check: str, meaning: str, default: Any = _MISSING) -> Any:
        """The value of the first of ``keys`` present (a parameter, then its older names), as :meth:`get`; absent: ``keys[0]``."""
        key = next((k for k in keys if self.has(k)), keys[0])
        return self.get(key, check, meaning, default)

    def get(self, key: str, check: str, meaning: str, default: Any = _MISSING) -> Any:
        """The value of ``key`` (dotted), checked by ``check``: positive, number, bool, name, names or pair.

        ``meaning`` says what it is, with its unit, for messages; ``default`` is the value when the key is absent
        (none given: the key is required).
        """
        value = self._raw(key)
        if value is _MISSING:
            if default is not _MISSING:
                return default
            close = difflib.get_close_matches(key.split(".")[-1], [".".join(k) for k in self.block.lines], n=1)
            self.fail(key, f"missing ({meaning})" + (f"; the file has {close[0]!r}" if close else ""))
        number = isinstance(value, (int, float)) and not isinstance(value, bool)
        if check in ("positive", "number"):
            if not number or not math.isfinite(value):
                self.fail(key, f"must be a finite number ({meaning}), got {toml_text(value)}")
            if check == "positive" and not value > 0:
                self.fail(key, f"must be positive ({meaning}), got {toml_text(value)}")
            return float(value)
        if check == "bool":
            if not isinstance(value, bool):
                self.fail(key, f"must be true or false ({meaning}), got {toml_text(value)}")
            return value
        if check == "name":
            if not isinstance(value, str) or not value:
                self.fail(key, f"must be a joint name ({meaning}), got {toml_text(value)}")
            return value
        if check == "names":
            if not isinstance(value, list) or not value or not all(isinstance(v, str) and v for v in value):
                self.fail(key, f"must be a list of joint names ({meaning}), got {toml_text(value)}")
            return list(value)
        if check == "pair":
            if (
                not isinstance(value, list)
                or len(value) != 2
                or not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in value)
            ):
                self.fail(key, f"must be two numbers [x, y] ({meaning}), got {toml_text(value)}")
            return (float(value[0]), float(value[1]))
        raise AssertionError(check)
