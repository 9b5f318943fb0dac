r"""The ROS 2 drive controllers wmr reads and writes: their parameters, and the layout each expresses.

Parameter names are those of ros2_controllers (jazzy and later; the older names that
steering controllers still accept are read too).  Joint names written are :func:`wmr.io.to_urdf`'s unless given.

==================================  ============  ================================================================
controller (``type``)               layout        parameters (metres)
==================================  ============  ================================================================
``diff_drive_controller``           differential  ``left_wheel_names``, ``right_wheel_names`` (one each),
                                                  ``wheel_separation``, ``wheel_radius``, ``*_multiplier``
``mecanum_drive_controller``        mecanum       ``{front,rear}_{left,right}_wheel_command_joint_name``,
                                                  ``kinematics.wheels_radius``,
                                                  ``kinematics.sum_of_robot_center_projection_on_X_Y_axis``
                                                  :math:`= l_x + l_y`, read as :math:`l_x = l_y`
``omni_wheel_drive_controller``     omni          ``wheel_names``, ``robot_radius``, ``wheel_radius``,
                                                  ``wheel_offset``
``swerve_drive_controller``         swerve (4 on  ``{front,rear}_{left,right}_{wheel,axle}_joint``, ``wheelbase``,
                                    a rectangle)  ``trackwidth``, ``wheel_radius``, ``offset`` (not yet released:
                                                  ros2_controllers' branch ``feature/swerve-drive-controller``)
``bicycle_steering_controller``     bicycle       ``traction_joints_names``, ``steering_joints_names``,
                                                  ``wheelbase``, ``traction_wheel_radius``
``tricycle_steering_controller``    tricycle      the same, ``traction_track_width``, ``traction_wheels_radius``
``ackermann_steering_controller``   ackermann     the same, ``traction_track_width``, ``steering_track_width``,
                                                  ``traction_wheels_radius``
==================================  ============  ================================================================

What the parameters cannot say: a mecanum robot's :math:`l_x` and :math:`l_y` apart (only their
sum; the robot read back is the square with the same kinematics), the radius of a steering
controller's steered wheels (read as the traction radius), passive castors (no controller
commands them), and every other layout (offset or dual units, Swedish wheels off these patterns):
writing such a robot raises :class:`~wmr.errors.InputValueError` saying why.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import InputValueError
from ..model.tolerance import TOL
from .layouts import car, differential, mecanum, omni, rectangle, swerve
from .recognise import rectangle_of
from .ros2_params import Params

__all__: list[str] = []  # the table wmr.io.ros2 reads and writes with


@dataclass(frozen=True)
class Controller:
    """One ROS 2 drive controller: how its parameters make a robot, and a robot's layout its parameters.

    ``name`` is its package (the node name written), ``plugin`` its ``type``, ``layout`` the layout of
    :mod:`wmr.io.layouts` it expresses, ``signature`` the sets of parameters that identify it without a ``type``;
    ``read(params) -> Robot``, ``write(layout, robot, names) -> (parameters, notes)`` with ``names(i, joint)``
    the name of joint ``joint`` of unit ``i`` (1-based).
    """

    name: str
    plugin: str
    layout: str
    signature: tuple
    read: Callable
    write: Callable


def _one_radius(radii, what="the controller"):
    r = np.asarray(radii, dtype=float)
    if np.abs(r - r[0]).max() > TOL * r.max():
        raise InputValueError(f"{what} has one wheel radius; the robot's wheels have radii {r.tolist()}")
    return float(r[0])


def _joint(robot, layout, k, kind, names):
    """The name of the ``kind`` ("steering" or "drive") joint of the layout's k-th wheel: ``names(i, joint)``."""
    i = layout.wheels[k]
    j = next(j for j in robot.wheels[i].joints if (j.steering if kind == "steering" else j.kind == "drive"))
    return names(i + 1, j.name)


# ------------------------------------------------------------------------------------------ diff drive
def _read_diff(p: Params):
    left = p.get("left_wheel_names", "names", "the left wheels' joints")
    right = p.get("right_wheel_names", "names", "the right wheels' joints")
    if len(left) != 1 or len(right) != 1:
        p.fail(
            "left_wheel_names" if len(left) != 1 else "right_wheel_names",
            f"{len(left)} left and {len(right)} "
            "right wheels: the parameters do not say where wheels of one side are along x (a skid-steer "
            "robot); read its URDF instead (wmr.io.from_urdf)",
        )
    sep = p.get("wheel_separation", "positive", "the distance between the wheels in metres, > 0")
    sep *= p.get("wheel_separation_multiplier", "positive", "a factor on wheel_separation", 1.0)
    r = p.get("wheel_radius", "positive", "the wheel radius in metres, > 0")
    return differential(
        sep,
        r * p.get("left_wheel_radius_multiplier", "positive", "a factor on wheel_radius", 1.0),
        r * p.get("right_wheel_radius_multiplier", "positive", "a factor on wheel_radius", 1.0),
    )


