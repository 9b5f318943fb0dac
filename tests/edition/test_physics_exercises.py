"""Chapter 9's exercise 9.1 never says "right" when its own physics run disagrees (issue 32): the rank of the
locked-drive system and the MuJoCo run must both say jam."""

from __future__ import annotations

import numpy as np

from edition.physics.exercises import jamming_angles


def test_no_answer_and_malformed_answers_get_a_message_not_a_traceback():
    assert "No answer yet" in jamming_angles(None).message
    assert "degrees" in jamming_angles([1.0, "x", 2.0]).message
    assert not jamming_angles([1.0, 2.0]).passed


def test_a_jam_is_right_only_where_the_model_and_the_physics_engine_agree():
    right = jamming_angles([20.0, 75.0, 140.0])
    assert right.passed and "rank M = 6" in right.message
    equal = jamming_angles([30.0, 30.0, 30.0])  # parallel arms: the dead zone, not a jam
    assert not equal.passed and "rank M = 5" in equal.message
    # the same angles typed in radians: rank 6 in the rigid model, but so near parallel that MuJoCo steers
    radians = jamming_angles(np.radians([20.0, 75.0, 140.0]).tolist())
    assert not radians.passed and "rank M = 6 in the rigid model" in radians.message and "radians" in radians.message
