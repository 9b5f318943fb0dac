r"""The words of ``wmr``'s output, explained for an engineer: ``wmr explain TERM`` and the notes under ``wmr analyze``.

Each entry has a one-line ``short`` form (a footnote under the table) and a ``text`` of a few
sentences (``wmr explain``).  Terms are looked up loosely: case, spaces, ``_`` and ``-`` do not
matter, and ``kappa(J_L1)`` finds ``J_L1``.

Examples
--------
>>> lookup("rank F").term
'rank-F'
>>> lookup("kappa(J_L1)").term
'J_L1'
"""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass

from ..errors import InputValueError

__all__ = ["Entry", "GLOSSARY", "lookup", "terms"]


@dataclass(frozen=True)
class Entry:
    """One glossary entry.

    Parameters
    ----------
    term : str
        The term as written in the output.
    short : str
        A one-line explanation (a note under ``wmr analyze``).
    text : str
        A few sentences (``wmr explain``).
    """

    term: str
    short: str
    text: str


_ENTRIES = [
    Entry(
        "twist",
        "the robot's velocity: turning rate omega (rad/s) and the velocity (vx, vy) of C, body frame",
        "A twist is the velocity of the whole robot: how fast it turns (omega, rad/s, counter-clockwise) and how "
        "fast its reference point C moves (vx forward, vy left, m/s), in the robot's own frame.  wmr writes it "
        "(omega, vx, vy); WPILib's ChassisSpeeds and ROS write (vx, vy, omega) (see 'convention').",
    ),
    Entry(
        "class",
        "Campion's class (delta_m, delta_s): how many ways it can move, and how many steering angles choose them",
        "Campion, Bastin and d'Andrea-Novel (1996) sort every wheeled robot by two numbers: delta_m, the number "
        "of independent motions it can make at a given steering (3: any direction and turning at once), and "
        "delta_s, the number of steering angles that choose among motions.  (3,0) omnidirectional (mecanum, "
        "omni, castors), (2,0) differential drive, (2,1) one steered wheel, (1,1) car-like, (1,2) two or more "
        "independently steered wheels (swerve).  Others, e.g. a skid steer's (1,0), are degenerate: the wheels "
        "fight each other in some motions.",
    ),
    Entry(
        "delta_m",
        "degree of mobility: the number of independent motions at a given steering (0 to 3)",
        "delta_m is the dimension of the twists the wheels allow without skidding at a generic steering: 3 "
        "means it can drive in any direction while turning; 1 means a single motion (forward along a circle) "
        "until it steers.",
    ),
    Entry(
        "delta_s",
        "degree of steerability: how many steering angles can be set independently",
        "delta_s counts the steering angles that can be chosen independently to pick the motion (a car: 1, "
        "the two front wheels being tied by Ackermann geometry; a swerve drive: 2).",
    ),
    Entry(
        "actuated-mobility",
        "the number of independent motions the motors command (at most delta_m)",
        "Not every joint has a motor: the rollers of mecanum and omni wheels, castors and free wheels are "
        "passive.  The actuated mobility is the number of independent motions the motors command.  When it is "
        "below delta_m, the robot has a motion it makes with every motor stopped: the motors can neither drive "
        "nor stop it (four mecanum wheels of the same hand roll freely along one diagonal).  wmr analyze names "
        "those motions.",
    ),
    Entry(
        "limitations",
        "what the robot cannot do, in plain words, computed from its class and actuation",
        "Sentences computed from the class and the actuation, e.g. 'turning requires skidding: it can only drive "
        "straight ahead' for a skid steer, or 'the motors cannot move it diagonally' for same-hand mecanum wheels.",
    ),
    Entry(
        "rank-F",
        "rank of F, the matrix of the no-slip equations: a drop marks a special steering",
        "Every wheel imposes no-slip equations on the twist and the wheel rates; F is their matrix (the paper's "
        "(24)).  Its rank is the number of independent equations.  The rank drops at special steering angles "
        "(e.g. all wheels parallel, all axles through one point), where the robot gains a motion.",
    ),
    Entry(
        "nullity",
        "nullity of F = 3 + (wheel rates) - rank F: the free motions of the robot and its wheels",
        "The nullity of F counts the independent ways the robot and its wheels can move together without "
        "slipping (the paper's mobility (27)).  It includes wheel motions that do not move the robot.",
    ),
    Entry(
        "L",
        "the characteristic length: the length that makes turning and driving comparable in J_L1",
        "Turning (rad/s) and driving (m/s) have different units; the characteristic length L converts one into "
        "the other (omega * L is a speed).  wmr uses the L that makes J_L1 best conditioned for the current C: "
        "L^2 = mean squared distance of the mount points from C.  Moving C changes L.",
    ),
    Entry(
        "J_L1",
        "the platform Jacobian with L: how the twist moves the wheel mount points (isotropic = 1 is best)",
        "J_L1 maps the twist (omega * L, vx, vy) to the velocities of the wheel mount points (the paper's (32)).  "
        "Its condition number kappa(J_L1) is 1 exactly when C is the centroid of the mount points (and L the "
        "characteristic length): then no direction of motion is favoured.",
    ),
    Entry(
        "J2",
        "the wheel Jacobian: how the wheel rates move the mount points (kappa(J2) = 1 is best)",
        "J2 maps the wheel rates to the velocities of the mount points (the paper's (21)).  kappa(J2) is the same "
        "at every steering; 1 means every wheel rate moves its mount point equally well in every direction it "
        "can; inf means some unit drives its mount point in one direction only (a conventional wheel).",
    ),
    Entry(
        "J",
        "J = J_L1^T J2: how the wheel rates produce the twist; singular where they cannot produce some",
        "J combines J_L1 and J2 (the paper's (56)): it says how well the wheel rates produce each twist.  "
        "kappa(J) near 1 means every motion costs the motors about the same; a large kappa(J) means some motion "
        "needs large wheel rates for little movement; inf (rank J < 3) is a singular configuration.",
    ),
    Entry(
        "kappa",
        "condition number: largest over smallest gain of a matrix; 1 is ideal, inf is singular",
        "The condition number of a matrix is the ratio of its largest to its smallest gain over all directions.  "
        "1 (isotropic) means every direction is equally easy; 10 means one direction needs ten times the effort "
        "of another; inf means one direction is impossible.",
    ),
    Entry(
        "isotropic",
        "condition number 1: every direction of motion equally easy",
        "A matrix is isotropic when its condition number is 1: it treats every direction alike.  The paper "
        "designs robots whose J_L1 and J2 are isotropic.",
    ),
    Entry(
        "singular",
        "a steering where the wheel rates cannot make every change of motion: re-steer first",
        "At a singular configuration (rank J < 3) some change of the robot's motion cannot be made by the wheel "
        "rates alone: the wheels must be re-steered first, which takes time.  A car driving straight ahead is "
        "singular (to turn it must steer); a robot without steering cannot make that change at all without "
        "skidding.",
    ),
    Entry(
        "parallel",
        "singular family: all wheels point the same way (straight-line driving)",
        "All wheel planes are parallel: the robot drives straight along them.  To turn or to move another way, "
        "steered wheels must first be turned; fixed wheels never can (the robot would skid).",
    ),
    Entry(
        "through-C",
        "singular family: every axle points at C: the robot spins on the spot",
        "The axles all meet at C, so the robot turns on the spot.  Its wheel rates alone cannot add a "
        "translation: the wheels must be re-steered first.",
    ),
    Entry(
        "through-P",
        "singular family: the axles meet at one wheel's mount point: that wheel stands still",
        "The axles meet at a mount point: the robot turns about that wheel, which stands still (its rate does "
        "nothing).  Moving the turning centre needs re-steering.",
    ),
    Entry(
        "through-point",
        "singular family: the axles meet at one point: the robot turns about it",
        "The axles meet at one point and the robot turns about it; to move that point (or to drive straight) "
        "the wheels must be re-steered first.",
    ),
    Entry(
        "dead-zone",
        "offset wheels: the circle C moves on when the units are steered without driving",
        "With offset (castor) wheels, steering the units while the wheels do not roll still moves the robot: C "
        "moves on a circle of radius equal to the offset.  Only a zero offset avoids it.",
    ),
    Entry(
        "drivable",
        "configurations the robot can drive in: steering angles coordinated for some twist",
        "A steered robot can move only when its wheels are coordinated (each rolls along its mount point's "
        "velocity).  wmr sweep samples twists and takes those steering angles by default; --angles any sweeps "
        "every combination of angles instead, almost none of which can move.",
    ),
    Entry(
        "admissible",
        "a motion the wheels allow without slip and the motors command",
        "A twist is admissible when the wheels can roll without slipping and the motors command it: a motion "
        "that the passive joints (rollers, castors) make by themselves with every motor stopped is not.",
    ),
    Entry(
        "slip",
        "the velocity the wheels would have to slide at: J1 t - J2 theta_dot (m/s)",
        "The slip residual is how fast the wheels would slide sideways or along their rolling direction for "
        "the given rates: zero for compatible rates.  Measured rates are never exactly compatible (encoder "
        "resolution), so wmr fk compares it with a slip tolerance you can set.",
    ),
    Entry(
        "convention",
        "how angles and twists are written: wmr (axle angles), wpilib or ros (headings)",
        "wmr's angles are the axle's (0: axle along x, the wheel rolls along y); WPILib's and ROS's are the "
        "direction of travel (0: rolls forward), 90 degrees less.  wmr writes twists (omega, vx, vy), WPILib and "
        "ROS (vx, vy, omega).  --convention wpilib|ros|wmr chooses for input and output.",
    ),
]

