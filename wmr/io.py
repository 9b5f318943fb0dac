r"""Robot files: a robot is a small TOML file; :func:`load` reads one, :func:`dump` writes one.

The schema (lengths in metres, or any one unit: every decision of :mod:`wmr` is the same in every
unit; angles in degrees)::

    name = "paper, three centred wheels"     # optional (default: the file's name)

    [[wheel]]                 # one table per wheel unit, wheel 1 first (the numbering of wmr.Robot)
    type = "centred"          # "fixed" | "centred" | "offset" | "dual" | "swedish"
    position = [-0.3, 0.0]    # the mount point d_i = CP_i, body frame, from the operation point C
    radius = 0.05             # the wheel radius r, > 0
    # offset = 0.03           # offset (castor) wheels: the offset d >= 0
    # half_separation = 0.1   # dual wheels: half the distance b > 0 between the two wheels
    # angle_deg = 90.0        # fixed and swedish wheels: the steering angle beta of wmr's conventions
    #                         #   (0: axle along the body x axis, the wheel rolls along body y)
    # roller_deg = 45.0       # swedish wheels: angle between the roller axes and the wheel axle
    #                         #   (90: omni wheel, 45: mecanum wheel)

Each type takes exactly its keys (:data:`KEYS`).  A malformed file raises :class:`RobotFileError`,
whose message is one line, ``FILE:LINE: key: what is wrong``; wheels are named ``wheel[k]`` with
``k`` counted from 1, as the paper numbers them.

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

import difflib
import math
import os
import re
import tomllib
from pathlib import Path

import numpy as np

from .model import validation as V
from .model.tolerance import near_zero
from .model.wheels import CentredWheel, DualWheel, FixedWheel, OffsetWheel, SwedishWheel

__all__ = ["RobotFileError", "KEYS", "load", "loads", "dump"]

#: the keys each wheel type takes (all of them are required)
KEYS = {
    "fixed": ("type", "position", "radius", "angle_deg"),
    "centred": ("type", "position", "radius"),
    "offset": ("type", "position", "radius", "offset"),
    "dual": ("type", "position", "radius", "half_separation"),
    "swedish": ("type", "position", "radius", "angle_deg", "roller_deg"),
}
_ALL_KEYS = ("type", "position", "radius", "offset", "half_separation", "angle_deg", "roller_deg")
_TOP_KEYS = ("name", "wheel")
#: what each key holds, for the messages
_MEANING = {"position": "the mount point [x, y] in metres", "radius": "the wheel radius in metres, > 0",
            "offset": "the offset d in metres, >= 0", "half_separation": "half the wheel separation b in metres, > 0",
            "angle_deg": "the steering angle in degrees", "roller_deg": "the roller angle in degrees (90 omni, 45 mecanum)"}


class RobotFileError(ValueError):
    """A malformed robot file; ``str(error)`` is one line: ``FILE:LINE: key: what is wrong``.

    Parameters
    ----------
    file : str
        The file's name as given.
    line : int
        The line (from 1) of the offending key or table.
    key : str
        The offending key, e.g. ``wheel[2].radius``.
    reason : str
        What is wrong.
    """

    def __init__(self, file, line, key, reason):
        self.file, self.line, self.key, self.reason = file, line, key, " ".join(str(reason).split())
        super().__init__(f"{file}:{line}: {key}: {self.reason}")


# ------------------------------------------------------------------------------------- lines
_WHEEL_HEADER = re.compile(r"""^\s*\[\[\s*(wheel|"wheel"|'wheel')\s*\]\]""")
_HEADER = re.compile(r"^\s*\[")
_KEY = re.compile(r"""^\s*("[^"]*"|'[^']*'|[A-Za-z0-9_-]+)\s*[=.]""")


class _Lines:
    """Where the keys are in the text: the line of each top-level key, wheel table and wheel key."""

    def __init__(self, text):
        self.top, self.wheels = {}, []          # wheels: [(header line, {key: line})]
        where = self.top
        for n, line in enumerate(text.splitlines(), 1):
            if _WHEEL_HEADER.match(line):
                self.wheels.append((n, {}))
                where = self.wheels[-1][1]
            elif _HEADER.match(line):
                where = {}
            else:
                m = _KEY.match(line)
                if m:
                    where.setdefault(m.group(1).strip("\"'"), n)
        self.end = max(1, len(text.splitlines()))

    def of(self, k=None, key=None):
        """Line of ``key`` in wheel ``k`` (0-based; None: top level), else of the wheel's table, else 1."""
        if k is None:
            return self.top.get(key, 1)
        if k < len(self.wheels):
            head, keys = self.wheels[k]
            return keys.get(key, head)
        return self.top.get("wheel", 1)             # an inline array of tables: the line of `wheel =`


