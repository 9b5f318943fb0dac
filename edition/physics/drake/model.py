r"""A :class:`wmr.Robot` as a Drake MultibodyPlant: the same bodies, masses, joints and servos as :mod:`wmr.sim`.

The plant is built programmatically from the units' mechanisms (:func:`wmr.sim.bodies.mechanisms`: each unit's bodies
and joints as data), the data :mod:`wmr.sim` writes as MJCF, with the same :class:`wmr.sim.Params`:

* the platform, a free body whose frame is wmr's body frame (C on the mount plane, at the height of the largest
  wheel radius), a uniform plate of ``platform_mass`` over the mount points (the MJCF's inertia, its centre of mass
  at their centroid); each unit's bodies on revolute joints, an intermediate body of ``body_mass`` (a small cube's
  inertia), a wheel of ``wheel_mass`` (a thin disk's);
* a servo on every driven joint, Drake's implicit PD control (inside SAP, with its effort limit): steering with the
  MJCF's gain :math:`k_p` = ``steer_kp`` times its limit ``steer_torque`` :math:`W r`, damping :math:`k_d =
  2\zeta\sqrt{k_p I}` (:math:`I` the mass matrix's diagonal at the joint, MuJoCo's ``dampratio``), fed the target
  angle and rate; drive with :math:`k_p = 0`, :math:`k_d` = ``drive_kv`` times ``drive_torque`` :math:`W r`.  A
  free drive has no actuator; a locked drive is a weld (``locked_drives``);
* contact (:data:`CONTACTS`): **point**, each wheel a rigid sphere of its radius touching a rigid half space at one
  point (MuJoCo's geometry), compliant by a stiffness that sinks a wheel :data:`SINK` of its radius under a third of
  the weight, with Hunt--Crossley dissipation :data:`DISSIPATION`; or **hydroelastic**, each wheel a compliant
  cylinder of its radius and width :data:`WIDTH` times it (the drawn disk of the MJCF) of hydroelastic modulus
  ``modulus`` on a rigid half space, tessellated at :func:`resolution` (:data:`RESOLUTION` times its radius at
  :math:`E = 10^7` Pa, finer for a stiffer wheel, whose patch is shorter): a contact *patch* whose
  pressure and friction are integrated over its area, so that a wheel spinning about the vertical meets a friction
  torque that no coefficient sets.  Both: Coulomb friction :math:`\mu_s = \mu_d` = ``sliding``; no torsional
  coefficient and no rolling resistance (Drake has neither); Drake's discrete SAP solver at the step :data:`STEP`,
  not MuJoCo's ``timestep`` (chapter 9, Section 9.10: why, and what changes at 1 ms).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

import wmr
from wmr.sim import Params
from wmr.sim.bodies import height_of, mechanisms, servo
from wmr.sim.params import GRAVITY

__all__ = ["CONTACTS", "DISSIPATION", "MODULI", "RESOLUTION", "SINK", "STEP", "WIDTH", "Plant", "build", "resolution"]

#: the two contact models
CONTACTS = ("point", "hydroelastic")
#: the hydroelastic moduli run (Pa): a stiff rubber and a ten times stiffer tread
MODULI = (1e7, 1e8)
#: a compliant wheel's width, in wheel radii (the MJCF's drawn disk)
WIDTH = 0.5
#: the tessellation of a compliant wheel: Drake's resolution hint, in wheel radii
RESOLUTION = 0.1
#: point contact: a wheel under a third of the weight sinks this fraction of its radius (sets the stiffness)
SINK = 0.005
#: Hunt--Crossley dissipation of both contact models, s/m
DISSIPATION = 10.0
#: the time step of Drake's discrete plant, s
STEP = 0.002
#: a warning Drake gives for every rigid half space (about deformable bodies, which these models have none of)
_DEFORMABLE = "Rigid (non-deformable) half spaces are not currently supported for deformable contact"


def _pd():
    import logging

    import pydrake.all as d

    logger = logging.getLogger("drake")
    if not any(getattr(f, "wmr", False) for f in logger.filters):
        quiet = logging.Filter()
        quiet.filter = lambda record: not str(record.getMessage()).startswith(_DEFORMABLE)  # type: ignore[method-assign]
        quiet.wmr = True  # type: ignore[attr-defined]
        logger.addFilter(quiet)
    return d


@dataclass
class Plant:
    """A built Drake model of a robot, ready to simulate.

    Attributes
    ----------
    robot : Robot
    params : Params
    contact : str
        ``"point"`` or ``"hydroelastic"``.
    modulus : float
        The hydroelastic modulus, Pa (0 for point contact).
    diagram, plant, simulator, context, plant_context : pydrake objects
    weight, height, mass : float
        :math:`W = m g` (N); the height of C above the ground at rest; the robot's mass (kg).
    servo_names : tuple of str
        The actuators, in Drake's order, named as :mod:`wmr.sim` names them (``u<i>_<joint>``).
    limit : numpy.ndarray
        Their effort limits, N m.
    steering : numpy.ndarray of bool
        Which actuators are steering (position) servos.
    joints : dict
        Name -> Drake joint, every unit's joint.
    wheels : list of tuple
        ``(unit index, Drake body, radius)`` for every wheel.
    platform : pydrake body
    target : pydrake InputPort or None
        The desired-state input of the servos (:meth:`Plant.command`).
    push_port : pydrake InputPort
        The plant's applied spatial force input (:meth:`Plant.push`).
    """

    robot: Any
    params: Params
    contact: str
    modulus: float
    diagram: Any
    plant: Any
    simulator: Any
    context: Any
    plant_context: Any
    weight: float
    height: float
    mass: float
    servo_names: tuple
    limit: np.ndarray
    steering: np.ndarray
    joints: dict
    wheels: list
    platform: Any
    target: Any
    push_port: Any

    def command(self, q, v):
        """Set the servos' targets: angles (rad; ignored by drive servos) and rates (rad/s), in actuator order.

        Parameters
        ----------
        q, v : array (number of servos,)

        Returns
        -------
        None
        """
        if self.target is not None:
            self.target.FixValue(self.context, np.r_[np.asarray(q, float), np.asarray(v, float)])

    def push(self, force):
        """Push the platform at C with a horizontal force (N, world frame), held until changed.

        Parameters
        ----------
        force : pair

        Returns
        -------
        None
        """
        d = _pd()
        f = d.ExternallyAppliedSpatialForce()
        f.body_index = self.platform.index()
        f.p_BoBq_B = np.zeros(3)
        f.F_Bq_W = d.SpatialForce(np.zeros(3), np.r_[np.asarray(force, float), 0.0])
        self.push_port.FixValue(self.plant_context, [f])

    def positions(self, names):
        """Joint angles, rad.

        Parameters
        ----------
        names : iterable of str

        Returns
        -------
        numpy.ndarray
        """
        return np.array([self.joints[n].get_angle(self.plant_context) for n in names])


def _inertia(mass, com, moments):
    d = _pd()
    return d.SpatialInertia.MakeFromCentralInertia(mass, np.asarray(com, float), d.RotationalInertia(*moments))


def resolution(modulus, r):
    r"""Drake's resolution hint for a compliant wheel of radius ``r`` and hydroelastic modulus ``modulus``.

    Under a load :math:`N` a compliant cylinder sinks by :math:`\delta` with :math:`N \propto E\,\delta^{3/2}`, and its
    patch is :math:`2\sqrt{2 r\delta} \propto E^{-1/3}` long: the hint, :data:`RESOLUTION` times ``r`` at
    :math:`E = 10^7` Pa, shrinks as :math:`E^{-1/3}`, so that the patch spans as many elements at every modulus (at
    :math:`10^8` Pa with the hint of :math:`10^7` Pa, the patch was two elements long and the dual wheel's torque moved
    by 5 % when the parameters moved by one ulp).

    Parameters
    ----------
    modulus : float
        Pa.
    r : float
        m.

    Returns
    -------
    float
        m.

    Examples
    --------
    >>> round(resolution(1e7, 0.05), 6), round(resolution(1e8, 0.05), 6)
    (0.005, 0.002321)
    """
    return RESOLUTION * r * (1e7 / modulus) ** (1 / 3)


def _platform_inertia(robot, params, height):
    """The MJCF's platform inertia (:func:`wmr.sim.mjcf._platform`): a plate over the mount points' bounding box."""
    P = robot.mount_points
    lo, hi = P.min(axis=0), P.max(axis=0)
    size = np.maximum(hi - lo, 0.2 * max(float(np.abs(P).max()), height))
    t = 0.1 * float(size.min())
    a, b = size
    m = params.platform_mass
    com = P.mean(axis=0)
    return _inertia(
        m, (com[0], com[1], 0.0), (m * (b * b + t * t) / 12, m * (a * a + t * t) / 12, m * (a * a + b * b) / 12)
    )


def _props(params, contact, modulus, r, weight):
    """A wheel's proximity properties: friction, dissipation, and its point stiffness or hydroelastic modulus."""
    d = _pd()
    props = d.ProximityProperties()
    k = None if contact == "hydroelastic" else (weight / 3) / (SINK * r)
    d.AddContactMaterial(DISSIPATION, k, d.CoulombFriction(params.sliding, params.sliding), props)
    if contact == "hydroelastic":
        d.AddCompliantHydroelasticProperties(resolution(modulus, r), modulus, props)
    return props


