r"""What a wheel kind says about design: its dead zone, and the changes that would make it isotropic or better actuated.

A base of :class:`~wmr.model.wheels.unit.WheelUnit`: the defaults (no dead zone, no advice, no other
build) are here; a kind with something to say overrides them (an offset wheel: its dead zone and
``d = r``; a Swedish wheel: omni rollers, the other hand).  The advice of ``wmr analyze`` applies
the changes to a copy of the robot and re-analyses it (:mod:`wmr.analysis.advice`).
"""

from __future__ import annotations

from typing import Self

__all__ = ["DesignHints"]


class DesignHints:
    """The design hints of a wheel unit (a base of every kind; see :class:`~wmr.model.wheels.unit.WheelUnit`)."""

    def dead_zone(self) -> float | None:
        """The radius of C's circle when every unit is steered with its drives locked, if this unit has one.

        The paper's dead zone of a robot on offset wheels (:func:`wmr.analysis.overview.dead_zone_radius`).

        Returns
        -------
        float or None
            None: steering the unit does not move the platform (or the unit is not steered).
        """
        return None

    def isotropy_advice(self) -> str | None:
        """What would make this unit's block isotropic (equal singular values), as a sentence about ``{wheels}``.

        Returns
        -------
        str or None
            A format string with the field ``{wheels}`` (the wheel numbers), or None when the
            block is isotropic already or no choice of this kind's parameters makes it so.
        """
        return None

    def isotropic_variant(self) -> Self | None:
        """The same unit changed as :meth:`isotropy_advice` says (its block isotropic), or None.

        The design advice of ``wmr analyze`` builds the changed robot from it and re-analyses it
        (:mod:`wmr.analysis.advice`) before printing the advice.

        Returns
        -------
        WheelUnit or None
        """
        return None

    def other_builds(self) -> tuple[tuple[str, Self], ...]:
        """Other ways to build this unit that change which motions its motors drive, as ``(words, unit)`` pairs.

        The design advice tries them when the motors of a robot cannot drive every motion it can
        make (:mod:`wmr.analysis.advice`): e.g. a mecanum wheel of the other hand.

        Returns
        -------
        tuple of (str, WheelUnit)
            Empty for the kinds without such a choice.
        """
        return ()
