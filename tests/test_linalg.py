"""The implementation helpers of wmr.analysis.linalg (their examples, kept as tests)."""

import numpy as np

from wmr.analysis.linalg import gram, left_null_space, pinv_columns


def test_pinv_columns_keeps_a_column_small_only_next_to_the_others():
    out = pinv_columns([[1e12, 0.0], [0.0, 1.0], [0.0, 0.0]]) * [1e12, 1, 1]
    assert out.round(12).tolist() == [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]


def test_left_null_space_of_a_centred_wheel_block():
    assert left_null_space([[0.0], [-2.0]]).round(12).tolist() == [[1.0], [0.0]]  # no slip along i


def test_gram():
    assert gram([[1.0, 2.0], [0.0, 1.0]]).tolist() == [[1.0, 2.0], [2.0, 5.0]]
    assert np.shape(gram(np.ones((4, 3, 2)))) == (4, 2, 2)