def build(
    robot,
    beta=None,
    params=None,
    contact="point",
    modulus=MODULI[0],
    servos=True,
    free_drives=False,
    locked_drives=False,
    ramp=None,
):
    """The Drake model of ``robot`` at rest on the ground with steering angles ``beta`` (module docstring).

    Parameters
    ----------
    robot : Robot
        Units with mechanisms (:mod:`wmr.sim`: not Swedish wheels).
    beta : array (w,), optional
        Steering angles at the start (default 0).
    params : Params, optional
    contact : {"point", "hydroelastic"}
    modulus : float
        The wheels' hydroelastic modulus, Pa (hydroelastic contact only).
    servos : bool
        Servos on the driven joints (False: none at all).
    free_drives : bool
        No servo on the drive joints (switched off, free to turn).
    locked_drives : bool
        Every drive joint a weld: the drives locked (the paper's Section 4.2), rigidly, as MuJoCo's lock (a joint
        equality) holds them.  (Drake 1.51's :meth:`Joint.Lock` crashed SAP on this plant, so the lock is built in.)
    ramp : tuple (dict, float), optional
        ``(rates, until)``: the servos named in ``rates`` (rad/s) are commanded from their starting angle at that
        rate until ``until`` seconds, then held; the others hold their start (rate 0).  The targets come from a
        trajectory source in the diagram, a step ahead (Drake's PD acts on the state at the end of the step), so
        that no Python runs between samples.  Without it the targets are fixed (:meth:`Plant.command`).

    Returns
    -------
    Plant
    """
    if contact not in CONTACTS:
        raise ValueError(f"contact must be one of {CONTACTS}, got {contact!r}")
    d = _pd()
    p = params or Params()
    robot = wmr.Robot(robot.wheels, name=robot.name) if not isinstance(robot, wmr.Robot) else robot
    beta0 = robot.effective_beta(np.zeros(robot.w) if beta is None else np.asarray(beta, float))
    height = height_of(robot)
    mechs = mechanisms(robot, height)
    n_wheels = sum(len(m.wheels) for m in mechs)
    n_bodies = sum(len(m.bodies) for m in mechs) - n_wheels
    mass = p.total_mass(n_bodies, n_wheels)
    W = mass * GRAVITY

    builder = d.DiagramBuilder()
    plant, scene = d.AddMultibodyPlantSceneGraph(builder, time_step=STEP)
    plant.set_discrete_contact_approximation(d.DiscreteContactApproximation.kSap)
    plant.set_contact_model(d.ContactModel.kHydroelastic if contact == "hydroelastic" else d.ContactModel.kPoint)
    platform = plant.AddRigidBody("platform", _platform_inertia(robot, p, height))
    ground = d.ProximityProperties()
    d.AddContactMaterial(DISSIPATION, None, d.CoulombFriction(p.sliding, p.sliding), ground)
    if contact == "hydroelastic":
        d.AddRigidHydroelasticProperties(ground)
    plant.RegisterCollisionGeometry(plant.world_body(), d.RigidTransform(), d.HalfSpace(), "ground", ground)

    joints, wheels, actuators = {}, [], []
    for i, (u, m) in enumerate(zip(robot.wheels, mechs)):

        def add(body, parent, i=i, u=u):
            name = f"u{i + 1}_{body.name}"
            if body.wheel is None:
                s = body.size
                inertia = _inertia(p.body_mass, (0, 0, 0), (p.body_mass * s * s / 6,) * 3)
            else:
                rw = body.wheel
                inertia = _inertia(
                    p.wheel_mass, (0, 0, 0), (p.wheel_mass * rw * rw / 2, *(p.wheel_mass * rw * rw / 4,) * 2)
                )
            b = plant.AddRigidBody(name, inertia)
            X = d.RigidTransform(d.RotationMatrix.MakeZRotation(body.angle), np.asarray(body.pos, float))
            F = plant.AddFrame(d.FixedOffsetFrame(f"{name}_mount", parent.body_frame(), X))
            if body.joint is None or (locked_drives and body.joint.kind == "drive"):
                plant.WeldFrames(F, b.body_frame())
            else:
                jn = f"u{i + 1}_{body.joint.name}"
                joints[jn] = plant.AddJoint(d.RevoluteJoint(jn, F, b.body_frame(), np.asarray(body.axis, float)))
                kind = servo(body.joint)
                if servos and kind is not None and not (free_drives and body.joint.kind == "drive"):
                    limit = (p.steer_torque if body.joint.steering else p.drive_torque) * W * float(u.r)
                    actuators.append((jn, body.joint.steering, limit, plant.AddJointActuator(jn, joints[jn], limit)))
            if body.wheel is not None:
                rw = body.wheel
                props = _props(p, contact, modulus, rw, W)
                if contact == "hydroelastic":
                    shape, X_BG = (
                        d.Cylinder(rw, WIDTH * rw),
                        d.RigidTransform(d.RotationMatrix.MakeYRotation(np.pi / 2)),
                    )
                else:
                    shape, X_BG = d.Sphere(rw), d.RigidTransform()
                plant.RegisterCollisionGeometry(b, X_BG, shape, name, props)
                wheels.append((i, b, rw))
            for c in body.children:
                add(c, b)

        add(m.root, platform)

    plant.Finalize()
    q0 = {}
    for i, m in enumerate(mechs):
        for j in m.joints:
            q0[f"u{i + 1}_{j.name}"] = float(beta0[i]) if j.steering else 0.0
    desired = plant.get_desired_state_input_port(d.default_model_instance())
    if actuators and ramp is not None:
        rates, until = ramp
        a0 = np.array([q0[a[0]] for a in actuators])
        v = np.array([float(rates.get(a[0], 0.0)) for a in actuators])
        h = STEP
        times = np.array([0.0, until - h, until - h + 1e-9, until + 1.0])
        rate = (v, v, 0 * v, 0 * v)  # the rates, held until the end of the ramp, then zero
        values = np.array([np.r_[a0 + v * min(t + h, until), w] for t, w in zip(times, rate)]).T
        source = builder.AddSystem(d.TrajectorySource(d.PiecewisePolynomial.FirstOrderHold(times, values)))
        builder.Connect(source.get_output_port(), desired)
    elif actuators:
        builder.ExportInput(desired, "target")
    diagram = builder.Build()
    simulator = d.Simulator(diagram)
    context = simulator.get_mutable_context()
    pc = plant.GetMyMutableContextFromRoot(context)
    plant.SetFreeBodyPose(pc, platform, d.RigidTransform(np.array([0.0, 0.0, height])))
    for jn, q in q0.items():
        if jn in joints:
            joints[jn].set_angle(pc, q)
    M = plant.CalcMassMatrix(pc)
    for jn, steering, limit, act in actuators:
        if steering:
            kp = p.steer_kp * limit
            inertia = float(M[joints[jn].velocity_start(), joints[jn].velocity_start()])
            act.set_controller_gains(d.PdControllerGains(p=kp, d=2 * p.steer_damping * np.sqrt(kp * inertia)))
        else:
            act.set_controller_gains(d.PdControllerGains(p=0.0, d=p.drive_kv * limit))
    order = sorted(actuators, key=lambda a: int(a[3].index()))
    target = None
    if actuators and ramp is None:
        target = diagram.get_input_port(0)
        target.FixValue(context, np.r_[[q0[a[0]] for a in order], np.zeros(len(order))])
    push_port = plant.get_applied_spatial_force_input_port()
    push_port.FixValue(pc, [])
    return Plant(
        robot=robot,
        params=p,
        contact=contact,
        modulus=modulus if contact == "hydroelastic" else 0.0,
        diagram=diagram,
        plant=plant,
        simulator=simulator,
        context=context,
        plant_context=pc,
        weight=W,
        height=height,
        mass=mass,
        servo_names=tuple(a[0] for a in order),
        limit=np.array([a[2] for a in order]),
        steering=np.array([a[1] for a in order], dtype=bool),
        joints=joints,
        wheels=wheels,
        platform=platform,
        target=target,
        push_port=push_port,
    )
