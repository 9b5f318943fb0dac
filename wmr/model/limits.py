r"""Limits that keep one call from running for hours or taking all the memory, checked before work starts.

============================  =======================  ===========================  ==========================
limit                         default                  environment variable         what it bounds
============================  =======================  ===========================  ==========================
``wheels``                    100                      ``WMR_MAX_WHEELS``           the units of a robot
``configurations``            1,000,000,000            ``WMR_MAX_CONFIGURATIONS``   the configurations of a sweep
``memory_mb``                 1024                     ``WMR_MAX_MEMORY_MB``        a sweep's working memory
============================  =======================  ===========================  ==========================

A check that fails raises :class:`~wmr.errors.LimitError` (an input error: the command line prints
one line and exits with status 2) naming the limit, the size asked for and how to raise it.  The
defaults allow any real robot (a dozen wheels) and sweeps of minutes; a robot file of 10,000 wheels
is refused before it is parsed (:mod:`wmr.io`).

Examples
--------
>>> limit("wheels") >= 100
True
>>> check("wheels", 10_000, "the robot file bot.toml")      # doctest: +ELLIPSIS
Traceback (most recent call last):
    ...
wmr.errors.LimitError: the robot file bot.toml has 10,000 wheel units, more than the limit of 100 (set ...
"""

from __future__ import annotations

import math
import os

from ..errors import InputValueError, LimitError
from .checks import number

__all__ = ["check"]

#: name -> (default, environment variable, what a request is said to have)
LIMITS = {
    "wheels": (100, "WMR_MAX_WHEELS", "has {} wheel units"),
    "configurations": (10**9, "WMR_MAX_CONFIGURATIONS", "has {} configurations"),
    "memory_mb": (1024, "WMR_MAX_MEMORY_MB", "needs {} MB of working memory"),
}


def limit(name: str) -> int:
    """The limit ``name`` (:data:`LIMITS`): its environment variable if set to a positive integer, else the default."""
    if not isinstance(name, str) or name not in LIMITS:
        raise InputValueError(f"name must be one of {', '.join(LIMITS)}, got {name!r}")
    default, env, _ = LIMITS[name]
    text = os.environ.get(env, "").strip().replace("_", "")
    try:
        value = int(float(text)) if text else default
    except ValueError:
        raise InputValueError(f"the environment variable {env} must be a positive whole number, got {text!r}") from None
    if value < 1:
        raise InputValueError(f"the environment variable {env} must be a positive whole number, got {text!r}")
    return value


def check(name: str, amount: float, what: str) -> None:
    """Refuse ``amount`` above the limit ``name``, with a message naming ``what``, the limit and how to raise it.

    Parameters
    ----------
    name : str
        A key of :data:`LIMITS`.
    amount : int or float
        The size asked for (wheel units, configurations, MB).
    what : str
        What asks for it, e.g. ``"the robot file bot.toml"`` or ``"--sample 1e30"``.

    Returns
    -------
    None

    Raises
    ------
    wmr.errors.LimitError
    """
    most = limit(name)
    if isinstance(amount, bool) or not isinstance(amount, int):  # (an int may be beyond a float)
        amount = number("amount", amount)
    if amount <= most:
        return
    _, env, unit = LIMITS[name]
    if amount < 1e15:
        shown, wanted = f"{amount:,.0f}", f"{math.ceil(amount)}"
    else:  # (an int may be beyond a float: its digits)
        digits = str(int(amount))
        shown = wanted = f"{digits[0]}.{digits[1:3]}e+{len(digits) - 1}"
    raise LimitError(
        f"{what} {unit.format(shown)}, more than the limit of {most:,} (set the environment variable "
        f"{env} to raise it, e.g. {env}={wanted})"
    )
