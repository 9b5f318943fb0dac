r"""The verdict on an exercise (:class:`Feedback`) and the checks' shared answer parsing."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

__all__ = ["Feedback", "missing", "as_matrix", "as_angles"]


@dataclass(frozen=True)
class Feedback:
    """The verdict on a student's answer.

    Attributes
    ----------
    correct : bool
    message : str
        Markdown: what is right, or why not.
    """

    correct: bool
    message: str

    def __bool__(self):
        return self.correct

    def _repr_markdown_(self):
        return ("**Right.** " if self.correct else "**Not yet.** ") + self.message

    def __repr__(self):
        return f"Feedback(correct={self.correct}, message={self.message!r})"


def missing(answer, what):
    """The feedback for an exercise not yet answered (``answer is None``), else None.

    Parameters
    ----------
    answer : object
        The student's answer.
    what : str
        What the answer should be, in words (Markdown).

    Returns
    -------
    Feedback or None
    """
    if answer is None:
        return Feedback(False, f"No answer yet: replace `None` by {what}.")
    return None


def as_matrix(answer, shape, wanted):
    """The answer as a SymPy matrix of ``shape``, or the feedback why it is not one.

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
    feedback : Feedback or None
        Exactly one of the two is None.
    """
    fb = missing(answer, wanted)
    if fb is not None:
        return None, fb
    try:
        M = sp.Matrix(answer)
    except (TypeError, ValueError, sp.SympifyError):
        return None, Feedback(False, f"the answer must be a SymPy matrix (or a list) of shape {shape}, got {answer!r}.")
    if M.shape != shape:
        return None, Feedback(False, f"the answer must have shape {shape}, got {M.shape}.")
    return M, None


def as_angles(answer, degrees=False):
    """The answer as steering angles in radians, or the feedback for an exercise not yet answered.

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
    feedback : Feedback or None
        Exactly one of the two is None.
    """
    fb = missing(answer, "three steering angles in degrees" if degrees else "three steering angles (radians)")
    if fb is not None:
        return None, fb
    beta = np.asarray(answer, dtype=float)
    return (np.radians(beta) if degrees else beta), None
