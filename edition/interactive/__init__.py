r"""The interactive chapter (``notebooks/07_interactive_robot``): a robot to steer, and mount points to place.

Computing, drawing and the widgets are apart, as in :mod:`edition.figures`:

* :func:`steering_state` -- the numbers of one configuration of a three-centred-wheel robot: the
  steering angles (given, or set by :func:`wmr.steering_angles` for a commanded twist), where the
  axle lines and the wheel-plane lines meet, :math:`\det\mathbf J`, :math:`\operatorname{rank}\mathbf F`,
  :math:`\kappa(\mathbf J)` and the admissible twist.  :func:`mount_state` does the same for a
  placement of three mount points and :math:`\kappa(\mathbf J_{L1})`.  No matplotlib, no widgets.
* :func:`draw_steering`, :func:`draw_mounts` -- one :class:`matplotlib.figure.Figure` of a state;
  :func:`describe_steering`, :func:`describe_mounts` -- its numbers as Markdown.
* :class:`SteeringExplorer`, :class:`MountExplorer` -- ipywidgets around them.  ``show()`` displays
  the controls and then the picture and the numbers as ordinary image and Markdown outputs, which
  the controls update in place (``display_id``).  Run headless (nbconvert, the report), the saved
  outputs are one representative state that needs no widget JavaScript.

The parts: :mod:`~edition.interactive.state` (the numbers), :mod:`~edition.interactive.draw`
(the figures), :mod:`~edition.interactive.describe` (the Markdown) and
:mod:`~edition.interactive.widgets` (the explorers).
"""

from .describe import describe_mounts, describe_steering
from .draw import draw_mounts, draw_steering, png
from .state import MountState, SteeringState, mount_state, steering_state
from .widgets import MountExplorer, SteeringExplorer

__all__ = [
    "SteeringState",
    "MountState",
    "steering_state",
    "mount_state",
    "draw_steering",
    "draw_mounts",
    "describe_steering",
    "describe_mounts",
    "SteeringExplorer",
    "MountExplorer",
    "png",
]
