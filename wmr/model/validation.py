r"""Every input check of the package under one name (``from wmr.model import validation``), and the robot checks.

The checks of scalars, points, flags and arrays are those of :mod:`wmr.model.checks` (the rule of the
two exception types is stated there); this module adds the checks of a robot, which need
:class:`wmr.Robot`.  The analyses use this module; the modules a robot is built from (platform,
wheels, robot) use :mod:`~wmr.model.checks`.

Examples
--------
>>> positive("r", 0.1), finite_array("beta", [0.5, 1]).tolist()
(0.1, [0.5, 1.0])
"""

from __future__ import annotations

from ..errors import InputTypeError
from .checks import (  # noqa: F401  (the analyses' checks, called as validation.real, ...)
    batch_shape,
    file_path,
    finite_array,
    finite_float,
    flag,
    integer,
    kind_error,
    nonnegative,
    number,
    point,
    positive,
    real,
    show,
    symbolic_matrix,
    symbolic_vector,
    twist_array,
    twist_kind,
)
from .robot import Robot

__all__ = ["number", "positive", "finite_array", "numeric_robot"]


def robot(value: object, name: str = "robot") -> Robot:
    """``value`` if it is a :class:`wmr.Robot` instance (the class itself is refused with a hint)."""
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
        The argument's name, for the message.

    Returns
    -------
    Robot
        ``value`` itself, or its float counterpart for an exact robot.
    """
    value = robot(value, name)
    return value.numeric() if value.is_symbolic else value  # (an input error names free symbols)
