"""Input checks (wmr.model.validation) and the numerical-zero policy (wmr.model.tolerance).
The edition's comparison helpers (edition.verify): tests/edition/test_verify.py.

Every bad input raises the package's own ``InputTypeError`` (wrong kind, a ``TypeError``) or
``InputValueError`` (bad value, a ``ValueError``) of :mod:`wmr.errors`, whose message names the argument
and shows the value.
"""

import warnings

import numpy as np
import pytest
import sympy as sp

import wmr
from wmr.errors import InputTypeError, InputValueError
from wmr.model import validation as V
from wmr.model.tolerance import TOL, near_zero

x = sp.Symbol("x", real=True)
p = sp.Symbol("p", positive=True)

#: the package's own type of each kind of input error
OWN = {ValueError: InputValueError, TypeError: InputTypeError}


# --- scalars ------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "check, value, expected",
    [
        (V.positive, 2, 2),
        (V.positive, 0.5, 0.5),
        (V.positive, np.float32(0.5), 0.5),
        (V.positive, np.array(3.0), 3.0),
        (V.positive, p, p),
        (V.positive, x, x),
        (V.nonnegative, 0, 0),
        (V.nonnegative, 0.0, 0.0),
        (V.nonnegative, p, p),
        (V.real, -3, -3),
        (V.real, np.int64(4), 4),
        (V.real, sp.pi, sp.pi),
    ],
)
def test_scalar_accepted(check, value, expected):
    out = check("v", value)
    assert out == expected
    if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
        assert type(out) is int  # exact, for SymPy products


@pytest.mark.parametrize(
    "check, value, shown, kind",
    [
        (V.positive, 0, "0", ValueError),
        (V.positive, -1.5, "-1.5", ValueError),
        (V.positive, np.nan, "nan", ValueError),
        (V.positive, np.inf, "inf", ValueError),
        (V.positive, True, "True", TypeError),
        (V.positive, "1", "'1'", TypeError),
        (V.positive, 1j, "1j", TypeError),
        (V.positive, [1.0], "[1.0]", TypeError),
        (V.positive, -p, "-p", ValueError),
        (V.positive, sp.oo, "oo", ValueError),
        (V.positive, sp.zoo, "zoo", ValueError),
        (V.positive, sp.nan, "nan", ValueError),
        (V.positive, 10**400, "1000", ValueError),
        (V.positive, np.longdouble("1e400"), "e+400", ValueError),
        (V.positive, sp.Integer(10) ** 400, "1000", ValueError),
        (V.positive, None, "None", TypeError),
        (V.positive, sp.Symbol("s") < 1, "s < 1", TypeError),
        (V.nonnegative, -1e-3, "-0.001", ValueError),
        (V.nonnegative, -np.inf, "inf", ValueError),
        (V.nonnegative, -p, "-p", ValueError),
        (V.real, np.nan, "nan", ValueError),
        (V.real, None, "None", TypeError),
        (V.real, sp.I, "I", ValueError),
        (V.real, x + sp.I, "x + I", ValueError),
        (V.real, np.complex128(1), "1", TypeError),
    ],
)
def test_scalar_rejected_with_name_and_value(check, value, shown, kind):
    with pytest.raises(Exception) as exc:
        check("the_arg", value)
    assert exc.type is OWN[kind], (exc.type, str(exc.value))
    msg = str(exc.value)
    assert "the_arg" in msg and shown in msg, msg


def test_fractions_are_real_numbers():
    from fractions import Fraction

    assert V.positive("r", Fraction(1, 4)) == 0.25
    assert V.finite_array("beta", [Fraction(1, 2), 1]).tolist() == [0.5, 1.0]  # type: ignore[arg-type]  # real numbers


@pytest.mark.parametrize(
    "value, shown, kind",
    [
        ((1.0,), "(1.0,)", ValueError),
        ((1, 2, 3), "(1, 2, 3)", ValueError),
        (1.0, "1.0", TypeError),
        ((np.nan, 0), "nan", ValueError),
        (("a", 0), "'a'", TypeError),
        ((True, 0), "True", TypeError),
        ("ab", "'ab'", TypeError),
        ((sp.oo, 0), "oo", ValueError),
        (None, "None", TypeError),
    ],
)
def test_point_rejected(value, shown, kind):
    with pytest.raises(kind) as exc:
        V.point("position", value)
    assert "position" in str(exc.value) and shown in str(exc.value)


