"""Run a batched NumPy kernel over chunks of the leading axes on all cores.

NumPy's batched ``linalg`` routines release the GIL, so threads give real parallelism.
"""
from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor

import numpy as np

_CHUNK = 65536


def map_matrices(fn, A, out_tail=None, chunk=_CHUNK):
    """Apply ``fn`` to a stack of matrices ``A (..., m, n)`` in chunks; results keep the batch shape.

    Parameters
    ----------
    fn : callable
        Maps a stack ``(k, m, n)`` to an array whose first axis has length ``k``.
    A : numpy.ndarray (..., m, n)
    out_tail : ignored
        Kept for compatibility.
    chunk : int, optional
        Matrices per chunk (each chunk is one task for the thread pool).

    Returns
    -------
    numpy.ndarray (..., *tail)
        ``fn``'s results, concatenated and reshaped to the batch shape of ``A``.
    """
    batch = A.shape[:-2]
    flat = A.reshape((-1,) + A.shape[-2:])
    if flat.shape[0] <= chunk:
        res = fn(flat)
    else:
        parts = [flat[i:i + chunk] for i in range(0, flat.shape[0], chunk)]
        with ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as ex:
            res = np.concatenate(list(ex.map(fn, parts)), axis=0)
    return res.reshape(batch + res.shape[1:])
