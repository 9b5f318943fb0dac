r"""Numbers as written in files: one rule, so that a file comes out the same on every CPU.

Another CPU computes the same number with arithmetic that differs in the last bits (another ``sin``,
another BLAS kernel), and ``repr`` writes every bit: the same robot would give files differing in the
16th or 17th digit.  Every file wmr writes (URDF, ROS 2 YAML, TOML, MJCF, the command line's
``--json``, the edition's tables) therefore writes its floats through :func:`quantise`, which rounds
them to a decimal grid, and :func:`float_text`:

**The rule.**  A value :math:`x` of a quantity whose scale is :math:`s` (:math:`s = 1` for angles in
radians and dimensionless numbers, :data:`DEGREES` for angles in degrees, the robot's size
(:func:`length_scale`) for its lengths, :math:`|x|` itself when no scale is known) is rounded to
the nearest multiple of the quantum

.. math:: q = 10^{\lfloor \log_{10} \max(|x|, s) \rfloor - 11},

i.e. to :data:`DIGITS` = 12 significant digits and nothing below about :math:`10^{-11} s`
(round-off of a quantity that is zero, e.g. ``6e-17`` for a length of a 0.3 m robot, is written
``0``); :math:`-0` becomes :math:`0`; infinities and NaN are kept.  The text is the shortest
``repr`` of the rounded double, adapted by each format (YAML 1.1 and TOML floats need a ``.``; URDF
drops a trailing ``.0``).  The decade :math:`\lfloor \log_{10} \rfloor` is read from a table of
decimal thresholds, not from ``log10`` (whose last bit is the CPU's), and is the decade of the value
rounded to 12 digits, so that a scale one ulp below a power of ten (``0.09999999999999999``) counts as
that power; the rounding itself is ``rint`` of the value times an exact power of ten, then one division
(IEEE arithmetic, the same on every CPU; vectorised over arrays; Python's correctly rounded
``round`` beyond the 22 exact powers).  Where a quantity needs other digits
its writer says why: MuJoCo's model keeps 12 digits of each value's own size, round-off of a zero
coordinate written 0 (:func:`wmr.sim.bodies.num`), and ``wmr simulate --json`` writes MuJoCo's
measurements with 6 (:mod:`wmr.cli.simulate`).

**Why it holds, and how far.**  Arithmetic on another CPU moves a result by an ulp or a few,
:math:`\sim 10^{-16}` relative; rounding to 12 digits gives a different decimal only when the exact
result lies within that distance of a rounding boundary (a half-quantum), which for a value that is
not a short decimal has a probability of about :math:`10^{-16}/10^{-12} = 10^{-4}` per value.  The
rule makes a changed file improbable, not impossible: the tests (``tests/test_written_files.py``)
write every example robot with its inputs and NumPy's transcendental functions moved one ulp both
ways and compare the bytes with the unperturbed ones and with the committed files.

NumPy only; nothing here knows a file format.
"""

from __future__ import annotations

import functools
from typing import Any

import numpy as np

from ..errors import InputTypeError, InputValueError
from ..model import validation

__all__ = ["DIGITS", "quantise", "float_text"]

#: significant digits a written float keeps (at most; fewer below its scale)
DIGITS = 12
#: the scale of an angle written in degrees: one radian (57.3 deg), as an angle in radians has the scale 1
DEGREES = 180.0 / np.pi
#: the decades :func:`quantise` knows (every finite double lies in them)
_KMIN, _KMAX = -325, 309
#: powers of ten that are exact doubles: the rounding is one multiplication or division by them
_EXACT = np.array([float(f"1e{k}") for k in range(23)])


@functools.lru_cache(maxsize=16)
def _thresholds(digits: int) -> np.ndarray:
    """``T[k - _KMIN]``: the smallest double that rounds to ``10**k`` at ``digits`` digits (a decimal, parsed exactly)."""
    return np.array([float("9" * digits + f"5e{k - digits - 1}") for k in range(_KMIN, _KMAX + 1)])


def _digits(digits):
    if isinstance(digits, bool) or not isinstance(digits, (int, np.integer)):
        raise InputTypeError(f"digits must be an int, got {validation.show(digits)}")
    if not 1 <= digits <= 15:
        raise InputValueError(f"digits must be from 1 to 15 (a double holds 15 decimal digits), got {digits}")
    return int(digits)


