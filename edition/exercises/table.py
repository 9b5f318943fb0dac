r"""Answer tables: the generic harness that tests a check against right, rounded, wrong and malformed answers.

An answer table lists, for one exercise, answers a student may give and what the check must say::

    from edition.exercises.table import Case, right_case, wrong_case, malformed_case, rounded, verify

    TABLE_4_1 = [
        right_case("exact", [30.0, 150.0, 270.0]),
        right_case("rounded to the stated decimals", rounded([30.004, 150.0, 270.0], TOL_4_1)),
        wrong_case("trivial: all equal", [30, 30, 30], says="all three"),
        wrong_case("radians for degrees", np.radians([30, 150, 270]), says="radians"),
        malformed_case("two numbers", [30, 150], says="three"),
    ]

    @pytest.mark.parametrize("case", TABLE_4_1, ids=str)
    def test_4_1(case):
        verify(check_4_1, case)

:func:`verify` calls the check and asserts what the case says (passed or not, the status, phrases the
message must and must not contain) *and* what every verdict must be (:func:`problems`): a
:class:`~edition.exercises.feedback.Result` whose points agree with ``passed``; one Markdown
paragraph; no traceback; no raw e-notation (``2.88e-16``) in the text; for a malformed answer one
line; and never the status ``error`` (a check that failed on the answer).  :data:`JUNK` and
:func:`junk_cases` give the malformed answers every check must survive.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np
import sympy as sp

from ..display import raw_output
from .feedback import Result

__all__ = [
    "Case",
    "right_case",
    "wrong_case",
    "malformed_case",
    "missing_case",
    "rounded",
    "problems",
    "verify",
    "JUNK",
    "junk_cases",
]


@dataclass(frozen=True)
class Case:
    """One row of an answer table.

    Attributes
    ----------
    label : str
        What the answer is ("rounded to 3 significant figures", "degrees for radians").
    args : tuple
        The check's arguments.
    passes : bool
        Whether the check must pass it.
    status : str or None
        The status the result must have (None: ``"right"`` when it passes, else anything but ``"error"``).
    says : tuple of str
        Phrases (regular expressions, case-insensitive) the message must contain.
    never_says : tuple of str
        Phrases (plain text) the message must not contain: the expected answer, a formula for it, a false claim.
    """

    label: str
    args: tuple
    passes: bool
    status: str | None = None
    says: tuple = ()
    never_says: tuple = ()

    def __str__(self):
        return self.label


def _tuple(x):
    return () if x is None else ((x,) if isinstance(x, str) else tuple(x))


def right_case(label, *args, says=None, never_says=None):
    """A case the check must pass (status ``right``)."""
    return Case(label, args, True, "right", _tuple(says), _tuple(never_says))


def wrong_case(label, *args, says=None, never_says=None):
    """A real attempt the check must reject (status ``wrong``)."""
    return Case(label, args, False, "wrong", _tuple(says), _tuple(never_says))


def malformed_case(label, *args, says=None, never_says=None):
    """An answer of the wrong type or shape: rejected with one line (status ``malformed``)."""
    return Case(label, args, False, "malformed", _tuple(says), _tuple(never_says))


def missing_case(label="not answered (None)", *args, says="No answer yet"):
    """The template's placeholder: not passed, status ``missing`` (default arguments: one ``None``)."""
    return Case(label, args or (None,), False, "missing", _tuple(says))


def rounded(value, tolerance):
    """``value`` rounded as the question states (``tolerance.digits`` significant figures or decimals).

    Parameters
    ----------
    value : float or array_like
    tolerance : Tolerance

    Returns
    -------
    float or numpy.ndarray
    """
    v = np.asarray(value, dtype=float)
    if tolerance.rel > 0:
        with np.errstate(divide="ignore"):
            k = np.where(v == 0, 0, np.floor(np.log10(np.abs(np.where(v == 0, 1, v))))).astype(int)
        out = np.array([round(x, int(tolerance.digits - 1 - e)) for x, e in zip(v.ravel(), k.ravel())])
        out = out.reshape(v.shape)
    else:
        out = np.round(v, tolerance.digits)
    return float(out) if out.ndim == 0 else out


def problems(result, case=None):
    """What is wrong with a verdict: the invariants of every result, and what ``case`` asks.

    Parameters
    ----------
    result : object
        What the check returned.
    case : Case, optional

    Returns
    -------
    list of str
        Empty when all is well.
    """
    if not isinstance(result, Result):
        return [f"the check returned {type(result).__name__}, not a Result"]
    out = []
    md = result.markdown()
    if result.status == "error":
        out.append(f"the check failed on the answer (status error): {result.message}")
    if result.points != (result.max_points if result.passed else 0):
        out.append(f"points {result.points} disagree with passed={result.passed}")
    if "\n\n" in md.strip() or "Traceback" in md:
        out.append(f"the verdict is not one Markdown paragraph: {md!r}")
    raw = raw_output(md)
    if raw:
        out.append(f"raw output in the verdict (e-notation or a Python container): {raw} in {md!r}")
    if result.status == "malformed" and "\n" in result.message.strip():
        out.append(f"a malformed answer gets more than one line: {result.message!r}")
    if case is None:
        return out
    if result.passed != case.passes:
        out.append(f"{case.label}: passed={result.passed}, expected {case.passes}: {md}")
    if case.status is not None and result.status != case.status:
        out.append(f"{case.label}: status {result.status!r}, expected {case.status!r}: {md}")
    for phrase in case.says:
        if not re.search(phrase, result.message, flags=re.IGNORECASE):
            out.append(f"{case.label}: the message does not say {phrase!r}: {md}")
    for phrase in case.never_says:
        if phrase in md:
            out.append(f"{case.label}: the message says {phrase!r}, which it must not: {md}")
    return out


def verify(check, case):
    """Assert that ``check(*case.args)`` answers as ``case`` says, with a verdict free of :func:`problems`.

    Parameters
    ----------
    check : callable
        A check made with :func:`~edition.exercises.framework.exercise`.
    case : Case

    Returns
    -------
    Result
        The verdict (for further assertions).

    Raises
    ------
    AssertionError
        Listing every problem.
    """
    result = check(*case.args)
    found = problems(result, case)
    assert not found, f"{getattr(check, '__name__', check)}: " + "; ".join(found)
    return result


#: answers of the wrong type every check must reject in one line (never pass, never fail inside)
JUNK = {
    "text": "0.5",
    "a dict": {"a": 1.0},
    "a set": {1.0, 2.0},
    "a truth value": True,
    "an object": object(),
    "NaN": float("nan"),
    "an empty list": [],
    "a ragged list": [[1.0, 2.0], [3.0]],
    "a free symbol": sp.Symbol("zeta_junk"),
    "a large array": np.ones((7, 9)),
}


def junk_cases(n_args=1):
    """For a check of ``n_args`` answers: each :data:`JUNK` value given for every answer, which must not pass.

    Parameters
    ----------
    n_args : int, optional

    Returns
    -------
    list of Case
        ``passes=False``, status not fixed (``malformed`` or ``wrong``), never ``error``.
    """
    return [Case(f"junk: {label}", (value,) * n_args, False) for label, value in JUNK.items()]
