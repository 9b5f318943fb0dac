r"""Chunked execution of a sweep: :func:`sweep`, in this process or on a Dask cluster.

The configurations ``0 .. N-1`` are cut into chunks of ``chunk`` consecutive numbers; each chunk
is generated, evaluated with the batched kernels and reduced (:func:`_evaluate`, which is what a
Dask worker runs), and the partial reductions are merged as they arrive.
"""

from __future__ import annotations

import contextlib
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
from .._batch import limit_threads
from ..isotropy import characteristic_length
from .analyses import ANALYSES
from .configurations import BLOCK, Grid, Sample, count
from .motions import Drivable, Motions
from .reduction import Partial, finish
from .result import Sweep
from .swerve_kappa import swerve_like

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
    qs = tuple(float(validation.real("quantiles", q)) for q in np.atleast_1d(np.asarray(quantiles, dtype=object)))
    if any(not 0.0 <= q <= 1.0 for q in qs):
        raise InputValueError(f"quantiles must lie in [0, 1], got {list(quantiles)}")
    if progress is not None and not callable(progress):
        raise InputTypeError(f"progress must be callable as progress(done, total), got {progress!r}")
    if client is not None and not callable(getattr(client, "map", None)):
        raise InputTypeError(f"client must be a dask.distributed.Client, got {client!r}")
    if L is not None:
        L = validation.number("L", validation.positive("L", L))
    source, total, covers = _source(angles, w)
    chunk = count("chunk", chunk)
    blocks = isinstance(source, (Sample, Drivable))
    if blocks:
        chunk = -(-chunk // BLOCK) * BLOCK
    check("configurations", total, "this sweep")  # the limits, before any work on the robot
    fused = an.fused and isinstance(source, Drivable) and swerve_like(robot)
    if fused and chunk == CHUNK:
        chunk = FUSED_CHUNK
    chunk = _fit_memory(chunk, total, robot, analysis, bool(keep), blocks, fused)
    if an.uses_L and L is None:
        L = characteristic_length(robot)
    if isinstance(source, Drivable):
        source = Motions(robot, source.n, source.seed, L if fused else None)
    bounds = ((a, min(a + chunk, total)) for a in range(0, total, chunk))
    run = _run_local if client is None else _run_dask
    with _interrupt(interruptible) as stop:
        result = run(bounds, total, progress, client, stop, robot, analysis, source, w, L, bool(keep))
    return finish(result, analysis, an, source, w, qs, bool(keep), covers, complete=not stop)


def _source(angles, w):
    """The source of a sweep's configurations (explicit angles as an array (N, w)), their number and what they cover."""
    if isinstance(angles, (Grid, Sample, Drivable)):
        size = angles.size(w)
        if size < 1:
            raise InputValueError(f"angles has no configurations: {angles!r}")
        return angles, size, angles.covers
    if isinstance(angles, (str, bytes)) or angles is None:
        raise InputTypeError(f"angles must be a Grid, a Sample or an array (N, {w}) of steering angles, got {angles!r}")
    beta = validation.finite_array("angles", angles, last=w).reshape(-1, w)
    if beta.shape[0] == 0:
        raise InputValueError(f"angles must hold at least one configuration, got shape {np.shape(angles)}")
    return beta, beta.shape[0], f"the {beta.shape[0]:,} configurations given"


#: bytes of one configuration's working memory in a chunk, by analysis: ``8 (6 w + 48 + a w + b n + c)`` for (a, b, c)
_BYTES = {
    "rank_F": (40, 0, 0),
    "mobility": (40, 0, 0),
    "actuated_mobility": (80, 0, 0),
    "det_J": (0, 24, 32),
    "kappa_J": (0, 24, 64),
    "kappa_JL1": (0, 0, 8),
}


def _fit_memory(chunk, total, robot, analysis, keep, blocks, fused):
    """The chunk, made small enough for the memory limit (:mod:`wmr.model.limits`), or a LimitError.

    A fused kernel holds a value and a share of its block's reduction per configuration (64 bytes).
    """
    budget = limit("memory_mb") * 2**20
    if keep:
        check("memory_mb", (8 * total + 64 * 2**20) / 2**20, "the sweep's kept values (keep=True)")
        budget -= 8 * total
    a, b, c = _BYTES[analysis]
    per = 64 if fused else 8 * (6 * robot.w + 48 + a * robot.w + b * robot.n_rates + c)
    per += 3 * 8 * BLOCK * robot.w // chunk if blocks else 0
    fits = int(budget // 2 // per)  # half the budget: the reduction, Python and NumPy themselves
    if fits < 256:
        check("memory_mb", 512 * per / 2**20, f"a sweep of {analysis} for this robot ({robot.w} wheel units)")
    chunk = max(256, min(chunk, fits))
    if blocks and chunk >= BLOCK:
        chunk = chunk // BLOCK * BLOCK  # whole blocks of a sample, none drawn twice
    return chunk


@contextlib.contextmanager
def _interrupt(enabled):
    """Within the block, a first Ctrl-C (SIGINT) asks the sweep to stop after the chunk in progress (a list, true then).

    Only when ``enabled`` and in the main thread; a second Ctrl-C interrupts at once (the default handler is back).
    """
    stop: list[bool] = []
    if not enabled or threading.current_thread() is not threading.main_thread():
        yield stop
        return
    old = signal.getsignal(signal.SIGINT)

    def handler(signum, frame):
        stop.append(True)
        signal.signal(signal.SIGINT, old)

    signal.signal(signal.SIGINT, handler)
    try:
        yield stop
    finally:
        if signal.getsignal(signal.SIGINT) == handler:
            signal.signal(signal.SIGINT, old)


def _evaluate(task, start, stop, threads):
    """The :class:`Partial` of configurations ``start .. stop-1`` of ``task`` (run here or on a Dask worker).

    ``task`` is ``(robot, analysis name, source, w, L, keep)``; ``threads`` limits the kernels' threads.
    """
    robot, name, source, w, L, keep = task
    an = ANALYSES[name]
    with limit_threads(threads):
        if isinstance(source, Motions) and source.L is not None:  # the fused kernel, from the twists
            return source.kappa_J(start, stop, keep)
        beta = source[start:stop] if isinstance(source, np.ndarray) else source.configurations(w, start, stop)
        x = np.asarray(an.evaluate(robot, beta, L))
    return Partial().add(start, x.astype(np.int64) if an.integer else x.astype(float), an.integer, keep)


def _run_local(bounds, total, progress, client, stop, *task):
    """Evaluate the chunks ``bounds`` one after the other in this process; the merged :class:`Partial`."""
    result, done = None, 0
    for a, b in bounds:
        if stop:
            break
        part = _evaluate(task, a, b, None)
        result = part if result is None else result.merge(part)
        done += b - a
        if progress is not None:
            progress(done, total)
    return Partial() if result is None else result


def _run_dask(bounds, total, progress, client, stop, *task):
    """Evaluate the chunks on a Dask cluster (one kernel thread per task), merged as they finish."""
    from dask.distributed import as_completed

    bounds = list(bounds)
    n = len(bounds)
    futures = client.map(_evaluate, [task] * n, [a for a, _ in bounds], [b for _, b in bounds], [1] * n, pure=False)
    result, done = Partial(), 0
    for fut in as_completed(futures):
        if stop:
            client.cancel(futures)
            break
        part = fut.result()
        result.merge(part)
        done += part.count
        fut.release()
        if progress is not None:
            progress(done, total)
    return result