def test_point_accepted():
    assert V.point("position", np.array([1, 2])) == (1.0, 2.0)
    assert V.point("position", (x, 0.5)) == (x, 0.5)


def test_the_small_checks():
    """What the checks' docstrings showed: the text of a value, the kind error, flags, integers, exact numbers."""
    assert V.show(np.zeros(100)) == "array of shape (100,), first values [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, ...]"
    assert str(V.kind_error("r", "0.1", "a real number")) == "r must be a real number, got '0.1' (str)"
    with pytest.raises(InputValueError, match=r"x must be a finite real number, got 1000.*too large for double"):
        V.finite_float("x", 10**400)
    assert V.real("angle", np.float32(0.5)) == 0.5 and V.real("angle", 3) == 3
    assert V.number("angle", sp.pi / 2) == 1.5707963267948966
    assert V.flag("exact", np.True_) is True
    assert V.integer("n", np.int64(3), minimum=1) == 3 and type(V.integer("n", np.int64(3))) is int
    with pytest.raises(InputTypeError, match=r"robot must be a wmr.Robot instance, got the class Robot itself"):
        V.robot(wmr.Robot)


# --- arrays -------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "value, last, shown, kind",
    [
        ([1.0, 2.0], 3, "(2,)", ValueError),
        ([[1.0, 2.0]], 3, "[[1., 2.]]", ValueError),
        (np.zeros((1000, 2)), 3, "(1000, 2)", ValueError),
        (5.0, 3, "()", ValueError),
        ([1.0, np.nan, 2.0], None, "nan", ValueError),
        ([np.inf, -np.inf], None, "inf", ValueError),
        ([[1.0, 2.0], [3.0]], None, "[[1.0, 2.0], [3.0]]", ValueError),
        ([10**400, 1.0], None, "1000", ValueError),
        (
            np.array([np.longdouble("1e400"), 1.0]),
            None,
            "too large" if np.isfinite(np.longdouble("1e400")) else "inf",
            ValueError,
        ),  # 80-bit long double: finite
        ("abc", None, "'abc'", TypeError),
        (["0.7", "0.1"], None, "'0.7'", TypeError),
        ([True, False], None, "True", TypeError),
        ([1j, 2.0], None, "1j", TypeError),
        ([x, 1.0], None, "x", TypeError),
        (None, None, "None", TypeError),
        ([None, 1.0], None, "None", TypeError),
    ],
)
def test_finite_array_rejected(value, last, shown, kind):
    with pytest.raises(kind) as exc:
        V.finite_array("beta", value, last=last)
    assert "beta" in str(exc.value) and shown in str(exc.value), str(exc.value)


def test_finite_array_messages_stay_short():
    with pytest.raises(ValueError) as exc:
        V.finite_array("beta", np.zeros((10**5, 2)), last=3)
    assert len(str(exc.value)) < 200 and "\n" not in str(exc.value)


def test_twists_batches_and_matrices():
    class ChassisSpeeds:  # what WPILib's looks like to wmr
        vx, vy, omega = 1.0, 2.0, 0.5

    assert V.twist_array("twist", ChassisSpeeds()).tolist() == [0.5, 1.0, 2.0]
    assert V.twist_array("twist", [0.5, 1.0, 2.0]).tolist() == [0.5, 1.0, 2.0]
    assert V.batch_shape({"beta": np.zeros((5, 3)), "rates": np.zeros(3)}) == (5,)
    wanted = r"beta and rates must have broadcastable batch shapes, got beta \(2,\) and rates \(4,\)"
    with pytest.raises(InputValueError, match=wanted):
        V.batch_shape({"beta": np.zeros((2, 3)), "rates": np.zeros((4, 3))})
    assert V.symbolic_matrix("M", [[1, x]]).shape == (1, 2)


