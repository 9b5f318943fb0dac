r"""How many singular families the paper's list covers and misses: one table of reading x result, computed once.

Two choices decide every count the report states about the list (i)-(v) of section 5.3:

*what counts as a family* (:data:`COUNTINGS`)
    ``"catalogue"``: every family of ``singularities.csv``, each once, including the single configuration (v-a)
    and the curve (v-c), which lie inside (v); ``"one free angle"``: only the families with one free
    parameter (:attr:`~edition.families.Family.free_parameters`) that no other family contains, i.e. that
    item (v) does not cover (the lines (ii)-(iv) and (v-b), and (i));
*which configurations item (v) admits* (:data:`~edition.families.READINGS`)
    ``"half-turn"`` ($D_P$ not a mount point) or ``"any point"``.

:func:`count_table` computes the four counts from the rows of ``singularities.csv``; the report states each
count from it, and the tests compare every count stated in the PDF with it.
"""

from __future__ import annotations

__all__ = ["COUNTINGS", "WHEN", "counted", "count_table", "summary"]

#: what counts as a family, in words (the report states it beside each count)
COUNTINGS = {
    "catalogue": "every family of the catalogue, each once (including the single configuration (v-a) and the "
    "curve (v-c), which lie inside (v))",
    "one free angle": "only the families with one free parameter that no other family contains: (i), the lines "
    "(ii)-(iv) and the three (v-b)",
}

#: each reading of item (v), as a clause of a sentence
WHEN = {
    "half-turn": "when $D_P$ in (v) may not be a mount point",
    "any point": "when it may",
}

#: each counting, as the phrase that names the families counted
NAMED = {"catalogue": "every family of the catalogue", "one free angle": "only the families with one free angle"}

_WORDS = "none one two three four five six seven eight nine ten eleven twelve".split()


def _words(n):
    return _WORDS[n] if 0 <= n < len(_WORDS) else str(n)


def _inside_v(row):
    return "(v)" in [s.strip() for s in row["paper_item"].split(",")] and not row["family"].startswith("(v) ")


def counted(row, counting):
    """Whether the family (a row of ``singularities.csv``) is counted under ``counting``.

    Parameters
    ----------
    row : dict
    counting : {"catalogue", "one free angle"}

    Returns
    -------
    bool
    """
    if counting not in COUNTINGS:
        raise ValueError(f"counting must be one of {sorted(COUNTINGS)}, got {counting!r}")
    if counting == "catalogue":
        return True
    return int(row["free_parameters"]) == 1 and not _inside_v(row)


def count_table(rows):
    """The families counted, covered and missed, for every counting and reading.

    Parameters
    ----------
    rows : list of dict
        Rows of ``singularities.csv`` (columns :data:`edition.families.COLUMNS`).

    Returns
    -------
    list of dict
        One per (counting, reading), in the order of :data:`COUNTINGS` and ``READINGS``: ``counting``,
        ``reading``, ``families``, ``covered``, ``missed`` (ints) and ``missed_names`` (list of str).

    Examples
    --------
    >>> rows = [{"family": "(i)", "paper_item": "(i)", "free_parameters": "1", "listed_in_paper": "yes",
    ...          "covered_any_point": "yes"},
    ...         {"family": "(v-b) x", "paper_item": "", "free_parameters": "1", "listed_in_paper": "no",
    ...          "covered_any_point": "yes"}]
    >>> [(t["families"], t["covered"], t["missed"]) for t in count_table(rows)]
    [(2, 1, 1), (2, 2, 0), (2, 1, 1), (2, 2, 0)]
    """
    from .coverage import READINGS

    out = []
    for counting in COUNTINGS:
        mine = [r for r in rows if counted(r, counting)]
        for reading in READINGS:
            key = "listed_in_paper" if reading == "half-turn" else "covered_any_point"
            missed = [r["family"] for r in mine if r[key] != "yes"]
            out.append(
                {
                    "counting": counting,
                    "reading": reading,
                    "families": len(mine),
                    "covered": len(mine) - len(missed),
                    "missed": len(missed),
                    "missed_names": missed,
                }
            )
    return out


def summary(table):
    """The counts of :func:`count_table` as prose, one clause per counting, every number taken from ``table``.

    Parameters
    ----------
    table : list of dict
        :func:`count_table`.

    Returns
    -------
    str
        E.g. "counting every family of the catalogue (ten), it covers seven and misses three when ..., and
        misses none when it may; counting ...".

    Examples
    --------
    >>> t = [{"counting": "catalogue", "reading": "half-turn", "families": 2, "covered": 1, "missed": 1},
    ...      {"counting": "catalogue", "reading": "any point", "families": 2, "covered": 2, "missed": 0}]
    >>> print(summary(t).replace(", and", ",\\nand"))
    counting every family of the catalogue (two), it covers one and misses one when $D_P$ in (v) may not be a mount point,
    and covers two and misses none when it may
    """
    parts = []
    for counting in COUNTINGS:
        rows = [t for t in table if t["counting"] == counting]
        if not rows:
            continue
        clauses = [f"covers {_words(t['covered'])} and misses {_words(t['missed'])} {WHEN[t['reading']]}" for t in rows]
        parts.append(f"counting {NAMED[counting]} ({_words(rows[0]['families'])}), it " + ", and ".join(clauses))
    return "; ".join(parts)
