"""The version of :mod:`wmr`, written once: the build reads it (``pyproject.toml``,
``[tool.setuptools.dynamic]``), ``wmr.__version__`` and ``wmr --version`` show it.

The distribution that provides the import package ``wmr`` and the command ``wmr`` is
``wmr-kinematics`` (``pip install wmr-kinematics``); the unrelated distribution called ``wmr``
ships a top-level package of the same name and must not be installed beside it.
"""

__version__ = "0.1.0"

#: the name of the distribution (``pip install`` / ``pip show``); pyproject.toml's ``[project] name``
DISTRIBUTION = "wmr-kinematics"