def test_symbolic_vector():
    assert V.symbolic_vector("beta", [x, 1, 2], 3).shape == (3, 1)
    with pytest.raises(ValueError, match=r"beta must have 3 entries, got shape \(2, 1\)"):
        V.symbolic_vector("beta", [x, 1], 3)
    with pytest.raises(ValueError, match=r"beta\[1\] must be finite, got oo"):
        V.symbolic_vector("beta", [x, sp.oo, 1], 3)
    with pytest.raises(TypeError, match=r"beta must be a sequence of 3 entries, got 1.0"):
        V.symbolic_vector("beta", 1.0, 3)


# --- every public entry point with the classic bad inputs ----------------------------------------
BOT = wmr.paper_robot("centred", L=0.5, r=0.1)
ENTRY_POINTS = [
    ("non-positive radius", lambda: wmr.CentredWheel((0, 0), r=-0.1), "r", "-0.1"),
    ("zero radius, offset wheel", lambda: wmr.OffsetWheel((0, 0), r=0, d=0.1), "r", "0"),
    ("negative offset", lambda: wmr.OffsetWheel((0, 0), r=0.1, d=-0.01), "d", "-0.01"),
    ("NaN radius", lambda: wmr.DualWheel((0, 0), r=np.nan, b=0.1), "r", "nan"),
    ("inf half separation", lambda: wmr.DualWheel((0, 0), r=0.1, b=np.inf), "b", "inf"),
    ("zero wheels", lambda: wmr.Robot([]), "wheels", "0"),
    ("None robot", lambda: wmr.mobility(None, [0.0] * 3), "robot", "None"),  # type: ignore[arg-type]
    ("the class Robot", lambda: wmr.rank_F(wmr.Robot, [0.0] * 3), "robot", "class Robot"),  # type: ignore[arg-type]
    ("name not a string", lambda: wmr.Robot(BOT.wheels, name=3), "name", "3"),  # type: ignore[arg-type]
    ("clockwise not a bool", lambda: wmr.equilateral_mounts(1.0, clockwise="yes"), "clockwise", "'yes'"),  # type: ignore[arg-type]
    ("exact not a bool", lambda: wmr.paper_robot("centred", exact=1), "exact", "1"),  # type: ignore[arg-type]
    ("kind not a string", lambda: wmr.paper_robot(3), "kind", "3"),  # type: ignore[arg-type]
    ("wheel not a unit", lambda: wmr.Robot([BOT.wheels[0], "x"]), "wheels[1]", "'x'"),  # type: ignore[list-item]
    ("complex beta", lambda: wmr.mobility(BOT, np.array([0.1, 0.2, 0.3j])), "beta", "0.3j"),
    ("strings as beta", lambda: wmr.rank_F(BOT, ["0.7"] * 3), "beta", "'0.7'"),
    ("beta with wrong w", lambda: wmr.mobility(BOT, [0.1, 0.2]), "beta", "[0.1, 0.2]"),
    (
        "rates with wrong n",
        lambda: wmr.forward(BOT, [0.1, 0.2, 0.3], [1.0, 2.0, 3.0, 4.0]),
        "rates",
        "[1., 2., 3., 4.]",
    ),
    ("NaN in beta", lambda: BOT.J([0.1, np.nan, 0.3]), "beta", "nan"),
    ("inf in twist", lambda: wmr.inverse(BOT, [0.0] * 3, [np.inf, 0.0, 0.0]), "twist", "inf"),
    ("twist of wrong shape", lambda: wmr.steering_angles(BOT, [[1.0, 2.0]]), "twist", "(1, 2)"),
    ("wrong matrix shape", lambda: wmr.condition_number([1.0, 2.0, 3.0]), "A", "(3,)"),
    ("NaN matrix", lambda: wmr.rank([[np.nan]]), "A", "nan"),
    ("L <= 0", lambda: BOT.J1(L=-2.0), "L", "-2"),
    ("dt <= 0", lambda: wmr.integrate(BOT, [1.0] * 3, [0.0] * 3, 1.0, 0.0), "dt", "0"),
    ("point_velocity shape", lambda: wmr.point_velocity([1.0, 0.0, 0.0], [1.0]), "d", "(1,)"),
]


