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

Experiments 1, 3, 4 and 5 test sentences the paper prints (each quoted with its section); 2, 6 and 7
test this edition's own models (the jam of Chapter 2, the near-tautological link between
:math:`\kappa(\mathbf J)` and the noise, Chapter 8's simulator) and are counted apart.  Every experiment
is judged over the parameter box of :mod:`edition.physics.box` (:func:`judge`): *holds*, *does not hold*
or *depends on the model*, and where it flips; a run that fails its validity checks gives no verdict.

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
from .box import DEPENDS, judge
from .common import FAILS, INVALID, Outcome
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
    "judge",
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
#: the columns of physics.csv (:meth:`Outcome.row`): ``nominal`` is the verdict at the nominal parameters,
#: ``verdict`` the verdict over the box (:mod:`edition.physics.box`), ``box_fraction`` the fraction of its valid
#: runs on which the claim holds, ``box_invalid`` its invalid runs, ``flips`` where it differs from the nominal run
COLUMNS = (
    "experiment",
    "claim",
    "quote",
    "prediction",
    "measurement",
    "agreement",
    "nominal",
    "verdict",
    "box_fraction",
    "box_holds",
    "box_invalid",
    "flips",
    "box",
    "parameters",
    "whose",
    "rests_on",
    "overturn",
)
#: arguments of an experiment at the box's points other than the nominal one (what only the figure needs is left out)
ELSEWHERE = {"brake_experiment": {"reference": False}}


def run(experiment, params=None):
    """One experiment judged over the parameter box (:func:`edition.physics.box.judge`).

    Parameters
    ----------
    experiment : callable
        One of :data:`EXPERIMENTS`.
    params : wmr.sim.Params, optional
        The nominal point (default :class:`wmr.sim.Params`).

    Returns
    -------
    Outcome
        The nominal run's, with the box's verdict (``outcome.box``).  While nbgrader grades chapter 9
        (:func:`edition.notebook.grading`) only the nominal point runs and the box is partial: no verdict.
    """
    from ..notebook import grading

    return judge(experiment, params, nominal_only=grading(), **ELSEWHERE.get(experiment.__name__, {}))


def run_all(params=None):
    """Run the seven experiments, each over the parameter box.

    Parameters
    ----------
    params : wmr.sim.Params, optional
        The nominal point (default :class:`wmr.sim.Params`).

    Returns
    -------
    list of Outcome
    """
    return [run(f, params) for f in EXPERIMENTS]


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
        ``{"paper": {"tested": n, "hold": k, "fail": f, "depends": m, "invalid": i}, "edition": {...}}``, by
        the verdict over the box (:mod:`edition.physics.box`): *holds*, *does not hold*, *depends on the
        model*, *invalid run*.

    Examples
    --------
    >>> t = tally([{"whose": "paper", "verdict": "holds (x)"}, {"whose": "edition", "verdict": "depends on the model"}])
    >>> t["paper"]
    {'tested': 1, 'hold': 1, 'fail': 0, 'depends': 0, 'invalid': 0}
    >>> t["edition"]["depends"]
    1
    """
    out = {}
    for whose in ("paper", "edition"):
        group = [r["verdict"] for r in rows if r["whose"] == whose]
        out[whose] = {
            "tested": len(group),
            "hold": sum(v.startswith("holds") for v in group),
            "fail": sum(v.startswith(FAILS) for v in group),
            "depends": sum(v.startswith(DEPENDS) for v in group),
            "invalid": sum(v.startswith(INVALID) for v in group),
        }
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
        Markdown: one paragraph of the box, its rule and the counts, and a table (experiment, whose claim,
        verdict over the box, on how many valid runs it holds, where it flips, what it rests on).  The finding cards
        (:func:`edition.cards.physics_card`) give the parameters and what would overturn each.
    """
    rows = read_csv(path)
    t = tally(rows)

    def cell(text):
        return text.replace("|", "\\|").replace("\n", " ")

    def counts(c):
        parts = [f"{c['hold']} {'holds' if c['hold'] == 1 else 'hold'} on the whole box"]
        parts.append(f"{c['fail']} {'does' if c['fail'] == 1 else 'do'} not hold on any of it")
        parts.append(f"{c['depends']} {'depends' if c['depends'] == 1 else 'depend'} on the model")
        if c["invalid"]:
            parts.append(f"{c['invalid']} had no valid run")
        return ", ".join(parts[:-1]) + " and " + parts[-1]

    p, e = t["paper"], t["edition"]
    head = (
        f"Chapter 9 runs {len(rows)} experiments in the physics engine MuJoCo, each over a box of physical "
        f"parameters ({rows[0]['box'] if rows else ''}); every run checks its own validity (energy, penetration, "
        "servo saturation and chatter, MuJoCo's warnings) and an invalid run gives no verdict. A verdict *holds* "
        "when the claim holds on every valid run of the box, *does not hold* when on none, and *depends on the "
        f"model* otherwise. Of the {p['tested']} claims of the paper tested there, {counts(p)}; of the "
        f"{e['tested']} predictions of this edition's own tested there (counted apart: not claims of the paper), "
        f"{counts(e)}. Every physics verdict rests on MuJoCo's contact model, unlike the kinematic verdicts, which "
        "are proven: the table says where each flips and what it turns on, and the finding cards give the "
        "parameters and what would overturn it.\n\n"
    )
    table = (
        "| Experiment | Whose claim | Verdict over the box | Holds on | Where it flips | What it rests on |\n"
        "|---|---|---|---|---|---|\n"
    ) + "".join(
        f"| {r['experiment'].replace('-', ' ')} | {'the paper' if r['whose'] == 'paper' else 'this edition'} | "
        f"{r['verdict'].split(' (')[0]} | {r['box_holds']}, {r['box_invalid']} invalid | {cell(r['flips'])} | "
        f"{cell(r['rests_on'])} |\n"
        for r in rows
    )
    return head + table
