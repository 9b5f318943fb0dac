"""What the report reads: the ledger, the figures' metadata, the singularity list, the executed
chapters. Data only (no formatting); counts for the prose are computed here, from these files.

The ledger's columns are fixed by the contract between the workstreams (``CONTRACTS.md``):
``id, kind, section, verdict, printed, corrected, why, convention, check, printed_holds, residual,
notebook, anchor, note``; every text field is Markdown with ``$...$`` math, ``printed`` and
``corrected`` of an equation are LaTeX bodies.
"""
from __future__ import annotations

import csv
import json
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

from .paths import Tree

__all__ = ["LEDGER_COLUMNS", "VERDICTS", "Entry", "FigureMeta", "Inputs", "read_inputs"]

LEDGER_COLUMNS = ("id", "kind", "section", "verdict", "printed", "corrected", "why", "convention", "check",
                  "printed_holds", "residual", "notebook", "anchor", "note")
VERDICTS = ("ok", "typo", "wrong")

@dataclass(frozen=True)
class Entry:
    """One ledger row: an equation of the paper or a claim of its text, and its verdict."""

    id: str
    kind: str
    section: str
    verdict: str
    printed: str
    corrected: str
    why: str
    convention: str
    check: str
    printed_holds: str
    residual: str
    notebook: str
    anchor: str
    note: str

    @property
    def is_equation(self) -> bool:
        return self.kind == "equation"

    @property
    def label(self) -> str:
        """``(59)`` for an equation, the claim's slug otherwise."""
        return f"({self.id})" if self.is_equation else self.id

    @property
    def chapter(self) -> str:
        """The chapter (notebook number) that derives it: ``"04"`` of ``04_centred...``."""
        return self.notebook.split("_", 1)[0] if self.notebook else ""


def _entry(row: dict) -> Entry:
    missing = [c for c in LEDGER_COLUMNS if c not in row]
    if missing:
        raise ValueError(f"ledger row {row.get('id')!r} lacks the columns {missing}")
    return Entry(**{c: (row[c] or "").strip() for c in LEDGER_COLUMNS})


@dataclass(frozen=True)
class FigureMeta:
    """One figure as written by ``edition.figures.save``: ``figures/<key>.json`` and its images."""

    key: str
    number: str
    title: str
    paper_caption: str
    caption: str
    images: dict = field(default_factory=dict)   # format -> Path (svg, pdf, png) that exist

    @property
    def label(self) -> str:
        return f"Figure {self.number}" if self.number else ""

    def sort_key(self):
        return (0, int(self.number), self.key) if self.number.isdigit() else (1, 0, self.key)


@dataclass
class Inputs:
    """Everything the report shows, read from ``figures/`` and ``build/notebooks/``."""

    ledger: list[Entry] | None
    figures: list[FigureMeta]
    singularities: list[dict] | None
    chapters: list[Path]                   # executed notebooks, in order
    sources: list[Path]                    # the notebooks they were executed from

    # --- counts for the prose (every number in the report's text comes from here)
    def verdicts(self, kind: str | None = None) -> Counter:
        return Counter(e.verdict for e in self.ledger or [] if kind is None or e.kind == kind)

    def equations(self) -> list[Entry]:
        return [e for e in self.ledger or [] if e.is_equation]

    def claims(self) -> list[Entry]:
        return [e for e in self.ledger or [] if not e.is_equation]

    def errata(self) -> list[Entry]:
        """Equations judged typo or wrong, in the paper's order."""
        return [e for e in self.equations() if e.verdict != "ok"]

    def failed_claims(self) -> list[Entry]:
        return [e for e in self.claims() if e.verdict != "ok"]

    def equation_range(self) -> tuple[str, str]:
        ids = sorted(int(e.id) for e in self.equations() if e.id.isdigit())
        return (str(ids[0]), str(ids[-1])) if ids else ("", "")

    def missed_singularities(self) -> list[dict]:
        """Rows of ``singularities.csv`` that the paper does not list."""
        return [r for r in self.singularities or [] if (r.get("listed_in_paper") or "").strip().lower() != "yes"]

    def figure(self, key: str) -> FigureMeta | None:
        return next((f for f in self.figures if f.key == key), None)


def _read_csv(path: Path) -> list[dict] | None:
    if not path.exists():
        return None
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def read_ledger(path: Path) -> list[Entry] | None:
    rows = _read_csv(path)
    return None if rows is None else [_entry(r) for r in rows]


def read_figures(figdir: Path) -> list[FigureMeta]:
    """Every ``figures/<key>.json`` (figures 7-13 in the paper's order, then ours)."""
    out = []
    metas = {p.stem: json.loads(p.read_text(encoding="utf-8")) for p in sorted(figdir.glob("*.json"))}
    for key, m in metas.items():
        if not isinstance(m, dict) or "title" not in m:
            continue
        images = {fmt: figdir / f"{key}.{fmt}" for fmt in ("svg", "pdf", "png") if (figdir / f"{key}.{fmt}").exists()}
        out.append(FigureMeta(key=key, number=str(m.get("number") or ""), title=m.get("title", ""),
                              paper_caption=m.get("paper_caption", "") or "", caption=m.get("caption", "") or "",
                              images=images))
    return sorted(out, key=FigureMeta.sort_key)


def read_inputs(t: Tree) -> Inputs:
    return Inputs(ledger=read_ledger(t.ledger), figures=read_figures(t.figures),
                  singularities=_read_csv(t.singularities),
                  chapters=[t.executed_notebook(nb) for nb in t.notebook_files()],
                  sources=t.notebook_files())
