"""``python -m wmr.paper.ledger CHAPTERS DEST``: merge the chapters' ledger rows (:func:`wmr.paper.ledger.main`)."""
from .store import main

raise SystemExit(main())
