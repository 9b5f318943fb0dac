@pytest.mark.parametrize("module", ["model", "run", "experiments", "table"])
def test_doctests_and_docstrings(module):
    import doctest
    import importlib

    mod = importlib.import_module(f"edition.physics.drake.{module}")
    assert mod.__doc__ and mod.__all__
    assert doctest.testmod(mod, optionflags=doctest.ELLIPSIS).failed == 0


@pytest.mark.parametrize("direction", [np.inf, -np.inf], ids=["up", "down"])
def test_a_drake_row_does_not_depend_on_the_last_bits(monkeypatch, direction):
    """The dead zone with point contact, every physical parameter and the robot's size moved by one ulp (as another
    CPU would move them), prints the committed row of engines.csv."""
    import dataclasses

    from edition.physics import common

    for k, v in list(common.SIZE.items()):
        monkeypatch.setitem(common.SIZE, k, float(np.nextafter(v, direction)))
    p = Params()
    nudged = {
        f.name: float(np.nextafter(getattr(p, f.name), direction))
        for f in dataclasses.fields(p)
        if isinstance(getattr(p, f.name), float) and getattr(p, f.name) > 0
    }
    r = X.dead_zone("point", params=Params(**nudged))
    row = next(x for x in T.read_csv(COMMITTED) if x["experiment"] == "dead-zone" and x["contact"] == "point")
    assert (r.measurement, r.verdict) == (row["measurement"], row["verdict"])
