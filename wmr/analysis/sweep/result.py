r"""The result of a sweep (:class:`Sweep`), assembled from the final reduction."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .analyses import ANALYSES

__all__ = ["Sweep"]


@dataclass(frozen=True)
class Sweep:
    r"""The result of :func:`sweep`.

    Attributes
    ----------
    analysis : str
        The analysis' name (a key of :data:`ANALYSES`).
    count : int
        Configurations evaluated.
    min : float
        Smallest value (exact).
    max : float
        Largest value (exact).
    argmin : numpy.ndarray (w,)
        The first configuration, in the sweep's numbering, where the minimum is attained.
    argmax : numpy.ndarray (w,)
        The first configuration where the maximum is attained.
    worst : float
        The value at the end closest to a singularity (see the module notes): the minimum of
        rank F, the maximum of the mobility and of condition numbers, the smallest
        :math:`|\det\mathbf J|`.
    worst_angles : numpy.ndarray (w,)
        The first configuration where ``worst`` is attained.
    worst_index : int
        Its number in the sweep.
    quantiles : dict of float -> float
        The order statistic of rank :math:`\lfloor q(\text{count}-1)\rfloor` for each requested
        ``q``: exact for the integer analyses (rank F, mobility) and for ``q`` = 0 or 1, within a
        relative error of :data:`SKETCH_ACCURACY` for the real-valued ones (a logarithmic
        bucket sketch that needs no sorted copy of the values).
    counts : dict of int -> int
        Integer analyses: how many configurations take each value; empty otherwise.
    infinite : int
        Configurations where the value is ``inf`` (a singular matrix's condition number).
    values : numpy.ndarray (count,) or None
        Every value, in the sweep's numbering, when ``keep=True``.
    covers : str
        Which configurations the reduction covers, in words: the drivable ones
        (:class:`~wmr.analysis.sweep.Drivable`) or all steering angles (a grid or a sample).
    complete : bool
        False when the sweep was interrupted: the reduction covers the configurations evaluated
        so far (``count``) only.
    """

    analysis: str
    count: int
    min: float
    max: float
    argmin: np.ndarray
    argmax: np.ndarray
    worst: float
    worst_angles: np.ndarray
    worst_index: int
    quantiles: dict
    counts: dict
    infinite: int
    values: np.ndarray | None = None
    covers: str = ""
    complete: bool = True

    def summary(self, convention: str = "wmr") -> str:
        """A few lines of text that state the result (used by ``wmr sweep``).

        Parameters
        ----------
        convention : str, optional
            How the worst configuration's angles are written (:data:`wmr.model.conventions.CONVENTIONS`).

        Returns
        -------
        str
        """
        from ...model.conventions import angle_to

        an = ANALYSES[self.analysis]
        deg = np.degrees(angle_to(self.worst_angles, convention))
        head = f"{an.title} over {self.count:,} configurations" + ("" if self.complete else " (INTERRUPTED: partial)")
        lines = [
            head + (f": {self.covers}" if self.covers else ""),
            f"  min {self.min:.6g}   max {self.max:.6g}",
            "  quantiles  " + "   ".join(f"{q:g}: {v:.6g}" for q, v in self.quantiles.items()),
        ]
        if self.counts:
            lines.append("  counts     " + "   ".join(f"{k}: {n:,}" for k, n in self.counts.items()))
        if self.infinite:
            lines.append(f"  singular (inf) at {self.infinite:,} configurations")
        end = {"min": "the minimum", "max": "the maximum", "min_abs": "the smallest magnitude"}[an.worst]
        what = "axle angles" if convention == "wmr" else f"{convention} angles"
        lines.append(
            f"  worst {self.worst:.6g} ({end}) at configuration {self.worst_index}: {what} ("
            + ", ".join(f"{a:.4f}" for a in deg)
            + ") deg"
        )
        return "\n".join(lines)