def _write_diff(layout, robot, names):
    rl, rr = (float(x) for x in layout.radii)
    out = {
        "left_wheel_names": [_joint(robot, layout, 0, "drive", names)],
        "right_wheel_names": [_joint(robot, layout, 1, "drive", names)],
        "wheel_separation": layout.numbers["track"],
        "wheel_radius": rl,
    }
    if rr != rl:
        out["right_wheel_radius_multiplier"] = rr / rl
    return out, []


# ------------------------------------------------------------------------------------------ mecanum
_MECANUM = ("front_left", "front_right", "rear_left", "rear_right")


def _read_mecanum(p: Params):
    for corner in _MECANUM:
        p.get(f"{corner}_wheel_command_joint_name", "name", f"the {corner.replace('_', ' ')} wheel's joint")
    for axis in ("x", "y", "theta"):
        if p.get(f"kinematics.base_frame_offset.{axis}", "number", "an offset of base_link", 0.0) != 0.0:
            p.fail(
                f"kinematics.base_frame_offset.{axis}",
                "wmr reads mecanum parameters with the base frame at the wheels' centre (offset 0) only",
            )
    r = p.get("kinematics.wheels_radius", "positive", "the wheel radius in metres, > 0")
    k = p.get("kinematics.sum_of_robot_center_projection_on_X_Y_axis", "positive", "lx + ly in metres, > 0")
    return mecanum(rectangle(k, k), r)


def _write_mecanum(layout, robot, names):
    r = _one_radius(layout.radii, "mecanum_drive_controller")
    order, length, width, centre = rectangle_of(layout.positions)
    if order != (0, 1, 2, 3) or np.abs(centre).max() > TOL * np.abs(layout.positions).max():
        raise InputValueError(
            "mecanum_drive_controller needs the wheels on a rectangle about C, front-left and "
            "rear-right rollers at +45 deg; the robot's are not"
        )
    out = {f"{c}_wheel_command_joint_name": _joint(robot, layout, k, "drive", names) for k, c in enumerate(_MECANUM)}
    out["kinematics"] = {
        "base_frame_offset": {"x": 0.0, "y": 0.0, "theta": 0.0},
        "wheels_radius": r,
        "sum_of_robot_center_projection_on_X_Y_axis": length / 2 + width / 2,
    }
    notes = (
        []
        if length == width
        else [
            f"lx = {length / 2!r}, ly = {width / 2!r}: the controller keeps their sum only "
            "(read back as lx = ly, the same kinematics)"
        ]
    )
    return out, notes


# ------------------------------------------------------------------------------------------ omni
def _read_omni(p: Params):
    names = p.get("wheel_names", "names", "the wheels' joints, anticlockwise")
    if len(names) < 3:
        p.fail("wheel_names", f"an omni drive has three or more wheels, got {len(names)}")
    return omni(
        len(names),
        p.get("robot_radius", "positive", "the distance from the centre to the wheels, > 0"),
        p.get("wheel_radius", "positive", "the wheel radius in metres, > 0"),
        p.get("wheel_offset", "number", "the first wheel's angle from x in radians", 0.0),
    )


def _write_omni(layout, robot, names):
    return {
        "wheel_names": [_joint(robot, layout, k, "drive", names) for k in range(len(layout.wheels))],
        "robot_radius": layout.numbers["ring"],
        "wheel_radius": _one_radius(layout.radii),
        "wheel_offset": layout.numbers["offset"],
    }, []


# ------------------------------------------------------------------------------------------ swerve
def _read_swerve(p: Params):
    for corner in _MECANUM:
        p.get(f"{corner}_wheel_joint", "name", f"the {corner.replace('_', ' ')} drive joint")
        p.get(f"{corner}_axle_joint", "name", f"the {corner.replace('_', ' ')} steering joint")
    x, y = p.get("offset", "pair", "the centre's offset from the modules' centre [x, y] in metres", (0.0, 0.0))
    return swerve(
        rectangle(
            p.get("wheelbase", "positive", "the distance between front and rear modules, > 0"),
            p.get("trackwidth", "positive", "the distance between left and right modules, > 0"),
            (-x, -y),
        ),
        p.get("wheel_radius", "positive", "the wheel radius in metres, > 0"),
    )


def _write_swerve(layout, robot, names):
    if len(layout.wheels) != 4:
        raise InputValueError(
            f"swerve_drive_controller has four modules; the robot has {len(layout.wheels)} swerve modules"
        )
    order, length, width, centre = rectangle_of(layout.positions)
    out = {}
    for corner, k in zip(_MECANUM, order):
        out[f"{corner}_wheel_joint"] = _joint(robot, layout, k, "drive", names)
        out[f"{corner}_axle_joint"] = _joint(robot, layout, k, "steering", names)
    out.update(
        {
            "wheelbase": length,
            "trackwidth": width,
            "offset": [-float(centre[0]) + 0.0, -float(centre[1]) + 0.0],
            "wheel_radius": _one_radius(layout.radii),
        }
    )
    return out, []


# ------------------------------------------------------------------------------------------ steering
_STEERED = {"bicycle": 1, "tricycle": 1, "ackermann": 2}


