r"""Robot files: a robot is a small TOML file; :func:`load` reads one, :func:`dump` writes one.

The schema (lengths in metres, or any one unit: every decision of :mod:`wmr` is the same in every
unit; angles in degrees)::

    name = "paper, three centred wheels"     # optional (default: the file's name)

    [[wheel]]                 # one table per wheel unit, wheel 1 first (the numbering of wmr.Robot)
    type = "centred"          # the wheel kind: offset, centred, dual, fixed, swedish, ... (wmr.io.wheel_keys())
    position = [-0.3, 0.0]    # the mount point d_i = CP_i, body frame, from the operation point C
    radius = 0.05             # the wheel radius r, > 0
    # ...                     # the kind's own keys, e.g. offset = 0.03 for an offset wheel
    # driven = {steer = false, drive = false}   # optional: joints whose actuation differs from the kind's default

Each kind takes exactly its keys, declared for it in :mod:`wmr.io.wheel_tables`
(:func:`~wmr.io.wheel_tables.wheel_keys` lists them); ``driven`` is optional for every kind.  A
malformed file raises :class:`~wmr.errors.RobotFileError`, whose message is one line,
``FILE:LINE: key: what is wrong`` (also for a file of more wheels than :mod:`wmr.model.limits`
allows, refused before it is parsed); a byte-order mark at the start is accepted; wheels are named
``wheel[k]`` with ``k`` counted from 1, as the paper numbers them.

Examples
--------
>>> import wmr
>>> text = wmr.dump(wmr.paper_robot("offset", L=0.5, r=0.1))
>>> print(text.splitlines()[3:8])
['[[wheel]]', 'type = "offset"', 'position = [-0.5, 0.0]', 'radius = 0.1', 'offset = 0.1']
>>> bot = loads(text)
>>> bool(np.allclose(bot.F([0.1, 0.2, 0.3]), wmr.paper_robot("offset", L=0.5, r=0.1).F([0.1, 0.2, 0.3])))
True
"""

from __future__ import annotations

import os
import re
import tomllib
from pathlib import Path
from typing import NoReturn

import numpy as np

from ..errors import InputError, InputTypeError, InputValueError, LimitError, RobotFileError
from ..model import validation
from ..model.checks import suggest
from ..model.limits import check, limit
from ..model.robot import Robot
from ..model.tolerance import near_zero
from ..model.types import PathLike
from .decimals import DEGREES, float_text, length_scale
from .wheel_tables import file_keys, readable_kinds, toml_string, toml_text

__all__ = ["RobotFileError", "load", "loads", "dump"]

_TOP_KEYS = ("name", "wheel")
#: the optional key of every wheel table: the joints whose actuation differs from the kind's default
_DRIVEN = "driven"


# ------------------------------------------------------------------------------------- lines
_WHEEL_HEADER = re.compile(r"""^\s*\[\[\s*(wheel|"wheel"|'wheel')\s*\]\]""")
_HEADER = re.compile(r"^\s*\[")
_KEY = re.compile(r"""^\s*("[^"]*"|'[^']*'|[A-Za-z0-9_-]+)\s*[=.]""")


class _Lines:
    """Where the keys are in the text: the line of each top-level key, wheel table and wheel key."""

    def __init__(self, text):
        self.top: dict[str, int] = {}
        self.wheels: list[tuple[int, dict[str, int]]] = []  # [(header line, {key: line})]
        self.owner: list[int | None] = [None]  # line -> its wheel table (0-based) or None
        where, wheel = self.top, None
        for n, line in enumerate(text.splitlines(), 1):
            if _WHEEL_HEADER.match(line):
                self.wheels.append((n, {}))
                where, wheel = self.wheels[-1][1], len(self.wheels) - 1
            elif _HEADER.match(line):
                where, wheel = {}, None
            else:
                m = _KEY.match(line)
                if m:
                    where.setdefault(m.group(1).strip("\"'"), n)
            self.owner.append(wheel)
        self.end = max(1, len(text.splitlines()))

    def key_at(self, line, key):
        """``key`` as it is named in messages when it is on ``line``: ``wheel[k].key`` inside a wheel table."""
        k = self.owner[line] if 0 < line < len(self.owner) else None
        return key if k is None else f"wheel[{k + 1}].{key}"

    def of(self, k=None, key=None):
        """Line of ``key`` in wheel ``k`` (0-based; None: top level), else of the wheel's table, else 1."""
        if k is None:
            return self.top.get(key, 1)
        if k < len(self.wheels):
            head, keys = self.wheels[k]
            return keys.get(key, head)
        return self.top.get("wheel", 1)  # an inline array of tables: the line of `wheel =`


