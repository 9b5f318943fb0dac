"""``python -m edition.ledger CHAPTERS... DEST``: the chapters' rows in one ledger (:func:`edition.ledger.main`)."""

from .store import main

raise SystemExit(main())
