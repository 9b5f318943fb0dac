r"""What a chapter (``notebooks/01..08``) is: where it writes, its ledger, its random generator, its figures.

* :func:`project` -- where a notebook writes its figures and ledger rows: ``$WMR_OUT`` (set by the
  build), else a scratch folder under the project's ``build/`` found from the notebook's own location,
  else a temporary folder.  A notebook never writes a tracked file.
* :class:`Chapter` -- one per notebook: its ledger, its random generator (fixed seed), its
  figures (:meth:`Chapter.figure`), its verdicts (:meth:`Chapter.record`, sentences generated
  from the ledger rows) and what it derived for later chapters (:meth:`Chapter.save_derived`).

The chapters show their results with :mod:`edition.display` (:func:`quote`, :func:`show`,
:func:`say`, :func:`table`, re-exported here, so that a chapter imports what it uses from one place).
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .display import quote, say, show, table
from .ledger import Finding, Ledger
from .verify import SEED

__all__ = ["OUT_VARIABLE", "Project", "project", "grading", "Chapter", "quote", "say", "show", "table"]


# --------------------------------------------------------------------------------------- where files go
#: Set by the build: the directory an executed chapter writes its figures and ledger rows to.
OUT_VARIABLE = "WMR_OUT"


@dataclass(frozen=True)
class Project:
    """Where a notebook writes.  Only the build publishes into the tracked ``figures/``.

    Attributes
    ----------
    root : pathlib.Path or None
        The project the notebook belongs to (the directory holding ``notebooks/`` and ``figures/``),
        or None for a notebook outside any project.
    out : pathlib.Path
        Where this run writes: ``$WMR_OUT`` when the build runs the chapter, else a scratch folder
        ``<root>/build/scratch/<chapter>`` (untracked), else a new temporary folder.
    source : str
        ``"build"``, ``"scratch"`` or ``"temporary"``.
    """

    root: Path | None
    out: Path
    source: str

    @property
    def figures(self):
        """The folder for figure files and tables: :attr:`out`."""
        return self.out

    def where(self):
        """A sentence saying where this notebook writes (and which ``wmr`` it imports, if from elsewhere).

        Returns
        -------
        str
            Markdown.
        """
        import wmr

        pkg = Path(wmr.__file__).resolve().parent
        why = {
            "scratch": "a scratch folder of this project; only `make report` or `make test` writes `figures/`",
            "temporary": "a temporary folder: this notebook is not inside the project; its figures are shown, not saved",
            "build": "the build",
        }[self.source]
        what = "ledger rows" if self.source == "temporary" else "figures and ledger rows"
        text = f"*This run writes its {what} to* `{self.out}` *({why}).*"
        if self.root is not None and pkg.parent != self.root:
            text += f" *The `wmr` package it imports is* `{pkg}`*, not this project’s.*"
        return text

    def _repr_markdown_(self):
        return self.where()


def _notebook_dir():
    """The running notebook's directory: ``$JPY_SESSION_NAME`` (Jupyter) if it names a notebook, else the cwd."""
    session = os.environ.get("JPY_SESSION_NAME", "")
    if session.endswith(".ipynb") and Path(session).is_file():
        return Path(session).resolve().parent
    return Path.cwd()


def _project_root(here):
    """The project holding the notebook directory ``here``: a directory with ``notebooks/`` and ``figures/``."""
    for root in (here.parent if here.name == "notebooks" else here, here):
        if (root / "notebooks").is_dir() and (root / "figures").is_dir():
            return root
    return None


def project(where=None, chapter="scratch"):
    """Where a notebook writes, never into a tracked file.

    ``$WMR_OUT`` when set (the build sets it, and publishes what the chapters wrote into
    ``figures/`` itself); otherwise the notebook's own location ``where`` (default: the running
    notebook's directory) decides: a notebook of a project (``<root>/notebooks/``, with
    ``<root>/figures/``) writes into ``<root>/build/scratch/<chapter>``; any other notebook (a copy)
    into a new temporary folder.

    Parameters
    ----------
    where : path-like, optional
        The notebook's directory.
    chapter : str, optional
        The chapter's name: the scratch folder's.

    Returns
    -------
    Project

    Examples
    --------
    >>> import os, tempfile
    >>> p = project(tempfile.gettempdir()) if "WMR_OUT" not in os.environ else None
    >>> p is None or (p.root, p.source)
    (None, 'temporary')
    """
    env = os.environ.get(OUT_VARIABLE, "").strip()
    here = (Path(where) if where is not None else _notebook_dir()).resolve()
    root = _project_root(here)
    if env:
        return Project(root=root, out=Path(env).resolve(), source="build")
    if root is not None:
        return Project(root=root, out=root / "build" / "scratch" / chapter, source="scratch")
    import tempfile

    return Project(root=None, out=Path(tempfile.mkdtemp(prefix=f"wmr-{chapter}-")), source="temporary")


