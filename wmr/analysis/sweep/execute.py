r"""Chunked execution of a sweep: :func:`sweep`, in this process or on a Dask cluster.

The configurations ``0 .. N-1`` are cut into chunks of ``chunk`` consecutive numbers; each chunk
is generated, evaluated with the batched kernels and reduced (:func:`_evaluate`, which is what a
Dask worker runs), and the partial reductions are merged as they arrive.
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Callable, Sequence
from typing import Any, TypeAlias

import numpy as np

from ...errors import InputTypeError, InputValueError
from ...model import validation
from ...model.limits import check, limit
from ...model.robot import Robot
from ...model.types import ArrayLike
from .analyses import ANALYSES, J_length
from .configurations import BLOCK, Grid, Sample, as_source, count
from .motions import Drivable, Motions
from .reduction import Partial
from .result import Sweep, finish

__all__ = ["Angles", "sweep", "QUANTILES", "CHUNK"]

#: what a sweep runs over: a :class:`~wmr.analysis.sweep.configurations.Grid`, a
#: :class:`~wmr.analysis.sweep.configurations.Sample`, the configurations a robot can drive in
#: (:class:`~wmr.analysis.sweep.motions.Drivable`), or explicit configurations (N, w)
Angles: TypeAlias = Grid | Sample | Drivable | ArrayLike

#: Quantiles reported by default.
QUANTILES = (0.0, 0.01, 0.05, 0.5, 0.95, 0.99, 1.0)
#: Configurations per chunk (a multiple of the random-sample block).
CHUNK = 1 << 18
#: The default chunk of a sweep with a fused kernel (kappa_J of a swerve over Drivable configurations):
#: its working memory is per block of twists, not per chunk, and fewer chunks wait less for each other
FUSED_CHUNK = 1 << 20


def _evaluate(task, start, stop, threads):
    """Evaluate the analysis of ``task`` on configurations ``start .. stop-1``: a :class:`Partial`.

    ``task`` is ``(robot, analysis name, source, w, L, keep)``.

    Runs in this process or on a Dask worker; ``threads`` limits the kernels' threads.
    """
    from .._batch import limit_threads

    robot, name, source, w, L, keep = task
    an = ANALYSES[name]

    def reduced(first, x):
        part = Partial()
        part.add(first, x.astype(np.int64) if an.integer else x.astype(float), an.integer, keep)
        return part

    with limit_threads(threads):
        if an.drivable is not None and isinstance(source, Motions):  # a fused kernel from the twists,
            parts: dict[int, Partial] = {}  # reduced block by block on any core

            def fold(first, x):
                parts[first] = reduced(first, x)

            if an.drivable(source, start, stop, L, fold):
                whole = Partial()
                for first in sorted(parts):
                    whole.merge(parts[first])
                return whole
        x = np.asarray(an.evaluate(robot, source.configurations(w, start, stop), L))
    return reduced(start, x)


def sweep(
    robot: Robot,
    analysis: str,
    angles: Angles,
    *,
    L: float | None = None,
    quantiles: Sequence[float] = QUANTILES,
    keep: bool = False,
    chunk: int = CHUNK,
    progress: Callable[[int, int], object] | None = None,
    client: Any = None,
    interruptible: bool = False,
) -> Sweep:
    r"""Evaluate an analysis over a grid or sample of configurations, chunk by chunk.

    Each chunk of configurations :math:`\boldsymbol\beta_k\in\mathbb R^w` is evaluated with the
    batched kernels and folded into the reduction; peak memory is that of one chunk plus the
    reduction, about ``chunk * (w + 20) * 8`` bytes plus a few MB (unless ``keep``).

    Parameters
    ----------
    robot : Robot
        A numeric robot.
    analysis : str
        A key of :data:`ANALYSES`: ``"rank_F"``, ``"mobility"``, ``"det_J"`` (square
        :math:`\mathbf J` only, i.e. ``robot.n_rates == 3``), ``"kappa_J"`` or ``"kappa_JL1"``.
    angles : Drivable, Grid, Sample or array_like (N, w)
        The configurations: those the robot can drive in (:class:`Drivable`: the steering angles of
        sampled twists), a :class:`Grid` or a :class:`Sample` of all steering angles, or explicit ones.
    L : float, optional
        Characteristic length of :math:`\mathbf J_{L1}` for ``det_J``, ``kappa_J`` and
        ``kappa_JL1`` (default :func:`wmr.characteristic_length`).
    quantiles : sequence of float, optional
        Quantile levels in [0, 1].
    keep : bool, optional
        Also return every value (``Sweep.values``, ``8 N`` bytes).
    chunk : int, optional
        Configurations per chunk (rounded up to a multiple of 65536 for a :class:`Sample`); by default
        :data:`CHUNK`, or :data:`FUSED_CHUNK` where a fused kernel evaluates the analysis from the
        twists (``kappa_J`` of a swerve-like robot over :class:`Drivable` configurations).
    progress : callable, optional
        Called as ``progress(done, total)`` after each chunk.
    client : dask.distributed.Client, optional
        Evaluate the chunks on this Dask cluster (one kernel thread per task) instead of in
        this process; the result is the same.
    interruptible : bool, optional
        A Ctrl-C (SIGINT) stops the sweep after the chunk in progress and the result covers the
        configurations evaluated so far (``Sweep.complete`` is False); a second Ctrl-C interrupts
        at once.  Only in the main thread.

    Returns
    -------
    Sweep

    Raises
    ------
    TypeError
        If ``robot`` is not a :class:`~wmr.Robot`, ``analysis`` not a string, ``angles`` not a
        grid, sample or array, or ``progress`` not callable.
    ValueError
        If ``analysis`` is unknown, ``det_J`` is asked of a non-square :math:`\mathbf J`, the
        robot is symbolic, or a number is out of range.
    wmr.errors.LimitError
        Limits (:mod:`wmr.model.limits`) are checked before any work: the number of
        configurations, and the working memory (the chunk is made smaller to fit; ``keep`` needs
        ``8 N`` bytes more).

    Examples
    --------
    >>> import wmr
    >>> from wmr.analysis.sweep import Grid
    >>> bot = wmr.paper_robot("centred")
    >>> res = wmr.sweep(bot, "mobility", Grid(12))
    >>> res.count, res.counts                    # mobility 1 where the axles meet (or are parallel)
    (1728, {0: 1408, 1: 320})
    >>> float(wmr.sweep(bot, "det_J", Grid(12)).worst)
    0.0
    """
    from ...model.robot import Robot

    if not isinstance(robot, Robot):
        raise InputTypeError(f"robot must be a wmr.Robot, got {robot!r}")
    if robot.is_symbolic:
        raise InputValueError(f"robot must be numeric for a sweep, got a symbolic robot {robot!r}")
    if not isinstance(analysis, str):
        raise InputTypeError(f"analysis must be a string, one of {sorted(ANALYSES)}, got {analysis!r}")
    if analysis not in ANALYSES:
        raise InputValueError(f"analysis must be one of {sorted(ANALYSES)}, got {analysis!r}")
    an = ANALYSES[analysis]
    if an.square and robot.n_rates != 3:
        raise InputValueError(
            f"analysis 'det_J' needs a square J (n_rates = 3), got n_rates = {robot.n_rates} "
            f"for {robot!r}; use 'kappa_J' for a non-square J"
        )
    w = robot.w
    source = angles if isinstance(angles, Drivable) else as_source(angles, w)
    qs = tuple(float(validation.real("quantiles", q)) for q in np.atleast_1d(np.asarray(quantiles, dtype=object)))
    if any(not 0.0 <= q <= 1.0 for q in qs):
        raise InputValueError(f"quantiles must lie in [0, 1], got {list(quantiles)}")
    chunk = count("chunk", chunk)
    blocks = isinstance(source, (Sample, Drivable))
    if blocks:
        chunk = -(-chunk // BLOCK) * BLOCK
    if progress is not None and not callable(progress):
        raise InputTypeError(f"progress must be callable as progress(done, total), got {progress!r}")
    if client is not None and not callable(getattr(client, "map", None)):
        raise InputTypeError(f"client must be a dask.distributed.Client, got {client!r}")
    keep = bool(keep)

    total = source.size(w)  # the limits, before any work on the robot
    check("configurations", total, "this sweep")
    fused = an.fused is not None and isinstance(source, Drivable) and an.fused(robot, L)
    if fused and chunk == CHUNK:
        chunk = FUSED_CHUNK
    chunk = _fit_memory(chunk, total, robot, analysis, keep, blocks, fused)
    if isinstance(source, Drivable):
        source = source.bind(robot)
    L = J_length(robot, L) if an.uses_L else None
    bounds = ((a, min(a + chunk, total)) for a in range(0, total, chunk))
    run = _run_local if client is None else _run_dask
    with _Interrupt(interruptible) as stop:
        result = run(bounds, total, progress, client, stop, robot, analysis, source, w, L, keep)
    return finish(result, analysis, an, source, w, qs, keep, complete=not stop.requested)


def bytes_per_configuration(robot, analysis) -> int:
    """An upper estimate of the working memory of one configuration in a chunk of ``analysis`` (bytes)."""
    robot = validation.numeric_robot(robot)
    if analysis not in ANALYSES:
        raise InputValueError(f"analysis must be one of {sorted(ANALYSES)}, got {analysis!r}")
    w, n = robot.w, robot.n_rates
    own = {
        "rank_F": 40 * w,
        "mobility": 40 * w,
        "actuated_mobility": 80 * w,
        "det_J": 24 * n + 32,
        "kappa_J": 24 * n + 64,
        "kappa_JL1": 8,
    }[analysis]
    return 8 * (6 * w + 48 + own)


def _fit_memory(chunk, total, robot, analysis, keep, blocks, fused=False):
    """The chunk, made small enough for the memory limit (:mod:`wmr.model.limits`), or a LimitError.

    A fused kernel (``fused``) holds a value and a share of its block's reduction per configuration
    (64 bytes) beside a few MB per thread.
    """
    budget = limit("memory_mb") * 2**20
    if keep:
        check("memory_mb", (8 * total + 64 * 2**20) / 2**20, "the sweep's kept values (keep=True)")
        budget -= 8 * total
    per = 64 if fused else bytes_per_configuration(robot, analysis)
    per += 3 * 8 * BLOCK * robot.w // chunk if blocks else 0
    fits = int(budget // 2 // per)  # half the budget: the reduction, Python and NumPy themselves
    if fits < 256:
        check("memory_mb", 512 * per / 2**20, f"a sweep of {analysis} for this robot ({robot.w} wheel units)")
    chunk = max(256, min(chunk, fits))
    if blocks and chunk >= BLOCK:
        chunk = chunk // BLOCK * BLOCK  # whole blocks of a sample, none drawn twice
    return chunk


class _Interrupt:
    """Within the ``with`` block, a first Ctrl-C (SIGINT) asks the sweep to stop after the chunk in progress.

    Only when ``enabled`` and in the main thread (where Python delivers signals); a second Ctrl-C
    interrupts at once (the default handler is back).
    """

    def __init__(self, enabled):
        self.enabled, self.requested, self._old = bool(enabled), False, None

    def _handler(self, signum, frame):
        self.requested = True
        signal.signal(signal.SIGINT, self._old)

    def __enter__(self):
        if self.enabled and threading.current_thread() is threading.main_thread():
            self._old = signal.signal(signal.SIGINT, self._handler)
        return self

    def __exit__(self, *exc):
        if self._old is not None and signal.getsignal(signal.SIGINT) == self._handler:
            signal.signal(signal.SIGINT, self._old)
        return False


def _run_local(bounds, total, progress, client, stop, *task):
    """Evaluate the chunks ``bounds`` one after the other in this process; the merged :class:`Partial`."""
    result, done = Partial(), 0
    for a, b in bounds:
        if stop.requested:
            break
        result.merge(_evaluate(task, a, b, None))
        done += b - a
        if progress is not None:
            progress(done, total)
    return result


def _run_dask(bounds, total, progress, client, stop, *task):
    """Evaluate the chunks on a Dask cluster (one kernel thread per task), merged as they finish."""
    from dask.distributed import as_completed

    bounds = list(bounds)
    n = len(bounds)
    futures = client.map(_evaluate, [task] * n, [a for a, _ in bounds], [b for _, b in bounds], [1] * n, pure=False)
    result, done = Partial(), 0
    for fut in as_completed(futures):
        if stop.requested:
            client.cancel(futures)
            break
        part = fut.result()
        result.merge(part)
        done += part.count
        fut.release()
        if progress is not None:
            progress(done, total)
    return result
