"""The rule of written numbers (wmr.io.decimals): what it keeps, what it drops, and that the last bits do not reach it."""

import numpy as np
import pytest

from wmr.errors import InputTypeError, InputValueError
from wmr.io.decimals import DIGITS, float_text, quantise, quantise_all

RNG = np.random.default_rng(28)
#: values of every size and sign, none of them a short decimal
VALUES = RNG.normal(size=20000) * 10.0 ** RNG.integers(-30, 30, 20000)


def _digits(text):
    """Significant digits of a float's text."""
    return len(text.split("e")[0].replace("-", "").replace(".", "").strip("0"))


def test_twelve_digits_the_nearest_and_a_fixed_point():
    q = quantise(VALUES)
    assert max(_digits(repr(float(v))) for v in q) <= DIGITS
    half = 0.5 * 10.0 ** (np.floor(np.log10(np.abs(VALUES))) - (DIGITS - 1))
    assert np.all(np.abs(q - VALUES) <= half * (1 + 1e-9))
    assert np.array_equal(quantise(q), q)  # what is read back is written again the same
    # the same as Python's correctly rounded decimal formatting, but for double rounding near a tie
    assert np.mean(q != np.array([float(f"{v:.{DIGITS - 1}e}") for v in VALUES])) < 1e-3


def test_below_the_scale_is_zero_and_no_negative_zero():
    assert quantise(-6.123233995736766e-17, 1.0) == 0.0 and float_text(-6.123233995736766e-17, 1.0) == "0.0"
    assert float_text(-0.0) == "0.0" and float_text(-1e-30, 1e-3) == "0.0"
    assert quantise(1.2345678901234e-3, 0.3) == 1.23456789e-3  # a multiple of 1e-12 (0.3: decade -1): 9 digits
    assert quantise([np.inf, -np.inf]).tolist() == [np.inf, -np.inf] and np.isnan(quantise(np.nan))


def test_one_ulp_rarely_changes_the_text():
    """A one-ulp change crosses a rounding boundary only within ~1e-16 of it: rarely (about 1e-4 of values), not never."""
    q = quantise(VALUES)
    for direction in (np.inf, -np.inf):
        assert np.mean(quantise(np.nextafter(VALUES, direction)) != q) < 1e-3
    # the scale counts by its decade as written: one ulp below a power of ten is that power
    x = 0.012345678901234
    for s in (0.1, 1.0, 1000.0):
        assert quantise(x, np.nextafter(s, 0)) == quantise(x, s) == quantise(x, np.nextafter(s, 2 * s))


def test_arrays_scalars_and_structures_agree():
    v = VALUES[:50]
    assert [quantise(float(x), 0.3) for x in v] == quantise(v, 0.3).tolist()
    assert quantise(v.reshape(5, 10), 0.3).shape == (5, 10)
    assert quantise_all({"a": (v[0], 2, True, "s", None), "b": np.array([[v[1]]])}) == {
        "a": [quantise(v[0]), 2, True, "s", None],
        "b": [[quantise(v[1])]],
    }
    assert float_text(2 / 3, digits=3) == "0.667" and float_text(1e22 / 3) == "3.33333333333e+21"


@pytest.mark.parametrize(
    "args, error",
    [
        (("0.3",), InputTypeError),
        ((None,), InputTypeError),
        ((0.3, "1"), InputTypeError),
        ((0.3, -1.0), InputValueError),
        ((0.3, np.inf), InputValueError),
        ((0.3, np.nan), InputValueError),
        ((0.3, None, 16), InputValueError),
        ((0.3, None, 2.5), InputTypeError),
        ((1j,), InputValueError),
    ],
)
def test_bad_input_gets_the_package_s_errors(args, error):
    with pytest.raises(error):
        quantise(*args)


def test_float_text_writes_one_number():
    with pytest.raises(InputValueError, match="one number"):
        float_text([1.0, 2.0])


def test_every_float_of_a_structure_and_a_robot_s_length_scale():
    import wmr
    from wmr.io.decimals import length_scale

    out = quantise_all({"a": [0.1 + 0.2, 3], "b": np.array([1e-17, 2.0]), "c": "x"}, scale=1.0)
    assert out == {"a": [0.3, 3], "b": [0.0, 2.0], "c": "x"}
    assert length_scale(wmr.paper_robot("centred", L=0.3, r=0.05)) == 0.3
