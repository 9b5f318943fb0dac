r"""The words of wmr's output, one presentation layer over the analyses' data: what the command line prints and
the notebooks show.

=================================  ===========================================================================
module                             what
=================================  ===========================================================================
:mod:`~wmr.words.glossary`         the terms of the output explained (``wmr explain``, the notes of ``wmr analyze``)
:mod:`~wmr.words.families`         the families of singular configurations in geometric words, and for a driver
=================================  ===========================================================================

The analyses return data (:mod:`wmr.analysis`); the words are made from it here, so that a test of an
analysis checks its data, and a test of the words checks the words.
"""

from . import families, glossary

__all__ = ["families", "glossary"]
