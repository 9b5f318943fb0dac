r"""What the seven experiments share: their outcome, how numbers are rounded, how a verdict is reached.

Every experiment puts wmr's kinematic prediction beside a MuJoCo measurement (:mod:`wmr.sim`) and
returns an :class:`Outcome`: the paper's claim, the prediction, the measurement, their agreement and
a **verdict** -- *holds*, *holds within* a stated error, or *does not hold* -- computed by
:func:`verdict` from the rounded numbers against the criterion the experiment states.  Every run
checks its own validity (:mod:`wmr.sim.validity`); an outcome carries the problems of its runs, and
:mod:`edition.physics.box` refuses a verdict from a run that has any.

Reproducibility: a physics engine's last bits differ between machines, and contact simulations can
amplify them, so every measurement that reaches a verdict or the table is rounded to
:data:`DIGITS` significant digits first (:func:`sig`); the verdict is computed from the rounded
values.  The robots are the paper's, at a realistic size (:func:`paper`), with the default physical
parameters of :class:`wmr.sim.Params` unless an experiment says otherwise.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

import wmr
from wmr.sim import Params

__all__ = [
    "DIGITS",
    "FAILS",
    "HOLDS",
    "INVALID",
    "RESOLVED",
    "SIZE",
    "WITHIN",
    "Outcome",
    "fmt",
    "fmt_above",
    "paper",
    "parameters",
    "pct",
    "relative_pose",
    "run_problems",
    "sig",
    "verdict",
]

#: significant digits of every measurement in a verdict or the table
DIGITS = 2
#: the three verdicts
HOLDS, WITHIN, FAILS = "holds", "holds within", "does not hold"
#: what a run with a validity problem gives instead of a verdict
INVALID = "invalid run"
#: what the measurements can resolve: MuJoCo's contacts are soft (a wheel held by static friction creeps)
#: and its servos compliant, so agreement to within 2 % is agreement
RESOLVED = 0.02
#: the size of the paper's robots here: mount points at L = 0.3 m from C, wheels of radius r = 0.05 m
SIZE = {"L": 0.3, "r": 0.05}


@dataclass(frozen=True)
class Outcome:
    """The result of one experiment: one row of ``physics.csv`` and the data of its figure.

    Attributes
    ----------
    key : str
        Short name, e.g. ``"dead-zone"``.
    title : str
        What is tested, in a few words.
    section : str
        Where the paper states the claim; for a prediction of this edition's own (not a claim of the
        paper), the chapter that makes it, starting ``"Chapter"``.
    claim : str
        The claim, in the paper's words where possible.
    prediction : str
        What wmr's kinematic model predicts (with numbers).
    measurement : str
        What MuJoCo measures (rounded numbers).
    agreement : str
        How far apart they are.
    verdict : str
        ``"holds"``, ``"holds within X %"`` or ``"does not hold"``, computed from the numbers.
    criterion : str
        The stated criterion of the verdict.
    parameters : str
        Robot, friction, servo and run parameters of the measurement.
    rests_on : str
        The modelling choice the verdict turns on (the contact model, a servo limit, an identity of linear
        algebra), in words: what a reader must accept for the verdict to stand.
    overturn : str
        What would overturn the verdict: the measurement, under another model or parameters, that would fail
        (or meet) the criterion.
    quote : str
        For a claim of the paper, its sentence as the paper prints it (Section :attr:`section`); empty for
        a prediction of this edition's own.
    problems : tuple of str
        The validity problems of the experiment's runs (:meth:`wmr.sim.Validity.problems`); any makes the
        run invalid, and no verdict is drawn from it (:mod:`edition.physics.box`).
    box : edition.physics.box.Box, optional
        The verdict over the parameter box (:func:`edition.physics.box.judge`); None for a single run.
    data : dict
        Arrays for the figure (not in the table).
    """

    key: str
    title: str
    section: str
    claim: str
    prediction: str
    measurement: str
    agreement: str
    verdict: str
    criterion: str
    parameters: str
    rests_on: str
    overturn: str
    quote: str = ""
    problems: tuple[str, ...] = ()
    box: Any = None
    data: dict = field(default_factory=dict, repr=False, compare=False)

    def __post_init__(self):
        for name in ("rests_on", "overturn"):
            if not str(getattr(self, name)).strip():
                raise ValueError(f"experiment {self.key!r}: {name} is empty (every verdict states what it rests on)")
        if self.whose == "paper" and not self.quote.strip():
            raise ValueError(f"experiment {self.key!r}: a claim of the paper quotes its sentence")

    @property
    def valid(self):
        """True when no run of the experiment had a validity problem."""
        return not self.problems

    @property
    def holds(self):
        """True when the verdict is *holds* or *holds within* (whatever the validity: see :attr:`valid`)."""
        return self.verdict.startswith(HOLDS)

    @property
    def whose(self):
        """``"paper"`` for a claim of the paper, ``"edition"`` for a prediction of this edition's own."""
        return "edition" if self.section.lower().startswith("chapter") else "paper"

    @property
    def nominal(self):
        """The verdict of this run with its criterion, or ``invalid run`` with its problems."""
        if not self.valid:
            return f"{INVALID} ({'; '.join(self.problems)})"
        return f"{self.verdict} ({self.criterion})"

    def row(self):
        """The row of ``physics.csv``: dict of str (the box's columns empty unless :attr:`box` is set)."""
        b = self.box
        return {
            "experiment": self.key,
            "claim": f"{self.claim} ({self.section})",
            "quote": f"“{self.quote}” (Section {self.section.split(',')[0]})" if self.quote else "",
            "prediction": self.prediction,
            "measurement": self.measurement,
            "agreement": self.agreement,
            "nominal": self.nominal,
            "verdict": self.nominal if b is None else f"{b.verdict} ({b.rule}; criterion: {self.criterion})",
            "box_fraction": "" if b is None else b.fraction_text,
            "box_holds": "" if b is None else f"{b.held} of {b.valid} valid runs",
            "box_invalid": "" if b is None else str(b.invalid),
            "flips": "" if b is None else b.flips,
            "box": "" if b is None else b.description,
            "parameters": self.parameters,
            "whose": self.whose,
            "rests_on": self.rests_on,
            "overturn": self.overturn,
        }


