r"""Singular configurations in words: what each family of :func:`wmr.analysis.families.singular_families` is, and
what it means to a driver.

Examples
--------
>>> description("v-C"), description("pair-12")
('wheel planes concurrent at C', 'the planes of wheels 1 and 2 on the line P1P2')
>>> meaning("pair-13'").startswith("two wheels pull along the line joining them")
True
"""

from __future__ import annotations

__all__ = ["FAMILIES", "MEANINGS", "description", "meaning"]

#: plain words for the families of :func:`wmr.analysis.singularities.classify` and of the other robots'
FAMILIES = {
    "i": "all wheel planes parallel, equal angles",
    "i'": "all wheel planes parallel, a wheel turned by 180 deg",
    "pair": "the planes of two wheels on the line through their mount points",
    "v-C": "wheel planes concurrent at C",
    "v-P": "wheel planes concurrent at a mount point",
    "v-circle": "wheel planes concurrent and axles concurrent (rotation about a point of the circle through the P_i)",
    "v": "wheel planes concurrent at another point",
    "parallel": "all wheel planes parallel",
    "through-C": "wheel planes concurrent at C",
    "through-P": "wheel planes concurrent at a mount point",
    "through-point": "wheel planes concurrent at another point",
    "other": "rank J < 3",
}


_PARALLEL = (
    "the wheels all point the same way: it drives along them, but to turn or move any other way it must "
    "steer first (a car driving straight ahead is here; without steering it cannot leave without skidding)"
)
_CENTRE = (
    "the axles meet at one point and the robot turns about it: to move its turning centre (or to drive "
    "straight) it must re-steer first"
)
#: what each family means to a driver (keys as in :data:`FAMILIES`)
MEANINGS = {
    "i": _PARALLEL,
    "i'": _PARALLEL,
    "parallel": _PARALLEL,
    "pair": "two wheels pull along the line joining them: the rates cannot turn the robot about a point of that line "
    "without re-steering",
    "v-C": _CENTRE,
    "through-C": _CENTRE,
    "v": _CENTRE,
    "through-point": _CENTRE,
    "v-circle": _CENTRE,
    "v-P": _CENTRE + "; the wheel at that mount point stands still",
    "through-P": _CENTRE + "; the wheel at that mount point stands still",
    "other": "the wheel rates cannot make every change of motion here: some need the wheels re-steered first",
}


def description(family: str) -> str:
    """The family's geometry in plain words.

    Parameters
    ----------
    family : str
        A family's short name (:func:`wmr.analysis.families.singular_families`).

    Returns
    -------
    str
    """
    if family.startswith("pair-"):
        i, j = family[5], family[6]
        turned = ", one turned by 180 deg" if family.endswith("'") else ""
        return f"the planes of wheels {i} and {j} on the line P{i}P{j}{turned}"
    return FAMILIES.get(family, family)


def meaning(family: str) -> str:
    """What the family means to a driver.

    Parameters
    ----------
    family : str
        A family's short name (:func:`wmr.analysis.families.singular_families`).

    Returns
    -------
    str
    """
    return MEANINGS[family.split("-")[0] if family.startswith("pair-") else family]
