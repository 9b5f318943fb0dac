r"""The paper's equations *as printed*, transcribed into SymPy once.

Each printed form is registered with :func:`register` in the module of its section
(:mod:`edition.platform_wheels` (2)-(19), :mod:`edition.offset` (20)-(29),
:mod:`edition.isotropy` (30)-(50), :mod:`edition.centred` (51)-(59),
:mod:`edition.steering` (60)-(65)).  These are the statements under test: the notebooks derive
each result from the model in :mod:`wmr` and compare it with the printed form, never the other
way round.  Where the extracted text is garbled, the entry records the most plausible printed
form and says so in ``garbled``.

The claims of the text that the edition checks (sentences, not numbered equations) are
registered the same way with :func:`register_claim` and read with :func:`claim`.
"""
from __future__ import annotations

import importlib
from dataclasses import dataclass, field


@dataclass(frozen=True)
class Printed:
    """One numbered equation as printed.

    Attributes
    ----------
    id : str
        Equation number, e.g. ``"20"``.
    section : str
        Paper section, e.g. ``"4.1"``.
    latex : str
        The printed form in LaTeX (reconstructed where the extraction is garbled).
    expr : object
        SymPy form: an ``Eq``, a ``Matrix`` or an expression; ``None`` when the equation is a
        definition or statement better checked through its consequences (said in ``note``).
    garbled : str
        What the extraction garbled and how it was read.
    note : str
        What the reader should know about the transcription.
    extra : dict
        Further printed objects of the equation, by name (e.g. the matrices of a product).

    Examples
    --------
    >>> printed(59).section
    '5.3'
    """

    id: str
    section: str
    latex: str
    expr: object = None
    garbled: str = ""
    note: str = ""
    extra: dict = field(default_factory=dict)


PRINTED: dict = {}
CLAIMS: dict = {}

_MODULES = ("platform_wheels", "offset", "isotropy", "centred", "steering", "conclusions")


def register(id, section, latex, expr=None, garbled="", note="", **extra):
    """Add a printed equation to :data:`PRINTED` (each id once).

    Parameters
    ----------
    id : int or str
        Equation number.
    section : str
        Paper section.
    latex : str
        The printed form in LaTeX.
    expr : object, optional
        Its SymPy form (see :class:`Printed`).
    garbled : str, optional
        What the extraction garbled and how it was read.
    note : str, optional
    **extra
        Further printed objects (:attr:`Printed.extra`).

    Returns
    -------
    Printed

    Raises
    ------
    ValueError
        If equation ``id`` is registered already.
    """
    id = str(id)
    if id in PRINTED:
        raise ValueError(f"equation ({id}) is registered twice")
    PRINTED[id] = Printed(id, section, latex, expr, garbled, note, extra)
    return PRINTED[id]


def _load():
    for m in _MODULES:
        try:
            importlib.import_module(f"{__name__}.{m}")
        except ModuleNotFoundError as e:
            if e.name != f"{__name__}.{m}":
                raise


def printed(id):
    """The printed form of equation ``id``, as transcribed in the modules of :mod:`edition`.

    Parameters
    ----------
    id : int or str
        Equation number, (2)-(65).

    Returns
    -------
    Printed

    Raises
    ------
    ValueError
        If the equation is not transcribed.

    Examples
    --------
    >>> printed(20).id
    '20'
    """
    _load()
    id = str(id)
    if id not in PRINTED:
        raise ValueError(f"equation ({id}) is not transcribed in edition")
    return PRINTED[id]


@dataclass(frozen=True)
class Claim:
    """A claim of the paper's text, quoted (not a numbered equation).

    Attributes
    ----------
    slug : str
        Short id, e.g. ``"drift"``.
    section : str
        Section(s) of the paper, e.g. ``"4.2"`` or ``"5.2, 5.4.3"``.
    text : str
        The claim, quoted or closely paraphrased, Markdown with ``$...$`` math.
    """

    slug: str
    section: str
    text: str


def register_claim(slug, section, text):
    """Add a claim to :data:`CLAIMS` (each slug once).

    Parameters
    ----------
    slug : str
    section : str
    text : str
        Markdown with ``$...$`` math.

    Returns
    -------
    Claim
    """
    if slug in CLAIMS:
        raise ValueError(f"claim {slug!r} is registered twice")
    CLAIMS[slug] = Claim(slug, section, text)
    return CLAIMS[slug]


def claim(slug):
    """The claim ``slug`` as quoted.

    Parameters
    ----------
    slug : str

    Returns
    -------
    Claim
    """
    _load()
    if slug not in CLAIMS:
        raise ValueError(f"claim {slug!r} is not transcribed in edition; known: {sorted(CLAIMS)}")
    return CLAIMS[slug]
