r"""Finding cards: for each independent problem and each physics verdict, what a referee needs on one card.

A card states the claim, its verdict, the readings it is judged under, what it depends on (convention, model,
parameters) and what would overturn it.  Every field is read from what the chapters wrote -- the ledger
(``figures/ledger.csv``, :mod:`edition.ledger`) and ``figures/physics.csv`` (:mod:`edition.physics`) -- and
nothing here is judged again: a card only puts side by side what the computations recorded.

:func:`problem_card` makes the card of one independent problem (:func:`edition.problems.problems`: failing rows
merged where they are one error); :func:`physics_card` the card of one physics verdict.
"""

from __future__ import annotations

import re

__all__ = ["KINEMATIC_MODEL", "problem_card", "physics_card", "evidence"]

#: The model every kinematic verdict is computed in: the paper's own (its Section 2)
KINEMATIC_MODEL = (
    "the paper's kinematic model (its Section 2): rigid bodies, ideal joints, thin wheels rolling without slip "
    "at a point contact on a plane"
)


def evidence(row):
    """How a ledger row's verdict was computed: exact algebra, numerics, or both, with the residual.

    Parameters
    ----------
    row : dict
        A ledger row (``check`` and ``residual`` are read).

    Returns
    -------
    str

    Examples
    --------
    >>> evidence({"check": "printed form proven (SymPy) at 200 random rates", "residual": "< 1e-12"})
    'exact algebra (SymPy) and a numerical check (largest residual < 1e-12)'
    >>> evidence({"check": "refuted at 2000 random configurations", "residual": "0.031"})
    'a numerical check (largest residual 0.031)'
    """
    numeric = f"a numerical check (largest residual {row['residual']})"
    return f"exact algebra (SymPy) and {numeric}" if "SymPy" in row["check"] else numeric


def _sentence(text):
    return str(text).strip().rstrip(".")


def problem_card(number, rows, readings, inferred, name):
    """The card of one independent problem (Markdown).

    Parameters
    ----------
    number : int
        The problem's number in the table of independent problems.
    rows : list of dict
        Its ledger rows (one, or several merged).
    readings : dict str -> str
        Equation number -> how the extracted text is read (:func:`edition.findings.readings`).
    inferred : dict str -> str
        Equation number -> the convention inferred (:data:`edition.findings.INFERRED`).
    name : callable
        A row -> its name as the report prints it (linked to its derivation).

    Returns
    -------
    str
        A heading line and a list: claim, verdict, readings, depends on, would overturn it.

    Examples
    --------
    >>> row = {"id": "42", "kind": "equation", "section": "4.3", "verdict": "typo", "why": "a sign slip",
    ...        "convention": "", "scope": "", "check": "refuted; proven (SymPy)", "residual": "0",
    ...        "overturn": "a page with the other sign"}
    >>> print(problem_card(5, [row], {}, {}, lambda r: f"({r['id']})"))  # doctest: +NORMALIZE_WHITESPACE
    **Problem 5: (42)**, paper §4.3, *typo*
    <BLANKLINE>
    - *Claim:* (42) as printed (the errata show it beside the corrected form).
    - *Verdict:* *typo*: a sign slip.
    - *Readings:* the printed form as transcribed; no convention beyond the paper's stated ones.
    - *Depends on:* the paper's kinematic model (its Section 2): rigid bodies, ideal joints, thin wheels rolling
      without slip at a point contact on a plane; exact algebra (SymPy) and a numerical check (largest
      residual 0).
    - *Would overturn it:* a page with the other sign.
    """
    names = [name(r) for r in rows]
    plural = len(rows) > 1

    def who(n):  # a field's owner, named only where a card merges several rows
        return f"{n}, " if plural else ""

    sections = ", ".join(
        dict.fromkeys(
            f"§{s.strip()}" if s.strip()[:1].isdigit() else s.strip() for r in rows for s in r["section"].split(",")
        )
    )
    verdict = "wrong" if any(r["verdict"] == "wrong" for r in rows) else "typo"
    claims = []
    for r, n in zip(rows, names):
        if r["kind"] == "equation":
            claims.append(f"{n} as printed (the errata show it beside the corrected form)")
        else:
            claims.append(f"{n}: “{_sentence(r['printed'])}”")
    reads = []
    for r, n in zip(rows, names):
        if r["id"] in readings:
            reads.append(f"{who(n)}extracted text: {_sentence(readings[r['id']])}")
        if r["id"] in inferred:
            reads.append(f"{who(n)}convention inferred (not stated in the paper): {_sentence(inferred[r['id']])}")
        if r["convention"]:
            reads.append(f"{who(n)}convention: {_sentence(r['convention'])}")
        if r["scope"]:
            label, _, text = r["scope"].partition(":")
            reads.append(f"{who(n)}scope ({label.strip()}): {_sentence(text)}")

    def each(field):  # one field of every row, named by its row where the card merges several
        return "; ".join(f"{n}: {field(r)}" if plural else field(r) for r, n in zip(rows, names))

    why = each(lambda r: _sentence(r["why"]))
    depends = each(evidence)
    overturn = each(lambda r: _sentence(r["overturn"]))
    return (
        f"**Problem {number}: {', '.join(names)}**, paper {sections}, *{verdict}*\n\n"
        f"- *Claim:* {'; '.join(claims)}.\n"
        f"- *Verdict:* *{verdict}*: {why}.\n"
        f"- *Readings:* {'; '.join(reads) or NO_READING}.\n"
        f"- *Depends on:* {KINEMATIC_MODEL}; {depends}.\n"
        f"- *Would overturn it:* {overturn}."
    )


