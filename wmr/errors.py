"""The exceptions wmr raises on purpose: one base class, and bad input told apart from a bug.

Every check of wmr's input raises an :class:`InputError` that is also the built-in exception a caller
expects (as python-control's ``ControlArgument(TypeError)``): :class:`InputTypeError` is a ``TypeError`` (the wrong
kind of thing), :class:`InputValueError` a ``ValueError`` (the right kind with a bad value), and their subclasses
say more.  So ``except ValueError`` still catches a bad value, and ``except wmr.errors.InputError`` catches bad
input and nothing else: any other exception out of wmr is a bug in wmr.  The command line (:func:`wmr.cli.main`)
relies on this: input errors become one line and exit status 2, anything else shows its traceback.

Examples
--------
>>> import wmr
>>> try:
...     wmr.CentredWheel((0.0, 0.0), r=-1.0)
... except InputError as exc:
...     print(type(exc).__name__, isinstance(exc, ValueError), exc)
InputValueError True r (wheel radius) must be positive, got -1.0
"""

from __future__ import annotations

__all__ = [
    "WmrError",
    "InputError",
    "InputTypeError",
    "InputValueError",
    "FrozenError",
    "RobotFileError",
    "LimitError",
    "MissingDependencyError",
]


class WmrError(Exception):
    """Base class of every exception wmr raises on purpose."""


class InputError(WmrError):
    """Bad input to wmr (an argument, an option or a file); its message names what is wrong and shows the value."""


class InputTypeError(InputError, TypeError):
    """An argument of the wrong kind (a string, a bool, ``None``, a symbol where a number is needed, ...)."""


class InputValueError(InputError, ValueError):
    """An argument of the right kind with a bad value (negative radius, NaN, wrong shape, too large, ...)."""


class FrozenError(InputTypeError, AttributeError):
    """An assignment to (or deletion of) an attribute of an immutable value, such as a robot's ``wheels``.

    A :class:`~wmr.model.robot.Robot` is checked once, when it is made, and what is derived from it
    is kept on it; the message says what to do instead (build a new robot).
    """


class RobotFileError(InputValueError):
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

    def __init__(self, file: str, line: int, key: str, reason: object) -> None:
        self.file, self.line, self.key, self.reason = file, line, key, " ".join(str(reason).split())
        super().__init__(f"{file}:{line}: {key}: {self.reason}")


class LimitError(InputValueError):
    """A request beyond a limit (:mod:`wmr.model.limits`): its message names the limit and how to raise it."""


class MissingDependencyError(WmrError, ImportError):
    """An optional package that this call needs is not installed; the message names the extra that installs it."""