def grading():
    """Whether nbgrader is running this notebook to grade it (it sets ``$NBGRADER_EXECUTION`` while it autogrades or
    validates).  Then a chapter computes what its cells use and skips what only a reader sees: figures are not
    drawn, and chapter 9 runs each experiment at its nominal point only, not over its parameter box.

    Returns
    -------
    bool
    """
    return bool(os.environ.get("NBGRADER_EXECUTION"))


# --------------------------------------------------------------------------------------- a chapter
class Chapter:
    r"""One notebook: its ledger, its random generator and where it writes.

    Parameters
    ----------
    notebook : str
        The notebook's stem, e.g. ``"04_centred_wheels_and_singularities"``.
    where : path-like, optional
        The notebook's directory (default: found by :func:`project`).

    Attributes
    ----------
    project : Project
    ledger : edition.ledger.Ledger
    rng : numpy.random.Generator
        Seeded with :data:`edition.verify.SEED`.
    """

    def __init__(self, notebook, where=None):
        self.notebook = notebook
        self.project = project(where, notebook)
        self.ledger = Ledger(notebook)
        self.rng = np.random.default_rng(SEED)
        if self.project.source != "build":
            say(self.project.where())

    def record(self, *results):
        """Grade and record findings; display each verdict sentence (generated from its ledger row).

        Parameters
        ----------
        *results : Finding or object with a ``findings`` attribute

        Returns
        -------
        None
            (The rows are in :attr:`ledger`.)
        """
        rows = []
        for res in results:
            for f in [res] if isinstance(res, Finding) else list(res.findings):
                rows.append(self.ledger.add(f))
        say("\n\n".join(r.sentence() for r in rows))

    def figure(self, key, data=None):
        """Compute (unless given), show and save one of the paper's figures into :attr:`Project.out`.

        Saved only when the notebook belongs to a project (or the build runs it); a notebook elsewhere,
        whose :attr:`Project.source` is ``"temporary"``, shows the figure and writes no file.  While nbgrader
        grades the notebook (``$NBGRADER_EXECUTION`` set) the numbers are computed and the figure is not drawn.

        Parameters
        ----------
        key : str
            A key of :data:`edition.figures.FIGURES`.
        data : data class, optional

        Returns
        -------
        data class
            The figure's numbers.
        """
        from .figures import show as show_figure

        # a notebook outside any project (a copy, a student's folder) only shows its figures: their files would go
        # to a temporary folder nobody reads, and writing SVG and PDF is most of a figure's time; while nbgrader
        # grades (it sets NBGRADER_EXECUTION) the figure is computed, not drawn: nobody sees it, and drawing the
        # figures is most of the time a chapter takes to grade
        keep = self.project.source != "temporary"
        return show_figure(key, data, outdir=self.project.figures if keep else None, draw=not grading())

    def save_derived(self, **objects):
        """Write derived objects a later chapter or a test reads (:func:`edition.derivations.derived`), silently.

        Into :attr:`Project.out`, as ``<chapter>.derived.json`` (:func:`edition.derivations.write`): the build
        publishes it into ``figures/``.

        Parameters
        ----------
        **objects
            ``name=object``: SymPy objects (or lists, tuples and dicts of them) as the derivation cells bound them.

        Returns
        -------
        pathlib.Path
            The file written.
        """
        from .derivations import write

        return write(self.project.out, self.notebook, objects)

    def close(self):
        """Write this chapter's ledger fragment and show its tally.

        Returns
        -------
        None
            (The rows are ``<out>/ledger.csv``.)
        """
        self.ledger.write(self.project.out)
        c = self.ledger.counts()
        say(
            f"*Ledger of this chapter:* {len(self.ledger.rows)} rows "
            f"({c['ok']} ok, {c['typo']} typo, {c['wrong']} wrong)."
        )
