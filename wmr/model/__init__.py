r"""The model: what a wheeled mobile robot *is* (no analysis here).

==============================  ===================================================================================================
:mod:`~wmr.model.backend`       the two backends (NumPy numbers, SymPy symbols) every matrix is built with
:mod:`~wmr.model.tolerance`     the one numerical tolerance
:mod:`~wmr.model.validation`    input checks: ``TypeError`` for the wrong kind, ``ValueError`` for a bad value
:mod:`~wmr.model.arrays`        the same for arrays (finite batches, SymPy vectors and matrices)
:mod:`~wmr.model.platform`      the rigid platform: :math:`\mathbf E`, rotations, :math:`[\mathbf E\mathbf d_i\ \mathbf 1]` (2)-(5)
:mod:`~wmr.model.wheels`        wheel units, each a block of :math:`\mathbf J_2`
:mod:`~wmr.model.wheels_fixed`  wheels without a steering joint: fixed and Swedish (omni, mecanum)
:mod:`~wmr.model.wheel_base`    what every wheel unit shares
:mod:`~wmr.model.robot`         the assembled robot: :math:`\mathbf J_1`, :math:`\mathbf J_2`, :math:`\mathbf F`, :math:`\mathbf J`
:mod:`~wmr.model.robots`        ready-made robots (the paper's three-wheel robots among them)
:mod:`~wmr.model.conventions`   frames, signs and numbering, stated once
==============================  ===================================================================================================
"""

__all__ = ["backend", "tolerance", "validation", "arrays", "platform", "wheel_base", "wheels", "wheels_fixed", "robot", "robots", "conventions"]
