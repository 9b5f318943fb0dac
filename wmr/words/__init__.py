r"""The words of wmr's output, one presentation layer over the analyses' data: what the command line prints and
the notebooks show.

=================================  ===========================================================================
module                             what
=================================  ===========================================================================
:mod:`~wmr.words.glossary`         the terms of the output explained (``wmr explain``, the notes of ``wmr analyze``)
:mod:`~wmr.words.families`         the families of singular configurations in geometric words, and for a driver
:mod:`~wmr.words.limitations`      what a robot cannot do, and where a motion takes it, in plain sentences
:mod:`~wmr.words.advice`           the checked design advice in sentences, with its numbers
=================================  ===========================================================================

The analyses return data (:mod:`wmr.analysis`); the words are made from it here, so that a test of an
analysis checks its data, and a test of the words checks the words.
"""

from . import advice, families, glossary, limitations

__all__ = ["advice", "families", "glossary", "limitations"]
