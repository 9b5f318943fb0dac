"""``python -m wmr``: the same as the ``wmr`` command."""
import sys

from .cli import main

sys.exit(main())
