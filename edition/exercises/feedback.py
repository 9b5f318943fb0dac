r"""The verdict on an exercise (:class:`Feedback`) and the checks' shared answer parsing."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
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


def _matrix(answer, shape, wanted):
    """``(M, None)``: the answer as a SymPy matrix of ``shape``; or ``(None, Feedback)``: none yet (``wanted``) or not one."""
    fb = _none(answer, wanted)
    if fb is not None:
        return None, fb
    try:
        M = sp.Matrix(answer)
    except (TypeError, ValueError, sp.SympifyError):
        return None, Feedback(False, f"the answer must be a SymPy matrix (or a list) of shape {shape}, got {answer!r}.")
    if M.shape != shape:
        return None, Feedback(False, f"the answer must have shape {shape}, got {M.shape}.")
    return M, None


def _angles(answer, degrees=False):
    """``(beta, None)``: the answer as steering angles in radians, array (k,); or ``(None, Feedback)``: none yet."""
    fb = _none(answer, "three steering angles in degrees" if degrees else "three steering angles (radians)")
    if fb is not None:
        return None, fb
    beta = np.asarray(answer, dtype=float)
    return (np.radians(beta) if degrees else beta), None
