r"""The paper's Figures 7-13, a map of det J and a drawing of the conventions, regenerated from the model.

One module per figure (:data:`FIGURES`), each with

``NUMBER``, ``TITLE``, ``PAPER_CAPTION``
    The paper's figure number (``""`` for our own figures), a title and the paper's caption.
``data(**params)``
    A frozen data class of every number the figure shows or asserts, computed from :mod:`wmr`
    (no matplotlib): the tests check these.
``draw(data, fig=None)``
    A :class:`matplotlib.figure.Figure` of that data (computes nothing new).
``caption(data)``
    Our caption, Markdown with ``$...$`` math, every number printed so that the text is the
    same on any machine.

:func:`save` writes ``<key>.svg|pdf|png`` and ``<key>.json`` (``key``, ``number``, ``title``,
``paper_caption``, ``caption``, ``numbers``, ``formats``) deterministically and atomically;
:func:`show` displays a figure in a notebook; ``python -m edition.figures OUTDIR [KEY ...]``
writes them all (:func:`write_all`).

Examples
--------
>>> from edition.figures import fig13
>>> d = fig13.data()                     # numbers only: matplotlib is not imported
>>> d.rank_F, d.admissible
(5, True)
"""

from __future__ import annotations

import importlib
import sys
import time
from pathlib import Path

from . import output
from .common import snapped

__all__ = ["FIGURES", "KEYS", "module", "save", "show", "write_all", "main"]

#: Figure keys in the order of the report.
KEYS = ("fig07", "fig08", "fig09", "fig10", "fig11", "fig12", "fig13", "detmap", "conventions")


#: Ordered key -> figure module (``fig07`` .. ``fig13``, ``detmap``, ``conventions``).
FIGURES = {key: importlib.import_module(f"{__name__}.{key}") for key in KEYS}


def module(key):
    """The figure module of ``key``.

    Parameters
    ----------
    key : str
        One of :data:`KEYS`.

    Returns
    -------
    module
        With ``NUMBER``, ``TITLE``, ``PAPER_CAPTION``, ``data``, ``draw`` and ``caption``.

    Raises
    ------
    TypeError
        If ``key`` is not a string.
    ValueError
        If it is not a known key (the message names them).

    Examples
    --------
    >>> module("fig07").NUMBER
    '7'
    """
    if not isinstance(key, str):
        raise TypeError(f"key must be a figure key (str), got {type(key).__name__}")
    if key not in KEYS:
        raise ValueError(f"key must be one of {list(KEYS)}, got {key!r}")
    return FIGURES[key]


def _draw(key, data):
    """Draw from the snapped data, then snap what the figure hands to the renderer (the same file anywhere)."""
    from wmr.plot.snapping import snap_figure

    return snap_figure(module(key).draw(snapped(data)))


def _render(key, data, fig=None, fmts=None):
    mod = module(key)
    fig = _draw(key, data) if fig is None else fig
    return output.render(
        fig,
        output.formats(mod) if fmts is None else fmts,
        title=f"{key}: {mod.TITLE}",
        creator=f"edition.figures.{key}",
    )


def save(key, data, outdir, *, fig=None):
    """Write ``outdir/<key>.<fmt>`` (each of the figure's formats) and ``outdir/<key>.json``.

    Parameters
    ----------
    key : str
        A key of :data:`FIGURES`.
    data : data class
        ``FIGURES[key].data(...)``.
    outdir : str or os.PathLike
        Created if needed.
    fig : Figure, optional
        ``FIGURES[key].draw(data)`` if already drawn.

    Returns
    -------
    list of pathlib.Path
    """
    files = _render(key, data, fig)
    return output.write(outdir, key, files, output.record(key, module(key), data))