def _steering_reader(layout):
    n_steered, n_traction = _STEERED[layout], 2 if layout != "bicycle" else 1
    one = "" if layout == "bicycle" else "s"

    def read(p: Params):
        new = p.has("traction_joints_names") or not p.has("rear_wheels_names")
        if not new and not p.get("front_steering", "bool", "the front wheels steer", True):  # humble's names
            p.fail("front_steering", "wmr reads front-steered robots only")
        for keys, n, what in (
            (("traction_joints_names", "rear_wheels_names"), n_traction, "traction"),
            (("steering_joints_names", "front_wheels_names"), n_steered, "steering"),
        ):
            names = p.get(keys[0] if new else keys[1], "names", f"the {what} joints (right, left)")
            if len(names) != n:
                p.fail(keys[0] if new else keys[1], f"{layout} steering has {n} {what} joint(s), got {len(names)}")
        base = p.get("wheelbase", "positive", "the distance between the axles in metres, > 0")
        rt = p.first(
            (f"traction_wheel{one}_radius", f"rear_wheel{one}_radius"),
            "positive",
            "the traction wheels' radius in metres, > 0",
        )
        rs = p.get(f"front_wheel{one}_radius", "positive", "the front wheels' radius in metres, > 0", rt)
        if layout == "bicycle":
            return car(base, 0.0, 0.0, rt, rs, name="bicycle")
        t = p.first(
            ("traction_track_width", "wheel_track" if layout == "tricycle" else "rear_wheel_track"),
            "positive",
            "the traction wheels' track in metres, > 0",
        )
        if layout == "tricycle":
            return car(base, t, 0.0, rt, rs, name="tricycle")
        s = p.first(("steering_track_width", "front_wheel_track"), "positive", "the steered wheels' track, > 0", t)
        return car(base, t, s, rt, rs, name="ackermann")

    return read


def _steering_writer(layout_name):
    n_steered = _STEERED[layout_name]

    def write(layout, robot, names):
        steered, traction = range(n_steered), range(n_steered, len(layout.wheels))
        out = {
            "traction_joints_names": [_joint(robot, layout, k, "drive", names) for k in reversed(traction)],
            "steering_joints_names": [_joint(robot, layout, k, "steering", names) for k in reversed(steered)],
            "wheelbase": layout.numbers["wheelbase"],
        }
        rt = _one_radius(layout.radii[n_steered:], "the controller's traction wheels")
        if layout_name != "bicycle":
            out["traction_track_width"] = layout.numbers["traction_track"]
        if layout_name == "ackermann":
            out["steering_track_width"] = layout.numbers["steering_track"]
        out["traction_wheel_radius" if layout_name == "bicycle" else "traction_wheels_radius"] = rt
        notes = (
            [
                f"the steered wheels' radii {layout.radii[:n_steered].tolist()} are not parameters of the "
                "controller (read back as the traction radius)"
            ]
            if np.any(layout.radii[:n_steered] != rt)
            else []
        )
        return out, notes + ["joint lists are (right, left), as the controller expects"]

    return write


#: the controllers, in the order :func:`wmr.io.to_ros2` tries them
CONTROLLERS = {
    c.name: c
    for c in (
        Controller(
            "diff_drive_controller",
            "diff_drive_controller/DiffDriveController",
            "differential",
            (("left_wheel_names", "right_wheel_names"),),
            _read_diff,
            _write_diff,
        ),
        Controller(
            "mecanum_drive_controller",
            "mecanum_drive_controller/MecanumDriveController",
            "mecanum",
            (("front_left_wheel_command_joint_name",),),
            _read_mecanum,
            _write_mecanum,
        ),
        Controller(
            "omni_wheel_drive_controller",
            "omni_wheel_drive_controller/OmniWheelDriveController",
            "omni",
            (("wheel_names", "robot_radius"),),
            _read_omni,
            _write_omni,
        ),
        Controller(
            "swerve_drive_controller",
            "swerve_drive_controller/SwerveController",
            "swerve",
            (("front_left_axle_joint",),),
            _read_swerve,
            _write_swerve,
        ),
        Controller(
            "ackermann_steering_controller",
            "ackermann_steering_controller/AckermannSteeringController",
            "ackermann",
            (("steering_joints_names", "steering_track_width"), ("front_wheel_track",)),
            _steering_reader("ackermann"),
            _steering_writer("ackermann"),
        ),
        Controller(
            "tricycle_steering_controller",
            "tricycle_steering_controller/TricycleSteeringController",
            "tricycle",
            (("steering_joints_names", "traction_track_width"), ("front_wheels_names", "wheel_track")),
            _steering_reader("tricycle"),
            _steering_writer("tricycle"),
        ),
        Controller(
            "bicycle_steering_controller",
            "bicycle_steering_controller/BicycleSteeringController",
            "bicycle",
            (("steering_joints_names", "traction_wheel_radius"), ("front_wheels_names", "rear_wheel_radius")),
            _steering_reader("bicycle"),
            _steering_writer("bicycle"),
        ),
    )
}
