r"""The paper's singular configurations of three centred wheels (section 5.3, items (i)-(v)), as computed families.

Each :class:`Family` states a set of configurations in the paper's words (LaTeX), the verdict on
whether the paper lists it, and carries computed evidence: :math:`|\det\mathbf J|` at sampled
members, an exact check that :math:`\det\mathbf J` vanishes identically on the family
(:func:`wmr.analysis.singularities.exact_zero`), the ranks of :math:`\mathbf F` found there and the
family :func:`wmr.analysis.singularities.classify` assigns.  :func:`check_paper_items` checks the
printed list literally.  The general analysis lives in :mod:`wmr.analysis.singularities`; only the
paper's catalogue is here.

The package, by job:

==================  ===========================================================================================
:mod:`.family`      :class:`Family` (a row of ``singularities.csv``) and the paper's items (:func:`paper_item`)
:mod:`.catalogue`   :func:`families`, sampled and checked exactly; :func:`check_paper_items`, the printed list
:mod:`.coverage`    the families modulo a half turn and the items that cover them; ``singularities.csv``
:mod:`.counts`      the counts of covered and missed families, one table of reading x result
==================  ===========================================================================================
"""

from .catalogue import check_paper_items, families
from .counts import COUNTINGS, count_table, counted, summary
from .coverage import ITEMS, READINGS, accounting, covering_items, table, write_csv
from .family import COLUMNS, PAPER_PAIR_ITEMS, Family, paper_item

__all__ = [
    "PAPER_PAIR_ITEMS",
    "COLUMNS",
    "Family",
    "families",
    "paper_item",
    "check_paper_items",
    "table",
    "write_csv",
    "READINGS",
    "ITEMS",
    "covering_items",
    "accounting",
    "COUNTINGS",
    "counted",
    "count_table",
    "summary",
]
