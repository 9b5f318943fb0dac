"""``python -m edition.ledger CHAPTERS DEST``: merge the chapters' ledger rows (:func:`edition.ledger.main`)."""
from .store import main

raise SystemExit(main())
