"""Names that moved out of the wheel kinds (issue 29), kept for one release with a warning naming the new place.

A wheel kind answers for its mathematics only; its drawing, its robot-file keys, its bodies and joints and
its design hints moved to the layers that use them.  ``import wmr`` imports this module, which puts the old methods
back on :class:`~wmr.model.wheels.WheelUnit` (each warns with a :class:`DeprecationWarning` and calls
its replacement) and the old modules' names in :data:`sys.modules`:

=============================================  ===================================================================
before                                         now
=============================================  ===================================================================
``unit.parts(beta)``                           :func:`wmr.plot.parts.unit_parts` ``(unit, beta)``
``unit.drawn_angle(beta)``                     :func:`wmr.plot.parts.drawn_angle` ``(unit, beta)``
``Kind.file_keys()``, ``Kind.FILE_KEYS``       :func:`wmr.io.wheel_tables.file_keys` ``(Kind)``, ``register``
``unit.dead_zone()``                           :func:`wmr.analysis.unit_design.dead_zone` ``(unit)``
``unit.isotropy_advice()``                     :func:`wmr.words.advice.change` of ``isotropic_change(unit)``
``unit.isotropic_variant()``                   :func:`wmr.analysis.unit_design.isotropic_change` ``(unit).unit``
``unit.other_builds()``                        :func:`wmr.analysis.unit_design.other_builds` ``(unit)``
``unit.mechanism(height)``                     :func:`wmr.io.mechanism.mechanism` ``(unit, height)``
``unit.root_body(height)``                     :func:`wmr.io.mechanism.root_body` ``(unit, height)``
``wmr.model.wheels.parts``                     :mod:`wmr.plot.parts`
``wmr.model.wheels.filekeys``                  :mod:`wmr.io.wheel_tables`
``wmr.model.wheels.mechanism``                 :mod:`wmr.io.mechanism` (``UnitMechanism``: no base class any more)
``wmr.model.wheels.swedish.NO_FAITHFUL...``    :data:`wmr.io.mechanism.NO_FAITHFUL_MECHANISM`
``wmr.model.wheels.design.DesignHints``        :mod:`wmr.analysis.unit_design` (no base class any more)
``Change.words``                               :func:`wmr.words.advice.change` ``(change)``
``Advice.text``                                :func:`wmr.words.advice.sentence` ``(advice)``
``wmr.analysis.actuation.describe_twist``      :func:`wmr.words.limitations.describe_twist`
``wmr.analysis.glossary``                      :mod:`wmr.words.glossary`
``wmr.analysis.families.FAMILIES, MEANINGS``   :mod:`wmr.words.families` (``description``, ``meaning``)
``wmr.sim.Sample``                             :class:`wmr.sim.Reading` (the sweeps' ``Sample`` is another thing)
``wmr.model.types.Twist`` (a type alias)       ``wmr.model.types.TwistLike`` (:class:`wmr.Twist` is the named twist)
``wmr.simulate``, ``wmr.analysis.simulation``  :func:`wmr.integrate`, :mod:`wmr.analysis.integration` (``wmr simulate`` is MuJoCo)
=============================================  ===================================================================
"""

from __future__ import annotations

import sys
import warnings
from collections.abc import Callable
from typing import Any

from .analysis import actuation, advice, families, integration, overview, unit_design
from .io import mechanism, wheel_tables
from .model import types
from .model.wheels import WheelUnit, swedish
from .plot import parts
from .words import advice as advice_words
from .words import families as family_words
from .words import glossary
from .words import limitations as limitation_words

__all__ = ["MOVED", "simulate"]

#: old name -> its replacement, as the warnings name them
MOVED = {
    "WheelUnit.parts(beta)": "wmr.plot.parts.unit_parts(unit, beta)",
    "WheelUnit.drawn_angle(beta)": "wmr.plot.parts.drawn_angle(unit, beta)",
    "WheelUnit.file_keys()": "wmr.io.wheel_tables.file_keys(kind)",
    "WheelUnit.dead_zone()": "wmr.analysis.unit_design.dead_zone(unit)",
    "WheelUnit.isotropy_advice()": "wmr.words.advice.change(wmr.analysis.unit_design.isotropic_change(unit))",
    "WheelUnit.isotropic_variant()": "wmr.analysis.unit_design.isotropic_change(unit).unit",
    "WheelUnit.other_builds()": "wmr.analysis.unit_design.other_builds(unit), Change(kind, unit) objects",
    "WheelUnit.mechanism(height)": "wmr.io.mechanism.mechanism(unit, height)",
    "WheelUnit.root_body(height)": "wmr.io.mechanism.root_body(unit, height) (register a kind's with root_body.register)",
    "Change.words": "wmr.words.advice.change(change)",
    "Advice.text": "wmr.words.advice.sentence(advice)",
}


def _warn(old: str) -> None:
    warnings.warn(f"{old} is deprecated: use {MOVED[old]}", DeprecationWarning, stacklevel=3)


