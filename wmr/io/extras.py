"""The optional packages of the bridges, imported only when a bridge is used.

``import wmr`` needs NumPy and SymPy only.  Reading or writing URDF needs yourdfpy, ROS 2
parameter files need PyYAML, WPILib objects need robotpy-wpimath; each is an extra of the
distribution (``pip install 'wmr-kinematics[urdf]'``, ``[ros]``, ``[wpilib]``), and a bridge
used without its package raises :class:`~wmr.errors.MissingDependencyError` naming the extra.
"""

from __future__ import annotations

import importlib
from types import ModuleType

from .._version import DISTRIBUTION
from ..errors import MissingDependencyError

__all__ = ["EXTRAS", "require"]

#: extra -> (module imported, distribution on PyPI)
EXTRAS = {
    "urdf": ("yourdfpy", "yourdfpy"),
    "ros": ("yaml", "pyyaml"),
    "wpilib": ("wpimath", "robotpy-wpimath"),
}


def require(extra: str, what: str, module: str | None = None) -> ModuleType:
    """The module of the optional package ``extra`` (or its submodule ``module``), imported now.

    Parameters
    ----------
    extra : str
        A key of :data:`EXTRAS`.
    what : str
        What needs it, for the message (e.g. ``"reading URDF"``).
    module : str, optional
        The module to import (default: the package's top module), e.g. ``"wpimath.kinematics"``.

    Returns
    -------
    module

    Raises
    ------
    wmr.errors.MissingDependencyError
        If the package is not installed (the message names the extra).

    Examples
    --------
    >>> require("ros", "reading ROS 2 parameters").__name__
    'yaml'
    """
    top, dist = EXTRAS[extra]
    try:
        return importlib.import_module(module or top)
    except ImportError as exc:
        raise MissingDependencyError(
            f"{what} needs the package {dist}, which is not installed ({exc}): "
            f"pip install '{DISTRIBUTION}[{extra}]' (or pip install {dist})"
        ) from None
