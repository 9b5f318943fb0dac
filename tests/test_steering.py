"""wmr.analysis.steering: the instantaneous centre (62)-(64) and compatible steering angles."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import wmr
from wmr.analysis import steering as Sg

from conftest import (
    angle_close,
    axle,
    check_positive_rolling,
    rigid_velocity,
    robots,
    rolling_dir,
    seeds,
    transform_twist,
)


@given(seeds)
def test_centre_has_zero_velocity(seed):
    t = np.random.default_rng(seed).normal(size=(20, 3))
    ic = wmr.instantaneous_centre(t)
    assert np.all(ic.kind == Sg.FINITE)
    assert np.allclose(wmr.point_velocity(t, ic.point), 0.0, atol=1e-10)  # (62)
    assert np.allclose(rigid_velocity(t[:, 0], t[:, 1:], ic.point), 0.0, atol=1e-10)
    assert np.allclose(np.linalg.norm(ic.direction, axis=-1), 1.0)
    # the direction points from C towards U
    assert np.all(np.sum(ic.direction * ic.point, -1) > 0)


@pytest.mark.parametrize(
    "twist, length, kind",
    [
        ([0.0, 1.0, 2.0], None, Sg.AT_INFINITY),
        ([1e-12, 1.0, 0.0], 1.0, Sg.AT_INFINITY),  # the centre 1e12 robot sizes away
        ([1e-12, 1.0, 0.0], 1e6, Sg.FINITE),  # ... but only 1e6 sizes of a bigger robot
        ([1e-12, 1.0, 0.0], None, Sg.FINITE),  # no size given: no tolerance
        ([0.0, 0.0, 0.0], None, Sg.STILL),
        ([1e-300, 0.0, 0.0], 1.0, Sg.FINITE),  # a (slow) spin is not rest
        ([1.0, 0.0, 0.0], 1.0, Sg.FINITE),
        ([-2.0, 3.0, 0.0], None, Sg.FINITE),
    ],
)
def test_centre_kinds(twist, length, kind):
    ic = wmr.instantaneous_centre(twist, length=length)
    assert int(ic.kind) == kind
    if kind == Sg.AT_INFINITY:
        assert np.all(np.isinf(ic.point))
        c = np.asarray(twist[1:])
        assert np.allclose(ic.direction, np.cross([0, 0, 1], [*c, 0])[:2] / np.linalg.norm(c))
    elif kind == Sg.STILL:
        assert np.all(np.isnan(ic.point)) and np.all(np.isnan(ic.direction))
    else:
        assert np.allclose(wmr.point_velocity(twist, ic.point), 0.0)


def test_centre_known_value_and_batch():
    ic = wmr.instantaneous_centre([[1.0, 0.0, 2.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0], [2.0, 0.0, 0.0]])
    assert ic.kind.tolist() == [Sg.FINITE, Sg.AT_INFINITY, Sg.STILL, Sg.FINITE]
    assert np.allclose(ic.point[0], [-2.0, 0.0]) and np.allclose(ic.point[3], [0.0, 0.0])


@given(robots(kinds=("centred", "dual")), seeds)
def test_steering_angles_wheel_planes_and_axles(bot, seed):
    t = np.random.default_rng(seed).normal(size=3)
    beta = wmr.steering_angles(bot, t)
    assert beta.shape == (bot.w,) and np.all(np.abs(beta) <= np.pi)
    vP = rigid_velocity(t[0], t[1:], bot.mount_points)
    j = rolling_dir(beta)
    speed = np.linalg.norm(vP, axis=-1)
    moving = speed > 1e-6
    # wheel plane parallel to the velocity, rolling forwards: j = -p_dot / |p_dot|
    assert np.allclose(j[moving], -vP[moving] / speed[moving, None], atol=1e-9)
    # equivalently the axle points at the instantaneous centre (cross product zero)
    U = wmr.instantaneous_centre(t).point
    u = U - bot.mount_points
    cross = axle(beta)[:, 0] * u[:, 1] - axle(beta)[:, 1] * u[:, 0]
    assert np.allclose(cross[moving], 0.0, atol=1e-8 * max(1.0, np.abs(u).max()))
    check_positive_rolling(bot, t)


def test_steering_angles_keep_current_where_free():
    bot = wmr.Robot(
        [wmr.CentredWheel((0, 0), r=0.1), wmr.OffsetWheel((1, 0), r=0.1, d=0.05), wmr.CentredWheel((0, 1), r=0.1)]
    )
    current = np.array([0.3, -0.7, 1.1])
    spin = wmr.steering_angles(bot, [1.0, 0.0, 0.0], current=current)  # wheel 1 sits at U = C
    assert spin[0] == 0.3 and spin[1] == -0.7
    assert np.isclose(spin[2], -np.pi / 2)  # axle (0, -1): from (0, 1) towards U = C
    still = wmr.steering_angles(bot, [0.0, 0.0, 0.0], current=current)
    assert np.array_equal(still, current)


@given(robots(), seeds, st.tuples(st.floats(-2, 2), st.floats(-2, 2)), st.floats(-np.pi, np.pi))
def test_steering_angles_do_not_depend_on_body_frame(bot, seed, origin, angle):
    t = np.random.default_rng(seed).normal(size=3)
    a = wmr.steering_angles(bot, t)
    b = wmr.steering_angles(bot.moved(origin, angle), transform_twist(t, origin, angle), current=np.full(bot.w, -angle))
    assert angle_close(b, a - angle, atol=1e-7)


def test_translation_steers_all_wheels_parallel():
    bot = wmr.paper_robot("dual", r=0.1)
    beta = wmr.steering_angles(bot, [0.0, 0.0, 1.0])  # along +y
    assert np.allclose(rolling_dir(beta), [0.0, -1.0])  # j = -c_dot / |c_dot|


@given(seeds)
def test_centre_to_wheels(seed):
    rng = np.random.default_rng(seed)
    t, d = rng.normal(size=(5, 3)), rng.normal(size=(4, 2))
    u = wmr.centre_to_wheels(t, d)
    assert u.shape == (5, 4, 2)
    assert np.allclose(u, wmr.instantaneous_centre(t).point[:, None, :] - d)  # (64)


BAD = [
    (lambda: wmr.instantaneous_centre([1.0, 2.0]), "twist", "(2,)"),
    (lambda: wmr.instantaneous_centre([1.0, np.nan, 0.0]), "twist", "nan"),
    (lambda: wmr.steering_angles(wmr.paper_robot(), [1.0, 0.0, 0.0], current=[0.0]), "current", "(1,)"),
    (lambda: wmr.steering_angles(wmr.paper_robot(), [1.0, 0.0]), "twist", "(2,)"),
    (lambda: wmr.centre_to_wheels([0.0, 1.0, 0.0], [[0.0, 0.0]]), "twist", "[0.0, 1.0, 0.0]"),
    (lambda: wmr.centre_to_wheels([1.0, 1.0, 0.0], [[0.0, 0.0, 1.0]]), "d", "(1, 3)"),
]


@pytest.mark.parametrize("call, name, value", BAD)
def test_bad_input(call, name, value):
    with pytest.raises(ValueError) as exc:
        call()
    assert name in str(exc.value) and value in str(exc.value), str(exc.value)
