r"""The model: what a wheeled mobile robot *is* (no analysis here).

==============================  ==================================================================================
:mod:`~wmr.model.backend`       the two backends (NumPy numbers, SymPy symbols) every matrix is built with
:mod:`~wmr.model.tolerance`     the one numerical tolerance, and the column scaling ranks are decided with
:mod:`~wmr.model.types`         the types of the public API's arguments and results (annotations)
:mod:`~wmr.model.checks`        input checks of scalars, points and arrays (:mod:`wmr.errors`: wrong kind, bad value)
:mod:`~wmr.model.validation`    every input check under one name (what the analyses import), robots' too
:mod:`~wmr.model.platform`      the platform: :math:`\mathbf E`, rotations, :math:`[\mathbf E\mathbf d_i\ \mathbf 1]`
:mod:`~wmr.model.trig`          batched sums of :math:`\cos\beta_i` and :math:`\sin\beta_i` terms
:mod:`~wmr.model.wheels`        wheel units, each a block of :math:`\mathbf J_2`; a module per kind, answering for it
:mod:`~wmr.model.robot`         the assembled robot: :math:`\mathbf J_1, \mathbf J_2, \mathbf F, \mathbf J`
:mod:`~wmr.model.robots`        ready-made robots (the paper's three-wheel robots among them)
:mod:`~wmr.model.conventions`   frames, signs, numbering and the layout of the project, stated once
==============================  ==================================================================================
"""

__all__ = [
    "backend",
    "tolerance",
    "types",
    "checks",
    "validation",
    "platform",
    "trig",
    "wheels",
    "robot",
    "robots",
    "conventions",
]
