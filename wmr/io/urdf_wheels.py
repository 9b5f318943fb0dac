r"""The wheels of a URDF file (:mod:`wmr.io.urdf_read` states the rules): which joints are wheels, and each
wheel's centre, axle, radius, steering joint and rollers, checked as they are read.

Every error names the file, the line of the joint or link and what is wrong (:meth:`~wmr.io.urdf_tree.UrdfTree.fail`).
"""

from __future__ import annotations

import numpy as np

from .urdf_tree import AXIS_SNAP, UrdfTree, is_horizontal, is_vertical, suggest

__all__: list[str] = []  # what wmr.io.urdf_read reads the wheels with


def find_wheels(rd: UrdfTree, wheel_joints):
    """The wheel joints of a file, in its order: ``[(joint name, radius or None)]``.

    ``wheel_joints`` names them ``{joint name: radius or None}``; None: every horizontal ``continuous`` joint whose
    link has a cylinder, rollers below a wheel excepted.
    """
    if wheel_joints is not None:
        out = []
        for name, radius in wheel_joints.items():
            if name not in rd.joints:
                rd.fail(
                    rd.line("robot", ""),
                    f"joint {name!r}",
                    "wheel_joints names a joint the file does not define" + suggest(name, rd.joints),
                )
            out.append((name, radius))
        order = list(rd.joints)
        return sorted(out, key=lambda item: order.index(item[0]))
    out, seen = [], []
    for name, j in rd.joints.items():
        if j.type != "continuous" or not is_horizontal(rd.axis(name)):
            continue
        if any(p.name in {w for w, _ in out} for p in rd.path(name)):
            continue  # a roller of a wheel above it
        radius, shapes = rd.cylinder(name)
        if radius is None:
            seen.append((name, shapes))
            continue
        out.append((name, None))
    rollers_of = {w for w, _ in out}
    for name, shapes in seen:
        if not any(p.name in rollers_of for p in rd.path(name)):
            what = f"a {shapes[0]}" if shapes else "no geometry"
            rd.fail(
                rd.line("joint", name),
                f"joint {name!r}",
                f"turns about a horizontal axis like a wheel, but its "
                f"link {rd.joints[name].child!r} has {what}, no <cylinder>: wmr reads a wheel's radius from its "
                f"cylinder; name the wheel joints and radii instead (wheel_joints={{{name!r}: RADIUS, ...}}, on "
                f"the command line --wheel-joints {name}=RADIUS,...)",
            )
    return out


def read_wheel(rd: UrdfTree, name, radius):
    """One wheel joint read and checked (``radius`` None: its cylinder's), in the platform frame.

    Returns ``(centre (3,), axle (3,), radius, steering joint or None, rollers' angle or None)``.
    """
    j, line, key = rd.joints[name], rd.line("joint", name), f"joint {name!r}"
    if j.type not in ("continuous", "revolute"):
        rd.fail(line, key, f"a wheel joint must be continuous (or revolute), got {j.type!r}")
    axle = rd.axis(name)
    if not is_horizontal(axle):
        rd.fail(
            line,
            key,
            f"a wheel's axis must be horizontal (the platform's z is up), got {axle.round(6).tolist()} "
            "in the platform frame",
        )
    cyl_r, cyl_axis = rd.cylinder(name)
    if radius is None:
        if cyl_r is None:
            what = f"a {cyl_axis[0]}" if cyl_axis else "no geometry"
            rd.fail(
                rd.line("link", j.child),
                f"link {j.child!r}",
                f"the wheel of joint {name!r} has {what}, no <cylinder>: give its radius ({name}=RADIUS)",
            )
        if np.linalg.norm(np.cross(cyl_axis, axle)) > AXIS_SNAP:
            rd.fail(
                rd.line("link", j.child),
                f"link {j.child!r}",
                f"its cylinder lies along "
                f"{cyl_axis.round(6).tolist()}, not along the axis of its joint {name!r} "
                f"({axle.round(6).tolist()}): a wheel's cylinder lies along its axle (turn its <origin rpy>)",
            )
        radius = cyl_r
    if not radius > 0:
        rd.fail(rd.line("link", j.child), f"link {j.child!r}", f"the wheel's radius must be positive, got {radius!r}")
    steering = None
    for p in rd.path(name):
        if p.type == "fixed" or p.type == "prismatic":
            continue
        if p.type in ("revolute", "continuous") and is_vertical(rd.axis(p.name)):
            if steering is not None:
                rd.fail(
                    rd.line("joint", p.name),
                    f"joint {p.name!r}",
                    f"a second steering joint above wheel joint {name!r} (after {steering!r}): a wheel unit has one",
                )
            steering = p.name
            continue
        rd.fail(
            rd.line("joint", p.name),
            f"joint {p.name!r}",
            f"a {p.type} joint about "
            f"{rd.axis(p.name).round(6).tolist()} between the platform and wheel joint {name!r}: only a vertical "
            "steering joint (and prismatic suspension) can be there",
        )
    return rd.centre(name), axle, float(radius), steering, roller_angle(rd, name, axle)


def rollers_below(rd: UrdfTree, wheel):
    """The continuous joints below the wheel joint ``wheel`` (its rollers), in the file's order."""
    return [n for n, j in rd.joints.items() if j.type == "continuous" and wheel in {p.name for p in rd.path(n)}]


def roller_angle(rd: UrdfTree, wheel, axle):
    r"""The angle :math:`\gamma` in :math:`(-\pi/2, \pi/2]` of the rollers below a wheel to its unit ``axle``.

    None when it has no rollers; the rollers are checked to agree.
    """
    below = rollers_below(rd, wheel)
    gammas = []
    for name in below:
        a = rd.axis(name)
        p = rd.centre(name) - rd.centre(wheel)
        p = p - (p @ axle) * axle
        if np.linalg.norm(p) == 0:
            rd.fail(
                rd.line("joint", name),
                f"joint {name!r}",
                f"a roller of wheel {wheel!r} on its axle: rollers sit on the rim",
            )
        t = np.cross(axle, p / np.linalg.norm(p))  # the rim's direction of motion at the roller
        g = float(np.arctan2(a @ t, a @ axle))
        g = g - np.pi if g > np.pi / 2 + AXIS_SNAP else g + np.pi if g <= -np.pi / 2 + AXIS_SNAP else g  # a line
        gammas.append((name, g))
    if not gammas:
        return None
    name0, g0 = gammas[0]
    for name, g in gammas[1:]:
        if abs(g - g0) > AXIS_SNAP:
            rd.fail(
                rd.line("joint", name),
                f"joint {name!r}",
                f"roller at {np.degrees(g):.6g} deg to the axle, "
                f"{name0!r} at {np.degrees(g0):.6g} deg: the rollers of one wheel are all at one angle",
            )
    if abs(g0) <= AXIS_SNAP:
        rd.fail(rd.line("joint", name0), f"joint {name0!r}", "rollers parallel to the axle roll nothing")
    return g0
