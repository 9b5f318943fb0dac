r"""A singular family of the paper's robot (section 5.3): what it is in the paper's words, and its computed evidence.

:class:`Family` is one row of ``singularities.csv`` (:data:`COLUMNS`); :func:`paper_item` names the printed item
(i)-(v) that states a family literally, for the paper's wheel numbering (:data:`PAPER_PAIR_ITEMS`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..text import bound

__all__ = ["PAPER_PAIR_ITEMS", "COLUMNS", "Family", "paper_item", "directions_at_angles"]

#: The paper's items of section 5.3 for its wheel numbering (wheels 1-based): planes of wheels i and j on
#: the line P_i P_j.
PAPER_PAIR_ITEMS = {(1, 3): "(ii)", (1, 2): "(iii)", (2, 3): "(iv)"}


def paper_item(family):
    """The paper's item (i)-(v) that states a family of :func:`~wmr.analysis.singularities.classify` literally.

    Parameters
    ----------
    family : str
        A family key (``"i"``, ``"pair-13"``, ``"v-C"``, ...).

    Returns
    -------
    str
        ``"(i)"`` .. ``"(v)"``, or ``""`` when the paper's list does not state it (``"i'"``, the
        half-turn pairs, ``"regular"``).

    Examples
    --------
    >>> paper_item("pair-13"), paper_item("pair-13'"), paper_item("v-circle")
    ('(ii)', '', '(v)')
    """
    if family == "i":
        return "(i)"
    if family.startswith("pair-") and not family.endswith("'"):
        i, j = int(family[5]), int(family[6])
        return PAPER_PAIR_ITEMS.get((i, j), "")
    if family == "v" or family.startswith("v-"):
        return "(v)"
    return ""


@dataclass
class Family:
    """One family of singular configurations, with computed evidence (a row of ``singularities.csv``).

    Attributes
    ----------
    key : str
        Short id of the family.
    family : str
        Its name in the table.
    configuration : str
        The steering angles that make it (Markdown).
    geometric_meaning : str
        What the wheel-plane lines do there.
    listed_in_paper : str
        Whether the paper's list (i)-(v) after (59) contains it.
    paper_item : str
        The paper's item, e.g. ``"(ii)"`` (:func:`paper_item`), or ``""``.
    note : str
    samples : numpy.ndarray (n, 3)
        Representative configurations (radians).
    exact : callable or None
        Returns the list of (cos, sin) pairs (unnormalised directions of :math:`\\mathbf i_i`, SymPy)
        parameterising the family by free symbols, used for the exact check.
    det_J_max : float
        Computed: the largest :math:`|\\det\\mathbf J|` (58) over ``samples``.
    det_J_exact_zero : bool or None
        Computed: :math:`\\det\\mathbf J` vanishes identically on the family (None: not checked).
    rank_F : str
        Computed: the ranks of :math:`\\mathbf F` (24) seen on ``samples``.
    classified_as : str
        Computed: what :func:`wmr.analysis.singularities.classify` calls the samples.
    free_parameters : int
        Computed: the number of free symbols of the exact parameterisation (``-1``: none given).
    covered_any_point : str
        Computed: ``"yes"`` when a printed item covers the family under the reading ``"any point"``.
    """

    key: str
    family: str
    configuration: str
    geometric_meaning: str
    listed_in_paper: str
    paper_item: str
    note: str
    samples: np.ndarray | None = None
    exact: Callable[[], Any] | None = None
    # computed
    det_J_max: float = float("nan")
    det_J_exact_zero: bool | None = None
    rank_F: str = ""
    classified_as: str = ""
    free_parameters: int = -1
    covered_any_point: str = ""

    def row(self):
        """The family as a row of ``singularities.csv``.

        Returns
        -------
        dict
            Columns :data:`COLUMNS`; numbers as text.
        """
        return {
            "family": self.family,
            "configuration": self.configuration,
            "geometric_meaning": self.geometric_meaning,
            "det_J": bound(self.det_J_max),
            "det_J_exact": (
                "0 identically"
                if self.det_J_exact_zero
                else ("NOT zero" if self.det_J_exact_zero is False else "not checked")
            ),
            "rank_F": self.rank_F,
            "samples": 0 if self.samples is None else len(self.samples),
            "listed_in_paper": self.listed_in_paper,
            "paper_item": self.paper_item,
            "note": self.note,
            "free_parameters": self.free_parameters,
            "covered_any_point": self.covered_any_point,
        }


COLUMNS = (
    "family",
    "configuration",
    "geometric_meaning",
    "det_J",
    "det_J_exact",
    "rank_F",
    "samples",
    "listed_in_paper",
    "paper_item",
    "note",
    "free_parameters",
    "covered_any_point",
)


def directions_at_angles(angles):
    """(cos, sin) of exact angles (SymPy) as unnormalised axle directions.

    Parameters
    ----------
    angles : sequence of sympy.Expr
        One steering angle per wheel (radians).

    Returns
    -------
    list of tuple
        ``(cos a, sin a)`` per angle.
    """
    return [(sp.cos(a), sp.sin(a)) for a in angles]
