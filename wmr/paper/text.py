r"""How the edition prints numbers: angles in degrees, round-off residuals as bounds.

Every number that reaches a caption, a CSV or the report goes through these helpers, so the
artefacts are the same on every machine: a result that is zero up to round-off is printed as a
bound at the stated resolution (:data:`RESOLUTION`), never with its round-off digits.
"""
from __future__ import annotations

import numpy as np

__all__ = ["RESOLUTION", "degrees", "bound"]

#: Residuals below this are printed as ``< 1e-12``: round-off of the 6x9 matrices built here is
#: about 1e-15, so the bound holds on any IEEE-754 machine while the printed text does not change.
RESOLUTION = 1e-12


def degrees(angle):
    r"""An angle given in radians, printed in degrees: an integer when it is one (to 1e-6 deg), else 6 digits.

    Parameters
    ----------
    angle : float
        Radians.

    Returns
    -------
    str

    Examples
    --------
    >>> degrees(np.pi / 3), degrees(np.radians(12.5)), degrees(-np.pi)
    ('60', '12.5', '-180')
    """
    v = round(float(np.degrees(angle)), 6) + 0.0
    if abs(v - round(v)) <= 1e-6:
        return str(int(round(v)))
    return f"{v:.6g}"


def bound(value, resolution=RESOLUTION, latex=False):
    r"""A non-negative residual printed as ``0``, as a bound ``< 1e-12`` when it is round-off, or with 2 digits.

    Parameters
    ----------
    value : float
        A residual, :math:`\ge 0`.
    resolution : float, optional
        Values below it are round-off and printed as ``< resolution``.
    latex : bool, optional
        Print ``< 10^{-12}`` in LaTeX (for ``$...$``) instead of ``< 1e-12``.

    Returns
    -------
    str

    Examples
    --------
    >>> bound(0.0), bound(4.2e-16), bound(3.14159e-3)
    ('0', '< 1e-12', '3.1e-03')
    >>> bound(4.2e-16, latex=True)
    '< 10^{-12}'
    """
    v = float(value)
    if not np.isfinite(v) or v < 0:
        raise ValueError(f"value must be a finite residual >= 0, got {value!r}")
    if v == 0:
        return "0"
    if v < resolution:
        k = int(round(np.log10(resolution)))
        return f"< 10^{{{k}}}" if latex else f"< 1e{k}"
    return f"{v:.1e}"
