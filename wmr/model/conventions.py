r"""Conventions used everywhere in :mod:`wmr` (stated once, here).

The drawing is ``figures/conventions.svg`` (made by :func:`edition.figures.conventions`).

Frames
    :math:`\mathcal F` is fixed, :math:`\mathcal B` is attached to the platform with origin at the
    operation point C; :math:`\psi` is the angle from :math:`\mathbf i_{\mathcal F}` to :math:`\mathbf i`,
    counter-clockwise positive seen from above (:math:`\mathbf k` points up).  All angles are in
    radians and counter-clockwise positive.
Twist
    :math:`\mathbf t = [\dot\psi\ \dot x\ \dot y]^T` with :math:`\dot{\mathbf c} = [\dot x\ \dot y]^T`
    in **body-frame** components (25); the fixed-frame velocity is :math:`[\dot X\ \dot Y]^T =
    \mathbf R(\psi)\dot{\mathbf c}`.  :math:`\mathbf t_L = [L\dot\psi\ \dot{\mathbf c}^T]^T` (33).
Mount points
    :math:`\mathbf d_i = \overrightarrow{CP_i}` in the body frame; :math:`P_i` lies on the steering axis.
Wheel frame
    :math:`\beta_i` is the angle of the intermediate body relative to the platform,
    :math:`\mathbf R_{bwi} = \mathbf R(\beta_i)` (11); :math:`\mathbf i_i = \mathbf R_{bwi}[1\ 0]^T` is
    the axle (axis of rolling), :math:`\mathbf j_i = \mathbf R_{bwi}[0\ 1]^T` the rolling direction in
    the wheel plane.  The absolute steering angle is :math:`\phi_i = \psi + \beta_i` (8).
Rolling
    :math:`\dot\theta_i` is the wheel's spin about :math:`\mathbf i_i` (right-hand rule); no slip
    gives :math:`\dot{\mathbf h}_i = -r\dot\theta_i\mathbf j_i` (6).
Offset
    The wheel centre of an offset wheel is :math:`H_i = P_i - d\,\mathbf j_i` (:math:`d \ge 0`), which
    gives (9) with the printed signs.
Dual wheel
    Wheel 1 at :math:`H_i + b\,\mathbf i_i`, wheel 2 at :math:`H_i - b\,\mathbf i_i`, :math:`H_i = P_i`.
Fixed and Swedish wheels
    No steering joint: :math:`\beta_i` is the unit's constant ``angle`` (0: axle along the body x
    axis), and the robot's configuration entry for the unit is ignored
    (:meth:`wmr.Robot.effective_beta`).  A Swedish wheel's rollers are at ``roller`` =
    :math:`\gamma` from the axle, counter-clockwise (:math:`\pi/2` omni, :math:`\pm\pi/4` mecanum);
    its second rate :math:`\dot\sigma_i` moves the hub along the rollers' rolling direction
    (:class:`wmr.SwedishWheel`).
Numbering
    Wheels are numbered in the order given to :class:`wmr.Robot`.  The paper's three-wheel robot
    (:func:`wmr.paper_robot`) has :math:`\mathbf d_1 = L(-1,0)`, :math:`\mathbf d_2 = L(\tfrac12,
    \tfrac{\sqrt3}2)`, :math:`\mathbf d_3 = L(\tfrac12,-\tfrac{\sqrt3}2)`: numbered clockwise from
    the negative x-axis, the one placement under which the printed (59) holds.
Tolerance
    One numerical zero, :data:`wmr.model.tolerance.TOL`, always relative: every decision is the same
    in every unit of length and time (how: :mod:`wmr.model.tolerance`).
Errors
    ``TypeError`` for the wrong kind of argument, ``ValueError`` for a bad value; the message
    names the argument and shows the value (:mod:`wmr.model.validation`).

Where things live
-----------------
Four layers, each importing only from the ones above it; ``import wmr`` loads the first two (no
matplotlib, pandas or IPython).

:mod:`wmr.model`
    What a robot *is*: the backends (NumPy numbers, SymPy symbols; :mod:`~wmr.model.backend`), the
    tolerance, the input checks (:mod:`~wmr.model.validation` for numbers and points,
    :mod:`~wmr.model.arrays`, :mod:`~wmr.model.robot_checks`), the platform (:math:`\mathbf E`,
    :math:`\mathbf R(\beta)` and the wheel block :math:`\mathbf R(\beta)\mathbf M = \cos\beta\,\mathbf M +
    \sin\beta\,\mathbf E\mathbf M` of (11), :func:`wmr.model.platform.rotated`), batched trigonometry
    (:mod:`~wmr.model.trig`), the wheel units, the assembled :class:`wmr.Robot` (:math:`\mathbf J_1,
    \mathbf J_2, \mathbf F, \mathbf J`), ready-made robots (:mod:`~wmr.model.robots`), and these
    conventions.
:mod:`wmr.analysis`
    What can be computed for *any* robot (every function takes one; none defaults to the
    paper's): linear algebra, mobility, Campion's classes (:mod:`~wmr.analysis.classes`), isotropy,
    kinematics, steering, simulation, singularities and the exact :math:`\det\mathbf J`; the packages :mod:`~wmr.analysis.lines` (``geometry``: 2-D
    lines, concurrency, circumcircle; ``robot``: a robot's axle and wheel-plane lines) and
    :mod:`~wmr.analysis.sweep` (``configurations``, ``analyses``, ``reduction``, ``execute`` in this
    process or on Dask, ``result``); design searches (:mod:`~wmr.analysis.design`), a robot at a
    glance (:mod:`~wmr.analysis.overview`), and the dense reference the fast kernels are checked
    against (:mod:`~wmr.analysis.reference`).
:mod:`wmr.swerve`, :mod:`wmr.io`
    Beside the analyses: swerve-drive practice (module states, limits, optimisation) and robot
    files (TOML in, TOML out).
:mod:`wmr.plot`
    Drawing with matplotlib (imported only there): the style, annotations and the robot seen
    from above (its world geometry, computed without matplotlib, in :mod:`~wmr.plot.geometry`).
:mod:`edition`
    The edition of the paper: its printed forms (one module per chapter, ``register``/``printed``),
    symbols, the ledger of verdicts (:mod:`~edition.ledger`: ``verdict``, ``markup``, ``rows``,
    ``store``), the checks (:mod:`~edition.checks`: one package per chapter, one module per
    equation group), the exercises (one module per chapter), the singular families, the figures
    (:mod:`~edition.figures`: one module per figure, each a ``data`` function returning a data
    class and a ``draw`` function taking it), the interactive chapter (``state``, ``draw``,
    ``describe``, ``widgets``) and the notebook helpers (:mod:`~edition.notebook`).  Where its
    files are written is always passed in.
:mod:`wmr.cli`
    The ``wmr`` command line: one module per command (:data:`wmr.cli.COMMANDS`).
``tools/build`` (in the repository, not in the installed package)
    The build of the edition: paths and stamps, cached parallel execution of the notebooks, the
    ledger merge, report assembly and export (HTML, PDF), and its command line
    (``python -m tools.build``).
"""

__all__ = []