#: every entry by its term
GLOSSARY = {e.term: e for e in _ENTRIES}
_ALIASES = {
    "mobility": "nullity",
    "nullity-f": "nullity",
    "jl1": "J_L1",
    "j-l1": "J_L1",
    "j1": "J_L1",
    "characteristic-length": "L",
    "condition-number": "kappa",
    "campion": "class",
    "deltam": "delta_m",
    "deltas": "delta_s",
    "actuated": "actuated-mobility",
    "limits": "limitations",
    "rank": "rank-F",
    "v-c": "through-C",
    "v-p": "through-P",
    "v": "through-point",
    "i": "parallel",
    "i'": "parallel",
    "singularity": "singular",
    "residual": "slip",
}


def _key(text):
    return re.sub(r"[\s_\-]+", "-", text.strip().lower()).strip("-")


def terms() -> list[str]:
    """Every term of the glossary, in its order.

    Returns
    -------
    list of str
    """
    return [e.term for e in _ENTRIES]


def lookup(term: str) -> Entry:
    """The entry for ``term`` (loosely matched: see the module notes).

    Parameters
    ----------
    term : str

    Returns
    -------
    Entry

    Raises
    ------
    wmr.errors.InputValueError
        For an unknown term, with the closest one and the list.
    """
    if not isinstance(term, str):
        raise InputValueError(f"term must be a string, got {term!r}")
    m = re.fullmatch(r"\s*kappa\s*\((.*)\)\s*", term)
    key = _key(m.group(1) if m else term)
    by_key = {_key(t): t for t in GLOSSARY}
    by_key.update({_key(a): t for a, t in _ALIASES.items()})
    if key in by_key:
        return GLOSSARY[by_key[key]]
    close = difflib.get_close_matches(key, list(by_key), n=1)
    hint = f" (did you mean {by_key[close[0]]!r}?)" if close else ""
    raise InputValueError(f"term {term!r} is not in the glossary{hint}; terms: {', '.join(terms())}")
