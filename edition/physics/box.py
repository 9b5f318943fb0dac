r"""Verdicts that survive their parameters: every experiment judged over a stated box of physical parameters.

One run of a physics engine judges a claim under one set of parameters, and a contact model has many
(time step, integrator, friction cone and coefficient, impratio, contact stiffness, masses, actuator
limits) that nothing in the paper fixes.  A verdict that flips when one of them moves to another
reasonable value is the model's, not the robot's.  So every experiment is run over the **box**
:data:`BOX`: the nominal point (:class:`wmr.sim.Params`) and, one factor at a time, each parameter moved
to each of its stated values (numbers as factors of the nominal value, so that the box moves with it).

Every run checks its own validity (:mod:`wmr.sim.validity`: energy, penetration, servo saturation and
chatter, MuJoCo's warnings, divergence); a run with a problem is **invalid** and gives no verdict.  Over
the valid runs the **rule** (:func:`rule`) is:

* *holds* if the experiment's verdict holds on every valid run of the box (*holds within* its stated error
  counts as holding),
* *does not hold* if it holds on none,
* *depends on the model* otherwise, and the table says where it flips (which parameter, which value);
* *invalid run* if no run of the box is valid.

:func:`judge` runs one experiment over the box and returns its nominal :class:`~edition.physics.common.Outcome`
with the :class:`Box` attached.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from wmr.sim import Params

from .common import FAILS, HOLDS, INVALID

__all__ = ["BOX", "CHECKS", "DEPENDS", "Box", "describe", "judge", "points", "rule"]

#: the verdict of an experiment that holds on part of the box only
DEPENDS = "depends on the model"
#: the box, one factor at a time: parameter -> its values (a factor of the nominal value, or a MuJoCo option);
#: ``actuators`` scales both torque limits, of the steering and of the drive servos
BOX: dict[str, tuple[float | str, ...]] = {
    "timestep": (2.0,),
    "integrator": ("Euler",),
    "cone": ("pyramidal",),
    "sliding": (0.5, 1.5),
    "impratio": (0.01,),
    "contact_time": (4.0,),
    "platform_mass": (2.0,),
    "actuators": (0.5, 2.0),
}


def points(params=None):
    """The points of the box: the nominal point first, then each parameter at each of its values.

    Parameters
    ----------
    params : wmr.sim.Params, optional
        The nominal point (default :class:`wmr.sim.Params`).

    Returns
    -------
    list of tuple
        ``(parameter, value as text, Params)``; the nominal point is ``("nominal", "", params)``.

    Examples
    --------
    >>> [(name, value) for name, value, _ in points()][:4]
    [('nominal', ''), ('timestep', '0.002 s'), ('integrator', 'Euler'), ('cone', 'pyramidal')]
    """
    p = params or Params()
    units = {"timestep": " s", "contact_time": " s", "platform_mass": " kg"}
    out = [("nominal", "", p)]
    for name, values in BOX.items():
        for v in values:
            if isinstance(v, str):
                out.append((name, v, p.replace(**{name: v})))
            elif name == "actuators":
                q = p.replace(steer_torque=p.steer_torque * float(v), drive_torque=p.drive_torque * float(v))
                out.append((name, f"x {v:g} (steer {q.steer_torque:g}, drive {q.drive_torque:g} W r)", q))
            else:
                q = p.replace(**{name: getattr(p, name) * float(v)})
                out.append((name, f"{getattr(q, name):g}{units.get(name, '')}", q))
    return out


def describe(params=None):
    """The box in words (the ``box`` column of ``physics.csv``).

    Parameters
    ----------
    params : wmr.sim.Params, optional

    Returns
    -------
    str
    """
    rest = "; ".join(f"{name} {value}" for name, value, _ in points(params)[1:])
    return f"the nominal point and, one at a time: {rest}"


def rule(held, valid):
    """The verdict over the box from the number of valid runs and of those on which the claim holds.

    Parameters
    ----------
    held, valid : int

    Returns
    -------
    str

    Examples
    --------
    >>> rule(3, 3), rule(0, 3), rule(2, 3), rule(0, 0)
    ('holds', 'does not hold', 'depends on the model', 'invalid run')
    """
    if valid == 0:
        return INVALID
    return HOLDS if held == valid else FAILS if held == 0 else DEPENDS


@dataclass(frozen=True)
class Box:
    """The verdict of one experiment over the box.

    Attributes
    ----------
    runs : tuple of tuple
        ``(parameter, value, status)`` per point of the box; status ``"holds"``, ``"does not hold"`` or
        ``"invalid run (<the checks it failed>)"``.
    description : str
        The box in words (:func:`describe`).
    partial : bool
        Only the nominal point was run (while nbgrader grades chapter 9: :func:`edition.notebook.grading`); then
        there is no verdict over the box.
    """

    runs: tuple[tuple[str, str, str], ...]
    description: str
    partial: bool = False

    @property
    def valid(self):
        """Valid runs: int."""
        return sum(not s.startswith(INVALID) for *_, s in self.runs)

    @property
    def held(self):
        """Valid runs on which the verdict holds: int."""
        return sum(s == HOLDS for *_, s in self.runs)

    @property
    def invalid(self):
        """Invalid runs: int."""
        return len(self.runs) - self.valid

    @property
    def verdict(self):
        """The verdict over the box by :func:`rule`, or, for a partial box, that there is none: str."""
        if self.partial:
            return f"not judged over the box (the nominal run only: {self.runs[0][2]})"
        return rule(self.held, self.valid)

    @property
    def rule(self):
        """The rule and the count, in words: str."""
        if self.partial:
            return "the box was not run: no verdict over it"
        return (
            f"holds on {self.held} of the {self.valid} valid runs of the box of {len(self.runs)}, "
            f"{self.invalid} invalid; holds: on all, does not hold: on none, else depends on the model"
        )

    @property
    def fraction_text(self):
        """The fraction of the valid runs on which it holds, two digits (empty with no valid run): str."""
        return f"{self.held / self.valid:.2f}" if self.valid and not self.partial else ""

    @property
    def flips(self):
        """Where the verdict differs from the nominal run's (or the run is invalid), in words: str."""
        nominal = self.runs[0][2]
        if self.partial:
            return "not run (the nominal point only)"
        other = [f"{name} {value}: {s}" for name, value, s in self.runs[1:] if s != nominal]
        return "; ".join(other) if other else f"nowhere (every run: {nominal})"


