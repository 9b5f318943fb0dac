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

__all__: list[str] = []  # what the bridges import their optional packages with

#: extra -> (module imported, distribution on PyPI)
EXTRAS = {
    "urdf": ("yourdfpy", "yourdfpy"),
    "ros": ("yaml", "pyyaml"),
    "wpilib": ("wpimath", "robotpy-wpimath"),
}


def require(extra: str, what: str, module: str | None = None) -> ModuleType:
    """The module of the optional package ``extra`` of :data:`EXTRAS` (or its submodule ``module``), imported now.

    Without the package, a MissingDependencyError names ``what`` needs it and the extra to install.
    """
    top, dist = EXTRAS[extra]
    try:
        return importlib.import_module(module or top)
    except ImportError as exc:
        raise MissingDependencyError(
            f"{what} needs the package {dist}, which is not installed ({exc}): "
            f"pip install '{DISTRIBUTION}[{extra}]' (or pip install {dist})"
        ) from None
