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

__all__ = ["COLUMNS", "EXPERIMENTS", "Outcome", "csv_text", "run_all", "write_csv"]

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
COLUMNS = ("experiment", "claim", "prediction", "measurement", "agreement", "verdict", "parameters")


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


def findings_markdown(path):
    """The report's findings on the physical claims: a Markdown section made from a published ``physics.csv``.

    Parameters
    ----------
    path : path-like
        ``figures/physics.csv``.

    Returns
    -------
    str
        A heading, one sentence of counts and a table (claim, verdict and criterion, prediction, measurement).
    """
    rows = read_csv(path)
    fails = [r for r in rows if r["verdict"].startswith("does not hold")]

    def cell(text):
        return text.replace("|", "\\|").replace("\n", " ")

    head = (
        f"# Physical claims in a physics engine\n\nChapter 9 puts {len(rows)} of the paper's claims about real "
        f"robots to MuJoCo: {len(rows) - len(fails)} hold, {len(fails)} do not "
        f"({', '.join(r['experiment'] for r in fails) or 'none'}).\n\n"
    )
    table = "| claim | verdict | prediction (wmr) | measurement (MuJoCo) |\n|---|---|---|---|\n" + "".join(
        f"| {cell(r['claim'])} | {cell(r['verdict'])} | {cell(r['prediction'])} | {cell(r['measurement'])} |\n"
        for r in rows
    )
    return head + table