# ------------------------------------------------------------------------------------ values
def _a(kind):
    return ("an " if kind[0] in "aeiou" else "a ") + kind


# ------------------------------------------------------------------------------------ reading
def _driven(value, cls, where, fail):
    """The ``driven`` table of a wheel: {joint name: bool}, joints of the kind only."""
    names = [j.name for j in cls.JOINTS]
    if not isinstance(value, dict):
        fail(
            *where,
            f"must be a table {{joint = true or false}} (joints of {_a(cls.kind)} wheel: "
            f"{', '.join(names)}), got {toml_text(value)}",
        )
    for name, flag in value.items():
        if name not in names:
            fail(
                *where,
                f"{_a(cls.kind)} wheel has no joint {name!r} (its joints: {', '.join(names)})" + suggest(name, names),
            )
        if not isinstance(flag, bool):
            fail(*where, f"{name} must be true or false, got {toml_text(flag)}")
    return value


def _wheel(k, table, lines, fail):
    """The wheel unit of the k-th ``[[wheel]]`` table (0-based ``k``)."""
    name = f"wheel[{k + 1}]"
    kinds = readable_kinds()
    if not isinstance(table, dict):
        fail(lines.of(k), name, f"must be a table ([[wheel]]), got {toml_text(table)}")
    if "type" not in table:
        fail(lines.of(k), f"{name}.type", f"missing (one of {', '.join(kinds)})")
    kind = table["type"]
    if not isinstance(kind, str) or kind not in kinds:
        fail(
            lines.of(k, "type"),
            f"{name}.type",
            f"must be one of {', '.join(kinds)}, got {toml_text(kind)}"
            + (suggest(kind, list(kinds)) if isinstance(kind, str) else ""),
        )
    cls = kinds[kind]
    keys = {key.name: key for key in file_keys(cls)}
    every = ["type", *dict.fromkeys(key.name for c in kinds.values() for key in file_keys(c)), _DRIVEN]
    for key in table:
        if key not in every:
            fail(lines.of(k, key), f"{name}.{key}", "unknown key" + suggest(key, every))
        if key not in keys and key not in ("type", _DRIVEN):
            fail(
                lines.of(k, key),
                f"{name}.{key}",
                f"not a key of {_a(kind)} wheel ({_a(kind)} wheel takes {', '.join(['type', *keys])})",
            )
    fields = {}
    for key in keys.values():
        if key.name not in table:
            fail(lines.of(k), f"{name}.{key.name}", f"missing ({key.meaning})")
        try:
            fields[key.field] = key.read(table[key.name])
        except InputError as exc:
            fail(lines.of(k, key.name), f"{name}.{key.name}", str(exc))
    if _DRIVEN in table:
        fields["driven"] = _driven(table[_DRIVEN], cls, (lines.of(k, _DRIVEN), f"{name}.{_DRIVEN}"), fail)
    try:
        return cls(**fields)
    except InputError as exc:  # the key whose field the message names first, else the table
        first = str(exc).split(" ", 1)[0]
        at = next((key.name for key in keys.values() if key.field == first), None)
        fail(lines.of(k, at), f"{name}.{at}" if at else name, str(exc))


