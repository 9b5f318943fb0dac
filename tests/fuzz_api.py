"""The public API as a fuzzer sees it: every function, its arguments' roles, and bad values for each role.

Used by ``tests/test_fuzz.py`` (Hypothesis) and, as a script, to count outcomes over many seeded
calls (``python tests/fuzz_api.py [N]``; run it with ``PYTHONPATH=<tree>`` to measure another tree).

Each argument has a *role*; a role gives three kinds of values for a robot:

* ``good``: ordinary valid values;
* ``odd``: valid but awkward values (extreme magnitudes, Fractions, NumPy scalars, empty batches):
  the call must return finite results or raise an input error (overflow detected);
* ``bad``: values the function cannot handle (wrong kind, wrong shape, NaN, infinity, SymPy
  ``oo``/``nan``/``zoo``/``I``, ``10**400``, ``np.longdouble('1e400')``, the class ``Robot``...):
  the call must raise an input error.

An input error is the package's own :class:`wmr.errors.InputError` (an ``InputTypeError`` or
``InputValueError``): a bare ``TypeError`` or ``ValueError`` (from inside NumPy, say) is a
``wrong-exception``.  A rejection's message must name the argument (as a word).  Outcomes: ``returned``, ``rejected``,
and the faults ``wrong-exception``, ``unnamed``, ``accepted-bad``, ``non-finite``, ``hang``.
"""

from __future__ import annotations

import dataclasses
import re
import signal
import sys
from fractions import Fraction

import numpy as np
import sympy as sp

import wmr
from wmr import swerve
from wmr.analysis import (
    actuation,
    advice,
    design,
    limitations,
    linalg,
    lines,
    mobility,
    motion_kappa,
    overview,
    reference,
    singularities,
    square,
)
from wmr.analysis.sweep import Drivable, Grid
from wmr.analysis.sweep import configurations as sweep_configurations
from wmr.analysis.sweep import motions as sweep_motions
from wmr.errors import InputError
from wmr.model import backend, checks, conventions, limits, platform, tolerance, wheels
from wmr.model.backend import NUMERIC, SYMBOLIC
from wmr.model.wheels import joints, unsteered
from wmr.words import glossary
from wmr.words import limitations as limitation_words

x_sym = sp.Symbol("x", positive=True)
RNG = np.random.default_rng(2002)
BIG, TINY = 1.7e308, 1e-320


def _robots():
    mixed = wmr.Robot(
        [
            wmr.OffsetWheel((1.0, 0.2), r=0.2, d=0.1),
            wmr.CentredWheel((-0.5, 0.9), r=0.3),
            wmr.DualWheel((-0.4, -1.0), r=0.25, b=0.15),
            wmr.CentredWheel((0.6, -0.7), r=0.1),
        ]
    )
    unsteered = wmr.Robot(
        [
            wmr.SwedishWheel((0.5, 0.3), r=0.1, angle=0.4, roller=np.pi / 4),
            wmr.FixedWheel((-0.6, 0.2), r=0.2, angle=1.2),
            wmr.SwedishWheel((0.1, -0.7), r=0.1, angle=-2.0, roller=-np.pi / 4),
        ]
    )
    return [
        wmr.paper_robot("centred", L=0.5, r=0.1),
        wmr.paper_robot("offset", L=2.0, r=0.3),
        wmr.paper_robot("dual", L=1.0, r=0.2),
        mixed,
        wmr.Robot([wmr.CentredWheel((0.0, 0.0), r=1.0)]),
        unsteered,
    ]


ROBOTS = _robots()
CENTRED3 = [ROBOTS[0], wmr.paper_robot("centred", L=1.0, r=1.0, exact=True)]
SYMBOLIC_ROBOT = wmr.Robot(
    [wmr.CentredWheel((x_sym, 0), r=1), wmr.CentredWheel((0, x_sym), r=1), wmr.CentredWheel((-x_sym, -x_sym), r=1)]
)

#: wrong for every numeric role
BAD_ANY = [
    None,
    "0.7",
    b"1",
    True,
    1j,
    np.nan,
    np.inf,
    -np.inf,
    sp.oo,
    sp.nan,
    sp.zoo,
    sp.I,
    10**400,
    np.longdouble("1e400"),
    wmr.Robot,
    object(),
    {},
    x_sym,
    [[1.0, 2.0], [3.0]],
]


def _arrays(last, n=4):
    """Good and odd arrays whose last axis is ``last``."""
    good = [
        np.zeros(last),
        RNG.uniform(-3, 3, last),
        RNG.uniform(-3, 3, (n, last)),
        list(RNG.uniform(-1, 1, last)),
        RNG.uniform(-1, 1, (2, 3, last)),
    ]
    odd = [
        np.full(last, BIG),
        np.full(last, -BIG),
        np.full(last, TINY),
        np.zeros((0, last)),
        [Fraction(1, 3)] * last,
        np.ones(last, dtype=np.float32),
        np.arange(last),
        np.full((2, last), 1e300),
    ]
    bad = [
        np.zeros(last + 1),
        np.zeros(max(last - 1, 0)),
        np.zeros((1, last + 1)),
        np.full(last, 1 + 1j),
        ["0.7"] * last,
        [True] * last,
        np.full(last, np.nan),
        [sp.oo] + [0] * (last - 1),
        [10**400] * last,
        np.array([np.longdouble("1e400")] * last),
        np.zeros((last, 0)),
        0.5,
    ]
    return good, odd, bad + BAD_ANY


def _scalar(kind):
    if kind == "positive":
        return (
            [0.5, 2, Fraction(1, 3), np.float32(0.1), np.array(1.5)],
            [BIG, TINY, 1e300, 5e-324],
            [0, 0.0, -1.0, -TINY, [1.0], np.array([1.0, 2.0])] + BAD_ANY,
        )
    if kind == "angle":
        return ([0.3, -2, np.float64(1.0), Fraction(1, 2)], [BIG, 1e300, TINY, -0.0], [[1.0], (0, 1)] + BAD_ANY)
    raise KeyError(kind)


