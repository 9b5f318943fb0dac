"""Names that moved out of the wheel kinds (issue 29), kept for one release with a warning naming the new place.

A wheel kind answers for its mathematics only; its drawing, its robot-file keys, its bodies and joints and
its design hints moved to the layers that use them; other libraries' conventions are converted by one module,
:mod:`wmr.model.conventions`.  ``import wmr`` imports this module, which puts the old methods
back on :class:`~wmr.model.wheels.WheelUnit` (each warns with a :class:`DeprecationWarning` and calls
its replacement), the old names on their modules (warning when read) and the old modules in :data:`sys.modules`:

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
``wmr.model.platform.cos_sin`` (and checked)   ``(np.cos(beta), np.sin(beta))`` (the half-angle form was 1.3x, not 3x)
``wmr.swerve.to_wpilib(beta)``                 :func:`wmr.model.conventions.angle_to` ``(beta, "wpilib")`` (``speed``: unchanged)
``wmr.swerve.from_wpilib(alpha)``              :func:`wmr.model.conventions.angle_from` ``(alpha, "wpilib")``
``wmr.swerve.to_chassis(twist)``               :func:`wmr.model.conventions.twist_to` ``(twist, "wpilib")``
``wmr.swerve.from_chassis(chassis)``           :func:`wmr.model.conventions.twist_from` ``(chassis, "wpilib")``
``wmr.io.chassis``                             :mod:`wmr.io.wpilib` (``twist_of``, ``chassis_speeds``, ``is_chassis_speeds``)
``wmr.analysis.sweep.gram_kappa``              :mod:`wmr.analysis.gram_kappa` (the same four names)
``wmr.model.arrays``                           :mod:`wmr.model.checks` (the same names)
``wmr.model.robot_checks``                     :mod:`wmr.model.validation` (the same names)
=============================================  ===================================================================
"""

from __future__ import annotations

import sys
import types
import warnings
from collections.abc import Callable
from typing import Any

from . import io, model, swerve
from .analysis import actuation, advice, families, gram_kappa, integration, overview, unit_design
from .analysis import sweep as sweep_package
from .io import mechanism, wheel_tables, wpilib
from .model import checks, conventions, platform, validation
from .model import types as model_types
from .model.wheels import WheelUnit, swedish
from .plot import parts
from .swerve import modules
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


def _moved(module: types.ModuleType, old: str, names: dict[str, tuple[str, Any]]) -> None:
    """Give ``module`` a ``__getattr__`` (PEP 562) that finds ``names`` (name -> (new place, value)), with a warning."""

    def __getattr__(name: str) -> Any:
        if name not in names:
            raise AttributeError(f"module {old!r} has no attribute {name!r}")
        warnings.warn(f"{old}.{name} is deprecated: use {names[name][0]}", DeprecationWarning, 2)
        return names[name][1]

    setattr(module, "__getattr__", __getattr__)  # noqa: B010 (PEP 562, on a module object)


_WORDS = {n: (f"wmr.words.families.{n}", getattr(family_words, n)) for n in ("FAMILIES", "MEANINGS")}
sys.modules.setdefault("wmr.analysis.singular", families)
_moved(families, "wmr.analysis.singular", _WORDS)
_moved(overview, "wmr.analysis.overview", _WORDS)
_DESCRIBE = ("wmr.words.limitations.describe_twist", limitation_words.describe_twist)
_moved(actuation, "wmr.analysis.actuation", {"describe_twist": _DESCRIBE})
_moved(model_types, "wmr.model.types", {"Twist": ("wmr.model.types.TwistLike", model_types.TwistLike)})


def _to_wpilib(beta: Any, speed: Any = None) -> Any:
    alpha = conventions.angle_to(beta, "wpilib")
    return alpha if speed is None else (alpha, validation.finite_array("speed", speed))


def _from_wpilib(alpha: Any, speed: Any = None) -> Any:
    beta = conventions.angle_from(alpha, "wpilib", "alpha")
    return beta if speed is None else (beta, validation.finite_array("speed", speed))


