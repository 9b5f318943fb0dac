r"""What a check establishes (:class:`Finding`), the verdict computed from it (:func:`grade`), a row's columns.

Part of the ledger: :mod:`edition.ledger`.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["COLUMNS", "KINDS", "VERDICTS", "SEVERITIES", "EQUATIONS", "Finding", "grade", "anchor"]


COLUMNS = (
    "id",
    "kind",
    "section",
    "verdict",
    "printed",
    "corrected",
    "why",
    "convention",
    "check",
    "printed_holds",
    "residual",
    "notebook",
    "anchor",
    "note",
)
KINDS = ("equation", "claim")
VERDICTS = ("ok", "typo", "wrong")
#: Classes of error a check may name for a refuted printed form: a slip of print (sign, factor,
#: size) that the surrounding argument does not rest on, or a false statement.
SEVERITIES = ("typo", "wrong")
EQUATIONS = tuple(str(n) for n in range(1, 66))


@dataclass(frozen=True)
class Finding:
    r"""What a check established about one printed equation or claim.

    Attributes
    ----------
    id : str
        Equation number (``"1"`` .. ``"65"``) or a claim's slug.
    printed_holds : bool
        Whether the printed form (or claim) was proven: computed by the check, never typed.
    check : str
        What was proven, in words (Markdown with ``$...$``).
    residual : float
        Largest numerical residual of the proven form (finite, ``>= 0``).
    corrected : str
        The proven form where the printed one fails: LaTeX body for an equation, Markdown for a claim.
    corrected_holds : bool
        Whether ``corrected`` was proven.
    severity : str
        ``typo`` or ``wrong``: the class of error if the printed form fails (ignored when it holds).
    why : str
        One line: why the printed form fails (Markdown).
    convention : str
        The convention under which the verdict holds (Markdown).
    note : str
        Anything else (Markdown).
    """

    id: str
    printed_holds: bool
    check: str
    residual: float
    corrected: str = ""
    corrected_holds: bool = False
    severity: str = ""
    why: str = ""
    convention: str = ""
    note: str = ""


def grade(finding):
    """The verdict of a finding: ``ok`` if the printed form holds, else its severity, if the correction is proven.

    Parameters
    ----------
    finding : Finding

    Returns
    -------
    str
        One of :data:`VERDICTS`.

    Raises
    ------
    ValueError
        When the printed form fails but no corrected form was proven, or the severity or the
        one-line *why* is missing: the message names the row and says what the check found.

    Examples
    --------
    >>> grade(Finding("42", False, "signs refuted", 0.0, corrected="d^2", corrected_holds=True,
    ...               severity="typo", why="sign slip"))
    'typo'
    >>> grade(Finding("42", True, "proven", 0.0, corrected="d^2", corrected_holds=True, severity="typo"))
    'ok'
    """
    if not isinstance(finding, Finding):
        raise TypeError(f"finding must be a Finding, got {type(finding).__name__}")
    if not isinstance(finding.printed_holds, bool):
        raise TypeError(
            f"printed_holds of row {finding.id!r} must be a bool (the outcome of the check), "
            f"got {finding.printed_holds!r}"
        )
    if finding.printed_holds:
        return "ok"
    label = _label(finding.id)
    if not str(finding.corrected).strip() or finding.corrected_holds is not True:
        raise ValueError(f"{label}: the printed form is refuted ({finding.check}) but no corrected form was proven")
    if finding.severity not in SEVERITIES:
        raise ValueError(
            f"{label}: the printed form is refuted; severity must be one of {SEVERITIES}, got {finding.severity!r}"
        )
    if not str(finding.why).strip():
        raise ValueError(f"{label}: the printed form is refuted but 'why' is empty")
    return finding.severity


def _label(id):
    return f"({id})" if str(id).isdigit() else f"claim {id!r}"


def anchor(id):
    """The HTML id a notebook puts before the derivation of row ``id``: ``eq-59`` or ``claim-drift``.

    Parameters
    ----------
    id : str or int

    Returns
    -------
    str

    Examples
    --------
    >>> anchor(59), anchor("drift")
    ('eq-59', 'claim-drift')
    """
    id = str(id)
    return f"eq-{id}" if id.isdigit() else f"claim-{id}"
