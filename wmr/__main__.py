"""``python -m wmr``: the same as the ``wmr`` command."""

import sys

from .cli import main

if __name__ == "__main__":  # importing wmr.__main__ (the API reference does) runs nothing
    sys.exit(main())
