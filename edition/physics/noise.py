r"""Encoder noise and the forward kinematics: does the error follow :math:`\kappa(\mathbf J)`? (experiment 6)

Sections 4.3 and 5.3 choose designs by the condition number of :math:`\mathbf J = \mathbf J_{L1}^{\mathrm T}\mathbf J_2`
(56): "the accuracy of the kinematic results depends on the condition number of the matrices whose
inverses are needed".  Here the encoders of a robot driving in MuJoCo are read with noise -- independent,
zero-mean, of standard deviation :math:`\sigma` on every joint rate -- and the twist is recovered by
wmr's forward kinematics (:func:`wmr.forward`).  Its error against the twist MuJoCo reports, in the
homogeneous units :math:`(L\dot\psi, \dot x, \dot y)` (:math:`L` the characteristic length), has a covariance
whose principal standard deviations spread by a ratio; for the least-squares solution through an
isotropic :math:`\mathbf J_{L1}` that ratio is :math:`\kappa(\mathbf J)`.
"""

from __future__ import annotations

import functools

import numpy as np

import wmr
from wmr.sim import Simulation, run, twist_schedule

from .common import (
    HOLDS,
    SIZE,
    Outcome,
    fmt,
    paper,
    parameters,
    pct,
    run_problems,
    sig,
    twist_text,
    verdict,
)

__all__ = ["DRAWS", "SEED", "SIGMA", "TWIST", "designs", "noise_experiment", "noise_run"]

#: standard deviation of the encoder noise, rad/s
SIGMA = 0.05
#: the noise's random generator is seeded: the same draws on every machine
SEED = 21
#: noise draws per sample
DRAWS = 100
#: the twist every design drives, (psi_dot, x_dot, y_dot)
TWIST = (0.3, 0.2, 0.1)


def designs():
    """The designs compared: the paper's offset robot at three offsets, an off-centre placement, the centred robot.

    Returns
    -------
    dict
        Name -> Robot.
    """
    r = SIZE["r"]
    off = [(-0.3, 0.0), (0.3, 0.25), (0.2, -0.3)]
    return {
        "offset, d = r": paper("offset"),
        "offset, d = r/2": paper("offset", d=r / 2),
        "offset, d = 2r": paper("offset", d=2 * r),
        "offset, d = r, off-centre": wmr.Robot([wmr.OffsetWheel(p, r=r, d=r) for p in off], name="off-centre"),
        "centred": paper("centred"),
    }


@functools.lru_cache(maxsize=16)
def _schedule(name, size, seconds):
    """The joint commands of design ``name`` along :data:`TWIST` (no physical parameter enters: once per size)."""
    return twist_schedule(designs()[name], TWIST, seconds, dt=0.1)


def noise_run(robot, params=None, seconds=3.0, rng=None, schedule=None):
    r"""Drive ``robot`` along :data:`TWIST`; read its encoders with noise; the spread of the forward-kinematics error.

    Parameters
    ----------
    robot : Robot
    params : Params, optional
    seconds : float
    rng : numpy.random.Generator, optional
        Default: seeded with :data:`SEED`.
    schedule : wmr.sim.Schedule, optional
        The joint commands of :data:`TWIST` (default: :func:`wmr.sim.twist_schedule` of ``robot``).

    Returns
    -------
    dict
        ``kappa`` (mean :math:`\kappa(\mathbf J(\boldsymbol\beta, L))` over the samples), ``spread`` (ratio of the
        largest to the smallest principal standard deviation of the error), ``std`` (the three, over
        :math:`\sigma`), ``bias`` (the mean error without noise: slip and compliance, homogeneous units, m/s).
    """
    rng = rng or np.random.default_rng(SEED)
    s = schedule if schedule is not None else twist_schedule(robot, TWIST, seconds, dt=0.1)
    rec = run(Simulation(robot, beta=s.beta[0], params=params), s, seconds)
    keep = rec.t >= 0.5
    beta, rates, true = rec.beta[keep], rec.rates[keep], rec.twist[keep]
    L = wmr.characteristic_length(robot)
    h = np.array([L, 1.0, 1.0])  # homogeneous units (L psi_dot, x_dot, y_dot)
    noisy = rates[None] + SIGMA * rng.standard_normal((DRAWS,) + rates.shape)
    err = (wmr.forward(robot, beta[None], noisy).value - true[None]) * h
    cov = np.cov(err.reshape(-1, 3).T)
    std = np.sqrt(np.linalg.eigvalsh(cov))
    kappa = np.array([wmr.condition_number(J) for J in robot.J(beta, L=L)])
    bias = (wmr.forward(robot, beta, rates).value - true) * h
    return {
        "kappa": float(kappa.mean()),
        "spread": float(std[-1] / std[0]),
        "std": std / SIGMA,
        "bias": float(np.linalg.norm(bias, axis=1).mean()),
        "samples": int(err.shape[0] * err.shape[1]),
        "validity": rec.validity,
    }


