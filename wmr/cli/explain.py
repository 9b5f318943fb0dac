"""``wmr explain [TERM]``: what a word of wmr's output means, in plain language.

Examples::

    wmr explain                 # every term, one line each
    wmr explain rank-F
    wmr explain "kappa(J_L1)"
    wmr explain through-P

The glossary is :mod:`wmr.words.glossary`; ``wmr analyze`` prints the lines of the terms its
table uses under the table.
"""

from __future__ import annotations

import argparse
import textwrap

__all__ = ["HELP", "add_arguments", "run"]

HELP = "explain a term of wmr's output (rank-F, nullity, J_L1, J2, kappa, through-P, actuated-mobility, ...)"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Options of ``wmr explain``.

    Parameters
    ----------
    parser : argparse.ArgumentParser

    Returns
    -------
    None
    """
    parser.add_argument(
        "term", nargs="?", default=None, help="the term (case, spaces, - and _ do not matter); none: list every term"
    )


def run(args: argparse.Namespace) -> int:
    """Run ``wmr explain``.

    Parameters
    ----------
    args : argparse.Namespace

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
