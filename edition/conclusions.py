r"""Sections 6-7 as printed: claims about dual wheels, omnidirectionality and discontinuous heading.

Section 6 has no numbered equations; these are the kinematic claims of Sections 3.2, 5.2, 5.4.3, 6,
7 and the abstract that the edition checks (see ``notebooks/06_dual_wheels_and_conclusions``).
Nothing here is derived.
"""
from __future__ import annotations

from . import register_claim

register_claim(
    "dual-wheel-equivalence", "3.2, 6",
    r"This is possible with the introduction of the average velocities $\dot{\mathbf h}_i$ and $\dot\theta_i$ "
    r"[(17), (18)] [...] the dual-wheel is kinematically equivalent to the centered wheel.")

register_claim(
    "mobility-dual", "7",
    r"WMRs with three offset wheels have a mobility [$\nu(\mathbf F)$] of 3, while WMRs with three centered wheels "
    r"or three dual-wheels have a mobility of 1.")

register_claim(
    "omnidirectional", "5.2, 5.4.3",
    r"The steering rates $\dot\phi_i$ are decoupled from the driving rates $\dot\theta_i$, such that the wheels are "
    r"capable of continuously varying their orientation through $360^\circ$; as such, this WMR [three centred "
    r"wheels] is omni-directional.")

register_claim(
    "discontinuous-heading", "Abstract, 7",
    r"WMRs with mobility [$\nu(\mathbf F)$] less than 3 cannot track a trajectory with a discontinuous heading "
    r"without incorporating a time delay, during which the wheel orientation should be changed.")
