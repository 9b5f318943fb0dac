r"""Input checks for robots: a :class:`wmr.Robot` instance, a numeric one, and the symbols in one.

The rule of the two exception types and the scalar checks are in :mod:`wmr.model.validation`
(which also gives access to these: ``validation.robot``).
"""
from __future__ import annotations

import dataclasses

import sympy as sp

from .validation import _kind_error, show

__all__ = ["robot", "numeric_robot", "free_symbols"]


def robot(value, name="robot"):
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
    TypeError: robot must be a wmr.Robot instance, got the class Robot itself (build one, e.g. wmr.Robot([...]) or wmr.paper_robot())
    """
    from .robot import Robot
    if isinstance(value, Robot):
        return value
    if isinstance(value, type) and issubclass(value, Robot):
        raise TypeError(f"{name} must be a wmr.Robot instance, got the class {value.__name__} itself "
                        "(build one, e.g. wmr.Robot([...]) or wmr.paper_robot())")
    raise _kind_error(name, value, "a wmr.Robot")


def numeric_robot(value, name="robot"):
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
        raise ValueError(f"{name} must have numeric mount points and lengths here, got a robot with the symbols "
                         f"{sorted(map(str, free_symbols(value)))}: {show(value)}")
    return value.numeric() if value.is_symbolic else value


def free_symbols(robot):
    """The SymPy symbols in a robot's mount points and lengths (empty for numeric and exact robots).

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    set of sympy.Symbol
    """
    out = set()
    for u in robot.wheels:
        for f in dataclasses.fields(u):
            v = getattr(u, f.name)
            for e in (v if isinstance(v, tuple) else (v,)):
                if isinstance(e, sp.Basic):
                    out |= e.free_symbols
    return out