TYPE_ERRORS = {
    "None robot",
    "the class Robot",
    "name not a string",
    "clockwise not a bool",
    "exact not a bool",
    "kind not a string",
    "wheel not a unit",
    "complex beta",
    "strings as beta",
}


@pytest.mark.parametrize("case, call, name, value", ENTRY_POINTS, ids=[c[0] for c in ENTRY_POINTS])
def test_entry_points_reject_bad_input(case, call, name, value):
    with pytest.raises((TypeError, ValueError)) as exc:
        call()
    assert exc.type is (InputTypeError if case in TYPE_ERRORS else InputValueError), (exc.type, str(exc.value))
    msg = str(exc.value)
    assert name in msg and value in msg, msg


# --- tolerance ----------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "value, scale, expected",
    [
        (1e-12, 1.0, True),
        (1e-8, 1.0, False),
        (1e-8, 1e2, True),
        (1e-10, 1e-6, False),  # relative
        (1e-16, 1e-6, True),
        (2 * TOL, 1.0, False),
        (TOL, 1.0, True),
        (-TOL / 2, 0.0, False),
        (0.0, 0.0, True),
    ],
)
def test_near_zero(value, scale, expected):
    assert bool(near_zero(value, scale)) is expected


def test_column_norms_neither_overflow_nor_divide_by_zero():
    from wmr.model.tolerance import column_norms

    assert column_norms([[3e300, 0.0], [4e300, 0.0]]).tolist() == [5e300, 1.0]


def test_near_zero_broadcasts():
    out = near_zero(np.array([[1e-12, 1.0]]), np.array([[1.0], [1e12]]))
    assert out.tolist() == [[True, False], [True, True]]


# --- the failures quoted in issue 11, part 2 -----------------------------------------------------------
from fractions import Fraction  # noqa: E402

import sympy as _sp  # noqa: E402  (kept local to this section)

_BOT = wmr.paper_robot("centred", L=0.5, r=0.1)
QUOTED = [  # (case, call, exception type, words the message must hold)
    ("complex beta", lambda: wmr.mobility(_BOT, np.array([0.1, 0.2, 0.3]) + 1e-3j), TypeError, ["beta", "complex"]),
    ("strings", lambda: wmr.mobility(_BOT, ["0.7"] * 3), TypeError, ["beta", "'0.7'"]),
    ("bools", lambda: wmr.mobility(_BOT, [True, False, True]), TypeError, ["beta", "booleans"]),
    ("SymPy oo position", lambda: wmr.CentredWheel((_sp.oo, 0), r=0.1), ValueError, ["position", "oo"]),
    ("SymPy nan length", lambda: wmr.CentredWheel((0, 0), r=_sp.nan), ValueError, ["r", "nan"]),
    ("SymPy zoo length", lambda: wmr.DualWheel((0, 0), r=0.1, b=_sp.zoo), ValueError, ["b", "zoo"]),
    ("SymPy I position", lambda: wmr.CentredWheel((_sp.I, 0), r=0.1), ValueError, ["position", "I"]),
    ("long double 1e400", lambda: wmr.CentredWheel((0, 0), r=np.longdouble("1e400")), ValueError, ["r", "e+400"]),  # type: ignore[arg-type]
    ("None robot", lambda: wmr.mobility(None, [0.0] * 3), TypeError, ["robot", "None"]),  # type: ignore[arg-type]
    ("the class Robot", lambda: wmr.rank_F(wmr.Robot, [0.0] * 3), TypeError, ["robot", "class Robot"]),  # type: ignore[arg-type]
    ("empty matrix", lambda: wmr.condition_number(np.empty((3, 0))), ValueError, ["A", "(3, 0)"]),
    ("10**400 entry", lambda: wmr.rank([[10**400, 1], [0, 1]]), ValueError, ["A", "1000000"]),
    (
        "current of the wrong shape",
        lambda: wmr.steering_angles(_BOT, [1.0, 0.0, 0.0], current=[[0.0]]),
        ValueError,
        ["current", "(1, 1)"],
    ),
    (
        "tiny dt",
        lambda: wmr.integrate(_BOT, [1.0] * 3, [0.0] * 3, t_end=0.5, dt=1e-9),
        ValueError,
        ["dt", "max_steps", "5e+08"],
    ),
    ("L = 1e-320", lambda: _BOT.J([0.1, 0.2, 0.3], L=1e-320), ValueError, ["L", "1e-320", "overflow"]),
    ("huge twist", lambda: wmr.inverse(_BOT, [0.0] * 3, [1.7e308] * 3), ValueError, ["twist", "overflow"]),
    (
        "huge rates",
        lambda: wmr.integrate(_BOT, [1.7e308] * _BOT.n_rates, [0.0] * 3, t_end=1.0, dt=0.1),
        ValueError,
        ["rates", "overflow"],
    ),
    ("name not a string", lambda: wmr.Robot(_BOT.wheels, name=["n"]), TypeError, ["name", "['n']"]),  # type: ignore[arg-type]
    ("exact not a bool", lambda: wmr.equilateral_mounts(1.0, exact="yes"), TypeError, ["exact", "'yes'"]),  # type: ignore[arg-type]
    ("clockwise not a bool", lambda: wmr.equilateral_mounts(1.0, clockwise=None), TypeError, ["clockwise", "None"]),  # type: ignore[arg-type]
    ("unused offset of a centred robot", lambda: wmr.paper_robot("centred", d=-1.0), ValueError, ["d", "-1.0"]),
    (
        "unused steer of an offset wheel",
        lambda: wmr.OffsetWheel((0, 0), r=1.0, d=0.5).beta_rate(0.0, [1.0, 1.0], "x"),
        TypeError,
        ["steer", "'x'"],
    ),
]