_SWERVE = {
    "to_wpilib": ('wmr.model.conventions.angle_to(beta, "wpilib")', _to_wpilib),
    "from_wpilib": ('wmr.model.conventions.angle_from(alpha, "wpilib")', _from_wpilib),
    "to_chassis": ('wmr.model.conventions.twist_to(twist, "wpilib")', lambda t: conventions.twist_to(t, "wpilib")),
    "from_chassis": (
        'wmr.model.conventions.twist_from(chassis, "wpilib")',
        lambda c: conventions.twist_from(c, "wpilib", "chassis"),
    ),
}
_moved(swerve, "wmr.swerve", _SWERVE)
_moved(modules, "wmr.swerve.modules", _SWERVE)
_chassis = types.ModuleType("wmr.io.chassis", "Deprecated: :mod:`wmr.io.wpilib`.")
_names = ("twist_of", "chassis_speeds", "is_chassis_speeds")
_moved(_chassis, "wmr.io.chassis", {n: (f"wmr.io.wpilib.{n}", getattr(wpilib, n)) for n in _names})
sys.modules.setdefault("wmr.io.chassis", _chassis)
setattr(io, "chassis", _chassis)  # noqa: B010 (import wmr.io.chassis finds it, as before)
sys.modules.setdefault("wmr.analysis.simulation", integration)
_gram = types.ModuleType("wmr.analysis.sweep.gram_kappa", "Deprecated: :mod:`wmr.analysis.gram_kappa`.")
_GRAM = ("UPPER", "SCRATCH", "kappa_from_gram", "kappa_by_lapack")
_moved(
    _gram,
    "wmr.analysis.sweep.gram_kappa",
    {n: (f"wmr.analysis.gram_kappa.{n}", getattr(gram_kappa, n)) for n in _GRAM},
)
sys.modules.setdefault("wmr.analysis.sweep.gram_kappa", _gram)
setattr(sweep_package, "gram_kappa", _gram)  # noqa: B010 (import wmr.analysis.sweep.gram_kappa finds it, as before)
_ARRAYS = (
    "finite_array",
    "twist_array",
    "twist_kind",
    "TWIST_OBJECTS",
    "batch_shape",
    "symbolic_vector",
    "symbolic_matrix",
)
_SHIMS: dict[str, dict[str, tuple[str, Any]]] = {
    "arrays": {n: (f"wmr.model.checks.{n}", getattr(checks, n)) for n in _ARRAYS},
    "robot_checks": {
        "robot": ("wmr.model.validation.robot", validation.robot),
        "numeric_robot": ("wmr.model.validation.numeric_robot", validation.numeric_robot),
        "free_symbols": ("wmr.Robot.free_symbols (an attribute)", lambda robot: set(robot.free_symbols)),
    },
}
for _shim_name, _shim_names in _SHIMS.items():
    _shim = types.ModuleType(
        f"wmr.model.{_shim_name}",
        f"Deprecated: the names moved to {sorted({v[0].rsplit('.', 1)[0] for v in _shim_names.values()})}.",
    )
    _moved(_shim, f"wmr.model.{_shim_name}", _shim_names)
    sys.modules.setdefault(f"wmr.model.{_shim_name}", _shim)
    setattr(model, _shim_name, _shim)


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


def _cos_sin(beta: Any, out: Any = None) -> tuple[Any, Any]:
    import numpy as np

    beta = np.asarray(beta, dtype=float)
    return (np.cos(beta), np.sin(beta)) if out is None else (np.cos(beta, out=out[0]), np.sin(beta, out=out[1]))


_COS_SIN = (
    "(np.cos(beta), np.sin(beta)) (the half-angle form was 1.3x faster, not the 3x a fast path must be)",
    _cos_sin,
)
_moved(platform, "wmr.model.platform", {"cos_sin": _COS_SIN, "cos_sin_checked": _COS_SIN})
