r"""The paper's physical claims in a physics engine: seven experiments, each a prediction beside a measurement.

Every verdict elsewhere in the edition is computed inside the paper's own model (rigid bodies, point
contacts, no slip).  The paper also says how a real robot behaves -- it drifts, jams, brakes, meets
friction torques, amplifies noise -- which that model cannot test.  Here each claim is put to MuJoCo
through :mod:`wmr.sim`, beside what wmr's kinematics predicts, and judged by a stated criterion
(:mod:`edition.physics.common`):

==  ==================================  =============================================  ==========================
#   experiment                          claim (paper)                                  module
==  ==================================  =============================================  ==========================
1   :func:`dead_zone_experiment`        the dead zone, Fig. 7, (28)-(29)               :mod:`~edition.physics.drift`
2   :func:`jam_experiment`              locked drives at generic angles jam            :mod:`~edition.physics.drift`
3   :func:`steering_experiment`         incompatible steering skids                    :mod:`~edition.physics.contact`
4   :func:`brake_experiment`            Fig. 12a "can be exploited for braking"        :mod:`~edition.physics.contact`
5   :func:`reorient_experiment`         dual wheels meet only rolling friction         :mod:`~edition.physics.friction`
6   :func:`noise_experiment`            the error follows :math:`\kappa(\mathbf J)`    :mod:`~edition.physics.noise`
7   :func:`resteer_experiment`          chapter 8's re-steering transients             :mod:`~edition.physics.resteer`
==  ==================================  =============================================  ==========================

:func:`run_all` runs them; :func:`write_csv` writes ``physics.csv``, one row per experiment with the
columns :data:`COLUMNS` (chapter 9 writes it, the build publishes it into ``figures/``), and
:func:`findings_markdown` turns the published file into the report's findings section;
:mod:`edition.physics.plot` draws the experiments; :mod:`edition.physics.exercises` holds chapter 9's
exercises.
"""

from __future__ import annotations

import csv
from pathlib import Path

from .. import files
from .common import Outcome
from .contact import brake_experiment, steering_experiment
from .drift import dead_zone_experiment, jam_experiment
from .friction import reorient_experiment
from .noise import noise_experiment
from .resteer import resteer_experiment

__all__ = [
    "COLUMNS",
    "EXPERIMENTS",
    "Outcome",
    "csv_text",
    "findings_markdown",
    "read_csv",
    "run_all",
    "tally",
    "write_csv",
]

#: the experiments, in the order of the chapter and the table
EXPERIMENTS = (
    dead_zone_experiment,
    jam_experiment,
    steering_experiment,
    brake_experiment,
    reorient_experiment,
    noise_experiment,
    resteer_experiment,
)
#: the columns of physics.csv
COLUMNS = (
    "experiment",
    "claim",
    "prediction",
    "measurement",
    "agreement",
    "verdict",
    "parameters",
    "whose",
    "rests_on",
    "overturn",
)


def run_all(params=None):
    """Run the seven experiments.

    Parameters
    ----------
    params : wmr.sim.Params, optional
        Physical parameters (default :class:`wmr.sim.Params`).

    Returns
    -------
    list of Outcome
    """
    return [f(params) for f in EXPERIMENTS]


def csv_text(outcomes):
    """``physics.csv`` as text: a header and one row per outcome (RFC 4180 quoting, ``\\n`` line ends).

    Parameters
    ----------
    outcomes : list of Outcome

    Returns
    -------
    str
    """
    return files.csv_text([o.row() for o in outcomes], COLUMNS)


def write_csv(outcomes, path):
    """Write ``physics.csv``.

    Parameters
    ----------
    outcomes : list of Outcome
    path : path-like

    Returns
    -------
    pathlib.Path
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(csv_text(outcomes), encoding="utf-8")
    return path


def read_csv(path):
    """The rows of a ``physics.csv``.

    Parameters
    ----------
    path : path-like

    Returns
    -------
    list of dict
        One per experiment, keyed by :data:`COLUMNS`.

    Raises
    ------
    ValueError
        If the file's header is not :data:`COLUMNS`.
    """
    path = Path(path)
    with path.open(newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    if not rows or tuple(rows[0]) != COLUMNS:
        raise ValueError(f"{path}: not a physics.csv (columns {COLUMNS}), got {tuple(rows[0]) if rows else 'no rows'}")
    return rows


def tally(rows):
    """The physics verdicts counted apart: the paper's claims and this edition's own predictions.

    Parameters
    ----------
    rows : list of dict
        Rows of ``physics.csv`` (:func:`read_csv`).

    Returns
    -------
    dict
        ``{"paper": {"tested": n, "hold": k, "fail": n - k}, "edition": {...}}``; a verdict *holds within*
        its error counts as holding.

    Examples
    --------
    >>> tally([{"whose": "paper", "verdict": "holds (x)"}, {"whose": "edition", "verdict": "does not hold (y)"}])
    {'paper': {'tested': 1, 'hold': 1, 'fail': 0}, 'edition': {'tested': 1, 'hold': 0, 'fail': 1}}
    """
    out = {}
    for whose in ("paper", "edition"):
        group = [r for r in rows if r["whose"] == whose]
        held = sum(r["verdict"].startswith("holds") for r in group)
        out[whose] = {"tested": len(group), "hold": held, "fail": len(group) - held}
    return out


def findings_markdown(path):
    """Part I's physics verdicts: the counts, the paper's claims and this edition's own apart, and a table.

    Parameters
    ----------
    path : path-like
        ``figures/physics.csv``.

    Returns
    -------
    str
        Markdown: one paragraph of counts and of what every physics verdict rests on, and a table (experiment,
        whose claim, verdict with its criterion, what the verdict rests on).  The finding cards
        (:func:`edition.cards.physics_card`) give the parameters and what would overturn each.
    """
    rows = read_csv(path)
    t = tally(rows)

    def cell(text):
        return text.replace("|", "\\|").replace("\n", " ")

    def verb(n):
        return "holds" if n == 1 else "hold"

    p, e = t["paper"], t["edition"]
    head = (
        f"Chapter 9 runs {len(rows)} experiments in the physics engine MuJoCo. Of the {p['tested']} claims of the "
        f"paper tested there, {p['hold']} {verb(p['hold'])} and {p['fail']} {'does' if p['fail'] == 1 else 'do'} "
        f"not; of the {e['tested']} predictions of this edition's own tested there (counted apart: not claims of "
        f"the paper), {e['hold']} {verb(e['hold'])} and {e['fail']} {'does' if e['fail'] == 1 else 'do'} not. "
        "Every physics verdict rests on MuJoCo's contact model and on the parameters of its run, unlike the "
        "kinematic verdicts, which are proven: the table says what each turns on, and the finding cards give the "
        "parameters and what would overturn it.\n\n"
    )
    table = "| Experiment | Whose claim | Verdict | What it rests on |\n|---|---|---|---|\n" + "".join(
        f"| {r['experiment'].replace('-', ' ')} | "
        f"{'the paper' if r['whose'] == 'paper' else 'this edition'} | {cell(r['verdict'])} | {cell(r['rests_on'])} |\n"
        for r in rows
    )
    return head + table