def loads(text: str, source: str = "<string>") -> Robot:
    """The robot described by the TOML text of a robot file.

    Parameters
    ----------
    text : str
        The file's contents (schema: module notes).
    source : str, optional
        The name used in error messages.

    Returns
    -------
    Robot

    Raises
    ------
    RobotFileError
        If the text is not TOML or does not describe a robot (one line: ``FILE:LINE: key: what``).
    TypeError
        If ``text`` or ``source`` is not a string.

    Examples
    --------
    >>> loads('[[wheel]]\\ntype = "centred"\\nposition = [0, 0]\\nradius = 0.1\\n')
    Robot('robot': centred@(0.0, 0.0))
    >>> loads('[[wheel]]\\ntype = "centred"\\nposition = [0, 0]\\n', "bot.toml")
    Traceback (most recent call last):
    ...
    wmr.errors.RobotFileError: bot.toml:1: wheel[1].radius: missing (the wheel radius in metres, > 0)
    """
    if not isinstance(text, str):
        raise InputTypeError(f"text must be the TOML text of a robot file (str), got {validation.show(text)}")
    if not isinstance(source, str):
        raise InputTypeError(f"source must be a file name (str), got {validation.show(source)}")
    text = text.removeprefix("\ufeff")  # a byte-order mark (some editors write one)
    lines = _Lines(text)

    def fail(line: int, key: str, reason: str) -> NoReturn:
        raise RobotFileError(source, line, key, reason)

    def too_many(count: int, line: int) -> None:  # before any work: parsing, units, the robot
        try:
            check("wheels", count, "the file")
        except LimitError as exc:
            fail(line, "wheel", str(exc))

    most = limit("wheels")
    too_many(len(lines.wheels), lines.wheels[most][0] if len(lines.wheels) > most else 1)

    try:
        data, msg = tomllib.loads(text), None
    except tomllib.TOMLDecodeError as exc:
        data, msg = None, str(exc)
    if msg is not None:  # outside the except: no chained traceback
        m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
        line = int(m.group(1)) if m else lines.end
        head = re.sub(r"\s*\(at .*\)$", "", msg) + (" (a key given twice?)" if "overwrite" in msg else "")
        where = f" at column {m.group(2)}" if m else " at the end of the file"
        at = _KEY.match(text.splitlines()[line - 1]) if text.splitlines() else None
        key = lines.key_at(line, at.group(1).strip("\"'")) if at else "syntax"
        fail(line, key, f"TOML syntax error: {head.lower()}{where}")
    assert data is not None
    for key in data:
        if key not in _TOP_KEYS:
            fail(
                lines.of(None, key),
                key,
                "unknown key" + suggest(key, _TOP_KEYS) + " (a robot file holds name and [[wheel]] tables)",
            )
    name = data.get("name", "robot" if source.startswith("<") else Path(source).stem or "robot")
    if not isinstance(name, str):
        fail(lines.of(None, "name"), "name", f"must be a string, got {toml_text(name)}")
    tables = data.get("wheel", [])
    if not isinstance(tables, list):
        fail(lines.of(None, "wheel"), "wheel", f"must be [[wheel]] tables, got {toml_text(tables)}")
    if not tables:
        fail(lines.of(None, "wheel"), "wheel", "no wheels: a robot needs at least one [[wheel]] table")
    too_many(len(tables), lines.of(None, "wheel"))
    units = [_wheel(k, t, lines, fail) for k, t in enumerate(tables)]
    points = np.array([u.position for u in units], dtype=float)
    size = float(np.abs(points).max())
    for k in range(1, len(units)):
        same = np.flatnonzero(near_zero(np.abs(points[:k] - points[k]).max(axis=1), size))
        if same.size:
            fail(
                lines.of(k, "position"),
                f"wheel[{k + 1}].position",
                f"the same mount point as wheel[{same[0] + 1}] "
                f"({points[k, 0]:g}, {points[k, 1]:g}): two units cannot share a steering axis",
            )
    try:
        return Robot(units, name=name)
    except InputError as exc:
        fail(lines.of(None, "wheel"), "wheel", str(exc))


