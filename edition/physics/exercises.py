r"""The exercises of chapter 9 (``notebooks/09_physics``): one check function each, answered from the model and MuJoCo.

As in :mod:`edition.exercises`: the student writes an answer and calls the check, which returns a
:class:`~edition.exercises.Feedback` computed from the model and, where it says so, from a short
MuJoCo run (never compared with a typed-in answer); ``None`` gives "no answer yet" without failing.

===========================  ==================================================================================
check                        the exercise
===========================  ==================================================================================
:func:`jamming_angles`       steering angles, not all equal, at which the locked offset robot cannot steer
:func:`braking_angles`       steering angles other than Fig. 12a's at which a parked centred robot resists
                             every push with its drives free
===========================  ==================================================================================

:func:`describe_robot` runs a robot of the reader's own in MuJoCo ("your own robot" cell).
"""

from __future__ import annotations

import numpy as np

import wmr
from wmr.analysis.linalg import rank
from wmr.model import validation as V

from ..checks.assembly.locked import locked_system
from ..exercises import Feedback, answers
from ..exercises.framework import exercise
from .common import fmt, paper, pct
from .contact import weakest_push
from .drift import JAM_TURN, turn_locked

__all__ = ["JAM_TURN", "braking_angles", "describe_robot", "jamming_angles"]


@exercise("9.1", answer="three steering angles in degrees, wheel 1 first", units={"beta_deg": "deg"})
def jamming_angles(beta_deg):
    r"""Exercise 9.1: steering angles, not all equal, at which the paper's offset robot with its drives locked jams.

    Checked by the rank of the locked-drive system :math:`\mathbf M(\boldsymbol\beta)` and by MuJoCo: the
    steering servos are commanded one full turn in 4 s with the drives locked
    (:func:`~edition.physics.drift.turn_locked`).  The answer is right only when both agree: rank 6 and at
    most :data:`JAM_TURN` of the turn made.  Rank 6 next to a singular configuration, where MuJoCo's soft
    contacts let the servos turn, is told so (and the framework adds its hint when the angles look like
    radians).

    Parameters
    ----------
    beta_deg : array (3,) or None
        Degrees.

    Returns
    -------
    Feedback
    """
    robot = paper("offset")
    beta = answers.angles(beta_deg, robot.w, "deg")  # radians; a malformed answer gets the framework's one line
    cols = [c for c, n in enumerate(robot.qdot_names) if not n.startswith("theta_dot")]
    r = int(rank(locked_system(robot, beta), scale=robot.F_column_norms[cols]))
    if r < 6:
        j = np.stack([-np.sin(beta), np.cos(beta)], axis=-1)
        parallel = rank(j, scale=[1.0, 1.0]) < 2
        why = (
            "all parallel: the platform translates"
            if parallel
            else "concurrent: the platform turns about their common point"
        )
        return Feedback(
            False,
            f"At these angles rank M = {r}: the arm lines (through $P_i$ along $\\mathbf j_i$) are "
            f"{why}, so the locked robot can still steer.",
        )
    rec = turn_locked(robot, beta)
    turned = float(np.abs(rec.beta[-1] - rec.beta[0]).max()) / (2 * np.pi)
    moved = np.linalg.norm(rec.pose[-1, 1:] - rec.pose[0, 1:])
    if turned > JAM_TURN:  # the rigid model says jam, the physics engine says it steers: never call that right
        return Feedback(
            False,
            f"rank M = 6 in the rigid model, but these angles are so close to a configuration where the locked robot "
            f"can steer (arm lines nearly concurrent or parallel) that in MuJoCo the steering servos turned "
            f"{pct(turned)} of the commanded turn (a jam turns at most {pct(JAM_TURN)}): the soft contacts give "
            "way. Choose angles farther from it.",
        )
    return Feedback(
        True,
        f"rank M = 6: no motion is possible. In MuJoCo the steering servos, commanded one full turn, "
        f"turned {pct(turned)} of it (a jam: at most {pct(JAM_TURN)}) and C moved {fmt(moved * 1000)} mm.",
    )


@exercise("9.2", answer="three steering angles in degrees, wheel 1 first", units={"beta_deg": "deg"})
def braking_angles(beta_deg):
    r"""Exercise 9.2: angles other than Fig. 12a's at which the parked centred robot, drives free, resists every push.

    It must have no admissible motion at all (rank F = 6, mobility 0); the feedback gives the weakest
    push by limit analysis (:func:`~edition.physics.contact.weakest_push`, equal loads, the default
    friction).

    Parameters
    ----------
    beta_deg : array (3,) or None
        Degrees.

    Returns
    -------
    Feedback
    """
    robot = paper("centred")
    beta = answers.angles(beta_deg, robot.w, "deg")
    d = robot.mount_points
    fig12a = np.arctan2(-d[:, 0], d[:, 1])
    if np.allclose(np.cos(2 * (beta - fig12a)), 1.0, atol=1e-9):
        return Feedback(False, "These are Fig. 12a's angles (every wheel plane through C): find others.")
    mob = int(wmr.mobility(robot, beta))
    if mob > 0:
        return Feedback(
            False,
            f"Mobility {mob}: the axle lines meet in one point (or are parallel), so the robot "
            "rolls away under a small push.",
        )
    worst = min(weakest_push(robot, beta, (np.cos(a), np.sin(a))) for a in np.radians(np.arange(0.0, 360.0, 5.0)))
    return Feedback(
        True,
        f"Mobility 0: every push must slide the wheels. The weakest push (limit analysis, every "
        f"5 deg) is {fmt(worst)} W -- a brake, though not necessarily as good as Fig. 12a's.",
    )


def describe_robot(robot, twist=(0.4, 0.3, 0.1), seconds=2.0):
    r"""A robot of the reader's own in MuJoCo: the twist it makes against the one commanded (Markdown).

    Parameters
    ----------
    robot : Robot
    twist : triple, optional
        :math:`(\dot\psi, \dot x, \dot y)` commanded.
    seconds : float, optional

    Returns
    -------
    str
    """
    from wmr.sim import Simulation, run, start_angles, twist_schedule

    robot = V.numeric_robot(robot)
    try:
        sim = Simulation(robot, beta=start_angles(robot, twist))
    except NotImplementedError as e:
        return f"MuJoCo refuses this robot: {e}."
    rec = run(sim, twist_schedule(robot, twist, seconds), seconds)
    late = rec.t >= seconds / 2
    got = rec.twist[late].mean(axis=0)
    adm = bool(wmr.inverse(robot, start_angles(robot, twist), twist).admissible)
    return (
        f"Commanded $(\\dot\\psi, \\dot x, \\dot y) = ({', '.join(f'{x:g}' for x in twist)})$"
        f"{'' if adm else ' (not admissible: wmr predicts slip)'}; MuJoCo: "
        f"$({', '.join(fmt(x, 3) for x in got)})$, the wheels sliding at {fmt(rec.slip_speed[late].mean())} m/s "
        f"on average."
    )
