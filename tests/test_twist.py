"""wmr.Twist: a twist with its components by name, taken wherever a twist is, and read out in other conventions."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

import wmr
from wmr import swerve
from wmr.errors import InputError

ROBOT = wmr.paper_robot("centred", L=0.3, r=0.05)


def test_a_twist_is_read_by_name_wherever_a_twist_is_taken():
    t = wmr.Twist(vy=-0.2, omega=0.5, vx=1.0)  # by name, in any order
    plain = [0.5, 1.0, -0.2]
    beta = np.array([0.1, 0.2, 0.3])
    assert tuple(t) == (0.5, 1.0, -0.2)
    assert np.array_equal(wmr.inverse(ROBOT, beta, t).value, wmr.inverse(ROBOT, beta, plain).value)
    assert np.array_equal(wmr.steering_angles(ROBOT, t), wmr.steering_angles(ROBOT, plain))
    many = [t, wmr.Twist(0.0, 0.0, 1.0)]
    assert np.array_equal(
        wmr.inverse(ROBOT, np.zeros((2, 3)), many).value, wmr.inverse(ROBOT, np.zeros((2, 3)), [plain, [0, 0, 1]]).value
    )
    cmd, plain_cmd = swerve.module_commands(ROBOT, t), swerve.module_commands(ROBOT, plain)
    assert np.array_equal(cmd.beta, plain_cmd.beta) and np.array_equal(cmd.speed, plain_cmd.speed)


def test_a_twist_from_other_libraries_and_back_in_their_order():
    speeds = SimpleNamespace(vx=1.0, vy=-0.2, omega=0.5)  # what a WPILib ChassisSpeeds(1.0, -0.2, 0.5) holds
    ros = SimpleNamespace(linear=SimpleNamespace(x=1.0, y=-0.2, z=0.0), angular=SimpleNamespace(x=0.0, y=0.0, z=0.5))
    t = wmr.Twist(0.5, 1.0, -0.2)
    assert wmr.Twist.of(speeds) == wmr.Twist.of(ros) == wmr.Twist.of(np.array([0.5, 1.0, -0.2])) == t
    assert t.in_convention("wmr") == (0.5, 1.0, -0.2)
    assert t.in_convention("wpilib") == t.in_convention("ros") == (1.0, -0.2, 0.5)
    assert wmr.Twist.of(speeds) != wmr.Twist(*[1.0, -0.2, 0.5])  # WPILib's order read as wmr's: another twist


def test_bad_twists_are_refused_by_name():
    with pytest.raises(InputError, match="twist"):
        wmr.Twist.of([1.0, 2.0])
    with pytest.raises(InputError, match=r"twist must be one twist \(3,\), got shape \(2, 3\)"):
        wmr.Twist.of([[0.5, 1.0, 0.0], [0.0, 1.0, 0.0]])  # a batch: was numpy's ValueError (reshape)
    with pytest.raises(InputError, match="twist"):
        wmr.inverse(ROBOT, [0.0, 0.0, 0.0], wmr.Twist(0.5, float("nan"), 0.0))
    with pytest.raises(InputError, match="twist"):
        wmr.inverse(ROBOT, [0.0, 0.0, 0.0], wmr.Twist("fast", 1.0, 0.0))  # type: ignore[arg-type]
    with pytest.raises(InputError, match="convention"):
        wmr.Twist(0.0, 1.0, 0.0).in_convention("ROS")


def test_twist_to_and_from_each_convention_by_name():
    """One table (TWIST_ORDER) orders every convention's twist; objects are read by field whatever the convention."""
    from wmr.model.conventions import TWIST_ORDER, twist_from, twist_to

    t = wmr.Twist(omega=0.5, vx=1.0, vy=-0.2)
    batch = np.array([t, [0.0, 2.0, 3.0]])
    for name, order in TWIST_ORDER.items():
        written = twist_to(batch, name)
        assert written[0].tolist() == [t._asdict()[k] for k in order] == list(t.in_convention(name))
        assert np.array_equal(twist_from(written, name), batch)
    speeds = SimpleNamespace(vx=1.0, vy=-0.2, omega=0.5)
    assert twist_from([speeds, speeds], "ros").tolist() == [list(t)] * 2
    assert twist_from(t, "wpilib").tolist() == twist_from([t], "ros")[0].tolist() == list(t)  # named: not reordered


def test_ros_steering_angles_are_headings_from_x():
    """REP-103: a steered wheel's angle is the heading it rolls along (0 forward, 90 degrees left), as WPILib's."""
    from wmr.model.conventions import angle_to

    for twist, heading in (([0.0, 1.0, 0.0], 0.0), ([0.0, 0.0, 1.0], 90.0), ([0.0, -1.0, 0.0], 180.0)):
        beta = swerve.module_commands(ROBOT, twist).beta
        assert np.allclose(np.degrees(angle_to(beta, "ros")), heading, rtol=0, atol=1e-9)
        assert np.array_equal(angle_to(beta, "ros"), angle_to(beta, "wpilib"))
