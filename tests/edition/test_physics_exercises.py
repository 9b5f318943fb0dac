"""Chapter 9's exercises as answer tables (issue 32): 9.1 is right only where the rank of the locked-drive system and
the MuJoCo run both say jam, so feedback never contradicts the physics it runs; 9.2 is the brake."""

from __future__ import annotations

import numpy as np
import pytest

from edition.exercises.table import junk_cases, malformed_case, missing_case, right_case, verify, wrong_case
from edition.physics.exercises import braking_angles, jamming_angles

TABLE_9_1 = [
    right_case("generic angles", [20.0, 75.0, 140.0], says="rank M = 6"),
    right_case("the solution's", [0.0, 60.0, 150.0], says="In MuJoCo"),
    wrong_case("all equal: the dead zone", [30.0, 30.0, 30.0], says="rank M = 5"),
    # the right angles typed in radians: rank 6 in the rigid model, but so near parallel that MuJoCo steers
    wrong_case(
        "radians for degrees (issue 32)",
        np.radians([20.0, 75.0, 140.0]).tolist(),
        says="rank M = 6 in the rigid model",
        never_says="no motion is possible",
    ),
    malformed_case("two angles", [1.0, 2.0], says="three angles in degrees"),
    missing_case(),
    *junk_cases(),
]

TABLE_9_2 = [
    right_case("axle lines forming a triangle", [10.0, 50.0, 100.0], says="Mobility 0"),
    wrong_case("all parallel", [0.0, 0.0, 0.0], says="Mobility 1"),
    malformed_case("two angles", [1.0, 2.0], says="three angles in degrees"),
    missing_case(),
    *junk_cases(),
]


@pytest.mark.parametrize("case", TABLE_9_1, ids=str)
def test_9_1(case):
    verify(jamming_angles, case)


@pytest.mark.parametrize("case", TABLE_9_2, ids=str)
def test_9_2(case):
    verify(braking_angles, case)
