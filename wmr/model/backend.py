"""Two backends, one model: NumPy (batched numbers) and SymPy (exact symbols).

Every matrix of the paper is built exactly once, by a builder that receives a backend
object and uses only the handful of operations below.  Passing :data:`NUMERIC` gives
batched NumPy arrays whose last two axes are the matrix axes; passing :data:`SYMBOLIC`
gives a :class:`sympy.Matrix`.  Neither form is written by hand anywhere else, so the
derivation notebooks and the numeric kernels cannot drift apart.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TypeAlias

import numpy as np

from ..errors import InputTypeError
from .lazysympy import is_sympy, sp
from .types import ArrayLike, FloatArray, Symbolic

__all__ = ["NumericBackend", "SymbolicBackend", "Backend", "NUMERIC", "SYMBOLIC"]


class NumericBackend:
    """NumPy backend: entries are floats or arrays with leading batch axes."""

    name = "numpy"

    @staticmethod
    def cos(x: ArrayLike) -> FloatArray:
        return np.cos(x)

    @staticmethod
    def sin(x: ArrayLike) -> FloatArray:
        return np.sin(x)

    @staticmethod
    def matrix(rows: Sequence[Sequence[ArrayLike]]) -> FloatArray:
        """Build a ``(..., m, n)`` array from nested rows of broadcastable entries."""
        flat = np.broadcast_arrays(*[np.asarray(e, dtype=float) for row in rows for e in row])
        m, n = len(rows), len(rows[0])
        return np.stack(flat, axis=-1).reshape(flat[0].shape + (m, n))

    @staticmethod
    def zeros(m: int, n: int, batch: tuple[int, ...] = ()) -> FloatArray:
        return np.zeros(tuple(batch) + (m, n))

    @staticmethod
    def set_block(M: FloatArray, i: int, j: int, B: ArrayLike) -> FloatArray:
        B = np.asarray(B, dtype=float)
        M[..., i : i + B.shape[-2], j : j + B.shape[-1]] = B
        return M

    @staticmethod
    def broadcast_hstack(*Ms: ArrayLike) -> FloatArray:
        """Concatenate along columns after broadcasting the batch axes (not the matrix axes)."""
        arrays = [np.asarray(M, dtype=float) for M in Ms]
        batch = np.broadcast_shapes(*[M.shape[:-2] for M in arrays])
        return np.concatenate([np.broadcast_to(M, batch + M.shape[-2:]) for M in arrays], axis=-1)

    hstack = broadcast_hstack

    @staticmethod
    def transpose(M: FloatArray) -> FloatArray:
        return np.swapaxes(M, -1, -2)

    @staticmethod
    def eye(n: int) -> FloatArray:
        return np.eye(n)


class SymbolicBackend:
    """SymPy backend: entries are SymPy expressions, results are ``sympy.Matrix``."""

    name = "sympy"

    @staticmethod
    def cos(x: Symbolic) -> Symbolic:
        return sp.cos(x)

    @staticmethod
    def sin(x: Symbolic) -> Symbolic:
        return sp.sin(x)

    @staticmethod
    def matrix(rows: Sequence[Sequence[Symbolic]]) -> Symbolic:
        return sp.Matrix(rows)

    @staticmethod
    def zeros(m: int, n: int, batch: tuple[int, ...] = ()) -> Symbolic:
        return sp.zeros(m, n)

    @staticmethod
    def set_block(M: Symbolic, i: int, j: int, B: Symbolic) -> Symbolic:
        B = sp.Matrix(B)
        M[i : i + B.rows, j : j + B.cols] = B
        return M

    @staticmethod
    def broadcast_hstack(*Ms: Symbolic) -> Symbolic:
        return sp.Matrix.hstack(*[sp.Matrix(M) for M in Ms])

    hstack = broadcast_hstack

    @staticmethod
    def transpose(M: Symbolic) -> Symbolic:
        return M.T

    @staticmethod
    def eye(n: int) -> Symbolic:
        return sp.eye(n)


#: either backend (the type of a ``backend`` argument)
Backend: TypeAlias = NumericBackend | SymbolicBackend
#: the NumPy backend: batched floating-point arrays
NUMERIC = NumericBackend()
#: the SymPy backend: exact matrices of symbols and rationals
SYMBOLIC = SymbolicBackend()


def is_symbolic(*values: object) -> bool:
    """True when any value, or any entry of a sequence or object array of values, is SymPy."""
    for v in values:
        if is_sympy(v, "Basic", "MatrixBase"):
            return True
        if isinstance(v, (list, tuple)) and is_symbolic(*v):
            return True
        if isinstance(v, np.ndarray) and v.dtype == object and is_symbolic(*v.ravel()):
            return True
    return False


def choose(*values: object, backend: Backend | None = None) -> Backend:
    """The backend given (checked), else SymPy if any of the builder's inputs is symbolic, else NumPy."""
    if backend is not None:
        if backend not in (NUMERIC, SYMBOLIC):
            raise InputTypeError(f"backend must be wmr.model.backend.NUMERIC or SYMBOLIC, got {backend!r}")
        return backend
    return SYMBOLIC if is_symbolic(*values) else NUMERIC
