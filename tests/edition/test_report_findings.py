"""What Part I computes itself (issue 19): the singular families counted under a stated reading, the
locked-drive claim as Chapter 2 judges it, the number of equations the paper numbers, the apparatus."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from edition import findings as F
from edition.families import ITEMS, READINGS, accounting, covering_items
from wmr.model.robots import paper_robot

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def fams():
    return {f.key: f for f in accounting(n=24)}


def test_families_modulo_a_half_turn_each_singular_exactly(fams):
    assert len(fams) == 10 and not [k for k in fams if k.endswith("'")], "a half-turned family counted apart"
    assert all(f.det_J_exact_zero for f in fams.values())
    assert all(f.det_J_max < 1e-9 for f in fams.values())


def test_the_mount_point_families_are_the_ones_missed(fams):
    missed = sorted(k for k, f in fams.items() if f.listed_in_paper == "no")
    assert missed == ["v-P1", "v-P2", "v-P3"]
    assert all(fams[k].note == "(v)" for k in missed), "read with D_P at a mount point, (v) covers them"
    assert fams["v-circle"].paper_item == "(v)", "(v-c) lies inside (v): not missed, not counted twice"
    assert fams["i"].paper_item == "(i)" and fams["pair-13"].paper_item == "(ii)"


def test_covering_items_can_say_no():
    bot = paper_robot("centred")
    rng = np.random.default_rng(3)
    for reading in READINGS:
        held = covering_items(bot, rng.uniform(-np.pi, np.pi, (200, 3)), reading)
        assert set(held) == set(ITEMS) and not any(h.any() for h in held.values()), "a regular configuration covered"
    turned = np.array([[0.4, 0.4 + np.pi, 0.4]])  # (i) with wheel 2 turned half a turn
    assert covering_items(bot, turned)["(i)"].all()
    with pytest.raises(ValueError, match="reading"):
        covering_items(bot, turned, "literal")


def test_locked_drive_claim_is_judged_on_whenever():
    """Chapter 2's check judges the claim "drift" on its word *whenever* from the chapter's derived det M, and the
    published ledger carries that verdict (Part I reads it, never judges it again)."""
    from types import SimpleNamespace

    from edition.checks.assembly import drift, locked_steering
    from edition.derivations import derived
    from edition.ledger import read as read_ledger

    ch2 = derived("02_offset_wheels_and_mobility")
    locked = locked_steering(ch2["det_M"], ch2["plucker"], robots=20, per=5)
    quiet = SimpleNamespace(residual=0.0)
    d = drift(quiet, quiet, locked, ch2["J2"], per=100)
    f = d["drift"]
    assert not f.printed_holds and f.corrected_holds and f.severity == "wrong"
    assert d.ranks == [6] and d.equal_rank == 5 and d.concurrent_rank == 5
    assert "all $\\beta_i$ equal" in f.corrected
    # a locked system that is singular everywhere (the claim would then hold) is not judged wrong
    singular = SimpleNamespace(**{**vars(locked), "ranks": {5}})
    assert drift(quiet, quiet, singular, ch2["J2"], per=10)["drift"].printed_holds
    row = next(r for r in read_ledger(ROOT / "figures" / "ledger.csv") if r["kind"] == "claim" and r["id"] == "drift")
    assert row["verdict"] == "wrong" and row["printed_holds"] == "no" and row["anchor"] == "claim-drift"


def test_equation_count_from_the_transcription():
    ledger = [{"kind": "equation", "id": str(n)} for n in (2, 3, 65)] + [{"kind": "claim", "id": "drift"}]
    c = F.equation_count(ledger)
    assert c["numbered"] == 65 and c["judged"] == [2, 3, 65]
    assert c["not_judged"][:3] == [1, 4, 5] and 1 not in c["not_transcribed"]
    assert F.equation_count([{"kind": "equation", "id": str(n)} for n in range(1, 66)])["not_judged"] == []


def test_readings_and_inferred_conventions_name_real_equations():
    from edition.transcription import table

    eqs = table().equations
    assert set(F.readings()) <= set(eqs) and {"13", "15", "21"} <= set(F.readings())
    assert set(F.INFERRED) <= set(eqs)


def test_environment_and_citation():
    env = F.environment()
    assert env["Python"] and env["numpy"] == np.__version__
    cite = F.citation()
    assert cite["bibtex"].startswith("@software{") and cite["version"] and cite["licence"]
    assert max(len(line) for line in cite["bibtex"].splitlines()) <= 72, "BibTeX wider than the page"