def sig(x, digits=DIGITS):
    """``x`` rounded to ``digits`` significant digits (a float; 0, inf and nan unchanged).

    Parameters
    ----------
    x : float
    digits : int, optional

    Returns
    -------
    float

    Examples
    --------
    >>> sig(0.012345), sig(-1234.5), sig(0.0)
    (0.012, -1200.0, 0.0)
    """
    x = float(x)
    if x == 0 or not np.isfinite(x):
        return x + 0.0
    return float(f"{x:.{digits - 1}e}") + 0.0


def fmt(x, digits=DIGITS):
    """A measurement as text, ``digits`` significant digits (plain, no exponent between 1e-4 and 1e5).

    Parameters
    ----------
    x : float
    digits : int, optional

    Returns
    -------
    str

    Examples
    --------
    >>> fmt(0.049373), fmt(12345.0), fmt(2.0), fmt(0.00001234)
    ('0.049', '12000', '2.0', '1.2e-05')
    """
    v = sig(x, digits)
    if v == 0:
        return "0"
    if not np.isfinite(v):
        return str(v)
    if 1e-4 <= abs(v) < 1e5:
        e = int(np.floor(np.log10(abs(v))))
        return f"{v:.{max(0, digits - 1 - e)}f}"
    return f"{v:.{digits - 1}e}"


def fmt_above(x, floor, digits=DIGITS):
    """``fmt(x)``, or a bound ``< floor`` when ``|x|`` is below ``floor`` (zero but for creep and round-off).

    Parameters
    ----------
    x : float
    floor : float
        The resolution of the measurement, > 0.
    digits : int, optional

    Returns
    -------
    str

    Examples
    --------
    >>> fmt_above(6.6e-05, 0.001), fmt_above(0.099, 0.001)
    ('< 0.001', '0.099')
    """
    return f"< {fmt(floor, 1)}" if abs(float(x)) < floor else fmt(x, digits)


def pct(x, digits=DIGITS):
    """A fraction as a percentage with ``digits`` significant digits: ``pct(0.0127) == "1.3 %"``.

    Parameters
    ----------
    x : float
    digits : int, optional

    Returns
    -------
    str
    """
    return f"{fmt(100 * x, digits)} %"


