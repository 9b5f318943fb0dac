r"""The paper as printed: the table ``edition/printed.toml`` read into :class:`Printed` and :class:`Claim` records.

The table is the transcription, written once as text: for each numbered equation (1)-(65) its
section, the LaTeX as printed, its SymPy form, what the text extraction shows (``extracted``,
verbatim) and any doubt about the reading (``doubt``); for each claim of the text that the edition
checks, the quoted sentence.  A transcription error is a change of one line of that file.

The SymPy forms are strings evaluated against :mod:`edition.symbols`, a few SymPy constructors and
the printed building blocks of the table's ``[notation]`` (the matrix E of (3), the rotation of (11),
...), each written once there.  No other name is known: a misspelt symbol is an error naming the
entry, never a new symbol.  Reading the table has no side effect; it is read once, on first use.

These are the statements under test: the checks (:mod:`edition.checks`) derive each result from
the model in :mod:`wmr` and compare it with the printed form, never the other way round.
"""

from __future__ import annotations

import functools
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import sympy as sp
from sympy.parsing.sympy_parser import auto_number, parse_expr

from . import symbols

__all__ = ["TABLE", "Printed", "Claim", "Transcription", "TranscriptionError", "load", "table", "printed", "claim"]

#: the transcription: one text file
TABLE = Path(__file__).with_name("printed.toml")

#: the SymPy names a printed form may use besides :mod:`edition.symbols` and the notation
_SYMPY = (
    "Matrix",
    "Tuple",
    "BlockMatrix",
    "BlockDiagMatrix",
    "ZeroMatrix",
    "Determinant",
    "diag",
    "eye",
    "zeros",
    "sqrt",
    "sin",
    "cos",
    "atan",
    "pi",
    "oo",
    "Integer",
    "Float",
    "Rational",
)
_EQUATION_KEYS = {"section", "latex", "sympy", "extracted", "doubt", "note", "extra", "data"}
_CLAIM_KEYS = {"title", "section", "text", "extracted"}


class TranscriptionError(ValueError):
    """The table is malformed: the message names the file, the entry and the key."""


