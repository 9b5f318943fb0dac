r"""How a wheel unit is written in a robot file: each kind's keys, what they mean, how they are read and written.

A wheel kind answers for its mathematics (:mod:`wmr.model.wheels`); how it is written in a file is this
module's.  Every kind has an entry here (:func:`register`): the keys of its ``[[wheel]]`` table, a
tuple of :class:`FileKey`, after the two every unit has, :data:`COMMON_KEYS` (``position`` and
``radius``); :mod:`wmr.io.toml` reads and writes robot files from these entries alone.  A key fills
one field of the unit: read with :meth:`FileKey.read` (checked, with a message that says what the
key means), written with :meth:`FileKey.write`.  Angles are written in degrees and held in radians.
A kind takes the entry of its nearest base class that has one (a subclass of
:class:`~wmr.model.wheels.unsteered.UnsteeredUnit` takes ``angle_deg``); :func:`has_file_keys` is what
the contract test asks of every kind.

Examples
--------
>>> key = FileKey("offset", "d", "the offset d in metres, >= 0", check="nonnegative")
>>> key.read(0.03)
0.03
>>> key.read(-1)
Traceback (most recent call last):
    ...
wmr.errors.InputValueError: must not be negative (the offset d in metres, >= 0), got -1
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..errors import InputTypeError, InputValueError
from ..model.checks import show
from ..model.wheels import CentredWheel, DualWheel, OffsetWheel, SwedishWheel, WheelUnit, wheel_kinds
from ..model.wheels.unsteered import UnsteeredUnit

__all__ = ["FileKey", "COMMON_KEYS", "register", "file_keys", "wheel_keys"]

_CHECKS = ("number", "positive", "nonnegative", "pair")
_ESCAPES = {'"': '\\"', "\\": "\\\\", "\n": "\\n", "\t": "\\t"}


def toml_string(s: str) -> str:
    """A TOML basic string (control characters escaped)."""
    return (
        '"'
        + "".join(_ESCAPES.get(c) or (f"\\u{ord(c):04X}" if ord(c) < 0x20 or ord(c) == 0x7F else c) for c in s)
        + '"'
    )


def toml_text(v: Any) -> str:
    """A short TOML-like text of a value read from a TOML file (for messages): strings cut at 40, lists at 4."""
    if isinstance(v, str):
        return toml_string(v) if len(v) < 40 else toml_string(v[:37] + "...")
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, list):
        return "[" + ", ".join(toml_text(x) for x in v[:4]) + (", ...]" if len(v) > 4 else "]")
    if isinstance(v, dict):
        return "a table"
    return show(v, 40)


def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


@dataclass(frozen=True)
class FileKey:
    """One key of a ``[[wheel]]`` table, and the field of the unit it fills.

    Parameters
    ----------
    name : str
        The key in the file, e.g. ``"half_separation"``.
    field : str
        The unit's field it fills, e.g. ``"b"``.
    meaning : str
        What it holds, with its unit, for messages: ``"half the wheel separation b in metres, > 0"``.
    check : {"number", "positive", "nonnegative", "pair"}, optional
        What a value must be: a finite number, one > 0, one >= 0, or two numbers ``[x, y]``.
    degrees : bool, optional
        The file holds degrees, the unit radians.
    """

    name: str
    field: str
    meaning: str
    check: str = "number"
    degrees: bool = False

    def __post_init__(self) -> None:
        for what in ("name", "field", "meaning"):
            if not isinstance(getattr(self, what), str):
                raise InputTypeError(f"{what} must be a string, got {show(getattr(self, what))}")
        if self.check not in _CHECKS:
            raise InputValueError(f"check must be one of {', '.join(_CHECKS)}, got {show(self.check)}")

    def _number(self, v: Any) -> float:
        if not _is_number(v):
            raise InputValueError(f"must be a number ({self.meaning}), got {toml_text(v)}")
        if not math.isfinite(v):
            raise InputValueError(f"must be a finite number ({self.meaning}), got {toml_text(v)}")
        return float(v)

    def read(self, value: Any) -> Any:
        """The field's value from the value in the file, checked.

        Parameters
        ----------
        value : object
            As parsed from TOML.

        Returns
        -------
        float or tuple of 2 float
            In the unit's units (radians for an angle).

        Raises
        ------
        wmr.errors.InputValueError
            Saying what is wrong and what the key means (without the key: the caller adds where).
        """
        if self.check == "pair":
            if not isinstance(value, list) or len(value) != 2 or not all(_is_number(x) for x in value):
                raise InputValueError(f"must be two numbers [x, y] ({self.meaning}), got {toml_text(value)}")
            return tuple(self._number(x) for x in value)
        x = self._number(value)
        if self.check == "positive" and not x > 0:
            raise InputValueError(f"must be positive ({self.meaning}), got {toml_text(value)}")
        if self.check == "nonnegative" and x < 0:
            raise InputValueError(f"must not be negative ({self.meaning}), got {toml_text(value)}")
        if self.degrees and abs(x) > 360:
            raise InputValueError(f"must be within -360 .. 360 ({self.meaning}), got {toml_text(value)}")
        return math.radians(x) if self.degrees else x

    def write(self, unit: Any) -> float | list[float]:
        """The value to write for ``unit`` (a numeric unit: see :meth:`wmr.Robot.numeric`).

        Parameters
        ----------
        unit : WheelUnit

        Returns
        -------
        float or list of 2 float
            In the file's units (degrees for an angle).
        """
        value = getattr(unit, self.field)
        if self.check == "pair":
            return [float(v) for v in value]
        return math.degrees(value) if self.degrees else float(value)


#: the keys every ``[[wheel]]`` table has, before the kind's own
COMMON_KEYS = (
    FileKey("position", "position", "the mount point [x, y] in metres", check="pair"),
    FileKey("radius", "r", "the wheel radius in metres, > 0", check="positive"),
)

#: each kind's own keys (:func:`register`), by class
_KEYS: dict[type, tuple[FileKey, ...]] = {}


def register(kind: type, keys: tuple[FileKey, ...]) -> None:
    """Declare the keys of a wheel kind's table in a robot file, after :data:`COMMON_KEYS`.

    Parameters
    ----------
    kind : type
        A subclass of :class:`~wmr.model.wheels.WheelUnit`.
    keys : tuple of FileKey
        Its own keys (empty for a kind with none); each fills the field it names.

    Returns
    -------
    None

    Raises
    ------
    wmr.errors.InputTypeError
        If ``kind`` is not a wheel kind or a key is not a :class:`FileKey`.
    """
    if not (isinstance(kind, type) and issubclass(kind, WheelUnit)):
        raise InputTypeError(f"kind must be a subclass of WheelUnit, got {show(kind)}")
    keys = tuple(keys)
    if not all(isinstance(k, FileKey) for k in keys):
        raise InputTypeError(f"keys must be FileKey objects, got {show(keys)}")
    _KEYS[kind] = keys


def file_keys(kind: type) -> tuple[FileKey, ...]:
    """Every key of a kind's table in a robot file: :data:`COMMON_KEYS`, then its own.

    Parameters
    ----------
    kind : type
        A wheel kind with an entry (its own or a base class's).

    Returns
    -------
    tuple of FileKey

    Raises
    ------
    NotImplementedError
        For a kind without an entry (the message says how to register one).
    """
    for c in kind.__mro__:
        if c in _KEYS:
            return COMMON_KEYS + _KEYS[c]
    raise NotImplementedError(
        f"{kind.__name__} has no robot-file keys: register them with wmr.io.wheel_tables.register"
    )


def has_file_keys(kind: type) -> bool:
    """Whether a wheel kind has robot-file keys (its own entry or a base class's)."""
    return any(c in _KEYS for c in kind.__mro__)


def wheel_keys() -> dict[str, tuple[str, ...]]:
    """The keys of each wheel kind's table, as the kinds declare them (all required; ``driven`` is optional).

    Returns
    -------
    dict of str to tuple of str
        ``{kind: ("type", "position", "radius", its own keys...)}``, every registered kind.

    Examples
    --------
    >>> wheel_keys()["dual"]
    ('type', 'position', 'radius', 'half_separation')
    """
    return {kind: ("type",) + tuple(k.name for k in file_keys(cls)) for kind, cls in readable_kinds().items()}


def readable_kinds() -> dict[str, type]:
    """The registered wheel kinds that robot files can hold (those with keys here), ``{kind: class}``."""
    return {kind: cls for kind, cls in wheel_kinds().items() if has_file_keys(cls)}


register(CentredWheel, ())
register(OffsetWheel, (FileKey("offset", "d", "the offset d in metres, >= 0", check="nonnegative"),))
register(DualWheel, (FileKey("half_separation", "b", "half the wheel separation b in metres, > 0", check="positive"),))
_ANGLE = FileKey("angle_deg", "angle", "the steering angle in degrees", degrees=True)
register(UnsteeredUnit, (_ANGLE,))  # a fixed wheel, and any kind at a constant angle
register(
    SwedishWheel,
    (_ANGLE, FileKey("roller_deg", "roller", "the roller angle in degrees (90 omni, 45 mecanum)", degrees=True)),
)
