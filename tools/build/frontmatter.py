"""Front matter of the report: title block, abstract, how to read this edition, conventions.

Every count in the text is computed from the ledger, the singularity list and the figures
(:class:`~tools.build.inputs.Inputs`); nothing here types a number that the data could give.
"""
from __future__ import annotations

import datetime as _dt

from . import typeset as ts
from .inputs import Inputs

__all__ = ["TITLE", "SUBTITLE", "PAPER", "title_metadata", "abstract", "how_to_read", "words", "verb", "plural", "listing"]

TITLE = "Kinematic modeling, mobility analysis and design of wheeled mobile robots"
SUBTITLE = "An executable edition of Leow, Low & Loh (2002)"
#: the paper's full reference, as the report cites it
PAPER = ("Y. P. Leow, K. H. Low and W. K. Loh, “Kinematic modeling, mobility analysis and design of "
         "wheeled mobile robots”, *Advanced Robotics* 16(2), 2002.")

_WORDS = ("no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve")


def words(n: int) -> str:
    """A count in words up to twelve (as prose writes it), in digits above."""
    return _WORDS[n] if 0 <= n < len(_WORDS) else str(n)


def listing(items: list[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``."""
    items = list(items)
    return "" if not items else items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def verb(n: int, one: str, many: str) -> str:
    """The verb that agrees with a count: ``verb(1, "is", "are")``."""
    return one if n == 1 else many


def plural(n: int, one: str, many: str | None = None) -> str:
    return f"{words(n)} {one if n == 1 else (many or one + 's')}"


def title_metadata(commit: str, epoch: int) -> dict:
    """What the title block shows: the build date is the commit's date (``SOURCE_DATE_EPOCH``)."""
    date = _dt.datetime.fromtimestamp(epoch, _dt.timezone.utc).strftime("%Y-%m-%d") if epoch else "unknown"
    return {"title": TITLE, "subtitle": SUBTITLE, "paper": PAPER, "commit": commit, "date": date}


def abstract(inp: Inputs) -> str:
    eqs, claims = inp.equations(), inp.claims()
    v, vc = inp.verdicts("equation"), inp.verdicts("claim")
    lo, hi = inp.equation_range()
    figs = [f.number for f in inp.figures if f.number]
    ours = [f for f in inp.figures if not f.number]
    s = ["# Abstract", "",
         "Leow, Low and Loh (2002) model a wheeled mobile robot as a platform carried by wheel units "
         "(offset, centred or dual wheels), judge its mobility by the rank of the functional matrix "
         "$\\mathbf F$, and look for wheel placements that make the robot kinetostatically isotropic. "
         "This edition re-derives the paper from the no-slip condition of a rolling wheel, with the "
         "package `wmr`, and compares every result with the printed one: exactly, with SymPy, and "
         "numerically, at random configurations drawn with fixed seeds."]
    if inp.ledger is not None:
        s += ["",
              f"Of the paper's {len(eqs)} numbered equations, ({lo})–({hi}), "
              f"{v['ok']} {verb(v['ok'], 'holds', 'hold')} as printed, {words(v['typo'])} "
              f"{verb(v['typo'], 'carries', 'carry')} a typo and {words(v['wrong'])} {verb(v['wrong'], 'is', 'are')} wrong "
              f"(the [errata](#errata) give the corrected forms). "
              f"Of the {plural(len(claims), 'claim')} of its text that this edition checks by computation, "
              f"{words(vc['ok'])} {verb(vc['ok'], 'holds', 'hold')} and {words(len(claims) - vc['ok'])} "
              f"{verb(len(claims) - vc['ok'], 'does', 'do')} not "
              "([claims that fail](#claims-that-fail))."]
    if inp.singularities is not None:
        fams = inp.singularities
        missed = inp.missed_singularities()
        s += ["",
              f"A computation of the zero set of $\\det\\mathbf J$ for the robot with three centred wheels finds "
              f"{plural(len(fams), 'family', 'families')} of singular configurations; "
              f"the paper's list does not state {words(len(missed))} of them in full "
              "([singular configurations](#singular-configurations-the-paper-misses))."]
    if figs:
        s += ["", f"Figures {figs[0]}–{figs[-1]} of the paper are recomputed from the model"
              + (f", with {plural(len(ours), 'figure')} of this edition's own" if ours else "")
              + "; each is shown once, with the paper's caption beside the computed one."]
    return "\n".join(s)


def how_to_read(inp: Inputs) -> list:
    cells = [ts.markdown(
        "# How to read this edition\n\n"
        "**Part I** states what was found; **Part II** holds the derivations, one chapter per group of "
        "sections of the paper, each executed as a Jupyter notebook when this report was built. "
        "Numbers in parentheses, such as (59), are the paper's equation numbers and link to their "
        "derivation; *paper §5.3* is a section of the paper, *Chapter 4* a chapter of this edition; "
        "figure numbers 7–13 are the paper's.\n\n"
        "**Verdicts.** Each equation and each checked claim receives one verdict, computed from the "
        "comparison of the printed form with the derived one:\n\n"
        "- *ok*: the printed form holds; it equals the derivation.\n"
        "- *typo*: the printed form does not hold as printed, and a slip of notation (a sign, a "
        "factor, a symbol, a stated dimension) separates it from the derivation; the corrected form "
        "holds.\n"
        "- *wrong*: the printed statement is false in substance; the edition states what is true and "
        "the computation that shows it.\n\n"
        "**Checks.** Each ledger row records *check*, what was proven, in words (for a *wrong* row: "
        "that the printed form was refuted, with a counterexample, and the corrected form proven); "
        "*printed holds*, whether the printed form itself holds (*yes* or *no*); *residual*, the "
        "largest numerical residual of the form accepted, over random configurations, printed as a "
        "bound where it is round-off (for example $< 10^{-12}$); and *convention*, the reading of the "
        "paper's notation under which the verdict holds, where the paper leaves it open.")]
    conv = inp.figure("conventions")           # chapters.FRONT_MATTER_FIGURES: shown here
    if conv is not None:
        cells.append(ts.markdown(
            "**Conventions.** Frames, angle signs and wheel numbering are stated once, in the package "
            "(`wmr.model.conventions`), and drawn here; every chapter uses them."))
        cells.append(ts.figure(conv.key, conv.label, conv.title, conv.paper_caption, conv.caption, conv.images))
    return cells
