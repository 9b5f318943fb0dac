r"""The verdict on an exercise (:class:`Feedback`) and the checks' shared answer parsing."""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

__all__ = ["Feedback"]


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


def _none(answer, what):
    if answer is None:
        return Feedback(False, f"No answer yet: replace `None` by {what}.")
    return None


def _matrix(answer, shape, what):
    try:
        M = sp.Matrix(answer)
    except (TypeError, ValueError, sp.SympifyError):
        return None, Feedback(False, f"{what} must be a SymPy matrix (or a list) of shape {shape}, got {answer!r}.")
    if M.shape != shape:
        return None, Feedback(False, f"{what} must have shape {shape}, got {M.shape}.")
    return M, None
