r"""The words of wmr's output, one presentation layer over the analyses' data (the command line, the notebooks):
:mod:`~wmr.words.glossary` (the terms explained), :mod:`~wmr.words.families` (singular families in words),
:mod:`~wmr.words.limitations` (what a robot cannot do), :mod:`~wmr.words.advice` (design advice in sentences).
A test of an analysis checks its data, a test of the words checks the words.
"""

from . import advice, families, glossary, limitations

__all__ = ["advice", "families", "glossary", "limitations"]
