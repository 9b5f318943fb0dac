r"""What a check establishes (:class:`Finding`), the verdict computed from it (:func:`grade`), a row's columns.

Part of the ledger: :mod:`edition.ledger`.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = [
    "COLUMNS",
    "KINDS",
    "VERDICTS",
    "SEVERITIES",
    "SCOPES",
    "EQUATIONS",
    "Finding",
    "grade",
    "anchor",
    "scope_label",
]


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
    "scope",
    "overturn",
)
KINDS = ("equation", "claim")
VERDICTS = ("ok", "typo", "wrong")
#: Classes of error a check may name for a refuted printed form: a slip of print (sign, factor,
#: size) that the surrounding argument does not rest on, or a false statement.
SEVERITIES = ("typo", "wrong")
EQUATIONS = tuple(str(n) for n in range(1, 66))
#: How far a verdict reaches, when less far than its label alone says: ``"label: what the computation showed"``,
#: the label one of these, with the verdicts it may qualify.  Set by the check from what it computed.
SCOPES = {
    "presupposition fails": ("wrong",),  # the implication holds; what it presupposes does not
    "terminology": ("wrong",),  # false under the meaning of a word the paper uses elsewhere, true under another
    "special case": ("ok",),  # proven only for the cases named (a family of robots, an assumption stated later)
}


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
    scope : str
        ``"label: explanation"`` with a label of :data:`SCOPES`, when the verdict reaches less far than its
        label alone says (computed by the check), else empty.
    overturn : str
        What would overturn the verdict (Markdown): the reading, convention or model under which the
        printed form would hold after all.  Required where the printed form fails (the report's finding cards
        print it), optional otherwise.
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
    scope: str = ""
    overturn: str = ""


def scope_label(scope):
    """The label of a ``scope`` field (``"terminology: ..."`` -> ``"terminology"``), ``""`` when empty.

    Examples
    --------
    >>> scope_label("special case: tested at mobility 1"), scope_label("")
    ('special case', '')
    """
    return str(scope).split(":", 1)[0].strip()


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
        When the printed form fails but no corrected form was proven, or the severity, the
        one-line *why* or what would overturn the verdict is missing: the message names the row and says what the check found.

    Examples
    --------
    >>> grade(Finding("42", False, "signs refuted", 0.0, corrected="d^2", corrected_holds=True,
    ...               severity="typo", why="sign slip", overturn="a page that prints the other sign"))
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
    _check_scope(finding)
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
    if not str(finding.overturn).strip():
        raise ValueError(
            f"{label}: the printed form is refuted but 'overturn' (what would overturn the verdict) is empty"
        )
    return finding.severity


def _check_scope(finding):
    if not finding.scope:
        return
    label = scope_label(finding.scope)
    verdict = "ok" if finding.printed_holds else finding.severity
    if label not in SCOPES or not finding.scope.split(":", 1)[1:] or not finding.scope.split(":", 1)[1].strip():
        raise ValueError(f"{_label(finding.id)}: scope must be 'label: explanation' with a label of {sorted(SCOPES)}")
    if verdict not in SCOPES[label]:
        raise ValueError(f"{_label(finding.id)}: scope {label!r} cannot qualify the verdict {verdict!r}")


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
