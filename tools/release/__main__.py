"""``python -m tools.release``: :func:`tools.release.check.main`."""

import sys

from .check import main

sys.exit(main())
