"""The implementation helpers of wmr.analysis.linalg and kinematics (their examples, kept as tests)."""

import numpy as np

from wmr.analysis.kinematics import pinv_columns
from wmr.analysis.linalg import left_null_space


def test_pinv_columns_keeps_a_column_small_only_next_to_the_others():
    out = pinv_columns(np.array([[1e12, 0.0], [0.0, 1.0], [0.0, 0.0]])) * [1e12, 1, 1]
    assert out.round(12).tolist() == [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]


def test_left_null_space_of_a_centred_wheel_block():
    assert left_null_space([[0.0], [-2.0]]).round(12).tolist() == [[1.0], [0.0]]  # no slip along i
