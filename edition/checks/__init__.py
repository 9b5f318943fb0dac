r"""The checks behind the chapters: each derivation compared with the printed statement, written once.

One module per chapter, so that a notebook shows the physics and calls one function per equation:

=======================  ====================================================================
:mod:`.wheels`           Chapter 1, (1)-(19): rigid-body velocities, the rolling disk, offset and dual wheels
:mod:`.assembly`         Chapter 2, (20)-(29): stacking the units, the null space of F, drift, dead zone
:mod:`.isotropy`         Chapter 3, (30)-(50): condition number, isotropy of :math:`\mathbf J_{L1}`, :math:`\mathbf J_2`
:mod:`.centred`          Chapter 4, (51)-(59): centred wheels, mobility, :math:`\det\mathbf J` and its zero set
:mod:`.steering`         Chapter 5, (60)-(65): steering angles and the instantaneous centre
:mod:`.dual`             Chapter 6: dual wheels, omnidirectionality, discontinuous heading
=======================  ====================================================================

Each check returns a :class:`Derivation`: the derived objects a chapter typesets (as attributes)
and the :class:`~edition.ledger.Finding` objects it establishes (``findings``).  Whether a
printed form holds is always computed (SymPy or a counterexample); the verdict is computed from
it by :func:`edition.ledger.grade`.  Cross-checks that must hold for the evidence to mean
anything (the package's kernels agree with the derivation) go through :func:`require`, which
raises :class:`CheckError` instead of recording a row.  Random samples use the fixed seed
:data:`edition.verify.SEED`.
"""

from __future__ import annotations

from types import SimpleNamespace

from ..ledger import Finding

__all__ = ["CheckError", "Derivation", "require", "equation", "claim"]


class CheckError(AssertionError):
    """A cross-check that the evidence rests on failed: no row may be recorded."""


def require(condition, what):
    """Raise :class:`CheckError` naming ``what`` unless ``condition`` holds.

    Parameters
    ----------
    condition : bool
    what : str
        What was expected, for the message.

    Returns
    -------
    None
    """
    if not bool(condition):
        raise CheckError(f"check failed: {what}")


class Derivation(SimpleNamespace):
    """Named results of one derivation (for the chapter to show) and ``findings``, the rows they establish.

    Parameters
    ----------
    **items
        Derived objects by name, and ``findings`` (a sequence of :class:`~edition.ledger.Finding`).
    """

    def __init__(self, **items):
        items.setdefault("findings", ())
        items["findings"] = tuple(items["findings"])
        super().__init__(**items)

    def __getitem__(self, id):
        for f in self.findings:
            if f.id == str(id):
                return f
        raise KeyError(id)


def equation(
    id,
    holds,
    proven,
    residual,
    *,
    refuted="",
    corrected="",
    corrected_holds=False,
    severity="",
    why="",
    convention="",
    note="",
    scope="",
    overturn="",
):
    r"""A :class:`~edition.ledger.Finding` for a numbered equation, its ``check`` text built from what was shown.

    Parameters
    ----------
    id : str or int
        The equation number.
    holds : bool
        Whether the printed form was proven.
    proven : str
        What was proven (Markdown): of the printed form when it holds, of the corrected form otherwise.
    residual : float
        Largest numerical residual of the proven form.
    refuted : str, optional
        How the printed form was refuted (a counterexample, the nonzero difference).
    corrected, corrected_holds, severity, why, convention, note, scope, overturn
        As in :class:`~edition.ledger.Finding`.

    Returns
    -------
    edition.ledger.Finding
    """
    holds = bool(holds)
    check = (
        f"printed form proven: {proven}"
        if holds
        else f"printed form refuted ({refuted}); corrected form proven: {proven}"
    )
    return Finding(
        str(id),
        holds,
        check,
        float(residual),
        corrected=corrected,
        corrected_holds=bool(corrected_holds),
        severity=severity,
        why=why,
        convention=convention,
        note=note,
        scope=scope,
        overturn=overturn,
    )


def claim(
    slug,
    holds,
    proven,
    residual,
    *,
    refuted="",
    corrected="",
    corrected_holds=False,
    severity="",
    why="",
    convention="",
    note="",
    scope="",
    overturn="",
):
    r"""A :class:`~edition.ledger.Finding` for a claim of the text (see :func:`equation`).

    Parameters
    ----------
    slug : str
    holds : bool
        Whether the claim was proven.
    proven : str
        What was proven: the claim's own evidence when it holds, the corrected statement's otherwise.
    residual : float
    refuted, corrected, corrected_holds, severity, why, convention, note, scope, overturn
        As in :func:`equation`.

    Returns
    -------
    edition.ledger.Finding
    """
    holds = bool(holds)
    check = f"claim proven: {proven}" if holds else f"claim refuted ({refuted}); what is true, proven: {proven}"
    return Finding(
        slug,
        holds,
        check,
        float(residual),
        corrected=corrected,
        corrected_holds=bool(corrected_holds),
        severity=severity,
        why=why,
        convention=convention,
        note=note,
        scope=scope,
        overturn=overturn,
    )
