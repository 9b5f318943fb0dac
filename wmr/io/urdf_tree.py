"""A URDF file as a tree at zero: its joints and links with their lines, each link's pose, each joint's axis.

:class:`UrdfTree` parses the file twice: with lxml (yourdfpy's XML parser) for the line of every
``<joint>`` and ``<link>`` and the checks whose errors should name a line, then with yourdfpy for
the model (origins, axes, geometry).  Every error is a :class:`~wmr.errors.RobotFileError`
``FILE:LINE: key: what is wrong``.  :mod:`wmr.io.urdf_read` reads the robot from it.
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any, NoReturn

import numpy as np

from ..errors import RobotFileError
from ..model.checks import suggest
from ..model.types import ArrayLike, FloatArray
from .extras import require

__all__: list[str] = []  # what wmr.io.urdf_read reads a URDF file with

#: direction components below this are read as zero (URDF files write pi/2 as 1.5708: 3.7e-6 off)
AXIS_SNAP = 1e-3
_MOVING = ("revolute", "continuous", "prismatic", "floating", "planar")


class UrdfTree:
    """One URDF file (``raw`` bytes, ``source`` its name in messages): its joints and links with their lines, at zero.

    ``name`` is the ``<robot name>``, ``joints`` and ``links`` yourdfpy's by name in the file's order, ``root`` the
    platform link, ``commanded`` the joints a ``<ros2_control>`` command interface or a ``<transmission>`` names
    (None without either).
    """

    def __init__(self, raw: bytes, source: str):
        self.source = source
        etree = require("urdf", "reading URDF", "lxml.etree")
        try:
            root = etree.fromstring(raw, etree.XMLParser(remove_comments=True, resolve_entities=False))
        except etree.XMLSyntaxError as exc:
            raise RobotFileError(source, exc.lineno or 1, "xml", f"not well-formed XML: {exc.msg}") from None
        if root.tag != "robot":
            self.fail(root.sourceline, root.tag, "a URDF file's root element must be <robot>")
        if not root.get("name"):
            self.fail(root.sourceline, "robot", "the <robot> element has no name attribute")
        for shape in root.iter("cylinder", "sphere", "box"):
            for attr in {"cylinder": ("radius", "length"), "sphere": ("radius",), "box": ("size",)}[shape.tag]:
                try:
                    values = [float(v) for v in (shape.get(attr) or "").split()]
                except ValueError:
                    values = []
                if not values or not np.isfinite(values).all() or min(values) < 0:
                    what = "numbers" if attr == "size" else "a number"
                    self.fail(
                        shape.sourceline, f"<{shape.tag} {attr}>", f"must be {what} >= 0, got {shape.get(attr)!r}"
                    )
        self.lines = {("robot", ""): root.sourceline or 1}
        for tag in ("link", "joint"):
            for el in root.iter(tag):
                if el.getparent() is root:
                    if not el.get("name"):
                        self.fail(el.sourceline, f"<{tag}>", "has no name attribute")
                    self.lines[(tag, el.get("name"))] = el.sourceline or 1
        self.commanded = self._commanded(root)
        for el in root.findall("joint"):
            self._check_joint(el)
        yourdfpy = require("urdf", "reading URDF")
        try:
            model = yourdfpy.URDF.load(
                io.BytesIO(raw),
                build_scene_graph=False,
                load_meshes=False,
                build_collision_scene_graph=False,
                load_collision_meshes=False,
            )
        except (ValueError, KeyError, AttributeError, TypeError) as exc:  # what yourdfpy raises on bad elements
            self.fail(self.lines[("robot", "")], "robot", f"yourdfpy cannot read it: {exc}")
        self.name = model.robot.name or Path(source).stem
        self.joints = {j.name: j for j in model.robot.joints}
        self.links = {link.name: link for link in model.robot.links}
        self.child_of: dict[str, Any] = {}  # link -> joint whose child it is
        for j in model.robot.joints:
            for end in (j.parent, j.child):
                if end not in self.links:
                    self.fail(
                        self.line("joint", j.name),
                        f"joint {j.name!r}",
                        f"names the link {end!r}, which the file does not define" + suggest(end, self.links),
                    )
            if j.child in self.child_of:
                self.fail(
                    self.line("joint", j.name),
                    f"joint {j.name!r}",
                    f"link {j.child!r} is the child of two "
                    f"joints ({self.child_of[j.child].name!r} too): a URDF is a tree",
                )
            self.child_of[j.child] = j
        roots = [name for name in self.links if name not in self.child_of]
        if len(roots) != 1:
            self.fail(self.lines[("robot", "")], "robot", f"needs one root link (the platform), has {roots or 'none'}")
        self.root = roots[0]
        self.pose = {self.root: np.eye(4)}
        for name in self.links:
            self._pose(name, ())

    def fail(self, line: Any, key: str, reason: str) -> NoReturn:
        """Raise the RobotFileError ``source:line: key: reason``."""
        raise RobotFileError(self.source, int(line or 1), key, reason)

    def line(self, tag: str, name: str) -> int:
        """The line of ``<tag name=name>`` (1 if unknown)."""
        return self.lines.get((tag, name), 1)

    @staticmethod
    def _commanded(root):
        """Joints a ``<ros2_control>`` command interface or a ``<transmission>`` names (None: neither element)."""
        blocks = root.findall("ros2_control") + root.findall("transmission")
        if not blocks:
            return None
        out = set()
        for block in root.findall("ros2_control"):
            out |= {j.get("name") for j in block.findall("joint") if j.find("command_interface") is not None}
        for block in root.findall("transmission"):
            out |= {j.get("name") for j in block.findall("joint")}
        return out

    def _check_joint(self, el):
        """The parts of a ``<joint>`` wmr reads, with the joint's line when one is missing or malformed."""
        name, line = el.get("name"), el.sourceline
        if el.get("type") not in ("fixed",) + _MOVING:
            self.fail(
                line, f"joint {name!r}", f"type must be one of fixed, {', '.join(_MOVING)}, got {el.get('type')!r}"
            )
        for end in ("parent", "child"):
            if el.find(end) is None or not el.find(end).get("link"):
                self.fail(line, f"joint {name!r}", f"has no <{end} link=...>")
        for tag, attr in (("origin", "xyz"), ("origin", "rpy"), ("axis", "xyz")):
            sub = el.find(tag)
            text = sub.get(attr) if sub is not None else None
            if text is not None:
                try:
                    values = [float(v) for v in text.split()]
                except ValueError:
                    values = []
                if len(values) != 3 or not np.isfinite(values).all():
                    self.fail(sub.sourceline, f"joint {name!r} <{tag} {attr}>", f"must be three numbers, got {text!r}")
        axis = el.find("axis")
        if axis is not None and axis.get("xyz") and not np.any([float(v) for v in axis.get("xyz").split()]):
            self.fail(axis.sourceline, f"joint {name!r} <axis xyz>", "must not be zero")

    def _pose(self, link, seen):
        if link in self.pose:
            return self.pose[link]
        j = self.child_of[link]
        if link in seen:
            self.fail(self.line("joint", j.name), f"joint {j.name!r}", "closes a loop: a URDF is a tree")
        origin = np.eye(4) if j.origin is None else np.asarray(j.origin, dtype=float)
        self.pose[link] = self._pose(j.parent, seen + (link,)) @ origin
        return self.pose[link]

    def path(self, joint: str) -> list[Any]:
        """The joints from the root down to ``joint`` (excluded), root first."""
        out, link = [], self.joints[joint].parent
        while link != self.root:
            j = self.child_of[link]
            out.append(j)
            link = j.parent
        return out[::-1]

    def axis(self, joint: str) -> FloatArray:
        """A joint's axis (3,) in the platform frame, unit length, components below AXIS_SNAP set to zero."""
        j = self.joints[joint]
        return snap(self.pose[j.child][:3, :3] @ np.asarray(j.axis, dtype=float))

    def centre(self, joint: str) -> FloatArray:
        """The origin (3,) of a joint (its child link's) in the platform frame."""
        return self.pose[self.joints[joint].child][:3, 3]

    def cylinder(self, joint: str) -> tuple[float | None, Any]:
        """(radius, axis in the platform frame) of the child link's first cylinder, or (None, the shapes it has)."""
        link = self.links[self.joints[joint].child]
        shapes = []
        for item in list(link.collisions) + list(link.visuals):
            g = item.geometry
            if g is not None and g.cylinder is not None:
                frame = self.pose[link.name] @ (np.eye(4) if item.origin is None else np.asarray(item.origin))
                return float(g.cylinder.radius), snap(frame[:3, :3] @ [0.0, 0.0, 1.0])
            shapes += [k for k in ("box", "sphere", "mesh") if g is not None and getattr(g, k) is not None]
        return None, shapes


def snap(v: ArrayLike) -> FloatArray:
    """``v`` (3,) normalised, components below :data:`AXIS_SNAP` set to zero, normalised again."""
    v = np.asarray(v, dtype=float)
    v = v / np.linalg.norm(v)
    v = np.where(np.abs(v) < AXIS_SNAP, 0.0, v)
    return v / np.linalg.norm(v)


def is_vertical(a: FloatArray) -> bool:
    """True for a unit axis along +-z (within :data:`AXIS_SNAP`)."""
    return bool(abs(abs(a[2]) - 1.0) <= AXIS_SNAP)


def is_horizontal(a: FloatArray) -> bool:
    """True for a unit axis in the xy plane (within :data:`AXIS_SNAP`)."""
    return bool(abs(a[2]) <= AXIS_SNAP)