def load(path: PathLike) -> Robot:
    """The robot described by a robot file (TOML).

    Parameters
    ----------
    path : str or os.PathLike
        The file (schema: module notes).

    Returns
    -------
    Robot
        Named by the file's ``name`` (default: the file's name without its suffix).

    Raises
    ------
    RobotFileError
        If the file is malformed; one line, ``FILE:LINE: key: what is wrong``.
    OSError
        If the file cannot be read.
    TypeError
        If ``path`` is not a path.
    """
    validation.file_path(path)
    raw = Path(path).read_bytes()
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        raise RobotFileError(os.fspath(path), line, "file", "not UTF-8 text (TOML files are UTF-8)") from None
    return loads(text, os.fspath(path))


# ------------------------------------------------------------------------------------ writing
def _float(x, scale):
    """A float by :func:`wmr.io.decimals.float_text` at ``scale`` (TOML floats need a '.' or an exponent)."""
    text = float_text(x, scale)
    return text if any(c in text for c in ".eE") else text + ".0"


def _value(v, scale):
    """The TOML text of a number or a list of numbers, at ``scale`` (:mod:`wmr.io.decimals`)."""
    return "[" + ", ".join(_float(x, scale) for x in v) + "]" if isinstance(v, list) else _float(v, scale)


def dump(robot: Robot, path: PathLike | None = None) -> str:
    """The TOML text of a robot file for ``robot`` (and write it to ``path`` if given).

    ``load(path)`` of the result builds the same matrices within a rounding error: numbers are
    written by the rule of :mod:`wmr.io.decimals` (12 significant digits; lengths at the scale of the
    robot's size, angles in degrees at the scale of one radian), so the bytes are the same on every
    CPU.  Symbolic robots are written with their float values.

    Parameters
    ----------
    robot : Robot
        Any robot: every wheel kind declares its keys (:func:`~wmr.io.wheel_tables.wheel_keys`).
    path : str or os.PathLike, optional
        Where to write the text (UTF-8).

    Returns
    -------
    str
        The TOML text.

    Examples
    --------
    >>> import wmr
    >>> print(dump(wmr.Robot([wmr.CentredWheel((0.3, 0.0), r=0.05)], name="one wheel")))
    # wmr robot file: lengths in metres, angles in degrees (schema: wmr.io)
    name = "one wheel"
    <BLANKLINE>
    [[wheel]]
    type = "centred"
    position = [0.3, 0.0]
    radius = 0.05
    <BLANKLINE>
    """
    robot = validation.robot(robot)
    validation.file_path(path, optional=True)
    robot = robot.numeric()
    out = [
        "# wmr robot file: lengths in metres, angles in degrees (schema: wmr.io)",
        f"name = {toml_string(robot.name)}",
    ]
    kinds, size = readable_kinds(), length_scale(robot)
    for k, u in enumerate(robot.wheels, 1):
        if kinds.get(u.kind) is not type(u):
            raise InputValueError(
                f"robot has wheel {k} of kind {u.kind!r} ({type(u).__name__}), which is not a registered wheel "
                f"kind with robot-file keys (wmr.io.wheel_tables.register): robot files cannot describe it "
                f"(kinds: {', '.join(kinds)})"
            )
        out += ["", "[[wheel]]", f"type = {toml_string(u.kind)}"]
        out += [f"{key.name} = {_value(key.write(u), DEGREES if key.degrees else size)}" for key in file_keys(type(u))]
        changed = [
            (j.name, j.driven) for j, default in zip(u.joints, u.JOINTS, strict=True) if j.driven != default.driven
        ]
        if changed:
            out.append(f"{_DRIVEN} = {{" + ", ".join(f"{n} = {'true' if d else 'false'}" for n, d in changed) + "}")
    text = "\n".join(out) + "\n"
    if path is not None:
        Path(path).write_text(text, encoding="utf-8")
    return text
