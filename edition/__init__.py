r"""The executable edition of Leow, Low & Loh (2002), built on the library :mod:`wmr`.

* The paper as printed is a table, ``edition/printed.toml``: every numbered equation (1)-(65)
  with its LaTeX, its SymPy form, what the text extraction shows and any doubt about it, and the
  claims of the text that the edition checks.  :mod:`edition.transcription` reads it
  (:func:`printed`, :func:`claim`); the names its SymPy forms use are :mod:`edition.symbols`.
* :mod:`edition.checks` derives each result from the model and compares it with the printed
  form; :mod:`edition.ledger` grades what a check found and keeps the rows.
* :mod:`edition.notebook` is what the chapters share; :mod:`edition.figures` draws the paper's
  figures; :mod:`edition.exercises` grades the chapters' exercises.

Imports go one way: edition -> wmr.
"""

from .transcription import Claim, Printed, claim, printed

__all__ = ["Printed", "Claim", "printed", "claim"]
