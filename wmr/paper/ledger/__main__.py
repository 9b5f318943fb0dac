"""``python -m wmr.paper.ledger [DIR]``: merge the ledger fragments (:func:`wmr.paper.ledger.main`)."""
from .store import main

raise SystemExit(main())
