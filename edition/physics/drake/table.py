r"""The engines side by side: ``engines.csv``, one row per experiment, engine and contact model.

Chapter 9 runs four experiments in Drake (:mod:`edition.physics.drake.experiments`) beside their MuJoCo runs
(:mod:`edition.physics`); :func:`rows` puts the nominal MuJoCo outcome of each beside Drake's results with point and
hydroelastic contact, :func:`write_csv` writes them (the build publishes the file into ``figures/`` as it does
``physics.csv``), and :func:`engines_markdown` turns the published file into the report's paragraph and table:
which verdicts agree across the engines and contact models, and which depend on them.  Every number in the file
is rounded as ``physics.csv``'s are (two significant digits, :mod:`edition.physics.common`), so that the file is
the same on every machine.
"""

from __future__ import annotations

import csv
from importlib.metadata import version
from pathlib import Path

from ... import files
from ..common import INVALID, fmt
from .experiments import BRAKE_DIRECTIONS, brake, dead_zone, dual_wheel, jam
from .model import DISSIPATION, MODULI, SINK, STEP, WIDTH, resolution

__all__ = [
    "EXPERIMENTS",
    "ENGINE_COLUMNS",
    "agreement",
    "available",
    "engines_markdown",
    "read_csv",
    "rows",
    "run_all",
    "write_csv",
]

#: the experiments run in both engines (``physics.csv``'s keys), in the table's order
EXPERIMENTS = ("dead-zone", "jam", "braking", "dual-wheel")
#: the columns of engines.csv
ENGINE_COLUMNS = ("experiment", "engine", "contact", "measurement", "verdict", "criterion", "parameters")


def available():
    """Whether Drake (``pydrake``) is installed: the edition's extra brings it; a student's package need not.

    Returns
    -------
    bool
    """
    import importlib.util

    return importlib.util.find_spec("pydrake") is not None


def run_all(params=None, clock=None):
    """Every Drake run of the table: each experiment with point and hydroelastic contact, the dual wheel at two moduli.

    Parameters
    ----------
    params : wmr.sim.Params, optional
    clock : callable, optional
        ``clock() -> float`` (e.g. :func:`time.process_time`), or any readings that subtract (an array of a wall
        and a CPU clock): each run is timed with it, the first including Drake's import.

    Returns
    -------
    list of tuple (Result, float)
        Each result with its time by ``clock`` (0 without one); the first dual-wheel run includes the point-contact
        runs the second reuses.
    """
    out = []

    def timed(f, *args, **kw):
        t0 = clock() if clock else 0.0
        r = f(*args, params=params, **kw)
        out.append((r, (clock() - t0) if clock else 0.0))
        return r

    for f in (dead_zone, jam, brake):
        for contact in ("point", "hydroelastic"):
            timed(f, contact, MODULI[0])
    t0 = clock() if clock else 0.0
    first, point = dual_wheel(MODULI[0], params=params)
    out.append((first, (clock() - t0) if clock else 0.0))
    for modulus in MODULI[1:]:
        t0 = clock() if clock else 0.0
        r, _ = dual_wheel(modulus, params=params, point=point)
        out.append((r, (clock() - t0) if clock else 0.0))
    return out


def _verdict(text):
    """The verdict without its criterion: ``holds``, ``holds within x %``, ``does not hold`` or ``invalid run (...)``."""
    return text if text.startswith(INVALID) else text.split(" (")[0]


def drake_parameters(key, contact, modulus, params=None):
    """The parameters of a Drake row, in words.

    Parameters
    ----------
    key : str
        The experiment.
    contact : str
        ``"point"`` or ``"hydroelastic"``.
    modulus : float
    params : wmr.sim.Params, optional

    Returns
    -------
    str
    """
    from wmr.sim import Params

    p = params or Params()
    model = (
        f"rigid spheres of the wheel radius, stiffness (W/3)/({SINK:g} r)"
        if contact == "point"
        else f"compliant cylinders of width {WIDTH:g} r, hydroelastic modulus {fmt(modulus)} Pa, resolution hint "
        f"{fmt(resolution(modulus, 1.0))} r, on a rigid half space"
    )
    common = (
        f"Drake {version('drake')}, SAP, step {STEP * 1000:g} ms; {model}; Hunt-Crossley dissipation {DISSIPATION:g} "
        f"s/m; mu_s = mu_d = {p.sliding:g}; no torsional coefficient, no rolling resistance; platform "
        f"{p.platform_mass:g} kg, bodies {p.body_mass:g} kg, wheels {p.wheel_mass:g} kg; servos (implicit PD) limited "
        f"to {p.steer_torque:g} W r (steering) and {p.drive_torque:g} W r (drive), gains {p.steer_kp:g} and "
        f"{p.drive_kv:g} limits per rad and per rad/s, damping ratio {p.steer_damping:g}"
    )
    if key == "braking":
        common += f"; pushes in {len(BRAKE_DIRECTIONS)} directions ({', '.join(map(str, BRAKE_DIRECTIONS))} deg)"
    if key == "dual-wheel":
        common += "; the spin-resisting part: hydroelastic minus point contact"
    return common


