"""A Robot is a frozen value (issue 29): checked once, never changed, so what it keeps cannot go stale.

Also the deprecated ``constants_kept`` and ``cos_sin`` (the half-angle cosine and sine, removed: 1.3x
faster than ``np.cos`` / ``np.sin`` on 10**6 angles, below the 3x a fast path must earn).
"""

import pickle

import numpy as np
import pytest

import wmr
from wmr.analysis import kinematics
from wmr.analysis import reference as R
from wmr.errors import FrozenError, InputError
from wmr.model import platform


def _bot():
    return wmr.Robot([wmr.CentredWheel((1.0, 0.0), r=0.1), wmr.CentredWheel((-1.0, 0.0), r=0.1)], name="two")


@pytest.mark.parametrize(
    "attr, value",
    [
        ("wheels", (wmr.CentredWheel((2.0, 0.0), r=0.1),)),
        ("name", "other"),
        ("rate_slices", (slice(0, 1),)),
        ("mount_points", None),
        ("_J1", None),
        ("anything_new", 1),
    ],
)
def test_assigning_an_attribute_raises_and_changes_nothing(attr, value):
    bot = _bot()
    F0 = bot.F([0.3, -0.2])
    with pytest.raises(FrozenError, match=attr) as info:
        setattr(bot, attr, value)
    assert isinstance(info.value, InputError) and isinstance(info.value, AttributeError)
    assert "new" in str(info.value)  # says what to do instead
    with pytest.raises(FrozenError, match=attr):
        delattr(bot, attr)
    assert bot.name == "two" and bot.w == 2 and bot.n_rates == 2
    np.testing.assert_array_equal(bot.F([0.3, -0.2]), F0)


def test_the_derived_numbers_and_kept_constants_cannot_go_stale():
    bot = _bot()
    J1, points = bot._J1, bot.mount_points
    sol = wmr.forward(bot, [0.0, 0.0], [1.0, 1.0])
    with pytest.raises(FrozenError):
        bot.wheels = (wmr.CentredWheel((5.0, 0.0), r=1.0), wmr.CentredWheel((-5.0, 0.0), r=1.0))
    assert bot._J1 is J1 and bot.mount_points is points  # made once, with the robot
    assert not points.flags.writeable  # and read-only
    assert bot._memo("kinematics", lambda: None) is kinematics._constants(bot)  # kept on the robot
    np.testing.assert_array_equal(wmr.forward(bot, [0.0, 0.0], [1.0, 1.0]).value, sol.value)
    # a robot with other units (a new robot) has its own, right, constants: nothing is keyed by id()
    other = wmr.Robot([wmr.CentredWheel((5.0, 0.0), r=1.0), wmr.CentredWheel((-5.0, 0.0), r=1.0)])
    beta, rates = np.array([0.2, 0.2]), np.array([1.0, 1.0])
    np.testing.assert_allclose(wmr.forward(other, beta, rates).value, R.forward(other, beta, rates)[0], atol=1e-14)
    assert not hasattr(kinematics, "_KEPT")


def test_equality_and_hashing_stay_by_identity():
    a, b = _bot(), _bot()
    assert a == a and a != b and len({a, b, a}) == 2
    assert {a: 1}[a] == 1


def test_a_pickled_robot_is_a_frozen_robot_with_the_same_matrices():
    bot = _bot()
    bot.J([0.1, 0.2])  # something kept
    back = pickle.loads(pickle.dumps(bot))
    np.testing.assert_array_equal(back.J([0.1, 0.2]), bot.J([0.1, 0.2]))
    with pytest.raises(FrozenError):
        back.name = "x"


def test_constants_kept_is_deprecated_and_names_its_replacement():
    bot = _bot()
    with pytest.warns(DeprecationWarning, match="forward/inverse on the robot directly"):
        with kinematics.constants_kept(bot):
            wmr.forward(bot, [0.0, 0.0], [1.0, 1.0])


def test_cos_sin_is_deprecated_and_is_numpys():
    beta = np.random.default_rng(7).uniform(-np.pi, np.pi, 100)
    with pytest.warns(DeprecationWarning, match=r"np\.cos\(beta\), np\.sin\(beta\)"):
        c, s = getattr(platform, "cos_sin")(beta)  # noqa: B009 (kept by wmr.deprecated, not in the module)
    assert np.array_equal(c, np.cos(beta)) and np.array_equal(s, np.sin(beta))


def test_numbers_of_a_robot_with_free_symbols_are_refused_by_the_package():
    """A robot reads the checked floats of its units when made; a free symbol still gets the package's own error."""
    import sympy as sp

    bot = wmr.Robot([wmr.CentredWheel((sp.Symbol("x"), 0.0), r=1.0)])
    with pytest.raises(InputError, match="position must be a number here, got the expression x"):
        _ = bot.mount_points