# ------------------------------------------------------------------------------------ values
def _is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _number(v, what):
    if not _is_number(v):
        raise ValueError(f"must be a number ({what}), got {_toml(v)}")
    if not math.isfinite(v):
        raise ValueError(f"must be a finite number ({what}), got {_toml(v)}")
    return float(v)


def _check(key, v):
    """The value of wheel key ``key`` as the wheel classes take it, or ValueError saying what is wrong."""
    if key == "position":
        if not isinstance(v, list) or len(v) != 2 or not all(_is_number(x) for x in v):
            raise ValueError(f"must be two numbers [x, y] ({_MEANING[key]}), got {_toml(v)}")
        return tuple(_number(x, _MEANING[key]) for x in v)
    x = _number(v, _MEANING[key])
    if key in ("radius", "half_separation") and not x > 0:
        raise ValueError(f"must be positive ({_MEANING[key]}), got {_toml(v)}")
    if key == "offset" and x < 0:
        raise ValueError(f"must not be negative ({_MEANING[key]}), got {_toml(v)}")
    return x


def _toml(v):
    """A short TOML-like text of a parsed value."""
    if isinstance(v, str):
        return _string(v) if len(v) < 40 else _string(v[:37] + "...")
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, list):
        return "[" + ", ".join(_toml(x) for x in v[:4]) + (", ...]" if len(v) > 4 else "]")
    if isinstance(v, dict):
        return "a table"
    return V.show(v, 40)


def _a(kind):
    return ("an " if kind[0] in "aeiou" else "a ") + kind