#: the checks a problem of :meth:`wmr.sim.Validity.problems` belongs to, by a word of its text
CHECKS = (
    ("diverged", "divergence"),
    ("warned", "MuJoCo's warnings"),
    ("energy", "energy"),
    ("sank", "penetration"),
    ("torque limit", "servo saturation"),
    ("chattered", "servo chatter"),
)


def _status(o):
    """The status of one run: holds, does not hold, or invalid with the checks it failed."""
    if not o.valid:
        failed = [name for word, name in CHECKS if any(word in p for p in o.problems)]
        return f"{INVALID} ({', '.join(failed or ['a check'])})"
    return HOLDS if o.holds else FAILS


def judge(experiment, params=None, nominal_only=False, **elsewhere):
    """Run an experiment over the box: its nominal outcome, with the :class:`Box` attached.

    Parameters
    ----------
    experiment : callable
        ``experiment(params, **kw) -> Outcome``.
    params : wmr.sim.Params, optional
        The nominal point.
    nominal_only : bool, optional
        Run the nominal point only: the :class:`Box` is partial and gives no verdict.
    **elsewhere
        Arguments of the experiment at the points other than the nominal one (runs that only the
        nominal point's figure and text need, left out to save time).

    Returns
    -------
    Outcome
        The nominal run's outcome; ``outcome.box`` the verdict over the box.

    Raises
    ------
    FloatingPointError
        If the nominal run itself diverges (a run elsewhere in the box that diverges is invalid).
    """
    pts = points(params)[:1] if nominal_only else points(params)
    nominal = experiment(pts[0][2])
    runs = [("nominal", "", _status(nominal))]
    for name, value, p in pts[1:]:
        try:
            status = _status(experiment(p, **elsewhere))
        except FloatingPointError:
            status = f"{INVALID} (divergence)"
        runs.append((name, value, status))
    box = Box(tuple(runs), describe(params), partial=nominal_only)
    return dataclasses.replace(nominal, box=box, data=nominal.data)