def rows(outcomes, results, params=None):
    """The rows of ``engines.csv``: per experiment the MuJoCo outcome, then the Drake results.

    Parameters
    ----------
    outcomes : list of Outcome
        Chapter 9's MuJoCo outcomes (at least those of :data:`EXPERIMENTS`).
    results : list of Result or of (Result, float)
        The Drake results (:func:`run_all`).
    params : wmr.sim.Params, optional

    Returns
    -------
    list of dict
        Keyed by :data:`ENGINE_COLUMNS`.
    """
    import mujoco

    from wmr.sim import Params

    p = params or Params()
    by_key = {o.key: o for o in outcomes}
    drake = [r[0] if isinstance(r, tuple) else r for r in results]
    out = []
    for key in EXPERIMENTS:
        o = by_key[key]
        out.append(
            {
                "experiment": key,
                "engine": f"MuJoCo {mujoco.__version__}",
                "contact": f"point, soft (contact time {p.contact_time:g} s, impratio {p.impratio:g}), {p.cone} cone, "
                f"torsional {p.torsional:g} r, rolling {p.rolling:g}",
                "measurement": o.measurement,
                "verdict": _verdict(o.nominal),
                "criterion": o.criterion,
                "parameters": o.parameters,
            }
        )
        for r in (r for r in drake if r.key == key):
            contact, modulus = r.data["model"]
            out.append(
                {
                    "experiment": key,
                    "engine": f"Drake {version('drake')}",
                    "contact": r.contact,
                    "measurement": r.measurement,
                    "verdict": _verdict(r.verdict),
                    "criterion": o.criterion,
                    "parameters": drake_parameters(key, contact, modulus, p),
                }
            )
    return out


def write_csv(table, path):
    """Write ``engines.csv`` (RFC 4180 quoting, ``\\n`` line ends).

    Parameters
    ----------
    table : list of dict
        :func:`rows`.
    path : path-like

    Returns
    -------
    pathlib.Path
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(files.csv_text(table, ENGINE_COLUMNS), encoding="utf-8")
    return path


def read_csv(path):
    """The rows of an ``engines.csv``.

    Parameters
    ----------
    path : path-like

    Returns
    -------
    list of dict

    Raises
    ------
    ValueError
        If the header is not :data:`ENGINE_COLUMNS`.
    """
    path = Path(path)
    with path.open(newline="", encoding="utf-8") as f:
        out = list(csv.DictReader(f))
    if not out or tuple(out[0]) != ENGINE_COLUMNS:
        raise ValueError(f"{path}: not an engines.csv (columns {ENGINE_COLUMNS})")
    return out


def agreement(table):
    """Per experiment: do the valid verdicts of every engine and contact model agree?

    Parameters
    ----------
    table : list of dict
        Rows of ``engines.csv``.

    Returns
    -------
    dict
        Experiment -> ``"agree: <verdict>"``, ``"depends on the engine or contact: ..."`` or ``"no valid run"``.

    Examples
    --------
    >>> agreement([{"experiment": "x", "verdict": "holds"}, {"experiment": "x", "verdict": "holds within 3 %"}])
    {'x': 'agree: holds'}
    """
    out = {}
    for key in dict.fromkeys(r["experiment"] for r in table):
        valid = [r["verdict"] for r in table if r["experiment"] == key and not r["verdict"].startswith(INVALID)]
        kinds = {("holds" if v.startswith("holds") else v) for v in valid}
        if not kinds:
            out[key] = "no valid run"
        elif len(kinds) == 1:
            out[key] = f"agree: {kinds.pop()}"
        else:
            out[key] = "depends on the engine or contact: " + "; ".join(
                f"{r['engine'].split()[0]} {r['contact'].split(',')[0]}: {r['verdict']}"
                for r in table
                if r["experiment"] == key
            )
    return out


def engines_markdown(path):
    """Part I's second engine: a paragraph and the table of ``engines.csv``.

    Parameters
    ----------
    path : path-like
        ``figures/engines.csv``.

    Returns
    -------
    str
        Markdown.
    """
    table = read_csv(path)
    agree = agreement(table)
    same = [k for k, v in agree.items() if v.startswith("agree")]
    differ = [k for k, v in agree.items() if not v.startswith("agree")]

    def cell(text):
        return text.replace("|", "\\|").replace("\n", " ")

    head = (
        f"Four of the physics experiments were also run in a second engine, Drake, from the same robots, with point "
        f"contact and with hydroelastic contact (compliant wheels whose contact is a patch), at the nominal "
        f"parameters only. The verdicts agree across the engines and contact models for "
        f"{', '.join(k.replace('-', ' ') for k in same) or 'none'}"
        + (f", and differ for {', '.join(k.replace('-', ' ') for k in differ)}" if differ else "")
        + "."
        + "".join(f" {k.replace('-', ' ').capitalize()}: {v}." for k, v in agree.items() if k in differ)
        + " The dual wheel in Drake: "
        + "; ".join(
            f"{r['contact']}: {r['verdict']} ({r['measurement'].split('; ')[-1]})"
            for r in table
            if r["experiment"] == "dual-wheel" and r["engine"].startswith("Drake")
        )
        + ".\n\n"
    )
    body = "| Experiment | Engine | Contact | Verdict | Measurement |\n|---|---|---|---|---|\n" + "".join(
        f"| {r['experiment'].replace('-', ' ')} | {r['engine']} | {cell(r['contact'])} | {cell(r['verdict'])} | "
        f"{cell(r['measurement'])} |\n"
        for r in table
    )
    return head + body
