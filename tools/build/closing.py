"""The end of Part I: conclusions (computed from the ledger) and references."""
from __future__ import annotations

import re

from . import typeset as ts
from .findings import claim_name, formula, link
from .frontmatter import PAPER, listing, plural, verb, words
from .inputs import Inputs

__all__ = ["conclusions", "references", "REFERENCES", "PAPER_CITATIONS"]

#: works this edition cites, in full
REFERENCES = (
    PAPER,
    "G. Campion, G. Bastin and B. d'Andrea-Novel, “Structural properties and classification of kinematic "
    "and dynamic models of wheeled mobile robots”, *IEEE Transactions on Robotics and Automation* 12(1), "
    "47–62, 1996.",
    "P. F. Muir and C. P. Neuman, “Kinematic modeling of wheeled mobile robots”, *Journal of Robotic "
    "Systems* 4(2), 281–340, 1987.",
)

#: the paper's numbered citations, by what the paper cites them for (from its text)
PAPER_CITATIONS = (
    ("[1]", "§1, §3.2", "forms of locomotion; wheel types (with [2]); decomposition of a WMR into subsystems (with [11]); wheel Jacobians combined into the robot's equation of motion (with [2])"),
    ("[2]", "§1", "wheel types; wheel Jacobians (with [1])"),
    ("[3]", "§1, §3.2", "the dual-wheel"),
    ("[4]–[6]", "§1", "the dual-wheel caster drive, the orthogonal wheel, the double-wheel drive"),
    ("[7]–[10]", "§1", "overviews and classifications of WMRs"),
    ("[11]", "§1, §4.2", "decomposition into subsystems; full mobility needs at least one motorized steering axis"),
    ("[12]", "§1, §4.2", "modular modelling of constrained multibody systems with Lagrange's equations (the holonomy matrix); mobility as the number of freely assignable generalized velocities"),
    ("[13]", "§2", "robustness: least sensitivity to parameters the designer does not control"),
    ("[14]", "§2", "non-cylindrical robots are more easily trapped"),
    ("[15]", "§3.1, §3.2, §6", "the operation point $C$"),
    ("[16]", "§3.1", "the velocity of a point of the platform"),
    ("[17]", "§4.2", "the name *functional matrix*"),
    ("[18]", "§4.2", "the nullity of a matrix"),
    ("[19]", "§4.2", "non-holonomic systems (with [12])"),
    ("[20]", "§4.3", "the condition number as round-off amplification"),
    ("[21]", "§4.3", "the characteristic length"),
    ("[22]", "§4.3, §7", "singular configurations of WMRs with offset wheels; mobile manipulators"),
    ("[23], [24]", "§5.2", "rank $\\mathbf F = 5$ in translation"),
    ("[25]", "§5.3", "Maple, used for $\\det\\mathbf J$"),
    ("[26]", "§7", "the authors' robot (the paper's Fig. 14)"),
    ("[27]", "§7", "mobile manipulators (with [22])"),
)


def conclusions(inp: Inputs) -> list:
    """What holds, what does not, what it means for a designer: counts and lists from the ledger."""
    if inp.ledger is None:
        return [ts.markdown("# Conclusions\n\n*The ledger (`figures/ledger.csv`) is missing.*")]
    eqs = inp.equations()
    v = inp.verdicts("equation")
    typo_eq = [e for e in eqs if e.verdict == "typo"]
    wrong_eq = [e for e in eqs if e.verdict == "wrong"]
    claims, failed = inp.claims(), inp.failed_claims()
    held = [e for e in claims if e.verdict == "ok"]
    s = ["# Conclusions", "",
         f"**What holds.** {v['ok']} of the paper's {len(eqs)} numbered equations hold as printed, and "
         f"{words(len(typo_eq))} more hold once a slip of notation is corrected"
         + (f" ({listing([link(e) for e in typo_eq])})" if typo_eq else "") + ". "
         "The kinematic model the paper builds (platform and wheel units, the assembly of the Jacobians "
         "and of the functional matrix $\\mathbf F$) can be used as printed, under the conventions stated "
         "in *How to read this edition*."
         + (f" Of the claims of its text, {words(len(held))} {verb(len(held), 'holds', 'hold')}"
            f" ({listing([link(e, claim_name(e)) for e in held])})." if held else ""),
         ""]
    if wrong_eq or failed:
        s.append("**What does not hold.** "
                 + (f"{plural(len(wrong_eq), 'equation').capitalize()} {verb(len(wrong_eq), 'is', 'are')} wrong "
                    f"({listing([link(e) for e in wrong_eq])}); the [errata](#errata) give the corrected forms and why. "
                    if wrong_eq else "")
                 + (f"{plural(len(failed), 'claim').capitalize()} of the text {verb(len(failed), 'fails', 'fail')}: "
                    + listing([link(e, claim_name(e)) for e in failed]) + "." if failed else ""))
        s.append("")
    if failed:
        s += ["**For a designer.** In place of each claim that fails, what is true, as proven in Part II:", ""]
        for e in failed:
            s.append(f"- **{link(e, claim_name(e))}** (paper §{e.section}). " + formula(e, "corrected"))
        s.append("")
    s += ["Every verdict can be checked again: `make report` re-executes the derivations, and the package "
          "`wmr` analyses any other wheel layout the same way (mobility, isotropy, singular configurations, "
          "steering)."]
    return [ts.markdown("\n".join(s))]


def references() -> list:
    s = ["# References", ""]
    s += [f"{i}. {r}" for i, r in enumerate(REFERENCES, 1)]
    n = max(int(x) for ref, _, _ in PAPER_CITATIONS for x in re.findall(r"\d+", ref))
    s += ["", f"The paper cites {n} works by number; the text this edition was made from does not include its "
          "reference list. What the paper cites each for:", ""]
    cells = [ts.markdown("\n".join(s)),
             ts.table([("Paper's ref.", 0.16), ("Where", 0.14), ("Cited for", 0.7)],
                      [list(r) for r in PAPER_CITATIONS], cls="citations")]
    return cells