@pytest.mark.parametrize("case, call, kind, words", QUOTED, ids=[q[0] for q in QUOTED])
def test_quoted_bad_input_is_rejected(case, call, kind, words):
    with pytest.raises(Exception) as exc, warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # no NumPy warning on the way to the error
        call()
    assert exc.type is OWN[kind], (exc.type, str(exc.value))
    assert all(w in str(exc.value) for w in words), str(exc.value)


def test_quoted_inputs_that_are_valid_give_right_finite_answers():
    pts = wmr.equilateral_mounts(1.0, first_deg=1e300)  # three distinct vertices
    assert len({tuple(np.round(p, 12)) for p in pts}) == 3
    assert np.allclose([np.hypot(*p) for p in pts], 1.0)
    assert wmr.CentredWheel((0, 0), r=Fraction(1, 4)).r == 0.25  # type: ignore[arg-type]  # Fractions are real numbers
    assert np.isfinite(wmr.characteristic_length(wmr.paper_robot("centred", L=1e300, r=1e299)))
    sol = wmr.forward(wmr.paper_robot("centred", L=1e300, r=1e299), [0.1, 0.2, 0.3], [1.0, 2.0, 3.0])
    assert np.all(np.isfinite(sol.value))  # (was: "fewer than two mount points")
    with pytest.raises(ValueError, match="max_steps"):
        wmr.integrate(_BOT, [1.0] * 3, [0.0] * 3, t_end=1.0, dt=0.1, max_steps=5)
    assert len(wmr.integrate(_BOT, [1.0] * 3, [0.0] * 3, t_end=1.0, dt=0.1, max_steps=10).t) == 11


def test_the_hint_of_a_near_name_and_the_check_of_a_path():
    from pathlib import Path

    from wmr.model.checks import suggest

    assert suggest("centered", ["centred", "offset"]) == " (did you mean 'centred'?)"
    assert suggest("wheel", ["name"]) == ""
    assert V.file_path("bot.toml") == "bot.toml" and V.file_path(None, optional=True) is None
    assert V.file_path(Path("bot.toml")) == Path("bot.toml")
    with pytest.raises(InputTypeError, match=r"^path must be a file name \(str or os.PathLike\), got 3$"):
        V.file_path(3)
    with pytest.raises(InputTypeError, match=r"^path must be a file name \(str or os.PathLike\) or None, got 3$"):
        V.file_path(3, optional=True)
