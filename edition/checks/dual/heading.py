r"""The claims of Sections 5-7 on the direction of travel: three centred wheels are not omnidirectional
(``omnidirectional``), and with mobility 1 a jump in the direction of travel needs re-steering
(``discontinuous-heading``); offset wheels need none.
"""

from __future__ import annotations

import numpy as np

from wmr import FixedWheel, Robot
from wmr.analysis.kinematics import inverse
from wmr.analysis.mobility import rank_F
from wmr.analysis.steering import steering_angles
from wmr.model.tolerance import TOL

from ...text import bound
from ...verify import SEED
from .. import Derivation, claim
from .motions import corner, curved_translation
from .robots import ROBOT, robots

__all__ = ["omnidirectional", "discontinuous_heading"]


def omnidirectional(n=2000, seed=SEED):
    r"""Claim ``omnidirectional``: three centred wheels are not omnidirectional; they must stop only to turn a sharp
    corner exactly.

    Parameters
    ----------
    n : int
        Random and coordinated steering configurations.
    seed : int

    Returns
    -------
    Derivation
        ``dims`` (admissible twist dimensions, centred and offset), ``corner`` (:func:`corner`),
        ``curve`` (:func:`curved_translation`), finding ``omnidirectional``.
    """
    cen, _, off = robots()
    rng = np.random.default_rng(seed)
    B = np.concatenate([rng.uniform(-np.pi, np.pi, (n, 3)), steering_angles(cen, rng.normal(size=(n, 3)))])
    dims = sorted(set((3 - (rank_F(cen, B) - 3)).tolist()))
    dims_off = sorted(set((3 - (rank_F(off, B) - 6)).tolist()))
    c = corner()
    curve = curved_translation()
    holds = dims == [3]
    proven = (
        dims == [0, 1]
        and dims_off == [3]
        and c["centred"]["slip"] < TOL
        and c["centred"]["moved"] == 0.0
        and not c["centred"]["admissible_at_once"]
        and abs(c["centred"]["at_once"] - c["v"]) < TOL
        and c["dual"]["slip"] < TOL
        and c["dual"]["moved"] < TOL
        and curve["psi"] < TOL
        and curve["slip"] < 1e-6
        and curve["miss"] < 1e-9
        and abs(curve["turned"] - curve["omega"] * curve["t_end"]) < 0.05
    )
    # the word's other meaning: any direction of travel, reached by re-steering (at rest or while moving)
    other_meaning = (
        c["centred"]["slip"] < TOL and c["centred"]["moved"] == 0.0 and curve["slip"] < 1e-6 and curve["miss"] < 1e-9
    )
    scope = (
        "terminology: false in the sense the paper gives the word in Section 4.2 (every twist executable at once), "
        "true in the looser sense of travelling in any direction after re-steering, which the same computation shows "
        "(the corner re-steered at rest and the curvilinear translation, both without slip)"
        if not holds and other_meaning
        else ""
    )
    return Derivation(
        dims=dims,
        dims_offset=dims_off,
        corner=c,
        curve=curve,
        n=2 * n,
        findings=[
            claim(
                "omnidirectional",
                holds,
                rf"the admissible twists of three centred wheels form a space of dimension at most 1 at all {2 * n} "
                r"configurations (3 for offset wheels); a 90-degree corner followed exactly needs the wheels re-steered with "
                r"the platform at rest (commanding the new twist at once slips at the full speed), while a curvilinear "
                rf"translation whose direction turns by ${np.degrees(curve['turned']):.0f}^\circ$ is followed without "
                rf"stopping: the twist executed differs from the one commanded by ${bound(curve['miss'], latex=True)}$, slip "
                rf"${bound(curve['slip'], latex=True)}$ (`wmr.integrate`)",
                max(curve["slip"], curve["miss"]),
                refuted=f"the admissible twists have dimension {' or '.join(map(str, dims))} (never 3): a twist in another "
                "direction than the current one cannot be executed without re-steering",
                corrected=r"A WMR with three centred (or dual) wheels has mobility $\nu = 1$ ($0$ at uncoordinated steering "
                r"angles): it is not omnidirectional. It can travel in any direction, and change direction while "
                r"moving when the wheels are re-steered together (they stay parallel, as in the curvilinear "
                r"translation of Fig. 8b); it must stop only to follow a sharp corner exactly, re-steering with the "
                r"platform at rest (type $(1, 2)$ in the classification of Campion et al.)",
                corrected_holds=proven,
                severity="wrong",
                overturn=(
                    r"the looser meaning of *omnidirectional*, travelling in any direction after re-steering: under it the"
                    r" claim holds (the terminology scope)"
                ),
                why="omnidirectional means every twist executable at once, the paper's own use in Section 4.2; decoupled "
                "steering only lets the wheels turn, one direction of motion at a time",
                convention="omnidirectional = every platform twist executable at once from any configuration (Section 4.2)",
                scope=scope,
            )
        ],
    )