def verdict(error, exact, within):
    r"""The verdict of a quantitative claim from its relative error (rounded first).

    Parameters
    ----------
    error : float
        The measured relative error (a fraction), >= 0.
    exact : float
        Up to this error the claim **holds** (the model's prediction is met as well as the
        measurement can tell).
    within : float
        Up to this error it **holds within** the (rounded) measured error; beyond it, it **does
        not hold**.

    Returns
    -------
    str

    Examples
    --------
    >>> verdict(0.004, 0.01, 0.1), verdict(0.0127, 0.01, 0.1), verdict(0.3, 0.01, 0.1)
    ('holds', 'holds within 1.3 %', 'does not hold')
    """
    e = sig(error)
    if e <= exact:
        return HOLDS
    if e <= within:
        return f"{WITHIN} {pct(e)}"
    return FAILS


def paper(kind, **kw):
    """One of the paper's three-wheel robots at the size :data:`SIZE` (``d = r``, ``b = r`` unless given).

    Parameters
    ----------
    kind : {"offset", "centred", "dual"}
    **kw
        ``d`` or ``b`` for :func:`wmr.paper_robot`.

    Returns
    -------
    Robot
    """
    return wmr.paper_robot(kind, L=SIZE["L"], r=SIZE["r"], **kw)


def parameters(robot, params=None, **extra):
    """The parameters of a measurement as one line of text.

    Parameters
    ----------
    robot : Robot
    params : Params, optional
    **extra
        Further ``name=value`` pairs (the run's).

    Returns
    -------
    str
    """
    p = params or Params()
    units = ", ".join(sorted({type(u).__name__ for u in robot.wheels}))
    size = f"{robot.w} x {units}, |d_i| <= {fmt(float(np.abs(robot.mount_points).max()), 3)} m"
    phys = (
        f"mu = {p.sliding:g}, torsional = {p.torsional:g} r, rolling = {p.rolling:g}, "
        f"platform {p.platform_mass:g} kg, wheel {p.wheel_mass:g} kg, steer limit {p.steer_torque:g} W r, "
        f"drive limit {p.drive_torque:g} W r, step {p.timestep:g} s ({p.integrator}), {p.cone} cone, impratio "
        f"{p.impratio:g}, contact time {p.contact_time:g} s"
    )
    more = "; ".join(f"{k.replace('_', ' ')} {v}" for k, v in extra.items())
    return f"{size}; {phys}" + (f"; {more}" if more else "")


def run_problems(label, validity, saturating=()):
    """The validity problems of one run, each named after the run (:meth:`wmr.sim.Validity.problems`).

    Parameters
    ----------
    label : str
        The run's name in the experiment.
    validity : wmr.sim.Validity or wmr.sim.Recording
        The run's validity (a recording's, :attr:`wmr.sim.Recording.validity`).
    saturating : iterable of str
        Servos expected to sit at their torque limit (a stall that is the measurement).

    Returns
    -------
    tuple of str
    """
    v = getattr(validity, "validity", validity)
    return tuple(f"{label}: {p}" for p in v.problems(saturating))


def twist_text(twist):
    r"""A body twist in words: its turning rate and the velocity of C.

    Parameters
    ----------
    twist : triple
        :math:`(\dot\psi, \dot x, \dot y)`.

    Returns
    -------
    str

    Examples
    --------
    >>> twist_text((0.5, 0.2, 0.0))
    'turning at 0.5 rad/s, C at (0.2, 0) m/s (body frame)'
    """
    w, x, y = (float(v) for v in twist)
    return f"turning at {w:g} rad/s, C at ({x:g}, {y:g}) m/s (body frame)"


def relative_pose(pose, start):
    """Poses (psi, X, Y) seen from the pose ``start``: the frame of C at the start.

    Parameters
    ----------
    pose : array (N, 3)
    start : array (3,)

    Returns
    -------
    numpy.ndarray (N, 3)
    """
    c, s = np.cos(start[0]), np.sin(start[0])
    dx, dy = pose[:, 1] - start[1], pose[:, 2] - start[2]
    return np.column_stack([pose[:, 0] - start[0], c * dx + s * dy, -s * dx + c * dy])