NO_READING = "the printed form as transcribed; no convention beyond the paper's stated ones"
_CITED = re.compile(r"\s*\(((?:[^()]|\([^()]*\))*)\)\s*$")  # the trailing "(4.2, Fig. 7, (28)-(29))" of a claim


def physics_card(row):
    """The card of one physics verdict (Markdown), from a row of ``physics.csv``.

    Parameters
    ----------
    row : dict
        A row of ``figures/physics.csv`` (:data:`edition.physics.COLUMNS`).

    Returns
    -------
    str
        A heading line and a list: claim, verdict, readings (prediction and measurement), depends on (what it
        rests on and the parameters of the run), would overturn it.

    Examples
    --------
    >>> row = {"experiment": "braking", "claim": "Fig. 12a brakes (5.3, Fig. 12a)", "whose": "paper",
    ...        "verdict": "holds (push >= 10 x)", "prediction": "rank F = 6", "measurement": "0.55 W",
    ...        "rests_on": "Coulomb friction", "parameters": "mu = 1", "overturn": "a weaker push"}
    >>> print(physics_card(row).splitlines()[0])
    **Physics: braking**, the paper's claim (5.3, Fig. 12a), *holds (push >= 10 x)*
    """
    m = _CITED.search(row["claim"])
    cited = m.group(1) if m else ""
    claim = row["claim"][: m.start()] if m else row["claim"]
    whose = "the paper's claim" if row["whose"] == "paper" else "this edition's own prediction"
    quote = f" The paper: {row['quote']}" if row.get("quote") else ""
    box = (
        f" Nominal run: {row['nominal']}. Over the box ({row['box']}): {row['box_holds']} hold, {row['box_invalid']} "
        f"invalid; where it flips: {row['flips']}."
        if row.get("box")
        else ""
    )
    return (
        f"**Physics: {row['experiment'].replace('-', ' ')}**, {whose}{f' ({cited})' if cited else ''}, "
        f"*{row['verdict']}*\n\n"
        f"- *Claim:* {_sentence(claim)}.{quote}\n"
        f"- *Verdict:* *{row['verdict']}*, computed from the measurements by the rule and criterion in "
        f"parentheses.{box}\n"
        f"- *Readings:* the prediction (wmr): {_sentence(row['prediction'])}; the measurement (MuJoCo): "
        f"{_sentence(row['measurement'])}.\n"
        f"- *Depends on:* {_sentence(row['rests_on'])}; the run: {_sentence(row['parameters'])}.\n"
        f"- *Would overturn it:* {_sentence(row['overturn'])}."
    )