def quantise(x: Any, scale: Any = None, digits: int = DIGITS) -> Any:
    r"""``x`` rounded by the rule of written numbers (module notes): the double a file holds for it.

    Vectorised: ``x`` may be an array (any shape), ``scale`` a number or an array broadcast with it.

    Parameters
    ----------
    x : float or array_like
        Real values.
    scale : float or array_like, optional
        The scale :math:`s \ge 0` of the quantity: 1 for angles (rad) and dimensionless numbers, the
        robot's size for lengths (:func:`length_scale`); default :math:`|x|` (``digits`` significant
        digits, whatever the size).
    digits : int, optional
        Significant digits kept of a value at least its scale (default :data:`DIGITS`, at most 15).

    Returns
    -------
    float or numpy.ndarray
        A float for a scalar ``x``, else a float array of its shape: each value the nearest multiple
        of :math:`10^{\lfloor\log_{10}\max(|x|, s)\rfloor - (\text{digits} - 1)}`, no negative zero.

    Raises
    ------
    wmr.errors.InputTypeError
        If ``x`` or ``scale`` is a string, a bool or (``x``) None, or ``digits`` is not an int.
    wmr.errors.InputValueError
        If a value or the scale is not real, a scale is negative or not finite, or ``digits`` is outside 1-15.

    Examples
    --------
    >>> quantise(1.0471975511965976), quantise(1.0471975511965979)      # pi/3 on two CPUs
    (1.0471975512, 1.0471975512)
    >>> quantise(0.1 + 0.2), quantise(-6.123233995736766e-17, scale=1.0)  # round-off below the scale: 0
    (0.3, 0.0)
    >>> quantise(1.2345678901234e-20), quantise(1.2345678901234e-20, scale=0.3)
    (1.23456789012e-20, 0.0)
    >>> quantise([0.25, 123456.789012345678], scale=1.0).tolist()
    [0.25, 123456.789012]
    >>> quantise(0.012345678901234, scale=np.nextafter(0.1, 0)) == quantise(0.012345678901234, scale=0.1)
    True
    """
    n_digits = _digits(digits)
    for name, v in (("x", x), ("scale", scale)):
        if isinstance(v, (str, bytes, bool)) or (v is None and name == "x"):
            raise InputTypeError(f"{name} must be a real number or an array of them, got {validation.show(v)}")
    try:
        a = np.asarray(x, dtype=float)
        s = np.abs(a) if scale is None else np.asarray(scale, dtype=float)
    except (TypeError, ValueError):
        raise InputValueError(
            f"quantise needs real numbers, got x={validation.show(x)}, scale={validation.show(scale)}"
        ) from None
    if scale is not None and not (np.all(np.isfinite(s)) and np.all(s >= 0)):
        raise InputValueError(f"scale must be finite and >= 0, got {validation.show(scale)}")
    finite = np.isfinite(a)
    mag = np.where(finite, np.maximum(np.abs(a), s), 0.0)
    mag = np.where(np.isfinite(mag), mag, 0.0)
    decade = _KMIN - 1 + np.searchsorted(_thresholds(n_digits), mag, side="right")
    places = n_digits - 1 - decade  # decimal places kept
    out = np.where(finite & (mag > 0), 0.0, a)  # infinities and NaN as they are; values of a zero scale: 0
    with np.errstate(over="ignore", invalid="ignore"):
        up = finite & (mag > 0) & (places >= 0) & (places <= 22)
        down = finite & (mag > 0) & (places < 0) & (places >= -22)
        p_up, p_down = _EXACT[np.clip(places, 0, 22)], _EXACT[np.clip(-places, 0, 22)]
        out = np.where(up, np.rint(a * p_up) / p_up, out)
        out = np.where(down, np.rint(a / p_down) * p_down, out)
    rest = finite & (mag > 0) & ~up & ~down  # outside the exact powers of ten: Python's correctly rounded round
    if np.any(rest):
        out = np.array(out, dtype=float)
        out[rest] = [round(float(v), int(n)) for v, n in zip(a[rest], places[rest])]
    out = out + 0.0  # no negative zero
    return float(out) if out.ndim == 0 else out


def float_text(x: Any, scale: Any = None, digits: int = DIGITS) -> str:
    """The text of one written float: the shortest ``repr`` of :func:`quantise` of it.

    Formats adapt it (YAML 1.1 and TOML need a ``.``, URDF drops a trailing ``.0``).

    Parameters
    ----------
    x : float
    scale : float, optional
    digits : int, optional
        As for :func:`quantise`.

    Returns
    -------
    str
        E.g. ``'0.3'``, ``'1e-05'``, ``'0.0'``, ``'inf'``, ``'nan'``.

    Examples
    --------
    >>> float_text(0.1 + 0.2), float_text(-0.0), float_text(2 / 3, digits=3), float_text(1e-5)
    ('0.3', '0.0', '0.667', '1e-05')
    """
    if np.ndim(x) != 0:
        raise InputValueError(f"float_text writes one number, got {validation.show(x)}")
    return repr(quantise(x, scale, digits))


def quantise_all(value: Any, scale: Any = None, digits: int = DIGITS) -> Any:
    """Every float in a nested structure (dicts, lists, tuples, arrays) quantised, as :func:`json.dumps` can write it.

    ``bool``, ``int``, ``str`` and ``None`` are kept; arrays and NumPy scalars become lists and Python numbers.
    """
    if isinstance(value, dict):
        return {k: quantise_all(v, scale, digits) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [quantise_all(v, scale, digits) for v in value]
    if isinstance(value, np.ndarray):
        if value.dtype.kind == "f":
            return quantise(value, scale, digits).tolist() if value.ndim else quantise(value, scale, digits)
        return quantise_all(value.tolist(), scale, digits)
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return quantise(value, scale, digits)
    return value


def length_scale(robot: Any) -> float:
    """The scale of a numeric robot's lengths for :func:`quantise`: its largest mount coordinate or wheel radius."""
    points = np.abs(np.asarray(robot.mount_points, dtype=float))
    radii = [abs(float(u.r)) for u in robot.wheels]
    return float(max(float(points.max(initial=0.0)), *radii))
