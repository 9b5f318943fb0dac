r"""The verdict on an exercise: a :class:`Result` with ``.passed`` and ``.points``, shown as one Markdown paragraph.

A check returns :func:`right` or :func:`wrong` (the decorator :func:`edition.exercises.framework.exercise`
turns a missing answer, a malformed one and an answer the check cannot evaluate into results of
their own), so that a student never sees a traceback and a grader reads ``.passed`` and ``.points``.

``Feedback(correct, message)``, the older name, builds the same object.  The helpers
:func:`missing`, :func:`as_matrix` and :func:`as_angles` are the older parsing used by chapter modules
not yet written with :mod:`edition.exercises.answers`.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import sympy as sp

__all__ = ["Result", "Feedback", "STATUSES", "right", "wrong", "undecided", "missing", "as_matrix", "as_angles"]

#: what a result can be: right, wrong (a real attempt that does not do it), missing (``None``),
#: malformed (not the expected type or shape), undecided (the check cannot tell; never passed),
#: error (the check itself failed on this answer: a defect of the check, caught so the student sees one line)
STATUSES = ("right", "wrong", "missing", "malformed", "undecided", "error")

_HEAD = {
    "right": "**Right.**",
    "wrong": "**Not yet.**",
    "missing": "**Not yet.**",
    "malformed": "**Not yet.**",
    "undecided": "**Cannot tell.**",
    "error": "**Not checked.**",
}


@dataclass(frozen=True)
class Result:
    r"""The verdict on a student's answer.

    Attributes
    ----------
    passed : bool
        The answer does what the exercise asks (within the tolerance the question states).
    message : str
        Markdown with ``$...$`` math: why it is right, or what is wrong -- true for the answer given, and
        never the expected answer.
    status : str
        One of :data:`STATUSES`; ``"right"`` exactly when ``passed``.
    exercise : str
        The exercise's number, e.g. ``"6.1"`` (set by :func:`~edition.exercises.framework.exercise`).
    max_points : float
        What the exercise is worth.
    """

    passed: bool
    message: str
    status: str = ""
    exercise: str = ""
    max_points: float = 1.0

    def __post_init__(self):
        status = self.status or ("right" if self.passed else "wrong")
        if status not in STATUSES:
            raise ValueError(f"status must be one of {STATUSES}, got {status!r}")
        if (status == "right") != bool(self.passed):
            raise ValueError(f"a result with status {status!r} cannot have passed={self.passed!r}")
        object.__setattr__(self, "status", status)
        object.__setattr__(self, "passed", bool(self.passed))

    @property
    def points(self):
        """The points earned: :attr:`max_points` when passed, else 0."""
        return self.max_points if self.passed else 0.0

    @property
    def correct(self):
        """The older name of :attr:`passed`."""
        return self.passed

    def __bool__(self):
        return self.passed

    def with_hint(self, hint):
        """The same result with ``hint`` (Markdown) appended to the message.

        Parameters
        ----------
        hint : str

        Returns
        -------
        Result
        """
        return replace(self, message=f"{self.message} {hint}".strip())

    def markdown(self):
        """The verdict as one Markdown paragraph, e.g. ``**Not yet.** ...``.

        Returns
        -------
        str
        """
        label = f"Exercise {self.exercise}: " if self.exercise else ""
        return f"{_HEAD[self.status]} {label}{self.message}".rstrip()

    def _repr_markdown_(self):
        return self.markdown()

    def require(self):
        """Show the verdict and raise ``AssertionError`` (its message: the verdict) unless the answer passed.

        The autograded test cell of an nbgrader assignment (``make assignments``) is one call of this.

        Returns
        -------
        Result
            ``self``, when passed.
        """
        from IPython.display import Markdown, display

        display(Markdown(self.markdown()))
        if not self.passed:
            raise AssertionError(self.markdown())
        return self

    def __repr__(self):
        return f"Result(passed={self.passed}, status={self.status!r}, points={self.points:g}, message={self.message!r})"


#: the older name: ``Feedback(correct, message)`` is ``Result(passed=correct, message=message)``
Feedback = Result


def right(message):
    """A passed :class:`Result`.

    Parameters
    ----------
    message : str
        Markdown: what the answer shows (a value printed in it must itself pass the check).

    Returns
    -------
    Result
    """
    return Result(True, message)


def wrong(message):
    """A failed :class:`Result` for a real attempt.

    Parameters
    ----------
    message : str
        Markdown: what is wrong, true for this answer, without the expected answer.

    Returns
    -------
    Result
    """
    return Result(False, message)


def undecided(message):
    """A result for an answer the check cannot judge (never passed; the message says why, not "wrong").

    Parameters
    ----------
    message : str
        Markdown: why the check cannot tell (e.g. the expression could not be evaluated).

    Returns
    -------
    Result
    """
    return Result(False, message, status="undecided")


# ------------------------------------------------------------------------------------------ older parsing
def missing(answer, what):
    """The result for an exercise not yet answered (``answer is None``), else None.

    Parameters
    ----------
    answer : object
        The student's answer.
    what : str
        What the answer should be, in words (Markdown).

    Returns
    -------
    Result or None
    """
    if answer is None:
        return Result(False, f"No answer yet: replace `None` by {what}.", status="missing")
    return None


def as_matrix(answer, shape, wanted):
    """The answer as a SymPy matrix of ``shape``, or the result saying why it is not one.

    Parameters
    ----------
    answer : object
        The student's answer: a SymPy matrix, or a list of lists.
    shape : tuple of int
        The shape the answer must have.
    wanted : str
        What the answer should be, in words (for an exercise not yet answered).

    Returns
    -------
    matrix : sympy.Matrix or None
    feedback : Result or None
        Exactly one of the two is None.
    """
    fb = missing(answer, wanted)
    if fb is not None:
        return None, fb
    try:
        M = sp.Matrix(answer)
    except (TypeError, ValueError, sp.SympifyError):
        return None, Result(
            False, f"The answer must be a SymPy matrix (or a list) of shape {shape}.", status="malformed"
        )
    if M.shape != shape:
        return None, Result(False, f"The answer must have shape {shape}, got {M.shape}.", status="malformed")
    return M, None


def as_angles(answer, degrees=False):
    """The answer as steering angles in radians, or the result for an exercise not yet answered.

    Parameters
    ----------
    answer : array_like or None
        Steering angles.
    degrees : bool, optional
        The answer is in degrees.

    Returns
    -------
    beta : numpy.ndarray (k,) or None
        Radians.
    feedback : Result or None
        Exactly one of the two is None.
    """
    fb = missing(answer, "three steering angles in degrees" if degrees else "three steering angles (radians)")
    if fb is not None:
        return None, fb
    beta = np.asarray(answer, dtype=float)
    return (np.radians(beta) if degrees else beta), None
