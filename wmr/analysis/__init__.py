r"""Analyses of any robot built with :mod:`wmr.model`.

==================================  ====================================================================================
:mod:`~wmr.analysis.linalg`         rank, nullity, null space, singular values, condition number, determinant
:mod:`~wmr.analysis.sv_decisions`   the two rules that judge singular values: rank and condition number
:mod:`~wmr.analysis.mobility`       rank and nullity of :math:`\mathbf F`, admissible twists (23)-(27)
:mod:`~wmr.analysis.isotropy`       isotropy tests and the characteristic length (30)-(50)
:mod:`~wmr.analysis.kinematics`     forward and inverse kinematics with the slip residual (21)
:mod:`~wmr.analysis.steering`       instantaneous centre and compatible steering angles (60)-(65)
:mod:`~wmr.analysis.integration`    time integration of the kinematics (:func:`wmr.integrate`)
:mod:`~wmr.analysis.lines`          2-D line geometry: intersections, concurrency, circumcircle
:mod:`~wmr.analysis.square`         the square :math:`\mathbf J` of three centred wheels: check, default L, exact robot
:mod:`~wmr.analysis.singularities`  :math:`\det\mathbf J` and the classification of singular configurations (58)-(59)
:mod:`~wmr.analysis.det_exact`      the exact :math:`\det\mathbf J`: SymPy derivation, polynomial, plane-line identity
:mod:`~wmr.analysis.classes`        Campion's classes: degrees of mobility and steerability
:mod:`~wmr.analysis.actuation`      driven and passive joints: actuated mobility, motions with every motor stopped
:mod:`~wmr.analysis.limitations`    what a robot cannot do, as records (class, actuation, steering joints)
:mod:`~wmr.analysis.advice`         design advice checked on the changed robot (move C, choose L, change a wheel)
:mod:`~wmr.analysis.families`       families of singular configurations, one example each
:mod:`~wmr.analysis.unit_design`    each wheel kind's design hints: dead zone, isotropic change, other builds
:mod:`~wmr.analysis.design`         worst-case :math:`\kappa(\mathbf J)` of a layout, search over offset-wheel designs
:mod:`~wmr.analysis.motion_kappa`   :math:`\kappa(\mathbf J)` along the admissible motions (rotations about each centre)
:mod:`~wmr.analysis.sweep`          one analysis over millions of configurations, in chunks
:mod:`~wmr.analysis.overview`       a robot at a glance (what ``wmr analyze`` reports)
:mod:`~wmr.analysis.reference`      the dense reference the fast kernels are checked against
==================================  ====================================================================================

Every function takes a robot; none defaults to the paper's.  The words of the output are made from
these analyses' data in :mod:`wmr.words`.
"""

__all__ = [
    "linalg",
    "sv_decisions",
    "mobility",
    "isotropy",
    "kinematics",
    "steering",
    "integration",
    "lines",
    "square",
    "singularities",
    "det_exact",
    "sweep",
    "reference",
    "classes",
    "design",
    "motion_kappa",
    "overview",
    "actuation",
    "limitations",
    "advice",
    "families",
    "unit_design",
]
