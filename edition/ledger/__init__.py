r"""The ledger of verdicts: one row per equation (2)-(65) and per checked claim of the paper.

A check (:mod:`edition.checks`) compares a printed statement with what the model proves and
returns a :class:`Finding`: whether the printed form holds, what was proven, the corrected form
when it does not, the largest numerical residual.  :meth:`Ledger.add` turns a finding into a
:class:`Row` and **computes** the verdict from it (:func:`grade`): ``ok`` when the printed form is
proven; ``typo`` or ``wrong`` (the class of error the check names) only when the printed form is
refuted *and* a corrected form is proven, otherwise it fails loudly with the reason.  A changed
transcription therefore re-grades its row, or stops the chapter.

Each notebook writes its rows to ``<figures>/ledger/<notebook>.csv`` (:meth:`Ledger.write`);
``python -m edition.ledger DIR`` merges the fragments into ``DIR/ledger.csv`` (equations in
numeric order, then claims) and reports what is missing.  Columns (:data:`COLUMNS`):

``id``, ``kind``, ``section``, ``verdict``
    Equation number or claim slug; ``equation`` or ``claim``; the paper's section; the verdict.
``printed``, ``corrected``
    For an equation the LaTeX body of the printed form (no ``$``) and of the proven form (empty
    for ``ok``); for a claim the quoted sentence and what is true, Markdown with ``$...$`` math.
``why``, ``convention``, ``check``, ``note``
    Markdown with ``$...$`` math: why the printed form fails (one line, ``typo``/``wrong`` only),
    the convention under which the verdict holds, what was proven, anything else.
``printed_holds``, ``residual``
    ``yes``/``no``; the largest numerical residual as a bound (:func:`edition.text.bound`).
``notebook``, ``anchor``
    The notebook that derives the row, and the HTML id it puts before the derivation
    (``eq-59``, ``claim-drift``).

No field may carry ASCII pseudo-math (``psi_dot``, ``!=``, ``<=>``, ``^T``, ``3*1``): math is
written in ``$...$`` (:func:`ascii_math` finds offenders; :meth:`Ledger.add` rejects them).

The parts: :mod:`~edition.ledger.verdict` (findings and their grading),
:mod:`~edition.ledger.markup` (the text rules of a row), :mod:`~edition.ledger.rows` (a
notebook's rows and their fragment) and :mod:`~edition.ledger.store` (reading, checking and
merging the fragments; ``python -m edition.ledger``).
"""
from .verdict import COLUMNS, KINDS, VERDICTS, SEVERITIES, EQUATIONS, Finding, grade
from .markup import ascii_math, anchor
from .rows import Row, Ledger
from .store import read, problems, merge, main

__all__ = ["COLUMNS", "KINDS", "VERDICTS", "SEVERITIES", "EQUATIONS", "Finding", "Row", "Ledger", "grade",
           "ascii_math", "anchor", "read", "problems", "merge", "main"]
