"""Part I of the report: what was found.

The errata (equations judged *typo* or *wrong*: printed form, corrected form, one line of why, a
link to the derivation), the claims of the text that fail, the singular configurations the paper
misses, a summary by section, and the figures, each shown once with both captions. Everything
shown comes from ``figures/ledger.csv``, ``figures/singularities.csv`` and ``figures/<key>.json``.
"""
from __future__ import annotations

from collections import Counter, OrderedDict

from . import typeset as ts
from .frontmatter import listing, plural, verb, words
from .inputs import Entry, Inputs

__all__ = ["link", "formula", "claim_name", "errata", "failed_claims", "by_section", "singularities", "figures"]


def link(e: Entry, text: str | None = None) -> str:
    """``[(59)](#eq-59)``: a mention of a ledger row that links to its derivation."""
    text = text or e.label
    return f"[{text}](#{e.anchor})" if e.anchor else text


def claim_name(e: Entry) -> str:
    """A claim's slug as words: ``isotropy placement``."""
    return e.id.replace("-", " ")


def _section(e: Entry) -> str:
    return section_label(e.section)


def section_label(section: str) -> str:
    """``§5.3`` for a numbered section of the paper, the name for another part (``Abstract``)."""
    return f"§{section}" if section[:1].isdigit() else section


def formula(e: Entry, field: str) -> str:
    """``printed``/``corrected`` as Markdown: an equation's LaTeX body displayed, a claim's
    sentence (Markdown with ``$...$`` math) as it is."""
    body = getattr(e, field)
    return ts.display(body) if e.is_equation else body


def _verdict_table(entries: list[Entry], first: tuple[str, float], printed: str, corrected: str, cls: str):
    """One table for errata and failed claims: a row (name, section, verdict, why) and under it
    the printed and the true statement, each beside its label."""
    body = []
    for e in entries:
        name = link(e) if e.is_equation else link(e, claim_name(e))
        body.append({"cells": [f"**{name}**", _section(e), f"*{e.verdict}*", e.why or e.note], "end": False})
        body.append({"cells": [f"*{printed}*", formula(e, "printed")], "span": True, "end": False})
        body.append({"cells": [f"*{corrected}*", formula(e, "corrected")], "span": True, "end": True})
    rest = 1.0 - first[1] - 0.2
    return ts.table([first, ("Paper", 0.1), ("Verdict", 0.1), ("Why", rest)], body, cls=cls)


def errata(inp: Inputs) -> list:
    rows = inp.errata()
    head = ("# Errata\n\n"
            + (f"{plural(len(rows), 'equation').capitalize()} of the paper {verb(len(rows), 'does', 'do')} not hold as printed "
               f"({words(sum(e.verdict == 'typo' for e in rows))} *typo*, "
               f"{words(sum(e.verdict == 'wrong' for e in rows))} *wrong*). For each, the form printed in the "
               "paper, the form proven here, and why they differ; the equation number links to the "
               "derivation in Part II." if rows else "Every numbered equation of the paper holds as printed."))
    cells = [ts.markdown(head)]
    if rows:
        cells.append(_verdict_table(rows, ("Equation", 0.13), "printed", "corrected", "errata"))
    return cells


def failed_claims(inp: Inputs) -> list:
    rows = inp.failed_claims()
    head = ("# Claims that fail\n\n"
            + (f"Besides its equations, the paper states results in words. Of the {len(inp.claims())} such claims "
               f"this edition checks by computation, {words(len(rows))} {verb(len(rows), 'does', 'do')} not hold. "
               "For each: what the paper says, what is true, and the computation that shows it." if rows else
               "Every claim of the text that this edition checks holds."))
    cells = [ts.markdown(head)]
    if rows:
        cells.append(_verdict_table(rows, ("Claim", 0.2), "the paper", "what is true", "claims"))
    return cells


def by_section(inp: Inputs) -> list:
    """Verdicts per top-level section of the paper (computed)."""
    groups: OrderedDict[str, Counter] = OrderedDict()
    for e in inp.ledger or []:
        top = (e.section.split(",")[0].strip().split(".")[0]) or "?"
        groups.setdefault(top, Counter())[(e.kind, e.verdict)] += 1
    rows = []
    for sec, c in sorted(groups.items(), key=lambda kv: (not kv[0].isdigit(), kv[0].zfill(3))):
        rows.append([section_label(sec)] + [str(c[("equation", v)]) for v in ("ok", "typo", "wrong")]
                    + [str(c[("claim", "ok")]), str(c[("claim", "typo")] + c[("claim", "wrong")])])
    total = Counter()
    for c in groups.values():
        total.update(c)
    rows.append(["**all**"] + [f"**{total[('equation', v)]}**" for v in ("ok", "typo", "wrong")]
                + [f"**{total[('claim', 'ok')]}**", f"**{total[('claim', 'typo')] + total[('claim', 'wrong')]}**"])
    return [ts.markdown("# Verdicts by section of the paper\n\nEquations and checked claims, counted by the "
                        "section of the paper that states them (a claim that spans two sections is counted "
                        "under the first)."),
            ts.table([("Paper", 0.2), ("Equations ok", 0.16), ("typo", 0.16), ("wrong", 0.16),
                      ("Claims ok", 0.16), ("fail", 0.16)], rows, cls="numbers")]


_SING_COLUMNS = (("family", "Family", 0.2), ("configuration", "Configuration", 0.25),
                 ("geometric_meaning", "Meaning", 0.2), ("listed_in_paper", "In the paper", 0.1),
                 ("note", "Note", 0.25))


def singularities(inp: Inputs) -> list:
    sing = inp.singularities
    if sing is None:
        return [ts.markdown("# Singular configurations the paper misses\n\n*`figures/singularities.csv` is missing.*")]
    missed = inp.missed_singularities()
    listed = Counter((r.get("listed_in_paper") or "").strip().lower() for r in sing)
    cols = [(k, h, w) for k, h, w in _SING_COLUMNS if sing and k in sing[0]]
    head = ("# Singular configurations the paper misses\n\n"
            "Paper §5.3 lists the configurations in which the three centred wheels of its robot make "
            "$\\det\\mathbf J = 0$. Chapter 4 computes the whole zero set and sorts it into "
            f"{plural(len(sing), 'family', 'families')}: the paper states {words(listed['yes'])} of them"
            + (f", {words(listed['partly'])} in part" if listed["partly"] else "")
            + f" and misses {words(listed['no'])}. The families it does not state in full:")
    rows = [[r.get(k, "") for k, _, _ in cols] for r in missed]
    return [ts.markdown(head), ts.table([(h, w) for _, h, w in cols], rows, cls="singular")]


def figures(inp: Inputs) -> list:
    shown = [f for f in inp.figures if f.key != "conventions"]
    nums = [f.number for f in shown if f.number]
    cells = [ts.markdown("# Figures\n\n"
                         + (f"Figures {nums[0]}–{nums[-1]} of the paper, recomputed from the model, " if nums else "")
                         + "each with the paper's caption beside the caption computed here; the numbers in "
                         "the computed captions come from the same run that drew the figure.")]
    for f in shown:
        cells.append(ts.figure(f.key, f.label, f.title, f.paper_caption, f.caption, f.images))
    return cells


def listing_links(entries: list[Entry]) -> str:
    return listing([link(e) for e in entries])