def _suggest(word, choices):
    close = difflib.get_close_matches(word, choices, n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


# ------------------------------------------------------------------------------------ reading
def _unit(kind, values):
    cls = {"fixed": FixedWheel, "centred": CentredWheel, "offset": OffsetWheel, "dual": DualWheel,
           "swedish": SwedishWheel}[kind]
    p, r = values["position"], values["radius"]
    if kind == "offset":
        return cls(p, r=r, d=values["offset"])
    if kind == "dual":
        return cls(p, r=r, b=values["half_separation"])
    if kind == "fixed":
        return cls(p, r, math.radians(values["angle_deg"]))
    if kind == "swedish":
        return cls(p, r, math.radians(values["angle_deg"]), math.radians(values["roller_deg"]))
    return cls(p, r=r)


def _wheel(k, table, lines, fail):
    """The wheel unit of the k-th ``[[wheel]]`` table (0-based ``k``)."""
    name = f"wheel[{k + 1}]"
    if not isinstance(table, dict):
        fail(lines.of(k), name, f"must be a table ([[wheel]]), got {_toml(table)}")
    if "type" not in table:
        fail(lines.of(k), f"{name}.type", f"missing (one of {', '.join(KEYS)})")
    kind = table["type"]
    if not isinstance(kind, str) or kind not in KEYS:
        fail(lines.of(k, "type"), f"{name}.type", f"must be one of {', '.join(KEYS)}, got {_toml(kind)}"
             + (_suggest(kind, KEYS) if isinstance(kind, str) else ""))
    for key in table:
        if key not in _ALL_KEYS:
            fail(lines.of(k, key), f"{name}.{key}", "unknown key" + _suggest(key, _ALL_KEYS))
        if key not in KEYS[kind]:
            fail(lines.of(k, key), f"{name}.{key}",
                 f"not a key of {_a(kind)} wheel ({_a(kind)} wheel takes {', '.join(KEYS[kind])})")
    values = {}
    for key in KEYS[kind][1:]:
        if key not in table:
            fail(lines.of(k), f"{name}.{key}", f"missing ({_MEANING[key]})")
        try:
            values[key] = _check(key, table[key])
        except ValueError as exc:
            fail(lines.of(k, key), f"{name}.{key}", str(exc))
    try:
        return _unit(kind, values)
    except (ValueError, TypeError) as exc:
        fail(lines.of(k), name, str(exc))


def loads(text, source="<string>"):
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
    wmr.io.RobotFileError: bot.toml:1: wheel[1].radius: missing (the wheel radius in metres, > 0)
    """
    if not isinstance(text, str):
        raise TypeError(f"text must be the TOML text of a robot file (str), got {V.show(text)}")
    if not isinstance(source, str):
        raise TypeError(f"source must be a file name (str), got {V.show(source)}")
    from .model.robot import Robot
    lines = _Lines(text)

    def fail(line, key, reason):
        raise RobotFileError(source, line, key, reason)

    try:
        data, msg = tomllib.loads(text), None
    except tomllib.TOMLDecodeError as exc:
        data, msg = None, str(exc)
    if msg is not None:                                   # outside the except: no chained traceback
        m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
        line = int(m.group(1)) if m else lines.end
        head = re.sub(r"\s*\(at .*\)$", "", msg) + (" (a key given twice?)" if "overwrite" in msg else "")
        where = f" at column {m.group(2)}" if m else " at the end of the file"
        key = _KEY.match(text.splitlines()[line - 1]) if text.splitlines() else None
        fail(line, key.group(1).strip("\"'") if key else "syntax", f"TOML syntax error: {head.lower()}{where}")
    for key in data:
        if key not in _TOP_KEYS:
            fail(lines.of(None, key), key, "unknown key" + _suggest(key, _TOP_KEYS)
                 + " (a robot file holds name and [[wheel]] tables)")
    name = data.get("name", "robot" if source.startswith("<") else Path(source).stem or "robot")
    if not isinstance(name, str):
        fail(lines.of(None, "name"), "name", f"must be a string, got {_toml(name)}")
    tables = data.get("wheel", [])
    if not isinstance(tables, list):
        fail(lines.of(None, "wheel"), "wheel", f"must be [[wheel]] tables, got {_toml(tables)}")
    if not tables:
        fail(lines.of(None, "wheel"), "wheel", "no wheels: a robot needs at least one [[wheel]] table")
    units = [_wheel(k, t, lines, fail) for k, t in enumerate(tables)]
    points = np.array([u.position for u in units], dtype=float)
    size = float(np.abs(points).max())
    for k in range(1, len(units)):
        same = np.flatnonzero(near_zero(np.abs(points[:k] - points[k]).max(axis=1), size))
        if same.size:
            fail(lines.of(k, "position"), f"wheel[{k + 1}].position", f"the same mount point as wheel[{same[0] + 1}] "
                 f"({points[k, 0]:g}, {points[k, 1]:g}): two units cannot share a steering axis")
    try:
        return Robot(units, name=name)
    except (ValueError, TypeError) as exc:
        fail(lines.of(None, "wheel"), "wheel", str(exc))


def load(path):
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
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path must be a file name (str or os.PathLike), got {V.show(path)}")
    raw = Path(path).read_bytes()
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[:exc.start].count(b"\n") + 1
        raise RobotFileError(os.fspath(path), line, "file", "not UTF-8 text (TOML files are UTF-8)") from None
    return loads(text, os.fspath(path))


# ------------------------------------------------------------------------------------ writing
_ESCAPES = {'"': '\\"', "\\": "\\\\", "\n": "\\n", "\t": "\\t"}


def _string(s):
    """A TOML basic string (control characters escaped)."""
    return '"' + "".join(_ESCAPES.get(c) or (f"\\u{ord(c):04X}" if ord(c) < 0x20 or ord(c) == 0x7F else c)
                         for c in s) + '"'


def _float(x):
    """The shortest text that reads back as the same double (TOML floats need a '.' or an exponent)."""
    text = repr(float(x))
    return text if any(c in text for c in ".eE") else text + ".0"


def dump(robot, path=None):
    """The TOML text of a robot file for ``robot`` (and write it to ``path`` if given).

    ``load(path)`` of the result builds the same matrices (angles go through degrees, within a
    rounding error).  Symbolic robots are written with their float values.

    Parameters
    ----------
    robot : Robot
        Its wheel units must be of a type of the schema (:data:`KEYS`).
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
    robot = V.robot(robot)
    if path is not None and not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path must be a file name (str or os.PathLike) or None, got {V.show(path)}")
    robot = robot.numeric()
    out = ["# wmr robot file: lengths in metres, angles in degrees (schema: wmr.io)", f"name = {_string(robot.name)}"]
    for k, u in enumerate(robot.wheels, 1):
        if u.kind not in KEYS:
            raise ValueError(f"robot has wheel {k} of kind {u.kind!r}, which robot files cannot describe "
                             f"(types: {', '.join(KEYS)})")
        x, y = u.position
        out += ["", "[[wheel]]", f"type = {_string(u.kind)}", f"position = [{_float(x)}, {_float(y)}]",
                f"radius = {_float(u.r)}"]
        if u.kind == "offset":
            out.append(f"offset = {_float(u.d)}")
        elif u.kind == "dual":
            out.append(f"half_separation = {_float(u.b)}")
        if u.kind in ("fixed", "swedish"):
            out.append(f"angle_deg = {_float(math.degrees(u.angle))}")
        if u.kind == "swedish":
            out.append(f"roller_deg = {_float(math.degrees(u.roller))}")
    text = "\n".join(out) + "\n"
    if path is not None:
        Path(path).write_text(text, encoding="utf-8")
    return text
