r"""Fair checks: the :func:`exercise` decorator, which makes a check that never raises for a student's answer.

A check is a function of the student's answer(s) that returns :func:`~edition.exercises.feedback.right`
or :func:`~edition.exercises.feedback.wrong`, reading the answer with :mod:`edition.exercises.answers`
and comparing with :mod:`edition.exercises.tolerance` or :mod:`edition.exercises.symbolic`.  The
decorator adds what every check needs::

    TOL_6_1 = sig_figs(3)

    @exercise("6.1", answer="three steering rates in rad/s", tolerance=TOL_6_1, units={"beta_dot": "rad"})
    def curved_translation(beta_dot):
        rates = answers.vector(beta_dot, 3, "three steering rates in rad/s")
        ...

* an answer left ``None`` -> "No answer yet: replace `None` by three steering rates in rad/s." (status
  ``missing``; the student notebooks run);
* :class:`~edition.exercises.answers.AnswerError` (wrong type or shape) -> its one line (``malformed``);
* wrong arguments (two answers for one) -> one line naming the check's parameters;
* any other exception inside the check -> one line, status ``error`` (a defect of the check, which the
  answer-table tests report; the student sees no traceback);
* a failed answer given in the other angle unit (``units``): the same numbers converted are tried, and
  when they pass the message says so; else :func:`~edition.exercises.tolerance.unit_hint`;
* the result carries the exercise number and its points (:attr:`Result.points`).

The decorated check keeps its name and docstring, and carries :attr:`exercise` (an :class:`Exercise`);
:func:`registered` lists every check of the edition (``make assignments`` reads the points there).
A check module must be imported by one of :data:`CHECK_MODULES` to be registered.

In a chapter an exercise is four cells, each tagged (cell metadata ``tags``), in this order:

1. markdown ``exercise``: the statement, with the units and the tolerance (``TOL_6_1.statement``), no answer;
2. code ``answer``: the template, e.g. ``beta_6_1 = None  # three steering rates in rad/s``;
3. code ``solution``: the worked solution, assigning the same name (dropped from the student edition);
4. code ``check``: one call, ``check_6_1(beta_6_1)``, which shows one Markdown verdict.

``make assignments`` (:mod:`tools.assignments`) turns them into nbgrader source notebooks; the answer
tables of :mod:`edition.exercises.table` test each check (right, rounded, wrong, trivial, other unit,
malformed, missing).
"""

from __future__ import annotations

import functools
import importlib
import inspect
from dataclasses import dataclass, replace

import numpy as np

from .answers import AnswerError
from .feedback import Result
from .tolerance import Tolerance, unit_hint

__all__ = ["Exercise", "exercise", "registered", "by_name", "CHECK_MODULES"]

#: the modules holding the edition's checks: :func:`registered` imports them
CHECK_MODULES = (
    "edition.exercises",
    "edition.design_study",
    "edition.exercises.ch10_classes",
    "edition.physics.exercises",
)

_REGISTRY: dict[str, Exercise] = {}


@dataclass(frozen=True)
class Exercise:
    """What the framework knows about one exercise.

    Attributes
    ----------
    number : str
        ``"6.1"``: chapter and exercise.
    name : str
        The check's function name (unique across the edition).
    answer : str
        What the student must give, in words (Markdown).
    points : float
    tolerance : Tolerance or None
        The tolerance the question states.
    units : dict
        Parameter name -> ``"deg"`` or ``"rad"``: the angle unit the question asks for.
    check : callable
        The decorated check.
    """

    number: str
    name: str
    answer: str
    points: float
    tolerance: Tolerance | None
    units: dict
    check: object


def _convert(value, to):
    """``value`` (numbers) read in the other unit: degrees -> radians (``to="rad"``) or radians -> degrees."""
    a = np.asarray(value, dtype=float)
    return np.radians(a) if to == "rad" else np.degrees(a)


def _numbers(value):
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return False
    return a.size > 0 and bool(np.all(np.isfinite(a)))


def _run(f, args, kwargs):
    """Call the check; its exceptions become results."""
    try:
        result = f(*args, **kwargs)
    except AnswerError as e:
        return Result(False, str(e), status="malformed")
    except Exception as e:
        first = (str(e).splitlines() or [""])[0][:160]
        return Result(
            False,
            f"The check could not evaluate this answer ({type(e).__name__}: {first}). Check its "
            "type and shape against the question.",
            status="error",
        )
    if not isinstance(result, Result):
        raise TypeError(f"check {f.__name__} returned {type(result).__name__}, not a Result")
    return result


