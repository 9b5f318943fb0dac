r"""What Part I of the report states that no chapter's ledger row says: computed here, shown by the findings chapter.

The findings chapter (``notebooks/findings.ipynb``) reads the ledger and the figures the chapters wrote
into ``figures/``; this module adds what it computes itself:

- :func:`equation_count`: how many equations the paper numbers, from the transcription
  (``edition/printed.toml``), and which of them the ledger judges;
- :func:`readings`: the verdicts that rest on a reading of the extracted text (the transcription's ``doubt``);
- :data:`INFERRED`: the verdicts that rest on a convention the paper's text does not state;
- :func:`environment` and :func:`citation`: the apparatus (versions, licence, BibTeX).
"""

from __future__ import annotations

import importlib.metadata as md
import platform
from pathlib import Path

__all__ = [
    "INFERRED",
    "DISTRIBUTIONS",
    "PROGRAMS",
    "LICENCES",
    "RESCIENCE",
    "COMMIT",
    "YEAR",
    "equation_count",
    "readings",
    "environment",
    "citation",
]

#: Stamped by the build (edition.report_cells.stamp): the commit and its year, which
#: the findings chapter cannot know when it is executed (it is not executed again for a new commit).
COMMIT, YEAR = "@COMMIT@", "@YEAR@"  # edition.report_cells.STAMPS

#: Equations whose verdict holds under a convention the paper's text leaves open, and what was inferred
#: (the ledger's ``convention`` column states the convention itself).  Facts about the text, not verdicts.
INFERRED = {
    "9": "the side of the wheel centre $H_i$ relative to the pivot $P_i$ (the text does not state it; Fig. 4 is "
    "missing from the extraction): inferred from the printed signs",
    "59": "the numbering and placement of the wheels: inferred from the printed determinant, which holds for one "
    "of the 24 numberings tried (wheel 1 at $180^\\circ$, numbered clockwise)",
    "60": "what $\\phi_i$ measures: the axle by (6), (8) and (11), the rolling direction if (60) is to hold",
    "65": "where $\\beta_i$ is measured from: the body axis $\\mathbf i$ by (11); the line $CU$ if (65) is to hold",
}

#: Distributions whose versions the report states, in this order (the first two are the edition's package).
DISTRIBUTIONS = (
    "wmr-kinematics",
    "wmr",
    "numpy",
    "sympy",
    "matplotlib",
    "nbclient",
    "nbconvert",
    "mujoco",
    "drake",
    "robotpy-wpimath",
)
#: Programs outside Python whose versions the report states: name -> (command, the line of its output to keep)
PROGRAMS = {"pandoc": ("pandoc", "--version"), "TeX (xelatex)": ("xelatex", "--version")}
#: What the edition's parts are licensed under: the code (the package and the build) and the text and figures
LICENCES = {"code": "MIT", "text and figures": "CC BY 4.0"}
#: The ReScience initiative, whose replications the reproduction summary follows
RESCIENCE = (
    "N. P. Rougier et al. (2017). Sustainable computational science: the ReScience initiative. "
    "*PeerJ Computer Science* 3, e142. doi:10.7717/peerj-cs.142."
)


def equation_count(ledger, transcription=None):
    """How many equations the paper numbers, and which the ledger judges.

    The paper numbers its equations from (1) on; the highest number transcribed in ``printed.toml`` is
    the last.

    Parameters
    ----------
    ledger : list of dict
        Rows of ``figures/ledger.csv``.
    transcription : Transcription, optional
        Default :func:`edition.transcription.table`.

    Returns
    -------
    dict
        ``numbered`` (int), ``transcribed``, ``judged``, ``not_judged``, ``not_transcribed`` (sorted lists of int).
    """
    from .transcription import table

    tr = table() if transcription is None else transcription
    transcribed = sorted(int(k) for k in tr.equations)
    judged = sorted(int(r["id"]) for r in ledger if r["kind"] == "equation")
    numbered = max(transcribed + judged)
    return {
        "numbered": numbered,
        "transcribed": transcribed,
        "judged": judged,
        "not_judged": sorted(set(range(1, numbered + 1)) - set(judged)),
        "not_transcribed": sorted(set(range(1, numbered + 1)) - set(transcribed)),
    }


def readings(transcription=None):
    """The equations whose verdict rests on a reading of the extracted text, and the reading.

    Parameters
    ----------
    transcription : Transcription, optional
        Default :func:`edition.transcription.table`.

    Returns
    -------
    dict str -> str
        Equation number -> the transcription's ``doubt`` (what the extraction shows and how it is read).
    """
    from .transcription import table

    tr = table() if transcription is None else transcription
    return {k: e.doubt for k, e in sorted(tr.equations.items(), key=lambda kv: int(kv[0])) if e.doubt}


