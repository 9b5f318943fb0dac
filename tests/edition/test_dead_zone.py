"""The dead zone that `wmr analyze` reports (wmr.analysis.overview) against the edition's simulation of it."""

import numpy as np

import wmr
from edition.checks.assembly import dead_zone
from wmr.analysis.unit_design import dead_zone_radius


def test_dead_zone_agrees_with_the_simulation():
    bot = wmr.paper_robot("offset", L=0.4, r=0.1, d=0.04)
    sim = dead_zone(bot)
    radius = dead_zone_radius(bot)
    assert radius is not None and np.isclose(sim["radius"], radius, rtol=1e-6)
