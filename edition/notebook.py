r"""What the chapters (``notebooks/01..07``) share: where they write, how they show results, how they record verdicts.

Written once here so that every chapter reads the same and none pastes its own helpers.

* :func:`project` -- where a notebook writes its figures and ledger rows: ``$WMR_OUT`` (set by the
  build), else a scratch folder under the project's ``build/`` found from the notebook's own location,
  else a temporary folder.  A notebook never writes a tracked file.
* :class:`Chapter` -- one per notebook: its ledger, its random generator (fixed seed), its
  figures (:meth:`Chapter.figure`) and its verdicts (:meth:`Chapter.record`, sentences generated
  from the ledger rows).
* :func:`quote`, :func:`show`, :func:`say`, :func:`table` -- everything a reader sees goes out as
  Markdown with ``$$...$$`` math (one path, one size of type); no ``print``, no raw data frames.
* :func:`explicit`, :func:`numeric`, :func:`mod_pi` -- small algebra helpers of the derivations.

IPython is imported only when something is displayed, so the path logic works anywhere.
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import sympy as sp

from .ledger import Finding, Ledger
from .verify import SEED

__all__ = ["Project", "project", "Chapter", "quote", "show", "say", "table", "explicit", "numeric", "mod_pi",
           "latex", "aligned_sum"]


def _display(*objs):
    from IPython.display import display
    display(*objs)


def _markdown(text):
    from IPython.display import Markdown
    return Markdown(text)


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
        why = {"scratch": "a scratch folder of this project; only `make report` or `make test` writes `figures/`",
               "temporary": "a temporary folder: this notebook is not inside the project",
               "build": "the build"}[self.source]
        text = f"*This run writes its figures and ledger rows to* `{self.out}` *({why}).*"
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


# --------------------------------------------------------------------------------------- showing
#: how a quantity that does not exist (SymPy's ``nan``, NumPy's NaN from 0/0) is written for the reader
UNDEFINED = "undefined"
UNDEFINED_TEX = rf"\text{{{UNDEFINED}}}"

def latex(obj):
    r"""LaTeX of a SymPy object (matrices with square brackets), or a string unchanged.

    SymPy's ``nan`` (what 0/0 evaluates to) is written as the word it means, *undefined*.

    Parameters
    ----------
    obj : SymPy object or str

    Returns
    -------
    str

    Examples
    --------
    >>> latex(sp.Matrix([[1, 0]])), latex(r"\alpha"), latex(sp.Integer(0) / 0)
    ('\\begin{bmatrix}1 & 0\\end{bmatrix}', '\\alpha', '\\text{undefined}')
    """
    if isinstance(obj, str):
        return obj
    if obj is sp.nan:
        return UNDEFINED_TEX
    return sp.latex(obj, mat_str="bmatrix", mat_delim="")


def show(lhs, expr=None, tag=None, per_line=None):
    r"""Typeset ``lhs = expr`` as display math (Markdown ``$$...$$``).

    Parameters
    ----------
    lhs : str
        LaTeX of the left side, or of the whole formula when ``expr`` is None.
    expr : SymPy object or str, optional
        The right side.
    tag : str, optional
        An equation tag, e.g. ``"59"`` for ``\tag{59}``.
    per_line : int, optional
        Break a SymPy sum into lines of this many terms (``aligned``), in SymPy's printing order:
        a long sum then keeps the size of the text instead of being shrunk to the line.

    Returns
    -------
    None
    """
    if per_line is not None:
        _check_per_line(per_line)
    if expr is None:
        body = lhs
    elif per_line is not None and isinstance(expr, sp.Add):
        body = aligned_sum(lhs, expr, per_line)
    else:
        body = f"{lhs} = {latex(expr)}"
    if tag is not None:
        body += rf" \tag{{{tag}}}"
    _display(_markdown(f"$$\n{body}\n$$"))


def _check_per_line(per_line):
    if isinstance(per_line, bool) or not isinstance(per_line, int):
        raise TypeError(f"per_line must be an int, got {per_line!r}")
    if per_line < 1:
        raise ValueError(f"per_line must be at least 1, got {per_line}")


def aligned_sum(lhs, expr, per_line):
    r"""LaTeX of ``lhs = expr`` with the terms of the sum ``expr`` in lines of ``per_line`` (``aligned``).

    Parameters
    ----------
    lhs : str
        LaTeX of the left side.
    expr : sympy.Add
        The right side; its terms are taken in SymPy's printing order.
    per_line : int
        Terms per line, at least 1.

    Returns
    -------
    str
        A LaTeX body (no ``$``).

    Examples
    --------
    >>> x, y, z = sp.symbols("x y z")
    >>> aligned_sum("s", x - y + z, 2)
    '\\begin{aligned}s = {}& x - y\\\\ &+ z\\end{aligned}'
    """
    _check_per_line(per_line)
    parts = []
    for k, term in enumerate(expr.as_ordered_terms()):
        neg = term.could_extract_minus_sign()
        text = latex(-term if neg else term)
        parts.append(("- " if neg else ("+ " if k else "")) + text)
    lines = [" ".join(parts[i:i + per_line]) for i in range(0, len(parts), per_line)]
    return r"\begin{aligned}" + lhs + " = {}& " + r"\\ &".join(lines) + r"\end{aligned}"


def say(text):
    """Display a Markdown paragraph (for results: no ``print``).

    Parameters
    ----------
    text : str
        Markdown with ``$...$`` math.

    Returns
    -------
    None
    """
    _display(_markdown(text))


def _cell(v, in_array=False):
    from .text import RESOLUTION, number
    if isinstance(v, (bool, np.bool_)):
        return "yes" if v else "no"
    if isinstance(v, (float, np.floating)):
        x = float(v)
        if np.isnan(x):                                   # a quantity that does not exist here (0/0)
            return UNDEFINED
        if 0 < abs(x) < RESOLUTION:                       # round-off: no digits that differ between machines
            return "$0$" if in_array else f"$< 10^{{{int(np.log10(RESOLUTION))}}}$"
        return f"${number(x)}$"
    if isinstance(v, (list, tuple, set, frozenset, np.ndarray)):
        items = sorted(v) if isinstance(v, (set, frozenset)) else list(np.ravel(v) if isinstance(v, np.ndarray) else v)
        cells = [_cell(x, in_array=True) for x in items]
        return UNDEFINED if cells and all(c == UNDEFINED for c in cells) else ", ".join(cells)
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    return str(v).replace("|", r"\|").replace("\n", " ")


def table(rows, columns=None):
    r"""A Markdown table (no index column): the one way a chapter shows tabular results.

    Parameters
    ----------
    rows : list of dict or list of sequence
        One entry per row.  Booleans print as yes/no, NaN as "undefined", floats with 3 significant digits in
        math (round-off below :data:`edition.text.RESOLUTION` as a bound, or 0 inside a
        vector), lists as comma-separated values.
    columns : sequence of str, optional
        Headers; for dict rows also the keys, in order (default: the first row's keys).

    Returns
    -------
    None

    """
    rows = list(rows)
    if rows and isinstance(rows[0], dict):
        columns = list(columns or rows[0].keys())
        body = [[r.get(c, "") for c in columns] for r in rows]
    else:
        if columns is None:
            raise ValueError("columns must be given for rows that are not dicts")
        body = [list(r) for r in rows]
    head = "| " + " | ".join(columns) + " |\n|" + "---|" * len(columns) + "\n"
    text = head + "".join("| " + " | ".join(_cell(v) for v in r) + " |\n" for r in body)
    _display(_markdown(text))


def quote(id):
    r"""Display what the paper says: equation ``id`` as printed (with ``\tag``), or the claim ``id``.

    Parameters
    ----------
    id : int or str
        An equation number, or a claim's slug.

    Returns
    -------
    None
        (Read the transcription itself with :func:`edition.printed` or :func:`edition.claim`.)
    """
    from . import claim, printed
    if str(id).isdigit():
        p = printed(id)
        text = f"*As printed (Section {p.section}):*\n\n$$\n{p.latex} \\tag{{{p.id}}}\n$$"
        if p.garbled:
            text += f"\n\n*Transcription:* {p.garbled}"
        _display(_markdown(text))
        return None
    c = claim(id)
    _display(_markdown(f"> {c.text} (Section {c.section})"))
    return None


# --------------------------------------------------------------------------------------- algebra helpers
def explicit(expr, mapping):
    """Substitute explicit matrices for the named objects (MatrixSymbols) of a printed form.

    Parameters
    ----------
    expr : SymPy expression or Matrix
    mapping : dict
        Named object -> SymPy matrix or expression.

    Returns
    -------
    sympy.Matrix
    """
    return sp.Matrix(sp.sympify(expr).subs(mapping).doit())


def numeric(expr, mapping):
    """:func:`explicit` with NumPy matrices; returns a float array.

    Parameters
    ----------
    expr : SymPy expression or Matrix
    mapping : dict
        Named object -> array.

    Returns
    -------
    numpy.ndarray
    """
    return np.array(explicit(expr, {k: sp.Matrix(v) for k, v in mapping.items()}), dtype=float)


def mod_pi(angle):
    r"""An angle modulo :math:`\pi`, in :math:`[-\pi/2, \pi/2)`: a wheel rolls either way, so axle angles count mod :math:`\pi`.

    Parameters
    ----------
    angle : array_like
        Radians.

    Returns
    -------
    numpy.ndarray

    Examples
    --------
    >>> float(mod_pi(np.pi + 0.25))
    0.25
    """
    return (np.asarray(angle, dtype=float) + np.pi / 2) % np.pi - np.pi / 2


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
            for f in ([res] if isinstance(res, Finding) else list(res.findings)):
                rows.append(self.ledger.add(f))
        say("\n\n".join(r.sentence() for r in rows))

    def figure(self, key, data=None):
        """Compute (unless given), show and save one of the paper's figures into :attr:`Project.out`.

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
        return show_figure(key, data, outdir=self.project.figures)

    def close(self):
        """Write this chapter's ledger fragment and show its tally.

        Returns
        -------
        None
            (The rows are ``<out>/ledger.csv``.)
        """
        self.ledger.write(self.project.out)
        c = self.ledger.counts()
        say(f"*Ledger of this chapter:* {len(self.ledger.rows)} rows "
            f"({c['ok']} ok, {c['typo']} typo, {c['wrong']} wrong).")
