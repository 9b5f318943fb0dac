"""wmr.plot's geometry helpers, without a figure: body-frame points in the world, a construction line's segment."""

import numpy as np

from wmr.plot.geometry import to_world
from wmr.plot.lines import segment_through


def test_to_world_turns_then_moves():
    assert (to_world((np.pi / 2, 1.0, 0.0), [1.0, 0.0]).round(12) + 0.0).tolist() == [1.0, 1.0]


def test_segment_reaches_the_projection_of_every_point_and_half_a_unit_back():
    assert segment_through((0, 0), (2, 0), include=[(3, 1)], margin=0.0) == (-0.5, 3.0)