def _version(name):
    try:
        return md.version(name)
    except md.PackageNotFoundError:
        return ""


def environment():
    """The versions the report was computed with (pinned by ``environment.lock``: the same on every build).

    Returns
    -------
    dict str -> str
        ``Python`` and each installed distribution of :data:`DISTRIBUTIONS`.
    """
    out = {"Python": platform.python_version()}
    for name in DISTRIBUTIONS:
        if (v := _version(name)) and not (name == "wmr" and "wmr-kinematics" in out):
            out[name] = v
    for name, command in PROGRAMS.items():
        if v := _program(command):
            out[name] = v
    out["operating system"] = _os()
    return out


def _program(command):
    """The first line a program prints for ``--version``, or ``""`` when it is not installed."""
    import shutil
    import subprocess

    if not shutil.which(command[0]):
        return ""
    try:
        done = subprocess.run(list(command), capture_output=True, text=True, timeout=30, check=False)
    except (OSError, subprocess.SubprocessError):
        return ""
    return (done.stdout.strip().splitlines() or [""])[0].strip()


def _os():
    """The operating system: its release name (``/etc/os-release``) and kind (not the kernel's release, which
    differs from machine to machine of one kind and would make two builds of one commit differ)."""
    try:
        name = platform.freedesktop_os_release().get("PRETTY_NAME", "")
    except OSError:
        name = ""
    return ", ".join(filter(None, (name, f"{platform.system()} {platform.machine()}")))


def _package():
    """(distribution name, version, licence) of the edition's package."""
    for name in DISTRIBUTIONS[:2]:
        if v := _version(name):
            meta = md.metadata(name)
            lic = (meta.get_all("License-Expression") or meta.get_all("License") or [""])[0]
            return name, v, lic
    return "wmr", "", ""


def citation(root=None):
    """How to cite this edition: a BibTeX entry, from ``CITATION.cff`` when the repository has one.

    Parameters
    ----------
    root : path-like, optional
        The repository (default: the parent of this package).

    Returns
    -------
    dict
        ``name``, ``version``, ``licence``, ``title``, ``authors``, ``cff`` (bool: read from CITATION.cff),
        ``bibtex`` (str).
    """
    name, version, lic = _package()
    title = "wmr: kinematics of wheeled mobile robots, and an executable edition of Leow, Low & Loh (2002)"
    authors = "the wmr contributors"
    path = Path(root if root is not None else Path(__file__).resolve().parents[1]) / "CITATION.cff"
    cff = path.exists()
    if cff:
        import yaml  # type: ignore[import-untyped]

        meta = yaml.safe_load(path.read_text(encoding="utf-8")) or {}
        title = " ".join(str(meta.get("title", title)).split())
        names = [
            a.get("name") or " ".join(filter(None, (a.get("given-names"), a.get("family-names"))))
            for a in meta.get("authors", [])
        ]
        authors = " and ".join(n for n in names if n) or authors
        lic = str(meta.get("license", lic))
        version = str(meta.get("version", version))
    import textwrap

    url = _repository(path.parent)
    licence = "; ".join(f"{v} ({k})" for k, v in LICENCES.items())
    wrapped = "\n".join(textwrap.wrap(title, 58, subsequent_indent=" " * 13))
    bib = (
        f"@software{{wmr_edition,\n  title   = {{{wrapped}}},\n  author  = {{{{{authors}}}}},\n"
        f"  year    = {{{YEAR}}},\n  version = {{{version}}},\n  commit  = {{{COMMIT}}},\n"
        + (f"  url     = {{{url}}},\n" if url else "")
        + f"  license = {{{licence}}},\n  note    = {{{name}}}\n}}"
    )
    return {
        "name": name,
        "version": version,
        "licence": lic,
        "licences": dict(LICENCES),
        "title": title,
        "authors": authors,
        "url": url,
        "cff": cff,
        "bibtex": bib,
    }


def _repository(root):
    """The repository's public address: ``repository-code`` of CITATION.cff or a URL of pyproject's
    ``[project.urls]``; ``""`` when the project states none."""
    import tomllib

    cff = Path(root) / "CITATION.cff"
    if cff.exists():
        import yaml

        meta = yaml.safe_load(cff.read_text(encoding="utf-8")) or {}
        if meta.get("repository-code") or meta.get("url"):
            return str(meta.get("repository-code") or meta.get("url"))
    pyproject = Path(root) / "pyproject.toml"
    if pyproject.exists():
        urls = tomllib.loads(pyproject.read_text(encoding="utf-8")).get("project", {}).get("urls", {})
        for key in ("Source", "Repository", "Homepage"):
            if urls.get(key):
                return str(urls[key])
    return ""
