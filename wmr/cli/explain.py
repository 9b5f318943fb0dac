"""``wmr explain [TERM]``: what a word of wmr's output means, in plain language.

Example (no term: every term, one line each)::

    wmr explain "kappa(J_L1)"

The glossary is :mod:`wmr.words.glossary`; ``wmr analyze`` prints the lines of the terms its
table uses under the table.
"""

from __future__ import annotations

import argparse
import textwrap

__all__ = ["run"]


def run(args: argparse.Namespace) -> int:
    """Run ``wmr explain``.

    Parameters
    ----------
    args : argparse.Namespace
        The options of ``wmr explain`` (:func:`wmr.cli.main` parses them).

    Returns
    -------
    int
        0; an unknown term raises an input error (one line, with the closest term; status 2).
    """
    from ..words.glossary import GLOSSARY, lookup

    if args.term is None:
        width = max(len(t) for t in GLOSSARY)
        for term, e in GLOSSARY.items():
            print(f"{term:<{width}}  {e.short}")
        print("\nwmr explain TERM says more.")
        return 0
    e = lookup(args.term)
    print(f"{e.term}: {e.short}\n")
    print(textwrap.fill(e.text, width=100))
    return 0
