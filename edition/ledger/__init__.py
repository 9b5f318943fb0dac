r"""The ledger of verdicts: one row per equation (1)-(65) and per checked claim of the paper.

A check (:mod:`edition.checks`) compares a printed statement with what the model proves and
returns a :class:`Finding`: whether the printed form holds, what was proven, the corrected form
when it does not, the largest numerical residual.  :meth:`Ledger.add` turns a finding into a
:class:`Row` and **computes** the verdict from it (:func:`grade`): ``ok`` when the printed form is
proven; ``typo`` or ``wrong`` (the class of error the check names) only when the printed form is
refuted *and* a corrected form is proven, otherwise it fails loudly with the reason.  A changed
transcription therefore re-grades its row, or stops the chapter.

Each chapter writes its rows to ``$WMR_OUT/ledger.csv`` (:meth:`Ledger.write`); :func:`assemble`
validates the chapters' rows and concatenates them into the published ledger (equations in numeric
order, then claims); ``python -m edition.ledger CHAPTERS... DEST`` does the same from a shell.
Columns (:data:`COLUMNS`):

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
``scope``
    ``"label: explanation"`` when the verdict reaches less far than its label alone says (:data:`SCOPES`:
    a presupposition that fails, a dispute of terminology, a special case), computed by the check; else empty.
``overturn``
    Markdown: what would overturn a ``typo`` or ``wrong`` verdict (the reading, convention or model under
    which the printed form would hold after all); empty for ``ok``.  The report's finding cards print it.

No field carries ASCII pseudo-math (``psi_dot``, ``!=``, ``<=>``, ``^T``, ``3*1``): math is
written in ``$...$``.  That is a rule of the text, checked by the tests over the published ledger
and the transcription, not at run time.

The parts: :mod:`~edition.ledger.verdict` (findings, their grading, the columns),
:mod:`~edition.ledger.rows` (a chapter's rows and its file) and :mod:`~edition.ledger.store`
(validating and concatenating the chapters' files; ``python -m edition.ledger``).
"""

from .rows import Ledger, Row
from .store import LedgerError, assemble, fragments, main, problems, read
from .verdict import COLUMNS, EQUATIONS, KINDS, SCOPES, SEVERITIES, VERDICTS, Finding, anchor, grade, scope_label

__all__ = [
    "COLUMNS",
    "KINDS",
    "VERDICTS",
    "SEVERITIES",
    "SCOPES",
    "scope_label",
    "EQUATIONS",
    "Finding",
    "Row",
    "Ledger",
    "grade",
    "anchor",
    "LedgerError",
    "read",
    "fragments",
    "problems",
    "assemble",
    "main",
]
