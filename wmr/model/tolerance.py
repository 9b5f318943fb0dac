"""The one numerical tolerance of the package.

Every "is this zero?" decision in :mod:`wmr` (rank, nullity, isotropy, admissibility of a
motion, whether a twist is a pure translation) goes through :data:`TOL`, so that the
package has a single documented notion of numerical zero.

* A singular value ``s`` of a matrix ``A`` counts as zero when
  ``s <= TOL * max(1, s_max)``: relative to the largest singular value for matrices of
  ordinary size, absolute for tiny ones (so that the zero matrix has rank 0).
* A residual (slip) of a kinematic equation counts as zero when it is at most
  ``TOL * max(1, scale)``, where ``scale`` is the size of the terms that produced it.

``TOL = 1e-9`` sits well above the round-off of the 6x9 matrices built here (about
``1e-15`` relative) and far below any physically meaningful quantity.
"""
from __future__ import annotations

import numpy as np

__all__ = ["TOL", "near_zero"]

#: The package-wide tolerance for numerical zero (see module docstring).
TOL: float = 1e-9


def near_zero(x, scale=1.0):
    """True where ``|x| <= TOL * max(1, |scale|)`` (element-wise).

    Parameters
    ----------
    x : array_like
        Values to test.
    scale : array_like, optional
        Size of the quantities whose difference ``x`` is; broadcast against ``x``.

    Returns
    -------
    numpy.ndarray of bool
        Same shape as ``np.broadcast(x, scale)``.

    Examples
    --------
    >>> bool(near_zero(1e-12))
    True
    >>> bool(near_zero(1e-3))
    False
    """
    x = np.abs(np.asarray(x, dtype=float))
    return x <= TOL * np.maximum(1.0, np.abs(np.asarray(scale, dtype=float)))