def show(key, data=None, *, outdir=None, width=None, draw=True):
    """Compute (unless ``data`` is given), draw and display a figure with its alt text and caption; save it if asked.

    The alt text is the figure module's ``alt(data)`` (plain text: what the figure shows) when it defines one,
    else its title; it is shown by :func:`edition.display.image`.

    Parameters
    ----------
    key : str
        A key of :data:`FIGURES`.
    data : data class, optional
        Default ``FIGURES[key].data()``.
    outdir : str or os.PathLike, optional
        Where to :func:`save` the figure's files.
    width : int, optional
        Display width in pixels (default: 110 pixels per inch of the figure).
    draw : bool, optional
        False: compute the numbers, draw nothing and save nothing, and display the caption with a line saying
        the figure was not drawn (what :meth:`edition.notebook.Chapter.figure` asks while nbgrader grades).

    Returns
    -------
    data class
        The figure's numbers.
    """
    from IPython.display import Markdown, display

    from ..display import image

    mod = module(key)
    data = mod.data() if data is None else data
    label = f"Figure {mod.NUMBER}" + (" (regenerated)" if mod.NUMBER.isdigit() else "") + ": " if mod.NUMBER else ""
    if not draw:
        display(
            Markdown(f"*{label}{mod.TITLE}* (not drawn in this run; run the notebook to see it.) {mod.caption(data)}")
        )
        return data
    fig = _draw(key, data)
    files = _render(key, data, fig, (*output.formats(mod), "png") if outdir is not None else ("png",))
    if outdir is not None:
        output.write(outdir, key, {f: b for f, b in files.items() if f != "png"}, output.record(key, mod, data))
    # alt text: the module's alt(data) when it has one, else the figure's title (what it shows, in words)
    alt = mod.alt(data) if hasattr(mod, "alt") else f"{label}{mod.TITLE}."
    # marked, so that the report shows the figure once, from its files, instead of this picture
    image(files["png"], alt, width or int(round(fig.get_figwidth() * 110)), metadata={"wmr_figure": key})
    display(Markdown(f"*{label}{mod.TITLE}.* {mod.caption(data)}"))
    return data


def write_all(outdir, keys=None, *, csv=True, verbose=False):
    """Compute and save the figures ``keys`` into ``outdir``.

    Each figure is written as its files and ``<key>.json`` (its numbers and both captions, what
    the report reads); with ``csv`` also ``singularities.csv`` (:func:`edition.families.write_csv`,
    which notebook 04 writes too).

    Parameters
    ----------
    outdir : str or os.PathLike
        Created if needed (the caller knows the project; the library does not).
    keys : sequence of str, optional
        Keys of :data:`FIGURES` (default: all).
    csv : bool, optional
        Also write ``singularities.csv``.
    verbose : bool, optional
        Print the time of each figure to stderr.

    Returns
    -------
    dict
        ``{key: data}``: the numbers of each figure written.
    """
    outdir = Path(outdir)
    keys = list(KEYS) if keys is None else list(keys)
    for key in keys:
        module(key)  # a clear error before any work
    out = {}
    for key in keys:
        t0 = time.perf_counter()
        out[key] = FIGURES[key].data()
        save(key, out[key], outdir)
        if verbose:
            print(f"  {key:12s} {time.perf_counter() - t0:5.2f} s", file=sys.stderr)
    if csv:
        from ..families import write_csv

        t0 = time.perf_counter()
        write_csv(outdir / "singularities.csv")
        if verbose:
            print(f"  {'singularities':12s} {time.perf_counter() - t0:5.2f} s", file=sys.stderr)
    return out


def main(argv=None):
    """``python -m edition.figures OUTDIR [KEY ...]``: write the figures (all, or the given keys) into OUTDIR.

    Parameters
    ----------
    argv : list of str, optional
        The arguments (default ``sys.argv[1:]``).

    Returns
    -------
    int
        Exit status: 0, or 2 for a usage error.
    """
    argv = sys.argv[1:] if argv is None else list(argv)
    if not argv or argv[0] in ("-h", "--help"):
        print((main.__doc__ or "") + "\nkeys: " + " ".join(KEYS))
        return 0 if argv else 2
    outdir, keys = argv[0], (argv[1:] or None)
    bad = [k for k in keys or [] if k not in KEYS]
    if bad:
        print(f"unknown figure keys {bad}; known: {list(KEYS)}", file=sys.stderr)
        return 2
    t0 = time.perf_counter()
    write_all(outdir, keys, verbose=True)
    print(f"wrote {outdir} in {time.perf_counter() - t0:.1f} s", file=sys.stderr)
    return 0
