r"""Wheel units: the intermediate body and its wheel(s), each a block of :math:`\mathbf J_2`; one module per kind.

A wheel unit is mounted on the platform at :math:`P_i` (``position`` = :math:`\mathbf d_i`, body frame),
through a vertical steering joint of angle :math:`\beta_i` (the angle of the intermediate body relative
to the platform, :math:`\mathbf R_{bwi}` of (11)) or at a constant angle of its own.  In the wheel frame
:math:`\mathcal W_i`, :math:`\mathbf i_i = \mathbf R_{bwi}[1\ 0]^T` is the axle direction and
:math:`\mathbf j_i = \mathbf R_{bwi}[0\ 1]^T` the rolling direction; the no-slip condition (6) is
:math:`\dot{\mathbf h}_i = -r\dot\theta_i\mathbf j_i` (wheel spin :math:`\dot\theta_i` positive by the
right-hand rule about :math:`\mathbf i_i`, :math:`\mathbf k` upward).

Each unit contributes the block of the no-slip equation
:math:`[\mathbf E\mathbf d_i\ \mathbf 1]\,\mathbf t = \mathbf B_i(\beta_i)\,\dot{\boldsymbol\theta}_i`
(the i-th block row of (21)), :math:`\mathbf B_i = \mathbf R_{bwi}\mathbf L_i`, where
:math:`\dot{\boldsymbol\theta}_i` are its rate variables and :math:`\mathbf L_i` its constant local block.

===================================  ======================================================================
module                               what
===================================  ======================================================================
:mod:`~wmr.model.wheels.unit`        :class:`WheelUnit`, what every kind shares and answers
:mod:`~wmr.model.wheels.registry`    the kinds, registered by being defined (:func:`wheel_kinds`)
:mod:`~wmr.model.wheels.geometry`    a unit's points seen from above
:mod:`~wmr.model.wheels.joints`      the joints of a unit (steer, swivel, drive, roller), driven or passive
:mod:`~wmr.model.wheels.unsteered`   the base of the kinds without a steering joint (a constant angle)
one module per kind                  ``offset``, ``centred``, ``dual``, ``fixed``, ``swedish``, ...
===================================  ======================================================================

**A new kind of wheel** is one module in this package: a frozen dataclass subclassing
:class:`WheelUnit` (or :class:`~wmr.model.wheels.unsteered.UnsteeredUnit`) that sets ``kind``,
``JOINTS`` and its other class attributes (``ANGLES``: which of its parameters are angles) and defines
:meth:`~WheelUnit.local_block` and :meth:`~WheelUnit.beta_rate` (and :meth:`~WheelUnit.steering_row`
where the default does not fit).  Every module of the package is imported with it, and defining the
class registers the kind: :class:`wmr.Robot` and the analyses take it without a change.  The outer
layers hold their own entry per kind, which the contract test asks of every kind: its keys in a robot
file (:func:`wmr.io.wheel_tables.register`), its bodies and joints (:func:`wmr.io.mechanism.root_body`,
or a refusal that says why, as the Swedish wheel's) and its drawing (:func:`wmr.plot.parts.unit_parts`);
its design hints default to none (:mod:`wmr.analysis.unit_design`).  A kind's module imports from the
modules above, never from this package's ``__init__``.

The kinds registered (built from the classes themselves, :func:`wheel_kinds`):
"""

from __future__ import annotations

import importlib
import pkgutil

from .centred import CentredWheel
from .dual import DualWheel
from .fixed import FixedWheel
from .joints import JOINT_KINDS, Joint
from .offset import OffsetWheel
from .registry import wheel_kind, wheel_kinds
from .swedish import SwedishWheel
from .unit import WheelUnit

__all__ = [
    "WheelUnit",
    "Joint",
    "JOINT_KINDS",
    "OffsetWheel",
    "CentredWheel",
    "DualWheel",
    "FixedWheel",
    "SwedishWheel",
    "wheel_kinds",
    "wheel_kind",
]

# a kind is registered by being defined: import every module of this package, so that a new module
# is all a new kind needs
for _info in pkgutil.iter_modules(__path__):
    importlib.import_module(f"{__name__}.{_info.name}")


def kinds_table() -> str:
    r"""An RST table of the registered wheel kinds: name, class, joints (driven or passive) and rates."""
    rows = [("kind", "class", "joints (default actuation)", r"rates :math:`\dot{\boldsymbol\theta}_i`")]
    for name, cls in wheel_kinds().items():
        joints = ", ".join(f"{j.name} ({'driven' if j.driven else 'passive'})" for j in cls.JOINTS)
        rates = r",\ ".join(rf"\dot{tex}_{{i{suffix}}}" if suffix else rf"\dot{tex}_i" for _, tex, suffix in cls.RATES)
        rows.append((f"``{name}``", f":class:`~{cls.__module__}.{cls.__name__}`", joints, f":math:`{rates}`"))
    widths = [max(len(r[k]) for r in rows) for k in range(4)]
    rule = "  ".join("=" * w for w in widths)
    lines = [rule, "  ".join(c.ljust(w) for c, w in zip(rows[0], widths, strict=True)).rstrip(), rule]
    lines += ["  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in rows[1:]]
    return "\n".join(lines + [rule])


__doc__ = (__doc__ or "") + "\n" + kinds_table() + "\n"
