"""Run a batched NumPy kernel over chunks of the leading axes on all cores.

NumPy's batched ``linalg`` routines release the GIL, so threads give real parallelism.
"""
from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor

import numpy as np

_CHUNK = 65536


def map_matrices(fn, A, out_tail=None):
    """Apply ``fn`` to a stack of matrices ``A (..., m, n)`` in chunks; results keep the batch shape."""
    batch = A.shape[:-2]
    flat = A.reshape((-1,) + A.shape[-2:])
    if flat.shape[0] <= _CHUNK:
        res = fn(flat)
    else:
        parts = [flat[i:i + _CHUNK] for i in range(0, flat.shape[0], _CHUNK)]
        with ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as ex:
            res = np.concatenate(list(ex.map(fn, parts)), axis=0)
    return res.reshape(batch + res.shape[1:])