def discontinuous_heading(n=2000, seed=SEED):
    r"""Claim ``discontinuous-heading``: with mobility 1 a jump in the direction of travel needs re-steering; offset
    wheels need none; and at mobility 2 a differential drive with C ahead of its axle needs none either, which
    refutes the claim as stated for every mobility below 3.

    Parameters
    ----------
    n : int
        Random twist jumps.
    seed : int

    Returns
    -------
    Derivation
        ``rows`` (executable fraction and largest residual per case), ``gain`` (largest joint-rate gain of the
        offset robot), ``bound`` (its bound), ``corner`` (:func:`corner`), finding ``discontinuous-heading``.
    """
    cen, _, off = robots()
    rng = np.random.default_rng(seed)
    t_minus, t_plus = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))
    lam = rng.choice([-1, 1], n) * rng.uniform(0.2, 3.0, n)
    b_minus = steering_angles(cen, t_minus)
    jump = inverse(cen, b_minus, t_plus)
    scaled = inverse(cen, b_minus, lam[:, None] * t_minus)
    be_off = rng.uniform(-np.pi, np.pi, (n, 3))
    sol_off = inverse(off, be_off, t_plus)
    gain = np.linalg.norm(sol_off.value, axis=-1) / np.linalg.norm(t_plus, axis=-1)
    bound_ = np.linalg.svd(off.J1(), compute_uv=False)[0] / np.linalg.svd(off.J2(be_off), compute_uv=False)[..., -1]
    c = corner()
    # mobility 2: a differential drive (two fixed wheels on one axle), C a distance a ahead of the axle.  Its
    # admissible twists are (psi_dot, x_dot, a psi_dot): C's velocity may point anywhere, the platform turning
    a, r = ROBOT["L"] / 2, ROBOT["r"]
    diff = Robot(
        [FixedWheel((-a, side * ROBOT["L"]), r=r, angle=np.pi / 2) for side in (1, -1)], name="differential drive"
    )
    omega, vx = rng.normal(size=n), rng.normal(size=n)
    t_diff = np.stack([omega, vx, a * omega], axis=-1)  # random admissible twists: C heading anywhere
    sol_diff = inverse(diff, np.zeros((n, diff.w)), t_diff)
    turned = np.abs(np.degrees(np.arctan2(t_diff[:, 2], t_diff[:, 1])))  # C's heading from straight ahead (x)
    rows: list[dict] = [
        {
            "case": r"centred: $\mathbf t^-$ to a random $\mathbf t^+$",
            "executable": float(jump.admissible.mean()),
            "largest residual": float(np.abs(jump.residual).max()),
        },
        {
            "case": r"centred: $\mathbf t^-$ to $\lambda\mathbf t^-$ (incl. "
            r"reversal)",
            "executable": float(scaled.admissible.mean()),
            "largest residual": float(np.abs(scaled.residual).max()),
        },
        {
            "case": r"offset ($d = r$): any $\boldsymbol\beta$, random "
            r"$\mathbf t^+$",
            "executable": float(sol_off.admissible.mean()),
            "largest residual": float(np.abs(sol_off.residual).max()),
        },
        {
            "case": rf"differential drive, C ${a:g}$ ahead of its axle: from straight ahead to a random heading of C "
            rf"(up to ${turned.max():.0f}^\circ$)",
            "executable": float(sol_diff.admissible.mean()),
            "largest residual": float(np.abs(sol_diff.residual).max()),
        },
    ]
    res = max(rows[2]["largest residual"], rows[3]["largest residual"])
    mobility_1_and_3 = (
        not jump.admissible.any()
        and bool(scaled.admissible.all())
        and bool(sol_off.admissible.all())
        and rows[2]["largest residual"] < TOL
        and bool(np.all(gain <= bound_ * (1 + 1e-12)))
        and c["offset"]["slip"] < TOL
        and bool(np.allclose(c["offset"]["final"], [0.0, c["v"], c["v"]], atol=0.01 * c["v"]))
    )
    # mobility 2: does the differential drive turn C's heading at once, with only its wheel rates jumping?
    jumps_at_2 = bool(sol_diff.admissible.all()) and rows[3]["largest residual"] < TOL
    holds = mobility_1_and_3 and not jumps_at_2

    def mobility(robot, beta):
        return (3 + robot.n_rates) - rank_F(robot, beta)  # the dimension of the null space of F

    # the mobilities tested (dimension of the admissible twists); the claim is about every mobility below 3
    tested = sorted(
        set(mobility(cen, b_minus).tolist())
        | set(mobility(off, be_off).tolist())
        | set(mobility(diff, np.zeros((1, diff.w))).tolist())
    )
    return Derivation(
        rows=rows,
        tested=tested,
        gain=float(gain.max()),
        bound=float(bound_.max()),
        corner=c,
        findings=[
            claim(
                "discontinuous-heading",
                holds,
                rf"of {n} random jumps of the twist, none is executable by the centred robot without re-steering, all jumps "
                r"$\mathbf t \to \lambda\mathbf t$ are; the offset robot executes all of them at once, with joint rates "
                r"bounded by "
                r"$\sigma_{\max}(\mathbf J_1)/\sigma_{\min}(\mathbf J_2)\,\|\mathbf t\|$, and turns a 90-degree corner without "
                r"stopping and without slip (`wmr.integrate`); a differential drive (mobility 2) with C "
                rf"${a:g}$ ahead of its axle executes all {n} random jumps of C's heading at once",
                res,
                refuted=rf"at mobility 2 a differential drive with C ${a:g}$ ahead of its axle turns C's heading by up to "
                rf"${turned.max():.0f}^\circ$ at once, in all {n} random jumps, only its wheel rates jumping",
                corrected=r"Whether a jump in the heading needs a delay is decided by the twist, not by the mobility: the "
                r"robot follows a jump at once exactly when the new twist is admissible at the present steering "
                r"angles. With three centred wheels ($\nu(\mathbf F) = 1$) only a reversal "
                r"$\mathbf t^+ = \lambda\mathbf t^-$ is, so a corner needs re-steering "
                r"at rest; a differential drive (mobility 2) with C off its axle may point C's velocity anywhere, "
                r"the platform turning, so it follows a corner of C's path without a delay; offset wheels "
                r"(mobility 3) follow any jump",
                corrected_holds=mobility_1_and_3 and jumps_at_2,
                severity="wrong",
                why="a mobility below 3 does not by itself force a delay: a differential drive (mobility 2) with C "
                "ahead of its axle turns C's heading at once, only its wheel rates jumping",
                overturn="reading *heading* as the direction of travel of a point on the axle of fixed wheels (a "
                "differential drive must then turn on the spot first), or the claim as one about the robots of "
                "Sections 5 and 6 only (centred and dual wheels, mobility 1): then no jump but a reversal is "
                "executable without re-steering, and the claim holds",
                convention=r"heading = the direction of travel of C (the platform twist); a jump "
                r"$\mathbf t \to \lambda\mathbf t$ (same instantaneous centre, a reversal for $\lambda < 0$) needs "
                r"no delay; offset wheels ($d > 0$) realise any twist at once",
            )
        ],
    )