def noise_experiment(params=None):
    r"""Experiment 6: the spread of the forward-kinematics error against :math:`\kappa(\mathbf J)`, design by design.

    Criterion: the largest relative difference between the measured spread and :math:`\kappa(\mathbf J)`
    over the designs: at most 5 % holds (the sampling error of a spread from the samples taken is
    about 2 %), at most 15 % holds within it.

    Parameters
    ----------
    params : Params, optional

    Returns
    -------
    Outcome
    """
    rng = np.random.default_rng(SEED)
    size = tuple(sorted(SIZE.items()))
    out = {
        name: noise_run(bot, params, rng=rng, schedule=_schedule(name, size, 3.0)) for name, bot in designs().items()
    }
    for v in out.values():
        v["kappa"], v["spread"] = sig(v["kappa"], 3), sig(v["spread"], 3)
    err = max(abs(v["spread"] / v["kappa"] - 1) for v in out.values())
    v = verdict(err, 0.05, 0.15)
    listing = "; ".join(f"{name}: {fmt(x['kappa'], 3)}" for name, x in out.items())
    measured = "; ".join(
        f"{name}: {fmt(x['spread'], 3)} (std / sigma {', '.join(fmt(s) for s in x['std'])})" for name, x in out.items()
    )
    n = next(iter(out.values()))["samples"]
    return Outcome(
        "isotropy-noise",
        "isotropy and encoder noise",
        "Chapter 3, from Sections 4.3 and 5.3: near-tautological, a check of wmr's model",
        r"the accuracy of the forward kinematics depends on the condition number: an isotropic design "
        r"($\kappa(\mathbf J) = 1$) spreads encoder noise evenly, $\kappa > 1$ by the ratio $\kappa$",
        rf"$\kappa(\mathbf J)$ along the run: {listing}",
        f"spread of the twist error (largest / smallest principal std): {measured}",
        rf"largest difference between the spread and $\kappa(\mathbf J)$: {pct(sig(err))}",
        v,
        "<= 5 %: holds; <= 15 %: holds within it",
        parameters(
            paper("offset"),
            params,
            twist=twist_text(TWIST),
            noise=f"sigma = {SIGMA:g} rad/s on every joint rate, {DRAWS} draws per sample, seed {SEED}",
            samples=f"{n} per design",
            units="turning rate times L and velocity of C, L = RMS mount distance",
        ),
        rests_on="independent encoder noise of equal size on every joint and the least-squares forward "
        "kinematics: under them the spread of the twist error equals $\\kappa(\\mathbf J)$ by linear algebra, so the run "
        "checks wmr's model against MuJoCo's kinematics more than a physical effect",
        overturn="noise that is not independent or not equal across the joints (backlash, correlated slip; not "
        "modelled here), under which the spread and $\\kappa(\\mathbf J)$ part",
        problems=sum((run_problems(name, x["validity"]) for name, x in out.items()), ()),
        data={"runs": out, "sigma": SIGMA, "holds": v == HOLDS},
    )
