"""Finding cards (edition.cards): every field read from the recorded rows, merged rows named field by field."""

from __future__ import annotations

from edition.cards import physics_card, problem_card


def _row(id, kind="equation", **kw):
    row = {
        "id": id,
        "kind": kind,
        "section": "3.2",
        "verdict": "wrong",
        "why": f"why {id}",
        "convention": "",
        "scope": "",
        "check": "refuted (SymPy)",
        "residual": "< 1e-12",
        "overturn": f"overturn {id}",
        "printed": f"printed {id}",
    }
    return row | kw


def test_a_merged_card_names_each_row_in_each_field():
    card = problem_card(
        1, [_row("15"), _row("16", convention="as (15)")], {"15": "2h read as 2b"}, {}, lambda r: f"({r['id']})"
    )
    assert card.startswith("**Problem 1: (15), (16)**, paper §3.2, *wrong*")
    for text in (
        "(15): why 15",
        "(16): why 16",
        "(15), extracted text: 2h read as 2b",
        "(16), convention: as (15)",
        "(15): overturn 15",
        "(16): overturn 16",
    ):
        assert text in card, text


def test_a_single_card_takes_its_fields_unprefixed_and_its_claim_quoted():
    card = problem_card(2, [_row("drift", kind="claim", scope="terminology: a word")], {}, {}, lambda r: "the claim")
    assert "- *Verdict:* *wrong*: why drift." in card and "- *Would overturn it:* overturn drift." in card
    assert "the claim: “printed drift”" in card and "scope (terminology): a word" in card


def test_a_physics_card_says_whose_claim_and_what_it_rests_on():
    row = {
        "experiment": "jam",
        "claim": "the robot jams (Chapter 2)",
        "whose": "edition",
        "verdict": "holds (x)",
        "prediction": "rank 6",
        "measurement": "0.5 %",
        "rests_on": "the servo cap",
        "parameters": "mu = 1",
        "overturn": "stronger servos",
    }
    card = physics_card(row)
    assert card.startswith("**Physics: jam**, this edition's own prediction (Chapter 2), *holds (x)*")
    assert "the servo cap; the run: mu = 1." in card and "*Would overturn it:* stronger servos." in card
    assert "- *Claim:* the robot jams." in card