def _unit_retry(f, bound, units, result):
    """A failed result with the hint for an angle given in the other unit (tried, or recognised by size)."""
    for name, unit in units.items():
        given = bound.arguments.get(name)
        if not _numbers(given):
            continue
        other = bound.arguments.copy()
        other[name] = _convert(given, unit)
        retry = _run(f, (), other)
        if retry.passed:
            was, want = ("radians", "degrees") if unit == "deg" else ("degrees", "radians")
            return result.with_hint(f"These numbers would be right in {was}; the question asks for {want}.")
        hint = unit_hint(given, unit)
        if hint:
            return result.with_hint(hint)
    return result


def exercise(number, *, answer, points=1, tolerance=None, units=None, register=True):
    """Make ``f`` a fair check of exercise ``number`` (see the module notes).

    Parameters
    ----------
    number : str
        ``"chapter.exercise"``, e.g. ``"6.1"``; unique.
    answer : str
        What the student must give, in words: "No answer yet: replace `None` by {answer}."
    points : float, optional
    tolerance : Tolerance, optional
        The tolerance the question states (the check applies it; recorded for the tests and the graders).
    units : dict, optional
        Parameter name -> ``"deg"`` / ``"rad"``: angles (or angular rates) in that unit.
    register : bool, optional
        List it in :func:`registered` (False for a check made in a test).

    Returns
    -------
    callable
        The decorator.
    """
    units = dict(units or {})
    if not isinstance(number, str) or not number.replace(".", "").isalnum():
        raise ValueError(f"number must be a string like '6.1', got {number!r}")
    if not points > 0:
        raise ValueError(f"points must be positive, got {points!r}")
    if any(u not in ("deg", "rad") for u in units.values()):
        raise ValueError(f"units must map parameter names to 'deg' or 'rad', got {units!r}")

    def wrap(f):
        sig = inspect.signature(f)
        required = [p.name for p in sig.parameters.values() if p.default is inspect.Parameter.empty]
        if set(units) - set(sig.parameters):
            raise ValueError(f"units names {sorted(set(units) - set(sig.parameters))}, not parameters of {f.__name__}")

        @functools.wraps(f)
        def check(*args, **kwargs):
            try:
                bound = sig.bind(*args, **kwargs)
            except TypeError:
                names = ", ".join(f"`{n}`" for n in required)
                result = Result(False, f"`{f.__name__}` takes {len(required)} answer(s): {names}.", status="malformed")
            else:
                bound.apply_defaults()
                if any(bound.arguments[n] is None for n in required):
                    result = Result(False, f"No answer yet: replace `None` by {answer}.", status="missing")
                else:
                    result = _run(f, bound.args, bound.kwargs)
                    if result.status == "wrong" and units:
                        result = _unit_retry(f, bound, units, result)
            return replace(result, exercise=number, max_points=float(points))

        info = Exercise(
            number=number,
            name=f.__name__,
            answer=answer,
            points=float(points),
            tolerance=tolerance,
            units=units,
            check=check,
        )
        old = _REGISTRY.get(number) if register else None
        if old is not None and (old.name, getattr(old.check, "__module__", "")) != (f.__name__, f.__module__):
            raise ValueError(f"exercise {number} is registered twice: {old.name} and {f.__name__}")
        if register:
            _REGISTRY[number] = info
        check.exercise = info  # type: ignore[attr-defined]
        return check

    return wrap


def registered():
    """Every exercise of the edition (the modules :data:`CHECK_MODULES` imported), by number.

    Returns
    -------
    dict of str -> Exercise
    """
    for m in CHECK_MODULES:
        importlib.import_module(m)
    return dict(sorted(_REGISTRY.items(), key=lambda kv: [int(x) if x.isdigit() else x for x in kv[0].split(".")]))


def by_name(name):
    """The exercise whose check is called ``name``.

    Parameters
    ----------
    name : str

    Returns
    -------
    Exercise

    Raises
    ------
    KeyError
        No registered check has that name.
    """
    found = [e for e in registered().values() if e.name == name]
    if len(found) != 1:
        raise KeyError(
            f"no registered exercise check is called {name!r}"
            if not found
            else f"{len(found)} exercise checks are called {name!r}"
        )
    return found[0]
