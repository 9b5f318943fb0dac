r"""The registry of wheel kinds: filled by defining them (:class:`~wmr.model.wheels.unit.WheelUnit` subclasses).

A subclass of :class:`~wmr.model.wheels.unit.WheelUnit` that sets ``kind`` is registered under that
name when its class is defined (:func:`register`); :func:`wheel_kinds` and :func:`wheel_kind` read
the registry, which is how :class:`wmr.Robot`, :mod:`wmr.io` and the messages know every kind
without a list written by hand.
"""

from __future__ import annotations

from typing import Any

from ...errors import InputValueError
from .. import checks

__all__ = ["wheel_kinds", "wheel_kind"]

_KINDS: dict[str, Any] = {}  # kind -> its class (a WheelUnit subclass)


def wheel_kinds() -> dict[str, Any]:
    """Every registered wheel kind: ``{kind: class}``, by name (the order in which messages list them).

    Returns
    -------
    dict of str to type

    Examples
    --------
    >>> list(wheel_kinds())[:3]
    ['centred', 'dual', 'fixed']
    """
    return dict(sorted(_KINDS.items()))


def wheel_kind(name: str) -> Any:
    """The class of the wheel kind ``name`` (the ``type`` of a robot file's ``[[wheel]]`` table).

    Parameters
    ----------
    name : str

    Returns
    -------
    type
        A subclass of :class:`WheelUnit`.

    Examples
    --------
    >>> wheel_kind("centred").__name__
    'CentredWheel'
    >>> wheel_kind("centered")
    Traceback (most recent call last):
        ...
    wmr.errors.InputValueError: kind must be one of ..., got 'centered' (did you mean 'centred'?)
    """
    if not isinstance(name, str):
        raise checks.kind_error("kind", name, f"a wheel kind ({', '.join(sorted(_KINDS))})")
    if name not in _KINDS:
        raise InputValueError(
            f"kind must be one of {', '.join(sorted(_KINDS))}, got {name!r}" + checks.suggest(name, sorted(_KINDS))
        )
    return _KINDS[name]


def register(cls: type) -> None:
    """Register the wheel kind ``cls`` under ``cls.kind`` (when its class is defined); a kind's name is taken once.

    A class defined again (on reloading its module) replaces itself.
    """
    kind = getattr(cls, "kind", "")
    if kind in _KINDS and _KINDS[kind].__qualname__ != cls.__qualname__:
        raise InputValueError(
            f"wheel kind {kind!r} is already {_KINDS[kind].__name__}: {cls.__name__} needs another name"
        )
    _KINDS[kind] = cls