def _method(old: str, new: Callable[..., Any]) -> Callable[..., Any]:
    """The old method: warns, then calls ``new`` with the unit (and the one argument the old method took)."""
    arg = old[old.index("(") + 1 : -1]
    returns = "Returns\n-------\nobject\n    What the replacement returns.\n"
    if arg:

        def method(self: Any, value: Any) -> Any:
            _warn(old)
            return new(self, value)

        method.__doc__ = (
            f"Deprecated: {MOVED[old]}.\n\nParameters\n----------\nvalue : object\n    ``{arg}``.\n\n{returns}"
        )
        return method

    def plain(self: Any) -> Any:
        _warn(old)
        return new(self)

    plain.__doc__ = f"Deprecated: {MOVED[old]}.\n\n{returns}"
    return plain


def _words(unit: Any) -> str | None:
    change = unit_design.isotropic_change(unit)
    return None if change is None else advice_words.change(change)


def _variant(unit: Any) -> Any:
    change = unit_design.isotropic_change(unit)
    return None if change is None else change.unit


def _builds(unit: Any) -> tuple[tuple[str, Any], ...]:
    return tuple((advice_words.change(c), c.unit) for c in unit_design.other_builds(unit))


for _old, _new in (
    ("WheelUnit.parts(beta)", parts.unit_parts),
    ("WheelUnit.drawn_angle(beta)", parts.drawn_angle),
    ("WheelUnit.dead_zone()", unit_design.dead_zone),
    ("WheelUnit.isotropy_advice()", _words),
    ("WheelUnit.isotropic_variant()", _variant),
    ("WheelUnit.other_builds()", _builds),
    ("WheelUnit.mechanism(height)", mechanism.mechanism),
    ("WheelUnit.root_body(height)", mechanism.root_body),
):
    setattr(WheelUnit, _old.split(".")[1].split("(")[0], _method(_old, _new))
WheelUnit.file_keys = classmethod(_method("WheelUnit.file_keys()", wheel_tables.file_keys))  # type: ignore[attr-defined]


def _attribute(old: str, new: Callable[[Any], str]) -> property:
    """The old attribute: warns, then returns the words of the record."""

    def get(self: Any) -> str:
        _warn(old)
        return new(self)

    get.__doc__ = f"Deprecated: {MOVED[old]}.\n\nReturns\n-------\nstr\n"
    return property(get)


unit_design.Change.words = _attribute("Change.words", advice_words.change)  # type: ignore[attr-defined]
advice.Advice.text = _attribute("Advice.text", advice_words.sentence)  # type: ignore[attr-defined]
sys.modules.setdefault("wmr.model.wheels.parts", parts)
sys.modules.setdefault("wmr.model.wheels.filekeys", wheel_tables)
sys.modules.setdefault("wmr.model.wheels.mechanism", mechanism)
swedish.NO_FAITHFUL_MECHANISM = mechanism.NO_FAITHFUL_MECHANISM  # type: ignore[attr-defined]
sys.modules.setdefault("wmr.analysis.glossary", glossary)


def _moved_words(module: str, names: dict[str, tuple[str, Any]]) -> Callable[[str], Any]:
    """A module ``__getattr__`` (PEP 562) that finds each old name (key) where it went (the value), with a warning."""

    def __getattr__(name: str) -> Any:
        if name in names:
            warnings.warn(f"{module}.{name} is deprecated: use {names[name][0]}", DeprecationWarning, 2)
            return names[name][1]
        raise AttributeError(f"module {module!r} has no attribute {name!r}")

    return __getattr__


_FAMILY_WORDS = {n: (f"wmr.words.families.{n}", getattr(family_words, n)) for n in ("FAMILIES", "MEANINGS")}
_TWIST_WORDS = {"describe_twist": ("wmr.words.limitations.describe_twist", limitation_words.describe_twist)}
sys.modules.setdefault("wmr.analysis.singular", families)
for _module, _name, _names in (
    (families, "wmr.analysis.singular", _FAMILY_WORDS),
    (overview, "wmr.analysis.overview", _FAMILY_WORDS),
    (actuation, "wmr.analysis.actuation", _TWIST_WORDS),
):
    setattr(_module, "__getattr__", _moved_words(_name, _names))  # noqa: B010 (PEP 562, on a module object)


def _types_getattr(name: str) -> Any:
    if name == "Twist":
        warnings.warn("wmr.model.types.Twist is deprecated: use wmr.model.types.TwistLike", DeprecationWarning, 2)
        return types.TwistLike
    raise AttributeError(f"module 'wmr.model.types' has no attribute {name!r}")


setattr(types, "__getattr__", _types_getattr)  # noqa: B010 (PEP 562, on a module object)
sys.modules.setdefault("wmr.analysis.simulation", integration)


def simulate(*args: Any, **kwargs: Any) -> Any:
    """Deprecated: :func:`wmr.integrate` (the kinematics integrated in time; ``wmr simulate`` runs MuJoCo).

    Parameters
    ----------
    *args, **kwargs
        Those of :func:`wmr.integrate`.

    Returns
    -------
    Trajectory
    """
    warnings.warn("wmr.simulate is deprecated: use wmr.integrate (the same function)", DeprecationWarning, 2)
    return integration.integrate(*args, **kwargs)
