"""The shape of the edition's code, read by the library's structure test (tests/test_structure.py) over
``edition/`` together with ``wmr/``: no import cycles through the edition, no private names imported
across its modules (``wmr`` never imports the edition: tests/test_structure.py checks that alone)."""

from conftest import ROOT
from test_structure import WMR, cycles, graph, modules, private_imports

EDITION = modules("edition", root=ROOT)
BOTH = {**WMR, **EDITION}


def test_the_reader_sees_the_edition():
    assert {"edition.transcription", "edition.ledger", "edition.physics.common"} <= set(EDITION)
    assert {"wmr", "wmr.sim"} <= graph(BOTH)["edition.physics.common"]  # edges into the library are seen


def test_no_import_cycles_in_the_edition():
    assert cycles(graph(BOTH)) == []


def test_no_private_names_imported_across_modules_of_the_edition():
    assert private_imports(BOTH) - private_imports(WMR) == set()