def _is_zero(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and v == 0


def _role(name, bot):
    """(good, odd, bad) values of a role for a robot."""
    w, n = bot.w, bot.n_rates
    if name == "robot":
        return ROBOTS, [], [None, wmr.Robot, "robot", 3, [bot], SYMBOLIC_ROBOT]
    if name == "self":  # the robot whose method is called: always a robot
        return [bot], [], []
    if name == "robot3":
        return CENTRED3, [], [None, wmr.Robot, ROBOTS[2], ROBOTS[3], "robot"]
    if name == "any_robot":
        return ROBOTS + [SYMBOLIC_ROBOT], [], [None, wmr.Robot, "robot", 3]
    if name == "beta":
        return _arrays(w)
    if name == "beta1":
        good, odd, bad = _arrays(w)
        return good[:2] + good[3:4], odd[:3] + odd[4:], bad + [RNG.uniform(size=(2, w))]
    if name == "twist":
        return _arrays(3)
    if name == "twist1":
        good, odd, bad = _arrays(3)
        return good[:2], odd[:3], bad + [np.zeros((2, 3))]
    if name == "rates":
        return _arrays(n)
    if name == "pair":
        return _arrays(2)
    if name == "pairs":
        return (
            [RNG.uniform(-1, 1, (3, 2)), [[0, 0], [1, 0], [0, 1]]],
            [np.full((3, 2), 1e300), np.full((3, 2), TINY)],
            [np.zeros((3, 3)), [[1, 2], [3]], np.full((3, 2), np.nan), np.full((3, 2), 1j)] + BAD_ANY,
        )
    if name == "matrix":
        return (
            [RNG.normal(size=(3, 3)), RNG.normal(size=(4, 6, 6)), RNG.normal(size=(2, 5)), np.eye(3), [[1.0, 2.0]]],
            [
                np.full((3, 3), BIG),
                np.full((2, 2), TINY),
                np.zeros((3, 3)),
                np.empty((3, 0)),
                np.empty((0, 3)),
                np.diag([1e300, 1e-300, 1.0]),
                [[Fraction(1, 3), 1], [2, 3]],
            ],
            [np.zeros(3), 2.0, np.full((2, 2), 1j), [["1", "2"]], np.full((2, 2), np.nan), [[True, False]]] + BAD_ANY,
        )
    if name == "matrix1":
        good, odd, bad = _role("matrix", bot)
        return good[:1] + good[2:], odd, bad + [good[1]]
    if name in ("positive", "angle"):
        return _scalar(name)
    if name == "length_sym":
        good, odd, bad = _scalar("positive")
        return good + [x_sym, sp.Rational(1, 2)], odd, [b for b in bad if b is not x_sym]
    if name == "nonneg_sym":
        good, odd, bad = _role("length_sym", bot)
        return good + [0, 0.0], odd, [b for b in bad if not _is_zero(b)]
    if name == "opt_length_sym":
        good, odd, bad = _role("opt_length", bot)
        return good + [x_sym], odd, [b for b in bad if b is not x_sym]
    if name == "opt_nonneg":  # an offset: SymPy lengths allowed
        good, odd, bad = _role("opt_length", bot)
        return good + [0, 0.0, x_sym], odd, [b for b in bad if not _is_zero(b) and b is not x_sym]
    if name == "rate_opt":
        good, odd, bad = _scalar("angle")
        return [None, -0.5] + good, odd, [b for b in bad if b is not None and not isinstance(b, (list, tuple))]
    if name == "anything":
        return [0.3, x_sym, [1.0, x_sym], np.zeros(3), None, "text", 10**400, np.nan], [], []
    if name == "L_opt":
        good, odd, bad = _scalar("positive")
        return good + [None], odd, [b for b in bad if b is not None]
    if name == "point":
        return (
            [(0.5, -0.2), np.array([1, 2]), [0, 0]],
            [(BIG, -BIG), (TINY, 0)],
            [(1.0,), (1, 2, 3), "ab", (np.nan, 0), (sp.oo, 0), (1j, 0), (True, 0), 1.0] + BAD_ANY,
        )
    if name == "point_sym":
        good, odd, bad = _role("point", bot)
        return good + [(x_sym, 0), (sp.Rational(1, 2), sp.sqrt(3) / 2)], odd, [b for b in bad if b is not x_sym]
    if name == "flag":
        return [True, False, np.True_], [], [1, 0, "yes", None, np.array([True, False]), 1.0]
    if name == "text":
        return [None, "bot"], [], [3, b"x", ["a"], True]
    if name == "kind":
        return ["centred", "offset", "dual"], [], ["tricycle", 3, None, b"centred"]
    if name == "wheel":
        return [1, 2, np.int64(w)], [], [0, w + 1, 1.5, True, "1", None, -1]
    if name == "angles_sym":  # the SymPy backend takes a symbol
        good, odd, bad = _role("angles", bot)
        return good + [x_sym], odd, [b for b in bad if b is not x_sym]
    if name == "nonneg_any":
        return [0, 1.0, [1.0], np.ones(3), np.zeros((2, 1))], [BIG, TINY], [-1.0, [-0.5]] + BAD_ANY
    if name == "sbeta":  # a robot method's beta: None means the symbols
        good, odd, bad = _arrays(w)
        return good + [None], odd, [b for b in bad if b is not None]
    if name == "count":
        return [1, 2, np.int64(7)], [10**6], [0, -1, 1.5, True, "1", None]
    if name == "angles":  # any shape
        return (
            [0.3, np.zeros(4), RNG.uniform(-3, 3, (2, 3)), [0.1, 0.2]],
            [BIG, np.full(3, 1e300), TINY, np.zeros(0)],
            [np.full(3, 1j), ["0.7"], [True], np.full(2, np.nan), [sp.oo, 0]] + BAD_ANY,
        )
    if name == "nonneg":
        good, odd, bad = _scalar("positive")
        return good + [0, 0.0], odd, [b for b in bad if not _is_zero(b)]
    if name == "backend":
        return [None, NUMERIC], [], ["numpy", 3, NUMERIC.__class__]
    if name == "backend_any":
        return [None, NUMERIC, SYMBOLIC], [], ["numpy", 3]
    if name == "dt":
        return [0.1, 0.25], [1e-9, TINY, BIG], [0, -0.1] + BAD_ANY
    if name == "opt_beta":
        good, odd, bad = _arrays(w)
        return [None] + good, odd, [b for b in bad if b is not None]
    if name == "opt_length":
        good, odd, bad = _scalar("positive")
        return [None] + good, odd, [b for b in bad if b is not None]
    if name == "analysis":
        return ["rank_F", "mobility", "kappa_JL1"], [], ["rank", 3, None, ["rank_F"]]
    if name == "angles":
        from wmr.analysis.sweep import Sample

        return [Sample(50, seed=1), RNG.uniform(-3, 3, (20, w))], [], [None, "grid", np.zeros((5, w + 1)), 3]
    if name == "key":
        return ["P", "H", "wheels", "i", "j"], [], ["Q", 3, None]
    if name == "driven":  # the actuation of a dual wheel's three joints
        return (
            [None, {"swivel": True}, {}, (False, True, True), [True, True, False], {"drive1": np.True_}],
            [],
            [{"steer": True}, {"drive1": 1}, (True, True), "swivel", 3, {"swivel": None}, [True] * 4, [1, 0, 1]],
        )
    if name == "index":
        return [0, w - 1], [], [w, -w - 1, 1.5, "0", None, True]
    if name == "convention":
        return ["wmr", "wpilib", "ros"], [], ["WPILib", 3, None, ["ros"]]
    if name == "term":
        return ["rank-F", "kappa(J_L1)", "through P", "nullity"], [], ["nonsense", 3, None, ""]
    if name == "limit":
        return ["wheels", "configurations", "memory_mb"], [], ["cpu", None, 3, ["wheels"]]
    if name == "amount":
        return [1, 50.0, np.int64(7)], [], [1e30, 10**400, np.nan, None, "1", True]
    if name == "twist_batch":
        return [RNG.normal(size=(6, 3)), np.zeros((1, 3))], [], []
    raise KeyError(name)


@dataclasses.dataclass(frozen=True)
class Case:
    """One public function: how to call it, the roles of its arguments."""

    name: str
    call: object  # call(**arguments)
    roles: tuple  # ((argument name, role), ...)
    allow: str = ""  # documented non-finite results: "inf" (condition numbers) or "inf nan" (centres)
    robots: tuple = ()  # which robots the roles are drawn for (default: all)


def _attr(module, name):
    """A call of ``module.name`` with the arguments by name (for the cases built in a loop)."""

    def call(**arguments):
        return getattr(module, name)(**arguments)

    return call


def _traj():
    return wmr.integrate(ROBOTS[0], [-1.0, -1.0, -1.0], [0.0, 0.0, 0.0], t_end=0.2, dt=0.1)


TRAJ = _traj()
R, B, T = ("robot", "robot"), ("beta", "beta"), ("twist", "twist")
S = ("robot", "self")

CASES = [
    # --- construction
    Case(
        "OffsetWheel",
        lambda position, r, d: wmr.OffsetWheel(position, r=r, d=d),
        (("position", "point_sym"), ("r", "length_sym"), ("d", "nonneg_sym")),
    ),
    Case(
        "CentredWheel",
        lambda position, r: wmr.CentredWheel(position, r=r),
        (("position", "point_sym"), ("r", "length_sym")),
    ),
    Case(
        "DualWheel",
        lambda position, r, b: wmr.DualWheel(position, r=r, b=b),
        (("position", "point_sym"), ("r", "length_sym"), ("b", "length_sym")),
    ),
    Case(
        "FixedWheel",
        lambda position, r, angle: wmr.FixedWheel(position, r=r, angle=angle),
        (("position", "point_sym"), ("r", "length_sym"), ("angle", "angle")),
    ),
    Case(
        "SwedishWheel",
        lambda position, r, angle, roller: wmr.SwedishWheel(position, r=r, angle=angle, roller=roller),
        (("position", "point_sym"), ("r", "length_sym"), ("angle", "angle"), ("roller", "roller")),
    ),
    Case("Robot", lambda wheels, name: wmr.Robot(wheels, name=name), (("wheels", "wheels"), ("name", "text"))),
    Case(
        "paper_robot",
        lambda kind, L, r, d, b, exact: wmr.paper_robot(kind, L=L, r=r, d=d, b=b, exact=exact),
        (
            ("kind", "kind"),
            ("L", "length_sym"),
            ("r", "length_sym"),
            ("d", "opt_nonneg"),
            ("b", "opt_length_sym"),
            ("exact", "flag"),
        ),
    ),
    Case(
        "equilateral_mounts",
        lambda L, first_deg, clockwise, exact: wmr.equilateral_mounts(L, first_deg, clockwise, exact),
        (("L", "length_sym"), ("first_deg", "angle"), ("clockwise", "flag"), ("exact", "flag")),
    ),
    # --- the robot's matrices (self is a valid robot)
    Case(
        "Robot.J1",
        lambda robot, L, backend: robot.J1(L=L, backend=backend),
        (S, ("L", "positive"), ("backend", "backend")),
    ),
    Case("Robot.J2", lambda robot, beta: robot.J2(beta), (S, ("beta", "sbeta"))),
    Case("Robot.F", lambda robot, beta: robot.F(beta), (S, ("beta", "sbeta"))),
    Case("Robot.J", lambda robot, beta, L: robot.J(beta, L=L), (S, ("beta", "sbeta"), ("L", "positive"))),
    Case(
        "Robot.moved",
        lambda robot, origin, angle: robot.moved(origin, angle),
        (S, ("origin", "point"), ("angle", "angle")),
    ),
    Case("Robot.effective_beta", lambda robot, beta: robot.effective_beta(beta), (S, B)),
    Case("unit.block", lambda robot, beta: robot.wheels[0].block(beta), (S, ("beta", "angles"))),
    Case("unit.points", lambda robot, beta: robot.wheels[0].points(beta), (S, ("beta", "angles"))),
    Case("unit.rate_names", lambda robot, i: robot.wheels[0].rate_names(i), (S, ("i", "count"))),
    Case(
        "unit.beta_rate",
        lambda robot, psi_dot, rates, steer: robot.wheels[0].beta_rate(psi_dot, rates, steer),
        (S, ("psi_dot", "angles"), ("rates", "pair"), ("steer", "rate_opt")),
    ),
    # --- platform and backends
    Case("E", lambda backend: wmr.E(backend), (("backend", "backend_any"),)),
    Case("rotation", lambda angle: wmr.rotation(angle), (("angle", "angles"),)),
    Case("rotated", lambda beta, M: platform.rotated(beta, M, M), (("beta", "angles_sym"), ("M", "matrix"))),
    Case("wrap_angle", lambda angle: platform.wrap_angle(angle), (("angle", "angles"),)),
    Case("point_row", lambda d, L: platform.point_row(d, L), (("d", "point"), ("L", "positive"))),
    Case("point_velocity", lambda twist, d: wmr.point_velocity(twist, d), (T, ("d", "pair"))),
    Case(
        "moved_points",
        lambda points, origin, angle: platform.moved_points(points, origin, angle),
        (("points", "pairs"), ("origin", "point"), ("angle", "angle")),
    ),
    Case(
        "choose",
        lambda value, backend: backend_choose(value, backend),
        (("value", "anything"), ("backend", "backend_any")),
    ),
    Case("near_zero", lambda x, scale: tolerance.near_zero(x, scale), (("x", "angles"), ("scale", "nonneg_any"))),
    # --- linear algebra
    *[
        Case(f"linalg.{f}", _attr(linalg, f), (("A", "matrix"),), allow="inf" if f == "condition_number" else "")
        for f in ("singular_values", "column_norms", "rank", "nullity", "condition_number")
    ],
    Case("linalg.det", lambda A: linalg.det(A), (("A", "square"),)),
    Case("linalg.null_space", lambda A: linalg.null_space(A), (("A", "matrix1"),)),
    Case("linalg.left_null_space", lambda A: linalg.left_null_space(A), (("A", "matrix1"),)),
    Case("is_isotropic", lambda A: wmr.is_isotropic(A), (("A", "matrix"),)),
    # --- analyses
    Case("mobility", lambda robot, beta: wmr.mobility(robot, beta), (R, B)),
    Case("rank_F", lambda robot, beta: wmr.rank_F(robot, beta), (R, B)),
    Case("twist_constraints", lambda robot, beta: mobility.twist_constraints(robot, beta), (R, B)),
    Case("admissible_twists", lambda robot, beta: wmr.admissible_twists(robot, beta), (R, ("beta", "beta1"))),
    Case("characteristic_length", lambda robot: wmr.characteristic_length(robot), (R,)),
    Case("campion_class", lambda robot: wmr.campion_class(robot), (R,)),
    Case("forward", lambda robot, beta, rates: wmr.forward(robot, beta, rates), (R, B, ("rates", "rates"))),
    Case(
        "inverse",
        lambda robot, beta, twist, beta_dot: wmr.inverse(robot, beta, twist, beta_dot),
        (R, B, T, ("beta_dot", "opt_beta")),
    ),
    Case(
        "instantaneous_centre",
        lambda twist, length: wmr.instantaneous_centre(twist, length),
        (T, ("length", "opt_length")),
        allow="inf nan",
    ),
    Case(
        "steering_angles",
        lambda robot, twist, current: wmr.steering_angles(robot, twist, current),
        (R, T, ("current", "opt_beta")),
    ),
    Case("centre_to_wheels", lambda twist, d: wmr.centre_to_wheels(twist, d), (T, ("d", "pairs"))),
    Case(
        "integrate",
        lambda robot, rates, beta0, t_end, dt: wmr.integrate(robot, rates, beta0, t_end, dt),
        (R, ("rates", "rates1"), ("beta0", "beta1"), ("t_end", "dt"), ("dt", "dt")),
    ),
    Case(
        "integrate(steer, pose0)",
        lambda robot, steer, pose0: wmr.integrate(
            robot, np.zeros(robot.n_rates), np.zeros(robot.w), 0.2, 0.1, steer, pose0
        ),
        (S, ("steer", "opt_beta1"), ("pose0", "twist1")),
    ),
    Case("Trajectory.world", lambda body_points: TRAJ.world(body_points), (("body_points", "pair"),)),
    Case(
        "Trajectory.unit_points", lambda i, key: TRAJ.unit_points(i, key), (("i", "index"), ("key", "key")), robots=(0,)
    ),
    Case(
        "sweep",
        lambda robot, analysis, angles: wmr.sweep(robot, analysis, angles),
        (R, ("analysis", "analysis"), ("angles", "angles")),
    ),
    Case("count", lambda value: sweep_configurations.count("value", value), (("value", "count"),)),
    Case("sweep(L)", lambda robot, L: wmr.sweep(robot, "kappa_J", Grid(3), L=L), (R, ("L", "L_opt")), allow="inf"),
    Case("require_square", lambda robot: square.require_square(robot), (R,)),
    Case("wheel_kind", lambda kind: wheels.wheel_kind(kind), (("kind", "kind"),)),
    Case("constant", lambda angle: unsteered.constant("angle", angle), (("angle", "angle"),)),
    Case(
        "actuation", lambda driven: joints.actuation(wmr.DualWheel.JOINTS, driven, "DualWheel"), (("driven", "driven"),)
    ),
    # --- design study
    Case(
        "worst_kappa",
        lambda robot, L: design.worst_kappa(robot, angles=Grid(3, 0.0, np.pi), L=L),
        (R, ("L", "L_opt")),
        allow="inf",
    ),
    Case(
        "WheelDesign",
        lambda mounts, d, r: design.WheelDesign(mounts, d, r),
        (("mounts", "pairs"), ("d", "nonneg"), ("r", "positive")),
    ),
    Case("equilateral_design", lambda ratio: design.equilateral_design(ratio), (("ratio", "nonneg"),)),
    Case(
        "worst_kappa_designs",
        lambda beta: design.worst_kappa_designs([design.equilateral_design(0.5)], beta),
        (("beta", "beta"),),
        robots=(0,),
    ),
    Case("rotation_twists", lambda centres: motion_kappa.rotation_twists(centres), (("centres", "pair"),)),
    Case(
        "motion_kappa",
        lambda robot, twist, L: motion_kappa.motion_kappa(robot, twist, L),
        (R, T, ("L", "L_opt")),
        allow="inf",
    ),
    Case("mount_circle", lambda robot: motion_kappa.mount_circle(robot), (R,)),
    Case(
        "motion_map",
        lambda robot, half_width, L: motion_kappa.motion_map(robot, 5, half_width, L),
        (R, ("half_width", "opt_length"), ("L", "L_opt")),
        allow="inf",
    ),
    # --- robot overview (wmr analyze) and robot files
    Case(
        "configurations",
        lambda robot, seed: overview.configurations(robot, grid=40, twists=4, seed=seed),
        (R, ("seed", "seed")),
    ),
    Case("singular_families", lambda robot, L: overview.singular_families(robot, L), (R, ("L", "L_opt"))),
    Case("overview", lambda robot: overview.overview(robot, grid=40, twists=4), (R,), allow="inf"),
    Case("dump", lambda robot, path: wmr.dump(robot, path), (R, ("path", "no_path"))),
    # --- lines and singularities
    Case(
        "line_intersection",
        lambda p1, u1, p2, u2: lines.line_intersection(p1, u1, p2, u2),
        (("p1", "pair1"), ("u1", "pair1"), ("p2", "pair1"), ("u2", "pair1")),
    ),
    Case(
        "pair_intersections",
        lambda points, directions: lines.pair_intersections(points, directions),
        (("points", "pairs"), ("directions", "pairs")),
    ),
    Case(
        "lines_concurrency",
        lambda points, directions: lines.lines_concurrency(points, directions),
        (("points", "pairs"), ("directions", "pairs")),
    ),
    Case(
        "concurrencies",
        lambda points, directions: lines.concurrencies(points, directions),
        (("points", "pairs"), ("directions", "pairs")),
    ),
    Case("circumcircle", lambda points: lines.circumcircle(points), (("points", "pairs"),)),
    *[Case(f"lines.{f}", _attr(lines, f), (R, B)) for f in ("wheel_plane_lines", "axle_lines")],
    *[Case(f"lines.{f}", _attr(lines, f), (R, ("beta", "beta1"))) for f in ("concurrency_point", "axles_concurrency")],
    Case("planes_through", lambda robot, D: lines.planes_through(robot, D), (R, ("D", "pair"))),
    Case("axles_through", lambda robot, U: lines.axles_through(robot, U), (R, ("U", "pair"))),
    Case(
        "pair_line_angle", lambda robot, i, j: lines.pair_line_angle(robot, i, j), (R, ("i", "wheel"), ("j", "wheel"))
    ),
    Case("line_angle", lambda beta: lines.line_angle(beta), (("beta", "angles"),)),
    *[
        Case(
            f"singularities.{f}",
            _attr(singularities, f),
            (("robot", "robot3"), ("beta", "beta"), ("L", "L_opt")),
            robots=(0,),
        )
        for f in ("det_J", "is_singular")
    ],
    Case(
        "classify",
        lambda robot, beta, L: singularities.classify(robot, beta, L),
        (("robot", "robot3"), ("beta", "beta1"), ("L", "L_opt")),
        robots=(0,),
    ),
    Case(
        "singular_motions",
        lambda robot, beta1: singularities.singular_motions(robot, beta1),
        (("robot", "robot3"), ("beta1", "angle")),
        robots=(0,),
    ),
    Case(
        "plane_line_matrix",
        lambda robot, beta, L, backend: singularities.plane_line_matrix(robot, beta, L, backend),
        (R, B, ("L", "positive"), ("backend", "backend")),
    ),
    Case("exact_robot", lambda robot: singularities.exact_robot(robot), (("robot", "any_robot"),)),
    Case("numeric_robot", lambda robot: singularities.numeric_robot(robot), (R,)),
    # --- the dense reference
    *[Case(f"reference.{f}", _attr(reference, f), (R, B)) for f in ("J2", "F", "rank_F")],
    Case(
        "reference.forward",
        lambda robot, beta, rates: reference.forward(robot, beta, rates),
        (R, B, ("rates", "rates")),
    ),
    Case("reference.inverse", lambda robot, beta, twist: reference.inverse(robot, beta, twist), (R, B, T)),
    Case("reference.det", lambda A: reference.det(A), (("A", "square"),)),
    *[
        Case(f"reference.{f}", _attr(reference, f), (("A", "matrix"),), allow="inf" if f == "condition_number" else "")
        for f in ("rank", "condition_number")
    ],
    # --- swerve practice (wmr.swerve): centred-wheel robots
    *[
        Case(f"swerve.{c.name}", c.call, c.roles, robots=(0, 4))
        for c in (
            Case(
                "module_commands",
                lambda robot, twist, current: swerve.module_commands(robot, twist, current),
                (R, T, ("current", "opt_beta")),
            ),
            Case("module_speeds", lambda robot, beta, twist: swerve.module_speeds(robot, beta, twist), (R, B, T)),
            Case(
                "chassis_twist",
                lambda robot, beta, speed: swerve.chassis_twist(robot, beta, speed),
                (R, B, ("speed", "beta")),
            ),
            Case("radii", lambda robot: swerve.radii(robot), (R,)),
            Case("swerve_robot", lambda robot: swerve.swerve_robot(robot), (R,)),
            Case(
                "optimize_modules",
                lambda robot, twist, current: swerve.optimize_modules(robot, twist, current),
                (R, T, ("current", "beta")),
            ),
            Case(
                "optimize_robot",
                lambda robot, twist, current, samples: swerve.optimize_robot(robot, twist, current, samples),
                (R, T, ("current", "beta"), ("samples", "samples")),
            ),
            Case(
                "transition_slip",
                lambda robot, current, beta, speed: swerve.transition_slip(robot, current, beta, speed),
                (R, ("current", "beta"), B, ("speed", "beta")),
            ),
            Case(
                "desaturate",
                lambda robot, twist, max_speed: swerve.desaturate(robot, twist, max_speed),
                (R, T, ("max_speed", "positive")),
            ),
            Case(
                "desaturation_scale",
                lambda robot, twist, max_speed: swerve.desaturation_scale(robot, twist, max_speed),
                (R, T, ("max_speed", "positive")),
            ),
        )
    ],
    Case(
        "swerve.cosine_compensate",
        lambda speed, beta, target: swerve.cosine_compensate(speed, beta, target),
        (("speed", "angles"), ("beta", "angles"), ("target", "angles")),
    ),
    Case("swerve.se2_exp", lambda twist, dt: swerve.se2_exp(twist, dt), (T, ("dt", "dt"))),
    Case("swerve.se2_log", lambda delta, dt: swerve.se2_log(delta, dt), (("delta", "twist"), ("dt", "dt"))),
    Case("swerve.discretize", lambda twist, dt: swerve.discretize(twist, dt), (T, ("dt", "dt"))),
    Case(
        "swerve.direction_change",
        lambda speed, angle, spin, t_change, t_end, dt: swerve.direction_change(
            speed, angle, spin, t_change, t_end, dt
        ),
        (
            ("speed", "positive"),
            ("angle", "angle"),
            ("spin", "angle"),
            ("t_change", "dt"),
            ("t_end", "dt"),
            ("dt", "dt"),
        ),
    ),
    Case(
        "swerve.spin_and_translate",
        lambda speed, rate, t_start, t_end, dt: swerve.spin_and_translate(speed, rate, t_start, t_end, dt),
        (("speed", "positive"), ("rate", "angle"), ("t_start", "dt"), ("t_end", "dt"), ("dt", "dt")),
    ),
    Case(
        "swerve.resteer_transient",
        lambda robot, profile, strategy, cosine, steer_rate: swerve.resteer_transient(
            robot, profile, strategy, cosine, steer_rate
        ),
        (R, ("profile", "profile"), ("strategy", "strategy"), ("cosine", "flag"), ("steer_rate", "positive")),
        robots=(0,),
    ),
    Case(
        "swerve.resteer_study",
        lambda robot, profile, steer_rate: swerve.resteer_study(robot, profile, steer_rate),
        (R, ("profile", "profile"), ("steer_rate", "positive")),
        robots=(0,),
    ),
    Case("Twist", lambda twist: wmr.Twist.of(twist), (("twist", "twist1"),)),
    # --- actuation, limitations, checked advice, glossary (issue 24)
    Case("actuated_mobility", lambda robot, beta: actuation.actuated_mobility(robot, beta), (R, B)),
    Case("free_twists", lambda robot, beta: actuation.free_twists(robot, beta), (R, ("beta", "beta1"))),
    Case("uncontrolled", lambda robot, beta, twist: actuation.uncontrolled(robot, beta, twist), (R, B, T), allow="inf"),
    Case("motion", lambda robot, twist: actuation.motion(robot, twist), (R, ("twist", "twist1"))),
    Case(
        "describe_twist", lambda robot, twist: limitation_words.describe_twist(robot, twist), (R, ("twist", "twist1"))
    ),
    Case("limitations", lambda robot: limitations.limitations(robot), (R,)),
    Case("advice", lambda robot: advice.advice(robot), (R,), allow="inf"),
    Case("lookup", lambda term: glossary.lookup(term), (("term", "term"),)),
    Case("checked", lambda convention: conventions.checked(convention), (("convention", "convention"),)),
    Case(
        "angle_to",
        lambda beta, convention: conventions.angle_to(beta, convention),
        (("beta", "angles"), ("convention", "convention")),
    ),
    Case(
        "angle_from",
        lambda angle, convention: conventions.angle_from(angle, convention),
        (("angle", "angles"), ("convention", "convention")),
    ),
    Case(
        "twist_to",
        lambda twist, convention: conventions.twist_to(twist, convention),
        (T, ("convention", "convention")),
    ),
    Case(
        "twist_from",
        lambda values, convention: conventions.twist_from(values, convention),
        (("values", "twist"), ("convention", "convention")),
    ),
    Case("twist_array", lambda twist: checks.twist_array("twist", twist), (T,)),
    Case("limit", lambda name: limits.limit(name), (("name", "limit"),)),
    Case("check", lambda name, amount: limits.check(name, amount, "amount"), (("name", "limit"), ("amount", "amount"))),
    Case("radians", lambda angle: unsteered.radians("angle", angle), (("angle", "angle"),)),
    Case("Drivable", lambda n, seed: Drivable(n, seed), (("n", "count"), ("seed", "seed"))),
    Case("Drivable.bind", lambda robot: Drivable(100, seed=1).bind(robot).configurations(robot.w, 0, 100), (R,)),
    Case(
        "kappa_J_of_twists",
        lambda robot, twist, L: sweep_motions.kappa_J_of_twists(robot, twist, L),
        (R, ("twist", "twist_batch"), ("L", "positive")),
        allow="inf",
    ),
    Case(
        "wheel_odometry",
        lambda robot, beta, angles, heading: wmr.wheel_odometry(robot, beta, angles, heading),
        (R, ("beta", "samples_beta"), ("angles", "samples_angles"), ("heading", "heading")),
    ),
]

#: public functions deliberately not fuzzed here, and why
NOT_FUZZED = {
    "det_J_symbolic": "SymPy factorisation (seconds per call); its robot and L checks are those of det_J",
    "det_J_polynomial": "as det_J_symbolic",
    "characterisation": "as det_J_symbolic",
    "exact_zero": "SymPy helper of the paper's families; argument checks tested in test_validation",
    "trig_combination": "kernel of Robot.J2/F/J and twist_constraints, fuzzed through them",
    "combine_checked": "trig_combination without the check of beta, for angles a robot has checked (fuzzed through Robot.J2/F/J)",
    "Terms": "the data of trig_combination, built by Robot.J2/F/J and twist_constraints (fuzzed through them)",
    "is_symbolic": "a predicate: any value is a valid question",
    "is_sympy": "a predicate: any value is a valid question (its kinds are SymPy class names the package passes)",
    "CampionClass": "the result type of campion_class, fuzzed through it",
    "Dimensions": "a TypedDict (the lengths paper_robot takes, for type checkers): no code runs; paper_robot is fuzzed",
    "search": "seconds per call (a search over designs); its arguments are checked in tests/test_design.py",
    "landscape": "seconds per call (two slices of the design space); its numbers are checked in tests/test_design.py",
    "WorstCase": "result type of worst_kappa",
    "DesignSearch": "result type of search",
    "Landscape": "result type of landscape",
    "MotionMap": "result type of motion_map",
    "load": "reads a file: every malformed case (one-line RobotFileError FILE:LINE: key) is tested in test_io.py",
    "Overview": "the result type of overview, fuzzed through it",
    # the wheel kinds' declarations (what a kind's author writes), checked in tests/test_wheel_kinds.py
    "WheelUnit": "the base of the wheel kinds, fuzzed through the five kinds (OffsetWheel, ...)",
    "UnsteeredUnit": "as WheelUnit (FixedWheel, SwedishWheel)",
    "Joint": "a kind's declaration (test_wheel_kinds)",
    "UnitGeometry": "a base of WheelUnit: its points, fuzzed through unit.points",
    "register": "called when a kind's class is defined, or its file keys declared (test_wheel_kinds defines one)",
    "FileKey": "a kind's declaration; reading robot files is tested in test_io.py",
    "Disc": "drawing data of wmr.plot.parts.unit_parts",
    "Link": "as Disc",
    "Rollers": "as Disc",
    "Pivot": "as Disc",
    "Body": "a kind's mechanism as data (wmr.io.mechanism.root_body), checked per kind by wheel_contract.check_mechanism",
    "Mechanism": "as Body; the height mechanism takes is checked in test_wheel_kinds",
    "root_body": "a kind's entry, checked per kind (wheel_contract.check_mechanism)",
    "mechanism": "as root_body; its height is checked in test_wheel_kinds",
    "has_mechanism": "a predicate on a kind (the contract test)",
    "mount": "a helper of the kinds' root_body (the unit's checked position)",
    "wheel": "as mount",
    "rate_columns": "read from a kind's JOINTS (a kind's declaration, test_wheel_kinds)",
    "wheel_kinds": "no arguments",
    "kinds_table": "no arguments",
    "toml_string": "formatting of robot files, tested through dump and load in test_io.py",
    "toml_text": "as toml_string",
    "kind_error": "builds the error every check raises (the checks are fuzzed)",
    "finite_float": "the conversion under real and number (fuzzed through every check); callers check the kind first",
    "rank_from_singular_values": "the rule rank applies to singular_values' output, fuzzed through rank",
    "kappa_from_singular_values": "the rule condition_number applies, fuzzed through it",
    "Partial": "the sweep's reduction, fuzzed through sweep",
    "first_written": "a kernel of the reduction, compared with rounding the whole chunk in tests/test_sweep.py",
    "finish": "as Partial",
    "Advice": "the result type of advice",
    "Suggestion": "an enum of Advice",
    "Verdict": "an enum of Advice",
    "Limitation": "the result type of limitations",
    "LimitationKind": "an enum of Limitation",
    "Motion": "the result type of motion",
    "MotionKind": "an enum of Motion",
    "ChangeKind": "an enum of Change",
    "Entry": "the result type of lookup",
    "terms": "no arguments",
    "Change": "the result type of isotropic_change and other_builds",
    "dead_zone": "a kind's entry (wmr.analysis.unit_design), checked per kind by wheel_contract.check_robot",
    "isotropic_change": "as dead_zone; fuzzed through advice on every robot",
    "other_builds": "as isotropic_change",
    "unit_parts": "a kind's drawing entry, checked per kind by wheel_contract.check_geometry_and_drawing",
    "drawn_angle": "as unit_parts",
    "has_parts": "a predicate on a kind (the contract test)",
    "has_file_keys": "as has_parts",
    "file_keys": "a kind's robot-file keys, checked per kind by wheel_contract.check_files",
    "readable_kinds": "no arguments",
    "Motions": "Drivable bound to a robot (Drivable.bind)",
    "SwerveKappa": "the fused kernel of a drivable sweep, fuzzed through kappa_J_of_twists and sweep",
    "swerve_like": "a predicate on a checked robot, fuzzed through kappa_J_of_twists",
    "fused_kernel": "as SwerveKappa",
    "kappa_from_gram": "a kernel on SwerveKappa's workspace arrays, fuzzed through kappa_J_of_twists and sweep",
    "kappa_by_lapack": "as kappa_from_gram",
    "in_degrees": "a helper of the kinds' constructors (angle or angle_deg), fuzzed through FixedWheel, SwedishWheel",
    "twist_kind": "a predicate: any value is a valid question",
}


def backend_choose(value, b):
    return backend.choose(value, backend=b)


def _more_roles(name, bot):
    if name == "wheels":
        return (
            [list(bot.wheels), tuple(bot.wheels), (u for u in bot.wheels)],
            [],
            [[], None, "wheels", bot.wheels[0], [bot.wheels[0], 3], 3],
        )
    if name == "square":
        good, odd, bad = _role("matrix", bot)
        return (
            [g for g in good if np.shape(g)[-1] == np.shape(g)[-2]],
            [np.full((3, 3), BIG), np.zeros((0, 0))],
            bad + [good[2]],
        )
    if name == "roller":
        return (
            [np.pi / 2, np.pi / 4, -np.pi / 4, 1, sp.pi / 3, np.float32(0.5)],
            [TINY, 1e-9, -np.pi / 2 + 1e-12],
            [0, 0.0, -np.pi / 2, 2.0, np.pi, -3.0, [0.5]] + BAD_ANY,
        )
    if name == "profile":  # short twist profiles (a simulation per call)
        return (
            [
                swerve.direction_change(t_change=0.02, t_end=0.05, dt=0.01),
                swerve.spin_and_translate(t_start=0.01, t_end=0.03, dt=0.01),
                swerve.TwistProfile("arc", 0.02, np.tile([1.0, 0.5, 0.0], (3, 1))),
            ],
            [
                swerve.TwistProfile("big", 0.01, np.full((2, 3), 1e300)),
                swerve.TwistProfile("tiny", 1e-300, np.full((2, 3), TINY)),
            ],
            [
                "profile",
                None,
                3,
                np.zeros((5, 3)),
                swerve.TwistProfile("nan", 0.01, np.full((2, 3), np.nan)),
                swerve.TwistProfile("empty", 0.01, np.zeros((0, 3))),
                swerve.TwistProfile("dt", -1.0, np.zeros((2, 3))),
            ],
        )
    if name == "strategy":
        return ["plain", "module", "robot"], [], ["wpilib", 3, None, ["robot"]]
    if name == "seed":
        return [0, 7, np.int64(3)], [2**40], [-1, 0.5, "1", None, True, np.nan]
    if name == "no_path":  # dump writes nothing when path is None
        return [None], [], [3, 1.5, b"x", object()]
    if name in ("samples_beta", "samples_angles"):  # four samples of odometry: (4, w), (4, measured joints)
        width = (
            bot.w
            if name == "samples_beta"
            else sum(1 for u in bot.wheels for j in u.joints if j.rate is not None and j.driven and not j.steering)
        )
        good = [np.zeros((4, width)), RNG.uniform(-3, 3, (4, width)), np.cumsum(RNG.uniform(0, 1, (4, width)), axis=0)]
        odd = [
            np.full((4, width), BIG),
            np.array([[BIG] * width, [-BIG] * width] * 2),
            np.full((4, width), TINY),
            np.ones((4, width), dtype=np.float32),
        ]
        bad = [
            np.zeros((1, width)),
            np.zeros(width),
            np.zeros((4, width + 1)),
            np.full((4, width), np.nan),
            np.full((4, width), 1j),
            np.zeros((2, 4, width)),
        ] + BAD_ANY
        return good, odd, bad
    if name == "heading":  # one gyro angle for each of the four samples
        return (
            [None, np.zeros(4), RNG.uniform(-3, 3, 4)],
            [np.full(4, BIG), np.full(4, TINY)],
            [np.zeros(3), np.zeros((4, 1)), np.full(4, np.nan), ["0"] * 4, np.full(4, 1j)]
            + [b for b in BAD_ANY if b is not None],
        )
    if name == "samples":
        return [1, 3, np.int64(2)], [], [0, -1, 1.5, True, "1", None]
    if name in ("pair1", "rates1", "opt_beta1"):
        base = {"pair1": "pair", "rates1": "rates", "opt_beta1": "opt_beta"}[name]
        good, odd, bad = _role(base, bot)
        keep = [g for g in good if g is None or np.ndim(g) == 1]
        return keep, [o for o in odd if np.ndim(o) == 1], bad + [np.zeros((2, np.shape(keep[-1])[-1]))]
    raise KeyError(name)


def role_values(name, bot):
    """(good, odd, bad) for role ``name`` and robot ``bot``."""
    try:
        return _role(name, bot)
    except KeyError:
        return _more_roles(name, bot)


# ---------------------------------------------------------------------------------------- outcomes
FAULTS = ("wrong-exception", "unnamed", "accepted-bad", "non-finite", "hang")


def _finite(value, allow="", seen=0):
    """True when every float in a result (arrays, dataclasses, tuples, dicts) is finite (or allowed: inf, nan)."""
    if seen > 6:
        return True
    if isinstance(value, (float, np.floating, np.ndarray)):
        a = np.asarray(value)
        if a.dtype.kind not in "fc":
            return True
        ok = np.isfinite(a) | (np.isinf(a) if "inf" in allow else False) | (np.isnan(a) if "nan" in allow else False)
        return bool(np.all(ok))
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return all(
            _finite(getattr(value, f.name), allow, seen + 1)
            for f in dataclasses.fields(value)
            if f.name not in ("robot",)
        )
    if isinstance(value, (tuple, list)):
        return all(_finite(v, allow, seen + 1) for v in value)
    if isinstance(value, dict):
        return all(_finite(v, allow, seen + 1) for v in value.values())
    return True


class _Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise _Timeout()


def outcome(case, args, bad, seconds=5):
    """Call ``case`` with ``args`` (``bad``: an argument is a value it must reject); return (outcome, detail)."""
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(seconds)
    try:
        result = case.call(**args)
    except _Timeout:
        return "hang", ""
    except InputError as e:  # the package's own input errors, nothing else
        msg = str(e)
        if not any(re.search(rf"(?<![A-Za-z_]){re.escape(a)}(?![A-Za-z_])", msg) for a in args):
            return "unnamed", f"{type(e).__name__}: {msg[:160]}"
        return "rejected", ""
    except Exception as e:
        if isinstance(e, AttributeError) and str(e).startswith("module 'wmr"):
            return "missing", str(e)  # (measuring an older tree)
        return "wrong-exception", f"{type(e).__name__}: {str(e)[:160]}"
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
    if bad:
        return "accepted-bad", f"(bad: {', '.join(bad)})"
    if not _finite(result, case.allow):
        return "non-finite", ""
    return "returned", ""


def draw(case, rng):
    """Random arguments for ``case``: each argument good (60 %), odd (20 %) or bad (20 %)."""
    pool = [ROBOTS[i] for i in case.robots] if case.robots else ROBOTS
    bot = pool[rng.integers(len(pool))]
    args, bad = {}, []
    for name, role in case.roles:
        good, odd, wrong = role_values(role, bot)
        if name == "robot" and role == "robot":
            good = [bot]
        u = rng.uniform()
        kind = "good" if u < 0.6 or not (odd or wrong) else ("odd" if (u < 0.8 and odd) or not wrong else "bad")
        vals = {"good": good, "odd": odd, "bad": wrong}[kind]
        args[name] = vals[rng.integers(len(vals))]
        if kind == "bad":
            bad.append(name)
    return args, bad


def _show(v):
    text = " ".join(repr(v).split())
    return text if len(text) <= 40 else text[:37] + "..."


def tally(n=12000, seed=0):
    """Outcome counts of ``n`` random calls spread over all cases (and a few examples of each fault)."""
    rng = np.random.default_rng(seed)
    counts: dict = {}
    examples: dict = {}
    for k in range(n):
        case = CASES[k % len(CASES)]
        args, bad = draw(case, rng)
        what, detail = outcome(case, args, bad)
        counts[what] = counts.get(what, 0) + 1
        if what in FAULTS and len(examples.setdefault(what, [])) < 6:
            shown = ", ".join(f"{a}={_show(v)}" for a, v in args.items())
            examples[what].append(f"{case.name}({shown}) {detail}")
    return counts, examples


if __name__ == "__main__":
    import warnings

    warnings.simplefilter("ignore")
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 12000
    counts, examples = tally(n)
    total = sum(counts.values())
    print(
        f"{total} calls over {len(CASES)} public functions:",
        ", ".join(f"{k} {v} ({100 * v / total:.1f} %)" for k, v in sorted(counts.items())),
    )
    for k, ex in examples.items():
        print(f"  {k}:")
        for e in ex:
            print("    " + e)