@dataclass(frozen=True)
class Printed:
    r"""One numbered equation as printed.

    Attributes
    ----------
    id : str
        Equation number, e.g. ``"20"``.
    section : str
        Paper section, e.g. ``"4.1"``.
    latex : str
        The printed form in LaTeX (reconstructed where the extraction is garbled).
    expr : object
        SymPy form: an ``Eq``, a ``Matrix``, an expression or a tuple of them; ``None`` when the
        equation is a statement better checked through its consequences (said in ``note``).
    extracted : tuple of str
        What the text extraction shows, verbatim (the display, and any sentence the entry rests on).
    doubt : str
        What in the extraction cannot be taken at its word, and how it was read.
    note : str
        What the reader should know about the transcription.
    extra : dict
        Further printed objects of the equation, by name (SymPy forms, or plain data).

    Examples
    --------
    >>> printed(59).section
    '5.3'
    """

    id: str
    section: str
    latex: str
    expr: object = None
    extracted: tuple = ()
    doubt: str = ""
    note: str = ""
    extra: dict = field(default_factory=dict)


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
    extracted : tuple of str
        The sentences of the text extraction it quotes, verbatim.
    title : str
        How the report names the claim (Markdown), e.g. ``"drift when steering without driving"``; never the slug.
    """

    slug: str
    section: str
    text: str
    extracted: tuple = ()
    title: str = ""


@dataclass(frozen=True)
class Transcription:
    """The table read: equations by number, claims by slug, the notation's names.

    Attributes
    ----------
    equations : dict
        ``{"1": Printed, ..., "65": Printed}`` in the table's order.
    claims : dict
        ``{slug: Claim}``.
    names : dict
        Every name a SymPy form may use (symbols, SymPy constructors, notation).
    """

    equations: dict
    claims: dict
    names: dict


def _fail(where, message):
    raise TranscriptionError(f"{where}: {message}")


def _names():
    names = {n: getattr(sp, n) for n in _SYMPY}
    names["Eq"] = lambda lhs, rhs: sp.Eq(lhs, rhs, evaluate=False)  # a printed identity, never decided here
    names.update({k: v for k, v in vars(symbols).items() if not k.startswith("_") and k != "sp"})
    return names


def _parse(text, names, where):
    if not isinstance(text, str):
        _fail(where, f"a SymPy form must be a string, got {text!r}")
    try:
        return parse_expr(text, local_dict={}, global_dict=names, transformations=(auto_number,))
    except Exception as e:  # SyntaxError, NameError, TypeError, ...: all say the same: this entry is wrong
        _fail(where, f"cannot read {text!r}: {type(e).__name__}: {e}")


def _plain(value):
    """TOML data as the checks use it: arrays become tuples (recursively)."""
    if isinstance(value, list):
        return tuple(_plain(v) for v in value)
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    return value


def _sympy_tree(value, names, where):
    """Strings parsed as SymPy forms, arrays as tuples, tables as dicts (recursively)."""
    if isinstance(value, list):
        return tuple(_sympy_tree(v, names, f"{where}[{k}]") for k, v in enumerate(value))
    if isinstance(value, dict):
        return {k: _sympy_tree(v, names, f"{where}.{k}") for k, v in value.items()}
    return _parse(value, names, where)


def _text(entry, key, where, required=False):
    v = entry.get(key, "")
    if required and not v:
        _fail(where, f"'{key}' is missing")
    if not isinstance(v, str):
        _fail(where, f"'{key}' must be a string, got {v!r}")
    return v


def _entry(entry, where, keys):
    """``where``, once the entry has no key outside ``keys``."""
    bad = set(entry) - keys
    if bad:
        _fail(where, f"unknown keys {sorted(bad)}; known: {sorted(keys)}")
    return where


def _fragments(entry, where):
    v = entry.get("extracted", ())
    v = (v,) if isinstance(v, str) else tuple(v)
    if not all(isinstance(x, str) and x for x in v):
        _fail(f"{where}.extracted", "must be a string or an array of non-empty strings")
    return v


def load(path=TABLE):
    """Read a transcription table (TOML).

    Parameters
    ----------
    path : path-like, optional
        Default :data:`TABLE`.

    Returns
    -------
    Transcription

    Raises
    ------
    TranscriptionError
        An unknown or missing key, a name defined twice, a SymPy form that cannot be read: the
        message names the entry and the key.
    """
    path = Path(path)
    try:
        with open(path, "rb") as f:
            raw = tomllib.load(f)
    except tomllib.TOMLDecodeError as e:
        raise TranscriptionError(f"{path}: {e}") from None
    unknown = set(raw) - {"notation", "equation", "claim"}
    if unknown:
        _fail(f"{path}: top level", f"unknown tables {sorted(unknown)}")
    names = _names()
    for name, text in raw.get("notation", {}).items():
        if name in names:
            _fail(f"{path}: notation.{name}", "the name is defined already (a symbol or a SymPy name)")
        names[name] = _parse(text, names, f"{path}: notation.{name}")
    equations = {}
    for key, entry in raw.get("equation", {}).items():
        where = _entry(entry, f"{path}: equation.{key}", _EQUATION_KEYS)
        expr = _parse(entry["sympy"], names, f"{where}.sympy") if "sympy" in entry else None
        extra = _sympy_tree(entry.get("extra", {}), names, f"{where}.extra")
        data = _plain(entry.get("data", {}))
        if set(extra) & set(data):
            _fail(where, f"{sorted(set(extra) & set(data))} both in 'extra' and in 'data'")
        equations[key] = Printed(
            key,
            _text(entry, "section", where, True),
            _text(entry, "latex", where, True),
            expr,
            _fragments(entry, where),
            _text(entry, "doubt", where),
            _text(entry, "note", where),
            {**extra, **data},
        )
    claims = {}
    for slug, entry in raw.get("claim", {}).items():
        where = _entry(entry, f"{path}: claim.{slug}", _CLAIM_KEYS)
        claims[slug] = Claim(
            slug,
            _text(entry, "section", where, True),
            _text(entry, "text", where, True),
            _fragments(entry, where),
            _text(entry, "title", where, True),
        )
    return Transcription(equations, claims, names)


@functools.cache
def table():
    """The edition's transcription, :data:`TABLE` read once.

    Returns
    -------
    Transcription
    """
    return load(TABLE)


def printed(id):
    """The printed form of equation ``id``.

    Parameters
    ----------
    id : int or str
        Equation number, (1)-(65).

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
    eqs = table().equations
    if str(id) not in eqs:
        raise ValueError(f"equation ({id}) is not transcribed in {TABLE.name}")
    return eqs[str(id)]


def claim(slug):
    """The claim ``slug`` as quoted.

    Parameters
    ----------
    slug : str

    Returns
    -------
    Claim

    Raises
    ------
    ValueError
        If the claim is not transcribed.
    """
    claims = table().claims
    if slug not in claims:
        raise ValueError(f"claim {slug!r} is not transcribed in {TABLE.name}; known: {sorted(claims)}")
    return claims[slug]
