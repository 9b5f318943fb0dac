r"""Input checks for robots: a :class:`wmr.Robot` instance, a numeric one, and the symbols in one.

The rule of the two exception types and the scalar checks are in :mod:`wmr.model.checks`;
:mod:`wmr.model.validation` gathers these with them (``validation.numeric_robot``).
"""

from __future__ import annotations

from ..errors import InputTypeError, InputValueError
from .checks import kind_error, show
from .robot import Robot
from .types import Symbolic

__all__ = ["robot", "numeric_robot", "free_symbols"]


def robot(value: object, name: str = "robot") -> Robot:
    """Return ``value`` if it is a :class:`wmr.Robot` instance.

    Parameters
    ----------
    value : object
    name : str, optional

    Returns
    -------
    Robot

    Examples
    --------
    >>> from wmr.model.robot import Robot
    >>> robot(Robot)
    Traceback (most recent call last):
        ...
    wmr.errors.InputTypeError: robot must be a wmr.Robot instance, got the class Robot itself (build one, ...)
    """
    if isinstance(value, Robot):
        return value
    if isinstance(value, type) and issubclass(value, Robot):
        raise InputTypeError(
            f"{name} must be a wmr.Robot instance, got the class {value.__name__} itself "
            "(build one, e.g. wmr.Robot([...]) or wmr.paper_robot())"
        )
    raise kind_error(name, value, "a wmr.Robot")


def numeric_robot(value: object, name: str = "robot") -> Robot:
    """Return ``value`` if it is a :class:`wmr.Robot` without free symbols, as floats (:meth:`wmr.Robot.numeric`).

    Parameters
    ----------
    value : object
    name : str, optional

    Returns
    -------
    Robot
        ``value`` itself, or its float counterpart for an exact robot.
    """
    value = robot(value, name)
    if free_symbols(value):
        raise InputValueError(
            f"{name} must have numeric mount points and lengths here, got a robot with the symbols "
            f"{sorted(map(str, free_symbols(value)))}: {show(value)}"
        )
    return value.numeric() if value.is_symbolic else value


def free_symbols(robot: Robot) -> set[Symbolic]:
    """The SymPy symbols in a robot's mount points and lengths (empty for numeric and exact robots).

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    set of sympy.Symbol
        :attr:`wmr.Robot.free_symbols`.
    """
    return robot.free_symbols
